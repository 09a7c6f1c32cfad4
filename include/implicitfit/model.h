// Public API: the model tree (primitives, smooth CSG operators, Bernstein patches) evaluated as
// one implicit function f(x), f < 0 inside, grad f outward; Bernstein patch conversions and the
// convexity certificate of patches.
//
// Only the headers of include/implicitfit/ are implicitfit's public API. They include internal
// headers (installed under include/implicitfit/internal/, like Ceres' ceres/internal/), whose
// names and layout may change without notice: include these, never those.
#pragma once

#include "model/bernstein/bernstein_conversion.h"
#include "model/bernstein/bernstein_patch.h"
#include "model/certificates/convexity_certificate.h"
#include "model/model.h"
