#include "fit/reconstruct/solid_verification.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

#include "fit/reconstruct/polytope_box.h"
#include "fit/reconstruct/sublevel_enclosure.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

std::string Format(const char* format, double a, double b = 0, double c = 0) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, format, a, b, c);
  return buffer;
}

std::string VecText(const Vec& v) { return Format("(%.4g, %.4g, %.4g)", v.x(), v.y(), v.z()); }

nlohmann::json VecJson(const Vec& v) { return {v.x(), v.y(), v.z()}; }

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// 1. The structural proof, then f on the faces of the bounds grown by 1%.
void CheckBounded(const Model& model, const Vec& cloud_lo, const Vec& cloud_hi, double diag,
                  const SolidVerificationOptions& options, SolidVerification* v) {
  const Vec limit_lo = cloud_lo - Vec::Constant(options.max_reach * diag);
  const Vec limit_hi = cloud_hi + Vec::Constant(options.max_reach * diag);
  const SublevelEnclosure enclosure = EncloseSublevel(model, 0.0, options.max_enclosure_pieces);
  v->enclosure_pieces = static_cast<int>(enclosure.pieces.size());
  v->enclosure_overflow = enclosure.overflow;
  Vec lo = Vec::Constant(1e300), hi = Vec::Constant(-1e300);
  bool all_bounded = true;
  // Each piece is decided by linear programming; one that leaves the limit is split on its
  // deferred outside literals (SplitOnOutside) while the budget of decided pieces lasts.
  std::vector<EnclosurePiece> work(enclosure.pieces.rbegin(), enclosure.pieces.rend());
  int budget = options.max_decided_pieces;
  while (!work.empty()) {
    const EnclosurePiece piece = std::move(work.back());
    work.pop_back();
    if (budget-- <= 0) {
      all_bounded = false;
      v->unbounded_piece = piece.label;
      v->unbounded_reason = "more than " + std::to_string(options.max_decided_pieces) +
                            " polyhedra to decide";
      break;
    }
    ++v->decided_pieces;
    const PolytopeBox box = BoundPolytope(piece.faces, limit_lo, limit_hi);
    if (box.extent == PolytopeExtent::kEmpty) {
      ++v->empty_pieces;
      continue;
    }
    if (box.extent == PolytopeExtent::kBounded) {
      ++v->bounded_pieces;
      lo = lo.cwiseMin(box.lo);
      hi = hi.cwiseMax(box.hi);
      continue;
    }
    if (box.extent == PolytopeExtent::kBeyondLimit && !piece.outside.empty()) {
      ++v->split_pieces;
      const std::vector<EnclosurePiece> parts = SplitOnOutside(model, piece);
      work.insert(work.end(), parts.rbegin(), parts.rend());
      continue;
    }
    if (all_bounded) {  // the first polyhedron that leaves the limit is the one reported
      v->unbounded_piece = piece.label;
      v->unbounded_reason =
          box.extent == PolytopeExtent::kUnsolved ? box.message : piece.unbounded_reason;
      // its exit where f is lowest: where the solid itself most clearly reaches out
      for (const PolytopeBox::Exit& e : box.exits)
        for (const Vec& w : e.witnesses) {
          const double f = model.Value(w);
          if (v->unbounded_direction.norm() > 0 && !(f < v->unbounded_witness_value)) continue;
          v->unbounded_direction = e.direction;
          v->unbounded_witness = w;
          v->unbounded_witness_value = f;
          v->unbounded_infinite = e.infinite;
        }
    }
    all_bounded = false;
    break;  // one failure decides the check
  }
  if (!all_bounded) {
    std::string reason =
        "not bounded: {f <= 0} may reach " +
        std::string(v->unbounded_infinite ? "infinity"
                                          : Format("beyond %.3g diagonals from the scan",
                                                   options.max_reach)) +
        " through " + v->unbounded_piece;
    if (v->unbounded_direction.norm() > 0)
      reason += " along " + VecText(v->unbounded_direction) + "; f" +
                VecText(v->unbounded_witness) + " = " + Format("%.4g", v->unbounded_witness_value) +
                (v->unbounded_witness_value <= 0 ? " (inside: the solid is unbounded)"
                                                 : " (outside: not proven)");
    if (!v->unbounded_reason.empty()) reason += " [no bound from " + v->unbounded_reason + "]";
    v->failures.push_back(reason);
    return;
  }
  if (v->bounded_pieces == 0) {
    v->failures.push_back("empty: f > 0 everywhere (every polyhedron of the enclosure is empty)");
    return;
  }
  v->bounds_min = lo;
  v->bounds_max = hi;
  // Consistency of the proof: f > 0 on the faces of the bounds grown by 1%.
  const Vec glo = lo - 0.01 * (hi - lo) - Vec::Constant(1e-9 * (1 + diag));
  const Vec ghi = hi + 0.01 * (hi - lo) + Vec::Constant(1e-9 * (1 + diag));
  const int grid = 32;
  v->face_min_value = 1e300;
  Vec worst = glo;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int a = 0; a <= grid; ++a)
        for (int b = 0; b <= grid; ++b) {
          Vec x;
          const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
          x[axis] = side ? ghi[axis] : glo[axis];
          x[a1] = glo[a1] + (ghi[a1] - glo[a1]) * a / grid;
          x[a2] = glo[a2] + (ghi[a2] - glo[a2]) * b / grid;
          const double f = model.Value(x);
          ++v->face_samples;
          if (!(f >= v->face_min_value)) {
            v->face_min_value = f;
            worst = x;
          }
        }
  if (!(v->face_min_value > 0)) {
    v->failures.push_back("the bound proof is contradicted: f" + VecText(worst) + " = " +
                          Format("%.4g", v->face_min_value) + " on the faces of its box");
    return;
  }
  v->bounded = true;
}

