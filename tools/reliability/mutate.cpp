#include "tools/reliability/mutate.h"

#include <algorithm>
#include <vector>

#include "core/util/random.h"

namespace rsaa::reliability {

std::string mutate(const std::string& input, std::uint64_t seed, std::uint64_t index) {
  static const std::vector<std::string> tokens = {
      "NaN", "1e999", "-1", "99999999999999999999999", "\xc3\x28", "\xff\xfe", "null", "[]", "{}",
      "\"", "[[[[[[[[", "}}}}", "0.5", "-0", "1e-400", "\x00", "inf", "true", ",", ":"};
  static const char special[] = {'\0', '\xff', '"', '[', ']', '{', '}', '9', '-', 'e', '.', ',', '\n'};
  CaseRandom random(seed, index);
  const auto pick = [&](std::size_t n) { return n ? std::size_t(random.uniform() * double(n)) % n : 0; };
  std::string s = input;
  const int edits = 1 + int(pick(4));
  for (int e = 0; e < edits; ++e) {
    const std::size_t at = pick(s.size() + 1);
    switch (pick(6)) {
      case 0:  // flip one bit
        if (!s.empty()) s[std::min(at, s.size() - 1)] ^= char(1u << pick(8));
        break;
      case 1:  // a special byte
        if (!s.empty()) s[std::min(at, s.size() - 1)] = special[pick(sizeof special)];
        break;
      case 2:  // delete a range
        s.erase(at, 1 + pick(64));
        break;
      case 3:  // duplicate a range
        s.insert(at, s.substr(at, 1 + pick(256)));
        break;
      case 4:  // truncate
        s.resize(at);
        break;
      default:  // insert a hard token
        s.insert(at, tokens[pick(tokens.size())]);
        break;
    }
  }
  return s;
}

}  // namespace rsaa::reliability
