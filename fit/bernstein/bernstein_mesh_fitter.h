// Fitting a Bernstein mesh (model/bernstein/bernstein_mesh.h) to an oriented cloud: the patch-mesh fit of
// docs/maths.md G-1 (fit --model patch-mesh).
//
// Grid. The cloud's bounding box grown on every side by the larger of 5% of its extent and
// box_margin (10%) of the longest extent (5% only with --convex; at least 5% of the longest
// extent on a flat axis); cube edge h = --cell, or (--cells n) the longest grown extent / n;
// n_a = ceil(extent_a / h) cubes per axis, centred on the box. The margin keeps the box faces
// beyond the far-field band, so that the box-face rows below can close the zero set.
// 1. Linear initialisation, one sparse least-squares problem: f(p_i) = 0 and
//    f(p_i +- d n_i) = +-d (d = 1% of the box diagonal), linear in the control points, plus the
//    far-field rows: at the points of a lattice of spacing h/2 farther than 2d from every input
//    point, f(x) = (x - p) . n_p with p the nearest input point (Hoppe's signed tangent-plane
//    distance, weight far_field_weight), so that f keeps the sign of the nearest data away from
//    the surface and no spurious sheet crosses empty space; on the box faces the target is
//    +|x - p| (outside), so that f > 0 on the whole box boundary and the zero set is a closed
//    surface inside the box: an open scan (oni's unscanned base) is capped smoothly instead of
//    leaving the box, where a mesher would cut it open (box_sign_errors counts the box-face
//    samples where f <= 0 after the fit; 0 on every benchmark cloud); so is it at lattice points
//    beside the data (direction from p more than 60 degrees off n_p: beyond an open rim, where
//    the tangent-plane sign means nothing), so that such a cap closes near the rim. By default
//    (far_field_winding) the inside/outside sign of every row off the box comes from the
//    cloud's generalised winding number w instead (fit/bernstein/winding_number.h: inside where w > 1/2;
//    its level 1/2 spans an open rim, flat for a planar one), and the target's magnitude is at
//    most |w - 1/2| / |grad w|, the first-order distance to that level, so the targets form one
//    signed distance across the cap (oni, degree 5: Chamfer 0.0149 -> 0.0132, PCL Poisson 0.0136;
//    a sphere scanned above z = -0.3: cap 0.2 below the rim -> 0.065). The weight of a
//    far-field row (not on the box) grows linearly with its distance to the data up to one cube
//    edge (far_field_ramp, in cubes), so that near the data, where the tangent-plane targets of a
//    curved surface disagree with each other, the data rows decide the shape and the far-field
//    rows only keep the signs (kitten, degree 5: RMS 0.00111 -> 0.00083, Chamfer
//    0.00387 -> 0.00372). Solved on the
//    global domain points (b = P w: C0 exact, model/bernstein/bernstein_mesh_continuity.h) with the C1
//    rows as weighted equations (weight continuity_weight) and soft C2 rows (smoothing_weight)
//    on the faces of tetrahedra that hold no point, so holes close smoothly, by sparse Cholesky
//    (CHOLMOD) of the normal equations; then the exact projection onto ker C. The refinement's
//    systems reuse the last factor as a preconditioner of conjugate gradients
//    (fit/bernstein/reused_cholesky.h).
// 2. Refinement (unconstrained): Gauss-Newton on r_i = f(p_i)/|grad f(p_i)| with |grad f|
//    frozen at the current iterate, i.e. iteratively reweighted linear least squares in the
//    same domain-point unknowns as step 1: rows c_i f(p_i)/g_i (c_i the Cauchy weight at 3x the
//    current RMS), w_n (grad f(p_i)/g_i - n_i) with w_n = normal_weight x diagonal / 10 (x
//    sharp_normal_factor in crease leaves when normals_estimated), the
//    offset rows of step 1 with weight 0.1 (they fix the scale of f, which r_i leaves free) and
//    the far-field rows; until the RMS improves by less than 0.5% (at most max_iterations);
//    the best iterate is kept, so the result is never worse than the start (and an iterate with
//    more far-field sign errors than the start, a spurious sheet, is never kept). When these steps
//    make no progress (< 0.5%; on grids of at most 1 500 tetrahedra), the Ceres refinement of step
//    3 without the guard runs from the result and is kept when better after the projection. Then
//    the exact projection onto the continuity space (fit/bernstein/continuity_projection.h). Why not Ceres
//    here (as the first version did, one parameter block per tetrahedron): with the continuity rows
//    as stiff penalties (weight 1e4) Levenberg-Marquardt did not converge in 100 iterations on
//    kitten (216 patches: 30 s) and its iterate used the slack of the penalty (continuity
//    defect 2.8e-5): RMS 0.0026 before the projection, 0.092 after it, so the start (0.0199) was
//    kept. Each linearised step is solved exactly instead (defect ~1e-6, which the projection
//    removes without changing the RMS): kitten 0.0199 -> 0.0094 in 4.5 s.
//    Far-field relaxation (issue 11). The far-field rows' targets (tangent-plane distances) are
//    not a function the spline can match near a curved surface (the signed distance has a
//    ridge on the medial axis: a torus tube's core circle, a sphere's centre), so at full weight
//    they hold the zero set off the data: on the noise-free torus of bench/surface_comparison
//    the fit stopped at RMS 1.9e-3 (truth distance 1.47e-3, as with noise: 1.57e-3), while the
//    space reaches 6.9e-4 (Ceres without far-field rows). So when the iteration stalls, the
//    far-field rows' weight is multiplied by far_field_relaxation (0.3) and the iteration goes on
//    from the best iterate, down to far_field_floor (0.005) x far_field_weight, for as long as
//    each stage improves the RMS; the rows only keep the signs there. In these relaxed stages
//    the rows are the exact Gauss-Newton linearisation of f/|grad f| and of the normal residual
//    (not the frozen-gradient rows, whose steps do not descend once the far-field rows no
//    longer hold |grad f|): J b = -r_i with J = B(p)/g - (f/g^3) g . grad B(p) (r is
//    homogeneous of degree 0 in b, so J b_current = 0). A relaxed step is admissible only if it
//    also changes nothing of f away from the data (fit/bernstein/empty_space_sign_guard.h: signs and
//    clearance at a lattice of spacing h / sign_guard_samples farther than 2d from the data, so
//    no new blob or sheet grows where the far-field rows are lighter); a stage without an
//    admissible improving step ends the relaxation. Noisy torus (20 000 points, sigma 0.005):
//    RMS distance to the truth 0.39 sigma -> 0.17 sigma (the least-squares floor
//    sigma sqrt(p/N) is 0.13 sigma; tests/fit/bernstein/bernstein_mesh_relaxation_test.cc).
// 3. --convex (C1 only; Ceres, one parameter block per tetrahedron, Cauchy loss at 3x the
//    step-1 RMS, the continuity rows as penalties (weight continuity_weight) and the offset rows
//    with weight 0.1; docs/maths.md G-1 theorem: C1 + every patch certified on a convex box =>
//    f convex on the box): start from the certified convex degree-2 patch fit
//    (fit/bernstein/patch_fitter.h) on the enclosing tetrahedron, restricted to every tetrahedron and
//    elevated to degree k (a global quadric: C-infinity, certified on every tetrahedron), so
//    the start is feasible; a guard rejects every step after which some tetrahedron's
//    smallest A^mu eigenvalue falls below the margin; after the projection every tetrahedron
//    is re-certified and the continuity defect checked. Failure => success = false. The
//    unconstrained fit (step 2) is also run, for its RMS (unconstrained_rms: the price of
//    convexity; it costs a fraction of the guarded refinement).
// Soft C1 (continuity 0). A C1 cubic spline on the Kuhn split is a small space (34 unknowns on
// one cube against 64 for C0) and rounds a crease over about a cube; a bare C0 spline follows
// the data but its free domain points between the far-field lattice's rows grow blobs in empty
// space (chamfered block, 8 cubes: Chamfer 0.060, 560 open edges). With continuity 0 the C1
// rows b'_{lambda + e5} - sum_{|nu| = 1} b_{lambda + nu} B^1_nu(alpha) of every face (sharp
// faces at soft_c1_sharp_factor of it) enter the same least squares as penalties of weight
// soft_c1_weight, so f is as smooth as the data allow and may kink where they demand; no
// projection (the file declares C0).
// Measured (bench/surface_comparison, 8 cubes, degree 3; docs/patch-mesh.md): chamfered block
// 0.00616 (C1) -> 0.00190, bracket 0.01216 -> 0.00246, kitten 0.00600 -> 0.00473; weights 0.1,
// 0.3, 1, 3 gave 0.00172 (a Hausdorff 0.127 blob), 0.00188 (0.130), 0.00190 (0.026), 0.00314.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "fit/bernstein/far_field_rows.h"
#include "fit/common/progress.h"
#include "model/bernstein/bernstein_mesh.h"
#include "model/model.h"

