#include "model/file/model_json.h"

#include <Eigen/Geometry>
#include <cmath>
#include <set>

#include "model/file/bernstein_mesh_json.h"
#include "model/file/spline_json.h"
#include "model/primitives/primitive_kinds.h"

namespace implicitfit {
namespace {

using nlohmann::json;

[[noreturn]] void Fail(const std::string& path, const std::string& problem) {
  throw ModelFormatError(path + ": " + problem);
}

// Magnitudes the evaluators handle (model_json.h: kMaxModelMagnitude).
void RequireInRange(double x, const std::string& where) {
  if (std::abs(x) > kMaxModelMagnitude)
    Fail(where, "magnitude " + json(x).dump() + " exceeds " + json(kMaxModelMagnitude).dump() +
                    " (beyond what the evaluators handle: its squares and products overflow)");
}

double Number(const json& node, const std::string& key, const std::string& path) {
  const std::string where = path + "." + key;
  if (!node.contains(key)) Fail(where, "missing");
  const json& v = node.at(key);
  if (!v.is_number()) Fail(where, "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) Fail(where, "must be finite");
  RequireInRange(x, where);
  return x;
}

std::vector<double> Vector(const json& v, size_t size, const std::string& where) {
  if (!v.is_array() || v.size() != size)
    Fail(where, "must be an array of " + std::to_string(size) + " numbers");
  std::vector<double> out;
  for (size_t i = 0; i < size; ++i) {
    if (!v[i].is_number()) Fail(where + "[" + std::to_string(i) + "]", "must be a number");
    out.push_back(v[i].get<double>());
    if (!std::isfinite(out.back())) Fail(where + "[" + std::to_string(i) + "]", "must be finite");
    RequireInRange(out.back(), where + "[" + std::to_string(i) + "]");
  }
  return out;
}

std::vector<double> Vector(const json& node, const std::string& key, size_t size,
                           const std::string& path) {
  if (!node.contains(key)) Fail(path + "." + key, "missing");
  return Vector(node.at(key), size, path + "." + key);
}

double Norm(const std::vector<double>& v, size_t begin = 0) {
  return std::sqrt(v[begin] * v[begin] + v[begin + 1] * v[begin + 1] + v[begin + 2] * v[begin + 2]);
}

void RequireNonZero(const std::vector<double>& v, size_t begin, const std::string& where) {
  if (!(Norm(v, begin) > 0.0)) Fail(where, "must be a non-zero vector");
}

void RequirePositive(double x, const std::string& where) {
  if (!(x > 0.0)) Fail(where, "must be > 0");
  if (x < kMinModelLength)
    Fail(where, "must be >= " + json(kMinModelLength).dump() +
                    " (smaller lengths make the evaluators divide by zero)");
}

void RequireAtMostElements(size_t count, const std::string& where, const char* what) {
  if (static_cast<long long>(count) > kMaxModelElements)
    Fail(where, std::to_string(count) + " " + what + ", more than the limit of " +
                    std::to_string(kMaxModelElements) +
                    " (meshing, sampling and checking cost grows with each)");
}

void CheckKeys(const json& node, const std::set<std::string>& allowed, const std::string& path) {
  for (auto it = node.begin(); it != node.end(); ++it)
    if (!allowed.count(it.key()))
      Fail(path + "." + it.key(),
           "unknown field for a node of type " + node.at("type").get<std::string>());
}

// Ellipsoid axes: 2 rows (e1, e2) or 3 rows whose third is parallel to e1 x e2.
std::vector<double> EllipsoidAxes(const json& node, const std::string& path) {
  const std::string where = path + ".axes";
  if (!node.contains("axes")) Fail(where, "missing");
  const json& axes = node.at("axes");
  if (!axes.is_array() || (axes.size() != 2 && axes.size() != 3))
    Fail(where, "must hold 2 or 3 direction vectors");
  const std::vector<double> e1 = Vector(axes[0], 3, where + "[0]");
  const std::vector<double> e2 = Vector(axes[1], 3, where + "[1]");
  RequireNonZero(e1, 0, where + "[0]");
  RequireNonZero(e2, 0, where + "[1]");
  const double n1 = Norm(e1), n2 = Norm(e2);
  const double cosine = (e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2]) / (n1 * n2);
  if (std::abs(cosine) > 1e-6) Fail(where, "the axes must be orthogonal");
  if (axes.size() == 3) {
    const std::vector<double> e3 = Vector(axes[2], 3, where + "[2]");
    RequireNonZero(e3, 0, where + "[2]");
    const double c[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                         e1[0] * e2[1] - e1[1] * e2[0]};
    const double dot = (c[0] * e3[0] + c[1] * e3[1] + c[2] * e3[2]) / (n1 * n2 * Norm(e3));
    if (std::abs(std::abs(dot) - 1.0) > 1e-6)
      Fail(where + "[2]", "must be orthogonal to the first two axes");
  }
  std::vector<double> out = e1;
  out.insert(out.end(), e2.begin(), e2.end());
  return out;
}

// Box "axes" (as the ellipsoid's: 2 or 3 orthogonal rows) as the unit quaternion (w, x, y, z)
// of the rotation whose columns are e1, e2, e1 x e2 (model/primitives/box.h).
std::vector<double> BoxQuaternion(const json& node, const std::string& path) {
  const std::vector<double> axes = EllipsoidAxes(node, path);
  const Eigen::Vector3d e1 = Eigen::Vector3d(axes[0], axes[1], axes[2]).normalized();
  Eigen::Vector3d e2(axes[3], axes[4], axes[5]);
  e2 = (e2 - e2.dot(e1) * e1).normalized();
  Eigen::Matrix3d r;
  r << e1, e2, e1.cross(e2);
  const Eigen::Quaterniond q(r);
  return {q.w(), q.x(), q.y(), q.z()};
}

// A primitive's parameters from its fields (model/primitives/primitive_kinds.h), each checked by its
// role: a direction must be non-zero, a positive length > 0, an angle in (0, pi/2).
std::vector<double> FieldsByRole(const PrimitiveKind& kind, const json& node,
                                 const std::string& path) {
  std::vector<double> p;
  for (const ParameterField& f : kind.fields) {
    const size_t begin = p.size();
    const std::string where = path + "." + f.name;
    if (f.size == 1) {
      p.push_back(Number(node, f.name, path));
    } else {
      const std::vector<double> v = Vector(node, f.name, f.size, path);
      p.insert(p.end(), v.begin(), v.end());
    }
    switch (f.role) {
      case FieldRole::kDirection:
        RequireNonZero(p, begin, where);
        break;
      case FieldRole::kPositiveLength:
        for (int i = 0; i < f.size; ++i)
          RequirePositive(p[begin + i],
                          f.size == 1 ? where : where + "[" + std::to_string(i) + "]");
        break;
      case FieldRole::kAngle:
        if (!(p[begin] > 0.0 && p[begin] < M_PI / 2)) Fail(where, "must be in (0, pi/2) radians");
        break;
      case FieldRole::kPlain:
      case FieldRole::kPosition:
      case FieldRole::kAxisPoint:
      case FieldRole::kPlaneOffset:
      case FieldRole::kRotation:
        break;
    }
  }
  return p;
}

// Primitives whose JSON form differs from their parameter layout are read here; every other
// primitive by FieldsByRole.
std::vector<double> PrimitiveParameters(NodeType type, const json& node, const std::string& path) {
  const PrimitiveKind* kind = FindPrimitiveKind(type);
  if (!kind) Fail(path, "internal: not a primitive");
  std::vector<double> p;
  auto append = [&p](const std::vector<double>& v) { p.insert(p.end(), v.begin(), v.end()); };
  if (type == NodeType::kPlane && node.contains("point")) {
    // LP-2 input form: through a point; stored unit normal, offset
    append(Vector(node, "normal", 3, path));
    RequireNonZero(p, 0, path + ".normal");
    if (node.contains("offset")) Fail(path + ".point", "give either point or offset, not both");
    const std::vector<double> x = Vector(node, "point", 3, path);
    const double n = Norm(p);
    for (int i = 0; i < 3; ++i) p[i] /= n;
    p.push_back(p[0] * x[0] + p[1] * x[1] + p[2] * x[2]);
  } else if (type == NodeType::kEllipsoid) {  // "axes": 2 or 3 rows, stored as 2
    append(Vector(node, "center", 3, path));
    append(Vector(node, "radii", 3, path));
    for (int i = 0; i < 3; ++i)
      RequirePositive(p[3 + i], path + ".radii[" + std::to_string(i) + "]");
    append(EllipsoidAxes(node, path));
  } else if (type == NodeType::kBox) {  // "axes": rows, stored as a quaternion
    append(Vector(node, "center", 3, path));
    append(BoxQuaternion(node, path));
    append(Vector(node, "half_sizes", 3, path));
    for (int i = 0; i < 3; ++i)
      RequirePositive(p[7 + i], path + ".half_sizes[" + std::to_string(i) + "]");
  } else {
    p = FieldsByRole(*kind, node, path);
    if (type == NodeType::kQuadric) {
      double largest = 0.0;
      for (double c : p) largest = std::max(largest, std::abs(c));
      if (largest == 0.0) Fail(path + ".coefficients", "must not all be zero");
    }
  }
  return p;
}

// bernstein_patch: {"degree": k, "vertices": [[3],[3],[3],[3]], "control_points": [...]}.
// Degree at most kMaxPatchDegree (model_json.h): an evaluation costs (k+1)(k+2)(k+3)/6 terms
// or more (286 at 10; a degree-100 patch took hours to mesh).
constexpr long long kMaxBernsteinDegree = kMaxPatchDegree;

int ReadBernsteinPatch(const json& node, const std::string& path, const std::string& name,
                       Model* model) {
  if (!node.contains("degree") || !node.at("degree").is_number_integer())
    Fail(path + ".degree", "missing or not an integer");
  const long long k = node.at("degree").get<long long>();
  if (k < 1 || k > kMaxBernsteinDegree)
    Fail(path + ".degree", "must be an integer in 1.." + std::to_string(kMaxBernsteinDegree));
  if (!node.contains("vertices")) Fail(path + ".vertices", "missing");
  const json& v = node.at("vertices");
  if (!v.is_array() || v.size() != 4) Fail(path + ".vertices", "must hold 4 points [x, y, z]");
  std::vector<double> corners;
  for (size_t i = 0; i < 4; ++i) {
    const std::vector<double> x = Vector(v[i], 3, path + ".vertices[" + std::to_string(i) + "]");
    corners.insert(corners.end(), x.begin(), x.end());
  }
  Tetrahedron tetrahedron;
  try {
    tetrahedron = Tetrahedron::FromArray(corners.data());
  } catch (const std::invalid_argument& e) {
    Fail(path + ".vertices", e.what());
  }
  const long long count = NumBernsteinControlPoints(k);
  if (!node.contains("control_points")) Fail(path + ".control_points", "missing");
  const json& cp = node.at("control_points");
  if (!cp.is_array() || static_cast<long long>(cp.size()) != count)
    Fail(path + ".control_points", "must be an array of " + std::to_string(count) +
                                       " numbers ((k+1)(k+2)(k+3)/6 for degree " +
                                       std::to_string(k) + ")");
  const std::vector<double> b = Vector(cp, static_cast<size_t>(count), path + ".control_points");
  return model->AddBernsteinPatch(static_cast<int>(k), tetrahedron, b, name);
}

// Operators: "smoothing": "li-phillips" (default when absent) | "convex". A convex blend has
// the width w = delta and no epsilon: a present "epsilon" is refused rather than ignored.
BlendSmoothing ReadSmoothing(const json& node, const std::string& path) {
  if (!node.contains("smoothing")) return BlendSmoothing::kLiPhillips;
  const json& v = node.at("smoothing");
  const std::string where = path + ".smoothing";
  if (!v.is_string()) Fail(where, "must be \"li-phillips\" or \"convex\"");
  const std::string value = v.get<std::string>();
  if (value == "li-phillips") return BlendSmoothing::kLiPhillips;
  if (value != "convex")
    Fail(where, "unknown smoothing '" + value + "' (\"li-phillips\" or \"convex\")");
  if (node.contains("epsilon"))
    Fail(path + ".epsilon",
         "must be absent with \"smoothing\": \"convex\" (the blend width is delta)");
  return BlendSmoothing::kConvex;
}

int ReadNode(const json& node, const std::string& path, int depth, Model* model);

// complement {"children": [A]}; morph {"children": [A, B], "t": t in [0, 1]}.
int ReadComposite(NodeType type, const json& node, const std::string& path, int depth,
                  const std::string& name, Model* model) {
  const size_t arity = type == NodeType::kComplement ? 1 : 2;
  if (!node.contains("children") || !node.at("children").is_array() ||
      node.at("children").size() != arity)
    Fail(path + ".children",
         "must be an array of " + std::to_string(arity) + " node" + (arity > 1 ? "s" : ""));
  std::vector<double> parameters;
  if (type == NodeType::kMorph) {
    const double t = Number(node, "t", path);
    if (!(t >= 0.0 && t <= 1.0)) Fail(path + ".t", "must be in [0, 1]");
    parameters.push_back(t);
  }
  std::vector<int> children;
  const json& ch = node.at("children");
  for (size_t i = 0; i < ch.size(); ++i)
    children.push_back(
        ReadNode(ch[i], path + ".children[" + std::to_string(i) + "]", depth + 1, model));
  return model->AddComposite(type, children, parameters, name);
}

// blobs {"centers": [[3],...], "weights": [...], "widths": [...], "threshold": T,
//        "kernel": "gaussian" | "wyvill" | "h_n", "order": n (h_n only, default 3)}.
int ReadBlobs(const json& node, const std::string& path, const std::string& name, Model* model) {
  if (!node.contains("centers") || !node.at("centers").is_array() || node.at("centers").empty())
    Fail(path + ".centers", "must be a non-empty array of points [x, y, z]");
  const json& c = node.at("centers");
  const size_t m = c.size();
  RequireAtMostElements(m, path + ".centers", "blobs");
  std::vector<double> centers;
  for (size_t i = 0; i < m; ++i) {
    const std::vector<double> x = Vector(c[i], 3, path + ".centers[" + std::to_string(i) + "]");
    centers.insert(centers.end(), x.begin(), x.end());
  }
  const std::vector<double> weights = Vector(node, "weights", m, path);
  const std::vector<double> widths = Vector(node, "widths", m, path);
  for (size_t i = 0; i < m; ++i)
    RequirePositive(widths[i], path + ".widths[" + std::to_string(i) + "]");
  const double threshold = Number(node, "threshold", path);
  if (!node.contains("kernel") || !node.at("kernel").is_string())
    Fail(path + ".kernel", "missing or not a string (gaussian, wyvill or h_n)");
  const std::string k = node.at("kernel").get<std::string>();
  BlobKernel kernel;
  if (k == "gaussian")
    kernel = BlobKernel::kGaussian;
  else if (k == "wyvill")
    kernel = BlobKernel::kWyvill;
  else if (k == "h_n")
    kernel = BlobKernel::kUnitStep;
  else
    Fail(path + ".kernel", "unknown kernel '" + k + "' (gaussian, wyvill or h_n)");
  long long order = 3;
  if (node.contains("order")) {
    if (kernel != BlobKernel::kUnitStep)
      Fail(path + ".order", "only the h_n kernel takes an order");
    if (!node.at("order").is_number_integer()) Fail(path + ".order", "must be an integer");
    order = node.at("order").get<long long>();
    if (order < 1 || order > UnitStep::kMaxOrder)
      Fail(path + ".order", "must be an integer in 1.." + std::to_string(UnitStep::kMaxOrder));
  }
  return model->AddBlobs(kernel, static_cast<int>(order), centers, weights, widths, threshold,
                         name);
}

std::vector<double> ReadFeatureList(const json& node, const std::string& path);

// skeleton_offset {"skeleton": {"points": [[3],...]} | {"segments": [[[3],[3]],...]} |
//                  {"polyline": [[3],...]} | {"triangles": [[[3],[3],[3]],...]}, "radius": r,
//                  "features": [...] (optional: docs/maths.md CO-2's field mode, R_C = r)}.
int ReadSkeletonOffset(const json& node, const std::string& path, const std::string& name,
                       Model* model) {
  const std::string where = path + ".skeleton";
  if (!node.contains("skeleton") || !node.at("skeleton").is_object() ||
      node.at("skeleton").size() != 1)
    Fail(where, "must be an object with exactly one of points, segments, polyline, triangles");
  const json& s = node.at("skeleton");
  const std::string key = s.begin().key();
  const json& list = s.begin().value();
  if (key == "curve") {  // model/file/spline_json.h
    const double radius = Number(node, "radius", path);
    RequirePositive(radius, path + ".radius");
    const std::vector<double> features =
        node.contains("features") ? ReadFeatureList(node, path) : std::vector<double>{};
    return ReadCurveSkeletonOffset(list, where + ".curve", radius, features, name, model);
  }
  SkeletonKind kind;
  if (key == "points")
    kind = SkeletonKind::kPoints;
  else if (key == "segments")
    kind = SkeletonKind::kSegments;
  else if (key == "polyline")
    kind = SkeletonKind::kPolyline;
  else if (key == "triangles")
    kind = SkeletonKind::kTriangles;
  else
    Fail(where + "." + key, "unknown skeleton (points, segments, polyline, triangles or curve)");
  const size_t least = kind == SkeletonKind::kPolyline ? 2 : 1;
  if (list.is_array()) RequireAtMostElements(list.size(), where + "." + key, "skeleton elements");
  if (!list.is_array() || list.size() < least)
    Fail(where + "." + key, "must be an array of at least " + std::to_string(least) +
                                (kind == SkeletonKind::kSegments    ? " segment [[3], [3]]"
                                 : kind == SkeletonKind::kTriangles ? " triangle [[3], [3], [3]]"
                                                                    : " points [x, y, z]"));
  std::vector<double> points;
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string at = where + "." + key + "[" + std::to_string(i) + "]";
    if (kind == SkeletonKind::kSegments || kind == SkeletonKind::kTriangles) {
      const size_t corners = kind == SkeletonKind::kSegments ? 2 : 3;
      if (!list[i].is_array() || list[i].size() != corners)
        Fail(at, "must hold " + std::to_string(corners) + " points [x, y, z]");
      for (size_t e = 0; e < corners; ++e) {
        const std::vector<double> x = Vector(list[i][e], 3, at + "[" + std::to_string(e) + "]");
        points.insert(points.end(), x.begin(), x.end());
      }
    } else {
      const std::vector<double> x = Vector(list[i], 3, at);
      points.insert(points.end(), x.begin(), x.end());
    }
  }
  const double radius = Number(node, "radius", path);
  RequirePositive(radius, path + ".radius");
  if (node.contains("features"))
    return model->AddSkeletonOffsetWithFeatures(kind, points, radius, ReadFeatureList(node, path),
                                                name);
  return model->AddSkeletonOffset(kind, points, radius, name);
}

// The "epsilon" (> 0) and "order" (0..14) of a partition node.
int ReadEpsilonAndOrder(const json& node, const std::string& path, double* epsilon) {
  *epsilon = Number(node, "epsilon", path);
  RequirePositive(*epsilon, path + ".epsilon");
  if (!node.contains("order") || !node.at("order").is_number_integer())
    Fail(path + ".order", "missing or not an integer");
  const long long order = node.at("order").get<long long>();
  if (order < 0 || order > UnitStep::kMaxOrder)
    Fail(path + ".order", "must be an integer in 0.." + std::to_string(UnitStep::kMaxOrder));
  return static_cast<int>(order);
}

// partition {"cuts": [[x..], [y..], [z..]], "epsilon": e, "order": n, "children": [...]}:
// strictly increasing cuts, every finite cell >= 2 epsilon wide (the partition of unity needs
// it), one child per cell, x fastest.
int ReadPartition(const json& node, const std::string& path, int depth, const std::string& name,
                  Model* model) {
  double epsilon;
  const int order = ReadEpsilonAndOrder(node, path, &epsilon);
  if (!node.contains("cuts") || !node.at("cuts").is_array() || node.at("cuts").size() != 3)
    Fail(path + ".cuts", "must hold 3 arrays of cut positions (x, y, z; each may be empty)");
  std::vector<std::vector<double>> cuts(3);
  size_t cells = 1;
  const char* axis = "xyz";
  for (size_t k = 0; k < 3; ++k) {
    const std::string where = path + ".cuts[" + std::to_string(k) + "]";
    const json& c = node.at("cuts")[k];
    if (!c.is_array()) Fail(where, "must be an array of numbers");
    cuts[k] = Vector(c, c.size(), where);
    for (size_t i = 1; i < cuts[k].size(); ++i) {
      const double width = cuts[k][i] - cuts[k][i - 1];
      if (!(width > 0.0))
        Fail(where + "[" + std::to_string(i) + "]", "cuts must be strictly increasing");
      if (width < 2.0 * epsilon)
        Fail(where + "[" + std::to_string(i) + "]",
             std::string("the cell between ") + axis[k] + " = " + json(cuts[k][i - 1]).dump() +
                 " and " + json(cuts[k][i]).dump() + " is " + json(width).dump() +
                 " wide, less than 2 epsilon = " + json(2.0 * epsilon).dump() +
                 " (the bases are a partition of unity only from 2 epsilon)");
    }
    cells *= cuts[k].size() + 1;
  }
  if (!node.contains("children") || !node.at("children").is_array() ||
      node.at("children").size() != cells)
    Fail(path + ".children",
         "must hold one node per cell: " + std::to_string(cells) + " nodes, x fastest");
  std::vector<int> children;
  const json& ch = node.at("children");
  for (size_t i = 0; i < ch.size(); ++i)
    children.push_back(
        ReadNode(ch[i], path + ".children[" + std::to_string(i) + "]", depth + 1, model));
  return model->AddPartition(cuts, epsilon, order, children, name);
}

// partition_sequence {"separators": [plane nodes x m], "epsilon": e, "order": n,
// "children": [m + 1 nodes]}: every cell >= 2 epsilon wide (model/blends/partition_sequence.h; the
// refusal names the cell's child and its width).
int ReadPartitionSequence(const json& node, const std::string& path, int depth,
                          const std::string& name, Model* model) {
  double epsilon;
  const int order = ReadEpsilonAndOrder(node, path, &epsilon);
  if (!node.contains("separators") || !node.at("separators").is_array() ||
      node.at("separators").empty())
    Fail(path + ".separators", "must be an array of at least 1 plane node");
  const json& sep = node.at("separators");
  if (!node.contains("children") || !node.at("children").is_array() ||
      node.at("children").size() != sep.size() + 1)
    Fail(path + ".children", "must hold one node per cell: " + std::to_string(sep.size() + 1) +
                                 " nodes (one more than separators)");
  std::vector<int> separators, children;
  for (size_t i = 0; i < sep.size(); ++i) {
    const std::string where = path + ".separators[" + std::to_string(i) + "]";
    if (!sep[i].is_object() || !sep[i].contains("type") || sep[i].at("type") != "plane")
      Fail(where, "must be a plane node ({\"type\": \"plane\", ...})");
    separators.push_back(ReadNode(sep[i], where, depth + 1, model));
  }
  const json& ch = node.at("children");
  for (size_t i = 0; i < ch.size(); ++i)
    children.push_back(
        ReadNode(ch[i], path + ".children[" + std::to_string(i) + "]", depth + 1, model));
  ModelNode probe;
  probe.count = static_cast<int>(separators.size());
  probe.children = separators;
  double width = 0.0;
  const int narrow = NarrowPartitionSequenceCell(model->SeparatorsOf(probe), epsilon, &width);
  if (narrow >= 0)
    Fail(path + ".children[" + std::to_string(narrow) + "]",
         "the cell of this child is " + json(width).dump() +
             " wide (twice its inscribed radius), less than 2 epsilon = " +
             json(2.0 * epsilon).dump() + " (its child would be reproduced nowhere)");
  return model->AddPartitionSequence(separators, epsilon, static_cast<int>(order), children, name);
}

// Coleman features [{"point": [3], "width": W, "depth": D, "radius": R, "flare": phi}, ...]
// (docs/maths.md CO-2): W, R > 0, D >= 0, 0 <= phi <= 1; 7 numbers each in parameter order.
std::vector<double> ReadFeatureList(const json& node, const std::string& path) {
  if (!node.contains("features") || !node.at("features").is_array() || node.at("features").empty())
    Fail(path + ".features", "must be an array of at least 1 feature object");
  std::vector<double> features;
  const json& list = node.at("features");
  RequireAtMostElements(list.size(), path + ".features", "features");
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string at = path + ".features[" + std::to_string(i) + "]";
    if (!list[i].is_object()) Fail(at, "must be an object {point, width, depth, radius, flare}");
    CheckKeys(list[i], {"point", "width", "depth", "radius", "flare"}, at);
    const std::vector<double> point = Vector(list[i], "point", 3, at);
    features.insert(features.end(), point.begin(), point.end());
    const double w = Number(list[i], "width", at), d = Number(list[i], "depth", at),
                 r = Number(list[i], "radius", at), flare = Number(list[i], "flare", at);
    RequirePositive(w, at + ".width");
    RequirePositive(r, at + ".radius");
    if (d < 0) Fail(at + ".depth", "must be >= 0");
    if (flare < 0 || flare > 1) Fail(at + ".flare", "must be in [0, 1]");
    features.insert(features.end(), {w, d, r, flare});
  }
  return features;
}

