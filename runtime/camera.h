// A pinhole camera. View space is OpenGL's: camera at the origin looking down -z, +y up.
#pragma once

#include <string>

#include <glm/glm.hpp>

namespace rsaa {

struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 45.0f;
  float near_plane = 0.1f;
  float far_plane = 100.0f;

  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
};

// A camera that sees the whole box from a fixed oblique direction, near/far fitted to it.
Camera frame_bounds(const glm::vec3& lo, const glm::vec3& hi, float fov_y_degrees = 45.0f);

// The camera turned by `degrees` about its up axis through its target (bench and scene-table
// camera paths).
Camera orbit_camera(const Camera& camera, double degrees);

// "ex,ey,ez,tx,ty,tz[,fov]". Throws std::invalid_argument naming the problem: wrong count,
// non-numbers, non-finite values, eye == target, fov outside (1, 170) degrees.
Camera parse_camera(const std::string& text, const glm::vec3& scene_lo, const glm::vec3& scene_hi);

// Window-space translation (pixels, +y up) that puts the point at pixel-space offset `s` (+y
// down, docs/conventions.md section 1) of every pixel onto that pixel's centre, as NDC units.
glm::vec2 jitter_ndc_for_sample(double sx, double sy, int width, int height);

}  // namespace rsaa
