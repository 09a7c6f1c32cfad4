// implicitfit design CLOUD --primitive plane|paraboloid --count m [--delta d] [--epsilon e]
//                   [--order n] [--smoothing li-phillips|convex] --out MODEL.json
// Li & Phillips' design from oriented points (implicitfit/design.h, fit/tree/design_builder.h): m
// oriented representatives of the cloud, written as the smooth intersection of the enclosing
// ellipsoid and one plane / paraboloid per representative; `fit --init MODEL.json` refines it.
// Exit 0 on success, 2 for invalid usage or input (no output file).
#include <cstdio>
#include <memory>

#include "apps/command.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "datasets/normals/oriented_cloud.h"
#include "implicitfit/design.h"

namespace implicitfit {
namespace {

struct DesignArgs {
  std::string cloud, out;
  DesignJobOptions options;
};

}  // namespace

CommandAction AddDesignCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "design", "Build a smooth intersection of primitives placed at oriented representatives");
  auto a = std::make_shared<DesignArgs>();
  cmd->add_option("CLOUD", a->cloud, "Oriented point cloud (normals estimated when absent)")
      ->required();
  cmd->add_option("--primitive", a->options.design.primitive, "plane (default) or paraboloid");
  cmd->add_option("--count", a->options.design.count, "Number of representatives m")
      ->required()
      ->check(CLI::Range(1, 10000));
  cmd->add_option("--delta", a->options.design.delta,
                  "Blend delta (default 2% of the bounding-box diagonal)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--epsilon", a->options.design.epsilon,
                  "Blend epsilon <= delta (default delta / 2)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--order", a->options.design.order, "Order n of the unit step H_n (default 3)")
      ->check(CLI::Range(0, 14));
  cmd->add_option("--smoothing", a->options.design.smoothing,
                  "li-phillips (default) or convex: the convexity-preserving smooth max over a "
                  "box base, certified convex by `check`");
  cmd->add_option("--out", a->out, "Output model file (JSON)")->required();
  return [a]() {
    const DesignOptions& o = a->options.design;
    if (!IsDesignPrimitive(o.primitive))
      throw InputError("--primitive '" + o.primitive + "': expected plane or paraboloid");
    if (!IsDesignSmoothing(o.smoothing))
      throw InputError("--smoothing '" + o.smoothing + "': expected li-phillips or convex");
    if (o.smoothing == "convex" && o.epsilon > 0)
      throw InputError("--epsilon: a convex-smoothing blend has no epsilon (its width is --delta)");
    if (o.delta > 0 && o.epsilon > o.delta) throw InputError("--epsilon must not exceed --delta");
    std::string error;
    if (!a->options.IsValid(&error)) throw InputError("--" + error);
    std::string normals;
    const PointCloud cloud = ReadOrientedCloud(a->cloud, &normals);
    if (static_cast<int>(cloud.size()) < o.count)
      throw InputError(a->cloud + ": " + std::to_string(cloud.size()) +
                       " points, fewer than --count " + std::to_string(o.count));
    DesignJobResult job;
    try {
      job = DesignModelJob(cloud.points, cloud.normals, a->options, normals);
    } catch (const std::invalid_argument& e) {
      throw InputError(a->cloud + ": " + e.what());
    }
    WriteModelFile(job.model, a->out);
    std::printf("design: %s -> %s\n", job.BriefReport().c_str(), a->out.c_str());
    return 0;
  };
}

}  // namespace implicitfit
