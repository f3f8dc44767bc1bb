// Times of the passes of one frame (docs/conventions.md section 5): GL timer queries, and the wall
// clock between glFinish() calls. On llvmpipe the "GPU" is the CPU and its timer queries proved
// inconsistent between techniques, so the bench ranks by the wall clock; both are reported.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "runtime/gl_objects.h"

namespace rsaa {

struct PassTime {
  std::string pass;
  double milliseconds = 0.0;       // GL timer query (GL_TIME_ELAPSED); kNoTimerQuery when implausible
  double wall_milliseconds = 0.0;  // wall clock between glFinish() calls around the pass
};

// A timer query's time that cannot be right is reported as this (printed "n/a", null in JSON):
// llvmpipe answers a query begun before a frame's compute dispatches with its clock since boot.
constexpr double kNoTimerQuery = -1.0;
// The query's milliseconds if plausible: finite, not negative and not longer than the wall clock
// between the glFinish() calls around the same work (with 1 ms and 2x of slack); else kNoTimerQuery.
double plausible_timer_query(double query_milliseconds, double wall_milliseconds);

class PassTimer {
 public:
  void begin(const std::string& pass);
  void end();
  // Waits for the queries and returns the times in the order the passes ran; clears.
  std::vector<PassTime> collect();

 private:
  struct Entry {
    std::string pass;
    gl::Query query;
    double wall_milliseconds = 0.0;
  };
  std::chrono::steady_clock::time_point started_;
  std::vector<Entry> entries_;
};

}  // namespace rsaa
