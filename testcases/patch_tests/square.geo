// Unit-square patch [X0, X0 + 1] x [0, 1] meshed unstructured (distorted cells). Boundary curves
// run counter-clockwise, so every edge's normal (t_y, -t_x) points out of the square.
// Options (gmsh -setnumber): X0 (left abscissa), QUAD (1: recombine into quadrangles),
// ORDER (1 or 2), INCOMPLETE (1: serendipity QUAD8), THREED (1: extrude in z, LAYERS cells).
DefineConstant[X0 = 0, QUAD = 0, ORDER = 1, INCOMPLETE = 0, THREED = 0, LAYERS = 2, STRUCT = 0];
h = 0.3;
Point(1) = {X0, 0, 0, h}; Point(2) = {X0 + 1, 0, 0, h}; Point(3) = {X0 + 1, 1, 0, h}; Point(4) = {X0, 1, 0, h};
Point(5) = {X0 + 0.37, 0.58, 0, h / 2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Point{5} In Surface{1};
If (QUAD)
  Recombine Surface{1};
EndIf
Mesh.ElementOrder = ORDER;
Mesh.SecondOrderIncomplete = INCOMPLETE;
If (!THREED)
  Physical Curve("BOTTOM") = {1};
  Physical Curve("RIGHT") = {2};
  Physical Curve("TOP") = {3};
  Physical Curve("LEFT") = {4};
  Physical Surface("ALL") = {1};
EndIf
If (THREED)
  If (STRUCT)
    out[] = Extrude {0, 0, 1} { Surface{1}; Layers{LAYERS}; Recombine; };
  Else
    out[] = Extrude {0, 0, 1} { Surface{1}; };
  EndIf
  Physical Surface("Z0") = {1};
  Physical Surface("Z1") = {out[0]};
  Physical Volume("ALL") = {out[1]};
  Physical Surface("Y0") = {out[2]};
  Physical Surface("X1") = {out[3]};
  Physical Surface("Y1") = {out[4]};
  Physical Surface("X0") = {out[5]};
EndIf
