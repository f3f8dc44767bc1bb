#include "tools/bench/chart.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "core/util/colour.h"
#include "image/image_io.h"
#include "tools/bench/csv.h"

namespace rsaa::bench {
namespace {

const cv::Scalar kInk(40, 40, 40), kGrid(225, 225, 225);

// Distinct colours (BGR) for up to 10 lines, then repeated.
cv::Scalar line_colour(std::size_t i) {
  static const cv::Scalar palette[] = {{0, 0, 0},     {160, 40, 160}, {200, 110, 30}, {40, 40, 210},
                                       {30, 140, 240}, {20, 170, 200}, {0, 110, 160},  {110, 110, 110},
                                       {40, 150, 40},  {150, 60, 90}};
  return palette[i % 10];
}

void text(cv::Mat& canvas, const std::string& s, cv::Point at, double scale = 0.45, cv::Scalar colour = kInk) {
  cv::putText(canvas, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
}


std::string number(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.4g", v);
  return s;
}

bool is_dashed(const ChartStyle& style, const std::string& name) {
  return std::any_of(style.dashed.begin(), style.dashed.end(),
                     [&](const std::string& d) { return name.find(d) != std::string::npos; });
}

void dashed_line(cv::Mat& canvas, cv::Point a, cv::Point b, cv::Scalar colour) {
  const double length = std::hypot(double(b.x - a.x), double(b.y - a.y));
  const int pieces = std::max(1, int(length / 6));
  for (int k = 0; k < pieces; k += 2) {
    const double t0 = double(k) / pieces, t1 = double(std::min(k + 1, pieces)) / pieces;
    cv::line(canvas, a + (b - a) * t0, a + (b - a) * t1, colour, 2, cv::LINE_AA);
  }
}

// A round tick step (1, 2 or 5 times a power of ten) of about span / 5.
double tick_step(double span) {
  const double raw = span / 5.0, power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10.0 * power;
}

struct Range {
  double lo = 1e300, hi = -1e300;
  void add(double v) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
};

}  // namespace

bool drawn_as_one_value(double lo, double hi) {
  // Spans below 1e-12 of the magnitude (a few thousand float steps of a double) are drawn as one
  // value: ticks a fifth of the span apart must still be distinct doubles.
  return !(hi - lo > 1e-12 * std::max({1.0, std::abs(lo), std::abs(hi)}));
}

AxisRange drawable_range(double lo, double hi, double fraction, const std::string& what) {
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo <= hi)) return {};
  const double magnitude = std::max({1.0, std::abs(lo), std::abs(hi)});
  const double span = hi - lo;
  const double pad = drawn_as_one_value(lo, hi) ? std::max(fraction, 0.05) * magnitude : fraction * span;
  const AxisRange r{lo - pad, hi + pad};
  if (!std::isfinite(r.lo) || !std::isfinite(r.hi) || !std::isfinite(r.hi - r.lo)) {
    char values[128];
    if (lo == hi) std::snprintf(values, sizeof values, "%s is %g", what.c_str(), lo);
    else std::snprintf(values, sizeof values, "%s from %g to %g", what.c_str(), lo, hi);
    throw std::runtime_error(std::string("the values span more than can be drawn (") + values + ")");
  }
  return r;
}

void write_canvas(const cv::Mat& canvas, const std::string& path) {
  Image image(canvas.cols, canvas.rows);
  for (int y = 0; y < canvas.rows; ++y)
    for (int x = 0; x < canvas.cols; ++x) {
      const cv::Vec3b p = canvas.at<cv::Vec3b>(y, x);
      image.at(x, y) = {srgb_to_linear(p[2] / 255.0f), srgb_to_linear(p[1] / 255.0f), srgb_to_linear(p[0] / 255.0f)};
    }
  write_image(path, image);
}

void FigureTable::add(std::vector<double> row, const std::string& label) {
  if (row.size() != columns.size()) throw std::invalid_argument("FigureTable: a row needs one cell per column");
  rows.push_back(std::move(row));
  if (!label.empty() || !row_labels.empty()) {
    row_labels.resize(rows.size() - 1);
    row_labels.push_back(label);
  }
}

