// implicitfit mesh MODEL.json --out MESH.ply [--box xmin,ymin,zmin,xmax,ymax,zmax] [--cell h]
//                 [--clip-to-tetrahedron] [--quiet]
// A triangle mesh of the model's zero set with normals from grad f (datasets/meshing/model_mesher.h).
// --clip-to-tetrahedron meshes every Bernstein patch as Guo's object S(f) ∩ V, the solid within
// its tetrahedron (model/file/clip_to_tetrahedron.h): a closed surface along V's faces.
// Progress on stderr (each step of the mesher: a fine grid takes seconds), unless --quiet.
#include <cmath>
#include <iostream>

#include "apps/command.h"
#include "apps/progress_printer.h"
#include "datasets/io/io_error.h"
#include "datasets/io/model_file.h"
#include "implicitfit/mesh.h"

namespace implicitfit {
namespace {

bool HasBernsteinPatch(const Model& model) {
  for (const ModelNode& node : model.nodes())
    if (node.type == NodeType::kBernsteinPatch) return true;
  return false;
}

}  // namespace

CommandAction AddMeshCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "mesh", "Triangle mesh of a model's zero set (binary PLY, normals from grad f)");
  auto model_path = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto box = std::make_shared<std::vector<double>>();
  auto cell = std::make_shared<double>(0.0);
  cmd->add_option("MODEL", *model_path, "Model file (JSON)")->required();
  cmd->add_option("--out", *out, "Output mesh (.ply; - for stdout)")->required();
  cmd->add_option("--box", *box,
                  "Box to mesh: xmin,ymin,zmin,xmax,ymax,zmax (default: the model's box, "
                  "enlarged; a patch mesh: its grid box)")
      ->delimiter(',')
      ->expected(6);
  cmd->add_option("--cell", *cell,
                  "Grid spacing (default: longest box side / 100; a patch mesh with creases: "
                  "half its finest leaf)")
      ->check(CLI::PositiveNumber);
  auto clip = std::make_shared<bool>(false);
  cmd->add_flag("--clip-to-tetrahedron", *clip,
                "Mesh each Bernstein patch within its tetrahedron only (Guo's object S(f) ∩ V)");
  auto quiet = std::make_shared<bool>(false);
  cmd->add_flag("--quiet", *quiet, "No progress on stderr (failures are still reported)");
  return [model_path, out, box, cell, clip, quiet]() {
    if (*out != "-" && (out->size() < 4 || out->substr(out->size() - 4) != ".ply"))
      throw InputError(*out + ": unsupported output format (use .ply, or - for stdout)");
    const Model model = ReadModelFile(*model_path);
    MeshJobOptions options;
    options.clip_to_tetrahedron = *clip;
    options.progress = StderrProgress("mesh", *quiet);
    if (*clip && !HasBernsteinPatch(model))
      throw InputError(*model_path + ": --clip-to-tetrahedron: the model has no bernstein_patch");
    options.mesh.cell = *cell;
    if (box->size() == 6) {
      options.mesh.has_box = true;
      options.mesh.box_min = Eigen::Vector3d((*box)[0], (*box)[1], (*box)[2]);
      options.mesh.box_max = Eigen::Vector3d((*box)[3], (*box)[4], (*box)[5]);
    }
    std::string error;
    if (!options.IsValid(&error)) throw InputError("--" + error);
    MeshJobResult job;
    try {
      job = MeshModelJob(model, options);
    } catch (const std::invalid_argument& e) {
      throw InputError(*model_path + ": " + e.what());
    }
    if (!job.success) {
      std::cerr << "implicitfit mesh: " << *model_path << ": " << job.message << "\n";
      return 1;
    }
    const MeshResult& result = job.result;
    WriteMeshPlyFile(result.mesh, *out);
    std::cout << "vertices " << result.mesh.vertices.size() << "\ntriangles "
              << result.mesh.triangles.size() << "\ncell " << result.cell << "\nmax_abs_value "
              << result.max_abs_value << "\n";
    return 0;
  };
}

}  // namespace implicitfit
