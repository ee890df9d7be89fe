// The rigid-surface study of testcases/rigid_surface with a cell size parameter (accuracy-cost sweep):
// elastic block 0 <= x <= 10, 0 <= y <= 10 (BLOC, N x N QUAD4 of side H = 10 / N) under a rigid plate
// -1 <= x <= 12, 10 <= y <= 12 (RIGIDE, meshed for the orientation of its skin only; its bottom edge
// RIGIDE_BAS, 3 N / 2 SEG2 that do not match the block's N, is the master). Units mm.
DefineConstant[ H = 2.5 ];
N = Round(10 / H);
Point(1) = {0, 0, 0}; Point(2) = {10, 0, 0}; Point(3) = {10, 10, 0}; Point(4) = {0, 10, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = N + 1; Transfinite Surface{1}; Recombine Surface{1};
Point(5) = {-1, 10, 0}; Point(6) = {12, 10, 0}; Point(7) = {12, 12, 0}; Point(8) = {-1, 12, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{5, 7} = Round(1.5 * N) + 1; Transfinite Curve{6, 8} = 2; Transfinite Surface{2}; Recombine Surface{2};
Physical Surface("BLOC") = {1}; Physical Surface("RIGIDE") = {2};
Physical Curve("BLOC_BAS") = {1}; Physical Curve("BLOC_DROIT") = {2}; Physical Curve("BLOC_HAUT") = {3};
Physical Curve("BLOC_GAUCHE") = {4}; Physical Curve("RIGIDE_BAS") = {5};