json WriteFeatureList(const std::vector<double>& p, int first, int count) {
  json features = json::array();
  for (int q = 0; q < count; ++q) {
    const int e = first + ColemanFeatures::kPerFeature * q;
    features.push_back({{"point", json(std::vector<double>(p.begin() + e, p.begin() + e + 3))},
                        {"width", p[e + 3]},
                        {"depth", p[e + 4]},
                        {"radius", p[e + 5]},
                        {"flare", p[e + 6]}});
  }
  return features;
}

// coleman_features {"core_radius": R_C, "features": [...], "children": [CORE]}: R_C > 0.
int ReadColemanFeatures(const json& node, const std::string& path, int depth,
                        const std::string& name, Model* model) {
  const double core_radius = Number(node, "core_radius", path);
  RequirePositive(core_radius, path + ".core_radius");
  // Point features may be absent when there are curve features (model/file/spline_json.h).
  const bool curves = node.contains("curve_features");
  const std::vector<double> features =
      curves && !node.contains("features") ? std::vector<double>{} : ReadFeatureList(node, path);
  const std::vector<std::vector<double>> curve_features =
      curves ? ReadCurveFeatures(node.at("curve_features"), path + ".curve_features")
             : std::vector<std::vector<double>>{};
  if (!node.contains("children") || !node.at("children").is_array() ||
      node.at("children").size() != 1)
    Fail(path + ".children", "must hold exactly 1 node: the core (a signed distance)");
  const int core = ReadNode(node.at("children")[0], path + ".children[0]", depth + 1, model);
  return model->AddColemanCurveFeatures(core, core_radius, features, curve_features, name);
}

