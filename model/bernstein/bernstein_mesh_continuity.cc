#include "model/bernstein/bernstein_mesh_continuity.h"

#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>

namespace implicitfit {
namespace {

using Lattice = std::array<int, 3>;

double Factorial(int n) {
  double f = 1;
  for (int i = 2; i <= n; ++i) f *= i;
  return f;
}

// B^j_nu(alpha) = j!/nu! prod alpha_i^nu_i.
double Bernstein(int j, const std::array<int, 4>& nu, const double* alpha) {
  double c = Factorial(j);
  for (int i = 0; i < 4; ++i) c *= std::pow(alpha[i], nu[i]) / Factorial(nu[i]);
  return c;
}

// Key of a face (its three lattice vertices, sorted), for the face map.
struct FaceKey {
  std::array<Lattice, 3> v;
  bool operator==(const FaceKey& o) const { return v == o.v; }
};
struct FaceKeyHash {
  size_t operator()(const FaceKey& f) const {
    size_t h = 0;
    for (const Lattice& x : f.v)
      for (int c : x) h = h * 1000003u + static_cast<size_t>(c + 7);
    return h;
  }
};

// Barycentric coordinates of lattice point p in the tetrahedron with lattice vertices v.
void LatticeBarycentric(const std::array<Lattice, 4>& v, const Lattice& p, double* alpha) {
  Eigen::Matrix3d e;
  Eigen::Vector3d d;
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < 3; ++i) e(c, i) = v[i][c] - v[3][c];
    d[c] = p[c] - v[3][c];
  }
  const Eigen::Vector3d t = e.partialPivLu().solve(d);
  for (int i = 0; i < 3; ++i) alpha[i] = std::round(t[i]);  // integers on a Kuhn grid
  alpha[3] = 1.0 - alpha[0] - alpha[1] - alpha[2];
}

}  // namespace

ContinuityRows BernsteinContinuityRows(const BernsteinGrid& grid, int k, int min_order,
                                       int max_order) {
  const long long nt = grid.NumTetrahedra();
  const long long n = NumBernsteinControlPoints(k);
  const auto multi = BernsteinMultiIndices(k);
  std::unordered_map<FaceKey, std::pair<long long, int>, FaceKeyHash> first;
  std::vector<std::array<long long, 4>> pairs;  // t, o, u, q
  first.reserve(static_cast<size_t>(2 * nt));
  for (long long t = 0; t < nt; ++t) {
    const auto v = grid.LatticeVertices(t);
    for (int o = 0; o < 4; ++o) {
      FaceKey key;
      int m = 0;
      for (int i = 0; i < 4; ++i)
        if (i != o) key.v[m++] = v[i];
      std::sort(key.v.begin(), key.v.end());
      auto it = first.find(key);
      if (it == first.end()) {
        first.emplace(key, std::make_pair(t, o));
      } else {
        pairs.push_back({it->second.first, it->second.second, t, o});
        first.erase(it);
      }
    }
  }
  ContinuityRows out;
  std::vector<Eigen::Triplet<double>> triplets;
  long long row = 0;
  for (const auto& pr : pairs) {
    const long long t = pr[0], u = pr[2];
    const int o = static_cast<int>(pr[1]), q = static_cast<int>(pr[3]);
    const auto V = grid.LatticeVertices(t), W = grid.LatticeVertices(u);
    int map_wv[4] = {-1, -1, -1, -1};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (i != q && j != o && W[i] == V[j]) map_wv[i] = j;
    double alpha[4];
    LatticeBarycentric(V, W[q], alpha);
    for (const auto& m : multi) {
      const int j = m[q];
      if (j < min_order || j > max_order) continue;
      std::array<int, 4> lam = {0, 0, 0, 0};
      for (int i = 0; i < 4; ++i)
        if (i != q) lam[map_wv[i]] = m[i];
      triplets.emplace_back(row, u * n + BernsteinIndex(m[1], m[2], m[3]), 1.0);
      for (const auto& nu : BernsteinMultiIndices(j)) {
        const double c = Bernstein(j, nu, alpha);
        if (c == 0.0) continue;
        triplets.emplace_back(
            row, t * n + BernsteinIndex(lam[1] + nu[1], lam[2] + nu[2], lam[3] + nu[3]), -c);
      }
      out.tetrahedra.emplace_back(u, t);
      out.order.push_back(j);
      ++row;
    }
  }
  out.C.resize(row, nt * n);
  out.C.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

long long NumDomainPoints(const BernsteinGrid& grid, int k) {
  return (1LL * k * grid.cells[0] + 1) * (1LL * k * grid.cells[1] + 1) *
         (1LL * k * grid.cells[2] + 1);
}

std::vector<long long> DomainPointIndices(const BernsteinGrid& grid, int k) {
  const long long nt = grid.NumTetrahedra();
  const auto multi = BernsteinMultiIndices(k);
  const long long sx = 1LL * k * grid.cells[0] + 1, sy = 1LL * k * grid.cells[1] + 1;
  std::vector<long long> out;
  out.reserve(static_cast<size_t>(nt * multi.size()));
  for (long long t = 0; t < nt; ++t) {
    const auto v = grid.LatticeVertices(t);
    for (const auto& m : multi) {
      long long p[3] = {0, 0, 0};  // sum lambda_i v_i, in units of h/k
      for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c) p[c] += 1LL * m[i] * v[i][c];
      out.push_back((p[2] * sy + p[1]) * sx + p[0]);
    }
  }
  return out;
}

Eigen::MatrixXd BernsteinSplineBasis(const BernsteinGrid& grid, int k, int continuity) {
  if (continuity != 0 && continuity != 1)
    throw std::invalid_argument("BernsteinSplineBasis: continuity must be 0 or 1");
  const std::vector<long long> domain = DomainPointIndices(grid, k);
  const long long nd = NumDomainPoints(grid, k);
  const long long nb = static_cast<long long>(domain.size());
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(nb, nd);
  for (long long i = 0; i < nb; ++i) P(i, domain[i]) = 1.0;
  if (continuity == 0) return P;
  // G = C1 P: each row's entries, moved to the domain points.
  const ContinuityRows rows = BernsteinContinuityRows(grid, k, 1, 1);
  Eigen::MatrixXd Gt = Eigen::MatrixXd::Zero(nd, rows.C.rows());
  for (int r = 0; r < rows.C.outerSize(); ++r)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows.C, r); it; ++it)
      Gt(domain[it.col()], r) += it.value();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Gt);
  qr.setThreshold(1e-10);
  const long long rank = qr.rank();
  Eigen::MatrixXd Q = qr.householderQ();
  return P * Q.rightCols(nd - rank);
}

double ContinuityDefect(const BernsteinGrid& grid, int k, int continuity, const double* b) {
  const ContinuityRows rows = BernsteinContinuityRows(grid, k, 0, continuity);
  const long long nb = rows.C.cols();
  const Eigen::Map<const Eigen::VectorXd> bv(b, nb);
  const double scale = bv.size() ? bv.cwiseAbs().maxCoeff() : 0.0;
  if (!(scale > 0.0)) return 0.0;
  const Eigen::VectorXd r = rows.C * bv;
  return r.size() ? r.cwiseAbs().maxCoeff() / scale : 0.0;
}

}  // namespace implicitfit
