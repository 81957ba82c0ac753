// Two unit squares meshed apart, one on the other: "base" [0,1] x [0,1] and "block"
// [0,1] x [1,2]. Geometry.AutoCoherence = 0 keeps their points at y = 1 apart, so that each
// body has its own nodes there: the block's bottom in 10 segments, the base's top in 7, so
// the interface meshes do not match. Boundaries: "ground" (y = 0), "top" (y = 2), "sides",
// "base top" and "block bottom".
Geometry.AutoCoherence = 0;
h = 0.1;
Point(1) = {0, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {1, 1, 0, h};
Point(4) = {0, 1, 0, h};
Point(5) = {0, 1, 0, h};
Point(6) = {1, 1, 0, h};
Point(7) = {1, 2, 0, h};
Point(8) = {0, 2, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};  // the base's top
Line(4) = {4, 1};
Line(5) = {5, 6};  // the block's bottom
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Transfinite Curve{3} = 8;
Transfinite Curve{5} = 11;
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Physical Curve("ground") = {1};
Physical Curve("top") = {7};
Physical Curve("sides") = {2, 4, 6, 8};
Physical Curve("base top") = {3};
Physical Curve("block bottom") = {5};
Physical Surface("base") = {1};
Physical Surface("block") = {2};
