/// Thread pool and (when built with it) the MPI work queue of `geardyn sweep`.

#include "sweep_runner.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <mutex>
#include <thread>

#include "geardyn/error.h"

#ifdef GEARDYN_HAVE_MPI
#include <mpi.h>
#endif

namespace geardyn::cli {
namespace {

/// Records finished by worker threads, handed to the calling thread.
class DoneQueue {
 public:
  void push(io::SweepCaseRecord r) {
    {
      std::lock_guard<std::mutex> lock(m_);
      q_.push_back(std::move(r));
    }
    cv_.notify_one();
  }
  /// Waits up to `wait` for records; returns what is there.
  std::deque<io::SweepCaseRecord> take(std::chrono::microseconds wait) {
    std::unique_lock<std::mutex> lock(m_);
    cv_.wait_for(lock, wait, [&] { return !q_.empty(); });
    std::deque<io::SweepCaseRecord> out;
    out.swap(q_);
    return out;
  }

 private:
  std::mutex m_;
  std::condition_variable cv_;
  std::deque<io::SweepCaseRecord> q_;
};

/// The shared queue of case indices (local threads and, under MPI, remote ranks).
class WorkQueue {
 public:
  explicit WorkQueue(const std::vector<long long>& pending) : pending_(pending) {}
  bool next(long long* index) {
    const std::size_t i = next_++;
    if (i >= pending_.size()) return false;
    *index = pending_[i];
    return true;
  }

 private:
  const std::vector<long long>& pending_;
  std::atomic<std::size_t> next_{0};
};

std::vector<std::thread> startWorkers(int threads, WorkQueue& work, const CaseFunction& run_case,
                                      DoneQueue& done) {
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) {
    pool.emplace_back([&] {
      for (long long index; work.next(&index);) done.push(run_case(index));
    });
  }
  return pool;
}

}  // namespace

void runCasesOnThreads(const std::vector<long long>& pending, int threads,
                       const CaseFunction& run_case, const DoneFunction& done) {
  WorkQueue work(pending);
  DoneQueue finished;
  auto pool = startWorkers(std::max(1, threads), work, run_case, finished);
  for (std::size_t received = 0; received < pending.size();) {
    for (const auto& r : finished.take(std::chrono::milliseconds(200))) {
      done(r);
      ++received;
    }
  }
  for (auto& t : pool) t.join();
}

bool launchedByMpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
}

#ifdef GEARDYN_HAVE_MPI

namespace {
constexpr int kTagResult = 1;  // worker → root: a record (or "" for the first request)
constexpr int kTagWork = 2;    // root → worker: a case index, −1 to stop
}  // namespace

MpiWorld::MpiWorld() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiWorld::~MpiWorld() {
  MPI_Finalize();
}

bool MpiWorld::agree(bool ok_on_root) {
  int flag = ok_on_root ? 1 : 0;
  MPI_Bcast(&flag, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return flag == 1;
}

void MpiWorld::runCases(const std::vector<long long>& pending, int threads,
                        const CaseFunction& run_case, const DoneFunction& done) {
  if (rank_ != 0) {
    std::string payload;  // empty: "ready"
    for (;;) {
      MPI_Send(payload.data(), static_cast<int>(payload.size()), MPI_CHAR, 0, kTagResult,
               MPI_COMM_WORLD);
      long long index = -1;
      MPI_Recv(&index, 1, MPI_LONG_LONG, 0, kTagWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (index < 0) return;
      payload = run_case(index).toJson().dump();
    }
  }
  // Rank 0: local workers plus a dispatcher loop on this (the only MPI) thread.
  WorkQueue work(pending);
  DoneQueue finished;
  auto pool = startWorkers(threads, work, run_case, finished);
  int stopped = 0;
  std::size_t received = 0;
  while (received < pending.size() || stopped < size_ - 1) {
    bool busy = false;
    for (const auto& r : finished.take(std::chrono::microseconds(0))) {
      done(r);
      ++received;
      busy = true;
    }
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &status);
    if (flag) {
      busy = true;
      int count = 0;
      MPI_Get_count(&status, MPI_CHAR, &count);
      std::string payload(static_cast<std::size_t>(count), '\0');
      MPI_Recv(payload.data(), count, MPI_CHAR, status.MPI_SOURCE, kTagResult, MPI_COMM_WORLD,
               MPI_STATUS_IGNORE);
      // Hand out the next case first, then record (the journal's fdatasync must not keep the
      // worker waiting).
      long long index = -1;
      if (!work.next(&index)) {
        index = -1;
        ++stopped;
      }
      MPI_Send(&index, 1, MPI_LONG_LONG, status.MPI_SOURCE, kTagWork, MPI_COMM_WORLD);
      if (!payload.empty()) {
        done(io::SweepCaseRecord::fromJson(nlohmann::json::parse(payload)));
        ++received;
      }
    }
    if (!busy) std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  for (auto& t : pool) t.join();
}

#else

MpiWorld::MpiWorld() {
  throw InputError("mpirun", "", "a geardyn built with MPI (install libopenmpi-dev and rebuild)");
}
MpiWorld::~MpiWorld() = default;
bool MpiWorld::agree(bool ok_on_root) {
  return ok_on_root;
}
void MpiWorld::runCases(const std::vector<long long>& pending, int threads,
                        const CaseFunction& run_case, const DoneFunction& done) {
  runCasesOnThreads(pending, threads, run_case, done);
}

#endif

}  // namespace geardyn::cli
