// Public API: the patch-mesh job — a Bernstein mesh (C0 or C1 patches on a cube grid's Kuhn
// tetrahedra) fitted to an oriented cloud, optionally certified convex (PatchMeshJobOptions with
// IsValid, FitPatchMeshJob, PatchMeshJobResult with ToModel, BriefReport and ToJson).
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include "jobs/patch_mesh_job.h"
