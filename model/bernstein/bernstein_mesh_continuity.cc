#include "model/bernstein/bernstein_mesh_continuity.h"

#include "model/bernstein/bernstein_conversion.h"

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

// Exact barycentric coordinates of lattice point p in tetrahedron t (a Kuhn tetrahedron of a leaf
// of edge s: tau = (1 - d_pi0, d_pi0 - d_pi1, d_pi1 - d_pi2, d_pi2) / s with d = p - corner; s
// is a power of 2, so these are exact in floating point).
Eigen::Vector4d KuhnBarycentric(const BernsteinGrid& grid, long long t, const Lattice& p) {
  const auto v = grid.LatticeVertices(t);
  const int* pi = kKuhnPermutations[t % 6];
  const double s = v[3][0] - v[0][0];
  double d[3];
  for (int a = 0; a < 3; ++a) d[a] = (p[a] - v[0][a]) / s;
  return Eigen::Vector4d(1.0 - d[pi[0]], d[pi[0]] - d[pi[1]], d[pi[1]] - d[pi[2]], d[pi[2]]);
}

bool InTetrahedron(const BernsteinGrid& grid, long long t, const Lattice& p) {
  return (KuhnBarycentric(grid, t, p).array() >= 0.0).all();
}

// Re-expression matrices (bernstein_conversion.h) cached by the barycentric coordinates of the
// finer tetrahedron's vertices: on a Kuhn octree only a few relative positions occur.
class ReexpressionCache {
 public:
  explicit ReexpressionCache(int k) : k_(k) {}
  // M with b^u = M b^t for the polynomial of t re-expressed on u.
  const Eigen::MatrixXd& Get(const BernsteinGrid& grid, long long u, long long t) {
    const auto w = grid.LatticeVertices(u);
    Eigen::Matrix4d a;
    std::array<double, 16> key;
    for (int i = 0; i < 4; ++i) {
      a.row(i) = KuhnBarycentric(grid, t, w[i]).transpose();
      for (int j = 0; j < 4; ++j) key[4 * i + j] = a(i, j);
    }
    auto it = cache_.find(key);
    if (it == cache_.end()) it = cache_.emplace(key, ReexpressionMatrix(k_, a)).first;
    return it->second;
  }

 private:
  int k_;
  std::map<std::array<double, 16>, Eigen::MatrixXd> cache_;
};

// The leaves of a refined grid coarser than leaf q that touch it (found at the centres of the 26
// cubes of q's size around it).
std::vector<int> CoarserNeighbours(const BernsteinGrid& grid, long long q) {
  const auto& leaf = grid.refinement.leaves[static_cast<size_t>(q)];
  const int units = grid.MaxLevel() + 1;
  const long long size = 1LL << (units - leaf[0]);
  std::vector<int> out;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const long long d[3] = {dx, dy, dz};
        std::array<long long, 3> p;
        bool inside = true;
        for (int a = 0; a < 3; ++a) {
          const long long i = leaf[1 + a] + d[a];
          inside = inside && i >= 0 && i < (1LL * grid.cells[a] << leaf[0]);
          p[a] = i * size + size / 2;
        }
        if (!inside) continue;
        const int other = LeafAt(grid.cells, grid.refinement, p, units);
        if (grid.refinement.leaves[other][0] < leaf[0] &&
            std::find(out.begin(), out.end(), other) == out.end())
          out.push_back(other);
      }
  return out;
}

struct FacePair {
  long long t, u;  // rows b^u - (t re-expressed on u)
  int o, q;        // the face's opposite vertex in t and in u
  bool hanging;    // u finer than t, u's face inside t's face o
};

