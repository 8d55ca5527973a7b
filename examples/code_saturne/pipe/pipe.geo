// A straight pipe section for code_saturne, all hexahedra: an O-grid ("butterfly") cross-section
// in the y-z plane, extruded along the axis x. Gravity is -y (vertical), so y is the vertical
// diameter and z the horizontal one.
//   gmsh -3 -format msh41 -setnumber D 0.05 -setnumber L 0.2 ... pipe.geo -o pipe.msh
// Parameters (override with -setnumber):
//   D   pipe diameter (m)                  L   section length (m), the streamwise period
//   NC  cells per quarter of the circumference (and per side of the core square)
//   NR  cells across the ring between core and wall
//   GR  ratio of neighbouring ring cells, growing from the wall (first cell the smallest)
//   NX  cells along the axis
// Physical groups: "wall" (the pipe wall), "inlet" (x = 0), "outlet" (x = L), "fluid". The
// inlet and outlet faces are node-for-node translates, which code_saturne joins into a
// periodic pair (cs_user_mesh.c).
If (!Exists(D))  D = 0.05; EndIf
If (!Exists(L))  L = 0.2; EndIf
If (!Exists(NC)) NC = 8; EndIf
If (!Exists(NR)) NR = 10; EndIf
If (!Exists(GR)) GR = 1.15; EndIf
If (!Exists(NX)) NX = 20; EndIf
R = D / 2;
a = 0.55 * R / Sqrt(2);   // half-diagonal of the core square over sqrt(2): its corners at 0.55 R

Point(1) = {0, 0, 0};
// core square corners (at 45 deg) and wall points (at 45 deg)
Point(2) = {0,  a,  a}; Point(3) = {0, -a,  a}; Point(4) = {0, -a, -a}; Point(5) = {0,  a, -a};
c = R / Sqrt(2);
Point(6) = {0,  c,  c}; Point(7) = {0, -c,  c}; Point(8) = {0, -c, -c}; Point(9) = {0,  c, -c};

Line(1) = {2, 3}; Line(2) = {3, 4}; Line(3) = {4, 5}; Line(4) = {5, 2};        // core
Circle(5) = {6, 1, 7}; Circle(6) = {7, 1, 8}; Circle(7) = {8, 1, 9}; Circle(8) = {9, 1, 6};  // wall
Line(9) = {2, 6}; Line(10) = {3, 7}; Line(11) = {4, 8}; Line(12) = {5, 9};    // radial

Transfinite Line {1, 2, 3, 4, 5, 6, 7, 8} = NC + 1;
// radial lines run core -> wall: cells shrink towards the wall
Transfinite Line {9, 10, 11, 12} = NR + 1 Using Progression 1 / GR;

Curve Loop(1) = {1, 2, 3, 4};           Plane Surface(1) = {1};
Curve Loop(2) = {9, 5, -10, -1};        Plane Surface(2) = {2};
Curve Loop(3) = {10, 6, -11, -2};       Plane Surface(3) = {3};
Curve Loop(4) = {11, 7, -12, -3};       Plane Surface(4) = {4};
Curve Loop(5) = {12, 8, -9, -4};        Plane Surface(5) = {5};
Transfinite Surface {1, 2, 3, 4, 5};
Recombine Surface {1, 2, 3, 4, 5};

out[] = Extrude {L, 0, 0} { Surface{1, 2, 3, 4, 5}; Layers{NX}; Recombine; };
// out[] per surface: [top, volume, 4 sides]; 6 entries each
Physical Surface("inlet") = {1, 2, 3, 4, 5};
Physical Surface("outlet") = {out[0], out[6], out[12], out[18], out[24]};
// the wall: for ring surface k (k = 2..5), the side extruded from its circle (loop order:
// radial, circle, radial, core side -> side index 3 of 4, i.e. out[6k + 3])
Physical Surface("wall") = {out[6 + 3], out[12 + 3], out[18 + 3], out[24 + 3]};
Physical Volume("fluid") = {out[1], out[7], out[13], out[19], out[25]};
