// Every anti-aliasing technique is a render pass behind this one interface (Falcor-style). How
// techniques are named, configured and made: runtime/technique_registry.h.
#pragma once

#include <string>
#include <vector>

#include "runtime/gpu_scene.h"
#include "runtime/pass_timer.h"

namespace rsaa {

class Technique {
 public:
  virtual ~Technique() = default;
  // Renders a frame of `scene` into `output`, an RGBA16F texture of view.width x view.height
  // holding linear colour.
  virtual void render(const GpuScene& scene, const View& view, GLuint output) = 0;
  // Bytes per pixel of every buffer the technique keeps for a frame.
  virtual double bytes_per_pixel() const = 0;
  // What the technique chose for this driver and size where it chooses (RSAA: the pre-pass), for
  // a user to read; empty where there is no choice.
  virtual std::string choices() const { return ""; }
  // GL times of the passes of the last frame.
  std::vector<PassTime> take_pass_times() { return timer_.collect(); }

 protected:
  PassTimer timer_;
};

}  // namespace rsaa
