#include "fit/splines/bspline_volume_fitter.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "fit/bernstein/patch_fitter.h"
#include "fit/bernstein/winding_number.h"
#include "model/bernstein/bernstein_conversion.h"
#include "model/dual3.h"

namespace implicitfit {
namespace {

using Vec = Eigen::Vector3d;

// The (k + 1)^3 coefficient indices and weights of one row f(x) (x inside the box).
struct TensorRow {
  int index[(SplineLimits::kMaxVolumeDegree + 1) * (SplineLimits::kMaxVolumeDegree + 1) *
            (SplineLimits::kMaxVolumeDegree + 1)];
  double weight[(SplineLimits::kMaxVolumeDegree + 1) * (SplineLimits::kMaxVolumeDegree + 1) *
                (SplineLimits::kMaxVolumeDegree + 1)];
  int terms = 0;
};

TensorRow RowAt(const SplineStructure& s, const Vec& x) {
  const int k = s.degree[0];
  double basis[3][kMaxSplineDegree + 1];
  int span[3];
  for (int a = 0; a < 3; ++a) {
    const double y = std::clamp(x[a], s.box[a], s.box[3 + a]);
    span[a] = FindSpan(k, s.count[a], s.knots[a].data(), y);
    BasisFunctions(span[a], y, k, s.knots[a].data(), basis[a]);
  }
  TensorRow row;
  for (int r = 0; r <= k; ++r)
    for (int q = 0; q <= k; ++q)
      for (int i = 0; i <= k; ++i) {
        row.index[row.terms] = (span[0] - k + i) +
                               s.count[0] * ((span[1] - k + q) + s.count[1] * (span[2] - k + r));
        row.weight[row.terms++] = basis[0][i] * basis[1][q] * basis[2][r];
      }
  return row;
}

// Normal equations H c = g in banded form: (a, b) with |i_a - i_b|, |j_a - j_b|, |l_a - l_b| <= k.
class VolumeNormalEquations {
 public:
  explicit VolumeNormalEquations(const SplineStructure& s)
      : n_{s.count[0], s.count[1], s.count[2]}, k_(s.degree[0]), side_(2 * k_ + 1),
        width_(side_ * side_ * side_) {
    size_ = n_[0] * n_[1] * n_[2];
    band_.assign(static_cast<size_t>(size_) * width_, 0.0);
    rhs_ = Eigen::VectorXd::Zero(size_);
  }
  void Clear() {
    std::fill(band_.begin(), band_.end(), 0.0);
    rhs_.setZero();
  }
  void AddRow(const int* index, const double* w, int terms, double target, double weight) {
    const double w2 = weight * weight;
    for (int s = 0; s < terms; ++s) {
      const int a = index[s];
      double* row = band_.data() + static_cast<size_t>(a) * width_;
      for (int t = 0; t < terms; ++t) row[Offset(a, index[t])] += w2 * w[s] * w[t];
      rhs_[a] += w2 * w[s] * target;
    }
  }
  // A row of RowAt: its terms form a (k+1)^3 tensor (i fastest), so the band offsets between
  // two terms follow from their local indices.
  void AddTensorRow(const TensorRow& row, double target, double weight) {
    const int e = k_ + 1;
    if (local_.empty()) {
      for (int r = 0; r < e; ++r)
        for (int q = 0; q < e; ++q)
          for (int i = 0; i < e; ++i) local_.push_back(i + side_ * (q + side_ * r));
    }
    const int centre = width_ / 2;
    const double w2 = weight * weight;
    for (int s = 0; s < row.terms; ++s) {
      const double ws = w2 * row.weight[s];
      if (ws == 0.0) continue;
      double* band = band_.data() + static_cast<size_t>(row.index[s]) * width_ + centre - local_[s];
      for (int t = 0; t < row.terms; ++t) band[local_[t]] += ws * row.weight[t];
      rhs_[row.index[s]] += ws * target;
    }
  }
  // Solves (H + ridge I) c = g; the pattern (every band entry) is analysed once.
  bool Solve(Eigen::VectorXd* c) {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(band_.size());
    double trace = 0.0;
    for (int a = 0; a < size_; ++a) trace += band_[static_cast<size_t>(a) * width_ + width_ / 2];
    const double ridge = 1e-12 * trace / size_ + 1e-300;
    for (int a = 0; a < size_; ++a) {
      const int ia = a % n_[0], ja = (a / n_[0]) % n_[1], la = a / (n_[0] * n_[1]);
      for (int o = 0; o < width_; ++o) {
        const int di = o % side_ - k_, dj = (o / side_) % side_ - k_, dl = o / (side_ * side_) - k_;
        const int ib = ia + di, jb = ja + dj, lb = la + dl;
        if (ib < 0 || jb < 0 || lb < 0 || ib >= n_[0] || jb >= n_[1] || lb >= n_[2]) continue;
        const double v = band_[static_cast<size_t>(a) * width_ + o] + (o == width_ / 2 ? ridge : 0);
        entries.emplace_back(a, ib + n_[0] * (jb + n_[1] * lb), v);
      }
    }
    Eigen::SparseMatrix<double> h(size_, size_);
    h.setFromTriplets(entries.begin(), entries.end());
    if (!analysed_) {
      ldlt_.analyzePattern(h);
      analysed_ = true;
    }
    ldlt_.factorize(h);
    if (ldlt_.info() != Eigen::Success) return false;
    *c = ldlt_.solve(rhs_);
    return c->allFinite();
  }

