/// Thread pool and MPI work queue of `geardyn sweep` (MPI through libgeardyn_mpi.so).

#include "sweep_runner.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <mutex>
#include <thread>

#include "geardyn/error.h"
#include "geardyn/module_loader.h"
#include "mpi_transport.h"

namespace geardyn::cli {
namespace {

/// Records finished by worker threads, handed to the calling thread.
class DoneQueue {
 public:
  void push(analysis::SweepCaseRecord r) {
    {
      std::lock_guard<std::mutex> lock(m_);
      q_.push_back(std::move(r));
    }
    cv_.notify_one();
  }
  /// Waits up to `wait` for records; returns what is there.
  std::deque<analysis::SweepCaseRecord> take(std::chrono::microseconds wait) {
    std::unique_lock<std::mutex> lock(m_);
    cv_.wait_for(lock, wait, [&] { return !q_.empty(); });
    std::deque<analysis::SweepCaseRecord> out;
    out.swap(q_);
    return out;
  }

 private:
  std::mutex m_;
  std::condition_variable cv_;
  std::deque<analysis::SweepCaseRecord> q_;
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

namespace {
constexpr int kTagResult = 1;  // worker → root: a record (or "" for the first request)
constexpr int kTagWork = 2;    // root → worker: a case index, −1 to stop

const MpiTransport& loadTransport() {
  using Entry = const MpiTransport* (*)();
  void* symbol = nullptr;
  try {
    // Global: OpenMPI's own components, loaded by MPI_Init, resolve libmpi's symbols.
    symbol = loadModuleSymbol("libgeardyn_mpi.so", "geardyn_mpi_transport", true);
  } catch (const IoError& e) {
    throw InputError(
        "mpirun", "",
        std::string("a geardyn built with MPI (install libopenmpi-dev and rebuild): ") + e.what());
  }
  const MpiTransport* transport = reinterpret_cast<Entry>(symbol)();
  if (transport->version != kMpiTransportVersion)
    throw IoError("libgeardyn_mpi.so does not match this geardyn: rebuild");
  return *transport;
}

}  // namespace

MpiWorld::MpiWorld() : mpi_(&loadTransport()) {
  if (mpi_->init(&rank_, &size_) != 0) throw IoError("MPI_Init_thread failed");
}

MpiWorld::~MpiWorld() {
  mpi_->finalize();
}

bool MpiWorld::agree(bool ok_on_root) {
  int flag = ok_on_root ? 1 : 0;
  mpi_->broadcast_int(&flag);
  return flag == 1;
}

void MpiWorld::runCases(const std::vector<long long>& pending, int threads,
                        const CaseFunction& run_case, const DoneFunction& done) {
  if (rank_ != 0) {
    std::string payload;  // empty: "ready"
    for (;;) {
      mpi_->send_bytes(payload.data(), static_cast<int>(payload.size()), 0, kTagResult);
      long long index = -1;
      mpi_->receive_index(&index, 0, kTagWork);
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
    int waiting = 0, source = 0, count = 0;
    mpi_->probe_bytes(kTagResult, &waiting, &source, &count);
    if (waiting) {
      busy = true;
      std::string payload(static_cast<std::size_t>(count), '\0');
      mpi_->receive_bytes(payload.data(), count, source, kTagResult);
      // Hand out the next case first, then record (the journal's fdatasync must not keep the
      // worker waiting).
      long long index = -1;
      if (!work.next(&index)) {
        index = -1;
        ++stopped;
      }
      mpi_->send_index(index, source, kTagWork);
      if (!payload.empty()) {
        done(analysis::SweepCaseRecord::fromJson(nlohmann::json::parse(payload)));
        ++received;
      }
    }
    if (!busy) std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
  for (auto& t : pool) t.join();
}

}  // namespace geardyn::cli
