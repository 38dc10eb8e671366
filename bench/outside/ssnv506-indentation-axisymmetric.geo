// code_aster SSNV506: an elastic-perfectly-plastic block (radius 1620 mm, depth 1920 mm) and a
// stiff sphere (R = 500 mm, its lowest point touching the block's top at the axis), the solid of
// revolution about the y axis (x = r >= 0). Quad4, 20 mm (times Size Factor) near the contact,
// up to 200 mm far from it (scenes/ssnv506-indentation-axisymmetric.yaml).
h = 20;
H = 200;
R = 500;
// The block.
Point(1) = {0, 0, 0, h};
Point(2) = {1620, 0, 0, H};
Point(3) = {1620, -1920, 0, H};
Point(4) = {0, -1920, 0, H};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {-4, -3, -2, -1};  // counter-clockwise
Plane Surface(1) = {1};
// The sphere (a quarter disc): centre (0, R), lowest point (0, 0) apart from the block's top.
Point(5) = {0, R, 0, H};
Point(6) = {0, 0, 0, h};
Point(7) = {R, R, 0, H};
Circle(5) = {6, 5, 7};
Line(6) = {7, 5};
Line(7) = {5, 6};
Curve Loop(2) = {5, 6, 7};
Plane Surface(2) = {2};
// Fine where the contact spreads (a = sqrt(2 R delta) ~ 320 mm at 100 mm of travel).
Field[1] = Box;
Field[1].VIn = h;
Field[1].VOut = H;
Field[1].XMin = -1;
Field[1].XMax = 450;
Field[1].YMin = -450;
Field[1].YMax = 150;
Field[1].Thickness = 400;
Background Field = 1;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.RecombineAll = 1;
Mesh.ElementOrder = 1;
Mesh.SecondOrderIncomplete = 1;
Physical Surface("block") = {1};
Physical Surface("sphere") = {2};
Physical Curve("block-top") = {1};
Physical Curve("block-bottom") = {3};
Physical Curve("block-axis") = {4};
Physical Curve("sphere-surface") = {5};
Physical Curve("sphere-top") = {6};
Physical Curve("sphere-axis") = {7};
