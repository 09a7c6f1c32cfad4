// The `implicitfit` Python module: the library's fits, models and clouds with NumPy arrays in
// and out (docs/python.md). Errors become Python exceptions with the command line's messages:
//   InputError (a file cannot be read or written, or is invalid)  -> OSError
//   ModelFormatError, std::invalid_argument (invalid values)       -> ValueError
//   other std::runtime_error (e.g. sampling cannot reach the zero set) -> RuntimeError
#include <glog/logging.h>
#include <pybind11/pybind11.h>

#include "datasets/io/io_error.h"
#include "model/file/model_json.h"
#include "python/bindings.h"

#ifndef IMPLICITFIT_VERSION
#define IMPLICITFIT_VERSION "unknown"
#endif

PYBIND11_MODULE(implicitfit, m) {
  namespace py = pybind11;
  using namespace implicitfit;
  m.doc() = "implicitfit: fit implicit surface models to oriented point clouds (NumPy in and out)";
  m.attr("__version__") = IMPLICITFIT_VERSION;
  // Ceres logs through glog; as on the command line, its warnings are not for users.
  FLAGS_minloglevel = google::GLOG_ERROR;

  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const ModelFormatError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  python::BindModel(m);
  python::BindFits(m);
  python::BindClouds(m);
  python::BindSample(m);
  python::BindDetect(m);
  python::BindReconstruct(m);
  python::BindMesh(m);
}
