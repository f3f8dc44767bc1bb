#include "runtime/allocation_budget.h"

#include <malloc.h>

#include <cstdlib>
#include <new>
#include <stdexcept>

namespace rsaa {
namespace {
thread_local AllocationBudget* t_budget = nullptr;
}  // namespace

AllocationBudget::AllocationBudget(std::uint64_t limit_bytes) : limit_(limit_bytes) {
  if (t_budget) throw std::logic_error("allocation budgets do not nest");
  t_budget = this;
}

AllocationBudget::~AllocationBudget() { t_budget = nullptr; }

bool AllocationBudget::admit(std::uint64_t bytes) {
  if (live_ < 0 || std::uint64_t(live_) + bytes <= limit_) return true;
  if (refused_request_ == 0) refused_request_ = bytes, live_when_refused_ = live_;
  return false;
}

void AllocationBudget::allocated(std::uint64_t bytes) {
  live_ += static_cast<std::int64_t>(bytes);
  if (live_ > peak_) peak_ = live_;
}

}  // namespace rsaa

// The replaceable global allocation functions (the array, nothrow and sized forms of libstdc++
// call these two). Outside a budget they are malloc and free.
void* operator new(std::size_t size) {
  rsaa::AllocationBudget* budget = rsaa::t_budget;
  if (budget && !budget->admit(size)) throw std::bad_alloc();
  for (;;) {
    if (void* p = std::malloc(size ? size : 1)) {
      if (budget) budget->allocated(::malloc_usable_size(p));
      return p;
    }
    const std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

void operator delete(void* p) noexcept {
  if (!p) return;
  if (rsaa::AllocationBudget* budget = rsaa::t_budget) budget->freed(::malloc_usable_size(p));
  std::free(p);
}

void operator delete(void* p, std::size_t) noexcept { ::operator delete(p); }
