// Public API: the design job — Li & Phillips' model from oriented points, the smooth
// intersection of an enclosing base and one plane or paraboloid per representative of the cloud
// (DesignJobOptions with IsValid, DesignModelJob, DesignJobResult with BriefReport and ToJson).
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include "jobs/design_job.h"
