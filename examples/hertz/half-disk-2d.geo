// An elastic half-disk of radius 1, flat side up (y = 1), its curved side down touching
// the rigid plane y = 0 at the origin. The mesh is graded from size `fine` at the origin
// to `coarse` along the flat top; "top", "contact" and "body" name the physical groups.
fine = 0.004;
coarse = 0.1;
Point(1) = {0, 0, 0, fine};
Point(2) = {1, 1, 0, coarse};
Point(3) = {-1, 1, 0, coarse};
Point(4) = {0, 1, 0, coarse};  // centre of the arcs
Circle(1) = {1, 4, 2};
Line(2) = {2, 3};
Circle(3) = {3, 4, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
// Grade by the distance to the first contact point: `fine` within 0.15, `coarse` from 0.6.
Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = fine;
Field[2].SizeMax = coarse;
Field[2].DistMin = 0.15;
Field[2].DistMax = 0.6;
Background Field = 2;
Physical Curve("top") = {2};
Physical Curve("contact") = {1, 3};
Physical Surface("body") = {1};
