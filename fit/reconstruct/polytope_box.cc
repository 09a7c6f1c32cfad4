#include "fit/reconstruct/polytope_box.h"

#include <glpk.h>

#include <cmath>
#include <mutex>

#include "fit/common/glpk_mutex.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// The programme over x, y, z (free) with one row per face; objective set by the caller.
glp_prob* MakeProgramme(const std::vector<HalfSpace>& faces) {
  FreeGlpkEnvironmentAtThreadExit();
  glp_prob* lp = glp_create_prob();
  glp_add_cols(lp, 3);
  for (int j = 1; j <= 3; ++j) glp_set_col_bnds(lp, j, GLP_FR, 0.0, 0.0);
  const int rows = static_cast<int>(faces.size());
  if (rows > 0) glp_add_rows(lp, rows);
  std::vector<int> ia(1), ja(1);
  std::vector<double> ar(1);
  for (int i = 0; i < rows; ++i) {
    glp_set_row_bnds(lp, i + 1, GLP_UP, 0.0, faces[i].offset);
    for (int j = 0; j < 3; ++j) {
      if (faces[i].normal[j] == 0.0) continue;
      ia.push_back(i + 1);
      ja.push_back(j + 1);
      ar.push_back(faces[i].normal[j]);
    }
  }
  glp_load_matrix(lp, static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());
  glp_set_obj_dir(lp, GLP_MAX);
  return lp;
}

// Solves; returns the status (GLP_OPT, GLP_UNBND, GLP_NOFEAS, ...) or -100 - GLPK's return
// code when it failed.
int Solve(glp_prob* lp) {
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  int rc = glp_simplex(lp, &parm);  // warm: from the previous programme's basis
  if (rc == 0) rc = glp_exact(lp, &parm);
  if (rc != 0) {  // a singular or ill-conditioned warm basis: again from the standard basis
    glp_std_basis(lp);
    rc = glp_simplex(lp, &parm);
    if (rc == 0) rc = glp_exact(lp, &parm);
  }
  if (rc != 0) return -100 - rc;
  return glp_get_status(lp);
}

double Pad(double v) { return 1e-9 * (1.0 + std::abs(v)); }

// The Chebyshev centre of the polyhedron's part beyond `bound` along axis a, direction s
// (x_a >= bound for s = +1, x_a <= bound for s = -1), ball radius capped at `cap`; `fallback`
// moved to the bound when the programme is not solved.
Vec DeepestBeyond(const std::vector<HalfSpace>& faces, int a, int s, double bound, double cap,
                  const Vec& fallback) {
  std::lock_guard<std::mutex> lock(GlpkMutex());
  glp_term_out(GLP_OFF);
  glp_prob* lp = MakeProgramme(faces);
  if (s > 0)
    glp_set_col_bnds(lp, a + 1, GLP_LO, bound, 0.0);
  else
    glp_set_col_bnds(lp, a + 1, GLP_UP, 0.0, bound);
  const int r = glp_add_cols(lp, 1);
  glp_set_col_bnds(lp, r, GLP_DB, 0.0, cap);
  glp_set_obj_coef(lp, r, 1.0);
  for (int i = 1; i <= static_cast<int>(faces.size()); ++i) {
    int ind[6];
    double val[6];
    const int len = glp_get_mat_row(lp, i, ind, val);  // 1-based: ind[1..len], len <= 3
    ind[len + 1] = r;
    val[len + 1] = faces[i - 1].normal.norm();
    glp_set_mat_row(lp, i, len + 1, ind, val);
  }
  Vec x = fallback;
  x[a] = bound;
  const int status = Solve(lp);
  if (status == GLP_OPT)
    for (int j = 0; j < 3; ++j) x[j] = glp_get_col_prim(lp, j + 1);
  glp_delete_prob(lp);
  return x;
}

}  // namespace

PolytopeBox BoundPolytope(const std::vector<HalfSpace>& faces, const Vec& limit_lo,
                          const Vec& limit_hi) {
  PolytopeBox out;
  const Vec centre = 0.5 * (limit_lo + limit_hi);
  std::vector<double> reach;  // per exit: how far the polyhedron goes that way (s x_a)
  if (faces.empty()) {  // all of space
    out.extent = PolytopeExtent::kBeyondLimit;
    for (int a = 0; a < 3; ++a)
      for (int s : {1, -1}) {
        Vec w = centre;
        w[a] = s > 0 ? limit_hi[a] : limit_lo[a];
        PolytopeBox::Exit exit;
        exit.direction = s * Vec::Unit(a);
        exit.witnesses = {w};
        exit.infinite = true;
        out.exits.push_back(exit);
      }
    return out;
  }
  std::unique_lock<std::mutex> lock(GlpkMutex());
  glp_term_out(GLP_OFF);
  glp_prob* lp = MakeProgramme(faces);
  // Feasibility first (objective 0): an empty polyhedron is empty whatever the objective.
  int status = Solve(lp);
  if (status == GLP_NOFEAS) {
    out.extent = PolytopeExtent::kEmpty;
  } else if (status != GLP_OPT) {
    out.message = "feasibility programme not solved (status " + std::to_string(status) + ")";
  } else {
    out.extent = PolytopeExtent::kBounded;
    for (int a = 0; a < 3 && out.extent != PolytopeExtent::kUnsolved; ++a)
      for (int s : {1, -1}) {
        for (int j = 1; j <= 3; ++j) glp_set_obj_coef(lp, j, j == a + 1 ? s : 0.0);
        status = Solve(lp);
        if (status != GLP_OPT && status != GLP_UNBND) {
          out.extent = PolytopeExtent::kUnsolved;
          out.message = "box programme not solved (status " + std::to_string(status) + ")";
          break;
        }
        const double limit = s > 0 ? limit_hi[a] : limit_lo[a];
        if (status == GLP_OPT) {
          const double v = glp_get_col_prim(lp, a + 1);
          (s > 0 ? out.hi : out.lo)[a] = v + s * Pad(v);
          if (s * (v - limit) <= 0) continue;
        }
        out.extent = PolytopeExtent::kBeyondLimit;
        PolytopeBox::Exit exit;
        exit.direction = s * Vec::Unit(a);
        exit.infinite = status == GLP_UNBND;
        reach.push_back(exit.infinite ? 1e300 : s * glp_get_col_prim(lp, a + 1));
        out.exits.push_back(exit);
      }
  }
  glp_delete_prob(lp);
  lock.unlock();  // DeepestBeyond takes it again
  if (out.extent != PolytopeExtent::kBeyondLimit) out.exits.clear();
  const double span = (limit_hi - limit_lo).norm();
  for (size_t k = 0; k < out.exits.size(); ++k) {
    PolytopeBox::Exit& e = out.exits[k];
    int a = 0;
    e.direction.cwiseAbs().maxCoeff(&a);
    const int s = e.direction[a] > 0 ? 1 : -1;
    const double limit = s > 0 ? limit_hi[a] : limit_lo[a];
    for (const double farther : {0.0, 1.0, 4.0, 16.0, 64.0}) {
      if (s * limit + farther * span > reach[k]) break;  // the polyhedron ends before
      e.witnesses.push_back(
          DeepestBeyond(faces, a, s, limit + s * farther * span, span, centre));
    }
  }
  return out;
}

}  // namespace implicitfit
