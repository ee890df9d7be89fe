// Mesh of the plate-plasticity sweep (doc/accuracy-cost/plate_plasticity/README.md): the unit cube
// in N x N x N structured HEXA8 (ORDER = 2: HEXA20, serendipity), groups X0, X1, Y0, Z0 (faces)
// and ALL (volume), as the unit cube of testcases/patch_tests used by testcases/plate_plasticity.
DefineConstant[N = 1, ORDER = 1];
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = N + 1; Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {0, 0, 1} { Surface{1}; Layers{N}; Recombine; };
Mesh.ElementOrder = ORDER;
Mesh.SecondOrderIncomplete = 1;
Physical Surface("Z0") = {1};
Physical Volume("ALL") = {out[1]};
Physical Surface("Y0") = {out[2]};
Physical Surface("X1") = {out[3]};
Physical Surface("X0") = {out[5]};
