// The model tree: primitives (leaves) and smooth CSG operators (inner nodes), evaluated as one
// implicit function f(x) with the project's sign (f < 0 inside, grad f outward).
//
// Structure and parameter values are kept apart: the nodes hold the structure (type, children,
// order n, offsets), and every continuous parameter of the tree (primitive parameters, delta
// and epsilon of every blend) lives in one flat vector, so a fitter can hand that vector to
// Ceres and evaluate the tree on Jets: Evaluate<T>(params, x).
//
// Operators with more than two children fold left to right: op(op(c0, c1), c2) ...
// Operator parameters: [delta, epsilon] with 0 < epsilon <= delta; order 0 is sharp min/max.
// With smoothing kConvex the blend width is w = delta and epsilon is unused (kept = delta).
// Bernstein patches (model/bernstein/bernstein_patch.h): the node holds the degree k and the tetrahedron
// (structure); its parameters are the (k+1)(k+2)(k+3)/6 control points, field "control_points".
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/bernstein/bernstein_mesh.h"
#include "model/bernstein/bernstein_patch.h"
#include "model/primitives/blobs.h"
#include "model/primitives/box.h"
#include "model/primitives/coleman_curve_features.h"
#include "model/primitives/coleman_features.h"
#include "model/primitives/cone.h"
#include "model/blends/convex_smooth_ops.h"
#include "model/primitives/cylinder.h"
#include "model/primitives/ellipsoid.h"
#include "model/blends/morph.h"
#include "model/primitives/paraboloid.h"
#include "model/blends/partition.h"
#include "model/blends/partition_sequence.h"
#include "model/primitives/plane.h"
#include "model/primitives/quadric.h"
#include "model/primitives/skeleton_offset.h"
#include "model/blends/smooth_ops.h"
#include "model/primitives/sphere.h"
#include "model/primitives/torus.h"
#include "model/splines/bspline_surface_distance.h"
#include "model/splines/bspline_volume.h"
#include "model/splines/curve_skeleton.h"

