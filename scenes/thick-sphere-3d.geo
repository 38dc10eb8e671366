// An eighth of a hollow sphere a = 1 <= r <= b = 2 (x, y, z >= 0) for
// scenes/thick-sphere-3d.yaml: tet10 of uniform size h; Size Factor (Mesh/file) scales it.
// Groups: the bore "inner", the symmetry planes "x0", "y0", "z0", the volume "shell".
SetFactory("OpenCASCADE");
a = 1.0;
b = 2.0;
h = 0.2;
Sphere(1) = {0, 0, 0, b, 0, Pi / 2, Pi / 2};
Sphere(2) = {0, 0, 0, a, 0, Pi / 2, Pi / 2};
BooleanDifference(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
eps = 1e-6;
Physical Volume("shell") = {3};
Physical Surface("inner") = Surface In BoundingBox{-eps, -eps, -eps, a + eps, a + eps, a + eps};
Physical Surface("x0") = Surface In BoundingBox{-eps, -eps, -eps, eps, b + eps, b + eps};
Physical Surface("y0") = Surface In BoundingBox{-eps, -eps, -eps, b + eps, eps, b + eps};
Physical Surface("z0") = Surface In BoundingBox{-eps, -eps, -eps, b + eps, b + eps, eps};