 private:
  int Offset(int a, int b) const {  // the 3-D difference of two indices, as a band slot
    const int ia = a % n_[0], ja = (a / n_[0]) % n_[1], la = a / (n_[0] * n_[1]);
    const int ib = b % n_[0], jb = (b / n_[0]) % n_[1], lb = b / (n_[0] * n_[1]);
    return (ib - ia + k_) + side_ * ((jb - ja + k_) + side_ * (lb - la + k_));
  }
  int n_[3], k_, side_, width_, size_ = 0;
  std::vector<int> local_;  // band slot of each tensor term relative to the first
  std::vector<double> band_;
  Eigen::VectorXd rhs_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  bool analysed_ = false;
};

// Second differences along each axis (weight 1) and mixed differences (weight sqrt 2).
template <typename Visit>
void SmoothingRows(const SplineStructure& s, const Visit& visit) {
  const int nx = s.count[0], ny = s.count[1], nz = s.count[2];
  auto id = [&](int i, int j, int l) { return i + nx * (j + ny * l); };
  const int e[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int l = 0; l < nz; ++l)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (int a = 0; a < 3; ++a) {
          const int* u = e[a];
          if (i + 2 * u[0] < nx && j + 2 * u[1] < ny && l + 2 * u[2] < nz) {
            const int idx[3] = {id(i, j, l), id(i + u[0], j + u[1], l + u[2]),
                                id(i + 2 * u[0], j + 2 * u[1], l + 2 * u[2])};
            const double w[3] = {1.0, -2.0, 1.0};
            visit(idx, w, 3);
          }
          const int* v = e[(a + 1) % 3];
          if (i + u[0] + v[0] < nx && j + u[1] + v[1] < ny && l + u[2] + v[2] < nz) {
            const int idx[4] = {id(i, j, l), id(i + u[0], j + u[1], l + u[2]),
                                id(i + v[0], j + v[1], l + v[2]),
                                id(i + u[0] + v[0], j + u[1] + v[1], l + u[2] + v[2])};
            const double r = std::sqrt(2.0);
            const double w[4] = {r, -r, -r, r};
            visit(idx, w, 4);
          }
        }
}

SplineStructure VolumeForCloud(const std::vector<Vec>& points, const VolumeFitOptions& o) {
  Vec lo = points[0], hi = points[0];
  for (const Vec& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec extent = hi - lo;
  const double longest = std::max(extent.maxCoeff(), 1e-12);
  const double margin_longest = o.convex ? 0.05 : o.box_margin;
  Vec grown;
  for (int a = 0; a < 3; ++a)
    grown[a] = extent[a] + 2 * std::max({0.05 * extent[a], margin_longest * longest, 0.05 * longest});
  const double h = grown.maxCoeff() / o.cells;
  double box[6];
  int cells[3];
  for (int a = 0; a < 3; ++a) {
    cells[a] = std::max(1, static_cast<int>(std::ceil(grown[a] / h - 1e-9)));
    const double centre = 0.5 * (lo[a] + hi[a]);
    box[a] = centre - 0.5 * cells[a] * h;
    box[3 + a] = centre + 0.5 * cells[a] * h;
  }
  return BSplineVolumeStructure(o.degree, box, cells);
}

// f and grad f at x.
double ValueAndGradient(const SplineStructure& s, const Eigen::VectorXd& c, const Vec& x, Vec* g) {
  static thread_local std::vector<Dual3> cd;
  cd.assign(c.data(), c.data() + c.size());
  const Dual3 xd[3] = {Dual3(x[0], Vec::UnitX()), Dual3(x[1], Vec::UnitY()),
                       Dual3(x[2], Vec::UnitZ())};
  const Dual3 f = BSplineVolumeEvaluator::Evaluate(s, cd.data(), xd);
  *g = f.v;
  return f.a;
}

double Rms(const SplineStructure& s, const Eigen::VectorXd& c, const std::vector<Vec>& points) {
  double sum = 0.0;
  for (const Vec& p : points) {
    Vec g;
    const double f = ValueAndGradient(s, c, p, &g);
    const double r = f / std::max(g.norm(), 1e-300);
    sum += r * r;
  }
  return std::sqrt(sum / points.size());
}

struct FarRow {
  Vec x;
  double target, weight;
};

// Step 1's far-field rows (header).
std::vector<FarRow> FarFieldRows(const SplineStructure& s, const std::vector<Vec>& points,
                                 const std::vector<Vec>& normals, double band) {
  std::vector<Vec> sample;  // at most 5000 points for the nearest-point search
  const size_t stride = (points.size() + 4999) / 5000;
  for (size_t i = 0; i < points.size(); i += stride) sample.push_back(points[i]);
  const WindingNumber winding(points, normals);
  const double h = (s.box[3] - s.box[0]) / s.cells[0];
  const int m[3] = {2 * s.cells[0], 2 * s.cells[1], 2 * s.cells[2]};
  std::vector<FarRow> rows;
  for (int l = 0; l <= m[2]; ++l)
    for (int j = 0; j <= m[1]; ++j)
      for (int i = 0; i <= m[0]; ++i) {
        const Vec x(s.box[0] + 0.5 * h * i, s.box[1] + 0.5 * h * j, s.box[2] + 0.5 * h * l);
        double best = std::numeric_limits<double>::infinity();
        for (const Vec& p : sample) best = std::min(best, (p - x).squaredNorm());
        const double distance = std::sqrt(best);
        if (distance <= band) continue;
        const bool on_box = i == 0 || j == 0 || l == 0 || i == m[0] || j == m[1] || l == m[2];
        const bool inside = !on_box && winding(x) > 0.5;
        rows.push_back({x, inside ? -distance : distance, on_box ? 1.0 : std::min(1.0, distance / h)});
      }
  return rows;
}

// One linear solve: data rows (weights 1 / g_i when gradients are given), offset rows, far rows,
// smoothing.
bool SolveRows(const SplineStructure& s, const std::vector<Vec>& points,
               const std::vector<Vec>& normals, const std::vector<double>* inverse_gradients,
               double d, double offset_weight, const std::vector<FarRow>& far, double far_weight,
               double lambda, VolumeNormalEquations* eq, Eigen::VectorXd* c) {
  eq->Clear();
  for (size_t i = 0; i < points.size(); ++i) {
    eq->AddTensorRow(RowAt(s, points[i]), 0.0, inverse_gradients ? (*inverse_gradients)[i] : 1.0);
    if (normals.empty()) continue;
    for (double side : {-1.0, 1.0})
      eq->AddTensorRow(RowAt(s, points[i] + side * d * normals[i]), side * d, offset_weight);
  }
  for (const FarRow& r : far) eq->AddTensorRow(RowAt(s, r.x), r.target, far_weight * r.weight);
  const double root = std::sqrt(lambda);
  SmoothingRows(s, [&](const int* idx, const double* w, int terms) {
    eq->AddRow(idx, w, terms, 0.0, root);
  });
  return eq->Solve(c);
}

// Coefficients of the quadric q on the volume: interpolation at the Greville points, one axis
// at a time (q lies in the spline space for degree >= 2, so this reproduces it).
Eigen::VectorXd QuadricCoefficients(const SplineStructure& s, const CartesianQuadric& q) {
  std::vector<double> g[3];
  Eigen::PartialPivLU<Eigen::MatrixXd> lu[3];
  for (int a = 0; a < 3; ++a) {
    g[a] = GrevilleAbscissae(s.knots[a], s.degree[a], s.count[a]);
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(s.count[a], s.count[a]);
    for (int r = 0; r < s.count[a]; ++r) {
      const int span = FindSpan(s.degree[a], s.count[a], s.knots[a].data(), g[a][r]);
      double N[kMaxSplineDegree + 1];
      BasisFunctions(span, g[a][r], s.degree[a], s.knots[a].data(), N);
      for (int j = 0; j <= s.degree[a]; ++j) m(r, span - s.degree[a] + j) = N[j];
    }
    lu[a].compute(m);
  }
  const int n[3] = {s.count[0], s.count[1], s.count[2]};
  Eigen::VectorXd c(n[0] * n[1] * n[2]);
  for (int l = 0; l < n[2]; ++l)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) c[i + n[0] * (j + n[1] * l)] = q(Vec(g[0][i], g[1][j], g[2][l]));
  for (int a = 0; a < 3; ++a) {  // solve along axis a for every line
    const int b = (a + 1) % 3, e = (a + 2) % 3;
    int idx[3];
    for (idx[b] = 0; idx[b] < n[b]; ++idx[b])
      for (idx[e] = 0; idx[e] < n[e]; ++idx[e]) {
        Eigen::VectorXd line(n[a]);
        for (idx[a] = 0; idx[a] < n[a]; ++idx[a]) line[idx[a]] = c[idx[0] + n[0] * (idx[1] + n[1] * idx[2])];
        const Eigen::VectorXd solved = lu[a].solve(line);
        for (idx[a] = 0; idx[a] < n[a]; ++idx[a]) c[idx[0] + n[0] * (idx[1] + n[1] * idx[2])] = solved[idx[a]];
      }
  }
  return c;
}

}  // namespace

bool VolumeFitOptions::IsValid(std::string* error) const {
  if (degree < (convex ? 2 : 1) || degree > SplineLimits::kMaxVolumeDegree) {
    *error = std::string("the degree must be in ") + (convex ? "2" : "1") + ".." +
             std::to_string(SplineLimits::kMaxVolumeDegree) +
             (convex ? " (a convexity certificate needs C1)" : "");
    return false;
  }
  if (cells < 1 || cells > SplineLimits::kMaxVolumeCells) {
    *error = "cells must be in 1.." + std::to_string(SplineLimits::kMaxVolumeCells);
    return false;
  }
  if (!(smoothing >= 0) || !(far_field_weight >= 0) || !(box_margin >= 0) || max_iterations < 0 ||
      !std::isfinite(smoothing + far_field_weight + box_margin)) {
    *error = "invalid smoothing, far-field weight, margin or iterations";
    return false;
  }
  return true;
}

Model VolumeFitResult::ToModel() const {
  Model m;
  m.AddBSplineVolume(structure.degree[0], structure.box, structure.cells, coefficients);
  return m;
}

VolumeFitResult FitBSplineVolume(const std::vector<Vec>& points, const std::vector<Vec>& normals,
                                 const VolumeFitOptions& o) {
  const auto start_time = std::chrono::steady_clock::now();
  VolumeFitResult r;
  r.points = points.size();
  auto fail = [&](const std::string& message) {
    r.success = false;
    r.message = message;
    r.termination = FitTermination::kFailure;
    return r;
  };
  std::string error;
  if (!o.IsValid(&error)) return fail(error);
  if (points.size() < 10) return fail("at least 10 points are needed");
  if (normals.size() != points.size()) return fail("one normal per point is needed");
  const SplineStructure s = VolumeForCloud(points, o);
  r.structure = s;
  const long long unknowns = static_cast<long long>(s.count[0]) * s.count[1] * s.count[2];
  if (unknowns > SplineLimits::kMaxVolumeCoefficients) return fail("too many coefficients");
  Vec lo = points[0], hi = points[0];
  for (const Vec& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double d = 0.01 * (hi - lo).norm();
  const double rows_per_coefficient = 3.0 * points.size() / unknowns;
  const double lambda = o.smoothing * std::max(1.0, rows_per_coefficient);
  VolumeNormalEquations eq(s);

  // The refinement (step 2) from c, with step control `accept` (the convex guard) or plain.
  auto refine = [&](Eigen::VectorXd c, const std::vector<FarRow>& far, bool guarded,
                    double margin, int* iterations) {
    double best = Rms(s, c, points);
    for (int it = 0; it < o.max_iterations; ++it) {
      std::vector<double> inverse(points.size());
      for (size_t i = 0; i < points.size(); ++i) {
        Vec g;
        ValueAndGradient(s, c, points[i], &g);
        inverse[i] = 1.0 / std::max(g.norm(), 1e-12);
      }
      Eigen::VectorXd next;
      if (!SolveRows(s, points, normals, &inverse, d, 0.1, far, o.far_field_weight, lambda, &eq,
                     &next))
        break;
      bool taken = false;
      for (double alpha = 1.0; alpha >= 1.0 / 64; alpha *= 0.5) {
        const Eigen::VectorXd trial = c + alpha * (next - c);
        if (guarded && !CertifyVolumeConvexity(s, trial.data(), margin).convex) continue;
        const double rms = Rms(s, trial, points);
        if (rms < best) {
          const bool small = rms > 0.995 * best;
          c = trial;
          best = rms;
          taken = !small;
          ++*iterations;
          break;
        }
        if (!guarded) break;
      }
      if (!taken) break;
    }
    return c;
  };

  if (!o.convex) {
    const std::vector<FarRow> far =
        o.far_field_weight > 0 ? FarFieldRows(s, points, normals, 2 * d) : std::vector<FarRow>{};
    Eigen::VectorXd c;
    if (!SolveRows(s, points, normals, nullptr, d, 1.0, far, o.far_field_weight, lambda, &eq, &c))
      return fail("the linear start failed (singular system)");
    r.initial_rms = Rms(s, c, points);
    c = refine(c, far, false, 0.0, &r.iterations);
    r.coefficients.assign(c.data(), c.data() + c.size());
    r.rms = Rms(s, c, points);
  } else {
    PatchFitOptions po;
    po.degree = 2;
    po.convex = true;
    const PatchFitResult quadric = FitBernsteinPatch(points, normals, po);
    if (!quadric.success || !quadric.certified_convex)
      return fail("no certified convex quadric start: " + quadric.message);
    const CartesianQuadric q =
        BernsteinToQuadric(quadric.control_points.data(), quadric.tetrahedron);
    Eigen::VectorXd c = QuadricCoefficients(s, q);
    const VolumeConvexityCertificate start = CertifyVolumeConvexity(s, c.data());
    if (!start.convex) return fail("the convex quadric start is not certified on the box");
    r.initial_rms = Rms(s, c, points);
    const double margin = 1e-6 * start.min_eigenvalue;
    c = refine(c, {}, true, margin, &r.iterations);
    r.coefficients.assign(c.data(), c.data() + c.size());
    r.rms = Rms(s, c, points);
    r.certificate = CertifyVolumeConvexity(s, c.data());
    r.certified_convex = r.certificate.convex;
    if (!r.certified_convex) return fail("the result is not certified convex");
    VolumeFitOptions plain = o;
    plain.convex = false;
    plain.box_margin = 0.05;
    r.unconstrained_rms = FitBSplineVolume(points, normals, plain).rms;
  }
  double angle = 0.0;
  const Eigen::VectorXd c = Eigen::Map<const Eigen::VectorXd>(r.coefficients.data(), r.coefficients.size());
  for (size_t i = 0; i < points.size(); ++i) {
    Vec g;
    ValueAndGradient(s, c, points[i], &g);
    angle += std::acos(std::clamp(g.normalized().dot(normals[i]), -1.0, 1.0)) * 180.0 / M_PI;
  }
  r.mean_normal_angle_deg = angle / points.size();
  if (!std::isfinite(r.rms)) return fail("the fit diverged");
  r.success = true;
  r.termination = FitTermination::kConverged;
  r.message = "converged";
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return r;
}

}  // namespace implicitfit
