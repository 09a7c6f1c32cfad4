// Public API: reading point clouds (.xyz/.pwn/.txt, .xyzl, .ply, .pcd) and writing them
// (.xyz, .ply); InputError names the file and, for text, the line.
// Only include/implicitfit/*.h is public API (see implicitfit/model.h).
#pragma once

#include "datasets/clouds/cloud_file.h"
#include "datasets/io/io_error.h"
#include "datasets/clouds/ply_writer.h"
#include "datasets/clouds/point_cloud.h"
#include "datasets/clouds/xyz_writer.h"
