// Public API, everything at once: the model and its file, the three fitters, cloud reading and
// normal estimation, and the jobs (detect, reconstruct, mesh, sample, design, patch mesh).
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include "implicitfit/cloud_file.h"
#include "implicitfit/design.h"
#include "implicitfit/detect.h"
#include "implicitfit/mesh.h"
#include "implicitfit/model.h"
#include "implicitfit/model_json.h"
#include "implicitfit/normal_estimation.h"
#include "implicitfit/patch_fitter.h"
#include "implicitfit/patch_mesh.h"
#include "implicitfit/primitive_fitter.h"
#include "implicitfit/reconstruct.h"
#include "implicitfit/sample.h"
#include "implicitfit/tree_fitter.h"
