// NAFEMS contact benchmark 2 (A. Konter, "Advanced Finite Element Contact Benchmarks", NAFEMS
// 2006; code_aster SSNA122): an axisymmetric steel punch with a rounded edge on an aluminium
// foundation. x = r, y the axis, mm; scenes/nafems-punch-axisymmetric.yaml.
h = 2.5;      // element size near the contact (Size Factor scales both)
H = 12.5;     // far
// Foundation: r in [0, 100], y in [-200, 0]
Point(1) = {0, -200, 0, H};
Point(2) = {100, -200, 0, H};
Point(3) = {100, 0, 0, H};
Point(4) = {60, 0, 0, h};
Point(5) = {0, 0, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
// Punch: r in [0, 50], y in [0, 100], the bottom edge rounded with radius 10 (centre (40, 10))
Point(11) = {0, 0, 0, h};
Point(12) = {40, 0, 0, h};
Point(13) = {40, 10, 0, h};
Point(14) = {50, 10, 0, h};
Point(15) = {50, 100, 0, H};
Point(16) = {0, 100, 0, H};
Line(11) = {11, 12};
Circle(12) = {12, 13, 14};
Line(13) = {14, 15};
Line(14) = {15, 16};
Line(15) = {16, 11};
Curve Loop(2) = {11, 12, 13, 14, 15};
Plane Surface(2) = {2};
Physical Surface("foundation") = {1};
Physical Surface("punch") = {2};
Physical Curve("foundation-top") = {3, 4};
Physical Curve("foundation-bottom") = {1};
Physical Curve("foundation-axis") = {5};
Physical Curve("punch-bottom") = {11, 12};
Physical Curve("punch-top") = {14};
Physical Curve("punch-axis") = {15};
Mesh.RecombineAll = 1;
Mesh.Algorithm = 6;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;
