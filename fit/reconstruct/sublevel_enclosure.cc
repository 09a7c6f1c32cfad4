#include "fit/reconstruct/sublevel_enclosure.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "model/primitives/box.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;
using Pieces = std::vector<EnclosurePiece>;

struct Context {
  const Model& model;
  int max_pieces;
  bool overflow = false;
};

Pieces AllOfSpace(const std::string& label, const std::string& reason) {
  EnclosurePiece p;
  p.label = label;
  p.unbounded_reason = reason;
  return {p};
}

// Two unit vectors orthogonal to u (and to each other).
void OrthonormalPair(const Vec& u, Vec* e1, Vec* e2) {
  const Vec helper = std::abs(u.x()) < 0.6 ? Vec::UnitX() : Vec::UnitY();
  *e1 = u.cross(helper).normalized();
  *e2 = u.cross(*e1).normalized();
}

// The 8 unit directions cos(k pi / 4) e1 + sin(k pi / 4) e2 about the axis u.
std::vector<Vec> RadialDirections(const Vec& u) {
  Vec e1, e2;
  OrthonormalPair(u, &e1, &e2);
  std::vector<Vec> w;
  for (int k = 0; k < 8; ++k)
    w.push_back(std::cos(k * M_PI / 4) * e1 + std::sin(k * M_PI / 4) * e2);
  return w;
}

// {w . (x - c) <= r} for each w.
void AddFaces(const std::vector<Vec>& directions, const Vec& c, double r, EnclosurePiece* p) {
  for (const Vec& w : directions) p->faces.push_back({w, w.dot(c) + r});
}

std::string LeafLabel(const Model& m, int index, int sign) {
  const ModelNode& node = m.nodes()[index];
  const std::string name = node.name.empty() ? m.NodeLabel(index) : node.name;
  return sign > 0 ? name : "!" + name;
}

// Enclosure of {sign * f_node <= t} for a primitive (empty vector: the set is empty).
Pieces PrimitivePieces(const Context& ctx, int index, int sign, double t) {
  const Model& m = ctx.model;
  const ModelNode& node = m.nodes()[index];
  const double* p = m.parameters().data() + node.first_parameter;
  const std::string label = LeafLabel(m, index, sign);
  EnclosurePiece piece;
  piece.label = label;
  if (node.type == NodeType::kPlane) {
    const Vec n(p[0], p[1], p[2]);
    const double norm = n.norm();
    piece.faces.push_back({sign * n / norm, sign * p[3] / norm + t});
    return {piece};
  }
  if (node.type == NodeType::kParaboloid) {
    const Vec a = Vec(p[3], p[4], p[5]).normalized(), vertex(p[0], p[1], p[2]);
    if (sign * p[6] < 0)  // f >= h needs kappa >= 0 (sigma = -1: kappa <= 0)
      return AllOfSpace(label, "a paraboloid's " + std::string(sign > 0 ? "inside" : "outside"));
    piece.faces.push_back({sign * a, sign * a.dot(vertex) + t});
    return {piece};
  }
  if (sign < 0) {
    Pieces all = AllOfSpace(label, "the outside of a " + std::string(NodeTypeName(node.type)));
    const bool convex = node.type == NodeType::kSphere || node.type == NodeType::kCylinder ||
                        node.type == NodeType::kCone || node.type == NodeType::kBox ||
                        node.type == NodeType::kEllipsoid;
    if (convex) all[0].outside.push_back({index, t});
    return all;
  }
  switch (node.type) {
    case NodeType::kSphere: {
      const double r = p[3] + t;
      if (r < 0) return {};
      std::vector<Vec> w;
      for (int a = 0; a < 3; ++a)
        for (int s : {-1, 1}) w.push_back(s * Vec::Unit(a));
      for (int s = 0; s < 8; ++s)
        w.push_back(Vec(s & 1 ? 1 : -1, s & 2 ? 1 : -1, s & 4 ? 1 : -1) / std::sqrt(3.0));
      AddFaces(w, Vec(p[0], p[1], p[2]), r, &piece);
      return {piece};
    }
    case NodeType::kCylinder: {
      const double r = p[6] + t;
      if (r < 0) return {};
      AddFaces(RadialDirections(Vec(p[3], p[4], p[5]).normalized()), Vec(p[0], p[1], p[2]), r,
               &piece);
      return {piece};
    }
    case NodeType::kCone: {
      const Vec u = Vec(p[3], p[4], p[5]).normalized();
      std::vector<Vec> m_dirs;
      for (const Vec& w : RadialDirections(u))
        m_dirs.push_back(std::cos(p[6]) * w - std::sin(p[6]) * u);
      AddFaces(m_dirs, Vec(p[0], p[1], p[2]), t, &piece);
      return {piece};
    }
    case NodeType::kTorus: {
      const double r = p[7] + t;
      if (r < 0) return {};
      const Vec u = Vec(p[3], p[4], p[5]).normalized(), c(p[0], p[1], p[2]);
      AddFaces({u, -u}, c, r, &piece);
      AddFaces(RadialDirections(u), c, p[6] + r, &piece);
      return {piece};
    }
    case NodeType::kBox: {
      double e[3][3];
      BoxEvaluator::Axes(p + 3, e);
      const Vec c(p[0], p[1], p[2]);
      for (int i = 0; i < 3; ++i) {
        const Vec axis(e[i][0], e[i][1], e[i][2]);
        AddFaces({axis, -axis}, c, p[7 + i] + t, &piece);
      }
      return {piece};
    }
    case NodeType::kEllipsoid: {
      // the evaluator's frame: e1 normalised, e2 Gram-Schmidt, e3 = e1 x e2
      const Vec e1 = Vec(p[6], p[7], p[8]).normalized();
      Vec e2(p[9], p[10], p[11]);
      e2 = (e2 - e2.dot(e1) * e1).normalized();
      const Vec axes[3] = {e1, e2, e1.cross(e2)};
      const double r_min = std::min({p[3], p[4], p[5]});
      const double scale = 1.0 + std::max(t, 0.0) / r_min;
      const Vec c(p[0], p[1], p[2]);
      for (int i = 0; i < 3; ++i) AddFaces({axes[i], -axes[i]}, c, p[3 + i] * scale, &piece);
      return {piece};
    }
    default:
      return AllOfSpace(label, std::string("a ") + NodeTypeName(node.type) + " (no bound known)");
  }
}

