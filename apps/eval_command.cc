// implicitfit eval MODEL.json POINTS [--clip-to-tetrahedron] — prints f at each point, one value
// per line, %.17g. --clip-to-tetrahedron evaluates every Bernstein patch as Guo's object
// S(f) ∩ V (model/file/clip_to_tetrahedron.h): max(f, the face planes of its tetrahedron).
#include <cstdio>
#include <string>

#include "apps/command.h"
#include "datasets/clouds/cloud_file.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "model/file/clip_to_tetrahedron.h"

namespace implicitfit {

CommandAction AddEvalCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("eval", "Print f (the model's signed distance) at each point");
  auto model_path = std::make_shared<std::string>();
  auto points_path = std::make_shared<std::string>();
  cmd->add_option("MODEL", *model_path, "Model file (JSON)")->required();
  cmd->add_option("POINTS", *points_path,
                  "Points (.xyz/.pwn/.txt/.xyzl/.ply/.pcd; normals ignored)")
      ->required();
  auto clip = std::make_shared<bool>(false);
  cmd->add_flag("--clip-to-tetrahedron", *clip,
                "Evaluate each Bernstein patch within its tetrahedron only: max(f, the "
                "tetrahedron's face planes), Guo's object S(f) ∩ V");
  return [model_path, points_path, clip]() {
    Model model = ReadModelFile(*model_path);
    if (*clip) {
      int clipped = 0;
      model = ClipPatchesToTetrahedra(model, &clipped);
      if (clipped == 0)
        throw InputError(*model_path + ": --clip-to-tetrahedron: the model has no bernstein_patch");
    }
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
