// implicitfit view INPUT... [--out PAGE.html] [--png PICTURE.png] [--size WxH] [--clip AXIS,T]
//                  [--camera AZ,EL] [--zoom F] [--color MODE] [--hide-panel] [--labels L.txt]
//                  [--resolution N] [--box xmin,ymin,zmin,xmax,ymax,zmax] [--scale S]
//                  [--point-size P] [--option KEY=VALUE]... [--title T] [--quiet]
// One self-contained HTML page of clouds, scenes, models and meshes (view/view_inputs.h,
// view/page_html.h), and its picture by headless Chromium (view/chromium_screenshot.h).
// Exit 0 written; 2 for invalid usage, an unreadable input (nothing written) or no Chromium
// for --png (checked before anything is read or written).
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <set>

#include "apps/command.h"
#include "datasets/io/atomic_file.h"
#include "datasets/io/io_error.h"
#include "view/chromium_screenshot.h"
#include "view/page_html.h"
#include "view/view_inputs.h"

namespace implicitfit {
namespace {

struct ViewArgs {
  std::vector<std::string> inputs, options;
  std::vector<double> box, camera;
  std::string out, png, size = "1000x750", clip, color, labels, title;
  double zoom = 0.0, scale = 0.0;
  int resolution = 100, point_size = 0;
  bool hide_panel = false, quiet = false;
};

// The page's default options (docs/view.md keys) from the command's arguments.
std::map<std::string, std::string> PageOptions(const ViewArgs& a) {
  std::map<std::string, std::string> o;
  if (!a.clip.empty()) {
    const size_t comma = a.clip.find(',');
    const std::string axis = a.clip.substr(0, comma);
    static const std::set<std::string> kAxes = {"x", "y", "z", "-x", "-y", "-z"};
    if (!kAxes.count(axis)) throw InputError("--clip " + a.clip + ": the axis is x, y, z, -x, -y or -z");
    if (comma != std::string::npos) {
      const std::string position = a.clip.substr(comma + 1);
      char* end = nullptr;
      const double t = std::strtod(position.c_str(), &end);
      if (position.empty() || *end != '\0' || !(t >= 0 && t <= 1))
        throw InputError("--clip " + a.clip + ": the position is a number in [0, 1]");
    }
    o["clip"] = a.clip;
  }
  if (!a.camera.empty()) {
    o["az"] = std::to_string(a.camera[0]);
    o["el"] = std::to_string(a.camera[1]);
  }
  if (a.zoom > 0) o["zoom"] = std::to_string(a.zoom);
  if (!a.color.empty()) {
    if (a.color != "auto" && a.color != "primitive" && a.color != "residual" && a.color != "plain")
      throw InputError("--color " + a.color + ": auto, primitive, residual or plain");
    o["color"] = a.color;
  }
  if (a.hide_panel) o["ui"] = "0";
  if (a.point_size > 0) o["size"] = std::to_string(a.point_size);
  for (const std::string& kv : a.options) {
    const size_t eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--option " + kv + ": KEY=VALUE");
    o[kv.substr(0, eq)] = kv.substr(eq + 1);
  }
  return o;
}

}  // namespace

CommandAction AddViewCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "view", "One self-contained HTML page (and a PNG) of clouds, scenes, models and meshes");
  auto a = std::make_shared<ViewArgs>();
  cmd->add_option("INPUT", a->inputs,
                  "Clouds (.xyz .pwn .txt .xyzl .ply .pcd), scenes and models (.json), meshes "
                  "(.ply with faces); drawn over each other")
      ->required();
  cmd->add_option("--out", a->out, "The page (HTML, opens without network access)");
  cmd->add_option("--png", a->png, "A picture of the page by headless Chromium");
  cmd->add_option("--size", a->size, "Picture size WxH in pixels (default 1000x750)");
  cmd->add_option("--clip", a->clip,
                  "Clipping plane AXIS[,T]: keeps the part below the plane across x, y, z (or "
                  "above for -x, -y, -z) at the fraction T of the box (default 0.5)");
  cmd->add_option("--camera", a->camera, "Camera direction AZ,EL in degrees (z up; default -60,25)")
      ->delimiter(',')
      ->expected(2);
  cmd->add_option("--zoom", a->zoom, "Camera zoom (default 1: the whole box in view)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--color", a->color, "Point colours: auto (default), primitive, residual, plain");
  cmd->add_flag("--hide-panel", a->hide_panel, "Draw without the panel (layers, legends)");
  cmd->add_option("--labels", a->labels, "Per-point labels of the (first) scene's cloud");
  cmd->add_option("--resolution", a->resolution,
                  "Models: grid cells along the longest side of the box (default 100)")
      ->check(CLI::Range(4, 400));
  cmd->add_option("--box", a->box, "Models: mesh in this box xmin,ymin,zmin,xmax,ymax,zmax")
      ->delimiter(',')
      ->expected(6);
  cmd->add_option("--scale", a->scale, "Residual colour map saturation (default: 95th pct |r|)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--point-size", a->point_size, "Point size in pixels (default by count)")
      ->check(CLI::Range(1, 20));
  cmd->add_option("--option", a->options,
                  "Any page option KEY=VALUE (docs/view.md: camera, target, fov, hide, ...)")
      ->allow_extra_args(false);  // one KEY=VALUE per --option: later words stay INPUTs
  cmd->add_option("--title", a->title, "Page title (default: the input names)");
  cmd->add_flag("--quiet", a->quiet, "No progress on stderr");
  return [a]() {
    if (a->out.empty() && a->png.empty()) throw InputError("--out PAGE.html or --png PICTURE.png is required");
    ScreenshotOptions shot;
    if (std::sscanf(a->size.c_str(), "%dx%d", &shot.width, &shot.height) != 2)
      throw InputError("--size " + a->size + ": expected WxH, e.g. 1000x750");
    const std::string chromium = a->png.empty() ? "" : RequireChromium();
    ViewInputOptions options;
    options.labels = a->labels;
    options.resolution = a->resolution;
    options.residual_scale = a->scale;
    options.quiet = a->quiet;
    if (!a->box.empty()) {
      const std::vector<double>& b = a->box;
      options.has_box = true;
      options.box_min = {b[0], b[1], b[2]};
      options.box_max = {b[3], b[4], b[5]};
      if (!(options.box_min.array() < options.box_max.array()).all())
        throw InputError("--box: every min must be below its max");
    }
    std::map<std::string, std::string> page_options = PageOptions(*a);  // checked before reading
    ViewPage page = ReadViewInputs(a->inputs, options);
    page.options = std::move(page_options);
    if (!a->title.empty()) page.title = a->title;
    const std::string html = PageHtml(page);
    size_t points = 0, triangles = 0;
    for (const ViewLayer& l : page.layers) points += l.points.size(), triangles += l.mesh.triangles.size();
    if (!a->out.empty()) WriteFileAtomically(a->out, html);
    if (!a->png.empty()) {
      if (!a->quiet) std::cerr << "view: drawing " << a->png << " with " << chromium << "\n";
      if (!a->out.empty())
        ScreenshotPage(chromium, a->out, a->png, shot);
      else
        ScreenshotHtml(chromium, html, a->png, shot);
    }
    std::printf("layers %zu  points %zu  triangles %zu  page %.1f MB%s%s%s%s\n", page.layers.size(),
                points, triangles, html.size() / 1e6, a->out.empty() ? "" : "  ", a->out.c_str(),
                a->png.empty() ? "" : "  picture ", a->png.c_str());
    return 0;
  };
}

}  // namespace implicitfit
