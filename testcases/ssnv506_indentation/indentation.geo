// ssnv506-like indentation, axisymmetric section (x = r, y = z), units mm.
// Sphere: radius 500, centre (0, 500), touching the massif at the origin; only its half-disc
// x >= 0 is meshed. Massif: 0 <= r <= 1620, -1920 <= z <= 0.
// Groups: MASSIF, SPHERE (surfaces); S_CONT (sphere's lower arc, master), M_CONT (massif top,
// r <= 600, slave), M_TOP_FAR (rest of the massif top), S_TOP (sphere arc r <= 250, driven),
// M_BASE (z = -1920), AXE (both bodies' r = 0 edges), S_SIDE (other sphere arc), M_SIDE (r = 1620).
// Options: H (cell size at the contact), ORDER (1: QUAD4, 2: QUAD8), QUADS (0: triangles), SECTOR (> 0: the 3D quarter
// model, the section revolved by 90 degrees about the y axis in SECTOR layers; HEXA8 and PENTA6
// next to the axis). 3D groups: MASSIF, SPHERE (volumes), S_CONT, M_CONT (faces), S_TOP, M_BASE
// (faces), SYM_Z (the section z = 0), SYM_X (the revolved section x = 0).
DefineConstant[H = 12, ORDER = 1, SECTOR = 0, QUADS = 1];
R = 500; L = 1620; D = 1920; RC = 600;
// Massif
Point(1) = {0, 0, 0, H}; Point(2) = {RC, 0, 0, 1.6 * H}; Point(3) = {L, 0, 0, 12 * H};
Point(4) = {L, -D, 0, 20 * H}; Point(5) = {0, -D, 0, 20 * H}; Point(6) = {0, -RC, 0, 2.5 * H};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
Curve Loop(1) = {-6, -5, -4, -3, -2, -1}; Plane Surface(1) = {1}; // counter-clockwise
// Sphere: arcs from the bottom (0,0) to (R,R) (contact), to the top arc start (250, 933), to (0, 2R).
// In 3D the revolution would merge the two bodies' nodes at the origin: the sphere is lifted by
// EPS = 1e-3 mm there (an initial gap of 1e-5 of the 100 mm indentation).
EPS = (SECTOR > 0) ? 1e-3 : 0;
Point(10) = {0, R + EPS, 0, 6 * H}; Point(11) = {0, EPS, 0, H}; Point(12) = {R, R + EPS, 0, 2.5 * H};
Point(13) = {250, R + EPS + Sqrt(R * R - 250 * 250), 0, 5 * H}; Point(14) = {0, 2 * R + EPS, 0, 5 * H};
Circle(10) = {11, 10, 12}; Circle(11) = {12, 10, 13}; Circle(12) = {13, 10, 14}; Line(13) = {14, 11};
Curve Loop(2) = {10, 11, 12, 13}; Plane Surface(2) = {2};
Mesh.Algorithm = 6;
If (QUADS)
  Recombine Surface{1, 2};
EndIf
Mesh.RecombinationAlgorithm = 1;
Mesh.ElementOrder = ORDER; Mesh.SecondOrderIncomplete = 1;
If (SECTOR == 0)
  Physical Surface("MASSIF") = {1}; Physical Surface("SPHERE") = {2};
  Physical Curve("M_CONT") = {1}; Physical Curve("M_TOP_FAR") = {2}; Physical Curve("M_SIDE") = {3};
  Physical Curve("M_BASE") = {4}; Physical Curve("M_AXE") = {5, 6};
  Physical Curve("S_CONT") = {10}; Physical Curve("S_SIDE") = {11}; Physical Curve("S_TOP") = {12};
  Physical Curve("S_AXE") = {13};
EndIf
If (SECTOR > 0)
  m[] = Extrude {{0, 1, 0}, {0, 0, 0}, Pi / 2} { Surface{1}; Layers{SECTOR}; Recombine; };
  s[] = Extrude {{0, 1, 0}, {0, 0, 0}, Pi / 2} { Surface{2}; Layers{SECTOR}; Recombine; };
  // m[0] = revolved section, m[1] = volume, then one face per boundary curve of the loop
  // {-6, -5, -4, -3, -2, -1} (the axis curves 6 and 5 give no face); s[]: loop {10, 11, 12, 13}.
  Physical Volume("MASSIF") = {m[1]}; Physical Volume("SPHERE") = {s[1]};
  Physical Surface("SYM_Z") = {1, 2}; Physical Surface("SYM_X") = {m[0], s[0]};
  Physical Surface("M_BASE") = {m[2]}; Physical Surface("M_SIDE") = {m[3]}; Physical Surface("M_TOP_FAR") = {m[4]};
  Physical Surface("M_CONT") = {m[5]}; Physical Surface("S_CONT") = {s[2]}; Physical Surface("S_SIDE") = {s[3]};
  Physical Surface("S_TOP") = {s[4]};
EndIf
