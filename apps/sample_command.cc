// implicitfit sample MODEL.json --count N [--noise s] [--outliers f] [--seed s]
//                    [--view x,y,z --view-angle deg] --out CLOUD.xyz|CLOUD.ply
//                    [--truth LABELS.txt]
// --truth: the truth labels of the points (datasets/io/truth_labels.h): the index of the leaf
// primitive each point was drawn on (leaves in the model file's node order), -1 for outliers
// and for points on no leaf (a blend's fillet), with a kinds line when every leaf drawn on is a
// plane, sphere, cylinder, cone or torus; `detect --truth` scores against it.
// Oriented points on the model's zero set with known truth (datasets/generators/model_sampler.h).
#include <iostream>

#include "apps/command.h"
#include "datasets/clouds/ply_writer.h"
#include "datasets/clouds/xyz_writer.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "datasets/io/read_limits.h"
#include "datasets/io/truth_labels.h"
#include "implicitfit/sample.h"

namespace implicitfit {

CommandAction AddSampleCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("sample", "Sample oriented points on a model's zero set");
  auto model_path = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto job_options = std::make_shared<SampleJobOptions>();
  SampleOptions* options = &job_options->sample;
  auto view = std::make_shared<std::vector<double>>();
  auto truth = std::make_shared<std::string>();
  cmd->add_option("MODEL", *model_path, "Model file (JSON)")->required();
  cmd->add_option("--count", options->count, "Number of points (inliers + outliers)")
      ->required()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--noise", options->noise, "Sigma of the Gaussian displacement along the normal")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--outliers", options->outlier_fraction,
                  "Fraction of uniform outliers in the sampling box")
      ->check(CLI::Range(0.0, 0.99));
  cmd->add_option("--seed", options->seed, "Random seed");
  cmd->add_option("--view", *view,
                  "Partial view: direction x,y,z the scanner sees the outward normals from")
      ->delimiter(',')
      ->expected(3);
  cmd->add_option("--view-angle", options->view_angle_deg,
                  "Partial view: keep normals within this angle of --view")
      ->check(CLI::Range(0.0, 180.0));
  cmd->add_option("--out", *out,
                  "Output cloud (.xyz/.pwn/.txt: x y z nx ny nz; .ply: binary with normals; - for "
                  "stdout, as .xyz)")
      ->required();
  cmd->add_option("--truth", *truth,
                  "Also write the truth labels: leaf primitive of each point, -1 for outliers");
  return [model_path, out, job_options, options, view, truth]() {
    const size_t dot = out->find_last_of('.');
    const std::string ext = *out == "-" ? "xyz" : dot == std::string::npos ? "" : out->substr(dot + 1);
    const bool ply = ext == "ply";
    if (!ply && ext != "xyz" && ext != "pwn" && ext != "txt")
      throw InputError(*out +
                       ": unsupported output format (use .xyz, .pwn, .txt or .ply; - for stdout)");
    if (static_cast<unsigned long long>(options->count) > CurrentReadLimits().max_points)
      throw InputError("--count " + std::to_string(options->count) +
                       ": more than the limit of " +
                       std::to_string(CurrentReadLimits().max_points) +
                       " points (raise it with --max-points)");
    if (view->size() == 3) options->view_dir = Eigen::Vector3d((*view)[0], (*view)[1], (*view)[2]);
    const Model model = ReadModelFile(*model_path);
    std::string error;
    if (!job_options->IsValid(&error)) throw InputError("--" + error);
    const SampleJobResult job = SampleModelJob(model, *job_options);
    if (!job.success) {
      std::cerr << "implicitfit sample: " << *model_path << ": " << job.message << "\n";
      return 1;
    }
    const SampledCloud& sampled = job.sampled;
    if (ply)
      WritePlyFile(sampled.cloud, *out);
    else
      WriteXyzFile(sampled.cloud, *out);
    if (!truth->empty()) WriteTruthFile(sampled.primitive, job.truth_kinds, *truth);
    return 0;
  };
}

}  // namespace implicitfit
