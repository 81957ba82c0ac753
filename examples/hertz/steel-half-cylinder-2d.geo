// A steel half-cylinder of radius 50 mm (plane strain), flat side up (y = 50), its curved side
// down touching the rigid plane y = 0 at the origin. Lengths in mm. The mesh is graded from
// `fine` within 5 mm of the first contact point to `coarse` beyond 30 mm; "top", "contact"
// and "body" name the physical groups.
fine = 0.35;
coarse = 5;
Point(1) = {0, 0, 0, fine};
Point(2) = {50, 50, 0, coarse};
Point(3) = {-50, 50, 0, coarse};
Point(4) = {0, 50, 0, coarse};  // centre of the arcs
Circle(1) = {1, 4, 2};
Line(2) = {2, 3};
Circle(3) = {3, 4, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Field[1] = Distance;
Field[1].PointsList = {1};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = fine;
Field[2].SizeMax = coarse;
Field[2].DistMin = 5;
Field[2].DistMax = 30;
Background Field = 2;
Physical Curve("top") = {2};
Physical Curve("contact") = {1, 3};
Physical Surface("body") = {1};
