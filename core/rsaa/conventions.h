// The project's conventions, written down once (docs/conventions.md section 1).
//
// Pixel space: units of one pixel, origin at the pixel centre, +x right, +y DOWN (the paper's
// and Direct3D's screen space). Sample patterns, masks, line cases and offset tables all live in
// pixel space. Image rows are stored top row first, so row index grows with +y.
//
// OpenGL window space has +y UP. Every conversion between the two goes through the functions
// below; nothing else in the project negates a y coordinate.
//
// Similarity mask: bit i set = subsample i (in pattern order) is similar to the pixel centre.
#pragma once

#include "core/util/vec2.h"

namespace rsaa {

// A displacement (offset, sample position) from pixel space to OpenGL window space.
inline Vec2 pixel_to_gl(Vec2 p) { return {p.x, -p.y}; }
// A displacement from OpenGL window space to pixel space.
inline Vec2 gl_to_pixel(Vec2 p) { return {p.x, -p.y}; }

// glGetMultisamplefv gives a sample position in [0,1]^2 of the pixel, origin at the bottom-left
// corner, y up. Pixel space puts the origin at the centre with y down.
inline Vec2 gl_sample_position_to_pixel(Vec2 s) { return {s.x - 0.5, 0.5 - s.y}; }

}  // namespace rsaa
