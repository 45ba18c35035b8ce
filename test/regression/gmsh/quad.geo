// check_gmsh.py's 2D mesh: 4x2 quadrilaterals of 1 mm on [0, 0.004] x [0.002, 0.004] (z = 0), counter-clockwise
// (normal +z, positive areas); physical surface 1 (block_1), physical curve 1 = the x = 0 edge (nodelist_1).
// gmsh -2 quad.geo -o quad.msh
Point(1) = {0, 0.002, 0}; Point(2) = {0.004, 0.002, 0}; Point(3) = {0.004, 0.004, 0}; Point(4) = {0, 0.004, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 5; Transfinite Curve{2, 4} = 3;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface(1) = {1};
Physical Curve(1) = {4};
Mesh.MshFileVersion = 4.1;
