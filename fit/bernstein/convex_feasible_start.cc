#include "fit/bernstein/convex_feasible_start.h"

#include <glpk.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <mutex>

#include "fit/bernstein/convex_patch_fit.h"
#include "fit/common/glpk_mutex.h"
#include "model/bernstein/bernstein_patch.h"
#include "model/certificates/convexity_certificate.h"

namespace implicitfit {
namespace {

// The mu of a degree-k patch, as (m2, m3, m4).
std::vector<std::array<int, 3>> Mus(int k) {
  std::vector<std::array<int, 3>> mus;
  for (const std::array<int, 4>& l : BernsteinMultiIndices(k - 2)) mus.push_back({l[1], l[2], l[3]});
  return mus;
}

Eigen::Matrix3d Guo(int k, const double* b, const std::array<int, 3>& mu) {
  double a[6];
  GuoMatrix(k, b, mu[0], mu[1], mu[2], a);
  Eigen::Matrix3d A;
  A << a[0], a[3], a[4], a[3], a[1], a[5], a[4], a[5], a[2];
  return A;
}

// phi(b) = min_mu lambda_min(A^mu) with the minimising mu and unit eigenvector.
double Phi(int k, const std::vector<double>& b, const std::vector<std::array<int, 3>>& mus,
           int* which, Eigen::Vector3d* v) {
  double best = INFINITY;
  for (size_t m = 0; m < mus.size(); ++m) {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(Guo(k, b.data(), mus[m]));
    if (eig.eigenvalues()[0] < best) {
      best = eig.eigenvalues()[0];
      *which = static_cast<int>(m);
      *v = eig.eigenvectors().col(0);
    }
  }
  return best;
}

// Affine control points: column i is the degree-1 function with value 1 at vertex i, elevated.
Eigen::MatrixXd AffineColumns(int k) {
  const std::vector<std::array<int, 4>> l = BernsteinMultiIndices(k);
  Eigen::MatrixXd E(l.size(), 4);
  for (size_t r = 0; r < l.size(); ++r)
    for (int i = 0; i < 4; ++i) E(r, i) = static_cast<double>(l[r][i]) / k;
  return E;
}

enum class Search { kFound, kInfeasible, kUndecided };

// Kelley's cutting planes (see the header): kInfeasible when the LP bound shows phi <= 0 on the
// subspace, kUndecided when the cuts ran out (300) or the LP failed.
Search MostConvexPoint(int k, const Eigen::MatrixXd& N, const Eigen::VectorXd& y0,
                       double margin, Eigen::VectorXd* y_out) {
  const int n = static_cast<int>(N.rows()), m = static_cast<int>(N.cols());
  const std::vector<std::array<int, 3>> mus = Mus(k);
  // A^mu(N e_l) for every column l: phi's cuts are linear in y through these.
  std::vector<std::vector<Eigen::Matrix3d>> column_guo(m);
  for (int l = 0; l < m; ++l) {
    const std::vector<double> col(N.col(l).data(), N.col(l).data() + n);
    for (const auto& mu : mus) column_guo[l].push_back(Guo(k, col.data(), mu));
  }
  std::lock_guard<std::mutex> lock(GlpkMutex());
  glp_term_out(GLP_OFF);
  FreeGlpkEnvironmentAtThreadExit();
  glp_prob* lp = glp_create_prob();
  glp_set_obj_dir(lp, GLP_MAX);
  glp_add_cols(lp, m + 1);
  for (int j = 1; j <= m; ++j) glp_set_col_bnds(lp, j, GLP_FR, 0.0, 0.0);
  glp_set_col_bnds(lp, m + 1, GLP_FR, 0.0, 0.0);
  glp_set_obj_coef(lp, m + 1, 1.0);
  glp_add_rows(lp, n);  // -1 <= (N y)_r <= 1
  for (int r = 0; r < n; ++r) {
    std::vector<int> idx(1);
    std::vector<double> val(1);
    for (int j = 0; j < m; ++j)
      if (N(r, j) != 0.0) idx.push_back(j + 1), val.push_back(N(r, j));
    glp_set_row_bnds(lp, r + 1, GLP_DB, -1.0, 1.0);
    glp_set_mat_row(lp, r + 1, static_cast<int>(idx.size()) - 1, idx.data(), val.data());
  }
  Eigen::VectorXd y = y0;
  Search result = Search::kUndecided;
  for (int iteration = 0; iteration < 300; ++iteration) {
    const Eigen::VectorXd b = N * y;
    const std::vector<double> bv(b.data(), b.data() + n);
    int which = 0;
    Eigen::Vector3d v;
    const double phi = Phi(k, bv, mus, &which, &v);
    const double scale = std::max(b.cwiseAbs().maxCoeff(), 1e-300);
    if (phi >= 10 * margin * scale) {
      result = Search::kFound;
      break;
    }
    // Cut: t - sum_l y_l v^T A^mu(N e_l) v <= 0.
    std::vector<int> idx(1);
    std::vector<double> val(1);
    for (int l = 0; l < m; ++l) {
      idx.push_back(l + 1);
      val.push_back(-v.dot(column_guo[l][which] * v));
    }
    idx.push_back(m + 1);
    val.push_back(1.0);
    const int row = glp_add_rows(lp, 1);
    glp_set_row_bnds(lp, row, GLP_UP, 0.0, 0.0);
    glp_set_mat_row(lp, row, m + 1, idx.data(), val.data());
    glp_smcp parm;
    glp_init_smcp(&parm);
    parm.msg_lev = GLP_MSG_OFF;
    if (glp_simplex(lp, &parm) != 0 || glp_get_status(lp) != GLP_OPT) break;
    // The LP optimum bounds max phi over |N y|_inf <= 1, which (phi being homogeneous) is the
    // largest relative margin of the subspace: below the required one, none is certifiable.
    if (glp_get_obj_val(lp) < margin) {
      result = Search::kInfeasible;
      break;
    }
    for (int j = 0; j < m; ++j) y[j] = glp_get_col_prim(lp, j + 1);
  }
  glp_delete_prob(lp);
  *y_out = y;
  return result;
}

}  // namespace

bool ConvexStartOnSubspace(int k, const std::vector<double>& b0, const Eigen::MatrixXd& N,
                           double margin, std::vector<double>* start, std::string* why) {
  const int n = static_cast<int>(b0.size());
  const Eigen::Map<const Eigen::VectorXd> b(b0.data(), n);
  const Eigen::MatrixXd off = Eigen::MatrixXd::Identity(n, n) - N * N.transpose();
  // 1. The affine correction.
  const Eigen::MatrixXd E = AffineColumns(k);
  const Eigen::VectorXd g = (off * E).colPivHouseholderQr().solve(off * b);
  const Eigen::VectorXd corrected = b - E * g;
  const double scale = std::max(b.cwiseAbs().maxCoeff(), 1e-300);
  if ((off * corrected).cwiseAbs().maxCoeff() <= 1e-12 * scale) {
    const Eigen::VectorXd on = N * (N.transpose() * corrected);  // exactly on the subspace
    start->assign(on.data(), on.data() + n);
    if (CertifiedRelativeMargin(k, *start) >= margin) return true;
  }
  // 2. The most convex point, then the nearest certified convex combination.
  const Eigen::VectorXd projected = N * (N.transpose() * b);
  Eigen::VectorXd y;
  const Search search = MostConvexPoint(k, N, N.transpose() * b / scale, margin, &y);
  if (search != Search::kFound) {
    *why = search == Search::kInfeasible
               ? "no strictly convex patch satisfies these shape constraints (on their subspace "
                 "the smallest A^mu eigenvalue stays below the margin times max |b|)"
               : "no certified convex patch satisfying these shape constraints was found (300 "
                 "cutting planes)";
    return false;
  }
  const Eigen::VectorXd feasible = N * y * (scale / std::max(y.cwiseAbs().maxCoeff(), 1e-300));
  auto at = [&](double a) {
    const Eigen::VectorXd v = (1 - a) * projected + a * feasible;
    return std::vector<double>(v.data(), v.data() + n);
  };
  double lo = 0.0, hi = 1.0;
  if (CertifiedRelativeMargin(k, at(0.0)) >= margin) {
    hi = 0.0;
  } else {
    for (int i = 0; i < 30; ++i) {
      const double mid = 0.5 * (lo + hi);
      (CertifiedRelativeMargin(k, at(mid)) >= margin ? hi : lo) = mid;
    }
  }
  *start = at(hi);
  if (CertifiedRelativeMargin(k, *start) >= margin) return true;
  *why = "could not find a certified convex start on the shape constraints' subspace";
  return false;
}

}  // namespace implicitfit
