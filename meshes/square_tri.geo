// Unit square membrane fixture for the Gmsh reader tests: a structured 2 x 2 grid of squares,
// each split into two triangles (8 triangles, 9 nodes).
// Regenerate: gmsh -2 square_tri.geo -format msh4 -o square_tri.msh
Point(1) = {0, 0, 0, 0.5};
Point(2) = {1, 0, 0, 0.5};
Point(3) = {1, 1, 0, 0.5};
Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 3;
Transfinite Surface{1};

Physical Surface("sail") = {1};
Physical Curve("edge_fixed") = {4};   // x = 0: a node group for nprops
Physical Curve("edge_cable") = {3};   // y = 1: cable elements
Physical Point("corner") = {3};       // (1, 1)