// Every interior face: conforming pairs (matched by their lattice vertices) and, on refined
// grids, hanging pairs (a face of u with no partner, on a coarser tetrahedron t).
std::vector<FacePair> InteriorFaces(const BernsteinGrid& grid) {
  const long long nt = grid.NumTetrahedra();
  std::unordered_map<FaceKey, std::pair<long long, int>, FaceKeyHash> first;
  std::vector<FacePair> pairs;
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
        pairs.push_back({it->second.first, t, it->second.second, o, false});
        first.erase(it);
      }
    }
  }
  if (!grid.refined()) return pairs;
  // Unmatched faces: on the box, the coarse side of a hanging face, or the fine side (kept).
  const Lattice top = {grid.cells[0] << grid.MaxLevel(), grid.cells[1] << grid.MaxLevel(),
                       grid.cells[2] << grid.MaxLevel()};
  const double unit = grid.LatticeUnit();
  for (const auto& [key, tf] : first) {
    bool on_box = false;
    for (int a = 0; a < 3; ++a)
      for (int side : {0, top[a]})
        on_box = on_box || (key.v[0][a] == side && key.v[1][a] == side && key.v[2][a] == side);
    if (on_box) continue;
    const auto [u, q] = tf;
    const auto v = grid.LatticeVertices(u);
    Eigen::Vector3d c = Eigen::Vector3d::Zero(), opposite = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector3d x(v[i][0], v[i][1], v[i][2]);
      if (i == q)
        opposite = x;
      else
        c += x / 3.0;
    }
    // A point just beyond the face's centroid lies in the tetrahedron across it.
    const Eigen::Vector3d across = grid.origin + unit * (c + 1e-3 * (c - opposite));
    double tau[4];
    const long long t = grid.Locate(across.data(), tau);
    if (grid.LevelOf(t) >= grid.LevelOf(u)) continue;  // u is the coarse side (or no partner)
    // t's face holding u's face: the vertex of t with weight 0 at all three of its vertices.
    bool inside = true, zero[4] = {true, true, true, true};
    for (const Lattice& x : key.v) {
      const Eigen::Vector4d a = KuhnBarycentric(grid, t, x);
      inside = inside && (a.array() >= 0.0).all();
      for (int i = 0; i < 4; ++i) zero[i] = zero[i] && a[i] == 0.0;
    }
    int o = -1;
    for (int i = 0; i < 4 && inside; ++i)
      if (zero[i] && o < 0) o = i;
    if (o < 0) continue;  // not inside a coarser face (cannot happen on a Kuhn octree)
    pairs.push_back({t, u, o, q, true});
  }
  return pairs;
}

}  // namespace

