// Public API: the detect job on one cloud — read it (or take one already read), estimate and
// orient its normals when it has none, detect every primitive, and build the scene and the JSON
// report the command line's `detect` writes (DetectCloudFile, DetectCloud with DetectionOptions;
// CloudDetection with BriefReport and ToJson); scoring against ground-truth labels (LoadTruth,
// ScoreDetection). Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include "jobs/detect_job.h"