std::set<std::string> AllowedKeys(NodeType type) {
  std::set<std::string> keys = {"type", "name", "fixed"};
  if (IsOperator(type)) {
    keys.insert({"children", "delta", "epsilon", "order", "smoothing"});
  } else {
    for (const ParameterField& f : ParameterFieldsOf(type)) keys.insert(f.name);
  }
  if (type == NodeType::kBernsteinPatch) keys.insert({"degree", "vertices"});
  if (IsComposite(type)) keys.insert("children");
  if (type == NodeType::kPlane) keys.insert("point");  // input form; written as normal, offset
  if (type == NodeType::kBlobs) keys.insert({"kernel", "order"});
  if (type == NodeType::kPartition) keys.insert({"cuts", "order", "children"});
  if (type == NodeType::kPartitionSequence) keys.insert({"separators", "order", "children"});
  if (type == NodeType::kColemanFeatures) keys.insert({"children", "curve_features"});
  if (type == NodeType::kSkeletonOffset) keys.insert("features");  // docs/maths.md CO-2
  if (type == NodeType::kBernsteinMesh) keys.insert({"degree", "grid", "continuity", "c0_faces"});
  if (type == NodeType::kBSplineSurface) keys.insert({"degree", "knots_u", "knots_v", "weights"});
  if (type == NodeType::kBSplineVolume) keys.insert({"degree", "box", "cells"});
  return keys;
}