ContinuityRows BernsteinContinuityRows(const BernsteinGrid& grid, int k, int min_order,
                                       int max_order, bool include_sharp) {
  const long long nt = grid.NumTetrahedra();
  const long long n = NumBernsteinControlPoints(k);
  const auto multi = BernsteinMultiIndices(k);
  ContinuityRows out;
  std::vector<Eigen::Triplet<double>> triplets;
  ReexpressionCache cache(k);
  long long row = 0;
  for (const FacePair& pr : InteriorFaces(grid)) {
    const long long t = pr.t, u = pr.u;
    const int o = pr.o, q = pr.q;
    const bool sharp = grid.IsSharp(t, o) || grid.IsSharp(u, q);
    const auto V = grid.LatticeVertices(t), W = grid.LatticeVertices(u);
    const Eigen::MatrixXd* m_ut = pr.hanging ? &cache.Get(grid, u, t) : nullptr;
    int map_wv[4] = {-1, -1, -1, -1};
    double alpha[4] = {0, 0, 0, 0};
    if (!pr.hanging) {
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          if (i != q && j != o && W[i] == V[j]) map_wv[i] = j;
      LatticeBarycentric(V, W[q], alpha);
    }
    for (const auto& m : multi) {
      const int j = m[q];
      if (j < min_order || j > max_order) continue;
      if (sharp && j >= 1 && !include_sharp) continue;
      const int mi = BernsteinIndex(m[1], m[2], m[3]);
      triplets.emplace_back(row, u * n + mi, 1.0);
      if (pr.hanging) {
        for (long long c = 0; c < n; ++c)
          if ((*m_ut)(mi, c) != 0.0) triplets.emplace_back(row, t * n + c, -(*m_ut)(mi, c));
      } else {
        std::array<int, 4> lam = {0, 0, 0, 0};
        for (int i = 0; i < 4; ++i)
          if (i != q) lam[map_wv[i]] = m[i];
        for (const auto& nu : BernsteinMultiIndices(j)) {
          const double c = Bernstein(j, nu, alpha);
          if (c == 0.0) continue;
          triplets.emplace_back(
              row, t * n + BernsteinIndex(lam[1] + nu[1], lam[2] + nu[2], lam[3] + nu[3]), -c);
        }
      }
      out.tetrahedra.emplace_back(u, t);
      out.order.push_back(j);
      out.face.push_back(q);
      out.sharp.push_back(sharp);
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
  if (grid.refined())
    throw std::invalid_argument("DomainPointIndices: a uniform grid only (refined grid given)");
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

C0Parametrization BernsteinC0Parametrization(const BernsteinGrid& grid, int k) {
  C0Parametrization out;
  const long long nt = grid.NumTetrahedra();
  const long long n = NumBernsteinControlPoints(k);
  const long long nb = nt * n;
  std::vector<Eigen::Triplet<double>> triplets;
  if (!grid.refined()) {
    out.identity = DomainPointIndices(grid, k);
    out.unknowns = NumDomainPoints(grid, k);
    for (long long i = 0; i < nb; ++i) triplets.emplace_back(i, out.identity[i], 1.0);
    out.P.resize(nb, out.unknowns);
    out.P.setFromTriplets(triplets.begin(), triplets.end());
    return out;
  }
  const auto multi = BernsteinMultiIndices(k);
  out.identity.assign(static_cast<size_t>(nb), -1);
  // Each control point's row of P, as (unknown, coefficient) lists; leaves coarse to fine.
  std::vector<std::vector<std::pair<long long, double>>> rows(static_cast<size_t>(nb));
  std::vector<long long> order(static_cast<size_t>(grid.NumLeaves()));
  for (size_t q = 0; q < order.size(); ++q) order[q] = static_cast<long long>(q);
  std::stable_sort(order.begin(), order.end(), [&](long long a, long long b) {
    return grid.refinement.leaves[a][0] < grid.refinement.leaves[b][0];
  });
  std::map<std::array<long long, 4>, long long> unknown;  // (level, k x position) -> unknown
  ReexpressionCache cache(k);
  for (long long q : order) {
    const int level = grid.refinement.leaves[q][0];
    std::vector<long long> coarse;  // tetrahedra of the coarser leaves touching q
    for (int leaf : CoarserNeighbours(grid, q))
      for (int p = 0; p < 6; ++p) coarse.push_back(6LL * leaf + p);
    for (long long t = 6 * q; t < 6 * q + 6; ++t) {
      const auto v = grid.LatticeVertices(t);
      const size_t nc = coarse.size();
      std::vector<std::array<bool, 4>> in(nc);  // in[c][i]: vertex i of t lies in coarse[c]
      for (size_t c = 0; c < nc; ++c)
        for (int i = 0; i < 4; ++i) in[c][i] = InTetrahedron(grid, coarse[c], v[i]);
      for (long long j = 0; j < n; ++j) {
        const auto& m = multi[static_cast<size_t>(j)];
        const long long id = t * n + j;
        size_t hang = nc;
        for (size_t c = 0; c < nc && hang == nc; ++c) {
          bool all = true;
          for (int i = 0; i < 4; ++i) all = all && (m[i] == 0 || in[c][i]);
          if (all) hang = c;
        }
        if (hang < nc) {  // on sigma = t meet coarse[hang]: that polynomial, re-expressed
          const long long tc = coarse[hang];
          const Eigen::MatrixXd& mt = cache.Get(grid, t, tc);
          std::map<long long, double> sum;
          for (long long c = 0; c < n; ++c) {
            if (mt(j, c) == 0.0) continue;
            for (const auto& [w, value] : rows[tc * n + c]) sum[w] += mt(j, c) * value;
          }
          for (const auto& [w, value] : sum)
            if (value != 0.0) rows[id].emplace_back(w, value);
          continue;
        }
        std::array<long long, 4> key = {level, 0, 0, 0};
        for (int i = 0; i < 4; ++i)
          for (int a = 0; a < 3; ++a) key[1 + a] += 1LL * m[i] * v[i][a];
        const auto [it, added] = unknown.emplace(key, out.unknowns);
        if (added) ++out.unknowns;
        rows[id].emplace_back(it->second, 1.0);
        out.identity[id] = it->second;
      }
    }
  }
  for (long long i = 0; i < nb; ++i)
    for (const auto& [w, value] : rows[i]) triplets.emplace_back(i, w, value);
  out.P.resize(nb, out.unknowns);
  out.P.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

Eigen::MatrixXd BernsteinSplineBasis(const BernsteinGrid& grid, int k, int continuity) {
  if (continuity != 0 && continuity != 1)
    throw std::invalid_argument("BernsteinSplineBasis: continuity must be 0 or 1");
  const C0Parametrization c0 = BernsteinC0Parametrization(grid, k);
  const Eigen::MatrixXd P = Eigen::MatrixXd(c0.P);
  if (continuity == 0) return P;
  // G = C1 P, and the orthonormal basis of its kernel from the QR of G^T.
  const ContinuityRows rows = BernsteinContinuityRows(grid, k, 1, 1);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> G = rows.C * c0.P;
  const Eigen::MatrixXd Gt = Eigen::MatrixXd(G).transpose();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Gt);
  qr.setThreshold(1e-10);
  const long long rank = qr.rank();
  Eigen::MatrixXd Q = qr.householderQ();
  return P * Q.rightCols(c0.unknowns - rank);
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
