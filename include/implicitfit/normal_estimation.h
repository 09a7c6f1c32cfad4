// Public API: estimating missing normals (PCA over density-adapted neighbourhoods) and orienting
// them (toward a viewpoint, else by minimum-spanning-tree propagation).
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include "datasets/normals/normal_estimation.h"