// A path of hundreds of levels, shortened for a one-line message: its start and its end.
std::string ShortPath(const std::string& path) {
  if (path.size() <= 120) return path;
  return path.substr(0, 50) + "..." + path.substr(path.size() - 60);
}

int ReadNode(const json& node, const std::string& path, int depth, Model* model) {
  if (depth > kMaxModelDepth)
    Fail(ShortPath(path), "the model tree nests deeper than " + std::to_string(kMaxModelDepth) +
                              " levels (the root is level 1)");
  if (!node.is_object()) Fail(path, "must be an object (a model node)");
  if (static_cast<long long>(model->nodes().size()) >= kMaxModelNodes)
    Fail(ShortPath(path), "the model has more than " + std::to_string(kMaxModelNodes) +
                              " nodes, the limit");
  if (!node.contains("type") || !node.at("type").is_string())
    Fail(path + ".type", "missing or not a string");
  const std::string type_name = node.at("type").get<std::string>();
  NodeType type;
  if (!NodeTypeFromName(type_name, &type))
    Fail(path + ".type", "unknown node type '" + type_name + "'");
  CheckKeys(node, AllowedKeys(type), path);

  std::string name;
  if (node.contains("name")) {
    if (!node.at("name").is_string()) Fail(path + ".name", "must be a string");
    name = node.at("name").get<std::string>();
  }
  std::vector<std::string> fixed;
  if (node.contains("fixed")) {
    const json& f = node.at("fixed");
    if (!f.is_array()) Fail(path + ".fixed", "must be an array of field names");
    for (size_t i = 0; i < f.size(); ++i) {
      const std::string where = path + ".fixed[" + std::to_string(i) + "]";
      if (!f[i].is_string()) Fail(where, "must be a string");
      const std::string field = f[i].get<std::string>();
      bool known = false;
      for (const ParameterField& pf : ParameterFieldsOf(type)) known |= field == pf.name;
      known |= type == NodeType::kSkeletonOffset && field == "features" && node.contains(field);
      known |= type == NodeType::kColemanFeatures && field == "curve_features" &&
               node.contains(field);
      if (!known) Fail(where, "'" + field + "' is not a parameter of a " + type_name);
      fixed.push_back(field);
    }
  }

  int index;
  if (IsOperator(type)) {
    if (!node.contains("children") || !node.at("children").is_array() ||
        node.at("children").size() < 2)
      Fail(path + ".children", "must be an array of at least 2 nodes");
    const BlendSmoothing smoothing = ReadSmoothing(node, path);
    const double delta = Number(node, "delta", path);
    const double epsilon =
        smoothing == BlendSmoothing::kConvex ? delta : Number(node, "epsilon", path);
    if (!node.contains("order") || !node.at("order").is_number_integer())
      Fail(path + ".order", "missing or not an integer");
    const long long order = node.at("order").get<long long>();
    if (order < 0 || order > UnitStep::kMaxOrder)
      Fail(path + ".order", "must be an integer in 0.." + std::to_string(UnitStep::kMaxOrder));
    RequirePositive(delta, path + ".delta");
    RequirePositive(epsilon, path + ".epsilon");
    if (epsilon > delta) Fail(path + ".epsilon", "must not exceed delta (0 < epsilon <= delta)");
    std::vector<int> children;
    const json& ch = node.at("children");
    for (size_t i = 0; i < ch.size(); ++i)
      children.push_back(
          ReadNode(ch[i], path + ".children[" + std::to_string(i) + "]", depth + 1, model));
    index = model->AddOperator(type, children, delta, epsilon, static_cast<int>(order), name);
    model->mutable_nodes()[index].smoothing = smoothing;
  } else if (type == NodeType::kBernsteinPatch) {
    index = ReadBernsteinPatch(node, path, name, model);
  } else if (IsComposite(type)) {
    index = ReadComposite(type, node, path, depth, name, model);
  } else if (type == NodeType::kBlobs) {
    index = ReadBlobs(node, path, name, model);
  } else if (type == NodeType::kPartition) {
    index = ReadPartition(node, path, depth, name, model);
  } else if (type == NodeType::kPartitionSequence) {
    index = ReadPartitionSequence(node, path, depth, name, model);
  } else if (type == NodeType::kColemanFeatures) {
    index = ReadColemanFeatures(node, path, depth, name, model);
  } else if (type == NodeType::kSkeletonOffset) {
    index = ReadSkeletonOffset(node, path, name, model);
  } else if (type == NodeType::kBernsteinMesh) {
    index = ReadBernsteinMeshNode(node, path, name, model);
  } else if (type == NodeType::kBSplineSurface) {
    index = ReadBSplineSurfaceNode(node, path, name, model);
  } else if (type == NodeType::kBSplineVolume) {
    index = ReadBSplineVolumeNode(node, path, name, model);
  } else {
    index = model->AddPrimitive(type, PrimitiveParameters(type, node, path), name);
  }
  model->mutable_nodes()[index].fixed = fixed;
  return index;
}

