// Public API: the mesh job — a triangle mesh of a model's zero set with normals from grad f
// (MeshJobOptions with IsValid, MeshModelJob, MeshJobResult with BriefReport and ToJson), and
// WriteMeshPlyFile. Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include "jobs/mesh_job.h"
