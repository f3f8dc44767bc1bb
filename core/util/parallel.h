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

// How many more threads can run at once right now, up to `at_most`: under a process limit
// (ulimit -u, RLIMIT_NPROC) fewer than asked may start. Probes by starting them (each waits
// until all have started, then they end).
int threads_that_can_start(int at_most);

// Under a process limit, llvmpipe (Mesa's software GL) starts fewer rasterizer threads than it
// counts on and then waits for the missing ones forever (Mesa 22, measured under ulimit -u 2).
// Before a GL context is made: when fewer than its threads (one per CPU, or LP_NUM_THREADS if
// set) plus `room_to_keep` can start, sets LP_NUM_THREADS to what fits (0: it rasterizes on the
// calling thread; a lowered user value is reported on stderr). Returns the value set, or -1 when
// nothing was set.
int fit_llvmpipe_threads_to_process_limit(int room_to_keep);

// The address-space limit (ulimit -v, RLIMIT_AS) in bytes; 0 when there is none.
std::uint64_t address_space_limit();

// Calls work(begin, end) for consecutive ranges of at most `chunk` items covering [0, count).
// threads <= 0 means default_thread_count(). Rethrows the first exception a worker threw.
void parallel_for(std::uint64_t count, std::uint64_t chunk, int threads,
                  const std::function<void(std::uint64_t, std::uint64_t)>& work,
                  const ProgressFn& progress = nullptr);

}  // namespace rsaa
