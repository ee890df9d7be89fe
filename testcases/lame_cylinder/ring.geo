// Quarter of a thick ring a = 1 <= r <= b = 2 (D_PLAN), or its axisymmetric section (AXIS=1):
// the rectangle [a, b] x [0, 0.5]. Curves run counter-clockwise around the domain so edge
// normals point out. Options: N (cells across the thickness), QUAD, ORDER, INCOMPLETE.
DefineConstant[AXIS = 0, N = 8, QUAD = 1, ORDER = 2, INCOMPLETE = 1];
a = 1; b = 2;
If (!AXIS)
  Point(1) = {0, 0, 0}; Point(2) = {a, 0, 0}; Point(3) = {b, 0, 0}; Point(4) = {0, b, 0}; Point(5) = {0, a, 0};
  Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
  Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
  Transfinite Curve{1, 3} = N + 1; Transfinite Curve{2, 4} = 2 * N + 1;
  Physical Curve("BOTTOM") = {1}; Physical Curve("OUTER") = {2}; Physical Curve("LEFT") = {3};
  Physical Curve("INNER") = {4};
EndIf
If (AXIS)
  Point(2) = {a, 0, 0}; Point(3) = {b, 0, 0}; Point(4) = {b, 0.5, 0}; Point(5) = {a, 0.5, 0};
  Line(1) = {2, 3}; Line(2) = {3, 4}; Line(3) = {4, 5}; Line(4) = {5, 2};
  Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
  Transfinite Curve{1, 3} = N + 1; Transfinite Curve{2, 4} = N / 2 + 1;
  Physical Curve("BOTTOM") = {1}; Physical Curve("OUTER") = {2}; Physical Curve("TOP") = {3};
  Physical Curve("INNER") = {4};
EndIf
Transfinite Surface{1};
If (QUAD)
  Recombine Surface{1};
EndIf
Mesh.ElementOrder = ORDER;
Mesh.SecondOrderIncomplete = INCOMPLETE;
Physical Surface("ALL") = {1};
