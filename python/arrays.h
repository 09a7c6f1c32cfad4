// NumPy arrays <-> the library's point lists (std::vector<Eigen::Vector3d>).
//
// In: an (N, 3) array. C-contiguous float64 and float32 arrays are read in place and converted
// once, row by row, into the library's vector (the one copy the library's API needs); anything
// else NumPy can turn into an (N, 3) float64 array (lists, strided views, ints) goes through
// numpy.ascontiguousarray first. A wrong shape or a non-finite value is a ValueError naming the
// argument and, for values, the row.
// Out: the library's vectors are moved into the returned arrays (no copy): the array's base is a
// capsule that owns the vector.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace implicitfit::python {

namespace py = pybind11;
using Points = std::vector<Eigen::Vector3d>;

// An (N, 3) float64 or float32 C-contiguous array (converted if needed); ValueError for a wrong
// shape. The result keeps the data alive.
py::array CheckedRows(const py::handle& object, const char* what);

// Calls visit(i, Eigen::Vector3d) for every row of a CheckedRows array, without copying it.
template <typename Visit>
void ForEachRow(const py::array& rows, Visit&& visit) {
  const py::ssize_t n = rows.shape(0);
  if (rows.dtype().is(py::dtype::of<double>())) {
    const double* p = static_cast<const double*>(rows.data());
    for (py::ssize_t i = 0; i < n; ++i, p += 3) visit(i, Eigen::Vector3d(p[0], p[1], p[2]));
  } else {
    const float* p = static_cast<const float*>(rows.data());
    for (py::ssize_t i = 0; i < n; ++i, p += 3)
      visit(i, Eigen::Vector3d(double(p[0]), double(p[1]), double(p[2])));
  }
}

// Points: finite rows; ValueError naming the first bad row, or fewer than min_count rows.
Points PointsFromArray(const py::handle& object, const char* what, size_t min_count = 0);
// Normals, one per point: finite, non-zero rows, scaled to unit length (rows already of unit
// length within 1e-9 are kept bit for bit, so normals read by read_cloud fit exactly as the
// command line fits them).
Points NormalsFromArray(const py::handle& object, size_t count);

// Moves the vector into an (N, 3) float64 array (no copy).
py::array_t<double> ArrayFromPoints(Points&& points);
// Moves the vector into an (N,) float64 array (no copy).
py::array_t<double> ArrayFromValues(std::vector<double>&& values);
// Indices or labels as an (N,) int64 array (copied: the library's are int).
py::array_t<std::int64_t> ArrayFromIndices(const std::vector<int>& values);

}  // namespace implicitfit::python
