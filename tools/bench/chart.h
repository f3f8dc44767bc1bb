// A numeric table written as CSV and drawn as a line or bar chart (PNG, OpenCV): the papers'
// figures (rsaa figures) are each one or more of these.
#pragma once

#include <string>
#include <vector>

namespace cv {
class Mat;
}

namespace rsaa::bench {

// Writes an 8-bit BGR canvas holding sRGB values as an image file (OpenImageIO, by extension):
// every plot of the bench and the figures goes out through here.
void write_canvas(const cv::Mat& canvas, const std::string& path);

// An axis's range [lo, hi] of the finite values it shows, widened on each side by `fraction` of
// its span, or, for a single value (or a span below 1e-12 of the values' magnitude), by
// `fraction` of the value's magnitude (at least 1): every tick and point then has
// a distinct, finite place (a constant column of 2e7 drew nothing, 1e308 and 1.7e308 overflowed
// the grid to a crash). No finite value: [0, 1]. Throws std::runtime_error, naming `what` and
// the values, when the widened range is beyond a double.
struct AxisRange {
  double lo = 0.0, hi = 1.0;
};
AxisRange drawable_range(double lo, double hi, double fraction, const std::string& what);
// Whether values from lo to hi are drawn as one value (a span below 1e-12 of their magnitude, at
// least 1): drawable_range's rule, for a caller that must tell distinct points apart.
bool drawn_as_one_value(double lo, double hi);

struct FigureTable {
  std::vector<std::string> columns;        // the first is the x axis (or the bar categories)
  std::vector<std::vector<double>> rows;   // each as many cells as columns
  std::vector<std::string> row_labels;     // bar charts: a label per row (empty: the x value)

  // Throws std::invalid_argument when a row's size differs from the columns'.
  void add(std::vector<double> row, const std::string& label = "");
  std::size_t column(const std::string& name) const;  // throws std::invalid_argument if absent
};

// Header row, then one row per line; the text columns are quoted (RFC 4180), numbers with 6
// significant digits, a cell without a value (not finite) empty. With row labels, a "label"
// column comes first.
std::string table_csv(const FigureTable& table);

struct ChartStyle {
  std::string title, x_label, y_label;
  bool log_x = false;
  // Lines whose name contains one of these are drawn dashed (the baselines a curve is read against).
  std::vector<std::string> dashed;
};

// One line per column after the first against the first column; the legend names each line.
void plot_lines(const FigureTable& table, const ChartStyle& style, const std::string& png_path);
// Grouped bars: one group per row (labelled by row_labels), one bar per column after the first,
// the value written above each bar.
void plot_bars(const FigureTable& table, const ChartStyle& style, const std::string& png_path);

}  // namespace rsaa::bench
