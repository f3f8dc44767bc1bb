// Runs work items on several threads. Items are claimed in order from a shared counter, and
// each item writes only its own results, so the output never depends on the thread count.
#pragma once

#include <cstdint>
#include <functional>

namespace rsaa {

// Called on the calling thread, about ten times a second and once at the end.
using ProgressFn = std::function<void(std::uint64_t done, std::uint64_t total)>;

// Default worker count: all hardware threads (at least 1).
int default_thread_count();

// Calls work(begin, end) for consecutive ranges of at most `chunk` items covering [0, count).
// threads <= 0 means default_thread_count(). Rethrows the first exception a worker threw.
void parallel_for(std::uint64_t count, std::uint64_t chunk, int threads,
                  const std::function<void(std::uint64_t, std::uint64_t)>& work,
                  const ProgressFn& progress = nullptr);

}  // namespace rsaa
