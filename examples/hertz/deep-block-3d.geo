// An elastic block 4 x 4 x 2, its bottom face z = 0 on a rigid sphere that first touches it
// at the origin. The block is deep against the contact radius (a / depth about 0.01), so that
// Hertz' half-space solution holds, and the mesh is graded from size `fine` within 0.05 of
// the origin to `coarse` beyond 1.5. "contact" (the bottom face), "top" and "body" name
// the physical groups.
SetFactory("OpenCASCADE");
fine = 0.002;
coarse = 0.4;
Box(1) = {-2, -2, 0, 4, 4, 2};
Point(100) = {0, 0, 0};  // for the distance field only
Field[1] = Distance;
Field[1].PointsList = {100};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = fine;
Field[2].SizeMax = coarse;
Field[2].DistMin = 0.05;
Field[2].DistMax = 1.5;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Surface("contact") = Surface In BoundingBox {-2.1, -2.1, -0.001, 2.1, 2.1, 0.001};
Physical Surface("top") = Surface In BoundingBox {-2.1, -2.1, 1.999, 2.1, 2.1, 2.001};
Physical Volume("body") = {1};
