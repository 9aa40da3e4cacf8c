// tests/data/gmsh/square.geo: a unit square of two triangles with a group of each dimension, for the
// byte-by-byte tests of seflex's MSH reader (tests/io/gmsh_msh_input_test.cpp).
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1:4} = 2; Transfinite Surface{1};
Physical Surface("plate") = {1};
Physical Curve("edge") = {1, 2};
Physical Point("corner") = {1};
