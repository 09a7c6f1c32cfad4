// The sampler's options (datasets/generators/model_sampler.h) most tests draw their clouds with:
// `count` points with Gaussian noise of sigma `noise` along the normal, seeded, in the box
// [box_min, box_max]; no outliers, no partial view.
#pragma once

#include "datasets/generators/model_sampler.h"

namespace testsupport {

inline implicitfit::SampleOptions SampleInBox(int count, double noise, unsigned seed,
                                              const Eigen::Vector3d& box_min,
                                              const Eigen::Vector3d& box_max) {
  implicitfit::SampleOptions so;
  so.count = count;
  so.noise = noise;
  so.seed = seed;
  so.has_box = true;
  so.box_min = box_min;
  so.box_max = box_max;
  return so;
}

}  // namespace testsupport
