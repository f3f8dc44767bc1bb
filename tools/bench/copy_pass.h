// The bench's speed of light: a full-screen copy (RGBA16F -> RGBA8, one texelFetch per pixel),
// the least a full-screen post-process can cost at a size on this driver. Timed as the
// techniques' passes are (wall clock between glFinish calls), so that a pass's time divided by
// it says how far that pass is from a plain read-and-write of the frame.
#pragma once

#include "runtime/gl_objects.h"

namespace rsaa::bench {

class CopyPass {
 public:
  CopyPass(int width, int height);  // needs a current GL context
  // Copies `source` (an RGBA16F texture of the size) into the pass's RGBA8 target; wall ms.
  double time_ms(GLuint source);
  GLuint target() const { return target_.get(); }  // the RGBA8 copy, for the tests

 private:
  int width_, height_;
  gl::Texture target_;
  gl::Framebuffer framebuffer_;
  gl::Program program_;
};

}  // namespace rsaa::bench