std::size_t FigureTable::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) throw std::invalid_argument("FigureTable: no column '" + name + "'");
  return std::size_t(it - columns.begin());
}

std::string table_csv(const FigureTable& t) {
  std::ostringstream s;
  const bool labelled = !t.row_labels.empty();
  if (labelled) s << "label,";
  for (std::size_t c = 0; c < t.columns.size(); ++c) s << (c ? "," : "") << csv_text(t.columns[c]);
  s << '\n';
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    if (labelled) s << csv_text(r < t.row_labels.size() ? t.row_labels[r] : "") << ',';
    // A cell without a value (NaN: a technique that keeps no such buffer) is empty, as the
    // Markdown's "-", never "nan".
    for (std::size_t c = 0; c < t.rows[r].size(); ++c)
      s << (c ? "," : "") << (std::isfinite(t.rows[r][c]) ? number(t.rows[r][c]) : "");
    s << '\n';
  }
  return s.str();
}

void plot_lines(const FigureTable& t, const ChartStyle& style, const std::string& path) {
  if (t.columns.size() < 2 || t.rows.size() < 2) throw std::invalid_argument("plot_lines: needs a y column and two rows");
  // The legend is as wide as its longest label (RSAA labels name every option they set).
  int legend_text = 0;
  for (std::size_t c = 1; c < t.columns.size(); ++c) {
    int baseline = 0;
    legend_text = std::max(legend_text, cv::getTextSize(t.columns[c], cv::FONT_HERSHEY_SIMPLEX, 0.4, 1, &baseline).width);
  }
  const int right = std::max(300, legend_text + 60), width = 740 + right, height = 560, left = 70, top = 50, bottom = 60;
  cv::Mat canvas(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const auto x_of = [&](double x) { return style.log_x ? std::log10(x) : x; };
  Range xr, yr;
  for (const auto& row : t.rows) {
    xr.add(x_of(row[0]));
    for (std::size_t c = 1; c < row.size(); ++c) yr.add(row[c]);
  }
  const AxisRange xa = drawable_range(xr.lo, xr.hi, 0.0, style.x_label), ya = drawable_range(yr.lo, yr.hi, 0.06, style.y_label);
  xr.lo = xa.lo, xr.hi = xa.hi, yr.lo = ya.lo, yr.hi = ya.hi;
  const auto px = [&](double x) { return left + int((x_of(x) - xr.lo) / (xr.hi - xr.lo) * (width - left - right)); };
  const auto py = [&](double y) { return height - bottom - int((y - yr.lo) / (yr.hi - yr.lo) * (height - top - bottom)); };
  const double y_step = tick_step(yr.hi - yr.lo);
  // Ticks counted, not accumulated: a step can be small beside the values.
  const double first_tick = std::ceil(yr.lo / y_step);
  for (int k = 0; k <= 20 && (first_tick + k) * y_step <= yr.hi; ++k) {
    const double y = (first_tick + k) * y_step;
    cv::line(canvas, {left, py(y)}, {width - right, py(y)}, kGrid);
    text(canvas, number(std::abs(y) < 1e-9 * y_step ? 0.0 : y), {8, py(y) + 5});
  }
  // At most about 12 x labels, at rows.
  const std::size_t step = std::max<std::size_t>(1, (t.rows.size() + 11) / 12);
  for (std::size_t r = 0; r < t.rows.size(); r += step) {
    const int x = px(t.rows[r][0]);
    cv::line(canvas, {x, top}, {x, height - bottom}, kGrid);
    text(canvas, number(t.rows[r][0]), {x - 12, height - bottom + 20}, 0.4);
  }
  cv::rectangle(canvas, {left, top}, {width - right, height - bottom}, kInk);
  text(canvas, style.title, {left, 28}, 0.55);
  text(canvas, style.x_label + (style.log_x ? " (log scale)" : ""), {left + 150, height - 18}, 0.5);
  text(canvas, style.y_label, {8, top - 8}, 0.45);
  for (std::size_t c = 1; c < t.columns.size(); ++c) {
    const cv::Scalar colour = line_colour(c - 1);
    const bool dashed = is_dashed(style, t.columns[c]);
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      const cv::Point p(px(t.rows[r][0]), py(t.rows[r][c]));
      if (!std::isfinite(t.rows[r][c])) continue;
      if (t.rows.size() <= 40) cv::circle(canvas, p, 3, colour, -1, cv::LINE_AA);
      if (r == 0 || !std::isfinite(t.rows[r - 1][c])) continue;
      const cv::Point q(px(t.rows[r - 1][0]), py(t.rows[r - 1][c]));
      if (dashed) dashed_line(canvas, q, p, colour);
      else cv::line(canvas, q, p, colour, 2, cv::LINE_AA);
    }
    const int y = top + 12 + 20 * int(c - 1);
    if (dashed) dashed_line(canvas, {width - right + 12, y - 4}, {width - right + 40, y - 4}, colour);
    else cv::line(canvas, {width - right + 12, y - 4}, {width - right + 40, y - 4}, colour, 2, cv::LINE_AA);
    text(canvas, t.columns[c], {width - right + 46, y}, 0.4, colour);
  }
  write_canvas(canvas, path);
}

