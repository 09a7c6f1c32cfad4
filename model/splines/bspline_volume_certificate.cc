#include "model/splines/bspline_volume_certificate.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/certificates/symmetric_eigen3.h"

namespace implicitfit {

std::vector<std::vector<double>> BezierExtraction(const std::vector<double>& knots, int degree,
                                                  int count) {
  const int k = degree;
  std::vector<std::vector<double>> rows(static_cast<size_t>(count),
                                        std::vector<double>(static_cast<size_t>(count), 0.0));
  for (int i = 0; i < count; ++i) rows[i][i] = 1.0;
  std::vector<double> u = knots;
  for (int index = k + 1; index < static_cast<int>(u.size()) - k - 1;) {
    const double t = u[index];
    int m = 0;  // multiplicity of t
    while (index + m < static_cast<int>(u.size()) && u[index + m] == t) ++m;
    for (int insert = m; insert < k; ++insert) {  // Boehm: one insertion of t
      const int s = index + insert - 1;           // last knot <= t before this insertion
      const int n = static_cast<int>(rows.size());
      std::vector<std::vector<double>> next(static_cast<size_t>(n + 1));
      for (int i = 0; i <= n; ++i) {
        if (i <= s - k) {
          next[i] = rows[i];
        } else if (i <= s - insert) {
          const double alpha = (t - u[i]) / (u[i + k] - u[i]);
          next[i].resize(rows[i].size());
          for (size_t c = 0; c < rows[i].size(); ++c)
            next[i][c] = alpha * rows[i][c] + (1.0 - alpha) * rows[i - 1][c];
        } else {
          next[i] = rows[i - 1];
        }
      }
      rows.swap(next);
      u.insert(u.begin() + s + 1, t);
    }
    index += std::max(m, k);
  }
  return rows;
}

namespace {

// Degree elevation m -> target of a 1-D Bernstein coefficient list (step 2 of the header).
std::vector<double> Elevate(std::vector<double> c, int target) {
  while (static_cast<int>(c.size()) - 1 < target) {
    const int m = static_cast<int>(c.size()) - 1;
    std::vector<double> e(static_cast<size_t>(m + 2));
    for (int i = 0; i <= m + 1; ++i) {
      const double a = static_cast<double>(i) / (m + 1);
      e[i] = (i > 0 ? a * c[i - 1] : 0.0) + (i <= m ? (1.0 - a) * c[i] : 0.0);
    }
    c.swap(e);
  }
  return c;
}

// A (k+1)^3 tensor (x fastest) as a function of three indices.
struct Tensor {
  int n[3];
  std::vector<double> v;
  double& at(int i, int j, int l) { return v[i + n[0] * (j + n[1] * l)]; }
  double at(int i, int j, int l) const { return v[i + n[0] * (j + n[1] * l)]; }
};

// Elevates a tensor of degrees (n - 1) to degree k along every axis.
Tensor ElevateTensor(const Tensor& t, int k) {
  Tensor cur = t;
  for (int axis = 0; axis < 3; ++axis) {
    if (cur.n[axis] == k + 1) continue;
    Tensor next = cur;
    next.n[axis] = k + 1;
    next.v.assign(static_cast<size_t>(next.n[0]) * next.n[1] * next.n[2], 0.0);
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (int p = 0; p < cur.n[a]; ++p)
      for (int q = 0; q < cur.n[b]; ++q) {
        std::vector<double> line(static_cast<size_t>(cur.n[axis]));
        int idx[3];
        for (int r = 0; r < cur.n[axis]; ++r) {
          idx[axis] = r;
          idx[a] = p;
          idx[b] = q;
          line[r] = cur.at(idx[0], idx[1], idx[2]);
        }
        const std::vector<double> up = Elevate(line, k);
        for (int r = 0; r <= k; ++r) {
          idx[axis] = r;
          idx[a] = p;
          idx[b] = q;
          next.at(idx[0], idx[1], idx[2]) = up[r];
        }
      }
    cur = next;
  }
  return cur;
}

// The difference tensor d_a d_b b (a == b: the second difference) of the cell's Bezier tensor.
Tensor Difference(const Tensor& b, int a1, int a2) {
  Tensor d;
  for (int axis = 0; axis < 3; ++axis) d.n[axis] = b.n[axis] - (axis == a1) - (axis == a2);
  d.v.assign(static_cast<size_t>(d.n[0]) * d.n[1] * d.n[2], 0.0);
  int e1[3] = {0, 0, 0}, e2[3] = {0, 0, 0};
  e1[a1] = 1;
  e2[a2] = 1;
  for (int l = 0; l < d.n[2]; ++l)
    for (int j = 0; j < d.n[1]; ++j)
      for (int i = 0; i < d.n[0]; ++i)
        d.at(i, j, l) = b.at(i + e1[0] + e2[0], j + e1[1] + e2[1], l + e1[2] + e2[2]) -
                        b.at(i + e1[0], j + e1[1], l + e1[2]) -
                        b.at(i + e2[0], j + e2[1], l + e2[2]) + b.at(i, j, l);
  return d;
}

// The smallest eigenvalue over the (k+1)^3 Hessian coefficient matrices of one cell.
double CellMinEigenvalue(const Tensor& b, int k, const double h[3]) {
  static const int pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  Tensor entries[6];
  double scale[6];
  for (int e = 0; e < 6; ++e) {
    const int a1 = pairs[e][0], a2 = pairs[e][1];
    entries[e] = ElevateTensor(Difference(b, a1, a2), k);
    scale[e] = (a1 == a2 ? k * (k - 1.0) : k * static_cast<double>(k)) / (h[a1] * h[a2]);
  }
  double smallest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < entries[0].v.size(); ++i) {
    double m[6];
    for (int e = 0; e < 6; ++e) m[e] = scale[e] * entries[e].v[i];
    smallest = std::min(smallest, SymmetricMinEigenvalue3(m));
  }
  return smallest;
}

}  // namespace

