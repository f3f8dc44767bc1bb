#include "tools/bench/csv.h"

#include <csv.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "core/util/atomic_file.h"

namespace rsaa::bench {
namespace {

struct Collector {
  std::vector<std::vector<std::string>> records;
  std::vector<std::string> current;
};

void on_field(void* data, std::size_t size, void* collector) {
  static_cast<Collector*>(collector)->current.emplace_back(static_cast<const char*>(data), size);
}

void on_record(int, void* collector) {
  auto* c = static_cast<Collector*>(collector);
  c->records.push_back(std::move(c->current));
  c->current.clear();
}

}  // namespace

CsvTable read_csv(const std::string& path) {
  std::string text = read_whole_file(path, kMaxCsvBytes, "CSV file");
  // A UTF-8 byte-order mark (spreadsheets write one) is not part of the first column's name.
  if (text.rfind("\xef\xbb\xbf", 0) == 0) text.erase(0, 3);
  csv_parser parser;
  if (csv_init(&parser, CSV_STRICT | CSV_STRICT_FINI) != 0)
    throw std::runtime_error(path + ": cannot start the CSV parser");
  Collector collector;
  const std::size_t parsed = csv_parse(&parser, text.data(), text.size(), on_field, on_record, &collector);
  const bool ok = parsed == text.size() && csv_fini(&parser, on_field, on_record, &collector) == 0;
  const std::string error = ok ? "" : csv_strerror(csv_error(&parser));
  csv_free(&parser);
  if (!ok)
    throw std::runtime_error(path + ": not valid CSV (" + error + ") near byte " + std::to_string(parsed) +
                             " (record " + std::to_string(collector.records.size() + 1) + ")");
  CsvTable table;
  for (std::size_t r = 0; r < collector.records.size(); ++r) {
    auto& record = collector.records[r];
    if (record.empty() || (record.size() == 1 && record[0].empty())) continue;
    if (table.header.empty()) {
      table.header = std::move(record);
      continue;
    }
    if (record.size() != table.header.size())
      throw std::runtime_error(path + ": record " + std::to_string(r + 1) + " has " + std::to_string(record.size()) +
                               " cells, the header " + std::to_string(table.header.size()));
    table.rows.push_back(std::move(record));
  }
  if (table.header.empty()) throw std::runtime_error(path + ": empty (no header row)");
  return table;
}

std::string csv_text(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

double csv_number(const CsvTable& table, const std::string& path, std::size_t row, std::size_t column) {
  const std::string& cell = table.rows.at(row).at(column);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(cell.c_str(), &end);
  if (cell.empty() || *end != '\0' || !std::isfinite(v))
    throw std::runtime_error(path + ": data row " + std::to_string(row + 1) + ", column '" + table.header[column] +
                             "': '" + cell + "' is not a finite number");
  return v;
}

}  // namespace rsaa::bench
