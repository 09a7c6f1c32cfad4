// A sparse symmetric positive definite solver for a sequence of nearby systems H_t w = g_t with
// one sparsity pattern (the iterations of the patch-mesh refinement, fit/bernstein/bernstein_mesh_fitter.h:
// the same rows every iteration, only their weights change).
//
// Maths. A supernodal Cholesky factor L L^T = H_s (CHOLMOD) of an earlier matrix of the sequence
// is a preconditioner for the current one: preconditioned conjugate gradients on H_t w = g_t
// with M = H_s converge in O(sqrt(kappa)) steps, kappa = cond(H_s^-1 H_t), which stays small when
// H_t - H_s is a reweighting of well-scaled rows (the stiff continuity rows, the bulk of H's
// spectrum, are the same in both, so they cancel in H_s^-1 H_t). Each step costs two triangular
// solves, O(nnz L), against a factorisation's O(sum of front sizes cubed): on the degree-5 grids
// of the patch-mesh fit one numeric factorisation costs as much as hundreds of solves. Stopping
// rule: the preconditioned residual r^T M^-1 r at most tolerance^2 g^T M^-1 g (scale-free in the
// metric of M), else after max_iterations the matrix is factorised afresh and solved directly.
// The default tolerance 1e-5 suits the refinement's steps, which are followed by a line search
// (kitten, degree 4: the same RMS to 6 digits as with 1e-8, 8-14 iterations instead of 14-30).
// Early abandonment: from the kRateIterations-th iteration on, the mean reduction of r^T M^-1 r
// per iteration so far predicts the iterations the target needs; when that exceeds
// max_iterations the iteration stops and the matrix is factorised at once. A failed iteration
// costs nearly a factorisation (Fit4CAD PC155, two levels, 49 090 unknowns: 30 iterations took
// 0.7-1.1x a factorisation's time) and failures come in runs (the relaxed stages reweight the
// far-field rows by 0.3 at a time): 39 of that fit's 65 iterative tries failed, 42% of its
// solver time, where a converging iteration reduces the residual steadily from the start.
// The symbolic analysis (ordering, supernodes) is kept while the pattern is unchanged.
#pragma once

#include <Eigen/SparseCore>
#include <memory>
#include <vector>

namespace implicitfit {

class ReusedCholeskySolver {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double>;

  // max_iterations 0: always factorise (a direct solve of every system).
  explicit ReusedCholeskySolver(int max_iterations = 30, double tolerance = 1e-5);
  ~ReusedCholeskySolver();

  // Solves H w = g (H compressed, symmetric positive definite; its lower and upper parts both
  // stored). guess: a starting point for the iterative path (may be empty).
  Eigen::VectorXd Solve(const SparseMatrix& H, const Eigen::VectorXd& g,
                        const Eigen::VectorXd& guess);

  int factorisations() const { return factorisations_; }
  int iterative_solves() const { return iterative_solves_; }
  long long cg_iterations() const { return cg_iterations_; }  // all, converged or not

  static constexpr int kRateIterations = 5;  // iterations before the rate is trusted

 private:
  bool SamePattern(const SparseMatrix& H) const;
  bool Iterate(const SparseMatrix& H, const Eigen::VectorXd& g, const Eigen::VectorXd& guess,
               Eigen::VectorXd* w, int* iterations) const;

  int max_iterations_;
  double tolerance_;
  struct Factor;                     // CHOLMOD's supernodal LL^T (SuiteSparse stays in the .cc)
  std::unique_ptr<Factor> cholmod_;  // analysed pattern
  std::vector<SparseMatrix::StorageIndex> inner_, outer_;  // of that pattern
  bool factor_valid_ = false;  // cholmod_ holds a successful numeric factor
  int factorisations_ = 0, iterative_solves_ = 0;
  long long cg_iterations_ = 0;
};

}  // namespace implicitfit
