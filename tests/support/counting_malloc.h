#pragma once
/// \file
/// Counts the calls to malloc, calloc and realloc made while `counting` is set. The allocation
/// test binary links tests/support/counting_malloc.cpp, which interposes those functions; it is
/// a separate binary so that no other test runs with the counting allocator.

namespace geardyn::testing {

/// Counts allocations from construction to `count()`.
class AllocationCounter {
 public:
  AllocationCounter();
  ~AllocationCounter();
  AllocationCounter(const AllocationCounter&) = delete;
  AllocationCounter& operator=(const AllocationCounter&) = delete;
  /// Stops counting and returns the allocations seen.
  long count();
};

}  // namespace geardyn::testing
