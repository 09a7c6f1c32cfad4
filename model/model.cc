#include "model/model.h"

#include "model/dual3.h"

#include <cmath>
#include <stdexcept>

namespace implicitfit {
namespace {

struct TypeInfo {
  NodeType type;
  const char* name;
  std::vector<ParameterField> fields;
};

const std::vector<TypeInfo>& Types() {
  static const std::vector<TypeInfo> types = {
      {NodeType::kPlane, "plane", {{"normal", 3}, {"offset", 1}}},
      {NodeType::kSphere, "sphere", {{"center", 3}, {"radius", 1}}},
      {NodeType::kCylinder, "cylinder", {{"point", 3}, {"axis", 3}, {"radius", 1}}},
      {NodeType::kCone, "cone", {{"apex", 3}, {"axis", 3}, {"half_angle", 1}}},
      {NodeType::kTorus,
       "torus",
       {{"center", 3}, {"axis", 3}, {"major_radius", 1}, {"minor_radius", 1}}},
      {NodeType::kEllipsoid, "ellipsoid", {{"center", 3}, {"radii", 3}, {"axes", 6}}},
      {NodeType::kQuadric, "quadric", {{"coefficients", 10}}},
      {NodeType::kBernsteinPatch, "bernstein_patch", {{"control_points", 0}}},
      {NodeType::kUnion, "union", {{"delta", 1}, {"epsilon", 1}}},
      {NodeType::kIntersection, "intersection", {{"delta", 1}, {"epsilon", 1}}},
      {NodeType::kDifference, "difference", {{"delta", 1}, {"epsilon", 1}}},
      {NodeType::kBernsteinMesh, "bernstein_mesh", {{"control_points", 0}}},
  };
  return types;
}

const TypeInfo& InfoOf(NodeType type) {
  for (const TypeInfo& info : Types())
    if (info.type == type) return info;
  throw std::logic_error("unhandled node type");
}

}  // namespace

const char* NodeTypeName(NodeType type) { return InfoOf(type).name; }

const std::vector<ParameterField>& ParameterFieldsOf(NodeType type) { return InfoOf(type).fields; }

std::vector<ParameterField> ParameterFieldsOf(const ModelNode& node) {
  std::vector<ParameterField> fields = ParameterFieldsOf(node.type);
  for (ParameterField& field : fields)
    if (field.size == 0) field.size = node.num_parameters;  // the one per-node field
  return fields;
}

bool NodeTypeFromName(const std::string& name, NodeType* type) {
  for (const TypeInfo& info : Types())
    if (name == info.name) {
      *type = info.type;
      return true;
    }
  return false;
}

bool IsOperator(NodeType type) {
  return type == NodeType::kUnion || type == NodeType::kIntersection ||
         type == NodeType::kDifference;
}

int NumParametersOf(NodeType type) {
  int n = 0;
  for (const ParameterField& field : InfoOf(type).fields) n += field.size;
  return n;
}

int Model::AddNode(ModelNode node, const std::vector<double>& parameters) {
  node.first_parameter = static_cast<int>(parameters_.size());
  node.num_parameters = static_cast<int>(parameters.size());
  parameters_.insert(parameters_.end(), parameters.begin(), parameters.end());
  nodes_.push_back(std::move(node));
  if (root_ < 0) root_ = static_cast<int>(nodes_.size()) - 1;
  return static_cast<int>(nodes_.size()) - 1;
}

int Model::AddPrimitive(NodeType type, const std::vector<double>& parameters, std::string name) {
  if (IsOperator(type)) throw std::invalid_argument("AddPrimitive: operator type");
  if (type == NodeType::kBernsteinPatch)
    throw std::invalid_argument("AddPrimitive: use AddBernsteinPatch for a bernstein_patch");
  if (type == NodeType::kBernsteinMesh)
    throw std::invalid_argument("AddPrimitive: use AddBernsteinMesh for a bernstein_mesh");
  if (static_cast<int>(parameters.size()) != NumParametersOf(type))
    throw std::invalid_argument(std::string("AddPrimitive: ") + NodeTypeName(type) + " takes " +
                                std::to_string(NumParametersOf(type)) + " parameters");
  ModelNode node;
  node.type = type;
  node.name = std::move(name);
  return AddNode(std::move(node), parameters);
}

int Model::AddBernsteinPatch(int degree, const Tetrahedron& tetrahedron,
                             const std::vector<double>& control_points, std::string name) {
  if (degree < 1) throw std::invalid_argument("AddBernsteinPatch: degree must be >= 1");
  if (static_cast<long long>(control_points.size()) != NumBernsteinControlPoints(degree))
    throw std::invalid_argument("AddBernsteinPatch: degree " + std::to_string(degree) + " takes " +
                                std::to_string(NumBernsteinControlPoints(degree)) +
                                " control points");
  ModelNode node;
  node.type = NodeType::kBernsteinPatch;
  node.name = std::move(name);
  node.degree = degree;
  node.tetrahedron = tetrahedron;
  return AddNode(std::move(node), control_points);
}

int Model::AddBernsteinMesh(int degree, const BernsteinGrid& grid, int continuity,
                            const std::vector<double>& control_points, std::string name) {
  if (degree < 1) throw std::invalid_argument("AddBernsteinMesh: degree must be >= 1");
  if (continuity != 0 && continuity != 1)
    throw std::invalid_argument("AddBernsteinMesh: continuity must be 0 or 1");
  if (!(grid.cell > 0.0) || !std::isfinite(grid.cell) || !grid.origin.allFinite())
    throw std::invalid_argument("AddBernsteinMesh: the grid needs a finite origin and cell > 0");
  for (int c : grid.cells)
    if (c < 1) throw std::invalid_argument("AddBernsteinMesh: every cells entry must be >= 1");
  const long long count = grid.NumTetrahedra() * NumBernsteinControlPoints(degree);
  if (static_cast<long long>(control_points.size()) != count)
    throw std::invalid_argument("AddBernsteinMesh: " + std::to_string(grid.NumTetrahedra()) +
                                " tetrahedra of degree " + std::to_string(degree) + " take " +
                                std::to_string(count) + " control points");
  ModelNode node;
  node.type = NodeType::kBernsteinMesh;
  node.name = std::move(name);
  node.degree = degree;
  node.grid = grid;
  node.continuity = continuity;
  return AddNode(std::move(node), control_points);
}

int Model::AddOperator(NodeType type, std::vector<int> children, double delta, double epsilon,
                       int order, std::string name) {
  if (!IsOperator(type)) throw std::invalid_argument("AddOperator: not an operator type");
  if (children.empty()) throw std::invalid_argument("AddOperator: no children");
  for (int c : children)
    if (c < 0 || c >= static_cast<int>(nodes_.size()))
      throw std::invalid_argument("AddOperator: child index out of range");
  ModelNode node;
  node.type = type;
  node.name = std::move(name);
  node.children = std::move(children);
  node.order = order;
  const int index = AddNode(std::move(node), {delta, epsilon});
  root_ = index;  // an operator added last is the natural root; SetRoot overrides
  return index;
}

double Model::Value(const Eigen::Vector3d& x) const {
  return Evaluate(parameters_.data(), x.data());
}

Eigen::Vector3d Model::Gradient(const Eigen::Vector3d& x, double* value) const {
  // Reused per thread: Gradient is called per point by samplers and reports.
  thread_local std::vector<Dual3> p;
  p.assign(parameters_.begin(), parameters_.end());
  const Dual3 xd[3] = {Dual3(x[0], Eigen::Vector3d::UnitX()), Dual3(x[1], Eigen::Vector3d::UnitY()),
                       Dual3(x[2], Eigen::Vector3d::UnitZ())};
  const Dual3 f = Evaluate(p.data(), xd);
  if (value) *value = f.a;
  return f.v;
}

std::string Model::NodeLabel(int index) const {
  if (!nodes_[index].name.empty()) return nodes_[index].name;
  if (index == root_) return "root";
  for (size_t parent = 0; parent < nodes_.size(); ++parent) {
    const std::vector<int>& ch = nodes_[parent].children;
    for (size_t c = 0; c < ch.size(); ++c)
      if (ch[c] == index)
        return NodeLabel(static_cast<int>(parent)) + ".children[" + std::to_string(c) + "]";
  }
  return "node[" + std::to_string(index) + "]";
}

std::vector<std::string> Model::ParameterNames() const {
  std::vector<std::string> names(parameters_.size());
  for (size_t i = 0; i < nodes_.size(); ++i) {
    const ModelNode& node = nodes_[i];
    const std::string label = NodeLabel(static_cast<int>(i));
    int k = node.first_parameter;
    for (const ParameterField& field : ParameterFieldsOf(node))
      for (int j = 0; j < field.size; ++j)
        names[k++] = label + "." + field.name +
                     (field.size > 1 ? "[" + std::to_string(j) + "]" : std::string());
  }
  return names;
}

}  // namespace implicitfit
