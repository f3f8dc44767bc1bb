#include "runtime/camera.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/rsaa/conventions.h"

namespace rsaa {

glm::mat4 Camera::view() const { return glm::lookAt(eye, target, up); }

glm::mat4 Camera::projection(float aspect) const {
  return glm::perspective(glm::radians(fov_y_degrees), aspect, near_plane, far_plane);
}

Camera frame_bounds(const glm::vec3& lo, const glm::vec3& hi, float fov_y_degrees) {
  Camera c;
  c.fov_y_degrees = fov_y_degrees;
  c.target = 0.5f * (lo + hi);
  const float radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
  // The bounding sphere just inside the view: boxes rarely fill their sphere.
  const float distance = radius / std::sin(glm::radians(0.5f * fov_y_degrees)) * 0.8f;
  c.eye = c.target + distance * glm::normalize(glm::vec3(0.55f, 0.45f, 1.0f));
  c.near_plane = std::max(distance - 1.5f * radius, distance * 1e-3f);
  c.far_plane = distance + 1.5f * radius;
  return c;
}

Camera orbit_camera(const Camera& c, double degrees) {
  const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(float(degrees)), c.up);
  Camera out = c;
  out.eye = c.target + glm::vec3(turn * glm::vec4(c.eye - c.target, 0.0f));
  return out;
}

Camera parse_camera(const std::string& text, const glm::vec3& lo, const glm::vec3& hi) {
  std::vector<float> v;
  // Every item between commas, an empty last one included (a trailing comma was taken as nothing).
  std::vector<std::string> items(1);
  for (char c : text) {
    if (c == ',') items.emplace_back();
    else items.back().push_back(c);
  }
  for (const std::string& item : items) {
    // Decimal numbers only, blanks around them (strtod also reads hexadecimal, "inf" and "nan").
    if (item.find_first_not_of(" \t0123456789.eE+-") != std::string::npos ||
        item.find_first_of("0123456789") == std::string::npos)
      throw std::invalid_argument("--camera: '" + item + "' is not a number");
    char* end = nullptr;
    // In double, then to float: a value too small for a float (1e-40) is 0 or subnormal, not an
    // error (stof called it "not a number").
    const double x = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || std::string(end).find_first_not_of(" \t") != std::string::npos)
      throw std::invalid_argument("--camera: '" + item + "' is not a number");
    if (!std::isfinite(x)) throw std::invalid_argument("--camera: values must be finite");
    v.push_back(float(x));
  }
  if (v.size() != 6 && v.size() != 7)
    throw std::invalid_argument("--camera: expected ex,ey,ez,tx,ty,tz[,fov], got " +
                                std::to_string(v.size()) + " numbers");
  Camera c;
  c.eye = {v[0], v[1], v[2]};
  c.target = {v[3], v[4], v[5]};
  if (v.size() == 7) c.fov_y_degrees = v[6];
  if (!(c.fov_y_degrees > 1.0f && c.fov_y_degrees < 170.0f))
    throw std::invalid_argument("--camera: fov must be within (1, 170) degrees");
  // Beyond this, or with the eye this close to the target, float cannot hold the view (a camera
  // at 3e38 or 1e20 rendered only the background without a word).
  constexpr float kLargest = 1e9f;
  for (float x : v)
    if (std::abs(x) > kLargest)
      throw std::invalid_argument("--camera: coordinates must be within +-1e9 to render correctly in float");
  const glm::vec3 forward = c.target - c.eye;
  const float largest = std::max({1.0f, glm::length(c.eye), glm::length(c.target)});
  if (!(glm::length(forward) > 1e-6f * largest))
    throw std::invalid_argument("--camera: eye equals target (closer than float can tell apart)");
  if (glm::length(glm::cross(glm::normalize(forward), c.up)) < 1e-4f) c.up = {0.0f, 0.0f, 1.0f};
  // Near and far enclose the scene's bounding sphere as seen from the eye.
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
  const float distance = glm::length(centre - c.eye);
  c.far_plane = distance + 1.5f * radius;
  c.near_plane = std::max(distance - 1.5f * radius, c.far_plane * 1e-4f);
  if (!(c.near_plane < c.far_plane) || !std::isfinite(c.far_plane))
    throw std::invalid_argument("--camera: the scene is too far from the eye for its size to render in float");
  return c;
}

glm::vec2 jitter_ndc_for_sample(double sx, double sy, int width, int height) {
  // The image moves by -s so that the scene point at centre + s lands on the centre; in window
  // space (y up) that is -pixel_to_gl(s). One window pixel is 2 / size NDC units.
  const Vec2 s = pixel_to_gl({sx, sy});
  return {float(-2.0 * s.x / width), float(-2.0 * s.y / height)};
}

}  // namespace rsaa
