// Public API: robust fitting of one primitive (plane, sphere, cylinder, cone, torus) to a cloud,
// with parameter standard deviations.
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include "fit/primitive/primitive_fitter.h"
