// Two stacked rectangles for 2D contact: block B (lower, 0<y<1) and block C (upper, 1<y<1.5,
// narrower). Quadrangles; groups Top_B / Bottom_C (the contact edges), Bottom_B (clamped edge),
// Top_C (loaded edge), and the surfaces B and C.
// gmsh -2 two_blocks_2d.geo -format msh22 -o two_blocks_2d.msh
n = 6;
Point(1) = {0, 0, 0}; Point(2) = {2, 0, 0}; Point(3) = {2, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {0.5, 1, 0}; Point(6) = {1.5, 1, 0}; Point(7) = {1.5, 1.5, 0}; Point(8) = {0.5, 1.5, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3} = 2 * n + 1; Transfinite Curve{2, 4} = n + 1;
Transfinite Curve{5, 7} = n + 2; Transfinite Curve{6, 8} = n / 2 + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Curve("Bottom_B") = {1};
Physical Curve("Top_B") = {3};
Physical Curve("Bottom_C") = {5};
Physical Curve("Top_C") = {7};
Physical Surface("B") = {1};
Physical Surface("C") = {2};