namespace implicitfit {

enum class NodeType {
  kPlane,
  kSphere,
  kCylinder,
  kCone,
  kTorus,
  kEllipsoid,
  kQuadric,
  kBernsteinPatch,
  kUnion,
  kIntersection,
  kDifference,
  kBox,                // exact box SDF (model/primitives/box.h)
  kComplement,         // -f of its one child (model/blends/morph.h)
  kMorph,              // t f_A + (1 - t) f_B of its two children (model/blends/morph.h)
  kParaboloid,         // vertex, axis, curvature (model/primitives/paraboloid.h)
  kBlobs,              // Blinn blobs and compact kernels (model/primitives/blobs.h)
  kSkeletonOffset,     // offsets of points, segments, polylines (model/primitives/skeleton_offset.h)
  kPartition,          // soft space partition on a grid (model/blends/partition.h)
  kBernsteinMesh,      // model/bernstein/bernstein_mesh.h: degree, grid, continuity; control_points
  kPartitionSequence,  // soft partition by separator planes (model/blends/partition_sequence.h)
  kColemanFeatures,    // Coleman's features on a core distance (model/primitives/coleman_features.h)
  kBSplineSurface,     // signed distance to a B-spline / NURBS patch (model/splines/bspline_surface_distance.h)
  kBSplineVolume,      // trivariate tensor B-spline implicit over a box (model/splines/bspline_volume.h)
};

// The JSON "type" string of a node type, and back (false when unknown).
const char* NodeTypeName(NodeType type);
bool NodeTypeFromName(const std::string& name, NodeType* type);
bool IsOperator(NodeType type);
// Nodes with children that are not smooth CSG operators (complement, morph, ...): their
// parameters are their own fields (ParameterFieldsOf), their children any nodes.
bool IsComposite(NodeType type);
// The named groups of a node type's parameters in flat-vector order, e.g. sphere:
// center (3), radius (1). The JSON fields carry the same names. A field of size 0 has a
// per-node length (bernstein_patch: control_points); ParameterFieldsOf(node) gives it. A
// negative size -s means s per element (blobs: centers -3, weights -1; skeleton_offset:
// skeleton -3 per point), ParameterFieldsOf(node) multiplies by the node's element count.
// What a field means, so that code common to every primitive (JSON checks, recentring,
// fitting bounds and manifolds, degrees of freedom) reads it from the table instead of from
// the field's name (model/primitives/primitive_kinds.h):
enum class FieldRole {
  kPlain,           // any finite numbers
  kPosition,        // a point: moves with the model when it is translated
  kAxisPoint,       // a point on an axis line: moves with the model; 2 degrees of freedom (it
                    // slides along the axis: the fitter keeps the foot of the cloud's centroid)
  kDirection,       // a non-zero 3-vector that means only its direction (unit in fits)
  kPlaneOffset,     // d of n . x = d (n: the node's direction field): moves by n . shift
  kPositiveLength,  // every number > 0
  kAngle,           // a half angle in (0, pi/2) radians
  kRotation,        // a unit quaternion (w, x, y, z): 3 degrees of freedom
};
struct ParameterField {
  const char* name;
  int size;
  FieldRole role = FieldRole::kPlain;
};
const std::vector<ParameterField>& ParameterFieldsOf(NodeType type);
// Number of parameters a primitive or operator node owns (0 for bernstein_patch: per node).
int NumParametersOf(NodeType type);

// The smooth max of a union / intersection / difference node ("smoothing" in JSON):
// Li & Phillips' S_max (delta, epsilon; model/blends/smooth_ops.h), or the convexity-preserving
// S^c_max of model/blends/convex_smooth_ops.h (width w = delta; the epsilon slot is unused).
enum class BlendSmoothing { kLiPhillips, kConvex };

struct ModelNode {
  NodeType type = NodeType::kSphere;
  std::string name;           // optional user label ("name" in JSON)
  int first_parameter = 0;    // offset of this node's parameters in the flat vector
  int num_parameters = 0;     // how many it owns
  std::vector<int> children;  // operators: indices into Model::nodes
  int order = 0;              // operators: n of H_n (0 = sharp)
  BlendSmoothing smoothing = BlendSmoothing::kLiPhillips;  // operators: which smooth max
  std::vector<std::string> fixed;         // JSON field names the fitter must keep constant
  int degree = 0;                         // bernstein_patch: k >= 1
  Tetrahedron tetrahedron;                // bernstein_patch: the patch's tetrahedron
  int count = 0;                          // kinds with per-element fields: number of elements
  int variant = 0;                        // blobs: BlobKernel; skeleton_offset: SkeletonKind
  std::vector<std::vector<double>> cuts;  // partition: the cuts of x, y, z (structure)
  BernsteinGrid grid;                     // bernstein_mesh: the Kuhn grid
  int continuity = 0;                     // bernstein_mesh: declared continuity, 0 or 1
  SplineStructure spline;  // bspline_surface, bspline_volume, curve skeletons: degrees, knots, ...
  std::vector<int> curve_vertices;  // coleman_features: the vertex count of each curve feature
};

// One fold step of a union / intersection / difference node: op(a, b) with the node's
// smoothing, order and parameters p (its own: [delta, epsilon]).
template <typename T>
T BlendPair(const ModelNode& node, const T& a, const T& b, const T* p) {
  if (node.smoothing == BlendSmoothing::kConvex) {
    if (node.type == NodeType::kUnion) return ConvexSmoothUnion(a, b, p[0], node.order);
    if (node.type == NodeType::kIntersection)
      return ConvexSmoothIntersection(a, b, p[0], node.order);
    return ConvexSmoothDifference(a, b, p[0], node.order);
  }
  if (node.type == NodeType::kUnion) return SmoothUnion(a, b, p[0], p[1], node.order);
  if (node.type == NodeType::kIntersection) return SmoothIntersection(a, b, p[0], p[1], node.order);
  return SmoothDifference(a, b, p[0], p[1], node.order);
}

// The parameter fields of one node, with the sizes of per-node fields filled in (a
// skeleton_offset with Coleman features gets a third field, "features", 7 per feature).
std::vector<ParameterField> ParameterFieldsOf(const ModelNode& node);
// The number of Coleman features on a skeleton_offset node (0: the plain distance form).
inline int SkeletonFeatureCount(const ModelNode& node) {
  if (node.type != NodeType::kSkeletonOffset) return 0;
  return (node.num_parameters - 3 * node.count - 1) / ColemanFeatures::kPerFeature;
}

// What the writer of a model states about the whole solid, beside the tree (optional top-level
// fields of the model file, docs/model-file.md; `reconstruct` writes them, fit/reconstruct/
// solid_verification.h proves them):
//   bounds        a box holding every x with f(x) <= 0 (f > 0 outside it); `mesh` grids it by
//                 default instead of a box guessed from the primitives' parameters
//   verification  whether the solid passed the writer's checks, and the reason when not
// They describe the parameters as written: a tool that changes the parameters (a refit) does
// not carry them over.
struct ModelClaims {
  bool has_bounds = false;
  Eigen::Vector3d bounds_min = Eigen::Vector3d::Zero(), bounds_max = Eigen::Vector3d::Zero();
  bool has_verification = false;
  bool verified = false;
  std::string verification_reason;  // empty when verified
};

class Model {
 public:
  // Builders. Parameters are copied into the flat vector; the new node's index is returned.
  int AddPrimitive(NodeType type, const std::vector<double>& parameters, std::string name = "");
  int AddOperator(NodeType type, std::vector<int> children, double delta, double epsilon, int order,
                  std::string name = "");
  // A Bernstein patch of degree k >= 1 with NumBernsteinControlPoints(k) control points
  // (docs/design.md order); throws std::invalid_argument otherwise.
  int AddBernsteinPatch(int degree, const Tetrahedron& tetrahedron,
                        const std::vector<double>& control_points, std::string name = "");
  // A composite node (IsComposite: complement, morph, ...) over existing nodes, with its own
  // parameters (ParameterFieldsOf); throws std::invalid_argument on a wrong count of either.
  int AddComposite(NodeType type, std::vector<int> children, const std::vector<double>& parameters,
                   std::string name = "");
  // Blobs (model/primitives/blobs.h): m = weights.size() >= 1 centres (3 m numbers), weights, widths
  // (> 0), threshold; order n of H_n for BlobKernel::kUnitStep (1..14). Throws
  // std::invalid_argument on inconsistent sizes.
  int AddBlobs(BlobKernel kernel, int order, const std::vector<double>& centers,
               const std::vector<double>& weights, const std::vector<double>& widths,
               double threshold, std::string name = "");
  // Skeleton offset (model/primitives/skeleton_offset.h): points as 3 numbers each (segments: two end
  // points each; polyline: >= 2 vertices), radius.
  int AddSkeletonOffset(SkeletonKind kind, const std::vector<double>& points, double radius,
                        std::string name = "");
  // docs/maths.md CO-2's form: a skeleton_offset in field mode with Coleman's features (7 numbers
  // each: point 3, width, depth, radius, flare; m >= 1), core radius R_C = `radius` > 0:
  // f = 1/2 - max(i, max_f g_f) of model/primitives/coleman_features.h over the skeleton's distance.
  // Parameters [skeleton points, radius, features]. Throws std::invalid_argument otherwise.
  int AddSkeletonOffsetWithFeatures(SkeletonKind kind, const std::vector<double>& points,
                                    double radius, const std::vector<double>& features,
                                    std::string name = "");
  // Appends Coleman features (7 numbers each) to the skeleton_offset node just added (a curve
  // skeleton's, e.g.); returns index. Throws std::invalid_argument otherwise.
  int AddSkeletonFeatures(int index, const std::vector<double>& features);
  // Grid partition (model/blends/partition.h): 3 strictly increasing cut lists, every finite cell
  // >= 2 epsilon wide, (a+1)(b+1)(c+1) children (x fastest), 0 <= order <= 14; throws
  // std::invalid_argument otherwise.
  int AddPartition(std::vector<std::vector<double>> cuts, double epsilon, int order,
                   std::vector<int> children, std::string name = "");
  // A Bernstein mesh of degree k >= 1 over the Kuhn split of `grid`, with
  // 6 * cubes * NumBernsteinControlPoints(k) control points; continuity is 0 or 1 (declared,
  // checked by `check`). Throws std::invalid_argument otherwise.
  // Sequential partition (model/blends/partition_sequence.h): m >= 1 plane nodes as separators, m + 1
  // cell children, 0 <= order <= 14, every cell >= 2 epsilon wide; throws
  // std::invalid_argument otherwise. node.count = m; node.children = separators, then cells.
  int AddPartitionSequence(const std::vector<int>& separators, double epsilon, int order,
                           const std::vector<int>& children, std::string name = "");
  // The separators of a partition_sequence node as unit-normal planes (stored parameters).
  std::vector<SeparatorPlane> SeparatorsOf(const ModelNode& node) const;
  // Coleman features (model/primitives/coleman_features.h) over the core child `core` (a signed
  // distance): core radius R_C > 0, features as 7 numbers each (point 3, width, depth, radius,
  // flare), m >= 1. Throws std::invalid_argument otherwise.
  int AddColemanFeatures(int core, double core_radius, const std::vector<double>& features,
                         std::string name = "");
  // The same with curve features (model/primitives/coleman_curve_features.h): each entry of
  // `curves` is [3 n vertices (n >= 1), W, D, R, flare]; point features may then be empty.
  int AddColemanCurveFeatures(int core, double core_radius, const std::vector<double>& features,
                              const std::vector<std::vector<double>>& curves,
                              std::string name = "");
  int AddBernsteinMesh(int degree, const BernsteinGrid& grid, int continuity,
                       const std::vector<double>& control_points, std::string name = "");
  // A B-spline / NURBS surface (model/splines/bspline_surface_distance.h): its structure
  // (degrees, counts n_u x n_v, knots, optional weights) and 3 n_u n_v control point numbers
  // (P_ij at 3 (i n_v + j)). Throws std::invalid_argument naming the problem otherwise.
  int AddBSplineSurface(const SplineStructure& structure, const std::vector<double>& control_points,
                        std::string name = "");
  // A bspline_volume (model/splines/bspline_volume.h) of degree k over box with cells; the
  // (n_x + k)(n_y + k)(n_z + k) coefficients, x fastest. Throws std::invalid_argument otherwise.
  int AddBSplineVolume(int degree, const double box[6], const int cells[3],
                       const std::vector<double>& coefficients, std::string name = "");
  // A tube of radius r around a curve (model/splines/curve_skeleton.h): skeleton_offset with
  // SkeletonKind::kCurve; `curve` holds the kind, degree, knots, weights or turns, `vectors` its
  // 3-vectors (control points; ellipse c, A, B; helix c, A, B, C).
  int AddCurveSkeletonOffset(const SplineStructure& curve, const std::vector<double>& vectors,
                             double radius, std::string name = "");
  void SetRoot(int node) { root_ = node; }

