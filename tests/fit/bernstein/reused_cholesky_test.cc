// fit/bernstein/reused_cholesky.h: a sequence of sparse SPD systems with one pattern (a stiff fixed part
// plus reweighted rows, the shape of the patch-mesh refinement's systems) solved against dense
// LDL^T solutions; the iterative path (the previous factor as preconditioner) is taken when the
// weights change mildly, a fresh factorisation when they change wildly or the pattern changes.
#include "fit/bernstein/reused_cholesky.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

namespace implicitfit {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// H = 1e8 S^T S + A^T W A + 1e-6 I: S couples neighbours (a stiff 1-D difference operator on
// half of the unknowns), A random sparse rows, W the given row weights.
SparseMatrix System(const SparseMatrix& A, const Eigen::VectorXd& weights, int n) {
  std::vector<Eigen::Triplet<double>> ts;
  for (int i = 0; i + 1 < n / 2; ++i) ts.emplace_back(i, i, 1.0), ts.emplace_back(i, i + 1, -1.0);
  SparseMatrix S(n / 2, n);
  S.setFromTriplets(ts.begin(), ts.end());
  SparseMatrix H = 1e8 * SparseMatrix(S.transpose() * S) +
                   SparseMatrix(A.transpose() * weights.asDiagonal() * A);
  for (int i = 0; i < n; ++i) H.coeffRef(i, i) += 1e-6;
  H.makeCompressed();
  return H;
}

TEST(ReusedCholesky, SolvesASequenceOfReweightedSystems) {
  const int n = 300, rows = 900;
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> column(0, n - 5);
  std::normal_distribution<double> normal;
  std::vector<Eigen::Triplet<double>> ts;
  for (int r = 0; r < rows; ++r) {
    const int c = column(rng);
    for (int j = 0; j < 4; ++j) ts.emplace_back(r, c + j, normal(rng));
  }
  SparseMatrix A(rows, n);
  A.setFromTriplets(ts.begin(), ts.end());
  const Eigen::VectorXd g = Eigen::VectorXd::Random(n);
  ReusedCholeskySolver solver(/*max_iterations=*/30, /*tolerance=*/1e-8);
  Eigen::VectorXd previous;
  std::uniform_real_distribution<double> mild(0.5, 2.0);
  for (int step = 0; step < 5; ++step) {
    Eigen::VectorXd weights(rows);
    for (int r = 0; r < rows; ++r) weights[r] = mild(rng);
    const SparseMatrix H = System(A, weights, n);
    const Eigen::VectorXd expected = Eigen::MatrixXd(H).ldlt().solve(g);
    const Eigen::VectorXd w = solver.Solve(H, g, previous);
    // Relative error in the energy norm of H (the stiff part makes the Euclidean one meaningless).
    const Eigen::VectorXd e = w - expected;
    EXPECT_LT(std::sqrt(e.dot(H * e) / expected.dot(H * expected)), 1e-6) << "step " << step;
    previous = w;
  }
  EXPECT_EQ(solver.factorisations(), 1);
  EXPECT_EQ(solver.iterative_solves(), 4);
}

// Solves a system with unit weights, then one whose weights spread over 12 orders of magnitude
// (a diagonal scaling as far from the first as possible: the first factor is no preconditioner
// for it); returns the second solution's relative error in the energy norm against a dense
// LDL^T (cond(H) ~ 1e14).
double SolveAFarSecondSystem(ReusedCholeskySolver* solver) {
  const int n = 200;
  std::vector<Eigen::Triplet<double>> ts;
  for (int i = 0; i < n; ++i) ts.emplace_back(i, i, 1.0);
  SparseMatrix A(n, n);
  A.setFromTriplets(ts.begin(), ts.end());
  const Eigen::VectorXd g = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  Eigen::VectorXd weights = Eigen::VectorXd::Ones(n);
  solver->Solve(System(A, weights, n), g, Eigen::VectorXd());
  for (int i = 0; i < n; ++i) weights[i] = std::pow(10.0, 12.0 * i / n - 6.0);
  const SparseMatrix H = System(A, weights, n);
  const Eigen::VectorXd w = solver->Solve(H, g, Eigen::VectorXd());
  const Eigen::VectorXd expected = Eigen::MatrixXd(H).ldlt().solve(g);
  const Eigen::VectorXd e = w - expected;
  return std::sqrt(e.dot(H * e) / expected.dot(H * expected));
}

TEST(ReusedCholesky, RefactorisesWhenTheIterationsDoNotConverge) {
  ReusedCholeskySolver solver(/*max_iterations=*/3);  // 3 iterations cannot converge
  EXPECT_LT(SolveAFarSecondSystem(&solver), 1e-6);
  EXPECT_EQ(solver.factorisations(), 2);
  EXPECT_EQ(solver.iterative_solves(), 0);
}

// Early abandonment (header): with the allowance of 30 iterations the same system is given up
// after the few iterations its rate is measured on, not after 30, and still solved exactly by the
// fresh factor. The mild sequence above (tolerance 1e-8, more iterations than the rate needs)
// still converges iteratively on every step.
TEST(ReusedCholesky, GivesUpEarlyOnAnIterationThatCannotConverge) {
  ReusedCholeskySolver solver(/*max_iterations=*/30);
  EXPECT_LT(SolveAFarSecondSystem(&solver), 1e-6);
  EXPECT_EQ(solver.factorisations(), 2);
  EXPECT_EQ(solver.iterative_solves(), 0);
  EXPECT_GE(solver.cg_iterations(), ReusedCholeskySolver::kRateIterations);
  EXPECT_LE(solver.cg_iterations(), 10);
}

}  // namespace
}  // namespace implicitfit
