#include "core/util/parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

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

}  // namespace rsaa
