// Result classes that also unpack as the pair their function used to return (`a, b = f(...)`,
// `f(...)[0]`): __iter__, __len__ and __getitem__ over Result::AsTuple().
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace implicitfit::python {

// `message`: the IndexError's, e.g. "FitResult unpacks as (model, report)".
template <typename Result>
void UnpacksAsPair(pybind11::class_<Result>& cls, const std::string& message) {
  namespace py = pybind11;
  cls.def("__iter__", [](const Result& r) { return py::iter(r.AsTuple()); })
      .def("__len__", [](const Result&) { return 2; })
      .def("__getitem__", [message](const Result& r, py::ssize_t i) -> py::object {
        if (i < -2 || i > 1) throw py::index_error(message);
        return r.AsTuple()[i < 0 ? i + 2 : i];
      });
}

}  // namespace implicitfit::python
