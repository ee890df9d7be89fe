// Mesh of the contact-patch sweep (doc/accuracy-cost/continuous_patch/README.md): the model of
// testcases/continuous_patch/blocks.geo with square QUAD4 of side H in the 10 x 10 block (BLOC)
// and in the 10 x 4 foundation (SOL). NM = 0: the same nodes along the interface y = 0 (the test
// case); NM = 1: the foundation has one cell more along x (non-matching interface).
// Groups: BLOC_BAS (slave), BLOC_HAUT (driven), SOL_HAUT (master), SOL_BAS, GAUCHE.
DefineConstant[H = 2, NM = 0];
NB = Round(10 / H);
NF = NB + NM;
Point(1) = {0, 0, 0}; Point(2) = {10, 0, 0}; Point(3) = {10, 10, 0}; Point(4) = {0, 10, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = NB + 1; Transfinite Surface{1}; Recombine Surface{1};
Point(5) = {0, -4, 0}; Point(6) = {10, -4, 0}; Point(7) = {10, 0, 0}; Point(8) = {0, 0, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{5, 7} = NF + 1; Transfinite Curve{6, 8} = Round(4 / H) + 1; Transfinite Surface{2}; Recombine Surface{2};
Physical Surface("BLOC") = {1}; Physical Surface("SOL") = {2};
Physical Curve("BLOC_BAS") = {1}; Physical Curve("BLOC_HAUT") = {3}; Physical Curve("SOL_HAUT") = {7};
Physical Curve("SOL_BAS") = {5}; Physical Curve("GAUCHE") = {4, 8};
