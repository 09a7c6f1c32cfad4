// Weighted linear least squares for the patch-mesh fit (fit/bernstein/bernstein_mesh_fitter.h,
// steps 1 and 2) in the unknowns w of the C0 spline space, b = P w
// (model/bernstein/bernstein_mesh_continuity.h: the global domain points on a uniform grid; on a
// refined grid also the hanging control points, linear in the coarser ones), so C0 holds
// exactly; the C1 rows enter as weighted equations (continuity_weight) and the soft C2 rows on
// the faces of empty tetrahedra with smoothing_weight. Rows are linear functionals of f at a
// point (its value, its gradient). Solved by sparse Cholesky of the normal equations.
// Assembly. Every row lies in one tetrahedron t, so A^T A is a sum of dense blocks
// L_t^T R_t^T R_t L_t (R_t: the rows of t, n wide; L_t: t's control points from its unknowns,
// the identity on w[cols] unless t holds hanging control points), each computed with dense
// products and added into H's value array at positions found once (the rows fall in the same
// tetrahedra every iteration); H = those blocks + the fixed continuity and C2 part + a tiny
// ridge. The refinement's systems share one sparsity pattern and differ only in row weights, so
// the last factor preconditions conjugate gradients on the next system
// (fit/bernstein/reused_cholesky.h).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <algorithm>
#include <vector>

#include "fit/bernstein/reused_cholesky.h"
#include "model/bernstein/bernstein_mesh.h"
#include "model/bernstein/bernstein_mesh_continuity.h"

namespace implicitfit {

// B^k_lambda(tau) for every lambda, docs/design.md order.
inline void BasisValues(int k, const double* tau, double* out) {
  static thread_local std::vector<double> unit;
  const long long n = NumBernsteinControlPoints(k);
  unit.assign(static_cast<size_t>(n), 0.0);
  for (long long j = 0; j < n; ++j) {
    unit[j] = 1.0;
    out[j] = BernsteinPatch::EvaluateBarycentric(k, unit.data(), tau);
    unit[j] = 0.0;
  }
}

class DomainLeastSquares {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double>;
  // continuity_weight: of the C1 rows (continuity 1); smoothing_weight: of the kept C2 rows.
  // sharp_weight >= 0 (soft C1 on a C0 mesh): the sharp faces' C1 rows with that weight.
  DomainLeastSquares(const BernsteinGrid& grid, int k, int continuity, double continuity_weight,
                     double smoothing_weight, const ContinuityRows& c2,
                     const std::vector<bool>& c2_keep, double sharp_weight = -1)
      : grid_(grid),
        k_(k),
        n_(NumBernsteinControlPoints(k)),
        basis_(static_cast<size_t>(n_)) {
    const C0Parametrization c0 = BernsteinC0Parametrization(grid, k);
    nd_ = c0.unknowns;
    P_ = SparseMatrix(c0.P);
    LocalMaps(c0);
    fixed_.resize(nd_, nd_);
    if (continuity == 1) {
      // Soft C1 on a C0 mesh (sharp_weight >= 0): the sharp faces' rows too, with that weight.
      const ContinuityRows c1 = BernsteinContinuityRows(grid, k, 1, 1, sharp_weight >= 0);
      Eigen::VectorXd w = Eigen::VectorXd::Constant(c1.C.rows(), continuity_weight);
      for (Eigen::Index r = 0; r < w.size(); ++r)
        if (c1.sharp[r]) w[r] = sharp_weight;
      const SparseMatrix G = w.asDiagonal() * SparseMatrix(c1.C) * P_;
      fixed_ += SparseMatrix(G.transpose()) * G;
    }
    std::vector<Eigen::Triplet<double>> ts;
    long long r = 0;
    for (int row = 0; row < c2.C.rows(); ++row) {
      if (!c2_keep[row]) continue;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(c2.C, row); it; ++it)
        ts.emplace_back(r, it.col(), it.value());
      ++r;
    }
    SparseMatrix S(r, c2.C.cols());
    S.setFromTriplets(ts.begin(), ts.end());
    const SparseMatrix SP = S * P_;
    fixed_ +=
        smoothing_weight * smoothing_weight * SparseMatrix(SP.transpose()) * SP;
  }

  long long unknowns() const { return nd_; }

  // The row weight (f(x) - target).
  void AddValueRow(const Eigen::Vector3d& x, double weight, double target) {
    double tau[4];
    const long long t = grid_.Locate(x.data(), tau);
    BasisValues(k_, tau, basis_.data());
    double* row = NewRow(t, weight * target);
    for (long long j = 0; j < n_; ++j) row[j] = weight * basis_[j];
  }

