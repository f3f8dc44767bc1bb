// Output files appear whole or not at all: write a temporary file beside the target, then
// rename it over the target.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rsaa {

// Throws std::runtime_error naming the path when the directory is missing or unwritable.
void write_file_atomically(const std::string& path, const std::string& contents);

// Several files that belong together: all temporaries are written first, then renamed, so a
// failure leaves none of the targets touched (short of a failing rename).
void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files);

// Whole file as a string; throws std::runtime_error naming the path when it cannot be read.
std::string read_whole_file(const std::string& path);

}  // namespace rsaa
