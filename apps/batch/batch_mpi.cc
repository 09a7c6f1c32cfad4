#include "apps/batch/batch_mpi.h"

#include <mpi.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "datasets/io/output_path.h"

namespace implicitfit {
namespace {

constexpr int kWork = 1, kStop = 2, kResult = 3;

int EnvInt(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : 0;
}

std::string EncodeOutcome(size_t index, const BatchOutcome& o) {
  return nlohmann::json{{"index", index},     {"status", static_cast<int>(o.status)},
                        {"rms", o.rms},       {"inliers", o.inliers},
                        {"points", o.points}, {"seconds", o.seconds},
                        {"error", o.error}}
      .dump();
}

// Fills the outcome at its index; returns the index.
size_t DecodeOutcome(const std::string& text, const std::vector<BatchInput>& inputs,
                     std::vector<BatchOutcome>* outcomes) {
  const nlohmann::json j = nlohmann::json::parse(text);
  const size_t index = j.at("index").get<size_t>();
  BatchOutcome& o = outcomes->at(index);
  o.input = inputs[index].path;
  o.name = inputs[index].name;
  o.status = static_cast<BatchStatus>(j.at("status").get<int>());
  o.rms = j.at("rms").get<double>();
  o.inliers = j.at("inliers").get<size_t>();
  o.points = j.at("points").get<size_t>();
  o.seconds = j.at("seconds").get<double>();
  o.error = j.at("error").get<std::string>();
  return index;
}

// Receives one result (from any worker) into outcomes; returns the sender.
int ReceiveResult(const std::vector<BatchInput>& inputs, std::vector<BatchOutcome>* outcomes,
                  const BatchProgressCallback& on_done) {
  MPI_Status status;
  MPI_Probe(MPI_ANY_SOURCE, kResult, MPI_COMM_WORLD, &status);
  int length = 0;
  MPI_Get_count(&status, MPI_CHAR, &length);
  std::string text(static_cast<size_t>(length), '\0');
  MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, kResult, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  const size_t index = DecodeOutcome(text, inputs, outcomes);
  if (on_done) on_done((*outcomes)[index]);
  return status.MPI_SOURCE;
}

void SendWork(int worker, size_t index) {
  const unsigned long long i = index;
  MPI_Send(&i, 1, MPI_UNSIGNED_LONG_LONG, worker, kWork, MPI_COMM_WORLD);
}
void SendStop(int worker) { MPI_Send(nullptr, 0, MPI_CHAR, worker, kStop, MPI_COMM_WORLD); }

std::vector<BatchOutcome> Coordinate(const std::vector<BatchInput>& inputs,
                                     const BatchOptions& options,
                                     const BatchProgressCallback& on_done, int size) {
  RemoveStaleTemporaries(options.out_dir);  // before any worker starts writing (killed runs only)
  std::vector<BatchOutcome> outcomes(inputs.size());
  // Every worker holds up to kQueued inputs, so it never waits for rank 0 between two fits
  // (rank 0 answers only between its own fits); a worker with none left is stopped.
  constexpr int kQueued = 2;
  size_t next = 0;
  std::vector<int> queued(size, 0);
  int busy = 0;
  for (int worker = 1; worker < size; ++worker) {
    for (int k = 0; k < kQueued && next < inputs.size(); ++k, ++queued[worker])
      SendWork(worker, next++);
    if (queued[worker] == 0) SendStop(worker);
    busy += queued[worker] > 0;
  }
  while (busy > 0 || next < inputs.size()) {
    int waiting = 0;
    MPI_Iprobe(MPI_ANY_SOURCE, kResult, MPI_COMM_WORLD, &waiting, MPI_STATUS_IGNORE);
    if (waiting || next >= inputs.size()) {
      const int worker = ReceiveResult(inputs, &outcomes, on_done);
      --queued[worker];
      if (next < inputs.size()) {
        SendWork(worker, next++);
        ++queued[worker];
      } else if (queued[worker] == 0) {
        SendStop(worker);
        --busy;
      }
    } else {
      const size_t index = next++;  // nobody waits for work: rank 0 fits one itself
      outcomes[index] = ProcessBatchInput(inputs[index], options);
      if (on_done) on_done(outcomes[index]);
    }
  }
  return outcomes;
}

void Work(const std::vector<BatchInput>& inputs, const BatchOptions& options) {
  while (true) {
    MPI_Status status;
    MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    if (status.MPI_TAG == kStop) {
      MPI_Recv(nullptr, 0, MPI_CHAR, 0, kStop, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      return;
    }
    unsigned long long index = 0;
    MPI_Recv(&index, 1, MPI_UNSIGNED_LONG_LONG, 0, kWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    const std::string text = EncodeOutcome(index, ProcessBatchInput(inputs.at(index), options));
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kResult, MPI_COMM_WORLD);
  }
}

}  // namespace

bool LaunchedUnderMpi() {
  return EnvInt("OMPI_COMM_WORLD_SIZE") > 1 || EnvInt("PMI_SIZE") > 1 || EnvInt("PMIX_SIZE") > 1;
}

MpiSession::MpiSession() {
  MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

std::vector<BatchOutcome> RunBatchOverMpi(const std::vector<BatchInput>& inputs,
                                          const BatchOptions& options,
                                          const BatchProgressCallback& on_done) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (rank == 0) return Coordinate(inputs, options, on_done, size);
  Work(inputs, options);
  return {};
}

}  // namespace implicitfit
