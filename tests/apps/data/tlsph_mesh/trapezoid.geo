// The trapezoid of tests/apps/test_tlsph_plugin.cpp, (0, 0), (0.04, 0), (0.03, 0.02), (0, 0.02),
// its slope tagged; the left side in no physical group (tagged 'boundary'):
// gmsh -2 -order 2 -format msh22 trapezoid.geo -o trapezoid.msh
lc = 0.008;
Point(1) = {0, 0, 0, lc};
Point(2) = {0.04, 0, 0, lc};
Point(3) = {0.03, 0.02, 0, lc};
Point(4) = {0, 0.02, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("bottom") = {1};
Physical Curve("slope") = {2};
Physical Curve("top") = {3};
Physical Surface("solid") = {1};
