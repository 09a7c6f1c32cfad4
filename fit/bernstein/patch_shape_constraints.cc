#include "fit/bernstein/patch_shape_constraints.h"

#include <ceres/manifold.h>

#include <Eigen/Dense>
#include <set>

namespace implicitfit {
namespace {

int IndexOf(const std::array<int, 4>& l) { return BernsteinIndex(l[1], l[2], l[3]); }

class LinearSubspaceManifold : public ceres::Manifold {
 public:
  explicit LinearSubspaceManifold(Eigen::MatrixXd basis) : n_(std::move(basis)) {}
  int AmbientSize() const override { return static_cast<int>(n_.rows()); }
  int TangentSize() const override { return static_cast<int>(n_.cols()); }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
    Eigen::Map<Eigen::VectorXd>(x_plus_delta, n_.rows()) =
        Eigen::Map<const Eigen::VectorXd>(x, n_.rows()) +
        n_ * Eigen::Map<const Eigen::VectorXd>(delta, n_.cols());
    return true;
  }
  bool PlusJacobian(const double*, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        jacobian, n_.rows(), n_.cols()) = n_;
    return true;
  }
  bool Minus(const double* y, const double* x, double* y_minus_x) const override {
    Eigen::Map<Eigen::VectorXd>(y_minus_x, n_.cols()) =
        n_.transpose() * (Eigen::Map<const Eigen::VectorXd>(y, n_.rows()) -
                          Eigen::Map<const Eigen::VectorXd>(x, n_.rows()));
    return true;
  }
  bool MinusJacobian(const double*, double* jacobian) const override {
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        jacobian, n_.cols(), n_.rows()) = n_.transpose();
    return true;
  }

 private:
  Eigen::MatrixXd n_;
};

}  // namespace

bool ShapeConstraintBasis(int k, const Tetrahedron& tet, const PatchShapeConstraints& c,
                          Eigen::MatrixXd* basis, std::string* error) {
  const int n = static_cast<int>(NumBernsteinControlPoints(k));
  auto valid = [](int v) { return v >= 0 && v < 4; };
  std::set<int> zero;
  for (int v : c.through_vertices) {
    if (!valid(v)) return *error = "vertex index out of range (1..4)", false;
    std::array<int, 4> l = {0, 0, 0, 0};
    l[v] = k;
    zero.insert(IndexOf(l));
  }
  for (const auto& e : c.through_edges) {
    if (!valid(e[0]) || !valid(e[1]) || e[0] == e[1])
      return *error = "an edge needs two different vertices in 1..4", false;
    for (int a = 0; a <= k; ++a) {
      std::array<int, 4> l = {0, 0, 0, 0};
      l[e[0]] = a;
      l[e[1]] = k - a;
      zero.insert(IndexOf(l));
    }
  }
  std::vector<std::vector<std::pair<int, double>>> groups;
  std::set<int> tied;
  for (const auto& vn : c.vertex_normals) {
    if (!valid(vn.vertex)) return *error = "vertex index out of range (1..4)", false;
    if (!(vn.normal.norm() > 0.0)) return *error = "a vertex normal must be non-zero", false;
    const int i = vn.vertex;
    std::array<int, 4> l = {0, 0, 0, 0};
    l[i] = k;
    zero.insert(IndexOf(l));
    std::vector<std::pair<int, double>> group;
    for (int j = 0; j < 4; ++j) {
      if (j == i) continue;
      std::array<int, 4> m = {0, 0, 0, 0};
      m[i] = k - 1;
      m[j] = 1;
      const double d = vn.normal.normalized().dot(tet.vertex(j) - tet.vertex(i)) / k;
      if (!tied.insert(IndexOf(m)).second)
        return *error = "two vertex normals share a control point (degree too low)", false;
      group.push_back({IndexOf(m), d});
    }
    groups.push_back(group);
  }
  for (const auto& g : groups)
    for (const auto& [index, d] : g)
      if (zero.count(index) && d != 0.0)
        return *error = "a vertex normal conflicts with a vertex or edge constraint", false;
  std::vector<Eigen::VectorXd> columns;
  for (int i = 0; i < n; ++i)
    if (!zero.count(i) && !tied.count(i)) columns.push_back(Eigen::VectorXd::Unit(n, i));
  for (const auto& g : groups) {
    Eigen::VectorXd col = Eigen::VectorXd::Zero(n);
    for (const auto& [index, d] : g) col[index] = d;
    if (col.norm() == 0.0)
      return *error = "a vertex normal is orthogonal to all three edges", false;
    columns.push_back(col / col.norm());
  }
  if (columns.empty()) return *error = "the constraints leave no free control point", false;
  basis->resize(n, static_cast<int>(columns.size()));
  for (size_t j = 0; j < columns.size(); ++j) basis->col(static_cast<int>(j)) = columns[j];
  return true;
}

ceres::Manifold* NewLinearSubspaceManifold(const Eigen::MatrixXd& basis) {
  return new LinearSubspaceManifold(basis);
}

}  // namespace implicitfit