json Slice(const std::vector<double>& p, int begin, int size) {
  return json(std::vector<double>(p.begin() + begin, p.begin() + begin + size));
}

json WriteNode(const Model& model, int index) {
  const ModelNode& node = model.nodes()[index];
  const std::vector<double>& p = model.parameters();
  json out;
  out["type"] = NodeTypeName(node.type);
  if (!node.name.empty()) out["name"] = node.name;
  if (IsOperator(node.type)) {
    json children = json::array();
    for (int c : node.children) children.push_back(WriteNode(model, c));
    out["children"] = children;
    out["delta"] = p[node.first_parameter];
    if (node.smoothing == BlendSmoothing::kConvex)
      out["smoothing"] = "convex";  // width w = delta; no epsilon
    else
      out["epsilon"] = p[node.first_parameter + 1];
    out["order"] = node.order;
  } else if (node.type == NodeType::kBernsteinPatch) {
    out["degree"] = node.degree;
    json vertices = json::array();
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector3d x = node.tetrahedron.vertex(i);
      vertices.push_back(json::array({x[0], x[1], x[2]}));
    }
    out["vertices"] = vertices;
    out["control_points"] = Slice(p, node.first_parameter, node.num_parameters);
  } else if (IsComposite(node.type)) {
    json children = json::array();
    for (int c : node.children) children.push_back(WriteNode(model, c));
    out["children"] = children;
    int k = node.first_parameter;
    for (const ParameterField& f : ParameterFieldsOf(node.type)) {
      out[f.name] = f.size == 1 ? json(p[k]) : Slice(p, k, f.size);
      k += f.size;
    }
  } else if (node.type == NodeType::kPartition) {
    out["cuts"] = node.cuts;
    out["epsilon"] = p[node.first_parameter];
    out["order"] = node.order;
    json children = json::array();
    for (int c : node.children) children.push_back(WriteNode(model, c));
    out["children"] = children;
  } else if (node.type == NodeType::kColemanFeatures) {
    const int b = node.first_parameter;
    out["core_radius"] = p[b];
    if (node.count > 0 || node.curve_vertices.empty())
      out["features"] = WriteFeatureList(p, b + 1, node.count);
    if (!node.curve_vertices.empty()) out["curve_features"] = WriteCurveFeatures(model, node);
    out["children"] = json::array({WriteNode(model, node.children[0])});
  } else if (node.type == NodeType::kPartitionSequence) {
    json separators = json::array(), children = json::array();
    for (int j = 0; j < node.count; ++j) separators.push_back(WriteNode(model, node.children[j]));
    for (size_t c = node.count; c < node.children.size(); ++c)
      children.push_back(WriteNode(model, node.children[c]));
    out["separators"] = separators;
    out["epsilon"] = p[node.first_parameter];
    out["order"] = node.order;
    out["children"] = children;
  } else if (node.type == NodeType::kBlobs) {
    const int b = node.first_parameter, m = node.count;
    json centers = json::array();
    for (int i = 0; i < m; ++i) centers.push_back(Slice(p, b + 3 * i, 3));
    out["centers"] = centers;
    out["weights"] = Slice(p, b + 3 * m, m);
    out["widths"] = Slice(p, b + 4 * m, m);
    out["threshold"] = p[b + 5 * m];
    const BlobKernel kernel = static_cast<BlobKernel>(node.variant);
    out["kernel"] = kernel == BlobKernel::kGaussian ? "gaussian"
                    : kernel == BlobKernel::kWyvill ? "wyvill"
                                                    : "h_n";
    if (kernel == BlobKernel::kUnitStep) out["order"] = node.order;
  } else if (node.type == NodeType::kSkeletonOffset) {
    const int b = node.first_parameter, m = node.count;
    const SkeletonKind kind = static_cast<SkeletonKind>(node.variant);
    json list = json::array();
    if (kind == SkeletonKind::kCurve) {
      out["skeleton"] = WriteCurveSkeleton(model, node);
    } else if (kind == SkeletonKind::kSegments) {
      for (int i = 0; i < m; i += 2)
        list.push_back(json::array({Slice(p, b + 3 * i, 3), Slice(p, b + 3 * i + 3, 3)}));
    } else if (kind == SkeletonKind::kTriangles) {
      for (int i = 0; i < m; i += 3)
        list.push_back(json::array(
            {Slice(p, b + 3 * i, 3), Slice(p, b + 3 * i + 3, 3), Slice(p, b + 3 * i + 6, 3)}));
    } else {
      for (int i = 0; i < m; ++i) list.push_back(Slice(p, b + 3 * i, 3));
    }
    const char* key = kind == SkeletonKind::kPoints      ? "points"
                      : kind == SkeletonKind::kSegments  ? "segments"
                      : kind == SkeletonKind::kTriangles ? "triangles"
                                                         : "polyline";
    if (kind != SkeletonKind::kCurve) out["skeleton"] = json{{key, list}};
    out["radius"] = p[b + 3 * m];
    if (const int features = SkeletonFeatureCount(node))
      out["features"] = WriteFeatureList(p, b + 3 * m + 1, features);
  } else if (node.type == NodeType::kBox) {
    const int b = node.first_parameter;
    out["center"] = Slice(p, b, 3);
    double e[3][3];
    BoxEvaluator::Axes(&p[b + 3], e);
    out["axes"] = json::array({json::array({e[0][0], e[0][1], e[0][2]}),
                               json::array({e[1][0], e[1][1], e[1][2]}),
                               json::array({e[2][0], e[2][1], e[2][2]})});
    out["half_sizes"] = Slice(p, b + 7, 3);
  } else if (node.type == NodeType::kBernsteinMesh) {
    WriteBernsteinMeshNode(model, node, &out);
  } else if (node.type == NodeType::kBSplineSurface) {
    WriteBSplineSurfaceNode(model, node, &out);
  } else if (node.type == NodeType::kBSplineVolume) {
    WriteBSplineVolumeNode(model, node, &out);
  } else if (node.type == NodeType::kEllipsoid) {
    const int b = node.first_parameter;
    out["center"] = Slice(p, b, 3);
    out["radii"] = Slice(p, b + 3, 3);
    // e3 = e1 x e2 (normalised) is derived, written for readers that want a full frame.
    const double* e1 = &p[b + 6];
    const double* e2 = &p[b + 9];
    double e3[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                    e1[0] * e2[1] - e1[1] * e2[0]};
    const double n = std::sqrt(e3[0] * e3[0] + e3[1] * e3[1] + e3[2] * e3[2]);
    out["axes"] = json::array(
        {Slice(p, b + 6, 3), Slice(p, b + 9, 3), json::array({e3[0] / n, e3[1] / n, e3[2] / n})});
  } else {
    int k = node.first_parameter;
    for (const ParameterField& f : ParameterFieldsOf(node.type)) {
      out[f.name] = f.size == 1 ? json(p[k]) : Slice(p, k, f.size);
      k += f.size;
    }
  }
  if (!node.fixed.empty()) out["fixed"] = node.fixed;
  return out;
}

