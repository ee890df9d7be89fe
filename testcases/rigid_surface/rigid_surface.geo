// Elastic block 0 <= x <= 10, 0 <= y <= 10 (BLOC, 4 x 4 QUAD4) under a rigid plate
// -1 <= x <= 12, 10 <= y <= 12 (RIGIDE, meshed for the orientation of its skin only; only its
// bottom edge RIGIDE_BAS is put in the model, 6 SEG2 not matching the block's 4). Units mm.
// Groups: BLOC, RIGIDE; BLOC_BAS, BLOC_GAUCHE, BLOC_DROIT, BLOC_HAUT (slave), RIGIDE_BAS (master).
Point(1) = {0, 0, 0}; Point(2) = {10, 0, 0}; Point(3) = {10, 10, 0}; Point(4) = {0, 10, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 5; Transfinite Surface{1}; Recombine Surface{1};
Point(5) = {-1, 10, 0}; Point(6) = {12, 10, 0}; Point(7) = {12, 12, 0}; Point(8) = {-1, 12, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{5, 7} = 7; Transfinite Curve{6, 8} = 2; Transfinite Surface{2}; Recombine Surface{2};
Physical Surface("BLOC") = {1}; Physical Surface("RIGIDE") = {2};
Physical Curve("BLOC_BAS") = {1}; Physical Curve("BLOC_DROIT") = {2}; Physical Curve("BLOC_HAUT") = {3};
Physical Curve("BLOC_GAUCHE") = {4}; Physical Curve("RIGIDE_BAS") = {5};
