// One primitive of a requested kind from a cloud that may hold many surfaces (`fit --model KIND`),
// never a confident wrong one: the fit of fit/primitive/primitive_fitter.h is accepted only when
// it passes the detector's candidate checks (fit/detect/primitive_detector.h), with the cloud's
// own scales (fit/detect/detection_scales.h: noise sigma, distance band tau, normal band theta,
// likelihood scale s = sigma clamped to [tau / 10, tau / 3]):
//   normals   at least 80% of the fit's inliers have normals within theta of grad f (a surface
//             crossing other surfaces meets them at angles);
//   connected the support S (inliers with agreeing normals) is cut to its connected parts C
//             (over the neighbour graph) of at least max(10, N / 500) points (the detector's
//             smallest primitive), which must hold at least half of S (a wrong surface meets the
//             real ones in scattered bits; a bore seen in two pieces keeps both);
//   noise     1.4826 median |f| over C <= 2 s (a right model leaves the noise; a wrong one that
//             crosses the band spreads its residuals over it);
//   kind      no simpler kind explains the points of C as well: a kind with fewer parameters,
//             least-squares fitted to C, that supports (|f| < tau, normal within theta) at least
//             97% as many of them, a curved one also at a penalised cost
//             sum min(r^2 / s^2, tau^2 / s^2) + p ln |C| at most twice the fit's, makes the fit a
//             wrong kind (a cylinder of huge radius over a plane). A sphere that coincides with a
//             requested cylinder along a great circle (a narrow band) does not count.
// When the first fit fails a check, every primitive of the requested kind that the detector
// finds in the cloud (largest first) is refined by the same fitter from its parameters with a
// fixed band (the user's threshold, else tau) and checked the same way; the first that passes
// is the result. Otherwise the result fails (success false) and says why: "no cylinder explains
// the cloud: ...".
// Checks apply to robust fits with normals of at least kMinCheckedPoints points; fits from
// points alone (metrology probes, untrusted normals) and the least-squares and minimum-zone
// estimators (every point by definition) are returned as fitted.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fit/primitive/primitive_fitter.h"
#include "datasets/clouds/neighbour_graph.h"

namespace implicitfit {

constexpr size_t kMinCheckedPoints = 50;

struct CheckedFit {
  PrimitiveFitResult result;  // success false: no real primitive of the kind (message: why)
  bool checked = false;       // the checks ran (robust fit with normals, enough points)
  std::string source;         // "fit" (the fitter's own result) or "detection"
  std::string first_check;    // the first fit's check: "passed" or why it failed
  double noise = 0.0, band = 0.0, normal_angle_deg = 0.0;  // the cloud's scales
  int support = 0;                                         // |C| of the accepted result
  // {"checked", "source", "first_check", "noise", "band", "normal_angle_deg", "support"}
  nlohmann::json ToJson() const;
};

// Whether a cloud fills a volume at its sampling scale by the detector's rule
// (fit/detect/detection_scales.h: tangent-plane noise above 0.4 spacings and neighbouring
// normals more than 15 deg apart; uniform random points read 0.58 spacings): then no surface
// explains it, and `fit` refuses it as `detect` does, unless a fixed threshold says which points
// are the inliers. normals: estimated ones, trusted or not (the fit from points alone drops
// those it does not trust, but they still tell a volume). why: the figures, when it does.
bool FillsAVolume(const std::vector<Eigen::Vector3d>& points,
                  const std::vector<Eigen::Vector3d>& normals, const NeighbourGraph& neighbours,
                  double spacing, std::string* why);

// points, normals (one per point, or empty: no checks); neighbours and spacing as for
// DetectPrimitives (datasets/normals/neighbourhoods.h); options as for FitPrimitive. When
// options has neither threshold nor start_band, the adaptive band starts at tau.
CheckedFit FitCheckedPrimitive(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<Eigen::Vector3d>& normals,
                               const NeighbourGraph& neighbours, double spacing,
                               const PrimitiveFitOptions& options);

}  // namespace implicitfit
