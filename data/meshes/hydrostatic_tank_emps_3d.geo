// The 3-D hydrostatic tank's inside, 0.2 x 0.4 x 0.2 m (y up), as a Gmsh surface of 116 triangles:
// gmsh -2 -format msh41 hydrostatic_tank_emps_3d.geo -o hydrostatic_tank_emps_3d.msh (Gmsh 4.8.4).
L = 0.2; H = 0.4; h = 0.1;
Point(1) = {0, 0, 0, h}; Point(2) = {L, 0, 0, h}; Point(3) = {L, H, 0, h}; Point(4) = {0, H, 0, h};
Point(5) = {0, 0, L, h}; Point(6) = {L, 0, L, h}; Point(7) = {L, H, L, h}; Point(8) = {0, H, L, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Line(9) = {1, 5}; Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};
// Each face's curve loop runs counter-clockwise seen from inside the tank: its triangles' normals
// point into the water (the fluid side of a tank wall).
Curve Loop(1) = {9, 5, -10, -1};   Plane Surface(1) = {1}; // floor y = 0
Curve Loop(2) = {-3, 11, 7, -12};  Plane Surface(2) = {2}; // top y = H
Curve Loop(3) = {1, 2, 3, 4};      Plane Surface(3) = {3}; // z = 0
Curve Loop(4) = {-8, -7, -6, -5};  Plane Surface(4) = {4}; // z = L
Curve Loop(5) = {-4, 12, 8, -9};   Plane Surface(5) = {5}; // x = 0
Curve Loop(6) = {10, 6, -11, -2};  Plane Surface(6) = {6}; // x = L
Physical Surface("tank") = {1, 2, 3, 4, 5, 6};
