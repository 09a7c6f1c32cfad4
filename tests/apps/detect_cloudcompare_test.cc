// `detect --ply` read by a real client: CloudCompare's command line (Debian `cloudcompare`;
// skipped when it is not installed). Its silent mode loads `scalar_*` vertex properties as
// scalar fields, RGB as colours, and (with -GLOBAL_SHIFT AUTO) double coordinates without loss.
// The cloud is CGAL's two-plane crease moved to survey coordinates (500 000.125, 4 000 000.0625):
// float32 holds only multiples of 0.03125 there, so coordinates within 1e-5 of the input prove the
// file carries doubles. Expected values come from the input file and the labels file `detect`
// writes beside the PLY (the contract the PLY must repeat), not from the PLY itself.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "support/run_command.h"

namespace {

using testsupport::RunCommand;
const std::string kCli = IMPLICITFIT_CLI;

bool HasCloudCompare() { return std::system("command -v CloudCompare > /dev/null 2>&1") == 0; }

std::vector<std::vector<double>> ReadRows(const std::string& path, std::string* header) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("//", 0) == 0) {
      if (header) *header = line;
      continue;
    }
    std::istringstream fields(line);
    std::vector<double> row;
    for (double v; fields >> v;) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

TEST(DetectCloudCompare, ReadsLabelsResidualsColoursAndDoubleCoordinates) {
  if (!HasCloudCompare()) GTEST_SKIP() << "CloudCompare is not installed (Debian: cloudcompare)";
  const std::string dir = testsupport::ScratchDir("detect_cloudcompare");
  const auto input = ReadRows(
      std::string(IMPLICITFIT_SOURCE_DIR) + "/datasets/data/cgal_fin90_two_planes_crease.xyz",
      nullptr);
  ASSERT_GT(input.size(), 700u);
  {
    std::ofstream out(dir + "/survey.xyz");
    out.precision(17);
    for (const auto& r : input)
      out << r[0] + 500000.125 << ' ' << r[1] + 4000000.0625 << ' ' << r[2] << ' ' << r[3] << ' '
          << r[4] << ' ' << r[5] << '\n';
  }
  const auto d =
      RunCommand(kCli + " detect " + dir + "/survey.xyz --quiet --out " + dir +
                 "/scene.json --labels " + dir + "/labels.txt --ply " + dir + "/seg.ply");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  const auto cc = RunCommand("cd " + dir +
                             " && QT_QPA_PLATFORM=offscreen timeout 120 CloudCompare -SILENT -O "
                             "-GLOBAL_SHIFT AUTO seg.ply -C_EXPORT_FMT ASC -ADD_HEADER -PREC 8 "
                             "-SAVE_CLOUDS FILE out.asc");
  ASSERT_EQ(cc.exit_code, 0) << cc.out << cc.err;
  std::string header;
  const auto rows = ReadRows(dir + "/out.asc", &header);
  ASSERT_EQ(rows.size(), input.size()) << header;
  // Columns by name: CloudCompare names the scalar fields after the properties.
  std::istringstream names(header.substr(2));
  std::map<std::string, size_t> column;
  size_t k = 0;
  for (std::string name; names >> name;) column[name] = k++;
  for (const char* name : {"X", "Y", "Z", "R", "G", "B", "label", "residual"})
    ASSERT_TRUE(column.count(name)) << name << " not loaded: " << header;
  std::ifstream labels_file(dir + "/labels.txt");
  std::vector<int> labels;
  for (int l; labels_file >> l;) labels.push_back(l);
  ASSERT_EQ(labels.size(), input.size());
  std::map<int, std::tuple<int, int, int>> colour_of;
  std::set<std::tuple<int, int, int>> colours;
  double worst = 0, largest_residual = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    worst = std::max({worst, std::abs(r[column["X"]] - (input[i][0] + 500000.125)),
                      std::abs(r[column["Y"]] - (input[i][1] + 4000000.0625)),
                      std::abs(r[column["Z"]] - input[i][2])});
    EXPECT_EQ(static_cast<int>(r[column["label"]]), labels[i]) << "point " << i;
    largest_residual = std::max(largest_residual, std::abs(r[column["residual"]]));
    const auto rgb =
        std::make_tuple(static_cast<int>(r[column["R"]]), static_cast<int>(r[column["G"]]),
                        static_cast<int>(r[column["B"]]));
    const auto [it, fresh] = colour_of.emplace(labels[i], rgb);
    EXPECT_EQ(it->second, rgb) << "one colour per primitive, point " << i;
    if (fresh) colours.insert(rgb);
  }
  EXPECT_LE(worst, 1e-5) << "coordinates lost precision (float32 steps 0.03125 here)";
  EXPECT_EQ(colours.size(), colour_of.size()) << "each primitive its own colour";
  EXPECT_GE(colour_of.size(), 2u);   // the crease's two planes
  EXPECT_GT(largest_residual, 0.0);  // residuals came through (not all zero)
}

}  // namespace
