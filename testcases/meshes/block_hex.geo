// A 1 x 1 x 2 block of 2 x 2 x 4 hexahedra (transfinite, recombined); faces and volume groups.
// gmsh -3 block_hex.geo -format msh22 -o block_hex.msh
// (-order 2 gives HEXA27; add -setnumber Mesh.SecondOrderIncomplete 1 for HEXA20)
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 3;
Transfinite Surface{1};
Recombine Surface{1};
out[] = Extrude {0, 0, 2} { Surface{1}; Layers{4}; Recombine; };
Physical Surface("BOTTOM") = {1};
Physical Surface("TOP") = {out[0]};
Physical Volume("BLOCK") = {out[1]};