// 2. Offset samples on both sides of every explained point, overall and per primitive.
void CheckAgreement(const Model& model, const std::vector<Vec>& points,
                    const std::vector<Vec>& normals, double diag,
                    const SolidVerificationOptions& options, SolidVerification* v) {
  const size_t n = points.size();
  std::vector<double> d(n);
  for (size_t i = 0; i < n; ++i) {
    double f;
    const Vec g = model.Gradient(points[i], &f);
    d[i] = std::abs(f) / std::max(g.norm(), 1e-300);
  }
  v->sigma = 1.4826 * Median(d);
  const double floor = std::max(3 * v->sigma, 1e-3 * diag);
  const std::vector<std::pair<std::string, int>> leaves = SolidLeaves(model);
  std::vector<int> leaf_points(leaves.size(), 0), leaf_agree(leaves.size(), 0);
  v->points = static_cast<int>(n);
  for (size_t i = 0; i < n; ++i) {
    if (!(d[i] <= options.max_offset * diag)) continue;
    ++v->explained_points;
    const double t = d[i] + floor;
    const bool agree = model.Value(points[i] - t * normals[i]) < 0 &&
                       model.Value(points[i] + t * normals[i]) > 0;
    v->agreeing_points += agree;
    int nearest = 0;
    double best = 1e300;
    for (size_t k = 0; k < leaves.size(); ++k) {
      // |f| of a leaf: every primitive's f is a distance, exact or first-order (model/model.h)
      const double dk = std::abs(
          model.EvaluateNode(leaves[k].second, model.parameters().data(), points[i].data()));
      if (dk < best) {
        best = dk;
        nearest = static_cast<int>(k);
      }
    }
    ++leaf_points[nearest];
    leaf_agree[nearest] += agree;
  }
  v->explained = n ? static_cast<double>(v->explained_points) / n : 0.0;
  v->agreement = v->explained_points ? static_cast<double>(v->agreeing_points) / v->explained_points : 0.0;
  std::string bad;
  for (size_t k = 0; k < leaves.size(); ++k) {
    PrimitiveAgreement a;
    a.name = leaves[k].first;
    a.points = leaf_points[k];
    a.agreement = a.points ? static_cast<double>(leaf_agree[k]) / a.points : 0.0;
    a.checked = a.points >= options.min_primitive_points;
    a.passed = !a.checked || a.agreement >= options.min_primitive_agreement;
    if (!a.passed)
      bad += (bad.empty() ? "" : ", ") + a.name + Format(" %.3f", a.agreement) + " of " +
             std::to_string(a.points);
    v->primitives.push_back(a);
  }
  if (v->explained < options.min_explained)
    v->failures.push_back(Format("the model explains %.3f of the points (within %.3g of its "
                                 "surface; needs %.2f)",
                                 v->explained, options.max_offset * diag, options.min_explained));
  if (v->agreement < options.min_agreement)
    v->failures.push_back(Format("inside/outside disagrees with the normals: %.3f of the "
                                 "explained points agree (needs %.2f)",
                                 v->agreement, options.min_agreement));
  if (!bad.empty())
    v->failures.push_back("inside/outside disagrees on " + bad +
                          Format(" (needs %.2f per primitive)", options.min_primitive_agreement));
}

