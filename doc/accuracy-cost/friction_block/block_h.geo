// Mesh of the friction-block sweep (doc/accuracy-cost/friction_block/README.md): the model of
// testcases/friction_block/friction_block.geo with square QUAD4 of side HB in the block (10 x 10,
// NB = 10 / HB cells a side; the test case has HB = 2.5) on the same rigid foundation
// -2 <= x <= 12, -2 <= y <= 0 (7 x 1 QUAD4, every node fixed by the command file).
// Groups: BLOC, SOL; BLOC_BAS (slave), BLOC_HAUT (driven), SOL_HAUT (master).
DefineConstant[HB = 2.5];
NB = Round(10 / HB);
Point(1) = {0, 0, 0}; Point(2) = {10, 0, 0}; Point(3) = {10, 10, 0}; Point(4) = {0, 10, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = NB + 1; Transfinite Surface{1}; Recombine Surface{1};
Point(5) = {-2, -2, 0}; Point(6) = {12, -2, 0}; Point(7) = {12, 0, 0}; Point(8) = {-2, 0, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{5, 7} = 8; Transfinite Curve{6, 8} = 2; Transfinite Surface{2}; Recombine Surface{2};
Physical Surface("BLOC") = {1}; Physical Surface("SOL") = {2};
Physical Curve("BLOC_BAS") = {1}; Physical Curve("BLOC_HAUT") = {3}; Physical Curve("SOL_HAUT") = {7};
