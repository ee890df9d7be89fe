// Unit square of 2 x 2 QUAD4 in the plane z = 0, a POI1 cell at each of its 4 corners (the
// springs) and the edge x = 1 for the pressure. gmsh -2 square.geo -format msh22 -o square.msh
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 3;
Transfinite Surface{1};
Recombine Surface{1};
Physical Point("CORNERS") = {1, 2, 3, 4};
Physical Curve("XMAX") = {2};
Physical Surface("PLATE") = {1};