namespace implicitfit {

struct MeshFitOptions {
  int degree = 3;         // 2..5 (C1 wants >= 3: C1 quadratics are nearly global)
  int cells = 0;          // cubes along the longest box edge (used when cell == 0)
  double cell = 0.0;      // cube edge h; 0: from cells (default 8 cubes, 4 with --convex)
  bool has_grid = false;  // use `grid` as given instead of the cloud's box
  BernsteinGrid grid;
  int continuity = 1;                 // 0 or 1
  bool convex = false;                // enforce and certify convexity on the whole box (C1 only)
  double normal_weight = 0.1;         // w of the normal residuals
  int max_iterations = 100;           // Ceres iterations
  double continuity_weight = 1e4;     // weight of the continuity rows before the projection
  double smoothing_weight = 0.1;      // weight of the C2 rows on faces of empty tetrahedra
  // Continuity 0: the C1 rows of every face as penalties of this weight (header, "Soft C1");
  // 0: none (a bare C0 fit, which grows blobs in empty space).
  double soft_c1_weight = 1.0;
  // The sharp faces' C1 rows (adaptive fits: the crease leaves) with soft_c1_weight x this: a
  // crease may bend more, but not freely (0, as C1 fits do: blobs at the creases; chamfered
  // block, two levels: Chamfer 0.01672; 0.1: 0.00149; 0.3: 0.00148; every face 1: 0.00156).
  double soft_c1_sharp_factor = 0.3;
  // Whether the normals were estimated from the points (PCA, datasets/normals) rather than
  // given (a scanner's, a CAD sampler's). Estimated normals near a crease are a blend of the
  // two faces' (the neighbourhood straddles it), so at the full weight their rows round the
  // crease and bend the faces beside it: with normals_estimated, the normal rows (step 2) of
  // the points in a tetrahedron with a sharp face (a crease leaf of the adaptive fit) get
  // normal_weight x sharp_normal_factor. Given normals keep the full weight: there they are
  // right, and lighter rows lose (tests/fit/bernstein/soft_c1_mesh_test.cc, chamfered block,
  // 3 000 points, one level on 4 cubes: RMS distance to the model, estimated normals
  // 0.00701 full, 0.00596 lighter; true normals 0.00394 full, 0.00505 lighter;
  // bench/RESULTS.md, "Normal rows lighter at the creases").
  bool normals_estimated = false;
  double sharp_normal_factor = 0.3;
  double far_field_weight = 1.0;      // weight of the far-field rows (header, step 1); 0: none
  double far_field_beside_cos = 0.5;  // far-field points beside the data are outside (.cc)
  double far_field_ramp = 1.0;        // > 0: row weight min(1, (distance / (ramp h))^power)
  double far_field_ramp_power = 1.0;
  bool far_field_winding = true;  // far-field signs from the winding number (header, step 1);
                                  // false: the nearest point's tangent plane and "beside"
  double box_margin = 0.1;        // grid box: cloud box + max(5%, box_margin x longest) per side
                                  // (not with --convex, which keeps 5%)
  // Step 2 (header): in the relaxed stages, Gauss-Newton rows from the exact linearisation of
  // f/|grad f| and of the normal residual (false: the frozen-gradient rows there too).
  bool exact_linearisation = true;
  // Step 2: when the refinement stalls, the far-field rows' weight is multiplied by
  // far_field_relaxation (0 or 1: never), down to far_field_floor x far_field_weight, while the
  // stages improve and keep every sign away from the data (sign_guard_samples per cube edge).
  double far_field_relaxation = 0.3;
  double far_field_floor = 0.005;
  int sign_guard_samples = 8;
  // Adaptive refinement (fit/bernstein/adaptive_mesh_fitter.h): rounds of fit, then split the
  // leaves whose points' RMS residual exceeds refine_factor x the noise level (the cloud's noise,
  // estimated when noise = 0, floored at refine_spacing_floor x its spacing), down to leaves of
  // at least min_leaf_spacings spacings, at most max_levels below the base grid, while the C0
  // unknowns stay within max_unknowns; sharp features: C0 only across the faces of leaves whose
  // data normals spread by more than feature_angle_deg (dihedral angle of a crease).
  bool adaptive = false;
  double noise = 0.0;
  // (1: refine until the residuals are at the noise, as the budget allows; 2 before, with 11 of
  // the 24 benchmark clouds at or below Poisson against 15 at 1: bench/RESULTS.md, "Leaves
  // refined down to the noise".)
  double refine_factor = 1.0;
  double refine_spacing_floor = 0.05;
  double min_leaf_spacings = 2.0;
  int max_levels = 3;
  // The budget, set when 1 000 unknowns cost about 1 CPU second with ATLAS (bunny 74 359: 87 s;
  // kitten 37 813: 44 s; OpenBLAS takes 0.5-0.8x that), so a 20 000-point part stays near a
  // minute (Fit4CAD PC35, noise-free, split nearly every leaf: one level 35 158 unknowns in 63 s,
  // two levels ran over 30 minutes at 400 000).
  long long max_unknowns = 60000;
  bool sharp_features = true;
  double feature_angle_deg = 40.0;
  // A refined round that grows surface away from the data (fit/bernstein/adaptive_mesh_fitter.h)
  // is fitted again with f pinned near the growth (from the second retry on, also with the
  // leaves near it left whole), up to this many times (on Fit4CAD PC131 a second retry changed
  // nothing: its first retry changed no sign, and the first such try is kept).
  int round_retries = 1;
  // Progress (fit/common/progress.h): stage "patch-mesh fit" per fit (its size at the start, the
  // RMS at the end); an adaptive fit also reports each refined try's fate as a "refinement"
  // update. Empty: nothing reported.
  ProgressCallback progress;
  bool IsValid(std::string* error) const;
};

struct MeshFitResult {
  bool success = false;
  std::string message;
  int degree = 0;
  int continuity = 0;
  BernsteinGrid grid;
  std::vector<double> control_points;  // all tetrahedra, model/bernstein/bernstein_mesh.h layout
  double rms = 0.0;                    // RMS of f/|grad f| over all points
  double initial_rms = 0.0;            // after the linear initialisation
  double unconstrained_rms = -1;       // --convex: RMS of the unconstrained fit (step 2), else -1
  double mean_normal_angle_deg = -1;   // mean angle between grad f and the normals
  double continuity_defect = 0.0;      // max |C b| / max |b| after the projection
  long long box_sign_errors = 0;  // far-field samples on the box faces with f <= 0 (0: the zero
                                  // set closes inside the box; -1 when no far-field rows)
  bool certified_convex = false;  // every tetrahedron certified (and, C1, defect tiny)
  int certified_tetrahedra = 0;
  double min_eigenvalue = 0.0;  // smallest A^mu eigenvalue over all tetrahedra
  long long tetrahedra = 0;
  int iterations = 0;
  bool kept_initialisation = false;  // the refinement did not improve: the initialisation is kept
  double seconds = 0.0;
  double far_weight = 1.0;  // the far-field rows' weight at the end (relaxation, step 2)
  // Adaptive refinement (options.adaptive): the scales read from the cloud, and what was built.
  double noise = 0.0, spacing = 0.0, residual_threshold = 0.0;
  int rounds = 0, levels = 0;
  long long leaves = 0, unknowns = 0, sharp_faces = 0;
  int rejected_rounds = 0;  // refined fits not kept (no lower RMS, or surface grown off the data)
  Model ToModel() const;
};

MeshFitResult FitBernsteinMesh(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<Eigen::Vector3d>& normals,
                               const MeshFitOptions& options);

// One fit on a given grid (steps 1-3); `start` (when not null: control points on `grid` and the
// far-field weight reached so far) replaces the linear initialisation of step 1. No validation
// (FitBernsteinMesh's), no seconds.
struct MeshFitStart {
  std::vector<double> control_points;
  double far_weight = 1.0;
  // Pinned empty-space rows: value rows at points away from the data, at the far-field weight
  // the fit started from (options.far_field_weight) through every relaxed stage, and no step
  // may add sign errors at them (the adaptive fit pins f where a refined try grew surface off
  // the data, fit/bernstein/adaptive_mesh_fitter.h).
  std::vector<FarFieldRow> pins;
};
MeshFitResult FitBernsteinMeshOnGrid(const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<Eigen::Vector3d>& normals,
                                     const MeshFitOptions& options, const BernsteinGrid& grid,
                                     const MeshFitStart* start);

// The grid the fitter uses for a cloud (see the header comment).
BernsteinGrid MeshGridForCloud(const std::vector<Eigen::Vector3d>& points, int cells, double cell,
                               double margin = 0.0);
// The grid FitBernsteinMesh uses with these options.
BernsteinGrid MeshFitGrid(const std::vector<Eigen::Vector3d>& points, const MeshFitOptions& options);

// Limit of the fit (docs/patch-mesh.md): prod_a (k cells_a + 1) distinct control points at most
// (measured, degree 3 on 2000 points: 10^3 cubes 35 s and 1.3 GB, 12^3 cubes 109 s and
// 2.8 GB, 16^3 over 2 min; 24^3 exhausted CHOLMOD). FitBernsteinMesh refuses larger grids with
// MeshFitSizeProblem's message.
constexpr double kMaxMeshFitControlPoints = 32768;
double MeshFitControlPoints(const BernsteinGrid& grid, int degree);
std::string MeshFitSizeProblem(const BernsteinGrid& grid, int degree);

}  // namespace implicitfit
