// Hostile option values: NaN, infinities, hex and octal-looking numbers, out-of-range counts and
// sizes that would exhaust memory or time. Each is refused (exit 2, the option named) before any
// work, or, for sizes that depend on the data, as soon as the data is read (exit 1 with the
// limit in the message); counts that only cost threads are clamped (exit 0).
#include "apps/hostile/hostile_case.h"

namespace hostile {
namespace {

struct OptionCase {
  std::string id, args, mention;
  int exit_code;
  std::vector<std::string> outputs;
  std::string defect;
  double seconds;
};

// Every case's folder holds c.xyz (a plane, oriented), s.xyz (a sphere, oriented), s.json (a
// sphere model) and q.json (a quadric patch model).
std::vector<OptionCase> Options() {
  const std::string fit = "fit c.xyz --model plane --out m.json ";
  const std::vector<std::string> fit_out = {"m.json"};
  std::vector<OptionCase> v = {
      {"fit_threshold_nan", fit + "--threshold nan", "--threshold", 2, fit_out,
       "NaN accepted by --threshold", 10},
      {"fit_threshold_inf", fit + "--threshold inf", "--threshold", 2, fit_out, "", 10},
      {"fit_threshold_hex", fit + "--threshold 0x10", "--threshold", 2, fit_out, "", 10},
      {"fit_threshold_overflow", fit + "--threshold 1e999", "--threshold", 2, fit_out, "", 10},
      {"fit_threshold_negative", fit + "--threshold -1", "--threshold", 2, fit_out, "", 10},
      {"fit_seed_octal", fit + "--seed 010", "--seed", 2, fit_out, "", 10},
      {"fit_seed_negative", fit + "--seed -1", "--seed", 2, fit_out, "", 10},
      {"fit_seed_hex", fit + "--seed 0x10", "--seed", 2, fit_out, "", 10},
      {"fit_fix_nan", "fit s.xyz --model sphere --out m.json --fix radius=nan", "--fix", 2,
       fit_out, "NaN accepted by --fix", 10},
      {"fit_fix_inf", "fit s.xyz --model sphere --out m.json --fix radius=inf", "--fix", 2,
       fit_out, "", 10},
      {"fit_fix_hexfloat", "fit s.xyz --model sphere --out m.json --fix radius=0x1p1", "--fix",
       2, fit_out, "", 10},
      {"fit_fix_word", "fit s.xyz --model sphere --out m.json --fix radius=two", "--fix", 2,
       fit_out, "", 10},
      {"fit_fix_center_nan", "fit s.xyz --model sphere --out m.json --fix center=0,nan,0",
       "--fix", 2, fit_out, "", 10},
      {"fit_degree_octal", "fit s.xyz --model quadric-patch --degree 02 --out m.json",
       "--degree", 2, fit_out, "", 10},
      {"fit_cell_nan", "fit s.xyz --model patch-mesh --cell nan --out m.json", "--cell", 2,
       fit_out, "NaN accepted by --cell", 10},
      {"fit_cell_tiny", "fit s.xyz --model patch-mesh --cell 1e-9 --out m.json", "limit", 1,
       fit_out, "--cell 1e-9 overflows to a 1x1x1 grid", 20},
      {"fit_cells_200", "fit s.xyz --model patch-mesh --cells 200 --out m.json", "limit", 1,
       fit_out, "patch-mesh --cells 200 takes 5 GB before failing", 20},
      {"fit_cells_zero", "fit s.xyz --model patch-mesh --cells 0 --out m.json", "--cells", 2,
       fit_out, "", 10},
      {"fit_grid_huge", "fit s.xyz --model partition --grid 100x100x100 --out m.json",
       "--grid", 2, fit_out, "partition --grid takes 5 GB before failing", 10},
      {"fit_grid_octal", "fit s.xyz --model partition --grid 03x3x3 --out m.json", "--grid", 2,
       fit_out, "", 10},
      {"fit_grid_zero", "fit s.xyz --model partition --grid 0x3x3 --out m.json", "--grid", 2,
       fit_out, "", 10},
      {"fit_tetrahedron_nan",
       "fit s.xyz --model quadric-patch --tetrahedron 0,0,0,1,0,0,0,1,0,0,0,nan --out m.json",
       "--tetrahedron", 2, fit_out, "", 10},
      {"fit_vertex_normal_nan",
       "fit s.xyz --model quadric-patch --vertex-normal 1=0,nan,1 --out m.json",
       "--vertex-normal", 2, fit_out, "", 10},
      {"fit_through_vertex_octal", "fit s.xyz --model quadric-patch --through-vertex 01 --out m.json",
       "--through-vertex", 2, fit_out, "", 10},
      {"sample_count_octal", "sample s.json --count 010 --out o.xyz", "--count", 2, {"o.xyz"},
       "--count 010 means 8", 10},
      {"sample_count_2_31", "sample s.json --count 2147483648 --out o.xyz", "--count", 2,
       {"o.xyz"}, "", 10},
      {"sample_count_int_max", "sample s.json --count 2147483647 --out o.xyz", "--count", 2,
       {"o.xyz"}, "sample --count has no cap (2^31 points: 4.6 GB)", 20},
      {"sample_count_over_limit", "sample s.json --count 200000000 --out o.xyz", "--count", 2,
       {"o.xyz"}, "sample --count has no cap (2^31 points: 4.6 GB)", 10},
      {"sample_count_over_max_points", "sample s.json --count 1000 --max-points 999 --out o.xyz",
       "--count", 2, {"o.xyz"}, "", 10},
      {"sample_count_zero", "sample s.json --count 0 --out o.xyz", "--count", 2, {"o.xyz"}, "",
       10},
      {"sample_noise_nan", "sample s.json --count 10 --noise nan --out o.xyz", "--noise", 2,
       {"o.xyz"}, "NaN accepted by --noise", 10},
      {"sample_noise_inf", "sample s.json --count 10 --noise inf --out o.xyz", "--noise", 2,
       {"o.xyz"}, "", 10},
      {"sample_outliers_nan", "sample s.json --count 10 --outliers nan --out o.xyz",
       "--outliers", 2, {"o.xyz"}, "", 10},
      {"sample_view_nan", "sample s.json --count 10 --view nan,0,1 --view-angle 30 --out o.xyz",
       "--view", 2, {"o.xyz"}, "", 10},
      {"sample_view_angle_nan", "sample s.json --count 10 --view 0,0,1 --view-angle nan --out o.xyz",
       "--view-angle", 2, {"o.xyz"}, "", 10},
      {"sample_seed_hex", "sample s.json --count 10 --seed 0x2 --out o.xyz", "--seed", 2,
       {"o.xyz"}, "", 10},
      {"mesh_cell_nan", "mesh s.json --cell nan --out o.ply", "--cell", 2, {"o.ply"}, "", 10},
      {"mesh_cell_tiny", "mesh s.json --cell 1e-9 --out o.ply", "", 2, {"o.ply"}, "", 10},
      {"mesh_cell_zero", "mesh s.json --cell 0 --out o.ply", "--cell", 2, {"o.ply"}, "", 10},
      {"mesh_box_nan", "mesh s.json --box 0,0,0,1,nan,1 --out o.ply", "--box", 2, {"o.ply"}, "",
       10},
      {"mesh_box_inf", "mesh s.json --box -inf,0,0,1,1,1 --out o.ply", "--box", 2, {"o.ply"},
       "", 10},
      {"mesh_box_empty", "mesh s.json --box 0,0,0,0,1,1 --out o.ply", "--box", 2, {"o.ply"}, "",
       10},
      {"detect_threshold_nan", "detect s.xyz --threshold nan --out o.json", "--threshold", 2,
       {"o.json"}, "", 10},
      {"detect_min_points_octal", "detect s.xyz --min-points 010 --out o.json", "--min-points",
       2, {"o.json"}, "", 10},
      {"detect_threads_word", "detect s.xyz --threads many --out o.json", "--threads", 2,
       {"o.json"}, "", 10},
      {"detect_kinds_unknown", "detect s.xyz --kinds plane,blob --out o.json", "--kinds", 2,
       {"o.json"}, "", 10},
      {"check_sample_huge", "check q.json --sample 100000000", "--sample", 2, {},
       "check --sample N is quadratic", 10},
      {"check_sample_octal", "check q.json --sample 0100", "--sample", 2, {}, "", 10},
      {"check_sample_nan", "check q.json --sample nan", "--sample", 2, {}, "", 10},
      {"design_count_octal", "design s.xyz --count 010 --out o.json", "--count", 2, {"o.json"},
       "", 10},
      {"design_delta_nan", "design s.xyz --count 4 --delta nan --out o.json", "--delta", 2,
       {"o.json"}, "", 10},
      {"design_epsilon_inf", "design s.xyz --count 4 --epsilon inf --out o.json", "--epsilon", 2,
       {"o.json"}, "", 10},
      {"design_order_hex", "design s.xyz --count 4 --order 0x3 --out o.json", "--order", 2,
       {"o.json"}, "", 10},
      {"reconstruct_seed_negative", "reconstruct s.xyz --seed -3 --out o.json", "--seed", 2,
       {"o.json"}, "", 10},
      {"batch_jobs_hex", "batch s.xyz --model sphere --out-dir out --jobs 0x10", "--jobs", 2,
       {}, "", 10},
      {"batch_threshold_nan", "batch s.xyz --model sphere --out-dir out --threshold nan",
       "--threshold", 2, {}, "", 10},
      {"batch_shard_zero", "batch s.xyz --model sphere --out-dir out --shard 1/0", "--shard", 2,
       {}, "", 10},
      {"batch_shard_octal", "batch s.xyz --model sphere --out-dir out --shard 01/2", "--shard",
       2, {}, "", 10},
      {"batch_shard_word", "batch s.xyz --model sphere --out-dir out --shard one/two", "--shard",
       2, {}, "", 10},
      {"batch_fix_nan", "batch s.xyz --model sphere --out-dir out --fix radius=nan", "--fix", 2,
       {}, "", 10},
      {"max_points_zero", "eval s.json s.xyz --max-points 0", "--max-points", 2, {}, "", 10},
      {"max_points_octal", "eval s.json s.xyz --max-points 010", "--max-points", 2, {}, "", 10},
      {"max_points_env_word", "env IMPLICITFIT_MAX_POINTS=lots {cli} eval s.json s.xyz",
       "IMPLICITFIT_MAX_POINTS", 2, {}, "", 10},
      {"max_points_exceeded", "eval s.json s.xyz --max-points 100", "--max-points", 2, {}, "",
       10},
      {"max_points_env_exceeded", "env IMPLICITFIT_MAX_POINTS=100 {cli} fit s.xyz --model "
                                  "sphere --out m.json",
       "--max-points", 2, fit_out, "", 10},
      // Counts that only cost threads: clamped, the work done.
      {"detect_threads_huge", "detect s.xyz --threads 100000 --out o.json", "", 0, {"o.json"},
       "", 30},
      {"batch_jobs_huge", "batch s.xyz --model sphere --out-dir out --jobs 100000", "", 0, {},
       "", 30},
      {"fit_minimum_zone_20000", "fit big.xyz --model sphere --estimator minimum-zone --out m.json",
       "", 0, fit_out, "minimum zone on 20 000 points runs over 60 s", 30},
  };
  return v;
}

}  // namespace

std::vector<Case> OptionCases() {
  std::vector<Case> cases;
  int n = 0;
  for (const OptionCase& o : Options()) {
    Case c;
    c.family = "options";
    c.name = o.id;
    c.setup = [](const std::string& dir) {
      Write(dir + "/c.xyz", PlaneXyz(300));
      Write(dir + "/s.xyz", SphereXyz(400));
      Write(dir + "/s.json", SphereModel());
      Write(dir + "/q.json", PatchModel(2));
    };
    if (o.id == "fit_minimum_zone_20000")  // a noisy sphere: many exchanges of contacts
      c.setup = [](const std::string& dir) { Write(dir + "/big.xyz", NoisySphereXyz(20000, 0.01)); };
    c.args = o.args;
    c.exit_code = o.exit_code;
    if (!o.mention.empty()) c.mention = {o.mention};
    c.outputs = o.outputs;
    if (o.id.rfind("batch_", 0) == 0) c.outputs = {"out", "out/summary.csv", "out/s.model.json",
                                                  "out/s.report.json", "out/c.model.json",
                                                  "out/c.report.json"};
    if (o.exit_code == 0) c.must_exist = o.outputs;
    c.seconds = o.seconds;
    c.defect = o.defect;
    c.sanitized = (n++ % 3 == 0 || !o.defect.empty()) && o.id != "fit_minimum_zone_20000";
    cases.push_back(c);
  }
  return cases;
}

}  // namespace hostile
