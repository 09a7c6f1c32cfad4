// `implicitfit batch` over MPI ranks (built when CMake finds MPI: IMPLICITFIT_WITH_MPI).
// Started as `mpirun -np P implicitfit batch ...`, every rank expands the same input list; then
//   rank 0 removes stale temporaries, hands out input indices, two queued per worker (a rank
//   that finishes one gets the next: dynamic load balancing), fits inputs itself whenever no result
//   is waiting, collects every outcome and writes the summary; ranks 1..P-1 fit the inputs they are
//   sent (apps/batch/batch_runner.h ProcessBatchInput, one at a time, single-threaded Ceres) and send
//   back their outcome, until told to stop.
// Messages (MPI_COMM_WORLD): rank 0 -> worker: tag kWork, one unsigned long long index, or tag
// kStop, no data; worker -> rank 0: tag kResult, the outcome as JSON text.
// Outputs are the same files as a single process writes, so --resume and --shard work as there.
#pragma once

#include <vector>

#include "apps/batch/batch_runner.h"

namespace implicitfit {

// True when this process was started by mpirun/srun among more than one rank (environment of
// Open MPI, MPICH/PMI or PMIx), without initialising MPI.
bool LaunchedUnderMpi();

// MPI_Init on construction, MPI_Finalize on destruction.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
};

// Collective over MPI_COMM_WORLD. Returns every outcome, in input order, on rank 0 (on_done is
// called there as they arrive), and an empty vector on the other ranks.
std::vector<BatchOutcome> RunBatchOverMpi(const std::vector<BatchInput>& inputs,
                                          const BatchOptions& options,
                                          const BatchProgressCallback& on_done);

}  // namespace implicitfit
