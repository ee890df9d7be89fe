// The Lame ring of ../lame_cylinder/ring.geo meshed the way older meshers and Salome often leave
// it: every curve and the surface run clockwise, so the cells are numbered clockwise in the xy
// plane and the edge normals (ty, -tx) point into the body. Quarter ring a = 1 <= r <= b = 2
// (D_PLAN, C_PLAN), or its axisymmetric section [a, b] x [0, 0.5] (AXIS=1).
// Options: N (cells across the thickness), QUAD, ORDER, INCOMPLETE.
DefineConstant[AXIS = 0, N = 8, QUAD = 1, ORDER = 2, INCOMPLETE = 1];
a = 1; b = 2;
If (!AXIS)
  Point(1) = {0, 0, 0}; Point(2) = {a, 0, 0}; Point(3) = {b, 0, 0}; Point(4) = {0, b, 0}; Point(5) = {0, a, 0};
  Line(1) = {3, 2}; Circle(2) = {4, 1, 3}; Line(3) = {5, 4}; Circle(4) = {2, 1, 5};
  Curve Loop(1) = {4, 3, 2, 1}; Plane Surface(1) = {1};
  Transfinite Curve{1, 3} = N + 1; Transfinite Curve{2, 4} = 2 * N + 1;
  Physical Curve("BOTTOM") = {1}; Physical Curve("OUTER") = {2}; Physical Curve("LEFT") = {3};
  Physical Curve("INNER") = {4};
EndIf
If (AXIS)
  Point(2) = {a, 0, 0}; Point(3) = {b, 0, 0}; Point(4) = {b, 0.5, 0}; Point(5) = {a, 0.5, 0};
  Line(1) = {3, 2}; Line(2) = {4, 3}; Line(3) = {5, 4}; Line(4) = {2, 5};
  Curve Loop(1) = {4, 3, 2, 1}; Plane Surface(1) = {1};
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
