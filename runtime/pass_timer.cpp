#include "runtime/pass_timer.h"

#include <algorithm>
#include <cmath>

namespace rsaa {

void PassTimer::begin(const std::string& pass) {
  GLuint id;
  glCreateQueries(GL_TIME_ELAPSED, 1, &id);
  entries_.push_back({pass, gl::Query(id), 0.0});
  glFinish();
  started_ = std::chrono::steady_clock::now();
  glBeginQuery(GL_TIME_ELAPSED, id);
}

void PassTimer::end() {
  glEndQuery(GL_TIME_ELAPSED);
  glFinish();
  entries_.back().wall_milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started_).count();
}

double plausible_timer_query(double query_milliseconds, double wall_milliseconds) {
  const bool plausible = std::isfinite(query_milliseconds) && query_milliseconds >= 0.0 &&
                         query_milliseconds <= 2.0 * wall_milliseconds + 1.0;
  return plausible ? query_milliseconds : kNoTimerQuery;
}

std::vector<PassTime> PassTimer::collect() {
  std::vector<PassTime> out;
  for (const Entry& e : entries_) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(e.query.get(), GL_QUERY_RESULT, &ns);
    // Passes with the same name (the jittered passes) add up, in order of first appearance.
    auto it = std::find_if(out.begin(), out.end(), [&](const PassTime& t) { return t.pass == e.pass; });
    if (it == out.end()) it = out.insert(out.end(), {e.pass, 0.0, 0.0});
    const double query = plausible_timer_query(ns * 1e-6, e.wall_milliseconds);
    it->milliseconds = it->milliseconds == kNoTimerQuery || query == kNoTimerQuery ? kNoTimerQuery
                                                                                 : it->milliseconds + query;
    it->wall_milliseconds += e.wall_milliseconds;
  }
  entries_.clear();
  return out;
}

}  // namespace rsaa
