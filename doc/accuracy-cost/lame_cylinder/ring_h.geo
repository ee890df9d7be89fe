// The Lame ring of testcases/lame_cylinder/ring.geo with its cell size H (thickness b - a = 1,
// so N = 1/H cells across it) instead of the count N: the x axis of the sweep's second panel.
DefineConstant[H = 0.125];
N = Round(1 / H);
Include "../../../testcases/lame_cylinder/ring.geo";
