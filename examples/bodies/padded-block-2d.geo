// A steel block (40 x 20 mm) on an elastomer pad (40 x 5 mm), bonded to it: two bodies meshed
// together, their interface nodes shared. Lengths in mm; the pad's underside lies on y = 0.
// Physical groups: bodies "steel" and "pad", boundaries "top" and "underside".
h = 1.0;
Point(1) = {-20, 0, 0, h};
Point(2) = {20, 0, 0, h};
Point(3) = {20, 5, 0, h};
Point(4) = {-20, 5, 0, h};
Point(5) = {20, 25, 0, 2 * h};
Point(6) = {-20, 25, 0, 2 * h};
Line(1) = {1, 2};  // underside
Line(2) = {2, 3};
Line(3) = {3, 4};  // the interface
Line(4) = {4, 1};
Line(5) = {3, 5};
Line(6) = {5, 6};  // top
Line(7) = {6, 4};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7};
Plane Surface(2) = {2};
Physical Curve("underside") = {1};
Physical Curve("top") = {6};
Physical Surface("pad") = {1};
Physical Surface("steel") = {2};
