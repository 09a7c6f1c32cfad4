#include "view/page_html.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "datasets/io/atomic_file.h"
#include "view/base64.h"
#include "view/page_assets.h"

namespace implicitfit {
namespace {

using Json = nlohmann::json;

template <typename T>
std::string Encode(const std::vector<T>& values) {
  return Base64Encode(values.data(), values.size() * sizeof(T));
}

std::vector<double> Vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

struct Box {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = Eigen::Vector3d::Constant(-HUGE_VAL);
  void Add(const Eigen::Vector3d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bool Empty() const { return !(lo.array() <= hi.array()).all(); }
};

// The colour map's saturation: the 95th percentile of |r| (so that a few outliers do not wash
// the map out), else the largest |r|, else 1.
double ResidualScale(const std::vector<double>& residuals) {
  std::vector<double> a;
  a.reserve(residuals.size());
  for (double r : residuals)
    if (std::isfinite(r)) a.push_back(std::abs(r));
  if (a.empty()) return 1.0;
  const size_t k = std::min(a.size() - 1, static_cast<size_t>(0.95 * a.size()));
  std::nth_element(a.begin(), a.begin() + k, a.end());
  if (a[k] > 0) return a[k];
  const double max = *std::max_element(a.begin(), a.end());
  return max > 0 ? max : 1.0;
}

Json LegendJson(const std::vector<LegendEntry>& legend) {
  Json out = Json::array();
  for (const LegendEntry& e : legend) {
    Json j = {{"name", e.name}, {"kind", e.kind}, {"parameters", e.parameters}};
    if (e.points >= 0) j["points"] = e.points;
    if (e.rms >= 0) j["rms"] = e.rms;
    out.push_back(j);
  }
  return out;
}

Json PointsJson(const ViewLayer& layer, size_t max_points) {
  const size_t n = layer.points.size();
  if (!layer.labels.empty() && layer.labels.size() != n)
    throw std::invalid_argument("view layer " + layer.name + ": " +
                                std::to_string(layer.labels.size()) + " labels for " +
                                std::to_string(n) + " points");
  if (!layer.residuals.empty() && layer.residuals.size() != n)
    throw std::invalid_argument("view layer " + layer.name + ": " +
                                std::to_string(layer.residuals.size()) + " residuals for " +
                                std::to_string(n) + " points");
  const size_t step = max_points > 0 && n > max_points ? (n + max_points - 1) / max_points : 1;
  Box box;
  for (size_t i = 0; i < n; i += step) box.Add(layer.points[i]);
  if (box.Empty()) box.lo = box.hi = Eigen::Vector3d::Zero();
  const Eigen::Vector3d extent = box.hi - box.lo;
  std::vector<std::uint16_t> q;
  std::vector<float> residuals;
  std::vector<int> labels;
  int max_label = -1, min_label = 0;
  for (size_t i = 0; i < n; i += step) {
    for (int k = 0; k < 3; ++k) {
      const double t = extent[k] > 0 ? (layer.points[i][k] - box.lo[k]) / extent[k] : 0.0;
      q.push_back(static_cast<std::uint16_t>(std::lround(std::clamp(t, 0.0, 1.0) * 65535.0)));
    }
    if (!layer.labels.empty()) {
      labels.push_back(std::max(-1, layer.labels[i]));
      max_label = std::max(max_label, labels.back());
      min_label = std::min(min_label, labels.back());
    }
    if (!layer.residuals.empty()) {
      const double r = layer.residuals[i];
      residuals.push_back(std::isnan(r) ? 0.0f : static_cast<float>(r));
    }
  }
  const size_t count = q.size() / 3;
  std::string note = layer.note;
  if (step > 1)
    note += (note.empty() ? "" : "; ") + std::string("1 point in ") + std::to_string(step) +
            " of " + std::to_string(n) + " shown";
  Json j = {{"type", "points"},          {"name", layer.name},   {"note", note},
            {"count", count},            {"origin", Vec(box.lo)}, {"extent", Vec(extent)},
            {"positions", Encode(q)},    {"colour", layer.colour}};
  if (!labels.empty()) {
    if (max_label <= 32767) {
      std::vector<std::int16_t> l(labels.begin(), labels.end());
      j["labels"] = {{"type", "int16"}, {"data", Encode(l)}};
    } else {
      std::vector<std::int32_t> l(labels.begin(), labels.end());
      j["labels"] = {{"type", "int32"}, {"data", Encode(l)}};
    }
    j["legend"] = LegendJson(layer.legend);
    j["legend_title"] = layer.legend_title;
  }
  if (!residuals.empty()) {
    j["residuals"] = Encode(residuals);
    j["residual_scale"] =
        layer.residual_scale > 0 ? layer.residual_scale : ResidualScale(layer.residuals);
    j["residual_title"] = layer.residual_title;
    j["residual_note"] = layer.residual_note;
  }
  return j;
}

Json MeshJson(const ViewLayer& layer) {
  const TriangleMesh& m = layer.mesh;
  Box box;
  for (const Eigen::Vector3d& v : m.vertices) box.Add(v);
  const Eigen::Vector3d origin =
      box.Empty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(0.5 * (box.lo + box.hi));
  std::vector<float> vertices;
  vertices.reserve(3 * m.vertices.size());
  for (const Eigen::Vector3d& v : m.vertices)
    for (int k = 0; k < 3; ++k) vertices.push_back(static_cast<float>(v[k] - origin[k]));
  std::vector<std::uint32_t> triangles;
  triangles.reserve(3 * m.triangles.size());
  for (const Eigen::Vector3i& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      if (t[k] < 0 || static_cast<size_t>(t[k]) >= m.vertices.size())
        throw std::invalid_argument("view layer " + layer.name + ": a triangle indexes vertex " +
                                    std::to_string(t[k]) + " of " +
                                    std::to_string(m.vertices.size()));
      triangles.push_back(static_cast<std::uint32_t>(t[k]));
    }
  Json j = {{"type", "mesh"},
            {"name", layer.name},
            {"note", layer.note},
            {"origin", Vec(origin)},
            {"vertices", Encode(vertices)},
            {"triangles", Encode(triangles)},
            {"triangle_count", m.triangles.size()},
            {"colour", layer.mesh_colour}};
  if (m.normals.size() == m.vertices.size() && !m.normals.empty()) {
    std::vector<std::int8_t> normals;
    normals.reserve(3 * m.normals.size());
    for (const Eigen::Vector3d& n : m.normals) {
      const Eigen::Vector3d u =
          n.allFinite() && n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) normals.push_back(static_cast<std::int8_t>(std::lround(u[k] * 127.0)));
    }
    j["normals"] = Encode(normals);
  }
  return j;
}

// The template with each marker replaced, in the order they appear (so that no inserted text is
// searched for the next marker).
std::string FillTemplate(std::string_view text,
                         const std::vector<std::pair<std::string, std::string_view>>& parts) {
  std::string out;
  size_t from = 0;
  for (const auto& [marker, content] : parts) {
    const size_t at = text.find(marker, from);
    if (at == std::string_view::npos)
      throw std::logic_error("view/page.html lacks the marker " + marker + " (in this order)");
    out.append(text.substr(from, at - from));
    out.append(content);
    from = at + marker.size();
  }
  out.append(text.substr(from));
  return out;
}

}  // namespace

std::string HtmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string PageHtml(const ViewPage& page) {
  if (ThreeJs().empty() || OrbitControlsJs().empty())
    throw std::runtime_error(
        "this implicitfit was built without three.js: install Debian's libjs-three "
        "(scripts/setup.sh) and rebuild to write view pages");
  Json layers = Json::array();
  Box box;
  for (const ViewLayer& layer : page.layers) {
    if (layer.is_mesh) {
      layers.push_back(MeshJson(layer));
      for (const Eigen::Vector3d& v : layer.mesh.vertices) box.Add(v);
    } else {
      layers.push_back(PointsJson(layer, page.max_points));
      for (const Eigen::Vector3d& p : layer.points) box.Add(p);
    }
  }
  if (box.Empty()) box.lo = -Eigen::Vector3d::Ones(), box.hi = Eigen::Vector3d::Ones();
  Json options = Json::object();
  for (const auto& [key, value] : page.options) options[key] = value;
  const Json data = {{"title", page.title},
                     {"options", options},
                     {"notes", page.notes},
                     {"centre", Vec(0.5 * (box.lo + box.hi))},
                     {"box_min", Vec(box.lo)},
                     {"box_max", Vec(box.hi)},
                     {"layers", layers}};
  // In a <script> element the text must not hold "</" or "<!--": every '<' (only ever inside a
  // JSON string) becomes the JSON escape \u003c.
  const std::string json = data.dump(-1, ' ', false, Json::error_handler_t::replace);
  std::string safe;
  safe.reserve(json.size());
  for (char c : json) {
    if (c == '<')
      safe += "\\u003c";
    else
      safe += c;
  }
  const std::string title = HtmlEscape(page.title);
  return FillTemplate(PageTemplate(), {{"@IMPLICITFIT_TITLE@", title},
                                       {"/*@IMPLICITFIT_THREE@*/", ThreeJs()},
                                       {"/*@IMPLICITFIT_ORBIT@*/", OrbitControlsJs()},
                                       {"@IMPLICITFIT_DATA@", safe},
                                       {"/*@IMPLICITFIT_VIEWER@*/", ViewerScript()}});
}

void WritePage(const ViewPage& page, const std::string& path) {
  WriteFileAtomically(path, PageHtml(page));
}

}  // namespace implicitfit
