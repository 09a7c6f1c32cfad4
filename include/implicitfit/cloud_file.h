// Public API: reading point clouds (.xyz/.pwn/.txt, .xyzl, .ply, .pcd) and writing them
// (.xyz, .ply); InputError names the file and, for text, the line.
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include "datasets/cloud_file.h"
#include "datasets/io_error.h"
#include "datasets/ply_writer.h"
#include "datasets/point_cloud.h"
#include "datasets/xyz_writer.h"
