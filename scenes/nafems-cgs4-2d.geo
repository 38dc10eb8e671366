// NAFEMS contact patch test CGS-4 as FrontISTR models it (tests/analysis/interaction/cgs4,
// merge request 599): a block pushed up a frictional incline of slope tan(alpha) = 0.1.
// scenes/nafems-cgs4-2d.yaml. Plane strain, unit thickness, lengths in the test's units.
nb = 12;   // base: elements along the incline
nt = 3;    // base: elements through its height
mb = 9;    // block: elements along the incline (non-matching: 12 against 9)
mt = 3;    // block: elements through its height
// Base: x in [0, 6], bottom y = 0, top y = 0.7 + 0.1 x (the incline)
Point(1) = {0, 0, 0};
Point(2) = {6, 0, 0};
Point(3) = {6, 1.3, 0};
Point(4) = {0, 0.7, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nb + 1;
Transfinite Curve{2, 4} = nt + 1;
Transfinite Surface{1};
// Block: x in [1, 5], its bottom on the incline, top y = 2
Point(11) = {1, 0.8, 0};
Point(12) = {5, 1.2, 0};
Point(13) = {5, 2, 0};
Point(14) = {1, 2, 0};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 11};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(2) = {2};
Transfinite Curve{11, 13} = mb + 1;
Transfinite Curve{12, 14} = mt + 1;
Transfinite Surface{2};
Physical Surface("base") = {1};
Physical Surface("block") = {2};
Physical Curve("base-bottom") = {1};
Physical Curve("incline") = {3};
Physical Curve("block-bottom") = {11};
Physical Curve("block-top") = {13};
Physical Curve("block-left") = {14};
Mesh.RecombineAll = 1;