// 3. Components and cavities, each with scan points on its boundary.
void CheckPieces(const Model& model, const std::vector<Vec>& points, const Vec& lo,
                 const Vec& hi, const SolidVerificationOptions& options, SolidVerification* v) {
  Vec glo, ghi;
  double cell;
  DefaultSolidGrid(lo, hi, options.grid_cells, &glo, &ghi, &cell);
  SolidComponentOptions co = options.components;
  if (co.num_threads == 0) co.num_threads = options.num_threads;
  v->components = FindSolidComponents(model, glo, ghi, cell, points, co);
  std::string bad;
  for (const SolidPiece& p : v->components.pieces)
    if (!p.supported)
      bad += (bad.empty() ? "" : "; ") + std::string(p.cavity ? "a cavity" : "a solid piece") +
             " of volume " + Format("%.4g", p.volume) + " at " + VecText(p.witness) +
             Format(" (%.0f points, coverage %.3f)", p.support_points, p.coverage);
  v->pieces_supported = bad.empty() && v->components.solids > 0;
  if (v->components.solids == 0)
    v->failures.push_back("no material on the grid (cell " + Format("%.4g", v->components.cell) + ")");
  if (!bad.empty()) v->failures.push_back("unsupported pieces (no scan points on them): " + bad);
}

}  // namespace

void DefaultSolidGrid(const Vec& bounds_min, const Vec& bounds_max, int cells, Vec* lo, Vec* hi,
                      double* cell) {
  const Vec margin = 0.1 * (bounds_max - bounds_min);
  *lo = bounds_min - margin;
  *hi = bounds_max + margin;
  *cell = (*hi - *lo).maxCoeff() / std::max(1, cells);
  if (!(*cell > 0)) *cell = 1e-3 * (1.0 + bounds_max.cwiseAbs().maxCoeff());
  *lo -= Vec::Constant(2 * *cell);
  *hi += Vec::Constant(2 * *cell);
}

