// Similarity masks: bit i set = subsample i is similar to the pixel centre (same surface).
#pragma once

#include <bitset>
#include <cstdint>

namespace rsaa {

using Mask = std::uint64_t;

constexpr int kMaxPatternSamples = 64;

constexpr bool is_similar(Mask mask, int sample) { return (mask >> sample) & 1u; }
constexpr Mask with_similar(Mask mask, int sample) { return mask | (Mask{1} << sample); }
// All n subsamples similar: the mask of a pixel that no edge crosses.
constexpr Mask full_mask(int sample_count) {
  return sample_count >= 64 ? ~Mask{0} : (Mask{1} << sample_count) - 1;
}
inline int similar_count(Mask mask) { return static_cast<int>(std::bitset<64>(mask).count()); }

}  // namespace rsaa