// The optional top-level claims (model/model.h ModelClaims):
//   "bounds": {"min": [3], "max": [3]} (min <= max), "verification": {"verified": bool[,
//   "reason": string]} (a reason only when not verified).
void CheckClaimKeys(const json& object, const std::set<std::string>& allowed,
                    const std::string& path) {
  for (auto it = object.begin(); it != object.end(); ++it)
    if (!allowed.count(it.key())) Fail(path + "." + it.key(), "unknown field");
}

void ReadClaims(const json& document, ModelClaims* claims) {
  if (document.contains("bounds")) {
    const json& b = document.at("bounds");
    if (!b.is_object()) Fail("bounds", "must be an object");
    CheckClaimKeys(b, {"min", "max"}, "bounds");
    const std::vector<double> lo = Vector(b, "min", 3, "bounds");
    const std::vector<double> hi = Vector(b, "max", 3, "bounds");
    for (int a = 0; a < 3; ++a)
      if (!(lo[a] <= hi[a])) Fail("bounds.min", "must be <= bounds.max on every axis");
    claims->has_bounds = true;
    claims->bounds_min = Eigen::Vector3d(lo[0], lo[1], lo[2]);
    claims->bounds_max = Eigen::Vector3d(hi[0], hi[1], hi[2]);
  }
  if (document.contains("verification")) {
    const json& v = document.at("verification");
    if (!v.is_object()) Fail("verification", "must be an object");
    CheckClaimKeys(v, {"verified", "reason"}, "verification");
    if (!v.contains("verified") || !v.at("verified").is_boolean())
      Fail("verification.verified", "missing or not a boolean");
    claims->has_verification = true;
    claims->verified = v.at("verified").get<bool>();
    if (v.contains("reason")) {
      if (!v.at("reason").is_string()) Fail("verification.reason", "must be a string");
      if (claims->verified) Fail("verification.reason", "must be absent when verified");
      claims->verification_reason = v.at("reason").get<std::string>();
    }
  }
}

