// The bench plots, drawn with OpenCV and written through OpenImageIO (atomically).
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "core/util/colour.h"
#include "image/image_io.h"
#include "tools/bench/bench.h"
#include "tools/bench/chart.h"
#include "tools/bench/growth.h"

namespace rsaa::bench {
namespace {

const cv::Scalar kInk(40, 40, 40), kGrid(220, 220, 220);

// Technique families by colour (BGR).
cv::Scalar family_colour(const TechniqueOptions& o) {
  if (o.technique == "noaa") return {0, 0, 0};
  if (o.technique == "fxaa") return {160, 40, 160};
  if (o.technique == "msaa") return {200, 110, 30};
  if (o.technique == "ssaa") return {40, 150, 40};
  if (o.technique == "ssaa-filtered") return {120, 160, 20};
  if (o.technique == "dcaa") return {20, 180, 200};
  if (o.technique == "dyncov") return {0, 110, 160};
  if (o.technique == "agaa") return {110, 110, 110};
  return o.similarity == "depth" ? cv::Scalar(30, 140, 240) : cv::Scalar(40, 40, 210);
}
cv::Scalar family_colour(const TechniqueResult& r) { return family_colour(r.options); }

// The k-th row of one family in a line plot: the family's colour, then darker and lighter shades
// of it, so that rows of one family (five RSAA rows in the growth plots) stay apart.
cv::Scalar family_shade(const cv::Scalar& colour, int k) {
  constexpr double kShades[] = {0.0, -0.45, 0.45, -0.7, 0.65};
  const double shade = kShades[k % 5];
  cv::Scalar out;
  for (int c = 0; c < 3; ++c) out[c] = shade < 0 ? colour[c] * (1 + shade) : colour[c] + (235 - colour[c]) * shade;
  return out;
}

// Marker k: a disc, a square, a triangle, a diamond, a cross.
void draw_marker(cv::Mat& canvas, cv::Point p, int k, const cv::Scalar& colour) {
  const int r = 4;
  switch (k % 5) {
    case 0: cv::circle(canvas, p, r - 1, colour, -1, cv::LINE_AA); break;
    case 1: cv::rectangle(canvas, p - cv::Point(r - 1, r - 1), p + cv::Point(r - 1, r - 1), colour, -1); break;
    case 2: {
      const std::vector<cv::Point> triangle = {p + cv::Point(0, -r), p + cv::Point(r, r), p + cv::Point(-r, r)};
      cv::fillConvexPoly(canvas, triangle, colour, cv::LINE_AA);
      break;
    }
    case 3: {
      const std::vector<cv::Point> diamond = {p + cv::Point(0, -r), p + cv::Point(r, 0), p + cv::Point(0, r),
                                              p + cv::Point(-r, 0)};
      cv::fillConvexPoly(canvas, diamond, colour, cv::LINE_AA);
      break;
    }
    default:
      cv::line(canvas, p + cv::Point(-r, -r), p + cv::Point(r, r), colour, 2, cv::LINE_AA);
      cv::line(canvas, p + cv::Point(-r, r), p + cv::Point(r, -r), colour, 2, cv::LINE_AA);
  }
}

// "R8 sadp a1" for rsaa 8x sadp auth1, the label itself otherwise. Every option the label names
// stays (cap1.5 ms sc, msaa, 1-pass, a table's name), so that two rows never share a legend entry.
std::string short_label(const std::string& label, const TechniqueOptions& o) {
  if (o.technique != "rsaa") return label;
  std::istringstream words(label);
  std::string word, out;
  while (words >> word) {
    if (word == "rsaa") {
      out = "R";
      continue;
    }
    if (out == "R" && word.size() == 2 && word[1] == 'x') {  // "rsaa 8x" -> "R8"
      out += word[0];
      continue;
    }
    if (word == "gl4x") continue;  // RSAA 4x's default pattern
    if (word.rfind("auth", 0) == 0) word = "a" + word.substr(4);
    if (word == "single-pass") word = "1-pass";
    out += " " + word;
  }
  return out;
}
std::string short_label(const TechniqueResult& r) { return short_label(r.label, r.options); }


void text(cv::Mat& canvas, const std::string& s, cv::Point at, double scale = 0.45,
          cv::Scalar colour = kInk) {
  cv::putText(canvas, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
}

// Width in pixels of `s` drawn by text() at `scale`, plus a margin: legend columns are as wide
// as their longest label (RSAA labels name every option they set).
int label_column(const std::vector<std::string>& labels, double scale, int at_least) {
  int widest = at_least;
  for (const std::string& s : labels) {
    int baseline = 0;
    widest = std::max(widest, cv::getTextSize(s, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline).width + 12);
  }
  return widest;
}

std::vector<const TechniqueResult*> of_scene(const std::vector<TechniqueResult>& results, const std::string& scene) {
  std::vector<const TechniqueResult*> out;
  for (const TechniqueResult& r : results)
    if (r.scene == scene) out.push_back(&r);
  return out;
}

}  // namespace

void plot_pareto(const std::vector<TechniqueResult>& results, const std::string& scene, const std::string& path) {
  const auto rows = of_scene(results, scene);
  if (rows.empty()) return;
  std::vector<std::string> labels;
  for (const auto* r : rows) labels.push_back("* " + short_label(*r));
  const int label_width = label_column(labels, 0.4, 150);
  const int right = label_width + 180, width = 730 + right, height = 600, left = 70, top = 50, bottom = 60;
  cv::Mat canvas(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  double x_lo = 1e9, x_hi = 0, y_lo = 1e9, y_hi = 0;
  for (const auto* r : rows) {
    x_lo = std::min(x_lo, r->frame_ratio), x_hi = std::max(x_hi, r->frame_ratio);
    y_lo = std::min(y_lo, r->psnr_db), y_hi = std::max(y_hi, r->psnr_db);
  }
  x_lo = std::log2(std::max(x_lo, 1e-3)) - 0.2, x_hi = std::log2(std::max(x_hi, 1e-3)) + 0.2;
  y_lo = std::floor(y_lo - 1), y_hi = std::ceil(y_hi + 1);
  const auto px = [&](double ratio) {
    return left + int((std::log2(std::max(ratio, 1e-3)) - x_lo) / (x_hi - x_lo) * (width - left - right));
  };
  const auto py = [&](double db) { return height - bottom - int((db - y_lo) / (y_hi - y_lo) * (height - top - bottom)); };
  // At most about 12 powers of two labelled (ratios from 1e-6 to 1e6 wrote 40 labels over each other).
  const int e_step = std::max(1, int(std::floor(x_hi) - std::ceil(x_lo)) / 12 + 1);
  for (int e = int(std::ceil(x_lo)); e <= int(std::floor(x_hi)); e += e_step) {
    const double ratio = std::pow(2.0, e);
    cv::line(canvas, {px(ratio), top}, {px(ratio), height - bottom}, kGrid);
    char label[32];
    // Far from 1, a power of two: 0.000976562x and 1.04858e+06x were too wide to stand apart.
    if (e >= -3 && e <= 12) std::snprintf(label, sizeof label, "%gx", ratio);
    else std::snprintf(label, sizeof label, "2^%dx", e);
    text(canvas, label, {px(ratio) - 12, height - bottom + 20});
  }
  for (int db = int(y_lo); db <= int(y_hi); db += std::max(1, int(y_hi - y_lo) / 8)) {
    cv::line(canvas, {left, py(db)}, {width - right, py(db)}, kGrid);
    text(canvas, std::to_string(db), {left - 30, py(db) + 5});
  }
  cv::rectangle(canvas, {left, top}, {width - right, height - bottom}, kInk);
  text(canvas, "frame time / no-AA frame time (log scale)", {left + 150, height - 15}, 0.5);
  text(canvas, "PSNR vs 64x SSAA (dB)", {10, top - 15}, 0.5);
  text(canvas, scene.size() > 60 ? "..." + scene.substr(scene.size() - 57) : scene, {left + 150, top - 15}, 0.55);
  // The Pareto front, left to right.
  std::vector<const TechniqueResult*> front;
  for (const auto* r : rows)
    if (r->pareto) front.push_back(r);
  std::sort(front.begin(), front.end(), [](auto* a, auto* b) { return a->frame_ratio < b->frame_ratio; });
  for (std::size_t i = 1; i < front.size(); ++i)
    cv::line(canvas, {px(front[i - 1]->frame_ratio), py(front[i - 1]->psnr_db)},
             {px(front[i]->frame_ratio), py(front[i]->psnr_db)}, {150, 150, 150}, 2, cv::LINE_AA);
  int legend_y = top + 10;
  for (const auto* r : rows) {
    const cv::Point p(px(r->frame_ratio), py(r->psnr_db));
    cv::circle(canvas, p, r->pareto ? 7 : 5, family_colour(*r), r->pareto ? -1 : 2, cv::LINE_AA);
    // Only the front is labelled in the plot (the rest cluster); the legend lists everything.
    if (r->pareto) {
      // Right of the point, or left of it where the label would run into the legend.
      int baseline = 0;
      const int w = cv::getTextSize(short_label(*r), cv::FONT_HERSHEY_SIMPLEX, 0.4, 1, &baseline).width;
      const int x = p.x + 8 + w > width - right - 4 ? p.x - 8 - w : p.x + 8;
      text(canvas, short_label(*r), {x, p.y - 6}, 0.4, family_colour(*r));
    }
    char line[96];
    std::snprintf(line, sizeof line, "%s %s", r->pareto ? "*" : " ", short_label(*r).c_str());
    text(canvas, line, {width - right + 10, legend_y}, 0.4, family_colour(*r));
    std::snprintf(line, sizeof line, "%6.2f dB  %6.2fx", r->psnr_db, r->frame_ratio);
    text(canvas, line, {width - right + 10 + label_width, legend_y}, 0.4, family_colour(*r));
    legend_y += 17;
  }
  text(canvas, "* = on the Pareto front", {width - right + 10, legend_y + 10}, 0.4);
  write_canvas(canvas, path);
}

void plot_growth(const GrowthResults& results, GrowthAxis axis, const std::string& path) {
  std::vector<const GrowthPoint*> points;
  for (const GrowthPoint& p : results.points)
    if (p.axis == axis && p.frame_ms > 0) points.push_back(&p);
  if (points.empty()) return;
  std::vector<std::string> labels;
  for (const GrowthSlope& slope : growth_slopes(results))
    if (slope.axis == axis) labels.push_back(short_label(slope.label, slope.options));
  const int label_width = label_column(labels, 0.4, 160);
  const int right = label_width + 182, width = 730 + right, height = 600, left = 70, top = 50, bottom = 60;
  cv::Mat canvas(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  double x_lo = 1e300, x_hi = 0, y_lo = 1e300, y_hi = 0;
  for (const auto* p : points) {
    x_lo = std::min(x_lo, p->x()), x_hi = std::max(x_hi, p->x());
    y_lo = std::min(y_lo, p->frame_ms), y_hi = std::max(y_hi, p->frame_ms);
  }
  // log2 axes: a doubling is one grid step, and a line's slope is its growth exponent.
  x_lo = std::log2(x_lo) - 0.2, x_hi = std::log2(x_hi) + 0.2;
  y_lo = std::floor(std::log2(y_lo)), y_hi = std::ceil(std::log2(y_hi));
  if (x_hi - x_lo < 1) x_hi = x_lo + 1;
  if (y_hi - y_lo < 1) y_hi = y_lo + 1;
  const auto px = [&](double x) { return left + int((std::log2(x) - x_lo) / (x_hi - x_lo) * (width - left - right)); };
  const auto py = [&](double ms) {
    return height - bottom - int((std::log2(ms) - y_lo) / (y_hi - y_lo) * (height - top - bottom));
  };
  for (int e = int(y_lo); e <= int(y_hi); ++e) {
    cv::line(canvas, {left, py(std::pow(2.0, e))}, {width - right, py(std::pow(2.0, e))}, kGrid);
    char label[32];
    std::snprintf(label, sizeof label, "%g", std::pow(2.0, e));
    text(canvas, label, {left - 45, py(std::pow(2.0, e)) + 5});
  }
  std::vector<double> xs;
  for (const auto* p : points)
    if (std::find(xs.begin(), xs.end(), p->x()) == xs.end()) xs.push_back(p->x());
  for (double x : xs) {
    cv::line(canvas, {px(x), top}, {px(x), height - bottom}, kGrid);
    char label[48];
    if (axis == GrowthAxis::Pixels) {
      const auto* p = *std::find_if(points.begin(), points.end(), [&](auto* q) { return q->x() == x; });
      std::snprintf(label, sizeof label, "%dx%d", p->width, p->height);
    } else if (axis == GrowthAxis::Triangles) {
      std::snprintf(label, sizeof label, "%.0fk", x / 1000.0);
    } else {
      std::snprintf(label, sizeof label, "%.0f", x);
    }
    text(canvas, label, {px(x) - 30, height - bottom + 20});
  }
  cv::rectangle(canvas, {left, top}, {width - right, height - bottom}, kInk);
  text(canvas,
       axis == GrowthAxis::Pixels      ? "image size (pixels, log scale)"
       : axis == GrowthAxis::Triangles ? "triangles (log scale)"
                                       : "lights N (log scale): the fixed light + N - 1 point lights",
       {left + 200, height - 15}, 0.5);
  text(canvas, "frame ms (log scale): " + scene_short_name(results.scene), {10, top - 15}, 0.5);
  int legend_y = top + 10;
  std::vector<std::string> drawn;
  const auto slopes = growth_slopes(results);
  std::map<std::string, int> family_rows;  // rows drawn so far per family colour
  for (const GrowthSlope& s : slopes) {
    if (s.axis != axis) continue;
    const cv::Scalar base = family_colour(s.options);
    const int k = family_rows[cv::format("%g,%g,%g", base[0], base[1], base[2])]++;
    const cv::Scalar colour = family_shade(base, k);
    const GrowthPoint* previous = nullptr;
    for (const auto* p : points) {
      if (p->label != s.label) continue;
      if (previous)
        cv::line(canvas, {px(previous->x()), py(previous->frame_ms)}, {px(p->x()), py(p->frame_ms)}, colour, 1,
                 cv::LINE_AA);
      draw_marker(canvas, {px(p->x()), py(p->frame_ms)}, k, colour);
      previous = p;
    }
    draw_marker(canvas, {width - right + 8, legend_y - 4}, k, colour);
    text(canvas, short_label(s.label, s.options), {width - right + 16, legend_y}, 0.4, colour);
    char line[96];
    std::snprintf(line, sizeof line, "exponent %.2f", s.exponent);
    text(canvas, line, {width - right + 22 + label_width, legend_y}, 0.4, colour);
    legend_y += 17;
  }
  write_canvas(canvas, path);
}

void plot_pass_times(const std::vector<TechniqueResult>& results, const std::string& scene, const std::string& path) {
  const auto rows = of_scene(results, scene);
  if (rows.empty()) return;
  const std::map<std::string, cv::Scalar> colours = {{"main", {200, 130, 60}},
                                                     {"pre-pass", {60, 60, 210}},
                                                     {"post-process", {60, 170, 60}},
                                                     {"aggregates", {170, 80, 150}},
                                                     {"resolve", {160, 160, 160}}};
  std::vector<std::string> labels;
  for (const auto* r : rows) labels.push_back(short_label(*r));
  const int left = label_column(labels, 0.42, 180) + 10, width = 770 + left, row_h = 24, right = 70, top = 40;
  const int height = top + int(rows.size()) * row_h + 70;
  cv::Mat canvas(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  double longest = 0;
  for (const auto* r : rows) longest = std::max(longest, r->frame_ms);
  const double scale = (width - left - right) / std::max(longest, 1e-6);
  text(canvas, "per-pass wall-clock time, median of the timed frames (ms): " + scene.substr(scene.rfind('/') + 1),
       {10, 25}, 0.5);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const int y = top + int(i) * row_h;
    text(canvas, short_label(*rows[i]), {10, y + 16}, 0.42);
    double x = left;
    for (const PassTime& p : rows[i]->pass_medians) {
      const auto it = colours.find(p.pass);
      const double w = p.wall_milliseconds * scale;
      cv::rectangle(canvas, cv::Point(int(x), y + 3), cv::Point(int(x + w), y + row_h - 3),
                    it == colours.end() ? kInk : it->second, -1);
      x += w;
    }
    char total[32];
    std::snprintf(total, sizeof total, "%.1f", rows[i]->frame_ms);
    text(canvas, total, {int(x) + 5, y + 16}, 0.38);
  }
  int x = 10;
  for (const auto& [name, colour] : colours) {
    cv::rectangle(canvas, {x, height - 40}, {x + 14, height - 26}, colour, -1);
    text(canvas, name, {x + 20, height - 28}, 0.45);
    x += 150;
  }
  write_canvas(canvas, path);
}

}  // namespace rsaa::bench

#include "tools/bench/csv.h"

namespace rsaa::bench {

void plot_csv(const std::string& csv_path, const std::string& x_column, const std::vector<std::string>& y_columns,
              bool log_x, const std::string& title, const std::string& png_path) {
  // Quoted text columns (the bench's own CSV) are fine; the columns drawn must be numbers.
  const CsvTable table = read_csv(csv_path);
  const auto column = [&](const std::string& name) {
    const auto it = std::find(table.header.begin(), table.header.end(), name);
    if (it == table.header.end()) throw std::runtime_error(csv_path + ": no column '" + name + "'");
    if (std::count(table.header.begin(), table.header.end(), name) > 1)
      throw std::runtime_error(csv_path + ": column '" + name + "' appears more than once in the header: which is meant?");
    return std::size_t(it - table.header.begin());
  };
  const std::size_t xc = column(x_column);
  std::vector<std::size_t> ycs;
  for (const auto& y : y_columns) ycs.push_back(column(y));
  std::vector<double> xs;
  std::vector<std::vector<double>> ys(ycs.size());
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    const double x = csv_number(table, csv_path, row, xc);
    if (log_x && !(x > 0)) throw std::runtime_error(csv_path + ": log x needs positive values");
    xs.push_back(log_x ? std::log10(x) : x);
    for (std::size_t k = 0; k < ycs.size(); ++k) ys[k].push_back(csv_number(table, csv_path, row, ycs[k]));
  }
  if (xs.size() < 2) throw std::runtime_error(csv_path + ": needs at least two rows");
  double x_lo = *std::min_element(xs.begin(), xs.end()), x_hi = *std::max_element(xs.begin(), xs.end());
  double y_lo = std::numeric_limits<double>::infinity(), y_hi = -y_lo;
  for (const auto& s : ys)
    for (double v : s) y_lo = std::min(y_lo, v), y_hi = std::max(y_hi, v);
  // x values that differ by less than the axis tells apart (1e-320 and 2e-320) would be drawn at
  // one x with their labels over each other; equal values are fine.
  if (x_lo != x_hi && drawn_as_one_value(x_lo, x_hi)) {
    char values[96];
    std::snprintf(values, sizeof values, "from %g to %g", x_lo, x_hi);
    throw std::runtime_error(csv_path + ": column '" + x_column + "' runs " + values +
                             ", too narrow a span to tell the points apart on the x axis (rescale the column)");
  }
  // A span beyond a double (1e308 and -1e308) would put every point at NaN: nothing drawn.
  try {
    const AxisRange x = drawable_range(x_lo, x_hi, 0.0, "x"), y = drawable_range(y_lo, y_hi, 0.08, "y");
    x_lo = x.lo, x_hi = x.hi, y_lo = y.lo, y_hi = y.hi;
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(csv_path + ": " + e.what());
  }
  const int width = 800, height = 480, left = 90, right = 30, top = 50, bottom = 60;
  cv::Mat canvas(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const auto px = [&](double x) { return left + int((x - x_lo) / (x_hi - x_lo) * (width - left - right)); };
  const auto py = [&](double y) { return height - bottom - int((y - y_lo) / (y_hi - y_lo) * (height - top - bottom)); };
  cv::rectangle(canvas, {left, top}, {width - right, height - bottom}, kInk);
  // Enough significant digits that labels a quarter of the span apart differ (1e9 and 1e9 + 300
  // were all "1e+09").
  const auto digits = [](double lo, double hi) {
    const double magnitude = std::max(std::abs(lo), std::abs(hi)), span = hi - lo;
    return span > 0 && magnitude > 0 ? std::clamp(int(std::ceil(std::log10(magnitude / span))) + 2, 4, 17) : 4;
  };
  const int y_digits = digits(y_lo, y_hi), x_digits = digits(x_lo, x_hi);
  for (int t = 0; t <= 4; ++t) {
    const double y = y_lo + (y_hi - y_lo) * (t / 4.0);
    cv::line(canvas, {left, py(y)}, {width - right, py(y)}, kGrid);
    char label[32];
    std::snprintf(label, sizeof label, "%.*g", y_digits, y);
    text(canvas, label, {5, py(y) + 5});
  }
  // One label per point while they fit (the trade curves), else 5 ticks: a label per row of a
  // 2-million-row CSV took 33 s.
  constexpr std::size_t kMostPointLabels = 20;
  std::vector<double> x_labels = xs;
  if (xs.size() > kMostPointLabels) {
    x_labels.clear();
    for (int t = 0; t <= 4; ++t) x_labels.push_back(x_lo + (x_hi - x_lo) * (t / 4.0));
  }
  for (double x : x_labels) {
    char label[32];
    std::snprintf(label, sizeof label, "%.*g", log_x ? 4 : x_digits, log_x ? std::pow(10.0, x) : x);
    text(canvas, label, {px(x) - 15, height - bottom + 20});
  }
  text(canvas, title, {left, 30}, 0.55);
  text(canvas, x_column + (log_x ? " (log scale)" : ""), {width / 2 - 60, height - 15}, 0.5);
  const cv::Scalar colours[] = {{40, 40, 210}, {200, 110, 30}, {40, 150, 40}, {160, 40, 160}};
  for (std::size_t k = 0; k < ys.size(); ++k) {
    const cv::Scalar c = colours[k % 4];
    for (std::size_t i = 0; i < xs.size(); ++i) {
      cv::circle(canvas, {px(xs[i]), py(ys[k][i])}, 4, c, -1, cv::LINE_AA);
      if (i) cv::line(canvas, {px(xs[i - 1]), py(ys[k][i - 1])}, {px(xs[i]), py(ys[k][i])}, c, 2, cv::LINE_AA);
    }
    text(canvas, y_columns[k], {width - right - 200, top + 20 + 18 * int(k)}, 0.45, c);
  }
  write_canvas(canvas, png_path);
}

}  // namespace rsaa::bench

namespace rsaa::bench {

const std::vector<std::string>& crop_labels() {
  static const std::vector<std::string> labels = {
      "noaa", "fxaa", "msaa 4x", "ssaa-filtered k2", "dyncov", "dcaa", "agaa 8x", "rsaa 4x gl4x sadp auth0",
      "rsaa 8x sadp auth0", "rsaa 8x sadp auth2"};
  return labels;
}

void plot_crops(const std::vector<std::pair<std::string, DisplayImage>>& images, const DisplayImage& reference,
                const std::string& path) {
  if (images.empty()) return;
  const int w = reference.width, h = reference.height;
  for (const auto& [label, image] : images)
    if (image.width != w || image.height != h) throw std::invalid_argument("plot_crops: '" + label + "' has another size");
  // The crop window: a quarter of each side, where the first image's error is largest (a
  // summed-area table makes every window O(1)).
  const int cw = std::max(8, w / 4), ch = std::max(8, h / 4);
  std::vector<double> integral(std::size_t(w + 1) * (h + 1), 0.0);
  const DisplayImage& first = images.front().second;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double e = 0.0;
      for (int c = 0; c < 3; ++c) e += std::abs(int(first.rgb[(y * w + x) * 3 + c]) - int(reference.rgb[(y * w + x) * 3 + c]));
      integral[(y + 1) * (w + 1) + x + 1] = e + integral[y * (w + 1) + x + 1] + integral[(y + 1) * (w + 1) + x] -
                                            integral[y * (w + 1) + x];
    }
  int best_x = 0, best_y = 0;
  double best = -1.0;
  for (int y = 0; y + ch <= h; y += 2)
    for (int x = 0; x + cw <= w; x += 2) {
      const double e = integral[(y + ch) * (w + 1) + x + cw] - integral[y * (w + 1) + x + cw] -
                       integral[(y + ch) * (w + 1) + x] + integral[y * (w + 1) + x];
      if (e > best) best = e, best_x = x, best_y = y;
    }
  const int scale = std::max(1, 360 / std::max(cw, ch)), pad = 8, caption = 22;
  const int tile_w = std::min(cw, w) * scale, tile_h = std::min(ch, h) * scale;
  std::vector<std::pair<std::string, const DisplayImage*>> tiles;
  for (const auto& [label, image] : images) tiles.push_back({label, &image});
  tiles.push_back({"64x SSAA (reference)", &reference});
  const int columns = std::min<int>(4, int(tiles.size())), rows = (int(tiles.size()) + columns - 1) / columns;
  cv::Mat canvas(rows * (tile_h + caption + pad) + pad, columns * (tile_w + pad) + pad, CV_8UC3, cv::Scalar(255, 255, 255));
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const int x0 = pad + int(i % columns) * (tile_w + pad), y0 = pad + int(i / columns) * (tile_h + caption + pad);
    text(canvas, tiles[i].first, {x0, y0 + 15});
    const DisplayImage& image = *tiles[i].second;
    for (int y = 0; y < tile_h; ++y)
      for (int x = 0; x < tile_w; ++x) {
        const std::uint8_t* p = &image.rgb[((best_y + y / scale) * w + best_x + x / scale) * 3];
        canvas.at<cv::Vec3b>(y0 + caption + y, x0 + x) = {p[2], p[1], p[0]};
      }
  }
  write_canvas(canvas, path);
}

}  // namespace rsaa::bench
