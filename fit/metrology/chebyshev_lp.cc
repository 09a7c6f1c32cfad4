#include "fit/metrology/chebyshev_lp.h"

#include <glpk.h>

#include <cmath>
#include <mutex>
#include <vector>

#include "fit/common/glpk_mutex.h"

namespace implicitfit {

ChebyshevLpSolution SolveChebyshevLp(const Eigen::VectorXd& d, const Eigen::MatrixXd& g,
                                     double radius) {
  const int n = static_cast<int>(d.size()), k = static_cast<int>(g.cols());
  ChebyshevLpSolution s;
  std::lock_guard<std::mutex> lock(GlpkMutex());
  glp_term_out(GLP_OFF);
  FreeGlpkEnvironmentAtThreadExit();
  glp_prob* lp = glp_create_prob();
  glp_set_obj_dir(lp, GLP_MIN);
  glp_add_cols(lp, k + 1);
  for (int j = 1; j <= k; ++j) {
    if (radius > 0)
      glp_set_col_bnds(lp, j, GLP_DB, -radius, radius);
    else
      glp_set_col_bnds(lp, j, GLP_FR, 0.0, 0.0);
  }
  glp_set_col_bnds(lp, k + 1, GLP_LO, 0.0, 0.0);  // t
  glp_set_obj_coef(lp, k + 1, 1.0);
  // Row 2i + 1: t - g_i y >= d_i (the outer face); row 2i + 2: t + g_i y >= -d_i (the inner).
  glp_add_rows(lp, 2 * n);
  std::vector<int> ia(1), ja(1);
  std::vector<double> ar(1);
  for (int i = 0; i < n; ++i) {
    for (int face = 0; face < 2; ++face) {
      const int row = 2 * i + face + 1;
      const double sign = face == 0 ? 1.0 : -1.0;
      glp_set_row_bnds(lp, row, GLP_LO, sign * d[i], 0.0);
      for (int j = 0; j < k; ++j) {
        if (g(i, j) == 0.0) continue;
        ia.push_back(row);
        ja.push_back(j + 1);
        ar.push_back(-sign * g(i, j));
      }
      ia.push_back(row);
      ja.push_back(k + 1);
      ar.push_back(1.0);
    }
  }
  glp_load_matrix(lp, static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  int rc = glp_simplex(lp, &parm);
  if (rc == 0) rc = glp_exact(lp, &parm);
  const int status = glp_get_status(lp);
  if (rc != 0 || status != GLP_OPT) {
    s.message = "linear programme not solved (GLPK return code " + std::to_string(rc) +
                ", status " + std::to_string(status) + ")";
    glp_delete_prob(lp);
    return s;
  }
  s.step.resize(k);
  for (int j = 0; j < k; ++j) {
    s.step[j] = glp_get_col_prim(lp, j + 1);
    if (radius > 0 && glp_get_col_dual(lp, j + 1) != 0.0) s.radius_active = true;
  }
  s.t = glp_get_col_prim(lp, k + 1);
  s.lambda = Eigen::VectorXd::Zero(n);
  s.side = Eigen::VectorXi::Zero(n);
  for (int i = 0; i < n; ++i) {
    const double outer = glp_get_row_dual(lp, 2 * i + 1), inner = glp_get_row_dual(lp, 2 * i + 2);
    if (outer > 0) {
      s.lambda[i] = outer;
      s.side[i] = 1;
    } else if (inner > 0) {
      s.lambda[i] = inner;
      s.side[i] = -1;
    }
  }
  glp_delete_prob(lp);
  s.success = true;
  return s;
}

}  // namespace implicitfit
