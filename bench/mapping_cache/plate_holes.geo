// A plate of N x M unit tiles, each with a hole of radius R at its centre,
// meshed as an O-grid of quadrilaterals (4 patches of n x m cells around
// the hole): 4 n m N M coarse cells, every hole a circle (boundary id
// 3 + tile: at most 252 holes, ids go to 254). Physical curves: 1 bottom, 2 top; surface 1 the body.
// bench/mapping_cache/run.sh makes the mesh and the manifolds.
N = DefineNumber[13, Name "Parameters/N"];
M = DefineNumber[12, Name "Parameters/M"];
n = DefineNumber[5, Name "Parameters/n"];  // cells along a quarter of a hole
m = DefineNumber[4, Name "Parameters/m"];  // cells from the hole to the tile edge
R = 0.3;

// Tile corners (shared between tiles), then the tile edges: horizontal
// h(i, j) from corner (i, j) to (i + 1, j), vertical v(i, j) to (i, j + 1).
For j In {0:M}
  For i In {0:N}
    Point(1 + i + j * (N + 1)) = {i, j, 0};
  EndFor
EndFor
For j In {0:M}
  For i In {0:N - 1}
    Line(1 + i + j * N) = {1 + i + j * (N + 1), 2 + i + j * (N + 1)};
  EndFor
EndFor
For j In {0:M - 1}
  For i In {0:N}
    Line(100000 + 1 + i + j * (N + 1)) = {1 + i + j * (N + 1), 1 + i + (j + 1) * (N + 1)};
  EndFor
EndFor

bottom[] = {};
top[] = {};
body[] = {};
For j In {0:M - 1}
  For i In {0:N - 1}
    t = i + j * N;
    c[] = {1 + i + j * (N + 1), 2 + i + j * (N + 1), 2 + i + (j + 1) * (N + 1), 1 + i + (j + 1) * (N + 1)};
    e[] = {1 + i + j * N, 100000 + 2 + i + j * (N + 1), -(1 + i + (j + 1) * N), -(100000 + 1 + i + j * (N + 1))};
    Point(200000 + 5 * t) = {i + 0.5, j + 0.5, 0};
    For k In {0:3}
      a = Pi * (1.25 + 0.5 * k);
      Point(200000 + 5 * t + 1 + k) = {i + 0.5 + R * Cos(a), j + 0.5 + R * Sin(a), 0};
      Line(300000 + 4 * t + k) = {200000 + 5 * t + 1 + k, c[k]};
    EndFor
    For k In {0:3}
      Circle(400000 + 4 * t + k) = {200000 + 5 * t + 1 + k, 200000 + 5 * t, 200000 + 5 * t + 1 + (k + 1) % 4};
    EndFor
    For k In {0:3}
      Curve Loop(500000 + 4 * t + k) = {400000 + 4 * t + k, 300000 + 4 * t + (k + 1) % 4, -e[k], -(300000 + 4 * t + k)};
      Plane Surface(1 + 4 * t + k) = {500000 + 4 * t + k};
      Transfinite Curve{400000 + 4 * t + k} = n + 1;
      Transfinite Curve{300000 + 4 * t + k} = m + 1;
      Transfinite Curve{Abs(e[k])} = n + 1;
      Transfinite Surface{1 + 4 * t + k};
      Recombine Surface{1 + 4 * t + k};
      body[] += {1 + 4 * t + k};
    EndFor
    Physical Curve(3 + t) = {400000 + 4 * t, 400000 + 4 * t + 1, 400000 + 4 * t + 2, 400000 + 4 * t + 3};
  EndFor
EndFor
For i In {0:N - 1}
  bottom[] += {1 + i};
  top[] += {1 + i + M * N};
EndFor
Physical Curve(1) = {bottom[]};
Physical Curve(2) = {top[]};
Physical Surface(1) = {body[]};