  int root() const { return root_; }
  const std::vector<ModelNode>& nodes() const { return nodes_; }
  std::vector<ModelNode>& mutable_nodes() { return nodes_; }
  const std::vector<double>& parameters() const { return parameters_; }
  std::vector<double>& mutable_parameters() { return parameters_; }
  const ModelClaims& claims() const { return claims_; }
  ModelClaims& mutable_claims() { return claims_; }

  // f(x) for the given parameter vector (same layout as parameters()), any scalar type.
  template <typename T>
  T Evaluate(const T* params, const T* x) const {
    return EvaluateNode(root_, params, x);
  }
  template <typename T>
  T EvaluateNode(int index, const T* params, const T* x) const;

  // f and grad f at x with the stored parameters (grad by forward-mode automatic
  // differentiation, model/dual3.h).
  double Value(const Eigen::Vector3d& x) const;
  Eigen::Vector3d Gradient(const Eigen::Vector3d& x, double* value = nullptr) const;

  // A readable name for every parameter, e.g. "root.children[1].center[2]" or, for a node with
  // a "name", "<name>.radius".
  std::vector<std::string> ParameterNames() const;
  // Path of a node from the root, e.g. "root.children[0]", or its name when it has one.
  std::string NodeLabel(int index) const;

 private:
  int AddNode(ModelNode node, const std::vector<double>& parameters);
  std::vector<ModelNode> nodes_;
  std::vector<double> parameters_;
  int root_ = -1;
  ModelClaims claims_;
};

template <typename T>
T Model::EvaluateNode(int index, const T* params, const T* x) const {
  const ModelNode& node = nodes_[index];
  const T* p = params + node.first_parameter;
  switch (node.type) {
    case NodeType::kPlane:
      return PlaneEvaluator::Evaluate(p, x);
    case NodeType::kSphere:
      return SphereEvaluator::Evaluate(p, x);
    case NodeType::kCylinder:
      return CylinderEvaluator::Evaluate(p, x);
    case NodeType::kCone:
      return ConeEvaluator::Evaluate(p, x);
    case NodeType::kTorus:
      return TorusEvaluator::Evaluate(p, x);
    case NodeType::kEllipsoid:
      return EllipsoidEvaluator::Evaluate(p, x);
    case NodeType::kQuadric:
      return QuadricEvaluator::Evaluate(p, x);
    case NodeType::kBernsteinPatch:
      return BernsteinPatch::Evaluate(node.degree, node.tetrahedron, p, x);
    case NodeType::kBernsteinMesh:
      return BernsteinMesh::Evaluate(node.degree, node.grid, p, x);
    case NodeType::kUnion:
    case NodeType::kIntersection:
    case NodeType::kDifference: {
      T acc = EvaluateNode(node.children[0], params, x);
      for (size_t c = 1; c < node.children.size(); ++c)
        acc = BlendPair(node, acc, EvaluateNode(node.children[c], params, x), p);
      return acc;
    }
    case NodeType::kBox:
      return BoxEvaluator::Evaluate(p, x);
    case NodeType::kComplement:
      return -EvaluateNode(node.children[0], params, x);
    case NodeType::kParaboloid:
      return ParaboloidEvaluator::Evaluate(p, x);
    case NodeType::kPartition: {
      const UnitStep& mu = UnitStep::OfOrder(node.order);
      int cells[3][PartitionAxis::kMaxCells];
      T factors[3][PartitionAxis::kMaxCells];
      int counts[3];
      for (int k = 0; k < 3; ++k)
        counts[k] = PartitionAxis::Factors(node.cuts[k], x[k], p[0], mu, cells[k], factors[k]);
      const int nx = static_cast<int>(node.cuts[0].size()) + 1;
      const int ny = static_cast<int>(node.cuts[1].size()) + 1;
      T acc = T(0.0);
      for (int k = 0; k < counts[2]; ++k)
        for (int j = 0; j < counts[1]; ++j)
          for (int i = 0; i < counts[0]; ++i) {
            const int child = cells[0][i] + nx * (cells[1][j] + ny * cells[2][k]);
            acc += factors[0][i] * factors[1][j] * factors[2][k] *
                   EvaluateNode(node.children[child], params, x);
          }
      return acc;
    }
    case NodeType::kPartitionSequence: {
      const int m = node.count;
      return PartitionSequence::Evaluate(
          UnitStep::OfOrder(node.order), p[0], m,
          [&](int j) { return EvaluateNode(node.children[j], params, x); },
          [&](int j) { return EvaluateNode(node.children[m + j], params, x); });
    }
    case NodeType::kColemanFeatures: {
      auto core = [&](const T* y) { return EvaluateNode(node.children[0], params, y); };
      const T f = ColemanFeatures::Evaluate(node.count, p, x, core);
      if (node.curve_vertices.empty()) return f;
      return ColemanCurveFeatures::Evaluate(
          node.curve_vertices, p[0], p + 1 + ColemanFeatures::kPerFeature * node.count, x, f, core);
    }
    case NodeType::kBlobs:
      return BlobsEvaluator::Evaluate(static_cast<BlobKernel>(node.variant), node.order, node.count,
                                      p, x);
    case NodeType::kSkeletonOffset: {
      const SkeletonKind kind = static_cast<SkeletonKind>(node.variant);
      const int features = SkeletonFeatureCount(node);
      auto nearest = [&](const T* y, T* c) {  // distance to the skeleton, nearest point c
        if (kind == SkeletonKind::kCurve) return CurveSkeletonClosest(node.spline, p, y, c);
        return SkeletonOffsetEvaluator::Closest(kind, node.count, p, y, c);
      };
      if (features == 0) {
        if (kind != SkeletonKind::kCurve)
          return SkeletonOffsetEvaluator::Evaluate(kind, node.count, p, x);
        T c[3];
        return nearest(x, c) - p[3 * node.count];
      }
      // docs/maths.md CO-2: Coleman's features in field mode, R_C = radius (model/primitives/coleman_features.h)
      auto closest = [&](const T* y, T* c, T* n) {
        nearest(y, c);
        ColemanFeatures::DirectionFrom(c, y, n);
      };
      auto distance = [&](const T* y) {
        T c[3];
        return nearest(y, c);
      };
      return ColemanFeatures::EvaluateOnCore(features, p + 3 * node.count, x, distance, closest);
    }
    case NodeType::kMorph:
      return Morph(p[0], EvaluateNode(node.children[0], params, x),
                   EvaluateNode(node.children[1], params, x));
    case NodeType::kBSplineSurface:
      return BSplineSurfaceSignedDistance(node.spline, p, x);
    case NodeType::kBSplineVolume:
      return BSplineVolumeEvaluator::Evaluate(node.spline, p, x);
  }
  return T(0.0);
}

}  // namespace implicitfit
