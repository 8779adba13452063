// Four-point sail: flat unit square; the corners "high" are lifted by displ_initial_z in the scene.
// Physical groups: membrane (triangles), edges (lines -> edge cables), low and high (corner points).
lc = 1.0 / 16;
Point(1) = {0, 0, 0, lc};
Point(2) = {1, 0, 0, lc};
Point(3) = {1, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("membrane") = {1};
Physical Curve("edges") = {1, 2, 3, 4};
Physical Point("low") = {1, 3};
Physical Point("high") = {2, 4};
