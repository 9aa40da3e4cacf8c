// meshes/panel.geo: the demonstration solar-array panel of ../shared/docs/solar-array.md, the same
// model as meshes/panel.bdf, for gmsh. Properties, masses and node ids: meshes/panel.props.bdf
// (read by seflex with this file; docs/gmsh-input.md).
//
// Panel frame: origin at the plate centre, x = stack normal, y across the width (1.0), z along the
// hinge lines (1.2). Units SI (m).
//
// refine = elements along each side of one cell of the 4 x 4 grid (cells 0.25 in y by 0.3 in z):
//   refine = 1 is panel.bdf's 4 x 4 mesh; the plate has (4 refine + 1)^2 nodes, 6 dofs each, plus the
//   6 hinge points: refine 8 -> 6,570 dofs, 32 -> 99,882, 102 -> 1,003,722.
//   seflex: --set refine=8      gmsh: gmsh panel.geo -2 -setnumber refine 8 (or the GUI parameter list)
// The 25 grid points (the CONM2 mass points), the edge members' and brackets' nodes are geometry
// points, hence mesh nodes at every refinement: the physical model stays the same and converges.
DefineConstant[ refine = {1, Min 1, Max 200, Step 1, Name "Parameters/refine"} ];
If (refine < 1 || refine != Floor(refine))
  Error("refine = %g: expected a whole number >= 1", refine);
EndIf

ys[] = {-0.5, -0.25, 0, 0.25, 0.5};
zs[] = {-0.6, -0.3, 0, 0.3, 0.6};

// Plate grid points: p(iy, iz) = 1 + 5 iy + iz (tags 1-25; the centre is 13).
For iy In {0:4}
  For iz In {0:4}
    Point(1 + 5*iy + iz) = {0, ys[iy], zs[iz]};
  EndFor
EndFor
// Lines along z: 100 + 4 iy + iz from p(iy, iz) to p(iy, iz+1); along y: 200 + 5 iy + iz from
// p(iy, iz) to p(iy+1, iz).
For iy In {0:4}
  For iz In {0:3}
    Line(100 + 4*iy + iz) = {1 + 5*iy + iz, 2 + 5*iy + iz};
  EndFor
EndFor
For iy In {0:3}
  For iz In {0:4}
    Line(200 + 5*iy + iz) = {1 + 5*iy + iz, 6 + 5*iy + iz};
  EndFor
EndFor
// Cells: surface 300 + 4 iy + iz, corners p(iy,iz) p(iy+1,iz) p(iy+1,iz+1) p(iy,iz+1): normal +x.
For iy In {0:3}
  For iz In {0:3}
    Curve Loop(300 + 4*iy + iz) = {200 + 5*iy + iz, 100 + 4*(iy+1) + iz, -(201 + 5*iy + iz), -(100 + 4*iy + iz)};
    Plane Surface(300 + 4*iy + iz) = {300 + 4*iy + iz};
    Transfinite Surface{300 + 4*iy + iz} = {1 + 5*iy + iz, 6 + 5*iy + iz, 7 + 5*iy + iz, 2 + 5*iy + iz};
    Recombine Surface{300 + 4*iy + iz};
  EndFor
EndFor
Transfinite Curve{100:119, 200:219} = refine + 1;

// Hinge points (ids 1-6 of solar-array.md): edge A (y = +0.5) at x = -0.02, edge B (y = -0.5) at
// x = +0.02; one bracket (line 400 + h, one element) from the edge point at the same z.
Point(31) = {-0.02, 0.5, -0.3};  Line(401) = {22, 31};   // 1: A, z = -0.3
Point(32) = {-0.02, 0.5, 0.3};   Line(402) = {24, 32};   // 2: A, z = +0.3
Point(33) = {0.02, -0.5, -0.3};  Line(403) = {2, 33};    // 3: B, z = -0.3
Point(34) = {0.02, -0.5, 0.3};   Line(404) = {4, 34};    // 4: B, z = +0.3
Point(35) = {-0.02, 0.5, 0};     Line(405) = {23, 35};   // 5: A, z = 0
Point(36) = {0.02, -0.5, 0};     Line(406) = {3, 36};    // 6: B, z = 0
Transfinite Curve{401:406} = 2;

Physical Surface("plate") = {300:315};
Physical Curve("edges") = {116:119, 100:103};   // edge A (y = +0.5), edge B (y = -0.5)
Physical Curve("brackets") = {401:406};
Physical Point("masses") = {1:25};
Physical Point("hinge1") = {31};
Physical Point("hinge2") = {32};
Physical Point("hinge3") = {33};
Physical Point("hinge4") = {34};
Physical Point("hinge5") = {35};
Physical Point("hinge6") = {36};
Physical Point("frame") = {13};
Physical Point("interface_3d") = {31, 32, 33, 34};
Physical Point("interface_beam") = {35, 36};
