// A 2 x 1 x 1 block meshed with tetrahedra; physical groups for the faces and the volume.
// gmsh -3 block_tet.geo -format msh22 -o block_tet.msh   (add -order 2 for TETRA10)
lc = 0.35;
Point(1) = {0, 0, 0, lc}; Point(2) = {2, 0, 0, lc}; Point(3) = {2, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
out[] = Extrude {0, 0, 1} { Surface{1}; };
Physical Surface("BOTTOM") = {1};
Physical Surface("TOP") = {out[0]};
Physical Surface("LEFT") = {out[5]};
Physical Surface("RIGHT") = {out[3]};
Physical Volume("BLOCK") = {out[1]};
