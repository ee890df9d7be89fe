// Hertz contact, plane strain (cylinder) or axisymmetric (sphere) section: an indenter of radius
// 50 (centre (0, 50)) on a block 0 <= x <= 200, -200 <= y <= 0, units mm. Half model (symmetry
// or axis x = 0); only the indenter's lower quarter (y <= 50) is meshed and its cut y = 50
// (IND_TOP) is driven down. All surfaces are counter-clockwise (positive Jacobians).
// Groups: IND, BLOC (surfaces); IND_CONT (arc x <= 25, slave), IND_ARC (rest of the arc),
// IND_TOP, IND_AXE, BLOC_TOP (x <= 40, master), BLOC_TOP_FAR, BLOC_AXE, BLOC_BASE, BLOC_SIDE;
// P0 (point cell on the indenter's node at the origin).
// Options: H (cell size in the contact zone |x| <= 8), QUADS (1: QUAD4, 0: TRIA3).
DefineConstant[H = 0.25, QUADS = 1];
R = 50; L = 200; D = 200; XC = 8;
Point(1) = {0, 0, 0, H}; Point(2) = {XC, 0, 0, H}; Point(3) = {40, 0, 0, 10 * H}; Point(4) = {L, 0, 0, 60 * H};
Point(5) = {L, -D, 0, 80 * H}; Point(6) = {0, -D, 0, 80 * H}; Point(7) = {0, -XC, 0, 1.5 * H};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 7};
Line(7) = {7, 1};
Curve Loop(1) = {-7, -6, -5, -4, -3, -2, -1}; Plane Surface(1) = {1}; // counter-clockwise
Point(10) = {0, R, 0, 40 * H}; Point(11) = {0, 0, 0, H};
Point(12) = {XC, R - Sqrt(R * R - XC * XC), 0, H};
Point(13) = {25, R - Sqrt(R * R - 25 * 25), 0, 10 * H};
Point(14) = {R, R, 0, 40 * H}; Point(15) = {0, XC, 0, 1.5 * H};
Circle(10) = {11, 10, 12}; Circle(11) = {12, 10, 13}; Circle(12) = {13, 10, 14};
Line(13) = {14, 10}; Line(14) = {10, 15}; Line(15) = {15, 11};
Curve Loop(2) = {10, 11, 12, 13, 14, 15}; Plane Surface(2) = {2};
Mesh.Algorithm = 6;
If (QUADS)
  Recombine Surface{1, 2};
  Mesh.RecombinationAlgorithm = 1;
EndIf
Physical Surface("BLOC") = {1}; Physical Surface("IND") = {2};
Physical Curve("BLOC_TOP") = {1, 2}; Physical Curve("BLOC_TOP_FAR") = {3}; Physical Curve("BLOC_SIDE") = {4};
Physical Curve("BLOC_BASE") = {5}; Physical Curve("BLOC_AXE") = {6, 7};
Physical Curve("IND_CONT") = {10, 11}; Physical Curve("IND_ARC") = {12}; Physical Curve("IND_TOP") = {13};
Physical Curve("IND_AXE") = {14, 15}; Physical Point("P0") = {11};
