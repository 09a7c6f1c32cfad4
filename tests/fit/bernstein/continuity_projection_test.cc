// The exact continuity projection (fit/bernstein/continuity_projection.h) against a dense reference: the
// orthogonal projection onto the column space of the spline basis N (model/
// bernstein_mesh_continuity.h, a separate construction: kernel of the C1 rows by dense
// column-pivoted QR), N (N^T N)^-1 N^T b, on grids small enough for dense algebra.
#include "fit/bernstein/continuity_projection.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "model/bernstein/bernstein_mesh_continuity.h"

namespace implicitfit {
namespace {

std::vector<double> DenseReference(const BernsteinGrid& grid, int k, int continuity,
                                   const std::vector<double>& b) {
  const Eigen::MatrixXd N = BernsteinSplineBasis(grid, k, continuity);
  const Eigen::Map<const Eigen::VectorXd> bv(b.data(), static_cast<long>(b.size()));
  const Eigen::VectorXd z = (N.transpose() * N).ldlt().solve(N.transpose() * bv);
  const Eigen::VectorXd p = N * z;
  return std::vector<double>(p.data(), p.data() + p.size());
}

struct Case {
  std::array<int, 3> cells;
  int k, continuity;
};

TEST(ContinuityProjection, MatchesTheDenseProjectionOntoTheSplineSpace) {
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  for (const Case& c : {Case{{2, 2, 2}, 3, 1}, Case{{2, 1, 2}, 4, 1}, Case{{2, 2, 1}, 3, 0},
                        Case{{1, 1, 1}, 5, 1}}) {
    BernsteinGrid grid;
    grid.origin = Eigen::Vector3d(-0.3, 0.1, 0.2);
    grid.cell = 0.7;
    grid.cells = c.cells;
    const long long size = grid.NumTetrahedra() * NumBernsteinControlPoints(c.k);
    std::vector<double> b(static_cast<size_t>(size));
    for (double& v : b) v = normal(rng);
    const std::vector<double> expected = DenseReference(grid, c.k, c.continuity, b);
    std::vector<double> projected = b;
    const double defect = ProjectOntoContinuitySpace(grid, c.k, c.continuity, &projected);
    EXPECT_LT(defect, 1e-12) << c.k;
    EXPECT_LT(ContinuityDefect(grid, c.k, c.continuity, projected.data()), 1e-12);
    double worst = 0;
    for (size_t i = 0; i < b.size(); ++i)
      worst = std::max(worst, std::abs(projected[i] - expected[i]));
    EXPECT_LT(worst, 1e-9) << "grid " << c.cells[0] << "x" << c.cells[1] << "x" << c.cells[2]
                           << " k " << c.k << " C" << c.continuity;
    // A projection: applying it again changes nothing.
    std::vector<double> twice = projected;
    const ContinuityProjector projector(grid, c.k, c.continuity);
    projector.Project(&twice);
    for (size_t i = 0; i < b.size(); ++i) EXPECT_NEAR(twice[i], projected[i], 1e-11);
  }
}

}  // namespace
}  // namespace implicitfit