Pieces Intersect(Context* ctx, const Pieces& a, const Pieces& b) {
  if (static_cast<double>(a.size()) * b.size() > ctx->max_pieces) {
    ctx->overflow = true;
    return AllOfSpace("(more than " + std::to_string(ctx->max_pieces) + " pieces)",
                      "the enclosure grew past its limit");
  }
  Pieces out;
  for (const EnclosurePiece& x : a)
    for (const EnclosurePiece& y : b) {
      EnclosurePiece z = x;
      z.faces.insert(z.faces.end(), y.faces.begin(), y.faces.end());
      z.label = x.label + " & " + y.label;
      if (!y.unbounded_reason.empty())
        z.unbounded_reason += (z.unbounded_reason.empty() ? "" : "; ") + y.unbounded_reason;
      z.outside.insert(z.outside.end(), y.outside.begin(), y.outside.end());
      out.push_back(std::move(z));
    }
  return out;
}

Pieces Unite(Context* ctx, Pieces a, const Pieces& b) {
  a.insert(a.end(), b.begin(), b.end());
  if (static_cast<int>(a.size()) > ctx->max_pieces) {
    ctx->overflow = true;
    return AllOfSpace("(more than " + std::to_string(ctx->max_pieces) + " pieces)",
                      "the enclosure grew past its limit");
  }
  return a;
}

Pieces Enclose(Context* ctx, int index, int sign, double t) {
  const Model& m = ctx->model;
  const ModelNode& node = m.nodes()[index];
  if (node.type == NodeType::kComplement) return Enclose(ctx, node.children[0], -sign, t);
  if (!IsOperator(node.type)) {
    if (IsComposite(node.type) || node.type == NodeType::kBernsteinPatch ||
        node.type == NodeType::kBernsteinMesh)
      return AllOfSpace(LeafLabel(m, index, sign),
                        std::string("a ") + NodeTypeName(node.type) + " (no bound known)");
    return PrimitivePieces(*ctx, index, sign, t);
  }
  const double* p = m.parameters().data() + node.first_parameter;
  const bool li_phillips = node.smoothing == BlendSmoothing::kLiPhillips;
  if (node.order > 0 && li_phillips && !(p[1] > 0 && p[1] <= p[0] * (1 + 1e-12)))
    return AllOfSpace(LeafLabel(m, index, sign), "a blend with epsilon outside (0, delta]");
  const double reach = node.order > 0 ? 0.25 * std::abs(p[0]) : 0.0;
  const double k = static_cast<double>(node.children.size());
  // max-like: intersection, difference (subtrahends negated); min-like: union.
  const bool max_like = node.type != NodeType::kUnion;
  // sigma f of a max-like node: sigma = +1 intersects (level t), sigma = -1 unites (t + (k-1) r);
  // a min-like node the reverse.
  const bool intersect = (sign > 0) == max_like;
  const double level = intersect ? t : t + (k - 1) * reach;
  Pieces acc;
  for (size_t c = 0; c < node.children.size(); ++c) {
    const bool negated = node.type == NodeType::kDifference && c > 0;
    Pieces child = Enclose(ctx, node.children[c], negated ? -sign : sign, level);
    if (c == 0)
      acc = std::move(child);
    else
      acc = intersect ? Intersect(ctx, acc, child) : Unite(ctx, std::move(acc), child);
  }
  return acc;
}

