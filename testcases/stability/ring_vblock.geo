// A ring (outer radius 0.05 m, inner 0.03 m, 8 sectors of 8 x 4 QUAD4, ANNEAU) centred at the
// origin, seated in a V-block (faces at 45 degrees, VE, every node fixed) and pressed from
// above by a punch (0.04 x 0.02 m, 8 x 4 QUAD4, POINCON). The V faces and the punch's bottom
// overlap the ring by d0 = 1e-6 m at the ring's nodes at 225, 315 and 90 degrees, so that the
// ring and the punch, held by contact only, are in contact from the first iteration. Units m.
// Groups: ANNEAU, VE, POINCON; slaves ANN_HAUT (outer arc 45..135 degrees), ANN_GAUCHE
// (180..225), ANN_DROITE (315..360); masters VE_GAUCHE, VE_DROITE, POINC_BAS; POINC_HAUT (the
// pressed face); ANN_AXE (the ring's nodes at 90 and 270 degrees, on the symmetry axis).
R = 0.05; r = 0.03; d0 = 1e-6; s = d0 * Sqrt(2);
Point(1) = {0, 0, 0};
For i In {0:7}
  Point(10 + i) = {R * Cos(i * Pi / 4), R * Sin(i * Pi / 4), 0};
  Point(20 + i) = {r * Cos(i * Pi / 4), r * Sin(i * Pi / 4), 0};
EndFor
For i In {0:7}
  j = (i + 1) % 8;
  Circle(100 + i) = {10 + i, 1, 10 + j};
  Circle(110 + i) = {20 + i, 1, 20 + j};
  Line(120 + i) = {20 + i, 10 + i};
EndFor
For i In {0:7}
  j = (i + 1) % 8;
  Curve Loop(200 + i) = {120 + i, 100 + i, -(120 + j), -(110 + i)};
  Plane Surface(200 + i) = {200 + i};
  Transfinite Curve{100 + i, 110 + i} = 9;
  Transfinite Curve{120 + i} = 5;
  Transfinite Surface{200 + i}; Recombine Surface{200 + i};
EndFor
// V-block: apex (0, -R sqrt2 + s), faces up to x = +-0.06, bottom y = -0.1.
Point(31) = {-0.06, -0.1, 0}; Point(32) = {0.06, -0.1, 0};
Point(33) = {0.06, 0.06 - R * Sqrt(2) + s, 0}; Point(34) = {0, -R * Sqrt(2) + s, 0};
Point(35) = {-0.06, 0.06 - R * Sqrt(2) + s, 0};
Line(301) = {31, 32}; Line(302) = {32, 33}; Line(303) = {33, 34}; Line(304) = {34, 35}; Line(305) = {35, 31};
Curve Loop(300) = {301, 302, 303, 304, 305}; Plane Surface(300) = {300};
Transfinite Curve{303, 304} = 13;
// Punch: -0.02 <= x <= 0.02, R - d0 <= y <= R - d0 + 0.02.
Point(41) = {-0.02, R - d0, 0}; Point(42) = {0.02, R - d0, 0};
Point(43) = {0.02, R - d0 + 0.02, 0}; Point(44) = {-0.02, R - d0 + 0.02, 0};
Line(401) = {41, 42}; Line(402) = {42, 43}; Line(403) = {43, 44}; Line(404) = {44, 41};
Curve Loop(400) = {401, 402, 403, 404}; Plane Surface(400) = {400};
Transfinite Curve{401, 403} = 9; Transfinite Curve{402, 404} = 5; Transfinite Surface{400}; Recombine Surface{400};
Physical Surface("ANNEAU") = {200:207}; Physical Surface("VE") = {300}; Physical Surface("POINCON") = {400};
Physical Curve("ANN_HAUT") = {101, 102}; Physical Curve("ANN_GAUCHE") = {104};
Physical Curve("ANN_DROITE") = {107};
Physical Curve("VE_DROITE") = {303}; Physical Curve("VE_GAUCHE") = {304};
Physical Curve("POINC_BAS") = {401}; Physical Curve("POINC_HAUT") = {403};
Physical Point("ANN_AXE") = {12, 16};
