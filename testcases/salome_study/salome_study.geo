// gmsh -2 salome_study.geo -format msh22 -o salome_study.msh, then converted to MED by make_mesh.sh.
// Salome-style: curve loops traversed clockwise, so every 2D cell is numbered clockwise in xy.
W = 1.0; H1 = 1.0; H2 = 0.5;
Point(1) = {0, 0, 0, 0.1}; Point(2) = {W, 0, 0, 0.1}; Point(3) = {W, H1, 0, 0.1}; Point(4) = {0, H1, 0, 0.1};
Point(5) = {0, H1, 0, 0.07}; Point(6) = {W, H1, 0, 0.07}; Point(7) = {W, H1+H2, 0, 0.07}; Point(8) = {0, H1+H2, 0, 0.07};
Line(1) = {1, 4}; Line(2) = {4, 3}; Line(3) = {3, 2}; Line(4) = {2, 1};
Line(5) = {5, 8}; Line(6) = {8, 7}; Line(7) = {7, 6}; Line(8) = {6, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3} = 9; Transfinite Curve{2, 4} = 11;
// The contact edges carry the same 10 segments on both sides (as a compound mesh of Salome gives).
Transfinite Curve{8} = 11;
Transfinite Surface{1}; Recombine Surface{1};
Physical Surface("Fondation") = {1};
Physical Surface("Patin") = {2};
Physical Curve("Fond_Haut") = {2};
Physical Curve("Fond_Bas") = {4};
Physical Curve("Sym_Fond") = {1};
Physical Curve("Patin_Bas") = {8};
Physical Curve("Patin_Haut") = {6};
Physical Curve("Sym_Patin") = {5};
