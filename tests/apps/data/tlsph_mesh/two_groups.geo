// rectangle.geo with its left side in two physical groups (refused: a side has one tag):
// gmsh -2 -order 2 -format msh41 two_groups.geo -o two_groups.msh
lc = 0.01;
Point(1) = {0, 0, 0, lc};
Point(2) = {0.02, 0, 0, lc};
Point(3) = {0.02, 0.04, 0, lc};
Point(4) = {0, 0.04, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Curve("wall") = {4};
Physical Surface("solid") = {1};
