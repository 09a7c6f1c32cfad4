// The parts of the `implicitfit` Python module, each adding its functions and classes to it.
#pragma once

#include <pybind11/pybind11.h>

namespace implicitfit::python {

void BindModel(pybind11::module_& m);  // Model (model_binding.cc)
void BindFits(pybind11::module_& m);   // fit, FitResult, fit_tree, fit_patch (fit_binding.cc)
void BindClouds(pybind11::module_& m);  // read_cloud, estimate_normals, check (cloud_binding.cc)
void BindSample(pybind11::module_& m);  // sample, SampleResult (sample_binding.cc)
void BindDetect(pybind11::module_& m);       // detect, DetectResult (detect_binding.cc)
void BindReconstruct(pybind11::module_& m);  // reconstruct (reconstruct_binding.cc)
void BindMesh(pybind11::module_& m);         // mesh (mesh_binding.cc)

}  // namespace implicitfit::python
