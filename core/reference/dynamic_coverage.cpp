#include "core/reference/dynamic_coverage.h"

#include <bitset>
#include <cmath>
#include <stdexcept>

namespace rsaa {
namespace {

float bits(Mask m) { return float(std::bitset<64>(m).count()); }
Rgb weighted(Rgb c, float w) { return {w * c.r, w * c.g, w * c.b}; }
Rgb operator+(Rgb a, Rgb b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }

}  // namespace

DcaaSettings dynamic_coverage_surface_settings() {
  DcaaSettings s = dcaa_settings("surface");
  s.max_surfaces = 2;
  // Measured on 34 scenes (README, "Coverage-based techniques"): 0 to +3.1 dB (mean +0.7), none worse;
  // on DCAA's four slots -0.24 to +0.52 dB, so DCAA keeps the least visible rule.
  s.second_merge_least_change = true;
  return s;
}

const SamplePattern& dynamic_coverage_pattern() {
  static const SamplePattern pattern = builtin_pattern("d3d16x");
  return pattern;
}

DynamicCoverageRules dynamic_coverage_rules(const std::string& name) {
  if (name == "seed") return DynamicCoverageRules::Seed;
  if (name == "surface") return DynamicCoverageRules::Surface;
  throw std::invalid_argument("dyncov --rules must be seed or surface, not '" + name + "'");
}

DynamicCoveragePixel::DynamicCoveragePixel(Rgb clear, DynamicCoverageRules rules)
    : colour{clear, clear},
      depth{1.0f, 1.0f},
      mask{0xFFFF, 0xFFFF},
      rules_(rules),
      clear_(clear),
      surfaces_(dynamic_coverage_surface_settings(), &dynamic_coverage_pattern()) {}

bool DynamicCoveragePixel::insert(const CoverageFragment& f) {
  const std::uint16_t incoming = std::uint16_t(f.coverage & 0xFFFF);
  if (rules_ == DynamicCoverageRules::Surface) {
    CoverageFragment g = f;
    g.coverage = incoming;
    return surfaces_.insert(g) != DcaaEvent::Ignored;
  }
  const float id = f.depth.at_centre;
  if (incoming == 0 || !std::isfinite(id) || !std::isfinite(f.colour.r) || !std::isfinite(f.colour.g) ||
      !std::isfinite(f.colour.b))
    return false;
  if (!(seed_closer(id, depth[0]) || seed_closer(id, depth[1]))) return false;
  const int slot = seed_closer(depth[0], depth[1]) ? 1 : 0;  // evict the farther (slot 0 on a tie)
  colour[slot] = f.colour, depth[slot] = id, mask[slot] = incoming;
  return true;
}

Rgb DynamicCoveragePixel::resolve() const {
  if (rules_ == DynamicCoverageRules::Surface) return surfaces_.resolve(dynamic_coverage_pattern(), clear_);
  const int near = seed_closer(depth[0], depth[1]) ? 0 : 1, far = 1 - near;
  const float total = bits(Mask(mask[0] | mask[1]));
  if (total == 0.0f) return colour[near];
  const float wn = bits(mask[near]) / total, wf = bits(Mask(mask[far] & ~mask[near])) / total;
  return weighted(colour[near], wn) + weighted(colour[far], wf);
}

}  // namespace rsaa
