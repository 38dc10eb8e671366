// NAFEMS contact patch test CGS-4 as FrontISTR models it (tests/analysis/interaction/cgs4,
// merge request 599): a block pushed up a frictional incline of slope tan(alpha) = 0.1.
// scenes/nafems-cgs4-3d.yaml: the 2D section (nafems-cgs4-2d.geo) extruded by one hex8 layer of
// unit thickness, as FrontISTR's model, z held on every node.
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
base[] = Extrude {0, 0, 1} { Surface{1}; Layers{1}; Recombine; };
block[] = Extrude {0, 0, 1} { Surface{2}; Layers{1}; Recombine; };
// Extrude returns the top surface, the volume, then the sides in the order of the loop's curves.
Physical Volume("base") = {base[1]};
Physical Volume("block") = {block[1]};
Physical Surface("base-bottom") = {base[2]};
Physical Surface("incline") = {base[4]};
Physical Surface("block-bottom") = {block[2]};
Physical Surface("block-top") = {block[4]};
Physical Surface("block-left") = {block[5]};
Physical Surface("faces") = {1, 2, base[0], block[0]};
Mesh.RecombineAll = 1;
