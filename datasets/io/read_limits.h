// The limits every reader enforces before it allocates (docs/cli.md, "Limits"): how many points a
// cloud file (or a labels file, or `sample --count`) may hold, and how large a JSON file (model,
// scene) or a batch manifest may be. A file over a limit is refused with InputError naming the
// file, the limit and how to raise it; nothing is read past it. Process-wide: the command line
// sets them once from --max-points / --max-json-mb (or IMPLICITFIT_MAX_POINTS,
// IMPLICITFIT_MAX_JSON_MB) before any file is read.
#pragma once

#include <cstddef>

namespace implicitfit {

struct ReadLimits {
  // Points (records) of one cloud file, lines of a labels file, `sample --count`. 10^8 points
  // take 4.8 GB as doubles with normals.
  unsigned long long max_points = 100000000ULL;
  // Bytes of a model or scene file, a batch manifest (parsed whole: a JSON document in memory
  // takes about 10x its text).
  unsigned long long max_text_bytes = 64ULL << 20;
  // Bytes of one line of a text cloud or labels file (lines are short; a file of one endless
  // line is refused there instead of filling memory).
  std::size_t max_line_bytes = 1 << 16;
};

const ReadLimits& CurrentReadLimits();
void SetReadLimits(const ReadLimits& limits);

}  // namespace implicitfit