void plot_bars(const FigureTable& t, const ChartStyle& style, const std::string& path) {
  if (t.columns.size() < 2 || t.rows.empty()) throw std::invalid_argument("plot_bars: needs a value column and a row");
  const std::size_t series = t.columns.size() - 1;
  // Wide enough for the bars and for the longest row label written below its group.
  std::size_t longest_label = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r)
    longest_label = std::max(longest_label, r < t.row_labels.size() ? t.row_labels[r].size() : 6);
  const int group_w = std::max({40, int(series * 26) + 16, int(longest_label) * 6 + 12});
  const int left = 80, right = series > 1 ? 240 : 30, top = 50, bottom = 60;
  const int width = std::max(640, left + right + group_w * int(t.rows.size())), height = 520;
  cv::Mat canvas(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  double hi = 0;
  for (const auto& row : t.rows)
    for (std::size_t c = 1; c < row.size(); ++c)
      if (std::isfinite(row[c])) hi = std::max(hi, row[c]);
  hi = hi > 0 ? hi * 1.12 : 1;
  const double y_step = tick_step(hi);
  const auto py = [&](double v) { return height - bottom - int(v / hi * (height - top - bottom)); };
  for (double v = 0; v <= hi; v += y_step) {
    cv::line(canvas, {left, py(v)}, {width - right, py(v)}, kGrid);
    text(canvas, number(v), {8, py(v) + 5});
  }
  const double bar_w = double(group_w - 16) / double(series);
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const int x0 = left + 8 + int(r) * group_w;
    for (std::size_t c = 1; c <= series; ++c) {
      const double v = t.rows[r][c];
      if (!std::isfinite(v)) continue;
      const int xa = x0 + int((c - 1) * bar_w), xb = x0 + int(c * bar_w) - 2;
      cv::rectangle(canvas, cv::Point(xa, py(v)), cv::Point(xb, py(0)), line_colour(c - 1 + (series == 1 ? 2 : 0)), -1);
      if (series <= 3 && bar_w >= 24) text(canvas, number(v), {xa, py(v) - 4}, 0.3);
    }
    const std::string label = r < t.row_labels.size() && !t.row_labels[r].empty() ? t.row_labels[r] : number(t.rows[r][0]);
    text(canvas, label, {x0, height - bottom + 18}, 0.33);
  }
  cv::line(canvas, {left, py(0)}, {width - right, py(0)}, kInk);
  text(canvas, style.title, {left, 28}, 0.55);
  text(canvas, style.y_label, {8, top - 8}, 0.45);
  if (!style.x_label.empty()) text(canvas, style.x_label, {width / 2 - 80, height - 6}, 0.45);
  if (series > 1)
    for (std::size_t c = 1; c <= series; ++c) {
      const int y = top + 12 + 20 * int(c - 1);
      cv::rectangle(canvas, {width - right + 12, y - 10}, {width - right + 26, y + 2}, line_colour(c - 1), -1);
      text(canvas, t.columns[c], {width - right + 32, y}, 0.42, line_colour(c - 1));
    }
  write_canvas(canvas, path);
}

}  // namespace rsaa::bench
