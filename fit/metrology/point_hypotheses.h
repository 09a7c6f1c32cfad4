// Primitive hypotheses from points alone, for clouds without trustworthy normals (a
// coordinate-measuring machine's few probed points, sparse scans): a sample of k points, k the
// number of free parameters (fit/metrology/primitive_tangent.h), determines the primitive.
//   plane    3 points: n = (p1 - p0) x (p2 - p0), d = n . p0
//   sphere   4 points: |x|^2 = 2 c . x + (r^2 - |c|^2) is linear in (c, r^2 - |c|^2): 4x4 solve
//   cylinder 5 points: for an axis direction u the points projected on the plane orthogonal to
//            u lie on a circle, linear in (centre, r^2 - |centre|^2) (Kasa); u is the best of
//            a Fibonacci grid of directions over the hemisphere by the geometric residual, then
//            Gauss-Newton on the 5 orthogonal distances
//   cone     6 points: for an axis direction u, ((x - a) . u)^2 = cos^2(alpha) |x - a|^2 is
//            linear in (s = a . u, c = cos^2 alpha, v = c a, k = c |a|^2 - s^2):
//            (x . u)^2 = 2 s (x . u) + c |x|^2 - 2 v . x + k, a 6x6 solve; u from the grid as
//            for the cylinder, then Gauss-Newton on the 6 distances
//   torus    10 points (k + 3; all of them when fewer): no practical closed form through 7, so
//            for every axis direction u of the grid the axis point is the Kasa centre of the
//            points projected orthogonally to u (parallels project onto circles about the
//            axis; or their centroid, whichever fits better) and the profile in (distance to
//            the axis, height) is a circle, linear in (R, h0, r^2 - R^2 - h0^2); the 6 best
//            directions refined by Levenberg-Marquardt on the sample's distances (7 free
//            parameters)
// The search tries every subset (k points, the torus' sample size above) when there are at
// most `budget` of them, else `budget` random ones; a hypothesis is scored by its support (points with |d| < tau), ties broken by
// the truncated squared distances (MSAC). It stops early once the best hypothesis is supported
// by every point (nothing can beat its support) and at least 4 valid hypotheses competed on
// the cost: on a clean CMM set that is after the first few subsets (the robust and
// least-squares refinements that follow converge from any of them).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "model/model.h"

namespace implicitfit {

bool PlaneFromPoints(const Eigen::Vector3d p[3], std::vector<double>* params);
bool SphereFromPoints(const Eigen::Vector3d p[4], std::vector<double>* params);
bool CylinderFromPoints(const Eigen::Vector3d p[5], std::vector<double>* params);
bool ConeFromPoints(const Eigen::Vector3d p[6], std::vector<double>* params);
bool TorusFromPoints(const Eigen::Vector3d* p, int count, std::vector<double>* params);
// Points per hypothesis: the free parameter count, or for a torus min(points, 10).
int PointSampleSize(NodeType kind, int points);

// "" when the points can determine the kind; else why not (too few points: the kind's free
// parameter count plus one are needed; collinear points for a plane; coplanar points for a
// sphere, cylinder, cone or torus).
std::string PointSetDegeneracy(NodeType kind, const std::vector<Eigen::Vector3d>& points);

struct PointHypothesisSearch {
  std::vector<double> parameters;  // the best hypothesis; empty when none was valid
  int support = 0;                 // its points with |d| < tau
  int tried = 0, valid = 0;        // subsets tried, hypotheses built
  bool enumerated = false;         // every subset was tried (unless stopped early)
  bool stopped_early = false;      // every point supported the best hypothesis
};

// constrain (may be empty) is applied to every hypothesis before scoring (fixed fields).
PointHypothesisSearch BestPointHypothesis(
    NodeType kind, const std::vector<Eigen::Vector3d>& points, double tau, int budget,
    std::mt19937& rng, const std::function<void(std::vector<double>*)>& constrain);

}  // namespace implicitfit
