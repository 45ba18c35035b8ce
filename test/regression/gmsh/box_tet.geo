// check_gmsh.py's unstructured mesh: tetrahedra filling the box of box.geo (block_1), element size 1.5 mm, with
// box.geo's face groups (OpenCASCADE's box faces: 1 min x, 2 max x, 3 min y, 5 min z).
// gmsh -3 box_tet.geo -o box_tet.msh
SetFactory("OpenCASCADE");
Box(1) = {0.001, -0.0015, 0.0005, 0.006, 0.003, 0.003};
Physical Volume(1) = {1};
Physical Surface(1) = {1};
Physical Surface("right_end", 2) = {2};
Physical Surface(3) = {3};
Physical Surface("bottom", 4) = {5};
Mesh.CharacteristicLengthMax = 0.0015;
Mesh.MshFileVersion = 4.1;
