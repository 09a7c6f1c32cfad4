#include "fit/reconstruct/solid_reconstruction.h"

#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <stdexcept>
#include <unordered_map>

#include "fit/primitive/primitive_fitter.h"
#include "fit/reconstruct/blend_refit.h"
#include "fit/reconstruct/csg_separation.h"
#include "fit/reconstruct/fillet_primitives.h"
#include "fit/reconstruct/fillet_separators.h"
#include "fit/reconstruct/offset_samples.h"
#include "fit/reconstruct/point_assignment.h"
#include "fit/reconstruct/separator_bridging.h"
#include "fit/reconstruct/solid_bounding.h"
#include "fit/reconstruct/term_bounds.h"
#include "fit/reconstruct/unsupported_repair.h"
#include "fit/tree/tree_covariance.h"
#include "model/median.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// Value and central-difference gradient of one node of a model.
double NodeValue(const Model& m, int node, const Vec& x, Vec* grad, double h) {
  const double* p = m.parameters().data();
  for (int k = 0; k < 3; ++k) {
    Vec a = x, b = x;
    a[k] += h;
    b[k] -= h;
    (*grad)[k] = (m.EvaluateNode(node, p, a.data()) - m.EvaluateNode(node, p, b.data())) / (2 * h);
  }
  return m.EvaluateNode(node, p, x.data());
}

SolidReconstruction ReconstructOnce(const std::vector<Vec>& points,
                                    const std::vector<Vec>& input_normals,
                                    const std::vector<SolidPrimitive>& primitives,
                                    const SolidReconstructionOptions& options);

}  // namespace