SolidVerification VerifySolid(const Model& model, const std::vector<Vec>& points,
                              const std::vector<Vec>& normals,
                              const SolidVerificationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SolidVerification v;
  ProgressStage stage(options.progress, "verification",
                      std::to_string(points.size()) + " points");
  if (model.nodes().empty() || model.root() < 0 || points.empty() ||
      normals.size() != points.size()) {
    v.failures.push_back("needs a model and points with normals");
    v.message = v.failures.back();
    return v;
  }
  Vec lo = points[0], hi = points[0];
  for (const Vec& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double diag = std::max((hi - lo).norm(), 1e-12);
  CheckBounded(model, lo, hi, diag, options, &v);
  stage.Update(v.bounded ? "bounded" : "not bounded");
  CheckAgreement(model, points, normals, diag, options, &v);
  stage.Update(Format("inside/outside agreement %.3f", v.agreement));
  if (v.bounded)
    CheckPieces(model, points, v.bounds_min, v.bounds_max, options, &v);
  else  // for the report only: the cloud's box
    CheckPieces(model, points, lo, hi, options, &v);
  v.verified = v.failures.empty();
  v.message = "verified";
  if (!v.verified) {
    v.message.clear();
    for (const std::string& f : v.failures) v.message += (v.message.empty() ? "" : "; ") + f;
  }
  v.max_reach = options.max_reach;
  v.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stage.End(v.verified ? "verified" : "failed");
  return v;
}

std::string SolidVerification::BriefReport() const {
  if (!verified) return "not verified: " + message;
  return Format("verified: bounded, inside/outside agreement %.3f, ", agreement) +
         std::to_string(components.solids) + (components.solids == 1 ? " solid, " : " solids, ") +
         std::to_string(components.cavities) +
         (components.cavities == 1 ? " cavity" : " cavities");
}

nlohmann::json SolidVerification::ToJson() const {
  using nlohmann::json;
  json j;
  j["verified"] = verified;
  j["message"] = message;
  j["failures"] = failures;
  json b = {{"proven", bounded},
            {"method",
             "structural: {f <= 0} enclosed in convex polyhedra from the tree (supporting "
             "half-spaces of each primitive, blend reach delta/4), each decided by exact linear "
             "programming (GLPK)"},
            {"polyhedra", enclosure_pieces},
            {"decided_polyhedra", decided_pieces},
            {"split_polyhedra", split_pieces},
            {"bounded_polyhedra", bounded_pieces},
            {"empty_polyhedra", empty_pieces},
            {"gave_up", enclosure_overflow}};
  if (bounded) {
    b["box"] = {{"min", VecJson(bounds_min)}, {"max", VecJson(bounds_max)}};
    b["face_samples"] = face_samples;
    b["face_min_f"] = face_min_value;
  } else if (!unbounded_piece.empty()) {
    b["unbounded"] = {{"polyhedron", unbounded_piece},
                      {"infinite", unbounded_infinite},
                      {"direction", VecJson(unbounded_direction)},
                      {"witness", VecJson(unbounded_witness)},
                      {"f_at_witness", unbounded_witness_value},
                      {"no_bound_from", unbounded_reason}};
  }
  b["max_reach"] = max_reach;
  j["bounded"] = b;
  json io = {{"method",
              "samples p -+ t n on both sides of every point within the offset limit of the "
              "surface, t = |d| + max(3 sigma, 0.001 diagonal); agree when f(p - t n) < 0 < "
              "f(p + t n); per primitive by the nearest leaf"},
             {"points", points},
             {"explained_points", explained_points},
             {"explained", explained},
             {"agreement", agreement},
             {"sigma", sigma},
             {"primitives", json::array()}};
  for (const PrimitiveAgreement& a : primitives)
    io["primitives"].push_back({{"name", a.name},
                                {"points", a.points},
                                {"agreement", a.agreement},
                                {"checked", a.checked},
                                {"passed", a.passed}});
  j["inside_outside"] = io;
  json pieces = {{"method",
                  "grid of the default mesh: inside nodes 26-connected, outside nodes "
                  "6-connected; a piece is supported when scan points lie on its boundary"},
                 {"cell", components.cell},
                 {"grid", {components.grid[0], components.grid[1], components.grid[2]}},
                 {"solids", components.solids},
                 {"cavities", components.cavities},
                 {"supported", pieces_supported},
                 {"list", json::array()}};
  for (const SolidPiece& p : components.pieces)
    pieces["list"].push_back({{"kind", p.cavity ? "cavity" : "solid"},
                              {"volume", p.volume},
                              {"box", {{"min", VecJson(p.lo)}, {"max", VecJson(p.hi)}}},
                              {"witness", VecJson(p.witness)},
                              {"support_points", p.support_points},
                              {"coverage", p.coverage},
                              {"supported", p.supported}});
  j["pieces"] = pieces;
  j["seconds"] = seconds;
  return j;
}

std::vector<std::pair<std::string, int>> SolidLeaves(const Model& model) {
  std::vector<std::pair<std::string, int>> leaves;
  std::vector<int> stack = {model.root()};
  while (!stack.empty()) {
    const int index = stack.back();
    stack.pop_back();
    const ModelNode& node = model.nodes()[index];
    if (IsOperator(node.type) || node.type == NodeType::kComplement) {
      for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back(*it);
      continue;
    }
    const std::string name = node.name.empty() ? model.NodeLabel(index) : node.name;
    bool known = false;
    for (const auto& leaf : leaves) known = known || leaf.first == name;
    if (!known) leaves.push_back({name, index});
  }
  return leaves;
}

void ClaimVerification(const SolidVerification& v, Model* model) {
  ModelClaims& c = model->mutable_claims();
  c.has_bounds = v.bounded;
  c.bounds_min = v.bounds_min;
  c.bounds_max = v.bounds_max;
  c.has_verification = true;
  c.verified = v.verified;
  c.verification_reason = v.verified ? "" : v.message;
}

}  // namespace implicitfit
