// implicitfit eval MODEL.json POINTS — prints f at each point, one value per line, %.17g.
#include <cstdio>
#include <string>

#include "apps/command.h"
#include "datasets/clouds/cloud_file.h"
#include "datasets/io/model_file.h"

namespace implicitfit {

CommandAction AddEvalCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("eval", "Print f (the model's signed distance) at each point");
  auto model_path = std::make_shared<std::string>();
  auto points_path = std::make_shared<std::string>();
  cmd->add_option("MODEL", *model_path, "Model file (JSON)")->required();
  cmd->add_option("POINTS", *points_path,
                  "Points (.xyz/.pwn/.txt/.xyzl/.ply/.pcd; normals ignored)")
      ->required();
  return [model_path, points_path]() {
    const Model model = ReadModelFile(*model_path);
    const PointCloud cloud = ReadCloudFile(*points_path);
    std::string out;
    out.reserve(cloud.size() * 24);
    char buffer[40];
    for (const Eigen::Vector3d& x : cloud.points) {
      std::snprintf(buffer, sizeof buffer, "%.17g\n", model.Value(x));
      out += buffer;
    }
    std::fwrite(out.data(), 1, out.size(), stdout);
    return 0;
  };
}

}  // namespace implicitfit
