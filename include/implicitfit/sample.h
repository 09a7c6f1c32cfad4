// Public API: the sample job — oriented points on a model's zero set with noise, outliers, a
// partial view and truth labels (SampleJobOptions with IsValid, SampleModelJob, SampleJobResult
// with BriefReport and ToJson), and the truth-label file writer. Only include/implicitfit/*.h
// is public API (see implicitfit/model.h).
#pragma once

#include "datasets/io/truth_labels.h"
#include "jobs/sample_job.h"
