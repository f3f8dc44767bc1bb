#include "core/dynamic_coverage.h"

#include <bitset>
#include <cmath>
#include <stdexcept>

namespace rsaa {
namespace {

float bits(Mask m) { return float(std::bitset<64>(m).count()); }
Rgb weighted(Rgb c, float w) { return {w * c.r, w * c.g, w * c.b}; }
Rgb operator+(Rgb a, Rgb b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }

}  // namespace

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
      surfaces_(DcaaSettings{2, DcaaSettings{}.cos_normal_threshold}) {}

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
  if (!(id < depth[0] || id < depth[1])) return false;
  const int slot = depth[0] < depth[1] ? 1 : 0;  // evict the farther (slot 0 on a tie)
  colour[slot] = f.colour, depth[slot] = id, mask[slot] = incoming;
  return true;
}

Rgb DynamicCoveragePixel::resolve() const {
  if (rules_ == DynamicCoverageRules::Surface) {
    const auto& s = surfaces_.surfaces();
    if (s.empty()) return clear_;
    // The nearer slot by depth at the centre (ties: the earlier), as the seed's resolve orders them.
    const int near = s.size() == 2 && s[1].depth.at_centre < s[0].depth.at_centre ? 1 : 0;
    const Mask near_mask = s[near].coverage, far_mask = s.size() == 2 ? s[1 - near].coverage & ~near_mask : 0;
    const float n = float(kSamples);
    Rgb c = weighted(s[near].colour, bits(near_mask) / n) + weighted(clear_, (n - bits(near_mask | far_mask)) / n);
    if (far_mask) c = c + weighted(s[1 - near].colour, bits(far_mask) / n);
    return c;
  }
  const int near = depth[0] < depth[1] ? 0 : 1, far = 1 - near;
  const float total = bits(Mask(mask[0] | mask[1]));
  if (total == 0.0f) return colour[near];
  const float wn = bits(mask[near]) / total, wf = bits(Mask(mask[far] & ~mask[near])) / total;
  return weighted(colour[near], wn) + weighted(colour[far], wf);
}

}  // namespace rsaa