SolidReconstruction ReconstructSolid(const std::vector<Vec>& points,
                                     const std::vector<Vec>& normals,
                                     const std::vector<SolidPrimitive>& primitives,
                                     const SolidReconstructionOptions& options) {
  SolidReconstruction first = ReconstructOnce(points, normals, primitives, options);
  if (first.success || !options.fillets_as_blends || !options.as_blends.empty() ||
      first.assignment.label.size() != points.size())
    return first;
  Vec lo = points[0], hi = points[0];
  for (const Vec& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  std::vector<Model> models;
  for (const SolidPrimitive& p : primitives) models.push_back(p.model);
  const std::vector<bool> fillets = FilletLikePrimitives(points, normals, models, first.assignment,
                                                         options.max_fillet * (hi - lo).norm());
  if (std::count(fillets.begin(), fillets.end(), true) == 0) return first;
  std::string names;
  for (size_t k = 0; k < fillets.size(); ++k)
    if (fillets[k]) names += (names.empty() ? "" : " ") + primitives[k].name;
  SolidReconstructionOptions second_options = options;
  second_options.as_blends = fillets;
  ProgressStage stage(options.progress, "fillets as blends",
                      "not verified (" + first.message + "); again with " + names + " as blends");
  stage.End("");
  SolidReconstruction second = ReconstructOnce(points, normals, primitives, second_options);
  if (!second.success) {
    first.message +=
        " (again with the fillet-like " + names + " as blends: " + second.message + ")";
    first.seconds += second.seconds;
    return first;
  }
  for (size_t k = 0; k < fillets.size(); ++k)
    if (fillets[k]) second.fillets_as_blends.push_back(primitives[k].name);
  second.assignment = first.assignment;
  second.seconds += first.seconds;
  return second;
}

double ImpliedFilletRadius(double delta, double crease_angle_rad) {
  return delta / (4.0 * (1.0 - std::cos(0.5 * crease_angle_rad)));
}

namespace {

// Points on the faces of the box [shell_lo, shell_hi], a 17 x 17 grid on each: samples outside
// the solid (step 3).
std::vector<Vec> BoxShell(const Vec& shell_lo, const Vec& shell_hi) {
  std::vector<Vec> shell;
  const int grid = 16;
  for (int axis = 0; axis < 3; ++axis)
    for (int face = 0; face < 2; ++face)
      for (int u = 0; u <= grid; ++u)
        for (int v = 0; v <= grid; ++v) {
          Vec x;
          x[axis] = face ? shell_hi[axis] : shell_lo[axis];
          const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
          x[a1] = shell_lo[a1] + (shell_hi[a1] - shell_lo[a1]) * u / grid;
          x[a2] = shell_lo[a2] + (shell_hi[a2] - shell_lo[a2]) * v / grid;
          shell.push_back(x);
        }
  return shell;
}

// Step 4's test of one unassigned point x (normal n) at the operator o of m: a transition point
// when its two most active children w_a, w_b are in [-R, tau_all], n lies between their
// gradients and within 20 degrees of the blend's normal there; then *delta is
// (sqrt(-w_a) + sqrt(-w_b))^2 and *angle the angle between the gradients.
bool TransitionPoint(const Model& m, int o, const Vec& x, const Vec& n, double R, double tau_all,
                     double h, double* delta, double* angle) {
  const ModelNode& node = m.nodes()[o];
  const bool is_union = node.type == NodeType::kUnion;
  // w: children values with subtrahends negated; union works on -w (both outside).
  double best[2] = {-1e300, -1e300};
  Vec grad[2] = {Vec::Zero(), Vec::Zero()};
  for (size_t c = 0; c < node.children.size(); ++c) {
    Vec g;
    double w = NodeValue(m, node.children[c], x, &g, h);
    if (node.type == NodeType::kDifference && c > 0) {
      w = -w;
      g = -g;
    }
    const double key = is_union ? -w : w;  // the most active children: largest key
    if (key > best[0]) {
      best[1] = best[0];
      grad[1] = grad[0];
      best[0] = key;
      grad[0] = g;
    } else if (key > best[1]) {
      best[1] = key;
      grad[1] = g;
    }
  }
  if (best[1] < -R || best[0] > tau_all) return false;
  bool between = true;
  for (int j = 0; j < 2; ++j) {
    const double gn = grad[j].norm();
    const double c = n.dot(grad[j]) / gn;
    between = between && gn > 0 && c > 0.0 && c < 0.98;
  }
  if (!between) return false;
  const double d =
      std::pow(std::sqrt(std::max(0.0, -best[0])) + std::sqrt(std::max(0.0, -best[1])), 2);
  if (d < 2 * tau_all || d > 4 * R) return false;
  // The blend's normal at that position (parabolic zone): grad S_max(a, b) is proportional
  // to (1 + (a - b) / delta) grad a + (1 - (a - b) / delta) grad b; the point's normal must
  // be within 20 degrees of it (random normals of outliers rarely are).
  const double mix = std::clamp((best[0] - best[1]) / d, -1.0, 1.0);
  const Vec predicted =
      ((1 + mix) * grad[0].normalized() + (1 - mix) * grad[1].normalized()).normalized();
  if (!(predicted.dot(n) > std::cos(20.0 * M_PI / 180.0))) return false;
  *delta = d;
  *angle = std::acos(std::clamp(grad[0].normalized().dot(grad[1].normalized()), -1.0, 1.0));
  return true;
}

// One reconstruction over one set of primitives: the steps of
// fit/reconstruct/solid_reconstruction.h as stages that share the state below, run in order by
// ReconstructOnce. A stage that returns false has set out.message; the run stops there.
struct ReconstructionRun {
  ReconstructionRun(const std::vector<Vec>& points, const std::vector<Vec>& input_normals,
                    const std::vector<SolidPrimitive>& primitives,
                    const SolidReconstructionOptions& options)
      : points(points),
        normals(input_normals),
        primitives(primitives),
        options(options),
        K(static_cast<int>(primitives.size())),
        N(points.size()),
        rng(options.seed) {}

  bool CheckInput();
  void Assign();          // step 1
  void Orient();          // step 2
  bool Separate();        // step 3
  void FindBlends();      // step 4
  bool Refit();           // step 5
  void EstimateBlends();  // step 5: the blends' figures and deviations
  void Verify();          // step 6

  // Step 3's parts.
  void SetUpSamples();
  const Vec& SampleAt(size_t s) const;
  void SetLiteralBits(int k);
  void AddPlaneLiteral(const PlaneLiteral& plane, int kind);
  void AddFilletSeparators();
  CsgSeparation SeparateSamples();
  Model BuildTree(const CsgSeparation& sep) const;
  bool BoundedOnShell(const Model& tree) const;
  void SeparateAndClose();
  void AddSeparators(const std::vector<Vec>& directions, int min_conflict);
  void AddClosures();
  void KeepFilletOuterCylinders();
  void BoundByClosureFaces();
  void ReportAddedLiterals();

  const std::vector<Vec>& points;
  std::vector<Vec> normals;  // re-signed per primitive in step 2
  const std::vector<SolidPrimitive>& primitives;
  const SolidReconstructionOptions& options;
  const int K;
  const size_t N;
  Vec lo, hi;         // the cloud's box
  double diag = 0.0;  // and its diagonal
  double R = 0.0;     // the largest fillet considered
  SolidReconstruction out;
  std::unique_ptr<ProgressStage> stage;  // one stage at a time: the last ends before the next

  // Steps 1-2: the primitives (planes flipped to their material side), their bands, the
  // assignment.
  std::vector<Model> prim;
  std::vector<double> tau;
  PointAssignment assignment;

  // Step 3: samples and literals.
  std::mt19937_64 rng;
  std::vector<Vec> assigned_positions;
  std::vector<size_t> assigned_points;  // shuffled, at most options.max_samples
  // Literals: the primitives, then separators and closures (fixed planes).
  std::vector<Model> lit;
  std::vector<std::string> names;
  std::vector<int> literal_kind;  // 0 primitive, 1 separator, 2 closure, 3 separator cylinder
  std::vector<PlaneLiteral> literal_plane;
  std::map<int, CylinderLiteral> literal_cylinder;
  // Primitives without points (redundant or unused) are no literals: their sign bits stay 0.
  std::vector<bool> literal_on;
  std::vector<Model> used_prim;
  std::vector<int> used_index;
  // Samples: positions, inside flags, sign vectors over the literals; the offset samples first,
  // then the shell's.
  double t = 0.0;  // the samples' offset along the normal
  std::vector<Vec> sx;
  std::vector<bool> sin;
  size_t offset_samples = 0;
  std::vector<Vec> shell;
  std::vector<std::uint64_t> signs;
  std::vector<std::pair<int, int>> fillet_outer;  // (hole torus, its outer cylinder) literals
  bool closed = false;                // closures added: cells outside the closure box are outside
  std::vector<Vec> box_corners;       // of the closure box (bit a of the index: face 2a + bit)
  std::vector<int> closure_literals;  // the literals of its faces -a0, +a0, -a1, ...
  std::uint64_t root_closures = 0;    // faces that bound the whole solid (BoundByClosureFaces)
  std::unordered_map<std::uint64_t, bool> bounded_cache;
  double placeholder = 0.0;  // delta and epsilon of the sharp operators
  CsgSeparation sep;

  // Steps 4-5: transition points per operator node, the smooth operators, the fit's inliers.
  std::vector<std::vector<double>> deltas, angles;
  std::vector<int> smooth;
  std::vector<Vec> inlier_points;
};

// Input sizes, the cloud's box and R.
bool ReconstructionRun::CheckInput() {
  if (K < 1 || K > 64) {
    out.message = "needs between 1 and 64 primitives, got " + std::to_string(K);
    return false;
  }
  if (normals.size() != N || N < 10) {
    out.message = "needs at least 10 points with normals";
    return false;
  }
  lo = points[0];
  hi = points[0];
  for (const Vec& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  diag = (hi - lo).norm();
  R = options.max_fillet * diag;
  return true;
}

// 1. Assignment of the points to the primitives, without the redundant ones and the blends.
void ReconstructionRun::Assign() {
  stage = std::make_unique<ProgressStage>(
      options.progress, "orientation",
      std::to_string(N) + " points, " + std::to_string(K) + " primitives");
  prim.resize(K);
  tau.resize(K);
  for (int k = 0; k < K; ++k) {
    prim[k] = primitives[k].model;
    tau[k] = std::max(3.0 * primitives[k].rms, 1e-3 * diag);
  }
  // Crease bands that detect fitted with extra surfaces are dropped, their points assigned
  // again (fit/reconstruct/point_assignment.h).
  std::vector<bool> active(K, true);
  for (int k = 0; k < K && k < static_cast<int>(options.as_blends.size()); ++k)
    active[k] = !options.as_blends[k];
  assignment = AssignPoints(points, normals, prim, tau, active);
  if (options.drop_redundant) {
    std::vector<double> band(K);
    for (int k = 0; k < K; ++k)
      band[k] = std::max(2.5 * primitives[k].rms, options.redundant_floor * diag);
    if (DropRedundantPrimitives(points, prim, band, assignment, options.redundant_share, &active) >
        0)
      assignment = AssignPoints(points, normals, prim, tau, active);
  }
  out.assignment = assignment;
  out.assigned = assignment.assigned;
  out.unassigned = assignment.unassigned;
}

// 2. Orientation. A primitive's points lie on one smooth sheet, so their outward normals all
//    face one side of it: where most of them (at least options.resign_majority) agree, the
//    others' signs are corrected to that side (the propagation of the normals' orientation
//    can carry a wrong sign into part of a small bore through its rim).
void ReconstructionRun::Orient() {
  const std::vector<int>& label = assignment.label;
  const std::vector<double>& side_vote = assignment.side_vote;
  for (size_t i = 0; i < N; ++i) {
    const int k = label[i];
    if (k < 0 || out.assigned[k] == 0) continue;
    const double majority = std::abs(side_vote[k]) / out.assigned[k];  // (agree - disagree) / n
    if (0.5 * (1.0 + majority) < options.resign_majority) continue;
    const double vote = normals[i].dot(prim[k].Gradient(points[i]));
    if ((vote > 0) != (side_vote[k] >= 0)) {
      normals[i] = -normals[i];
      ++out.resigned_normals;
    }
  }
  //    Planes are flipped to their material side; other kinds keep f and say hole.
  out.sides.assign(K, "unused");
  for (int k = 0; k < K; ++k) {
    if (out.assigned[k] == 0) continue;
    const bool solid = side_vote[k] >= 0;
    const ModelNode& root = prim[k].nodes()[prim[k].root()];
    if (!solid && root.type == NodeType::kPlane && prim[k].nodes().size() == 1) {
      for (double& v : prim[k].mutable_parameters()) v = -v;
      out.sides[k] = "solid";
    } else {
      out.sides[k] = solid ? "solid" : "hole";
    }
  }
}

// 3. Inside/outside samples and the separation, with separators and closures when needed
//    (fit/reconstruct/solid_bounding.h): the sharp tree in out.model and its expression.
bool ReconstructionRun::Separate() {
  stage.reset();
  stage = std::make_unique<ProgressStage>(options.progress, "separation", "");
  SetUpSamples();
  AddFilletSeparators();
  SeparateAndClose();
  KeepFilletOuterCylinders();
  out.expression = CsgExpressionText(sep.terms, names);
  BoundByClosureFaces();
  ReportAddedLiterals();
  Model& m = out.model;
  if (m.nodes().empty()) {
    out.message = "the oriented cloud gives no bounded Boolean expression over the primitives (" +
                  std::to_string(sep.inside_cells) + " inside cells)";
    return false;
  }
  for (ModelNode& node : m.mutable_nodes())
    if (IsOperator(node.type)) node.fixed = {"delta", "epsilon"};
  return true;
}

// The primitives as literals, the offset samples of (at most options.max_samples) assigned
// points, the shell around the cloud, and the samples' sign bits over the primitives.
void ReconstructionRun::SetUpSamples() {
  const std::vector<int>& label = assignment.label;
  for (size_t i = 0; i < N; ++i)
    if (label[i] >= 0) assigned_points.push_back(i);
  for (size_t i : assigned_points) assigned_positions.push_back(points[i]);
  std::shuffle(assigned_points.begin(), assigned_points.end(), rng);
  if (static_cast<int>(assigned_points.size()) > options.max_samples)
    assigned_points.resize(options.max_samples);
  lit = prim;
  for (int k = 0; k < K; ++k) {
    names.push_back(primitives[k].name.empty() ? "p" + std::to_string(k) : primitives[k].name);
    lit[k].mutable_nodes()[lit[k].root()].name = names[k];  // the expression's name in the model
  }
  literal_kind.assign(K, 0);
  literal_plane.resize(K);
  literal_on.resize(K);
  used_index.assign(K, -1);
  for (int k = 0; k < K; ++k) {
    literal_on[k] = out.sides[k] != "unused";
    if (!literal_on[k]) continue;
    used_index[k] = static_cast<int>(used_prim.size());
    used_prim.push_back(prim[k]);
  }
  t = options.offset * diag;
  for (size_t i : assigned_points) {
    const OffsetSamplePair pair = OffsetSamples(points[i], normals[i], used_index[label[i]],
                                                used_prim, t, options.adaptive_offset);
    sx.push_back(pair.inside);
    sin.push_back(true);
    sx.push_back(pair.outside);
    sin.push_back(false);
  }
  offset_samples = sx.size();
  shell = BoxShell(lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo));
  signs.assign(sx.size() + shell.size(), 0);
  for (int k = 0; k < K; ++k) SetLiteralBits(k);
  placeholder = 1e-3 * diag;
}

const Vec& ReconstructionRun::SampleAt(size_t s) const {
  return s < offset_samples ? sx[s] : shell[s - offset_samples];
}

// Bit k of every sample's sign vector: inside literal k.
void ReconstructionRun::SetLiteralBits(int k) {
  if (k < K && !literal_on[k]) return;
  for (size_t s = 0; s < signs.size(); ++s)
    if (lit[k].Value(SampleAt(s)) < 0) signs[s] |= 1ULL << k;
}

// A separator (kind 1) or closure (kind 2) plane as the next literal.
void ReconstructionRun::AddPlaneLiteral(const PlaneLiteral& plane, int kind) {
  const int k = static_cast<int>(lit.size());
  names.push_back((kind == 1 ? "separator" : "closure") +
                  std::to_string(std::count(literal_kind.begin(), literal_kind.end(), kind)));
  lit.push_back(plane.ToModel(names.back()));
  literal_kind.push_back(kind);
  literal_plane.push_back(plane);
  SetLiteralBits(k);
}

// Fillets (tori; holes are concave fillets, solids convex ones): the box of revolution of their
// points (fit/reconstruct/fillet_separators.h): two planes (separators) and two coaxial
// cylinders (kind 3).
void ReconstructionRun::AddFilletSeparators() {
  const std::vector<int>& label = assignment.label;
  for (int k = 0; k < K; ++k) {
    if (!options.fillet_separators || out.sides[k] == "unused" || lit.size() + 4 > 58) continue;
    std::vector<Vec> on_torus, their_normals;
    for (size_t i = 0; i < N; ++i)
      if (label[i] == k) {
        on_torus.push_back(points[i]);
        their_normals.push_back(normals[i]);
      }
    FilletBounds bounds;
    const bool found = out.sides[k] == "hole"
                           ? FilletBoundsOf(prim[k], on_torus, t / 8, &bounds)
                           : FilletBoundsOf(prim[k], on_torus, their_normals, t / 8, &bounds);
    if (!found) continue;
    AddPlaneLiteral(bounds.low, 1);
    AddPlaneLiteral(bounds.high, 1);
    for (const bool outer : {false, true}) {
      const CylinderLiteral& c = outer ? bounds.outer : bounds.inner;
      if (!(c.radius > 0)) continue;
      const int j = static_cast<int>(lit.size());
      if (outer) fillet_outer.push_back({k, j});
      names.push_back("separator_cylinder" + std::to_string(literal_cylinder.size()));
      lit.push_back(c.ToModel(names.back()));
      literal_kind.push_back(3);
      literal_plane.push_back(PlaneLiteral{});
      literal_cylinder[j] = c;
      SetLiteralBits(j);
    }
  }
}

// The cells of the arrangement of the literals, from the samples
// (fit/reconstruct/csg_separation.h).
CsgSeparation ReconstructionRun::SeparateSamples() {
  std::vector<CsgSample> samples(signs.size());
  for (size_t s = 0; s < signs.size(); ++s)
    samples[s] = {signs[s], s < offset_samples && sin[s], closed && s >= offset_samples};
  CsgSeparationOptions so;
  // closures, then separators (fillets' cylinders first), then detected surfaces
  for (int kind : {2, 3, 1, 0})
    for (int k = 0; k < static_cast<int>(lit.size()); ++k)
      if (literal_kind[k] == kind) so.drop_order.push_back(k);
  // Every term stays bounded within the verifier's limit box (fit/reconstruct/term_bounds.h);
  // the literals only grow, so the answers for a mask stay valid.
  so.bounded = [&](std::uint64_t mask) {
    const auto found = bounded_cache.find(mask);
    if (found != bounded_cache.end()) return found->second;
    const Vec reach = Vec::Constant(options.verification.max_reach * diag);
    return bounded_cache[mask] = TermIsBounded(lit, mask, lo - reach, hi + reach);
  };
  return SeparateCells(samples, static_cast<int>(lit.size()), so);
}

// The sharp tree: union of difference(intersection(positives), negatives).
Model ReconstructionRun::BuildTree(const CsgSeparation& sep) const {
  Model tree;
  std::vector<int> term_nodes;
  for (const CsgTerm& term : sep.terms) {
    std::vector<int> pos, neg;
    for (int k = 0; k < static_cast<int>(lit.size()); ++k) {
      if (term.inside >> k & 1) pos.push_back(CopySubtree(lit[k], lit[k].root(), &tree));
      if (term.outside >> k & 1) neg.push_back(CopySubtree(lit[k], lit[k].root(), &tree));
    }
    if (pos.empty()) continue;  // unbounded (only complements): cannot be part of a solid
    int node = pos.size() == 1
                   ? pos[0]
                   : tree.AddOperator(NodeType::kIntersection, pos, placeholder, placeholder, 0);
    if (!neg.empty()) {
      std::vector<int> children = {node};
      children.insert(children.end(), neg.begin(), neg.end());
      node = tree.AddOperator(NodeType::kDifference, children, placeholder, placeholder, 0);
    }
    term_nodes.push_back(node);
  }
  if (term_nodes.empty()) return tree;
  tree.SetRoot(term_nodes.size() == 1
                   ? term_nodes[0]
                   : tree.AddOperator(NodeType::kUnion, term_nodes, placeholder, placeholder, 0));
  return tree;
}

bool ReconstructionRun::BoundedOnShell(const Model& tree) const {
  if (tree.nodes().empty()) return false;
  for (const Vec& x : shell)
    if (!(tree.Value(x) > 0)) return false;
  return true;
}

// Separators, then the tree; closures (once) when a term is open (no literal bounds it in some
// direction) or the shell meets the solid, then separators and the tree again.
void ReconstructionRun::SeparateAndClose() {
  const std::vector<Vec> directions = SeparatorDirections(used_prim);
  const int min_conflict =
      std::max(options.min_conflict_samples,
               static_cast<int>(std::ceil(options.min_conflict_fraction * signs.size())));
  Model& m = out.model;
  for (;;) {
    AddSeparators(directions, min_conflict);
    m = BuildTree(sep);
    if (closed || (sep.unbounded_terms == 0 && BoundedOnShell(m))) break;
    if (lit.size() + 6 > 64) break;
    AddClosures();
  }
}

// Separators: split the most mixed cell while a plane separates it well; sep is the last
// separation.
void ReconstructionRun::AddSeparators(const std::vector<Vec>& directions, int min_conflict) {
  for (int round = 0;; ++round) {
    sep = SeparateSamples();
    if (round >= options.max_separators || lit.size() + (closed ? 0 : 6) >= 64) break;
    std::map<std::uint64_t, std::pair<int, int>> votes;
    for (size_t s = 0; s < signs.size(); ++s) {
      if (closed && s >= offset_samples) continue;  // certain: not a vote
      auto& v = votes[signs[s]];
      (s < offset_samples && sin[s] ? v.first : v.second) += 1;
    }
    std::uint64_t worst = 0;
    int worst_minority = 0;
    for (const auto& [cell, v] : votes) {
      const int minority = std::min(v.first, v.second);
      if (minority >= min_conflict && minority >= 0.1 * (v.first + v.second) &&
          minority > worst_minority) {
        worst = cell;
        worst_minority = minority;
      }
    }
    if (worst_minority == 0) break;
    std::vector<Vec> cell_x;
    std::vector<bool> cell_in;
    for (size_t s = 0; s < signs.size(); ++s)
      if (signs[s] == worst && !(closed && s >= offset_samples)) {
        cell_x.push_back(SampleAt(s));
        cell_in.push_back(s < offset_samples && sin[s]);
      }
    const StumpSplit split = BestStump(cell_x, cell_in, directions);
    // Accepted when it removes at least max(min_conflict, 10%) of the misclassified samples: a
    // cell may need several cuts, none of them alone halving its minority (Fit4CAD PC131: the
    // slab's centre and the space beyond its four rounded sides, one plane per side).
    if (!split.found ||
        worst_minority - split.errors < std::max<double>(min_conflict, 0.1 * worst_minority))
      break;
    AddPlaneLiteral(split.plane, 1);
  }
}

// Closures: the box around the assigned points in the part's frame, its faces as literals; a
// new shell around it, whose samples are outside for certain.
void ReconstructionRun::AddClosures() {
  closed = true;
  const std::vector<PlaneLiteral> faces =
      ClosureBox(ClosureFrame(prim, out.assigned, assigned_positions), assigned_positions,
                 options.closure_margin * diag);
  Vec box_lo = Vec::Constant(1e300), box_hi = Vec::Constant(-1e300);
  box_corners.resize(8);
  for (int corner = 0; corner < 8; ++corner) {
    // the box's corners: intersections of one face of each pair
    Eigen::Matrix3d a;
    Vec b;
    for (int axis = 0; axis < 3; ++axis) {
      const PlaneLiteral& f = faces[2 * axis + (corner >> axis & 1)];
      a.row(axis) = f.normal.transpose();
      b[axis] = f.offset;
    }
    const Vec x = a.inverse() * b;
    box_corners[corner] = x;
    box_lo = box_lo.cwiseMin(x);
    box_hi = box_hi.cwiseMax(x);
  }
  shell = BoxShell(box_lo - 0.1 * (box_hi - box_lo), box_hi + 0.1 * (box_hi - box_lo));
  signs.resize(offset_samples + shell.size());
  for (size_t s = offset_samples; s < signs.size(); ++s) {
    signs[s] = 0;
    for (int k = 0; k < static_cast<int>(lit.size()); ++k)
      if ((k >= K || literal_on[k]) && lit[k].Value(shell[s - offset_samples]) < 0)
        signs[s] |= 1ULL << k;
  }
  for (const PlaneLiteral& f : faces) {
    closure_literals.push_back(static_cast<int>(lit.size()));
    AddPlaneLiteral(f, 2);
  }
}

// A term that carves a concave fillet's tube out (negated hole torus) keeps the fillet's outer
// cylinder when (all but 1% of) its inside samples are in it: the shell's samples may all lie
// in the tube (Fit4CAD PC124), so that nothing else bounds the term radially.
void ReconstructionRun::KeepFilletOuterCylinders() {
  bool tightened = false;
  for (CsgTerm& term : sep.terms)
    for (const auto& [torus, outer] : fillet_outer) {
      const std::uint64_t bit = 1ULL << outer;
      if (!(term.outside >> torus & 1) || ((term.inside | term.outside) & bit)) continue;
      int covered = 0, beyond = 0;
      for (size_t s = 0; s < offset_samples; ++s)
        if (sin[s] && (signs[s] & term.inside) == term.inside && !(signs[s] & term.outside)) {
          ++covered;
          beyond += !(signs[s] & bit);
        }
      if (beyond > 0.01 * covered) continue;
      term.inside |= bit;
      tightened = true;
    }
  if (tightened) out.model = BuildTree(sep);
}

// A closed solid lies in its closure box (the cells beyond it are outside), but a term that no
// sample bounds may still reach out of it between the shell's samples (the Kinect milk carton:
// two cylinders of radius 0.29 and 0.1 intersect far beyond the scan). Every face of the box
// that the union crosses (a point of a 64 x 64 grid on the face inside the solid) bounds the
// whole solid: intersection(union of the terms, those faces).
void ReconstructionRun::BoundByClosureFaces() {
  Model& m = out.model;
  if (!closed || m.nodes().empty()) return;
  std::vector<int> bounding = {m.root()};
  std::string faces_text;
  for (int f = 0; f < 6; ++f) {
    const int axis = f / 2, side = f % 2;
    std::vector<Vec> c;  // the face's corners, (u, v) = (0, 0), (1, 0), (0, 1)
    for (int corner = 0; corner < 8; ++corner)
      if ((corner >> axis & 1) == side) c.push_back(box_corners[corner]);
    bool crosses = false;
    const int n = 64;
    for (int u = 0; u <= n && !crosses; ++u)
      for (int v = 0; v <= n && !crosses; ++v) {
        const Vec x = c[0] + (c[1] - c[0]) * u / n + (c[2] - c[0]) * v / n;
        crosses = m.Value(x) < -1e-9 * diag;
      }
    if (!crosses) continue;
    const int k = closure_literals[f];
    root_closures |= 1ULL << k;
    bounding.push_back(CopySubtree(lit[k], lit[k].root(), &m));
    faces_text += " & " + names[k];
  }
  if (bounding.size() > 1) {
    m.SetRoot(m.AddOperator(NodeType::kIntersection, bounding, placeholder, placeholder, 0));
    out.expression = "(" + out.expression + ")" + faces_text;
  }
}

// The separators, closures and separator cylinders that the model uses, for the report.
void ReconstructionRun::ReportAddedLiterals() {
  for (int k = K; k < static_cast<int>(lit.size()); ++k) {
    bool used = (root_closures >> k & 1) != 0;
    for (const CsgTerm& term : sep.terms) used = used || ((term.inside | term.outside) >> k & 1);
    if (!used) continue;
    if (literal_kind[k] == 3) {
      const CylinderLiteral& c = literal_cylinder.at(k);
      out.separator_cylinders.push_back({names[k], c.point, c.axis, c.radius});
      continue;
    }
    (literal_kind[k] == 1 ? out.separators : out.closures)
        .push_back({names[k], literal_plane[k].normal, literal_plane[k].offset});
  }
}

// 4. Blends from the transition points: an operator with enough of them is made smooth, delta
//    at their median.
void ReconstructionRun::FindBlends() {
  stage.reset();
  stage = std::make_unique<ProgressStage>(options.progress, "blends", out.expression);
  Model& m = out.model;
  const std::vector<int>& label = assignment.label;
  const double h = 1e-6 * diag;
  const double tau_all = *std::max_element(tau.begin(), tau.end());
  std::vector<int> operators;
  for (int i = 0; i < static_cast<int>(m.nodes().size()); ++i)
    if (IsOperator(m.nodes()[i].type)) operators.push_back(i);
  deltas.resize(m.nodes().size());
  angles.resize(m.nodes().size());
  for (size_t i = 0; i < N; ++i) {
    if (label[i] >= 0) continue;
    const Vec& x = points[i];
    if (std::abs(m.Value(x)) > R) continue;
    for (int o : operators) {
      double d = 0.0, angle = 0.0;
      if (!TransitionPoint(m, o, x, normals[i], R, tau_all, h, &d, &angle)) continue;
      deltas[o].push_back(d);
      angles[o].push_back(angle);
    }
  }
  const int min_points = std::max(options.min_transition_points,
                                  static_cast<int>(std::ceil(options.min_transition_fraction * N)));
  for (int o : operators) {
    if (static_cast<int>(deltas[o].size()) < min_points) continue;
    ModelNode& node = m.mutable_nodes()[o];
    node.order = options.blend_order;
    node.fixed.clear();
    const double delta0 = Median(deltas[o]);
    m.mutable_parameters()[node.first_parameter] = delta0;
    m.mutable_parameters()[node.first_parameter + 1] = 0.6 * delta0;
    smooth.push_back(o);
  }
}

// 5. Joint refinement on the points near the initial solid; its inliers.
bool ReconstructionRun::Refit() {
  stage.reset();
  stage = std::make_unique<ProgressStage>(options.progress, "tree fit",
                                          std::to_string(smooth.size()) + " blends");
  const std::vector<int>& label = assignment.label;
  std::vector<Vec> near_points, near_normals;
  std::vector<bool> near_on_face;
  for (size_t i = 0; i < N; ++i) {
    const double f = out.model.Value(points[i]);
    if (std::abs(f) < R) {
      near_points.push_back(points[i]);
      near_normals.push_back(normals[i]);
      near_on_face.push_back(label[i] >= 0);
    }
  }
  // Each smooth operator's subtree on the points where the solid's value is its own
  // (fit/reconstruct/blend_refit.h); with no blend nothing is refitted.
  const TreeFitResult fit = RefitBlends(out.model, near_points, near_normals, near_on_face,
                                        options.max_fit_points, 1e-6 * diag, options.tree, &rng);
  out.fit_seconds = fit.seconds;
  out.fit_iterations = fit.iterations;
  if (!fit.success) {
    out.message = "tree fit failed: " + fit.message;
    return false;
  }
  out.model = fit.model;
  out.rms = fit.rms;
  out.sigma = fit.sigma;
  int agree = 0;
  for (size_t i = 0; i < near_points.size(); ++i) {
    double f;
    const Vec g = out.model.Gradient(near_points[i], &f);
    if (!(std::abs(f) / g.norm() < std::max(3 * fit.sigma, 1e-6 * diag))) continue;
    inlier_points.push_back(near_points[i]);
    agree += g.dot(near_normals[i]) > 0;
  }
  out.inliers = static_cast<int>(inlier_points.size());
  out.normal_agreement = out.inliers ? static_cast<double>(agree) / out.inliers : 0.0;
  return true;
}

// Deviations of the refitted parameters only (blends and their faces), and each blend's
// figures.
void ReconstructionRun::EstimateBlends() {
  const std::vector<double> sd = BlendStandardDeviations(out.model, inlier_points);
  for (int o : smooth) {
    const ModelNode& node = out.model.nodes()[o];
    if (node.order == 0) continue;  // the refit kept it sharp (fit/reconstruct/blend_refit.h)
    BlendEstimate b;
    b.node = out.model.NodeLabel(o);
    b.type = NodeTypeName(node.type);
    b.transition_points = static_cast<int>(deltas[o].size());
    b.delta = out.model.parameters()[node.first_parameter];
    b.epsilon = out.model.parameters()[node.first_parameter + 1];
    b.sd_delta = sd[node.first_parameter];
    b.sd_epsilon = sd[node.first_parameter + 1];
    const double phi = Median(angles[o]);
    b.crease_angle_deg = phi * 180.0 / M_PI;
    b.fillet_radius = ImpliedFilletRadius(b.delta, phi);
    b.sd_fillet_radius = ImpliedFilletRadius(b.sd_delta, phi);
    out.blends.push_back(b);
  }
}

// 6. Verification: bounded (proven), inside/outside, supported pieces; unsupported pieces
//    repaired and separated pieces bridged when that verifies.
void ReconstructionRun::Verify() {
  stage.reset();
  SolidVerificationOptions vo = options.verification;
  if (!vo.progress) vo.progress = options.progress;
  out.verification = VerifySolid(out.model, points, normals, vo);
  if (!out.verification.verified) {  // unsupported pieces alone: removed when that verifies
    const PieceRepair repair =
        RepairUnsupportedPieces(&out.model, &out.verification, points, normals, vo);
    if (repair.verified) {
      out.expression = "(" + out.expression + ")" + repair.expression;
      out.filled_cavities = repair.filled;
      out.removed_pieces = repair.removed;
    }
  }
  if (out.verification.verified && out.verification.components.solids > 1) {
    // a separator in an unconstrained gap may cut the solid apart (fit/reconstruct/
    // separator_bridging.h)
    SolidVerificationOptions quiet = vo;
    quiet.progress = {};
    ProgressStage bridge(options.progress, "bridging",
                         std::to_string(out.verification.components.solids) + " solid pieces");
    const SeparatorBridging b =
        BridgeSeparatedPieces(&out.model, &out.verification, points, normals, quiet);
    for (const auto& [from, to] : b.replaced)
      out.expression = RenameInExpression(out.expression, from, to);
    out.bridged_separators = b.Text();
    bridge.End(b.replaced.empty() ? "none" : out.bridged_separators);
  }
  ClaimVerification(out.verification, &out.model);
  out.bounded = out.verification.bounded;
  out.success = out.verification.verified;
  out.message = out.success ? "ok" : out.verification.message;
  for (int k = 0; k < K && k < static_cast<int>(options.as_blends.size()); ++k)
    if (options.as_blends[k]) out.sides[k] = "blend";
}

// The six steps in order (fit/reconstruct/solid_reconstruction.h); out.seconds only when all ran.
SolidReconstruction ReconstructOnce(const std::vector<Vec>& points,
                                    const std::vector<Vec>& input_normals,
                                    const std::vector<SolidPrimitive>& primitives,
                                    const SolidReconstructionOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ReconstructionRun run(points, input_normals, primitives, options);
  if (!run.CheckInput()) return run.out;
  run.Assign();
  run.Orient();
  if (!run.Separate()) return run.out;
  run.FindBlends();
  if (!run.Refit()) return run.out;
  run.EstimateBlends();
  run.Verify();
  run.out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run.out;
}

}  // namespace

std::vector<SolidPrimitive> FitLabelledPrimitives(const std::vector<Vec>& points,
                                                  const std::vector<Vec>& normals,
                                                  const std::vector<int>& labels,
                                                  const std::vector<NodeType>& kinds,
                                                  unsigned seed) {
  std::vector<SolidPrimitive> primitives;
  for (size_t k = 0; k < kinds.size(); ++k) {
    std::vector<Vec> pts, nrm;
    for (size_t i = 0; i < points.size(); ++i)
      if (labels[i] == static_cast<int>(k)) {
        pts.push_back(points[i]);
        nrm.push_back(normals[i]);
      }
    PrimitiveFitOptions options;
    options.kind = kinds[k];
    options.seed = seed;
    const PrimitiveFitResult fit = FitPrimitive(pts, nrm, options);
    if (!fit.success)
      throw std::runtime_error("primitive " + std::to_string(k) + ": " + fit.message);
    primitives.push_back({"p" + std::to_string(k), fit.ToModel(kinds[k]), fit.rms});
  }
  return primitives;
}

}  // namespace implicitfit
