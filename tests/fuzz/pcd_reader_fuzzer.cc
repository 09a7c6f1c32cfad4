// libFuzzer target: arbitrary bytes as a .pcd file through ReadCloudFile.
#include "fuzz/fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  return implicitfit_fuzz::ReadAsFile(data, size, "pcd");
}
