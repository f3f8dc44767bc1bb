#include "core/util/parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <future>
#include <limits>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include <sys/resource.h>

namespace rsaa {

int default_thread_count() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void parallel_for(std::uint64_t count, std::uint64_t chunk, int threads,
                  const std::function<void(std::uint64_t, std::uint64_t)>& work,
                  const ProgressFn& progress) {
  if (threads <= 0) threads = default_thread_count();
  chunk = std::max<std::uint64_t>(chunk, 1);
  std::atomic<std::uint64_t> next{0};
  std::atomic<std::uint64_t> done{0};
  std::atomic<int> running{0};
  std::exception_ptr error;
  std::mutex error_mutex;

  auto worker = [&] {
    for (;;) {
      const std::uint64_t begin = next.fetch_add(chunk);
      if (begin >= count) break;
      const std::uint64_t end = std::min(count, begin + chunk);
      try {
        work(begin, end);
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        next = count;  // stop handing out work
      }
      done += end - begin;
    }
    --running;
  };

  // Under a process limit (ulimit -u) threads may not start: the loop goes on with those that
  // did, or on this thread alone; results never depend on the thread count.
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) {
    ++running;
    try {
      pool.emplace_back(worker);
    } catch (const std::system_error&) {
      --running;
      break;
    }
  }
  if (pool.empty()) {
    running = 1;
    worker();
  }
  if (progress) {
    while (running > 0) {
      progress(std::min(done.load(), count), count);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  if (progress) progress(count, count);
}

namespace {

// This process's thread count (/proc/self/status), -1 when unknown.
int thread_count() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "Threads:") {
      int n = -1;
      status >> n;
      return n;
    }
    status.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return -1;
}

}  // namespace

int threads_that_can_start(int at_most) {
  const int before = thread_count();
  std::promise<void> release;
  const std::shared_future<void> released = release.get_future().share();
  std::vector<std::thread> probes;
  try {
    for (int k = 0; k < at_most; ++k) probes.emplace_back([released] { released.wait(); });
  } catch (const std::system_error&) {
  }
  release.set_value();
  for (std::thread& t : probes) t.join();
  // A joined thread may still count against the limit for a moment (the kernel releases it
  // after waking the joiner): wait until it is gone, so that the probe itself takes no room.
  for (int wait = 0; before > 0 && wait < 1000 && thread_count() > before; ++wait)
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  return static_cast<int>(probes.size());
}

std::uint64_t address_space_limit() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return 0;
  return std::uint64_t(limit.rlim_cur);
}

int fit_llvmpipe_threads_to_process_limit(int room_to_keep) {
  // The user's LP_NUM_THREADS is kept when its threads can start; more than can start would
  // make llvmpipe wait forever (LP_NUM_THREADS=32 under ulimit -u 8 did), so it is lowered then.
  const char* users = std::getenv("LP_NUM_THREADS");
  int asked = std::min(default_thread_count(), 16);
  if (users) {
    char* end = nullptr;
    const long value = std::strtol(users, &end, 10);
    if (end == users || *end != '\0' || value < 0) return -1;  // llvmpipe ignores it: its default
    asked = int(std::min<long>(value, 1024));
  }
  const int wanted = asked + room_to_keep;
  const int can = threads_that_can_start(wanted);
  if (can >= wanted) return -1;
  const int fitting = std::max(0, can - room_to_keep);
  if (users)
    std::fprintf(stderr, "rsaa: LP_NUM_THREADS=%s lowered to %d: the process limit (ulimit -u) leaves room for no more\n",
                 users, fitting);
  ::setenv("LP_NUM_THREADS", std::to_string(fitting).c_str(), 1);
  return fitting;
}

}  // namespace rsaa
