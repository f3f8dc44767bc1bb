// Counter-based random numbers: draw k of case i depends only on (seed, i, k), so a case set is
// the same whatever the thread count and order of generation.
#pragma once

#include <cstdint>

namespace rsaa {

// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mix.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

class CaseRandom {
 public:
  CaseRandom(std::uint64_t seed, std::uint64_t case_index)
      : state_(mix64(mix64(seed) ^ mix64(case_index ^ 0x5851f42d4c957f2dull))) {}

  // Uniform in [0, 1), 53 random bits.
  double uniform() {
    state_ += 0x9e3779b97f4a7c15ull;
    return static_cast<double>(mix64(state_) >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_;
};

}  // namespace rsaa
