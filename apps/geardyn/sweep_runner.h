#pragma once
/// \file
/// Where the cases of a sweep run: a local thread pool, or MPI ranks fed by a dynamic work queue
/// (rank 0 hands out one case at a time to whichever rank asks, so cases of unequal cost balance
/// themselves) with rank 0 gathering every record. Without mpirun the same binary runs on
/// threads only; MPI (libgeardyn_mpi.so, see mpi_transport.h) is loaded and initialised only
/// when the process was started by an MPI launcher.

#include <functional>
#include <vector>

#include "geardyn/analysis/sweep_results.h"
#include "geardyn/config/sweep_config.h"

namespace geardyn::cli {

struct MpiTransport;

using CaseFunction = std::function<analysis::SweepCaseRecord(long long index)>;
/// Called on the calling thread (rank 0), one record at a time.
using DoneFunction = std::function<void(const analysis::SweepCaseRecord&)>;

/// Runs the `pending` cases on `threads` worker threads.
void runCasesOnThreads(const std::vector<long long>& pending, int threads,
                       const CaseFunction& run_case, const DoneFunction& done);

/// True when an MPI launcher started this process (OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_RANK
/// set).
bool launchedByMpi();

/// The MPI world of this run, initialised on construction and finalised on destruction.
class MpiWorld {
 public:
  /// Loads libgeardyn_mpi.so and initialises MPI; InputError when geardyn was built without MPI.
  MpiWorld();
  ~MpiWorld();
  MpiWorld(const MpiWorld&) = delete;
  MpiWorld& operator=(const MpiWorld&) = delete;
  int rank() const noexcept { return rank_; }
  int size() const noexcept { return size_; }
  /// Rank 0: dispatches `pending` to the other ranks and to `threads` local worker threads,
  /// calling `done` for every record. Other ranks: run what rank 0 sends (`pending` unused).
  void runCases(const std::vector<long long>& pending, int threads, const CaseFunction& run_case,
                const DoneFunction& done);
  /// Broadcasts an error flag from rank 0 (so that all ranks stop on bad input together).
  bool agree(bool ok_on_root);

 private:
  const MpiTransport* mpi_;
  int rank_ = 0, size_ = 1;
};

}  // namespace geardyn::cli
