// Two blocks, units mm. BAS: its top BAS_HAUT is the inclined line y = 0.1 x, -2 <= x <= 12
// (master). HAUT: the rectangle 0 <= x <= 10, 1.5 <= y <= 4; its bottom HAUT_BAS (6 nodes,
// x = 0, 2, ..., 10) is the slave, its top HAUT_HAUT is driven. Counter-clockwise surfaces.
Point(1) = {-2, -3, 0}; Point(2) = {12, -3, 0}; Point(3) = {12, 1.2, 0}; Point(4) = {-2, -0.2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 8; Transfinite Curve{2, 4} = 3; Transfinite Surface{1}; Recombine Surface{1};
Point(5) = {0, 1.5, 0}; Point(6) = {10, 1.5, 0}; Point(7) = {10, 4, 0}; Point(8) = {0, 4, 0};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{5, 7} = 6; Transfinite Curve{6, 8} = 3; Transfinite Surface{2}; Recombine Surface{2};
Physical Surface("BAS") = {1}; Physical Surface("HAUT") = {2};
Physical Curve("BAS_BASE") = {1}; Physical Curve("BAS_HAUT") = {3};
Physical Curve("HAUT_BAS") = {5}; Physical Curve("HAUT_HAUT") = {7};