// The faces (outward normals w, offsets c: w . x <= c) of a convex polyhedron inscribed in
// {f_node < -t}; false when that set is empty.
bool InscribedFaces(const Model& m, int index, double t, std::vector<HalfSpace>* faces) {
  const ModelNode& node = m.nodes()[index];
  const double* p = m.parameters().data() + node.first_parameter;
  const double shrink = 1.0 - 1e-9;  // strictly inside, against rounding
  faces->clear();
  auto add = [&](const Vec& w, const Vec& c, double r) { faces->push_back({w, w.dot(c) + r}); };
  switch (node.type) {
    case NodeType::kSphere: {
      const double r = (p[3] - t) * shrink;
      if (!(r > 0)) return false;
      for (int a = 0; a < 3; ++a)
        for (int s : {-1, 1}) add(s * Vec::Unit(a), Vec(p[0], p[1], p[2]), r / std::sqrt(3.0));
      return true;
    }
    case NodeType::kCylinder: {
      const double r = (p[6] - t) * shrink;
      if (!(r > 0)) return false;
      for (const Vec& w : RadialDirections(Vec(p[3], p[4], p[5]).normalized()))
        add(w, Vec(p[0], p[1], p[2]), r * std::cos(M_PI / 8));  // vertices on the circle
      return true;
    }
    case NodeType::kCone: {
      const Vec u = Vec(p[3], p[4], p[5]).normalized();
      const double a = p[6];
      const Vec apex = Vec(p[0], p[1], p[2]) + (std::max(t, 0.0) / std::sin(a)) * u;
      const std::vector<Vec> w = RadialDirections(u);
      for (int k = 0; k < 8; ++k) {
        const Vec g0 = std::cos(a) * u + std::sin(a) * w[k];
        const Vec g1 = std::cos(a) * u + std::sin(a) * w[(k + 1) % 8];
        Vec n = g0.cross(g1).normalized();
        if (n.dot(w[k] + w[(k + 1) % 8]) < 0) n = -n;  // outward
        add(n, apex, -1e-9 * (1.0 + apex.norm()));
      }
      return true;
    }
    case NodeType::kBox: {
      double e[3][3];
      BoxEvaluator::Axes(p + 3, e);
      const double inset = std::max(t, 0.0);  // t < 0: the box itself (its offset is rounded)
      for (int i = 0; i < 3; ++i)
        if (!(p[7 + i] - inset > 0)) return false;
      for (int i = 0; i < 3; ++i) {
        const Vec axis(e[i][0], e[i][1], e[i][2]);
        for (int s : {-1, 1}) add(s * axis, Vec(p[0], p[1], p[2]), (p[7 + i] - inset) * shrink);
      }
      return true;
    }
    case NodeType::kEllipsoid: {
      const double r_min = std::min({p[3], p[4], p[5]});
      const double scale = (1.0 - std::max(t, 0.0) / r_min) * shrink;
      if (!(scale > 0)) return false;
      const Vec e1 = Vec(p[6], p[7], p[8]).normalized();
      Vec e2(p[9], p[10], p[11]);
      e2 = (e2 - e2.dot(e1) * e1).normalized();
      const Vec axes[3] = {e1, e2, e1.cross(e2)};
      for (int i = 0; i < 3; ++i)
        for (int s : {-1, 1})
          add(s * axes[i], Vec(p[0], p[1], p[2]), p[3 + i] * scale / std::sqrt(3.0));
      return true;
    }
    default:
      return false;
  }
}

}  // namespace

std::vector<EnclosurePiece> SplitOnOutside(const Model& model, const EnclosurePiece& piece) {
  EnclosurePiece rest = piece;
  const EnclosurePiece::Outside literal = rest.outside.front();
  rest.outside.erase(rest.outside.begin());
  std::vector<HalfSpace> inscribed;
  if (!InscribedFaces(model, literal.node, literal.level, &inscribed)) return {rest};
  std::vector<EnclosurePiece> out;
  for (const HalfSpace& h : inscribed) {
    EnclosurePiece q = rest;
    q.faces.push_back({-h.normal, -h.offset});  // beyond that face: n . x >= d
    out.push_back(std::move(q));
  }
  return out;
}

SublevelEnclosure EncloseSublevel(const Model& model, double level, int max_pieces) {
  SublevelEnclosure out;
  if (model.nodes().empty() || model.root() < 0) return out;
  Context ctx{model, max_pieces};
  out.pieces = Enclose(&ctx, model.root(), +1, level);
  out.overflow = ctx.overflow;
  return out;
}

}  // namespace implicitfit
