// NAFEMS contact benchmark 1 (A. Konter, NAFEMS R0094), the 2D cylindrical roller: half model
// (symmetry plane x = 0), plane strain, units mm. Block 0 <= x <= W/2, -200 <= y <= 0 (full block
// W x 200); cylinder of diameter 100, centre (0, 50), touching the block at the origin; only its
// lower quarter (y <= 50) is meshed, its cut y = 50 carries the load at the centre (point C).
// Under the contact the block is a structured square [0, XS] x [-XS, 0] of QUAD4 of size H;
// elsewhere free quadrilaterals graded to about 60 H. All surfaces counter-clockwise.
// Groups: BLOC, CYL (surfaces); BLOC_TOP (x <= 40, master), BLOC_TOP_FAR, BLOC_SIDE, BLOC_BASE,
// BLOC_AXE, TOP_IN (x <= 23 H), TOP_OUT (26 H <= x <= XS); CYL_CONT (arc x <= 25, slave), CYL_ARC (rest of the arc), CYL_TOP (cut y = 50),
// CYL_AXE; points B (block, origin), P0 (cylinder, origin), C (cylinder centre, loaded).
// Options: H (cell size under the contact), W (full block width), UNIT (length factor: 1 for mm,
// 1e-3 for m: the same mesh in other units, nodes scaled exactly).
DefineConstant[H = 0.25, W = 200, UNIT = 1];
R = 50; D = 200; XS = 12; XC = 12;
// block
Point(1) = {0, 0, 0, H}; Point(2) = {XS, 0, 0, H}; Point(3) = {XS, -XS, 0, H}; Point(4) = {0, -XS, 0, H};
Point(5) = {40, 0, 0, 12 * H}; Point(6) = {W / 2, 0, 0, 60 * H}; Point(7) = {W / 2, -D, 0, 80 * H};
Point(8) = {0, -D, 0, 80 * H};
// the top under the contact is cut at a - h and a + h (XIN, XOUT: whole cells of size H) so that
// the contact edge can be tested within one cell (groups TOP_IN, TOP_OUT)
XIN = 23 * H; XOUT = 26 * H;
Point(16) = {XIN, 0, 0, H}; Point(17) = {XOUT, 0, 0, H};
Line(1) = {1, 16}; Line(16) = {16, 17}; Line(17) = {17, 2};
Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 7}; Line(8) = {7, 8}; Line(9) = {8, 4};
N = Round(XS / H) + 1;
Transfinite Curve{2, 3, 4} = N;
Transfinite Curve{1} = 24; Transfinite Curve{16} = 4; Transfinite Curve{17} = N - 26;
Curve Loop(1) = {-3, -2, -17, -16, -1, -4}; Plane Surface(1) = {1}; // counter-clockwise
Transfinite Surface{1} = {4, 3, 2, 1};
Curve Loop(2) = {-9, -8, -7, -6, -5, 2, 3}; Plane Surface(2) = {2};
// cylinder (lower quarter)
Point(10) = {0, R, 0, 40 * H}; Point(11) = {0, 0, 0, H};
Point(12) = {XC, R - Sqrt(R * R - XC * XC), 0, H};
Point(13) = {25, R - Sqrt(R * R - 25 * 25), 0, 10 * H};
Point(14) = {R, R, 0, 40 * H}; Point(15) = {0, XC, 0, 2 * H};
Circle(10) = {11, 10, 12}; Circle(11) = {12, 10, 13}; Circle(12) = {13, 10, 14};
Line(13) = {14, 10}; Line(14) = {10, 15}; Line(15) = {15, 11};
Transfinite Curve{10} = N;
Curve Loop(3) = {10, 11, 12, 13, 14, 15}; Plane Surface(3) = {3};
Mesh.Algorithm = 6;
Recombine Surface{1, 2, 3};
Mesh.RecombinationAlgorithm = 1;
Physical Surface("BLOC") = {1, 2}; Physical Surface("CYL") = {3};
Physical Curve("BLOC_TOP") = {1, 16, 17, 5}; Physical Curve("TOP_IN") = {1}; Physical Curve("TOP_OUT") = {17}; Physical Curve("BLOC_TOP_FAR") = {6}; Physical Curve("BLOC_SIDE") = {7};
Physical Curve("BLOC_BASE") = {8}; Physical Curve("BLOC_AXE") = {4, 9};
Physical Curve("CYL_CONT") = {10, 11}; Physical Curve("CYL_ARC") = {12}; Physical Curve("CYL_TOP") = {13};
Physical Curve("CYL_AXE") = {14, 15};
Physical Point("B") = {1}; Physical Point("P0") = {11}; Physical Point("C") = {10};
Mesh.ScalingFactor = UNIT;
