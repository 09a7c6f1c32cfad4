// Public API: the reconstruct job on one cloud — read it (or take one already read), estimate
// and orient its normals when it has none, take the primitives of a scene file or detect them,
// reconstruct and verify the solid, and build the JSON report the command line's `reconstruct`
// writes (ReconstructJobOptions, ReconstructCloudFile, ReconstructCloud; CloudReconstruction with
// BriefReport and ToJson). Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include "jobs/reconstruct_job.h"
