// Deterministic input mutations for the bounded fuzz loops: the same (seed, index) always gives
// the same mutated input.
#pragma once

#include <cstdint>
#include <string>

namespace rsaa::reliability {

// 1 to 4 edits of `input`: bit flips, special bytes, deleted / duplicated / truncated ranges,
// and inserted tokens that parsers find hard (NaN, 1e999, huge integers, invalid UTF-8, ...).
std::string mutate(const std::string& input, std::uint64_t seed, std::uint64_t index);

}  // namespace rsaa::reliability
