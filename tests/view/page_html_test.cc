// The HTML of view pages (view/page_html.h): a page of 10^6 labelled points with residuals stays
// within 20 MB; its data decodes back (independent base64 decoder) to the points within the
// 16-bit quantisation, the labels and the residuals as float; text from the user cannot close
// the page's <script> elements; mismatched layers are refused; nothing is loaded from outside.
#include "view/page_html.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <random>

#include "support/base64_decode.h"

namespace implicitfit {
namespace {

using testsupport::Base64Decode;

nlohmann::json PageData(const std::string& html) {
  const std::string open = "<script id=\"implicitfit-view-data\" type=\"application/json\">";
  const size_t begin = html.find(open);
  EXPECT_NE(begin, std::string::npos);
  const size_t end = html.find("</script>", begin);
  return nlohmann::json::parse(html.substr(begin + open.size(), end - begin - open.size()));
}

template <typename T>
std::vector<T> Array(const std::string& base64) {
  const std::vector<unsigned char> bytes = Base64Decode(base64);
  std::vector<T> out(bytes.size() / sizeof(T));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

size_t Count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(PageHtml, MillionLabelledPointsWithResidualsFitIn20MegabytesAndDecodeBack) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-50.0, 150.0);
  ViewLayer layer;
  layer.name = "scan";
  const size_t n = 1000000;
  for (size_t i = 0; i < n; ++i) {
    layer.points.emplace_back(u(rng), 0.5 * u(rng), 1e5 + 0.01 * u(rng));  // survey-sized z
    layer.labels.push_back(static_cast<int>(i % 41) - 1);
    layer.residuals.push_back(1e-3 * u(rng));
  }
  ViewPage page;
  page.layers.push_back(layer);
  const std::string html = PageHtml(page);
  EXPECT_LE(html.size(), 20u * 1000 * 1000);
  const nlohmann::json data = PageData(html);
  const nlohmann::json& l = data["layers"][0];
  ASSERT_EQ(l["count"].get<size_t>(), n);
  const std::vector<std::uint16_t> q = Array<std::uint16_t>(l["positions"]);
  const std::vector<std::int16_t> labels = Array<std::int16_t>(l["labels"]["data"]);
  const std::vector<float> residuals = Array<float>(l["residuals"]);
  ASSERT_EQ(q.size(), 3 * n);
  ASSERT_EQ(labels.size(), n);
  ASSERT_EQ(residuals.size(), n);
  double worst = 0.0;
  for (size_t i = 0; i < n; i += 997) {
    for (int k = 0; k < 3; ++k) {
      const double extent = l["extent"][k].get<double>();
      const double x = l["origin"][k].get<double>() + extent * q[3 * i + k] / 65535.0;
      worst = std::max(worst, std::abs(x - layer.points[i][k]) / extent);
    }
    EXPECT_EQ(labels[i], layer.labels[i]);
    EXPECT_EQ(residuals[i], static_cast<float>(layer.residuals[i]));
  }
  EXPECT_LE(worst, 0.5 / 65535 + 1e-12);  // rounding to the nearest of 65536 levels
}

TEST(PageHtml, UserTextCannotCloseTheScriptsAndNothingIsLoadedFromOutside) {
  ViewPage page;
  page.title = "</script><script>alert(1)</script>";
  ViewLayer layer;
  layer.name = "a</script><!--b";
  layer.points = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 3)};
  layer.legend.push_back({"</script>", "plane", "<b>", 1, 0.5});
  layer.labels = {0, -1};
  page.layers.push_back(layer);
  const std::string html = PageHtml(page);
  EXPECT_EQ(Count(html, "</script>"), 4u);  // three.js, OrbitControls, the data, the viewer
  EXPECT_EQ(Count(html, "<script"), 4u);
  EXPECT_EQ(Count(html, "<script src"), 0u);
  EXPECT_EQ(Count(html, "<link"), 0u);
  EXPECT_NE(html.find("<title>&lt;/script&gt;&lt;script&gt;alert(1)&lt;/script&gt;</title>"),
            std::string::npos);
  const nlohmann::json data = PageData(html);
  EXPECT_EQ(data["title"], page.title);
  EXPECT_EQ(data["layers"][0]["name"], "a</script><!--b");
  EXPECT_EQ(data["layers"][0]["legend"][0]["name"], "</script>");
}

TEST(PageHtml, MismatchedLayersAreRefused) {
  ViewPage page;
  ViewLayer points;
  points.points = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()};
  points.labels = {0};
  page.layers = {points};
  EXPECT_THROW(PageHtml(page), std::invalid_argument);
  points.labels.clear();
  points.residuals = {1.0, 2.0, 3.0};
  page.layers = {points};
  EXPECT_THROW(PageHtml(page), std::invalid_argument);
  ViewLayer mesh;
  mesh.is_mesh = true;
  mesh.mesh.vertices = {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()};
  mesh.mesh.triangles = {Eigen::Vector3i(0, 1, 3)};
  page.layers = {mesh};
  EXPECT_THROW(PageHtml(page), std::invalid_argument);
}

TEST(PageHtml, MeshVerticesAreRelativeToTheLayerCentreAndBigCloudsAreThinned) {
  ViewPage page;
  ViewLayer mesh;
  mesh.is_mesh = true;
  mesh.mesh.vertices = {Eigen::Vector3d(1e6, 0, 0), Eigen::Vector3d(1e6 + 1, 0, 0),
                        Eigen::Vector3d(1e6, 1, 0.25)};
  mesh.mesh.normals.assign(3, Eigen::Vector3d(0, 0, 2));
  mesh.mesh.triangles = {Eigen::Vector3i(0, 1, 2)};
  ViewLayer points;
  for (int i = 0; i < 10; ++i) points.points.emplace_back(i, 0, 0);
  page.layers = {mesh, points};
  page.max_points = 4;
  const nlohmann::json data = PageData(PageHtml(page));
  const nlohmann::json& m = data["layers"][0];
  const std::vector<float> v = Array<float>(m["vertices"]);
  ASSERT_EQ(v.size(), 9u);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(m["origin"][k].get<double>() + v[3 * i + k], mesh.mesh.vertices[i][k], 1e-6);
  const std::vector<std::int8_t> normals = Array<std::int8_t>(m["normals"]);
  ASSERT_EQ(normals.size(), 9u);
  EXPECT_EQ(normals[2], 127);  // unit normal * 127
  EXPECT_EQ(Array<std::uint32_t>(m["triangles"]), (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(data["layers"][1]["count"], 4);  // points 0, 3, 6, 9
  EXPECT_NE(data["layers"][1]["note"].get<std::string>().find("1 point in 3 of 10"),
            std::string::npos);
}

}  // namespace
}  // namespace implicitfit
