// A square with a square hole (refused: a region is one loop):
// gmsh -2 -order 2 -format msh41 holed.geo -o holed.msh
lc = 0.01;
Point(1) = {0, 0, 0, lc};
Point(2) = {0.04, 0, 0, lc};
Point(3) = {0.04, 0.04, 0, lc};
Point(4) = {0, 0.04, 0, lc};
Point(5) = {0.015, 0.015, 0, lc};
Point(6) = {0.025, 0.015, 0, lc};
Point(7) = {0.025, 0.025, 0, lc};
Point(8) = {0.015, 0.025, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
Physical Curve("outer") = {1, 2, 3, 4};
Physical Surface("solid") = {1};
