#include "core/dynamic_coverage.h"

#include <bitset>
#include <cmath>

namespace rsaa {

DynamicCoveragePixel::DynamicCoveragePixel(Rgb clear)
    : colour{clear, clear}, depth{1.0f, 1.0f}, mask{0xFFFF, 0xFFFF} {}

bool DynamicCoveragePixel::insert(const CoverageFragment& f) {
  const std::uint16_t incoming = std::uint16_t(f.coverage & 0xFFFF);
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
  const int near = depth[0] < depth[1] ? 0 : 1, far = 1 - near;
  const auto bits = [](unsigned m) { return float(std::bitset<16>(m).count()); };
  const float total = bits(unsigned(mask[0] | mask[1]));
  if (total == 0.0f) return colour[near];
  const float wn = bits(mask[near]) / total, wf = bits(unsigned(mask[far] & ~mask[near])) / total;
  return {wn * colour[near].r + wf * colour[far].r, wn * colour[near].g + wf * colour[far].g,
          wn * colour[near].b + wf * colour[far].b};
}

}  // namespace rsaa
