// CSV files as the project writes them (RFC 4180: quoted fields, doubled quotes, commas and
// newlines inside quotes), read with libcsv.
#pragma once

#include <string>
#include <vector>

namespace rsaa::bench {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // each as many cells as the header
};

// Read budget of a CSV file: far above any the project writes.
constexpr unsigned long long kMaxCsvBytes = 64ull << 20;

// Throws std::runtime_error naming the file (and the record) when it cannot be read, is not
// valid CSV, has no header, or a record's cell count differs from the header's. Empty records
// (blank lines) are skipped.
CsvTable read_csv(const std::string& path);

// A text cell as written: in quotes, with quotes doubled (RFC 4180).
std::string csv_text(const std::string& text);

// The cell as a finite number; throws naming the file, record and column otherwise.
double csv_number(const CsvTable& table, const std::string& path, std::size_t row, std::size_t column);

}  // namespace rsaa::bench
