// An elastic half-ball of radius 1 (flat side up at z = 1, centre (0, 0, 1)) resting on an
// elastic block [-2, 2] x [-2, 2] x [-2, 0], meshed apart: the ball touches the block's top
// at the origin. The ball is cut at the height of 30 degrees around its lowest point, so
// that its cap there is a surface of its own (the slave side); the OpenCASCADE volumes of the
// two bodies share nothing. Both meshes are graded from `fine` near the origin to `coarse`.
// Physical groups: bodies "ball" and "block"; boundaries "top" (the ball's flat side), "cap",
// "block top" and "block bottom".
SetFactory("OpenCASCADE");
fine = 0.02;
coarse = 0.25;
Sphere(1) = {0, 0, 1, 1};
Box(2) = {-1.1, -1.1, 0, 2.2, 2.2, 1};
BooleanIntersection(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
cut = 1 - Cos(Pi / 6);
Box(4) = {-1.1, -1.1, cut, 2.2, 2.2, 1};  // the ball above the cap
ball() = BooleanFragments{Volume{3}; Delete;}{Volume{4}; Delete;};
Recursive Delete{Volume{ball({2:#ball()-1})};}  // the box beyond the ball, if any is left
Box(10) = {-2, -2, -2, 4, 4, 2};
Point(100) = {0, 0, 0};  // for the distance field only
Field[1] = Distance;
Field[1].PointsList = {100};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = fine;
Field[2].SizeMax = coarse;
Field[2].DistMin = 0.15;
Field[2].DistMax = 1;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
eps = 1e-6;
top() = Surface In BoundingBox {-1.1, -1.1, 1 - eps, 1.1, 1.1, 1 + eps};
cap() = Surface In BoundingBox {-0.6, -0.6, -eps, 0.6, 0.6, cut + eps};
cap() -= Surface In BoundingBox {-0.6, -0.6, cut - eps, 0.6, 0.6, cut + eps};  // the cut inside the ball
blockTop() = Surface In BoundingBox {-2 - eps, -2 - eps, -eps, 2 + eps, 2 + eps, eps};
blockBottom() = Surface In BoundingBox {-2 - eps, -2 - eps, -2 - eps, 2 + eps, 2 + eps, -2 + eps};
Physical Surface("top") = top();
Physical Surface("cap") = cap();
Physical Surface("block top") = blockTop();
Physical Surface("block bottom") = blockBottom();
Physical Volume("ball") = Volume In BoundingBox {-1.1, -1.1, -eps, 1.1, 1.1, 1 + eps};
Physical Volume("block") = {10};
