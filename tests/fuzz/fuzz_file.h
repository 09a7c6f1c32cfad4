// Fuzz harness support: the PLY and PCD readers take a path (PCL reads files), so each input
// is written to a per-process scratch file first. Any InputError is an expected refusal; a
// crash, a sanitizer report or another exception is a finding.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

#include "datasets/clouds/cloud_file.h"
#include "datasets/io/io_error.h"

namespace implicitfit_fuzz {

inline int ReadAsFile(const std::uint8_t* data, size_t size, const char* extension) {
  static const std::string path =
      "/tmp/implicitfit_fuzz_" + std::to_string(::getpid()) + "." + extension;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    implicitfit::CloudFileInfo info;
    const implicitfit::PointCloud cloud = implicitfit::ReadCloudFile(path, &info);
    // Contract of a successful read: finite points, unit normals or none.
    for (const auto& p : cloud.points)
      if (!p.allFinite()) __builtin_trap();
    if (cloud.has_normals() && cloud.normals.size() != cloud.size()) __builtin_trap();
  } catch (const implicitfit::InputError&) {
  }
  return 0;
}

}  // namespace implicitfit_fuzz
