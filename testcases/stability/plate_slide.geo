// A plate 0.1 x 0.01 m (20 x 2 QUAD4, PLAQUE) on a foundation -0.01 <= x <= 0.11,
// -0.01 <= y <= 1e-6 (SOL, every node fixed: a rigid plane). The foundation's top overlaps the
// plate's bottom by 1e-6 m, so that the plate, held in DY by contact only, is in contact from
// the first iteration. Units m. Groups: PLAQUE, SOL; PLAQ_BAS (slave), PLAQ_HAUT (pressed and
// driven), SOL_HAUT (master).
Point(1) = {0, 0, 0}; Point(2) = {0.1, 0, 0}; Point(3) = {0.1, 0.01, 0}; Point(4) = {0, 0.01, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 21; Transfinite Curve{2, 4} = 3; Transfinite Surface{1}; Recombine Surface{1};
Point(5) = {-0.01, -0.01, 0}; Point(6) = {0.11, -0.01, 0}; Point(7) = {0.11, 1e-6, 0}; Point(8) = {-0.01, 1e-6, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{5, 7} = 13; Transfinite Curve{6, 8} = 2; Transfinite Surface{2}; Recombine Surface{2};
Physical Surface("PLAQUE") = {1}; Physical Surface("SOL") = {2};
Physical Curve("PLAQ_BAS") = {1}; Physical Curve("PLAQ_HAUT") = {3}; Physical Curve("SOL_HAUT") = {7};
