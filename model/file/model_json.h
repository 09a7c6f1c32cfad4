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

// What the evaluators handle, and what meshing, sampling and checking a model can do in bounded
// time (docs/model-file.md, "Limits"), refused at read time with the field's path:
// every number |x| <= kMaxModelMagnitude (squares overflow from 1.3e154, products of a few
// magnitudes must stay finite); positive lengths (radii, widths, half sizes, delta, epsilon)
// >= kMinModelLength; a Bernstein patch or mesh of degree <= kMaxPatchDegree (meshing a
// degree-10 patch at the default grid: 16 s; degree 20: 3 minutes); at most
// kMaxModelElements blobs, skeleton elements or features in one node, and kMaxModelNodes nodes.
constexpr double kMaxModelMagnitude = 1e15;
constexpr double kMinModelLength = 1e-12;
constexpr int kMaxPatchDegree = 10;
constexpr long long kMaxModelElements = 10000;
constexpr long long kMaxModelNodes = 10000;

class ModelFormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Model ModelFromJson(const nlohmann::json& document);
nlohmann::json ModelToJson(const Model& model);

}  // namespace implicitfit
