// check_gmsh.py's box: 6x3x3 hex cells of 1 mm at (0.001, -0.0015, 0.0005), the lattice of check_exodus.py.
// Volume 1: the two lower layers (block_1); volume 7, named "top": the top layer. Face groups as check_exodus.py's
// node sets: 1 (min x, unnamed: nodelist_1), "right_end" (max x), 3 (min y: nodelist_3), "bottom" (min z).
// gmsh -3 box.geo -o box.msh; gmsh -3 box.geo -bin -o box_bin.msh
x0 = 0.001; y0 = -0.0015; z0 = 0.0005; h = 0.001;
Point(1) = {x0, y0, z0, h};
l[] = Extrude {6*h, 0, 0} { Point{1}; Layers{6}; Recombine; };
s[] = Extrude {0, 3*h, 0} { Line{l[1]}; Layers{3}; Recombine; };
v1[] = Extrude {0, 0, 2*h} { Surface{s[1]}; Layers{2}; Recombine; };
v2[] = Extrude {0, 0, h} { Surface{v1[0]}; Layers{1}; Recombine; };
Physical Volume(1) = {v1[1]};
Physical Volume("top", 7) = {v2[1]};
e = 1e-9;
Physical Surface(1) = {Surface In BoundingBox {x0-e, y0-e, z0-e, x0+e, y0+3*h+e, z0+3*h+e}};
Physical Surface("right_end", 2) = {Surface In BoundingBox {x0+6*h-e, y0-e, z0-e, x0+6*h+e, y0+3*h+e, z0+3*h+e}};
Physical Surface(3) = {Surface In BoundingBox {x0-e, y0-e, z0-e, x0+6*h+e, y0+e, z0+3*h+e}};
Physical Surface("bottom", 4) = {Surface In BoundingBox {x0-e, y0-e, z0-e, x0+6*h+e, y0+3*h+e, z0+e}};
Mesh.MshFileVersion = 4.1;
