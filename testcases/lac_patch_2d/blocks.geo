// Two blocks for the LAC patch test (ssnp170-like, 2D): LOW = [0,1]x[0,1], UP = [0,1]x[1,2], each
// meshed on its own (nodes duplicated on y = 1), NLOW and NUP cells along x (non-matching),
// 2 cells along y; UP is lifted by GAP (the closing-gap case). QLOW/QUP = 1 recombines into quadrangles; ORDER 2 (INCOMPLETE 1: serendipity).
DefineConstant[ NLOW = 4, NUP = 3, QLOW = 0, QUP = 0, ORDER = 1, INCOMPLETE = 0, GAP = 0 ];
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {0, 1 + GAP, 0}; Point(6) = {1, 1 + GAP, 0}; Point(7) = {1, 2 + GAP, 0}; Point(8) = {0, 2 + GAP, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3} = NLOW + 1; Transfinite Curve{2, 4} = 3;
Transfinite Curve{5, 7} = NUP + 1; Transfinite Curve{6, 8} = 3;
If (QLOW == 1)
  Transfinite Surface{1}; Recombine Surface{1};
EndIf
If (QUP == 1)
  Transfinite Surface{2}; Recombine Surface{2};
EndIf
Mesh.ElementOrder = ORDER;
Mesh.SecondOrderIncomplete = INCOMPLETE;
Physical Curve("BAS") = {1};
Physical Curve("LOW_TOP") = {3};
Physical Curve("LOW_LEFT") = {4};
Physical Curve("UP_BOT") = {5};
Physical Curve("UP_TOP") = {7};
Physical Curve("UP_LEFT") = {8};
Physical Surface("LOW") = {1};
Physical Surface("UP") = {2};
