// libFuzzer target: arbitrary bytes as a model file (.json) through ReadModelFile, the reader
// every command uses. An InputError (invalid JSON or an invalid model, with its path) is an
// expected refusal; a crash, a sanitizer report or another exception is a finding. A model that
// is accepted must keep the reader's contract: written and read back it has exactly the same
// parameters and structure, and it can be evaluated (value, gradient, sampling box, parameter
// names) without undefined behaviour.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "datasets/generators/model_sampler.h"
#include "model/file/model_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  static const std::string path = "/tmp/implicitfit_fuzz_" + std::to_string(::getpid()) + ".json";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  implicitfit::Model model;
  try {
    model = implicitfit::ReadModelFile(path);
  } catch (const implicitfit::InputError&) {
    return 0;
  }
  const implicitfit::Model again = implicitfit::ModelFromJson(implicitfit::ModelToJson(model));
  if (again.parameters() != model.parameters() || again.nodes().size() != model.nodes().size())
    __builtin_trap();
  for (size_t i = 0; i < model.nodes().size(); ++i)
    if (again.nodes()[i].type != model.nodes()[i].type ||
        again.nodes()[i].children != model.nodes()[i].children)
      __builtin_trap();
  if (model.ParameterNames().size() != model.parameters().size()) __builtin_trap();
  Eigen::Vector3d lo, hi;
  implicitfit::SamplingBox(model, &lo, &hi);
  for (const Eigen::Vector3d& x :
       {Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Vector3d(lo), Eigen::Vector3d(hi)}) {
    double value = 0.0;
    model.Gradient(x, &value);
  }
  return 0;
}
