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
  double milliseconds = 0.0;       // GL timer query (GL_TIME_ELAPSED)
  double wall_milliseconds = 0.0;  // wall clock between glFinish() calls around the pass
};

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
