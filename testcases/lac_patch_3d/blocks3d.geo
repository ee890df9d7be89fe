// Two blocks for the 3D LAC patch test (ssnp170-like): LOW = [0,1]^2 x [0,1], UP = [0,1]^2 x [1,2],
// meshed on their own (nodes duplicated on z = 1), NLOW and NUP cells along x and y (non-matching),
// 2 along z. HLOW/HUP = 1: hexahedra (transfinite), else tetrahedra. ORDER 2 with INCOMPLETE 1.
SetFactory("OpenCASCADE");
DefineConstant[ NLOW = 3, NUP = 2, HLOW = 1, HUP = 1, ORDER = 1, INCOMPLETE = 1 ];
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {0, 0, 1, 1, 1, 1};
low() = Unique(Abs(Boundary{ Surface{1:6}; }));
up() = Unique(Abs(Boundary{ Surface{7:12}; }));
For i In {0 : #low() - 1}
  bb() = BoundingBox Curve{low(i)};
  If (Fabs(bb(5) - bb(2)) > 0.5)
    Transfinite Curve{low(i)} = 3;
  Else
    Transfinite Curve{low(i)} = NLOW + 1;
  EndIf
EndFor
For i In {0 : #up() - 1}
  bb() = BoundingBox Curve{up(i)};
  If (Fabs(bb(5) - bb(2)) > 0.5)
    Transfinite Curve{up(i)} = 3;
  Else
    Transfinite Curve{up(i)} = NUP + 1;
  EndIf
EndFor
If (HLOW == 1)
  Transfinite Surface{1:6}; Recombine Surface{1:6}; Transfinite Volume{1};
EndIf
If (HUP == 1)
  Transfinite Surface{7:12}; Recombine Surface{7:12}; Transfinite Volume{2};
EndIf
Mesh.ElementOrder = ORDER;
Mesh.SecondOrderIncomplete = INCOMPLETE;
Physical Surface("LOW_X0") = {1};
Physical Surface("LOW_Y0") = {3};
Physical Surface("BAS") = {5};
Physical Surface("LOW_TOP") = {6};
Physical Surface("UP_X0") = {7};
Physical Surface("UP_Y0") = {9};
Physical Surface("UP_BOT") = {11};
Physical Surface("UP_TOP") = {12};
Physical Volume("LOW") = {1};
Physical Volume("UP") = {2};
