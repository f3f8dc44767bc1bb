#include "core/rsaa/bilinear.h"

namespace rsaa {

std::uint16_t Neighbourhood3x3::binary_code() const {
  std::uint16_t code = 0;
  for (int k = 0; k < 9; ++k)
    if (value[k / 3][k % 3] != 0.0) code |= std::uint16_t(1u << k);
  return code;
}

Neighbourhood3x3 Neighbourhood3x3::from_binary_code(std::uint16_t code) {
  Neighbourhood3x3 n;
  for (int k = 0; k < 9; ++k) n.value[k / 3][k % 3] = (code >> k) & 1u ? 1.0 : 0.0;
  return n;
}

}  // namespace rsaa
