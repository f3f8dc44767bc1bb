#include "core/rsaa/sample_pattern.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "core/rsaa/conventions.h"

namespace rsaa {
namespace {

struct BuiltinPattern {
  const char* name;
  std::vector<std::pair<int, int>> sixteenths;  // (x, y), 1/16 pixel, y down
};

const std::vector<BuiltinPattern>& builtins() {
  static const std::vector<BuiltinPattern> patterns = {
      {"d3d4x", {{-2, -6}, {6, -2}, {-6, 2}, {2, 6}}},
      {"d3d8x", {{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}}},
      {"d3d16x",
       {{1, 1}, {-1, -3}, {-3, 2}, {4, -1}, {-5, -2}, {2, 5}, {5, 3}, {3, -5},
        {-2, 6}, {0, -7}, {-4, -6}, {-6, 4}, {-8, 0}, {7, -4}, {6, 7}, {-7, -8}}},
  };
  return patterns;
}

std::string joined_builtin_names() {
  std::string out;
  for (const auto& p : builtins()) out += (out.empty() ? "" : ", ") + std::string(p.name);
  return out;
}

}  // namespace

const std::vector<std::string>& builtin_pattern_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& p : builtins()) n.emplace_back(p.name);
    return n;
  }();
  return names;
}

bool is_builtin_pattern(const std::string& name) {
  for (const auto& p : builtins())
    if (name == p.name) return true;
  return false;
}

SamplePattern builtin_pattern(const std::string& name) {
  for (const auto& p : builtins()) {
    if (name != p.name) continue;
    SamplePattern pattern{name, {}};
    for (auto [x, y] : p.sixteenths) pattern.positions.push_back({x / 16.0, y / 16.0});
    return pattern;
  }
  throw std::invalid_argument("unknown sample pattern '" + name +
                              "' (known: " + joined_builtin_names() + ")");
}

bool is_valid_pattern_name(const std::string& name) {
  if (name.empty() || name.size() > kMaxPatternNameLength) return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') return false;
  return true;
}

SamplePattern pattern_from_positions(const std::string& name, const std::vector<Vec2>& positions) {
  // The name becomes file names and shader identifiers: no path separators, no newlines.
  if (!is_valid_pattern_name(name))
    throw std::invalid_argument("pattern name '" + name + "' must be 1 to " +
                                std::to_string(kMaxPatternNameLength) +
                                " letters, digits, '-' or '_'");
  if (positions.empty() || positions.size() > static_cast<std::size_t>(kMaxPatternSamples))
    throw std::invalid_argument("pattern '" + name + "' has " + std::to_string(positions.size()) +
                                " samples; expected 1 to " + std::to_string(kMaxPatternSamples));
  // A driver pattern's name says its count: gl8x with four positions would pass for eight.
  const int driver_samples = gl_pattern_samples(name);
  if (driver_samples > 0 && positions.size() != std::size_t(driver_samples))
    throw std::invalid_argument("pattern '" + name + "' has " + std::to_string(positions.size()) + " samples; " +
                                name + " has " + std::to_string(driver_samples));
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec2 p = positions[i];
    if (!is_finite(p) || std::abs(p.x) > 0.5 || std::abs(p.y) > 0.5)
      throw std::invalid_argument("pattern '" + name + "': sample " + std::to_string(i) +
                                  " is not a finite point of the pixel [-0.5, 0.5]^2");
    // Coordinates finer than the resolution step (subnormals, 1e-300) make the trainer's
    // geometry degenerate; hardware positions are on a 1/16 or 1/256 grid anyway.
    for (double c : {p.x, p.y})
      if (c != 0.0 && std::abs(c) < kMinSampleSpacing)
        throw std::invalid_argument("pattern '" + name + "': sample " + std::to_string(i) +
                                    " has a coordinate closer to 0 than " +
                                    std::to_string(kMinSampleSpacing) + " but not 0");
    for (std::size_t k = 0; k < i; ++k)
      if (std::max(std::abs(p.x - positions[k].x), std::abs(p.y - positions[k].y)) < kMinSampleSpacing)
        throw std::invalid_argument("pattern '" + name + "': samples " + std::to_string(k) +
                                    " and " + std::to_string(i) + " are closer than " +
                                    std::to_string(kMinSampleSpacing) + " (coincident)");
  }
  return SamplePattern{name, positions};
}

SamplePattern pattern_from_gl_positions(const std::string& name,
                                        const std::vector<Vec2>& gl_positions) {
  std::vector<Vec2> pixel;
  pixel.reserve(gl_positions.size());
  for (Vec2 s : gl_positions) pixel.push_back(gl_sample_position_to_pixel(s));
  return pattern_from_positions(name, pixel);
}

SamplePattern cell_pattern(const SamplePattern& base, int columns, int rows) {
  if (columns < 1 || rows < 1 || base.size() < 1 || std::int64_t(columns) * rows * base.size() > kMaxPatternSamples)
    throw std::invalid_argument("cells " + std::to_string(columns) + "x" + std::to_string(rows) + " of pattern '" +
                                base.name + "' (" + std::to_string(base.size()) + " samples): at least 1x1 and at most " +
                                std::to_string(kMaxPatternSamples) + " subsamples in all");
  const std::string stem = base.name.rfind("custom-", 0) == 0 ? base.name.substr(7) : base.name;
  std::string shape = "cells" + std::to_string(columns) + "x" + std::to_string(rows);
  if (columns == 2 && rows == 1) shape = "wide";
  if (columns == 1 && rows == 2) shape = "tall";
  if (columns == 2 && rows == 2) shape = "quad";
  const std::string name = "custom-" + stem + "-" + shape;
  if (name.size() > kMaxPatternNameLength)
    throw std::invalid_argument("the cell pattern of '" + base.name + "' would be named '" + name + "', longer than " +
                                std::to_string(kMaxPatternNameLength) + " characters: give the pattern a shorter name");
  std::vector<Vec2> positions;
  for (int row = 0; row < rows; ++row)
    for (int column = 0; column < columns; ++column)
      for (const Vec2& p : base.positions)
        positions.push_back({(column + 0.5 + p.x) / columns - 0.5, (row + 0.5 + p.y) / rows - 0.5});
  return pattern_from_positions(name, positions);
}

PixelStep outside_pixel_towards(Vec2 sample) {
  const double scale = std::max(std::abs(sample.x), std::abs(sample.y));
  if (!(scale > 0.0)) return {1, 0};
  return {int(std::lround(sample.x / scale)), int(std::lround(sample.y / scale))};
}

int representative_dissimilar(const SamplePattern& pattern, Mask mask) {
  int best = -1;
  double best_distance = -1.0;
  for (int i = 0; i < pattern.size(); ++i) {
    const Vec2 s = pattern.positions[i];
    const double d = s.x * s.x + s.y * s.y;
    if (!is_similar(mask, i) && d >= best_distance) best = i, best_distance = d;
  }
  return best;
}

int gl_pattern_samples(const std::string& name) {
  for (int n : {2, 4, 8, 16})
    if (name == "gl" + std::to_string(n) + "x") return n;
  return 0;
}

bool is_known_pattern_name(const std::string& name) {
  return is_builtin_pattern(name) || gl_pattern_samples(name) > 0 ||
         (name.rfind("custom-", 0) == 0 && name.size() > 7 && is_valid_pattern_name(name));
}

}  // namespace rsaa
