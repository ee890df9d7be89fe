// Quarter of a thick ring a = 1 <= r <= b = 2 extruded to a slab 0 <= z <= H = 0.25 (3D), with
// N cells across the thickness, 2N around, max(1, N/4) layers. Faces: INNER (pressure), LEFT
// (x = 0), BOTTOM (y = 0), ZMIN, ZMAX; volume ALL. Options: N, HEX (1: HEXA, 0: TETRA), ORDER,
// INCOMPLETE. gmsh -3 ring3d.geo -format msh22 -setnumber N 4 -o ring3d.msh
DefineConstant[N = 4, HEX = 1, ORDER = 1, INCOMPLETE = 1];
a = 1; b = 2; H = 0.25;
Point(1) = {0, 0, 0}; Point(2) = {a, 0, 0}; Point(3) = {b, 0, 0}; Point(4) = {0, b, 0}; Point(5) = {0, a, 0};
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = N + 1; Transfinite Curve{2, 4} = 2 * N + 1;
Transfinite Surface{1};
If (HEX)
  Recombine Surface{1};
  out[] = Extrude {0, 0, H} { Surface{1}; Layers{Ceil(N / 4)}; Recombine; };
EndIf
If (!HEX)
  out[] = Extrude {0, 0, H} { Surface{1}; Layers{Ceil(N / 4)}; };
EndIf
// out[0] = top, out[1] = volume, out[2..5] = sides from curves 1, 2, 3, 4
Physical Surface("ZMIN") = {1};
Physical Surface("ZMAX") = {out[0]};
Physical Surface("BOTTOM") = {out[2]};
Physical Surface("OUTER") = {out[3]};
Physical Surface("LEFT") = {out[4]};
Physical Surface("INNER") = {out[5]};
Physical Volume("ALL") = {out[1]};
Mesh.ElementOrder = ORDER;
Mesh.SecondOrderIncomplete = INCOMPLETE;
