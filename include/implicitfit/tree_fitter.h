// Public API: fitting every free parameter of a model tree (primitives, blend delta and epsilon,
// patch control points) to an oriented cloud.
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include "fit/tree/tree_fitter.h"
