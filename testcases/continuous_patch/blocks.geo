// A 10 x 10 block (BLOC, 5 x 5 QUAD4) standing on a 10 x 4 foundation (SOL, 5 x 2 QUAD4) with
// the same nodes along the interface y = 0 (not merged: two bodies). Counter-clockwise surfaces.
// Groups: BLOC_BAS (slave), BLOC_HAUT (driven), SOL_HAUT (master), SOL_BAS (DY = 0), GAUCHE
// (x = 0 of both bodies, DX = 0).
Point(1) = {0, 0, 0}; Point(2) = {10, 0, 0}; Point(3) = {10, 10, 0}; Point(4) = {0, 10, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 6; Transfinite Surface{1}; Recombine Surface{1};
Point(5) = {0, -4, 0}; Point(6) = {10, -4, 0}; Point(7) = {10, 0, 0}; Point(8) = {0, 0, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{5, 7} = 6; Transfinite Curve{6, 8} = 3; Transfinite Surface{2}; Recombine Surface{2};
Physical Surface("BLOC") = {1}; Physical Surface("SOL") = {2};
Physical Curve("BLOC_BAS") = {1}; Physical Curve("BLOC_HAUT") = {3}; Physical Curve("SOL_HAUT") = {7};
Physical Curve("SOL_BAS") = {5}; Physical Curve("GAUCHE") = {4, 8};