VolumeConvexityCertificate CertifyVolumeConvexity(const SplineStructure& s, const double* c,
                                                  double margin) {
  VolumeConvexityCertificate r;
  const int k = s.degree[0];
  r.cells = s.cells[0] * s.cells[1] * s.cells[2];
  r.cell_min_eigenvalues.assign(static_cast<size_t>(r.cells), 0.0);
  r.min_eigenvalue = -std::numeric_limits<double>::infinity();
  if (k < 2) return r;  // C^0 only: no certificate (header)
  std::vector<std::vector<double>> m[3];
  double h[3];
  for (int a = 0; a < 3; ++a) {
    m[a] = BezierExtraction(s.knots[a], k, s.count[a]);
    h[a] = (s.box[3 + a] - s.box[a]) / s.cells[a];
  }
  const int nx = s.count[0], ny = s.count[1];
  r.min_eigenvalue = std::numeric_limits<double>::infinity();
  bool all = true;
  for (int cz = 0; cz < s.cells[2]; ++cz)
    for (int cy = 0; cy < s.cells[1]; ++cy)
      for (int cx = 0; cx < s.cells[0]; ++cx) {
        // The cell's Bezier tensor: b_ijl = sum M_x[cx k + i][p] M_y[..][q] M_z[..][w] c_pqw over
        // the k + 1 B-spline coefficients per axis that act on the cell (span cx + k, ...).
        Tensor b;
        b.n[0] = b.n[1] = b.n[2] = k + 1;
        b.v.assign(static_cast<size_t>(k + 1) * (k + 1) * (k + 1), 0.0);
        for (int l = 0; l <= k; ++l)
          for (int j = 0; j <= k; ++j)
            for (int i = 0; i <= k; ++i) {
              const std::vector<double>& rx = m[0][cx * k + i];
              const std::vector<double>& ry = m[1][cy * k + j];
              const std::vector<double>& rz = m[2][cz * k + l];
              double sum = 0.0;
              for (int w = cz; w <= cz + k; ++w)
                for (int q = cy; q <= cy + k; ++q) {
                  const double f = ry[q] * rz[w];
                  if (f == 0.0) continue;
                  for (int p = cx; p <= cx + k; ++p) sum += rx[p] * f * c[p + nx * (q + ny * w)];
                }
              b.at(i, j, l) = sum;
            }
        const double e = CellMinEigenvalue(b, k, h);
        const int cell = cx + s.cells[0] * (cy + s.cells[1] * cz);
        r.cell_min_eigenvalues[cell] = e;
        if (e < r.min_eigenvalue) {
          r.min_eigenvalue = e;
          r.worst_cell = cell;
        }
        if (e > margin)
          ++r.certified_cells;
        else
          all = false;
      }
  r.convex = all;
  return r;
}

}  // namespace implicitfit
