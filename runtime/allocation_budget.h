// A budget for the memory one thread allocates while an AllocationBudget lives: the generic guard
// of model loading. assimp's importers trust the counts and sizes a file declares (an OFF
// vertex count, a glTF accessor count, an FBX array length, a 3DS chunk size...) and allocate
// for them before reading; a few bytes can ask for many gigabytes. Rather than a pre-scan per
// format, every allocation on the loading thread is checked against the budget before the
// memory is taken, and one that would exceed it fails as out of memory does: operator new throws
// std::bad_alloc, which the importer reports as a failed import, and malloc, calloc, realloc and
// the aligned forms return null (allocation_budget.cpp replaces them in the executable; under a
// sanitizer, which owns malloc, only operator new is counted).
#pragma once

#include <cstdint>

namespace rsaa {

class AllocationBudget {
 public:
  // Allocations on this thread count against `limit_bytes` until the destructor. Budgets do
  // not nest (a second on the same thread throws std::logic_error).
  explicit AllocationBudget(std::uint64_t limit_bytes);
  ~AllocationBudget();
  AllocationBudget(const AllocationBudget&) = delete;
  AllocationBudget& operator=(const AllocationBudget&) = delete;

  // The budget of the calling thread (null: none), e.g. for a fault handler to tell whether an
  // allocation was refused before the fault.
  static const AllocationBudget* on_this_thread();
  // Whether malloc and its family are counted in this build (false under a sanitizer).
  static bool counts_malloc();

  void raise_limit(std::uint64_t more_bytes) { limit_ += more_bytes; }
  std::uint64_t limit() const { return limit_; }
  // Bytes live now (allocated minus freed within the budget's life) and at most.
  std::int64_t live() const { return live_; }
  std::int64_t peak() const { return peak_; }
  // The first request refused (0: none): its size and the bytes live when it came.
  std::uint64_t refused_request() const { return refused_request_; }
  std::int64_t live_when_refused() const { return live_when_refused_; }

  // For the allocation functions (allocation_budget.cpp).
  bool admit(std::uint64_t bytes);
  void allocated(std::uint64_t bytes);
  void freed(std::uint64_t bytes) { live_ -= static_cast<std::int64_t>(bytes); }

 private:
  std::uint64_t limit_;
  std::int64_t live_ = 0, peak_ = 0, live_when_refused_ = 0;
  std::uint64_t refused_request_ = 0;
};

}  // namespace rsaa
