#include "runtime/allocation_budget.h"

#include <malloc.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <new>
#include <stdexcept>

// Where the budget hooks in. In a normal build this file replaces malloc and its family in the
// executable (glibc documents replacing malloc in the main program; the replacements forward to
// glibc's own __libc_malloc & co., so the heap stays glibc's and every function not replaced
// here works on the same blocks): assimp's direct malloc/realloc, and those of the libraries it
// uses (pugixml's DOM, rapidjson, zlib, minizip, draco), count, and so does operator new, which
// libstdc++ builds on malloc. Under a sanitizer, which owns malloc, only operator new is
// replaced and counted, as before.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define RSAA_BUDGET_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define RSAA_BUDGET_MALLOC 0
#endif
#endif
#ifndef RSAA_BUDGET_MALLOC
#define RSAA_BUDGET_MALLOC 1
#endif

namespace rsaa {
namespace {
// initial-exec: reading it from inside malloc must not allocate (a global-dynamic TLS access can
// call __tls_get_addr, which may allocate); the executable's static TLS block needs no call.
__attribute__((tls_model("initial-exec"))) thread_local AllocationBudget* t_budget = nullptr;
}  // namespace

AllocationBudget::AllocationBudget(std::uint64_t limit_bytes) : limit_(limit_bytes) {
  if (t_budget) throw std::logic_error("allocation budgets do not nest");
  t_budget = this;
}

AllocationBudget::~AllocationBudget() { t_budget = nullptr; }

const AllocationBudget* AllocationBudget::on_this_thread() { return t_budget; }

bool AllocationBudget::counts_malloc() { return RSAA_BUDGET_MALLOC; }

bool AllocationBudget::admit(std::uint64_t bytes) {
  // Signed: live_ goes below zero when the thread frees blocks allocated before the budget,
  // which gives the room back but never lifts the limit altogether.
  const std::uint64_t room = live_ < 0 ? limit_ + static_cast<std::uint64_t>(-live_)
                                       : limit_ - std::min<std::uint64_t>(limit_, static_cast<std::uint64_t>(live_));
  if (bytes <= room) return true;
  if (refused_request_ == 0) refused_request_ = bytes, live_when_refused_ = live_;
  return false;
}

void AllocationBudget::allocated(std::uint64_t bytes) {
  live_ += static_cast<std::int64_t>(bytes);
  if (live_ > peak_) peak_ = live_;
}

}  // namespace rsaa

#if RSAA_BUDGET_MALLOC

extern "C" {
void* __libc_malloc(std::size_t size);
void __libc_free(void* p);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
void* __libc_valloc(std::size_t size);
void* __libc_pvalloc(std::size_t size);
}

namespace {

// One allocation of `bytes` under the thread's budget (if any); `take` allocates. A refusal is
// the out-of-memory result malloc has always had: null with errno ENOMEM.
template <class Take>
inline void* budgeted(std::size_t bytes, Take take) {
  rsaa::AllocationBudget* budget = rsaa::t_budget;
  if (!budget) return take();
  if (!budget->admit(bytes)) {
    errno = ENOMEM;
    return nullptr;
  }
  void* p = take();
  if (p) budget->allocated(::malloc_usable_size(p));
  return p;
}

bool power_of_two(std::size_t v) { return v != 0 && (v & (v - 1)) == 0; }

}  // namespace

extern "C" {

void* malloc(std::size_t size) noexcept {
  return budgeted(size, [&] { return __libc_malloc(size); });
}

void free(void* p) noexcept {
  if (p)
    if (rsaa::AllocationBudget* budget = rsaa::t_budget) budget->freed(::malloc_usable_size(p));
  __libc_free(p);
}

void* calloc(std::size_t count, std::size_t size) noexcept {
  std::size_t bytes = 0;
  if (__builtin_mul_overflow(count, size, &bytes)) return __libc_calloc(count, size);  // fails: ENOMEM
  return budgeted(bytes, [&] { return __libc_calloc(count, size); });
}

void* realloc(void* p, std::size_t size) noexcept {
  rsaa::AllocationBudget* budget = rsaa::t_budget;
  if (!budget || !p) return budget ? malloc(size) : __libc_realloc(p, size);
  const std::size_t before = ::malloc_usable_size(p);
  // Growing may move the block: old and new are both live for the copy, so the whole new size
  // is admitted against what is live now.
  if (size > before && !budget->admit(size)) {
    errno = ENOMEM;
    return nullptr;
  }
  void* q = __libc_realloc(p, size);
  if (q || size == 0) budget->freed(before);
  if (q) budget->allocated(::malloc_usable_size(q));
  return q;
}

void* memalign(std::size_t alignment, std::size_t size) noexcept {
  return budgeted(size, [&] { return __libc_memalign(alignment, size); });
}

void* aligned_alloc(std::size_t alignment, std::size_t size) noexcept {
  if (!power_of_two(alignment)) {
    errno = EINVAL;
    return nullptr;
  }
  return memalign(alignment, size);
}

int posix_memalign(void** out, std::size_t alignment, std::size_t size) noexcept {
  if (!power_of_two(alignment) || alignment % sizeof(void*) != 0) return EINVAL;
  const int saved = errno;
  void* p = memalign(alignment, size);
  if (!p) return ENOMEM;
  errno = saved;
  *out = p;
  return 0;
}

void* valloc(std::size_t size) noexcept {
  return budgeted(size, [&] { return __libc_valloc(size); });
}

void* pvalloc(std::size_t size) noexcept {
  return budgeted(size, [&] { return __libc_pvalloc(size); });
}

}  // extern "C"

#else  // a sanitizer owns malloc: the budget counts operator new only

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

#endif
