// `batch --view` (docs/batch.md, docs/view.md): after the batch, one view page per input that
// has a result (ok or skipped), DIR/<name>.view.html: the input cloud with its result file (the
// model of a primitive, Bernstein or solid fit, coloured by its residual; the scene and labels of
// `--model scene`, coloured by primitive), built by view/view_inputs.h as `implicitfit view`
// would. Then DIR/index.html (DIR/index-<i>-of-<N>.html with --shard): one row per input in
// input order with its figures (status, points, inliers, RMS, seconds, error) linking its page,
// result and report. A page that cannot be made is an error in its row, not a batch failure.
#pragma once

#include <string>
#include <vector>

#include "apps/batch/batch_runner.h"

namespace implicitfit {

// Writes the pages and the index (named index_name, inside options.out_dir) and prints
// "index: PATH (N pages)" on stdout; progress on stderr unless quiet. Returns N.
size_t WriteBatchViews(const std::vector<BatchInput>& inputs,
                       const std::vector<BatchOutcome>& outcomes, const BatchOptions& options,
                       const std::string& index_name, bool quiet);

}  // namespace implicitfit
