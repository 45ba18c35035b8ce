// The paper's plate with a hole (examples/plate_with_hole: Pirzadeh et al. 2024, Sec. 4.1) as a Gmsh mesh of
// quadrilaterals for Discretization Type = Gmsh: 100 x 100 mm, hole of diameter 30 mm at (50, 50) mm, origin at
// the lower-left corner, with the lattice deck's two loading layers (3 mm, one horizon, wide) outside the left and
// right edges.
//   gmsh -2 plate_with_hole.geo -o plate_with_hole.msh
// The mesh is structured: outside the square [30, 70]^2 mm around the hole it is the lattice's 1 mm grid (its
// element centroids are the lattice's points), inside it an O-grid of 4 blocks, 40 elements along each quarter of
// the hole and 9 from the hole to the square. Peridynamics needs no conforming mesh: each element is one point.
// Physical groups (docs/input.md, "Gmsh"): every surface is block_1, named "plate"; the curve "hold_y" (y = 50 mm
// across the left layer) is a node set, the 6 elements touching it.
mm = 0.001;
xs[] = {0, 30*mm, 70*mm, 100*mm};   // grid lines of the outer blocks
n[] = {31, 41, 31};                 // nodes per grid line segment: 1 mm elements
For j In {0:3}
  For i In {0:3}
    Point(1 + 4*j + i) = {xs[i], xs[j], 0};
  EndFor
EndFor
// The outer blocks: grid cell (i, j) of the 3 x 3 grid but the centre one.
s = 0;
For j In {0:2}
  For i In {0:2}
    If (i != 1 || j != 1)
      p = 1 + 4*j + i;
      b = newl; Line(b) = {p, p + 1}; Line(b + 1) = {p + 1, p + 5}; Line(b + 2) = {p + 5, p + 4}; Line(b + 3) = {p + 4, p};
      Transfinite Curve{b, b + 2} = n[i]; Transfinite Curve{b + 1, b + 3} = n[j];
      cl = newll; Curve Loop(cl) = {b, b + 1, b + 2, b + 3};
      s = news; Plane Surface(s) = {cl};
      Transfinite Surface{s}; Recombine Surface{s};
      blocks[] += s;
    EndIf
  EndFor
EndFor
// The O-grid between the hole and the square [30, 70]^2 (corners: points 6, 7, 11, 10).
c = newp; Point(c) = {50*mm, 50*mm, 0};
a = 15*mm/Sqrt(2);
q = newp; Point(q) = {50*mm + a, 50*mm - a, 0}; Point(q + 1) = {50*mm + a, 50*mm + a, 0};
Point(q + 2) = {50*mm - a, 50*mm + a, 0}; Point(q + 3) = {50*mm - a, 50*mm - a, 0};
corner[] = {7, 11, 10, 6};          // the square's corners beside q, q + 1, q + 2, q + 3
For k In {0:3}
  arc[k] = newl; Circle(arc[k]) = {q + k, c, q + (k + 1) % 4};
  diagonal[k] = newl; Line(diagonal[k]) = {q + k, corner[k]};
  side[k] = newl; Line(side[k]) = {corner[k], corner[(k + 1) % 4]};
  Transfinite Curve{arc[k], side[k]} = 41;
  Transfinite Curve{diagonal[k]} = 10;
EndFor
For k In {0:3}
  cl = newll; Curve Loop(cl) = {diagonal[k], side[k], -diagonal[(k + 1) % 4], -arc[k]};  // counter-clockwise: areas > 0
  s = news; Plane Surface(s) = {cl};
  Transfinite Surface{s}; Recombine Surface{s};
  blocks[] += s;
EndFor
// The loading layers, 3 x 100 elements each; the left one in two halves, for the curve y = 50 mm between them
// (no Coherence: the blocks need not share their edges, and merging would drop that curve).
Macro Layer
  p = newp; Point(p) = {x0, y0, 0}; Point(p + 1) = {x0 + 3*mm, y0, 0};
  Point(p + 2) = {x0 + 3*mm, y0 + h, 0}; Point(p + 3) = {x0, y0 + h, 0};
  b = newl; Line(b) = {p, p + 1}; Line(b + 1) = {p + 1, p + 2}; Line(b + 2) = {p + 2, p + 3}; Line(b + 3) = {p + 3, p};
  Transfinite Curve{b, b + 2} = 4; Transfinite Curve{b + 1, b + 3} = h/mm + 1;
  cl = newll; Curve Loop(cl) = {b, b + 1, b + 2, b + 3};
  s = news; Plane Surface(s) = {cl};
  Transfinite Surface{s}; Recombine Surface{s};
  blocks[] += s;
Return
x0 = -3*mm; y0 = 0; h = 50*mm; Call Layer;
x0 = -3*mm; y0 = 50*mm; h = 50*mm; Call Layer;
hold = b;                           // the upper half's bottom edge: y = 50 mm across the left layer
x0 = 100*mm; y0 = 0; h = 100*mm; Call Layer;

Physical Surface("plate", 1) = {blocks[]};
Physical Curve("hold_y", 1) = {hold};
Mesh.MshFileVersion = 4.1;
