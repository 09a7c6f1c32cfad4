#include "fit/bernstein/reused_cholesky.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

namespace implicitfit {

struct ReusedCholeskySolver::Factor : Eigen::CholmodSupernodalLLT<SparseMatrix> {};

ReusedCholeskySolver::ReusedCholeskySolver(int max_iterations, double tolerance)
    : max_iterations_(max_iterations), tolerance_(tolerance) {}

ReusedCholeskySolver::~ReusedCholeskySolver() = default;

bool ReusedCholeskySolver::SamePattern(const SparseMatrix& H) const {
  return cholmod_ && H.nonZeros() == static_cast<long>(inner_.size()) &&
         std::equal(inner_.begin(), inner_.end(), H.innerIndexPtr()) &&
         std::equal(outer_.begin(), outer_.end(), H.outerIndexPtr());
}

// Preconditioned conjugate gradients with the stored factor as M (header).
bool ReusedCholeskySolver::Iterate(const SparseMatrix& H, const Eigen::VectorXd& g,
                                   const Eigen::VectorXd& guess, Eigen::VectorXd* w,
                                   int* iterations) const {
  *iterations = 0;
  const Eigen::VectorXd mg = cholmod_->solve(g);
  const double reference = g.dot(mg);
  if (!(reference > 0) || !std::isfinite(reference)) return false;
  Eigen::VectorXd x = guess.size() == g.size() ? guess : mg;
  Eigen::VectorXd r = g - H * x;
  Eigen::VectorXd z = cholmod_->solve(r);
  double rz = r.dot(z);
  const double target = tolerance_ * tolerance_ * reference;
  Eigen::VectorXd p = z;
  // Early abandonment (header): the reduction of r^T M^-1 r still needed, in orders of e.
  const double rz_start = rz, needed = std::log(rz_start / target);
  int& it = *iterations;
  for (it = 0; it < max_iterations_ && rz > target;) {
    const Eigen::VectorXd hp = H * p;
    const double php = p.dot(hp);
    if (!(php > 0)) return false;
    const double alpha = rz / php;
    x += alpha * p;
    r -= alpha * hp;
    z = cholmod_->solve(r);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
    ++it;
    if (it >= kRateIterations && rz > target) {
      const double rate = std::log(rz_start / rz) / it;  // mean reduction per iteration so far
      if (!(rate > 0) || needed / rate > max_iterations_) return false;
    }
  }
  if (!(rz <= target) || !x.allFinite()) return false;
  *w = std::move(x);
  return true;
}

Eigen::VectorXd ReusedCholeskySolver::Solve(const SparseMatrix& H, const Eigen::VectorXd& g,
                                            const Eigen::VectorXd& guess) {
  Eigen::VectorXd w;
  const bool same_pattern = SamePattern(H);
  if (same_pattern && factor_valid_ && max_iterations_ > 0) {
    int iterations = 0;
    const bool converged = Iterate(H, g, guess, &w, &iterations);
    cg_iterations_ += iterations;
    if (converged) {
      ++iterative_solves_;
      return w;
    }
  }
  if (!same_pattern) {
    cholmod_ = std::make_unique<Factor>();
    cholmod_->analyzePattern(H);
    inner_.assign(H.innerIndexPtr(), H.innerIndexPtr() + H.nonZeros());
    outer_.assign(H.outerIndexPtr(), H.outerIndexPtr() + H.outerSize() + 1);
  }
  cholmod_->factorize(H);
  ++factorisations_;
  factor_valid_ = cholmod_->info() == Eigen::Success;
  if (factor_valid_) w = cholmod_->solve(g);
  if (!factor_valid_ || !w.allFinite()) {
    // Not numerically positive definite: Eigen's simplicial LDL^T as the fallback.
    factor_valid_ = false;
    Eigen::SimplicialLDLT<SparseMatrix> ldlt(H);
    w = ldlt.solve(g);
  }
  return w;
}

}  // namespace implicitfit
