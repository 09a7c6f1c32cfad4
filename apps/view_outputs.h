// The result pages of `fit --view`, `detect --view` and `reconstruct --view`, and the residual
// cloud of `fit --ply` (docs/view.md): view pages (view/view_page.h) built from what the jobs
// already hold, so the commands add one call each.
//   fit          the cloud coloured by residual (f of the fitted model) and, for primitives, by
//                inlier (label 0) / outlier (-1), with the model meshed in the cloud's box;
//   detect       the cloud coloured by primitive (the detection's labels) with the scene's legend,
//                and by residual (f of each point's primitive);
//   reconstruct  the cloud coloured by residual (f of the solid) and by primitive (detect's
//                labels, else the nearest primitive), with the solid meshed in the cloud's box.
#pragma once

#include <string>
#include <vector>

#include "implicitfit/detect.h"
#include "implicitfit/reconstruct.h"
#include "model/model.h"

namespace implicitfit {

void WriteDetectionView(const CloudDetection& detection, const std::string& page_path);

void WriteReconstructionView(const CloudReconstruction& job, const std::string& cloud_path,
                             const std::string& page_path);

// Reads the cloud again (as ReadCloudFile gives it) and writes, for the non-empty paths, the page
// and the PLY of the cloud with "residual" (f of the model) and, when inliers is given, "label"
// (0 inlier, -1 outlier).
void WriteFitOutputs(const std::string& cloud_path, const Model& model,
                     const std::vector<int>* inliers, const std::string& page_path,
                     const std::string& ply_path);

}  // namespace implicitfit
