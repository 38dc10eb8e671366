// An elastic-perfectly-plastic sphere (R = 1) as the solid of revolution of a quarter disc about
// the y axis: x = r >= 0, the centre (0, 1), the lowest point (0, 0) on the axis; graded towards
// it, h over the 0.08 around it where the contact (radius <= 0.05 at the scene's deepest
// interference) and its plastic zone lie (scenes/sphere-indentation-axisymmetric.yaml).
// Size Factor (Mesh/file) scales every size.
h = 0.002;  // near the contact point
H = 0.1;    // far
Point(1) = {0, 1, 0, H};   // centre
Point(2) = {0, 0, 0, h};   // contact point, on the axis
Point(3) = {1, 1, 0, H};   // equator
Circle(1) = {2, 1, 3};
Line(2) = {3, 1};
Line(3) = {1, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Field[1] = Distance;
Field[1].PointsList = {2};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = H;
Field[2].DistMin = 0.08;
Field[2].DistMax = 0.5;
Background Field = 2;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.RecombineAll = 1;
Mesh.ElementOrder = 1;
Mesh.SecondOrderIncomplete = 1;
Physical Surface("sphere") = {1};
Physical Curve("curved") = {1};
Physical Curve("flat") = {2};
Physical Curve("axis") = {3};
