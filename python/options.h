// Checks of the option values the Python functions share (seed, positive lengths), each a
// ValueError naming the option, as the command line's option validators do for its flags.
#pragma once

#include <pybind11/pybind11.h>

#include <cmath>
#include <limits>
#include <string>

namespace implicitfit::python {

inline unsigned SeedFrom(long long seed) {
  if (seed < 0 || seed > std::numeric_limits<unsigned>::max())
    throw pybind11::value_error("seed: must be in [0, 2^32 - 1], got " + std::to_string(seed));
  return static_cast<unsigned>(seed);
}

// A finite number > 0, else ValueError "<what>: must be a positive number".
inline double PositiveFrom(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw pybind11::value_error(std::string(what) + ": must be a positive number");
  return value;
}

}  // namespace implicitfit::python