  // Rows weight_r (a_r f(x) + c_r . grad f(x) - target_r) at one point x: linear functionals of
  // f's value and gradient (the gradient rows below; the exact linearisations of f/|grad f| and
  // grad f/|grad f| in RefineLinearised); grad B_j by the patch's derivatives of unit control
  // vectors, computed once for all the rows.
  struct PointRow {
    double weight, a;
    Eigen::Vector3d c;
    double target;
  };
  void AddPointRows(const Eigen::Vector3d& x, const PointRow* rows, int count) {
    double tau[4];
    const long long t = grid_.Locate(x.data(), tau);
    const Tetrahedron tet = grid_.TetrahedronOf(t);
    BasisValues(k_, tau, basis_.data());
    for (int r = 0; r < count; ++r) NewRow(t, rows[r].weight * rows[r].target);
    unit_.assign(static_cast<size_t>(n_), 0.0);
    for (long long j = 0; j < n_; ++j) {
      unit_[j] = 1.0;
      Eigen::Vector3d g;
      BernsteinPatch::Derivatives(k_, tet, unit_.data(), x.data(), &g);
      unit_[j] = 0.0;
      for (int r = 0; r < count; ++r)
        coefficients_[(rows_ - count + r) * n_ + j] =
            rows[r].weight * (rows[r].a * basis_[j] + rows[r].c.dot(g));
    }
  }

  // The three rows weight (grad f(x) - target).
  void AddGradientRows(const Eigen::Vector3d& x, double weight, const Eigen::Vector3d& target) {
    PointRow rows[3];
    for (int c = 0; c < 3; ++c) rows[c] = {weight, 0.0, Eigen::Vector3d::Unit(c), target[c]};
    AddPointRows(x, rows, 3);
  }

  // Solves with the rows added since the last Solve (then drops them); returns b = P w.
  // Assembly. Every row lies in one tetrahedron, so A^T A is a sum of dense n x n blocks
  // R_t^T R_t (R_t: the rows of tetrahedron t), each computed with dense products and added
  // into H's value array at positions found once (the rows fall in the same tetrahedra every
  // iteration); H = those blocks + the fixed continuity and C2 part + a tiny ridge.
  std::vector<double> Solve() {
    std::vector<long long> order(static_cast<size_t>(rows_));
    for (long long r = 0; r < rows_; ++r) order[r] = r;
    std::stable_sort(order.begin(), order.end(),
                     [&](long long a, long long b) { return row_tet_[a] < row_tet_[b]; });
    std::vector<long long> tets;
    for (long long r : order)
      if (tets.empty() || tets.back() != row_tet_[r]) tets.push_back(row_tet_[r]);
    if (tets != pattern_tets_) BuildPattern(tets);
    Eigen::VectorXd values = Eigen::VectorXd::Zero(H_.nonZeros());
    for (size_t i = 0; i < fixed_positions_.size(); ++i)
      values[fixed_positions_[i]] += fixed_.valuePtr()[i];
    Eigen::VectorXd g = Eigen::VectorXd::Zero(nd_);
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    RowMajor R;
    Eigen::VectorXd y;
    size_t next = 0;
    for (size_t ti = 0; ti < tets.size(); ++ti) {
      const long long t = tets[ti];
      size_t end = next;
      while (end < order.size() && row_tet_[order[end]] == t) ++end;
      R.resize(static_cast<long>(end - next), n_);
      y.resize(static_cast<long>(end - next));
      for (size_t i = next; i < end; ++i) {
        R.row(static_cast<long>(i - next)) =
            Eigen::Map<const Eigen::RowVectorXd>(&coefficients_[order[i] * n_], n_);
        y[static_cast<long>(i - next)] = rhs_[order[i]];
      }
      next = end;
      const std::vector<long long>& cols = cols_[t];
      const long long m = static_cast<long long>(cols.size());
      Eigen::MatrixXd block;
      Eigen::VectorXd local;
      if (maps_[t].size() == 0) {  // b_t = w[cols]: the rows act on the unknowns directly
        block = R.transpose() * R;
        local = R.transpose() * y;
      } else {  // b_t = L_t w[cols] (hanging control points)
        const Eigen::MatrixXd RL = R * maps_[t];
        block = RL.transpose() * RL;
        local = RL.transpose() * y;
      }
      const int* pos = &block_positions_[block_offsets_[ti]];
      for (long long a = 0; a < m; ++a) {
        g[cols[a]] += local[a];
        for (long long c = 0; c < m; ++c) values[pos[a * m + c]] += block(c, a);
      }
    }
    // A tiny ridge keeps the system definite where nothing else reaches (far corners).
    double largest = 1.0;
    for (int d : diagonal_positions_) largest = std::max(largest, values[d]);
    for (int d : diagonal_positions_) values[d] += 1e-10 * largest;
    std::copy(values.data(), values.data() + values.size(), H_.valuePtr());
    // CHOLMOD's supernodal Cholesky (SuiteSparse, linked for the projection already) is an order
    // of magnitude faster than Eigen's simplicial one on these 3-D grids. The refinement's systems
    // share one sparsity pattern (the same points, offsets and far-field points every
    // iteration) and differ only in row weights, so the last factor preconditions conjugate
    // gradients on the next system and a new factorisation is made only when they do not
    // converge (fit/bernstein/reused_cholesky.h).
    last_w_ = cholmod_.Solve(H_, g, last_w_);
    const Eigen::VectorXd b = P_ * last_w_;
    row_tet_.clear();
    coefficients_.clear();
    rhs_.clear();
    rows_ = 0;
    return std::vector<double>(b.data(), b.data() + b.size());
  }

