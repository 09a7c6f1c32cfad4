// Public API: fitting a Bernstein-Bezier patch of degree 2..4 to an oriented cloud, optionally
// constrained to be convex and certified.
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include "fit/bernstein/patch_fitter.h"
