// Guo §3 topology diagnostics of a Bernstein patch (docs/maths.md G-3), from the control
// points alone.
//
// Edge x_i x_j: f restricted to it is the univariate Bernstein polynomial with the k + 1 control
// points b_lambda, lambda_l = 0 for l not in {i, j}, ordered lambda_i = k..0. By Descartes' rule
// for the Bernstein form the number of zeros on the open edge is at most the number V of sign
// changes of that sequence (zeros skipped) and has the same parity; V = 0 with all one strict
// sign means no crossing. A face whose control points (lambda_l = 0 for the opposite vertex l)
// are strictly one sign holds no point of the zero set (convex hull property). Vertices 0-based.
#pragma once

#include <array>
#include <vector>

namespace implicitfit {

struct EdgeSignChanges {
  std::array<int, 2> vertices;  // i < j
  int sign_changes = 0;
};

// The six edges (0,1), (0,2), (0,3), (1,2), (1,3), (2,3).
std::vector<EdgeSignChanges> EdgeSignChangeCounts(int k, const double* b);
// Faces (listed by their three vertices, ascending) whose control points are strictly one sign.
std::vector<std::array<int, 3>> FacesWithoutCrossing(int k, const double* b);

}  // namespace implicitfit
