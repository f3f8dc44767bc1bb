// GL timer queries around the passes of one frame (DESIGN.md section 5: per-pass times).
#pragma once

#include <string>
#include <vector>

#include "runtime/gl_objects.h"

namespace rsaa {

struct PassTime {
  std::string pass;
  double milliseconds = 0.0;
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
  };
  std::vector<Entry> entries_;
};

}  // namespace rsaa
