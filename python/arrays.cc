#include "python/arrays.h"

#include <cmath>
#include <cstring>
#include <string>

namespace implicitfit::python {

py::array CheckedRows(const py::handle& object, const char* what) {
  py::array rows;
  const bool c_contiguous_float =
      py::isinstance<py::array>(object) &&
      (py::isinstance<py::array_t<double, py::array::c_style>>(object) ||
       py::isinstance<py::array_t<float, py::array::c_style>>(object));
  if (c_contiguous_float) {
    rows = py::reinterpret_borrow<py::array>(object);
  } else {
    try {
      rows = py::module_::import("numpy").attr("ascontiguousarray")(object, "float64");
    } catch (const py::error_already_set& e) {
      throw py::value_error(std::string(what) + ": not convertible to an (N, 3) float64 array (" +
                            e.what() + ")");
    }
  }
  if (rows.ndim() != 2 || rows.shape(1) != 3) {
    std::string shape = "(";
    for (py::ssize_t d = 0; d < rows.ndim(); ++d)
      shape += (d ? ", " : "") + std::to_string(rows.shape(d));
    shape += rows.ndim() == 1 ? ",)" : ")";
    throw py::value_error(std::string(what) + ": expected an (N, 3) array, got shape " + shape);
  }
  return rows;
}

Points PointsFromArray(const py::handle& object, const char* what, size_t min_count) {
  const py::array rows = CheckedRows(object, what);
  if (static_cast<size_t>(rows.shape(0)) < min_count)
    throw py::value_error(std::string(what) + ": " + std::to_string(rows.shape(0)) +
                          " points, at least " + std::to_string(min_count) + " are needed");
  Points points(rows.shape(0));
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "Vector3d must be 3 packed doubles");
  if (rows.dtype().is(py::dtype::of<double>()) && !points.empty())
    std::memcpy(points.front().data(), rows.data(), points.size() * sizeof(Eigen::Vector3d));
  else
    ForEachRow(rows, [&](py::ssize_t i, const Eigen::Vector3d& p) { points[i] = p; });
  // One vectorised pass over all coordinates; the row is looked for only when one is bad.
  const auto all =
      Eigen::Map<const Eigen::ArrayXd>(points.empty() ? nullptr : points.front().data(),
                                       3 * static_cast<Eigen::Index>(points.size()));
  py::ssize_t bad = -1;
  if (!all.allFinite())
    for (size_t i = 0; i < points.size() && bad < 0; ++i)
      if (!points[i].allFinite()) bad = static_cast<py::ssize_t>(i);
  if (bad >= 0)
    throw py::value_error(std::string(what) + "[" + std::to_string(bad) +
                          "]: not a finite number (NaN or infinity)");
  return points;
}

Points NormalsFromArray(const py::handle& object, size_t count) {
  Points normals = PointsFromArray(object, "normals");
  if (normals.size() != count)
    throw py::value_error("normals: " + std::to_string(normals.size()) + " rows for " +
                          std::to_string(count) + " points");
  for (size_t i = 0; i < normals.size(); ++i) {
    const double squared = normals[i].squaredNorm();
    if (std::abs(squared - 1.0) <= 2e-9) continue;  // unit within 1e-9: kept bit for bit
    if (squared == 0.0) throw py::value_error("normals[" + std::to_string(i) + "]: zero vector");
    normals[i] /= std::sqrt(squared);
  }
  return normals;
}

py::array_t<double> ArrayFromPoints(Points&& points) {
  auto* owned = new Points(std::move(points));
  py::capsule owner(owned, [](void* p) { delete static_cast<Points*>(p); });
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "Vector3d must be 3 packed doubles");
  const py::ssize_t n = static_cast<py::ssize_t>(owned->size());
  return py::array_t<double>({n, py::ssize_t(3)},
                             {py::ssize_t(3 * sizeof(double)), py::ssize_t(sizeof(double))},
                             owned->empty() ? nullptr : owned->front().data(), owner);
}

py::array_t<double> ArrayFromValues(std::vector<double>&& values) {
  auto* owned = new std::vector<double>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>({static_cast<py::ssize_t>(owned->size())},
                             {py::ssize_t(sizeof(double))}, owned->data(), owner);
}

py::array_t<std::int64_t> ArrayFromIndices(const std::vector<int>& values) {
  py::array_t<std::int64_t> out(static_cast<py::ssize_t>(values.size()));
  std::int64_t* data = out.mutable_data();
  for (size_t i = 0; i < values.size(); ++i) data[i] = values[i];
  return out;
}

}  // namespace implicitfit::python
