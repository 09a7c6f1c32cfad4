// The model file, version 1 (docs/model-file.md, a public contract):
//   {"format": "implicitfit-model", "version": 1, "root": NODE}
// Reading is strict: a missing or unknown field, a wrong type, a non-finite number or an
// invalid value (radius <= 0, zero axis, epsilon > delta, ...) is refused with a
// ModelFormatError whose message names the JSON path of the offending field, e.g.
// "root.children[1].radius: must be > 0". Nothing is silently dropped or misread.
// Writing emits every parameter as stored, with round-trip precision, so
// read(write(m)) has exactly m's parameters.
// Nesting: a tree deeper than kMaxModelDepth levels (the root is level 1) is refused, with the
// path of the first node too deep (shortened in the middle), so that reading and every recursive
// walk over the tree (evaluation, parameters, sampling) stay far from the stack's limit.
// Extension (documented in docs/model-file.md): any node may carry "fixed": [field names], the
// parameters a fitter keeps constant.
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "model/model.h"

namespace implicitfit {

constexpr int kMaxModelDepth = 256;

class ModelFormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Model ModelFromJson(const nlohmann::json& document);
nlohmann::json ModelToJson(const Model& model);

}  // namespace implicitfit
