// The thick-tube section of testcases/plastic_tube (a = 10 <= r <= b = 20, 0 <= z <= L = 10),
// structured quadrangles of size H: N = 10/H cells across the wall, N/2 along it. ORDER 2 makes
// QUAD8 (incomplete), 1 QUAD4.
DefineConstant[H = 1, ORDER = 1];
SetFactory("Built-in");
a = 10; b = 20; L = 10; N = Round((b - a) / H); M = Round(L / H / 2);
Point(1) = {a, 0, 0}; Point(2) = {b, 0, 0}; Point(3) = {b, L, 0}; Point(4) = {a, L, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = N + 1; Transfinite Curve{2, 4} = M + 1;
Transfinite Surface{1}; Recombine Surface{1};
Mesh.ElementOrder = ORDER;
Mesh.SecondOrderIncomplete = 1;
Physical Surface("TUBE") = {1}; Physical Curve("INNER") = {4}; Physical Curve("BOTTOM") = {1}; Physical Curve("TOP") = {3};
