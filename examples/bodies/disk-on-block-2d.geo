// An elastic half-disk of radius 1 (flat side up at y = 1, centre (0, 1)) resting on an
// elastic block [-2, 2] x [-2, 0], meshed apart: the disk touches the block's top at the
// origin. Geometry.AutoCoherence = 0 keeps the two bodies' points at the origin apart. Both
// meshes are graded from `fine` near the origin to `coarse`. Physical groups: bodies "disk"
// and "block"; boundaries "top" (the disk's flat side), "arc" (its lower arc within 30
// degrees of the contact point: the slave side), "block top" and "block bottom".
Geometry.AutoCoherence = 0;
fine = 0.005;
coarse = 0.2;
s = Sin(Pi / 6);
c = 1 - Cos(Pi / 6);
// The disk.
Point(1) = {0, 0, 0, fine};
Point(2) = {s, c, 0, coarse};
Point(3) = {1, 1, 0, coarse};
Point(4) = {-1, 1, 0, coarse};
Point(5) = {-s, c, 0, coarse};
Point(6) = {0, 1, 0, coarse};  // centre of the arcs
Circle(1) = {1, 6, 2};
Circle(2) = {2, 6, 3};
Line(3) = {3, 4};
Circle(4) = {4, 6, 5};
Circle(5) = {5, 6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
// The block.
Point(11) = {-2, -2, 0, coarse};
Point(12) = {2, -2, 0, coarse};
Point(13) = {2, 0, 0, coarse};
Point(14) = {0, 0, 0, fine};
Point(15) = {-2, 0, 0, coarse};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 15};
Line(15) = {15, 11};
Curve Loop(2) = {11, 12, 13, 14, 15};
Plane Surface(2) = {2};
// Graded by the distance to the contact point: `fine` within 0.15, `coarse` from 1.
Field[1] = Distance;
Field[1].PointsList = {1, 14};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = fine;
Field[2].SizeMax = coarse;
Field[2].DistMin = 0.15;
Field[2].DistMax = 1;
Background Field = 2;
Physical Curve("top") = {3};
Physical Curve("arc") = {1, 5};
Physical Curve("block top") = {13, 14};
Physical Curve("block bottom") = {11};
Physical Surface("disk") = {1};
Physical Surface("block") = {2};
