// Two unit cubes meshed apart, one on the other: "base" [0,1]^3 and "block" [0,1]^2 x [1,2].
// Without a boolean fragment the OpenCASCADE boxes keep their own faces at z = 1, so each
// body has its own nodes there, meshed at different sizes: the interface meshes do not match.
// Boundaries: "ground" (z = 0), "top" (z = 2), "x sides", "y sides", "base top" and
// "block bottom".
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {0, 0, 1, 1, 1, 1};
MeshSize{PointsOf{Volume{1};}} = 0.3;
MeshSize{PointsOf{Volume{2};}} = 0.22;
Physical Surface("ground") = {5};
Physical Surface("base top") = {6};
Physical Surface("block bottom") = {11};
Physical Surface("top") = {12};
Physical Surface("x sides") = {1, 2, 7, 8};
Physical Surface("y sides") = {3, 4, 9, 10};
Physical Volume("base") = {1};
Physical Volume("block") = {2};
