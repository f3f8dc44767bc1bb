#include "core/rsaa/postprocess_cpu.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rsaa {

Image apply_offset_table(const Image& colour, const std::vector<Mask>& masks,
                         const OffsetTable& table) {
  if (masks.size() != colour.pixels.size())
    throw std::invalid_argument("post-process: " + std::to_string(masks.size()) + " masks for " +
                                std::to_string(colour.pixels.size()) + " pixels");
  const Mask all = table.pattern.all_similar();
  Image out = colour;
  for (int y = 0; y < colour.height; ++y) {
    for (int x = 0; x < colour.width; ++x) {
      const Mask m = masks[std::size_t(y) * colour.width + x];
      if (m > all)
        throw std::invalid_argument("post-process: mask " + std::to_string(m) + " at pixel (" +
                                    std::to_string(x) + ", " + std::to_string(y) +
                                    ") has bits beyond the " +
                                    std::to_string(table.pattern.size()) + " samples of " +
                                    table.pattern.name);
      if (m == all) continue;
      const Vec2 d = table.offsets[m];
      const Rgb fetched = bilinear_fetch(colour, x + d.x, y + d.y);
      // A non-finite neighbour must not spread: keep the pixel's own colour then.
      if (std::isfinite(fetched.r) && std::isfinite(fetched.g) && std::isfinite(fetched.b))
        out.at(x, y) = fetched;
    }
  }
  return out;
}

}  // namespace rsaa