void WriteClaims(const ModelClaims& claims, json* out) {
  if (claims.has_bounds) {
    const Eigen::Vector3d &lo = claims.bounds_min, &hi = claims.bounds_max;
    (*out)["bounds"] = {{"min", {lo.x(), lo.y(), lo.z()}}, {"max", {hi.x(), hi.y(), hi.z()}}};
  }
  if (claims.has_verification) {
    json v = {{"verified", claims.verified}};
    if (!claims.verified) v["reason"] = claims.verification_reason;
    (*out)["verification"] = v;
  }
}

}  // namespace

Model ModelFromJson(const json& document) {
  if (!document.is_object()) Fail("(document)", "must be a JSON object");
  for (auto it = document.begin(); it != document.end(); ++it)
    if (it.key() != "format" && it.key() != "version" && it.key() != "root" &&
        it.key() != "bounds" && it.key() != "verification")
      Fail(it.key(), "unknown top-level field");
  if (!document.contains("format") || document.at("format") != "implicitfit-model")
    Fail("format", "must be \"implicitfit-model\"");
  if (!document.contains("version") || !document.at("version").is_number_integer())
    Fail("version", "missing or not an integer");
  if (document.at("version").get<long long>() != 1)
    Fail("version",
         "unsupported version " + document.at("version").dump() + " (this build reads 1)");
  if (!document.contains("root")) Fail("root", "missing");
  Model model;
  const int root = ReadNode(document.at("root"), "root", 1, &model);
  model.SetRoot(root);
  ReadClaims(document, &model.mutable_claims());
  return model;
}

json ModelToJson(const Model& model) {
  json out;
  out["format"] = "implicitfit-model";
  out["version"] = 1;
  out["root"] = WriteNode(model, model.root());
  WriteClaims(model.claims(), &out);
  return out;
}

}  // namespace implicitfit
