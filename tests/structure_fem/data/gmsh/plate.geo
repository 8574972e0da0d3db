// A 2 m x 1 m plate: clamped on the left, the interface on top and right; 6-node triangles.
Point(1) = {0, 0, 0, 0.5};
Point(2) = {2, 0, 0, 0.5};
Point(3) = {2, 1, 0, 0.5};
Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("clamped") = {4};
Physical Curve("interface") = {2, 3};
Physical Surface("solid") = {1};
