// Convexity of a Bernstein mesh on its whole box (docs/maths.md G-1), and an independent sampling
// test of it.
//
// Theorem (standard convex analysis). If f is C1 on the box (a convex domain, the union of the
// mesh's tetrahedra) and convex on every tetrahedron (every A^mu positive definite: the
// single-patch certificate, model/certificates/convexity_certificate.h), then f is convex on the box and
// {f <= 0} within the box is convex: along any segment the restriction is C1 with a
// nondecreasing derivative on each piece, continuous at the breaks, hence nondecreasing.
// With only C0 it fails (a concave kink at a face).
//
// The certificate therefore reports, per tetrahedron, the single-patch certificate; the
// largest C1 defect max |C b| / max |b| over the C0 and C1 rows of every interior face
// (model/bernstein/bernstein_mesh_continuity.h), whatever continuity the node declares; the domain
// convexity (always true for a box grid); and the verdict convex_on_box only when every
// tetrahedron is certified AND the C1 defect is at most kMaxContinuityDefect (rounding of an
// exact projection).
//
// Sampling test (a second opinion, Guo's definition on the zero set): random segments between
// uniform points of the box (crossing tetrahedra), sign changes of f bisected to zero points p,
// then every zero point q must satisfy (q - p) . grad f(p)/|grad f(p)| <= tolerance * diagonal.
#pragma once

#include <cstdint>
#include <vector>

#include "model/bernstein/bernstein_mesh.h"
#include "model/certificates/convexity_certificate.h"

namespace implicitfit {

// Largest C1 defect that still counts as C1 (relative to max |b|).
constexpr double kMaxContinuityDefect = 1e-9;

struct MeshConvexityCertificate {
  long long tetrahedra = 0;
  long long certified_tetrahedra = 0;
  double min_eigenvalue = 0.0;       // smallest A^mu eigenvalue over all tetrahedra
  long long worst_tetrahedron = -1;  // where it is attained
  double c1_defect = 0.0;            // max |C b| / max |b|, C0 + C1 rows
  bool c1 = false;                   // c1_defect <= kMaxContinuityDefect
  bool domain_convex = true;         // a box grid is convex
  bool convex_on_box = false;        // all of the above
  std::vector<ConvexityCertificate> per_tetrahedron;
};

MeshConvexityCertificate CertifyMeshConvexity(int k, const BernsteinGrid& grid, const double* b);

struct MeshSamplingOptions {
  int segments = 10000;
  int steps = 32;
  double tolerance = 1e-8;  // relative to the box diagonal
  std::uint64_t seed = 1;
};

struct MeshSamplingResult {
  int zero_points = 0;
  int violations = 0;
  double worst_excursion = 0.0;  // largest (q - p) . n / diagonal
};

MeshSamplingResult MeshTangentPlaneTest(int k, const BernsteinGrid& grid, const double* b,
                                        const MeshSamplingOptions& options = {});

}  // namespace implicitfit
