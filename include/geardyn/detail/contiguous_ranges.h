#pragma once
/// \file
/// Independent work items 0..count−1 split into `threads` contiguous ranges, the first on the
/// calling thread (the one that may report progress: geardyn/progress.h), the others on new
/// threads. Contiguous, so that each item may start from its predecessor's result (a Campbell
/// diagram's warm-started eigenproblems). If the calling thread's range throws (an interrupted
/// run: its progress callback throws), `stop` is raised, the other ranges end at their next
/// item, and the exception leaves once they are joined. The other ranges must not throw.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace geardyn::detail {

/// Calls work(first, last, on_caller, stop) per range [first, last); `work` checks
/// `stop` (a const std::atomic<bool>&) between items.
template <class Work>
void runContiguousRanges(std::size_t count, std::size_t threads, Work&& work) {
  threads = std::max<std::size_t>(1, std::min(threads, count));
  std::atomic<bool> stop{false};
  const auto first = [&](std::size_t t) { return count * t / threads; };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) {
    pool.emplace_back([&, t] { work(first(t), first(t + 1), false, stop); });
  }
  try {
    work(first(0), first(1), true, stop);
  } catch (...) {
    stop = true;
    for (auto& thread : pool) thread.join();
    throw;
  }
  for (auto& thread : pool) thread.join();
}

}  // namespace geardyn::detail
