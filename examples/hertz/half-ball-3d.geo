// An elastic half-ball of radius 1, flat side up (z = 1), its curved side down touching the
// rigid plane z = 0 at the origin. The mesh is graded from size `fine` within 0.12 of the
// first contact point to `coarse` beyond 0.6; "top", "contact" and "body" name the
// physical groups.
SetFactory("OpenCASCADE");
fine = 0.01;
coarse = 0.12;
Sphere(1) = {0, 0, 1, 1};
Box(2) = {-1.1, -1.1, 0, 2.2, 2.2, 1};
BooleanIntersection(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
Point(100) = {0, 0, 0};  // for the distance field only
Field[1] = Distance;
Field[1].PointsList = {100};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = fine;
Field[2].SizeMax = coarse;
Field[2].DistMin = 0.12;
Field[2].DistMax = 0.6;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
top() = Surface In BoundingBox {-1.1, -1.1, 0.999, 1.1, 1.1, 1.001};  // the flat side
curved() = Surface{:};
curved() -= top();  // the curved side
Physical Surface("top") = top();
Physical Surface("contact") = curved();
Physical Volume("body") = {3};
