// Fullscreen passes: a program from fullscreen.vert and a fragment shader, and the one draw call.
// Part of the pass library (rsaa::pass), which the scene renderer and the techniques build on.
#pragma once

#include <string>

#include "runtime/gl_objects.h"

namespace rsaa {

// A fullscreen-triangle program from fullscreen.vert and the given fragment shader.
gl::Program make_fullscreen_program(const std::string& fragment_name, const std::string& defines);
// Draws one triangle covering the viewport with the current program (binds, then unbinds, a VAO).
void draw_fullscreen_triangle();

}  // namespace rsaa
