// Unit cube of 2 x 2 x 2 HEXA8, a POI1 cell at each of its 8 corners (the springs) and the face
// x = 1 for the pressure. gmsh -3 cube.geo -format msh22 -o cube.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Transfinite Curve{:} = 3;
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{1};
Physical Point("CORNERS") = {1, 2, 3, 4, 5, 6, 7, 8};
Physical Surface("XMAX") = {2};
Physical Volume("BLOCK") = {1};
