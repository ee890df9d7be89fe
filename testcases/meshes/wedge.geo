// A triangle extruded in 3 layers: a mesh of pentahedra (PENTA6; -order 2 gives PENTA18,
// with -setnumber Mesh.SecondOrderIncomplete 1 PENTA15).
// gmsh -3 wedge.geo -format msh22 -o wedge.msh
lc = 0.4;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
out[] = Extrude {0, 0, 1} { Surface{1}; Layers{3}; Recombine; };
Physical Surface("BASE") = {1};
Physical Volume("WEDGE") = {out[1]};