 private:
  // Appends a row in tetrahedron t with right-hand side rhs; returns its n coefficients.
  double* NewRow(long long t, double rhs) {
    row_tet_.push_back(t);
    rhs_.push_back(rhs);
    coefficients_.resize(static_cast<size_t>((rows_ + 1) * n_));
    return &coefficients_[rows_++ * n_];
  }

  // H's pattern: the fixed part plus a dense block on the domain points of every tetrahedron
  // that holds rows; the value positions of both and of the diagonal.
  void BuildPattern(const std::vector<long long>& tets) {
    std::vector<Eigen::Triplet<double>> ts;
    ts.reserve(tets.size() * n_ * n_);
    for (long long t : tets)
      for (long long a : cols_[t])
        for (long long c : cols_[t]) ts.emplace_back(c, a, 1.0);
    for (long long i = 0; i < nd_; ++i) ts.emplace_back(i, i, 1.0);
    for (int j = 0; j < fixed_.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(fixed_, j); it; ++it)
        ts.emplace_back(it.row(), it.col(), 1.0);
    H_.resize(nd_, nd_);
    H_.setFromTriplets(ts.begin(), ts.end());
    H_.makeCompressed();
    auto position = [&](long long row, long long col) {
      const auto* first = H_.innerIndexPtr() + H_.outerIndexPtr()[col];
      const auto* last = H_.innerIndexPtr() + H_.outerIndexPtr()[col + 1];
      return static_cast<int>(std::lower_bound(first, last, row) - H_.innerIndexPtr());
    };
    block_positions_.clear();
    block_offsets_.clear();
    for (long long t : tets) {
      block_offsets_.push_back(block_positions_.size());
      for (long long a : cols_[t])
        for (long long c : cols_[t]) block_positions_.push_back(position(c, a));
    }
    fixed_.makeCompressed();
    fixed_positions_.clear();
    for (int j = 0; j < fixed_.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(fixed_, j); it; ++it)
        fixed_positions_.push_back(position(it.row(), it.col()));
    diagonal_positions_.resize(static_cast<size_t>(nd_));
    for (long long i = 0; i < nd_; ++i) diagonal_positions_[i] = position(i, i);
    pattern_tets_ = tets;
  }

 private:
  // Per tetrahedron: the unknowns its control points depend on, and L_t with b_t = L_t w[cols]
  // (empty when b_t = w[cols] itself: no hanging control point).
  void LocalMaps(const C0Parametrization& c0) {
    const long long nt = grid_.NumTetrahedra();
    cols_.assign(static_cast<size_t>(nt), {});
    maps_.assign(static_cast<size_t>(nt), Eigen::MatrixXd());
    for (long long t = 0; t < nt; ++t) {
      bool identity = true;
      for (long long a = 0; a < n_ && identity; ++a) identity = c0.identity[t * n_ + a] >= 0;
      if (identity) {
        for (long long a = 0; a < n_; ++a) cols_[t].push_back(c0.identity[t * n_ + a]);
        continue;
      }
      std::vector<long long>& cols = cols_[t];
      for (long long a = 0; a < n_; ++a)
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(c0.P, t * n_ + a); it;
             ++it)
          cols.push_back(it.col());
      std::sort(cols.begin(), cols.end());
      cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
      Eigen::MatrixXd& L = maps_[t];
      L = Eigen::MatrixXd::Zero(n_, static_cast<long>(cols.size()));
      for (long long a = 0; a < n_; ++a)
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(c0.P, t * n_ + a); it;
             ++it)
          L(a, std::lower_bound(cols.begin(), cols.end(), it.col()) - cols.begin()) = it.value();
    }
  }

  const BernsteinGrid& grid_;
  int k_;
  long long n_;
  long long nd_ = 0;
  std::vector<std::vector<long long>> cols_;
  std::vector<Eigen::MatrixXd> maps_;
  SparseMatrix P_, fixed_;
  ReusedCholeskySolver cholmod_;
  Eigen::VectorXd last_w_;  // the last solution (the next system's starting point)
  // Rows added since the last Solve: tetrahedron, n coefficients each, right-hand side.
  std::vector<long long> row_tet_;
  std::vector<double> coefficients_, rhs_, basis_, unit_;
  long long rows_ = 0;
  // H's pattern (BuildPattern) and where the blocks, the fixed part and the diagonal go in it.
  SparseMatrix H_;
  std::vector<long long> pattern_tets_;
  std::vector<int> block_positions_, fixed_positions_, diagonal_positions_;
  std::vector<size_t> block_offsets_;  // where each pattern tetrahedron's block starts
};

}  // namespace implicitfit
