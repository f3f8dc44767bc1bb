// JSON parsed with every object's keys required to be distinct: nlohmann keeps the last of
// repeated keys without a word, so a file saying "pattern" twice would be read as whichever came
// last. What the project reads (tables, bench reports) is parsed through this.
#pragma once

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rsaa {

// Throws std::invalid_argument naming the first repeated key (and its depth) for a document with
// one, nlohmann::json::exception for one that is not JSON.
inline nlohmann::json parse_json_with_unique_keys(const std::string& text) {
  std::vector<std::set<std::string>> open_objects;
  const nlohmann::json::parser_callback_t check = [&](int depth, nlohmann::json::parse_event_t event,
                                                      nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    if (event == Event::object_start) open_objects.emplace_back();
    if (event == Event::object_end && !open_objects.empty()) open_objects.pop_back();
    if (event == Event::key && !open_objects.empty() && !open_objects.back().insert(parsed.get<std::string>()).second)
      throw std::invalid_argument("the key \"" + parsed.get<std::string>() + "\" appears twice in one object (depth " +
                                  std::to_string(depth) + ")");
    return true;
  };
  return nlohmann::json::parse(text, check);
}

}  // namespace rsaa
