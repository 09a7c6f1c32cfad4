#include "model/model.h"

#include <cmath>
#include <stdexcept>

#include "model/dual3.h"
#include "model/primitives/primitive_kinds.h"

namespace implicitfit {
namespace {

struct TypeInfo {
  NodeType type;
  const char* name;
  std::vector<ParameterField> fields;
};

// Primitives from their table (model/primitives/primitive_kinds.h), then every other node type.
const std::vector<TypeInfo>& Types() {
  static const std::vector<TypeInfo> types = [] {
    std::vector<TypeInfo> t;
    for (const PrimitiveKind& kind : PrimitiveKinds())
      t.push_back({kind.type, kind.name, kind.fields});
    const std::vector<TypeInfo> others = {
        {NodeType::kBernsteinPatch, "bernstein_patch", {{"control_points", 0}}},
        {NodeType::kUnion, "union", {{"delta", 1}, {"epsilon", 1}}},
        {NodeType::kIntersection, "intersection", {{"delta", 1}, {"epsilon", 1}}},
        {NodeType::kDifference, "difference", {{"delta", 1}, {"epsilon", 1}}},
        {NodeType::kComplement, "complement", {}},
        {NodeType::kMorph, "morph", {{"t", 1}}},
        {NodeType::kBlobs,
         "blobs",
         {{"centers", -3, FieldRole::kPosition},
          {"weights", -1},
          {"widths", -1, FieldRole::kPositiveLength},
          {"threshold", 1}}},
        {NodeType::kSkeletonOffset,
         "skeleton_offset",
         {{"skeleton", -3, FieldRole::kPosition}, {"radius", 1, FieldRole::kPositiveLength}}},
        {NodeType::kPartition, "partition", {{"epsilon", 1}}},
        {NodeType::kBernsteinMesh, "bernstein_mesh", {{"control_points", 0}}},
        {NodeType::kPartitionSequence, "partition_sequence", {{"epsilon", 1}}},
        {NodeType::kColemanFeatures,
         "coleman_features",
         {{"core_radius", 1, FieldRole::kPositiveLength},
          {"features", -ColemanFeatures::kPerFeature}}},
        {NodeType::kBSplineSurface, "bspline_surface", {{"control_points", 0}}},
        {NodeType::kBSplineVolume, "bspline_volume", {{"coefficients", 0}}},
    };
    t.insert(t.end(), others.begin(), others.end());
    return t;
  }();
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
    if (field.size == 0)
      field.size = node.num_parameters;  // the one per-node field
    else if (field.size < 0)
      field.size *= -node.count;  // per element
  if (const int features = SkeletonFeatureCount(node))
    fields.push_back({"features", ColemanFeatures::kPerFeature * features});
  if (!node.curve_vertices.empty()) {
    int size = 0;
    for (int n : node.curve_vertices) size += 3 * n + 4;
    fields.push_back({"curve_features", size});
  }
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

bool IsComposite(NodeType type) {
  return type == NodeType::kComplement || type == NodeType::kMorph;
}

// Children a composite node takes (-1: any number >= 1).
static int CompositeArity(NodeType type) {
  if (type == NodeType::kComplement) return 1;
  if (type == NodeType::kMorph) return 2;
  return -1;
}

int NumParametersOf(NodeType type) {
  int n = 0;
  for (const ParameterField& field : InfoOf(type).fields) n += std::max(field.size, 0);
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
  if (IsOperator(type) || IsComposite(type))
    throw std::invalid_argument("AddPrimitive: operator type");
  if (type == NodeType::kBernsteinPatch)
    throw std::invalid_argument("AddPrimitive: use AddBernsteinPatch for a bernstein_patch");
  if (type == NodeType::kBlobs || type == NodeType::kSkeletonOffset ||
      type == NodeType::kPartition || type == NodeType::kPartitionSequence ||
      type == NodeType::kColemanFeatures)
    throw std::invalid_argument("AddPrimitive: use AddBlobs / AddSkeletonOffset / AddPartition");
  if (type == NodeType::kBernsteinMesh)
    throw std::invalid_argument("AddPrimitive: use AddBernsteinMesh for a bernstein_mesh");
  if (type == NodeType::kBSplineSurface || type == NodeType::kBSplineVolume)
    throw std::invalid_argument("AddPrimitive: use AddBSplineSurface / AddBSplineVolume");
  if (static_cast<int>(parameters.size()) != NumParametersOf(type))
    throw std::invalid_argument(std::string("AddPrimitive: ") + NodeTypeName(type) + " takes " +
                                std::to_string(NumParametersOf(type)) + " parameters");
  ModelNode node;
  node.type = type;
  node.name = std::move(name);
  return AddNode(std::move(node), parameters);
}

int Model::AddComposite(NodeType type, std::vector<int> children,
                        const std::vector<double>& parameters, std::string name) {
  if (!IsComposite(type)) throw std::invalid_argument("AddComposite: not a composite type");
  const int arity = CompositeArity(type);
  if (children.empty() || (arity > 0 && static_cast<int>(children.size()) != arity))
    throw std::invalid_argument(std::string("AddComposite: ") + NodeTypeName(type) + " takes " +
                                std::to_string(arity) + " children");
  for (int c : children)
    if (c < 0 || c >= static_cast<int>(nodes_.size()))
      throw std::invalid_argument("AddComposite: child index out of range");
  if (static_cast<int>(parameters.size()) != NumParametersOf(type))
    throw std::invalid_argument(std::string("AddComposite: ") + NodeTypeName(type) + " takes " +
                                std::to_string(NumParametersOf(type)) + " parameters");
  ModelNode node;
  node.type = type;
  node.name = std::move(name);
  node.children = std::move(children);
  const int index = AddNode(std::move(node), parameters);
  root_ = index;  // as for operators: the node added last is the natural root
  return index;
}

int Model::AddPartition(std::vector<std::vector<double>> cuts, double epsilon, int order,
                        std::vector<int> children, std::string name) {
  if (cuts.size() != 3) throw std::invalid_argument("AddPartition: cuts for x, y and z");
  if (!(epsilon > 0.0)) throw std::invalid_argument("AddPartition: epsilon must be > 0");
  if (order < 0 || order > UnitStep::kMaxOrder) throw std::invalid_argument("AddPartition: order");
  size_t cells = 1;
  for (const std::vector<double>& c : cuts) {
    for (size_t i = 1; i < c.size(); ++i)
      if (!(c[i] > c[i - 1])) throw std::invalid_argument("AddPartition: cuts must increase");
    cells *= c.size() + 1;
  }
  if (SmallestPartitionCell(cuts) < 2.0 * epsilon)
    throw std::invalid_argument("AddPartition: a cell is narrower than 2 epsilon");
  if (children.size() != cells)
    throw std::invalid_argument("AddPartition: needs " + std::to_string(cells) + " children");
  for (int c : children)
    if (c < 0 || c >= static_cast<int>(nodes_.size()))
      throw std::invalid_argument("AddPartition: child index out of range");
  ModelNode node;
  node.type = NodeType::kPartition;
  node.name = std::move(name);
  node.children = std::move(children);
  node.order = order;
  node.cuts = std::move(cuts);
  const int index = AddNode(std::move(node), {epsilon});
  root_ = index;
  return index;
}

int Model::AddPartitionSequence(const std::vector<int>& separators, double epsilon, int order,
                                const std::vector<int>& children, std::string name) {
  const std::string who = "AddPartitionSequence: ";
  if (separators.empty()) throw std::invalid_argument(who + "needs at least one separator");
  if (!(epsilon > 0.0)) throw std::invalid_argument(who + "epsilon must be > 0");
  if (order < 0 || order > UnitStep::kMaxOrder) throw std::invalid_argument(who + "order");
  if (children.size() != separators.size() + 1)
    throw std::invalid_argument(who + "needs " + std::to_string(separators.size() + 1) +
                                " children (one more than separators)");
  for (int c : separators)
    if (c < 0 || c >= static_cast<int>(nodes_.size()) || nodes_[c].type != NodeType::kPlane)
      throw std::invalid_argument(who + "every separator must be a plane node");
  for (int c : children)
    if (c < 0 || c >= static_cast<int>(nodes_.size()))
      throw std::invalid_argument(who + "child index out of range");
  ModelNode node;
  node.type = NodeType::kPartitionSequence;
  node.name = std::move(name);
  node.count = static_cast<int>(separators.size());
  node.order = order;
  node.children = separators;
  node.children.insert(node.children.end(), children.begin(), children.end());
  double width = 0.0;
  const int narrow = NarrowPartitionSequenceCell(SeparatorsOf(node), epsilon, &width);
  if (narrow >= 0)
    throw std::invalid_argument(who + "cell " + std::to_string(narrow) + " is " +
                                std::to_string(width) +
                                " wide, less than 2 epsilon = " + std::to_string(2.0 * epsilon));
  const int index = AddNode(std::move(node), {epsilon});
  root_ = index;
  return index;
}

int Model::AddColemanFeatures(int core, double core_radius, const std::vector<double>& features,
                              std::string name) {
  const size_t m = features.size() / ColemanFeatures::kPerFeature;
  if (m == 0 || features.size() != m * ColemanFeatures::kPerFeature)
    throw std::invalid_argument("AddColemanFeatures: 7 numbers per feature, at least one");
  if (!(core_radius > 0.0)) throw std::invalid_argument("AddColemanFeatures: core radius > 0");
  if (core < 0 || core >= static_cast<int>(nodes_.size()))
    throw std::invalid_argument("AddColemanFeatures: core index out of range");
  ModelNode node;
  node.type = NodeType::kColemanFeatures;
  node.name = std::move(name);
  node.count = static_cast<int>(m);
  node.children = {core};
  std::vector<double> p = {core_radius};
  p.insert(p.end(), features.begin(), features.end());
  const int index = AddNode(std::move(node), p);
  root_ = index;
  return index;
}

int Model::AddColemanCurveFeatures(int core, double core_radius,
                                   const std::vector<double>& features,
                                   const std::vector<std::vector<double>>& curves,
                                   std::string name) {
  if (curves.empty()) return AddColemanFeatures(core, core_radius, features, std::move(name));
  const size_t m = features.size() / ColemanFeatures::kPerFeature;
  if (features.size() != m * ColemanFeatures::kPerFeature)
    throw std::invalid_argument("AddColemanCurveFeatures: 7 numbers per point feature");
  if (!(core_radius > 0.0)) throw std::invalid_argument("AddColemanCurveFeatures: core radius > 0");
  if (core < 0 || core >= static_cast<int>(nodes_.size()))
    throw std::invalid_argument("AddColemanCurveFeatures: core index out of range");
  ModelNode node;
  node.type = NodeType::kColemanFeatures;
  node.name = std::move(name);
  node.count = static_cast<int>(m);
  node.children = {core};
  std::vector<double> p = {core_radius};
  p.insert(p.end(), features.begin(), features.end());
  for (const std::vector<double>& c : curves) {
    if (c.size() < 7 || (c.size() - 4) % 3 != 0)
      throw std::invalid_argument("AddColemanCurveFeatures: 3 n + 4 numbers per curve feature");
    node.curve_vertices.push_back(static_cast<int>((c.size() - 4) / 3));
    p.insert(p.end(), c.begin(), c.end());
  }
  const int index = AddNode(std::move(node), p);
  root_ = index;
  return index;
}

std::vector<SeparatorPlane> Model::SeparatorsOf(const ModelNode& node) const {
  std::vector<SeparatorPlane> out;
  for (int j = 0; j < node.count; ++j) {
    const double* p = parameters_.data() + nodes_[node.children[j]].first_parameter;
    const Eigen::Vector3d n(p[0], p[1], p[2]);
    out.push_back({n / n.norm(), p[3] / n.norm()});
  }
  return out;
}

int Model::AddBlobs(BlobKernel kernel, int order, const std::vector<double>& centers,
                    const std::vector<double>& weights, const std::vector<double>& widths,
                    double threshold, std::string name) {
  const size_t m = weights.size();
  if (m == 0 || centers.size() != 3 * m || widths.size() != m)
    throw std::invalid_argument("AddBlobs: need m >= 1 weights, 3 m centre coordinates, m widths");
  if (kernel == BlobKernel::kUnitStep && (order < 1 || order > UnitStep::kMaxOrder))
    throw std::invalid_argument("AddBlobs: the h_n kernel needs an order 1.." +
                                std::to_string(UnitStep::kMaxOrder));
  ModelNode node;
  node.type = NodeType::kBlobs;
  node.name = std::move(name);
  node.count = static_cast<int>(m);
  node.variant = static_cast<int>(kernel);
  node.order = kernel == BlobKernel::kUnitStep ? order : 0;
  std::vector<double> p = centers;
  p.insert(p.end(), weights.begin(), weights.end());
  p.insert(p.end(), widths.begin(), widths.end());
  p.push_back(threshold);
  return AddNode(std::move(node), p);
}

int Model::AddSkeletonOffset(SkeletonKind kind, const std::vector<double>& points, double radius,
                             std::string name) {
  const size_t m = points.size() / 3;
  if (m == 0 || points.size() != 3 * m || (kind == SkeletonKind::kSegments && m % 2 != 0) ||
      (kind == SkeletonKind::kPolyline && m < 2) ||
      (kind == SkeletonKind::kTriangles && m % 3 != 0))
    throw std::invalid_argument(
        "AddSkeletonOffset: points (3 numbers each), two per segment, "
        ">= 2 for a polyline, three per triangle");
  ModelNode node;
  node.type = NodeType::kSkeletonOffset;
  node.name = std::move(name);
  node.count = static_cast<int>(m);
  node.variant = static_cast<int>(kind);
  std::vector<double> p = points;
  p.push_back(radius);
  return AddNode(std::move(node), p);
}

int Model::AddSkeletonOffsetWithFeatures(SkeletonKind kind, const std::vector<double>& points,
                                         double radius, const std::vector<double>& features,
                                         std::string name) {
  const size_t m = features.size() / ColemanFeatures::kPerFeature;
  if (m == 0 || features.size() != m * ColemanFeatures::kPerFeature)
    throw std::invalid_argument("AddSkeletonOffsetWithFeatures: 7 numbers per feature, >= 1");
  if (!(radius > 0.0))
    throw std::invalid_argument("AddSkeletonOffsetWithFeatures: core radius must be > 0");
  const int index = AddSkeletonOffset(kind, points, radius, std::move(name));
  return AddSkeletonFeatures(index, features);
}

int Model::AddSkeletonFeatures(int index, const std::vector<double>& features) {
  if (features.empty() || features.size() % ColemanFeatures::kPerFeature != 0 ||
      index != static_cast<int>(nodes_.size()) - 1 ||
      nodes_[index].type != NodeType::kSkeletonOffset)
    throw std::invalid_argument("AddSkeletonFeatures: 7 numbers per feature, on the last node");
  parameters_.insert(parameters_.end(), features.begin(), features.end());
  nodes_[index].num_parameters += static_cast<int>(features.size());
  return index;
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
  if (grid.refined() && static_cast<long long>(grid.refinement.root.size()) != grid.NumCubes())
    throw std::invalid_argument("AddBernsteinMesh: the refinement is not of this grid's cubes");
  if (!grid.sharp.empty() && static_cast<long long>(grid.sharp.size()) != grid.NumTetrahedra())
    throw std::invalid_argument("AddBernsteinMesh: sharp flags must be one per tetrahedron");
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

int Model::AddBSplineSurface(const SplineStructure& structure,
                             const std::vector<double>& control_points, std::string name) {
  const std::string problem = SurfaceStructureProblem(structure);
  if (!problem.empty()) throw std::invalid_argument("AddBSplineSurface: " + problem);
  const size_t count = 3 * static_cast<size_t>(structure.count[0]) * structure.count[1];
  if (control_points.size() != count)
    throw std::invalid_argument("AddBSplineSurface: " + std::to_string(count / 3) +
                                " control points take " + std::to_string(count) + " numbers");
  ModelNode node;
  node.type = NodeType::kBSplineSurface;
  node.name = std::move(name);
  node.spline = structure;
  node.spline.count[2] = 0;
  node.count = structure.count[0] * structure.count[1];
  return AddNode(std::move(node), control_points);
}

int Model::AddBSplineVolume(int degree, const double box[6], const int cells[3],
                            const std::vector<double>& coefficients, std::string name) {
  const std::string problem = VolumeStructureProblem(degree, box, cells);
  if (!problem.empty()) throw std::invalid_argument("AddBSplineVolume: " + problem);
  ModelNode node;
  node.type = NodeType::kBSplineVolume;
  node.name = std::move(name);
  node.spline = BSplineVolumeStructure(degree, box, cells);
  node.degree = degree;
  const size_t count = static_cast<size_t>(node.spline.count[0]) * node.spline.count[1] *
                       node.spline.count[2];
  if (coefficients.size() != count)
    throw std::invalid_argument("AddBSplineVolume: degree " + std::to_string(degree) +
                                " on these cells takes " + std::to_string(count) +
                                " coefficients");
  return AddNode(std::move(node), coefficients);
}

int Model::AddCurveSkeletonOffset(const SplineStructure& curve, const std::vector<double>& vectors,
                                  double radius, std::string name) {
  const std::string problem = CurveStructureProblem(curve);
  if (!problem.empty()) throw std::invalid_argument("AddCurveSkeletonOffset: " + problem);
  const size_t count = 3 * static_cast<size_t>(CurveVectorCount(curve));
  if (vectors.size() != count)
    throw std::invalid_argument("AddCurveSkeletonOffset: the curve takes " +
                                std::to_string(count) + " numbers");
  ModelNode node;
  node.type = NodeType::kSkeletonOffset;
  node.name = std::move(name);
  node.count = static_cast<int>(count / 3);
  node.variant = static_cast<int>(SkeletonKind::kCurve);
  node.spline = curve;
  std::vector<double> p = vectors;
  p.push_back(radius);
  return AddNode(std::move(node), p);
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
      if (ch[c] == index) {
        const ModelNode& up = nodes_[parent];
        if (up.type == NodeType::kPartitionSequence) {  // JSON: separators, then children
          const int m = up.count, k = static_cast<int>(c);
          return NodeLabel(static_cast<int>(parent)) +
                 (k < m ? ".separators[" + std::to_string(k) + "]"
                        : ".children[" + std::to_string(k - m) + "]");
        }
        return NodeLabel(static_cast<int>(parent)) + ".children[" + std::to_string(c) + "]";
      }
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
