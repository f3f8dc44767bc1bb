#include "tools/bench/diagnosis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/util/colour.h"
#include "core/util/parallel.h"
#include "core/rsaa/polygon.h"

namespace rsaa {
namespace {

// Squared error of a linear colour against a display (8-bit sRGB) reference, mean of RGB.
double display_error(const Rgb& linear, const Rgb& reference_linear) {
  const auto channel = [](float a, float b) {
    const double d = 255.0 * (double(linear_to_srgb(a)) - double(linear_to_srgb8(b)) / 255.0);
    return d * d;
  };
  return (channel(linear.r, reference_linear.r) + channel(linear.g, reference_linear.g) +
          channel(linear.b, reference_linear.b)) / 3.0;
}

// The 8-bit value as written, for the figures that must match `rsaa compare`.
double quantised_error(const Rgb& a, const Rgb& b) {
  const auto channel = [](float x, float y) {
    const double d = double(linear_to_srgb8(x)) - double(linear_to_srgb8(y));
    return d * d;
  };
  return (channel(a.r, b.r) + channel(a.g, b.g) + channel(a.b, b.b)) / 3.0;
}

double psnr_of(double summed_error, std::size_t pixels) {
  const double mse = summed_error / double(std::max<std::size_t>(pixels, 1));
  return mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
}

// The best single bilinear fetch of `colour` around pixel (x, y) against the reference: a 21 x 21
// grid over [-1, 1]^2, then a 9 x 9 refinement of step 0.0125 around the best grid point.
Rgb oracle_fetch(const Image& colour, const Rgb& reference, int x, int y) {
  double best_error = std::numeric_limits<double>::infinity();
  double best_dx = 0.0, best_dy = 0.0;
  const auto try_offset = [&](double dx, double dy) {
    if (std::abs(dx) > 1.0 || std::abs(dy) > 1.0) return;
    const double e = display_error(bilinear_fetch(colour, x + dx, y + dy), reference);
    if (e < best_error) best_error = e, best_dx = dx, best_dy = dy;
  };
  for (int j = -10; j <= 10; ++j)
    for (int i = -10; i <= 10; ++i) try_offset(i * 0.1, j * 0.1);
  const double cx = best_dx, cy = best_dy;
  for (int j = -4; j <= 4; ++j)
    for (int i = -4; i <= 4; ++i) try_offset(cx + i * 0.0125, cy + j * 0.0125);
  return bilinear_fetch(colour, x + best_dx, y + best_dy);
}

DiagnosisClass classify(const DiagnosisInputs& in, int x, int y, Mask all_similar) {
  const std::size_t p = std::size_t(y) * in.noaa.width + x;
  const PixelSurfaces& s = in.surfaces[p];
  const bool resampled = in.masks[p] != all_similar;
  if (s.count <= 1)
    return resampled ? DiagnosisClass::OneSurfaceResampled : DiagnosisClass::OneSurfaceUntouched;
  if (!resampled) return in.subsample_sees_other[p] ? DiagnosisClass::Missed : DiagnosisClass::Unsampled;
  // Does any neighbour centre show a surface of this pixel other than its own centre's?
  const std::uint32_t own = in.centre_surface[p];
  bool other_colour = false;
  for (int j = -1; j <= 1 && !other_colour; ++j)
    for (int i = -1; i <= 1 && !other_colour; ++i) {
      const int nx = std::clamp(x + i, 0, in.noaa.width - 1), ny = std::clamp(y + j, 0, in.noaa.height - 1);
      const std::uint32_t n = in.centre_surface[std::size_t(ny) * in.noaa.width + nx];
      if (n == own) continue;
      for (int k = 0; k < std::min(s.count, PixelSurfaces::kMaxKept); ++k) other_colour |= s.ids[k] == n;
    }
  if (!other_colour) return DiagnosisClass::NoOtherColour;
  if (s.count >= 3) return DiagnosisClass::ThreeSurfaces;
  switch (in.table->sources[in.masks[p]]) {
    case OffsetSource::OneLine: return DiagnosisClass::TwoSurfacesOneLine;
    case OffsetSource::TwoLine: return DiagnosisClass::TwoSurfacesTwoLine;
    default: return DiagnosisClass::TwoSurfacesFallback;
  }
}

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<std::uint32_t> smooth_surface_ids(const Scene& scene) {
  const std::size_t triangles = scene.triangle_count();
  std::vector<glm::vec3> normals(triangles);
  std::vector<int> range_of(triangles, -1);
  for (std::size_t r = 0; r < scene.draws.size(); ++r)
    for (std::uint32_t t = scene.draws[r].first_index / 3;
         t < (scene.draws[r].first_index + scene.draws[r].index_count) / 3 && t < triangles; ++t)
      range_of[t] = int(r);
  const auto position = [&](std::size_t t, int k) { return scene.vertices[scene.indices[3 * t + k]].position; };
  for (std::size_t t = 0; t < triangles; ++t) {
    const glm::vec3 n = glm::cross(position(t, 1) - position(t, 0), position(t, 2) - position(t, 0));
    const float length = glm::length(n);
    normals[t] = length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f);
  }
  // Edges keyed by their two end positions (bit patterns, sorted): welds split vertices.
  using Key = std::array<std::uint32_t, 6>;
  const auto key_of = [](glm::vec3 a, glm::vec3 b) {
    Key ka, kb;
    std::memcpy(ka.data(), &a, 12), std::memcpy(ka.data() + 3, &b, 12);
    std::memcpy(kb.data(), &b, 12), std::memcpy(kb.data() + 3, &a, 12);
    return std::min(ka, kb);
  };
  std::map<Key, std::uint32_t> first_triangle_of_edge;
  std::vector<std::uint32_t> parent(triangles);
  for (std::size_t t = 0; t < triangles; ++t) parent[t] = std::uint32_t(t);
  const float cos30 = std::cos(glm::radians(30.0f));
  for (std::size_t t = 0; t < triangles; ++t) {
    if (normals[t] == glm::vec3(0.0f)) continue;
    for (int k = 0; k < 3; ++k) {
      const auto [it, inserted] =
          first_triangle_of_edge.emplace(key_of(position(t, k), position(t, (k + 1) % 3)), std::uint32_t(t));
      const std::uint32_t u = it->second;
      if (!inserted && range_of[u] == range_of[t] && glm::dot(normals[u], normals[t]) > cos30)
        parent[find_root(parent, std::uint32_t(t))] = find_root(parent, u);
    }
  }
  std::vector<std::uint32_t> ids(triangles);
  std::map<std::uint32_t, std::uint32_t> numbering;
  for (std::size_t t = 0; t < triangles; ++t)
    ids[t] = numbering.emplace(find_root(parent, std::uint32_t(t)), std::uint32_t(numbering.size() + 1))
                 .first->second;
  return ids;
}

Rgb coverage_resolve(const DiagnosisInputs& in, int x, int y) {
  const int w = in.noaa.width, h = in.noaa.height;
  const std::size_t p = std::size_t(y) * w + x;
  const PixelSurfaces& s = in.surfaces[p];
  const Rgb own = in.noaa.at(x, y);
  if (s.total <= 0 || s.count <= 1) return own;
  // Edge neighbours first, then the diagonals.
  static const int steps[8][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}, {-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
  const auto colour_of = [&](std::uint32_t surface) {
    if (surface == in.centre_surface[p]) return own;
    for (const auto& d : steps) {
      const int nx = x + d[0], ny = y + d[1];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
      if (in.centre_surface[std::size_t(ny) * w + nx] == surface) return in.noaa.at(nx, ny);
    }
    return own;
  };
  double r = 0.0, g = 0.0, b = 0.0;
  int counted = 0;
  for (int k = 0; k < std::min(s.count, PixelSurfaces::kMaxKept); ++k) {
    const Rgb c = colour_of(s.ids[k]);
    const double weight = double(s.samples[k]) / s.total;
    r += weight * c.r, g += weight * c.g, b += weight * c.b;
    counted += s.samples[k];
  }
  const double rest = double(std::max(0, s.total - counted)) / s.total;  // surfaces beyond the kept ones
  return {float(r + rest * own.r), float(g + rest * own.g), float(b + rest * own.b)};
}

Rgb line_fit_resolve(const DiagnosisInputs& in, int x, int y) {
  const int w = in.noaa.width, h = in.noaa.height;
  const std::size_t p = std::size_t(y) * w + x;
  const std::uint32_t own_surface = in.centre_surface[p];
  const std::vector<Vec2>& positions = in.table->pattern.positions;
  struct Labelled {
    Vec2 position;  // pixel space, from the pixel's centre
    bool other;     // on another surface than the pixel's centre
    int weight;
  };
  std::vector<Labelled> points;
  bool any_other = false;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      const int nx = x + i, ny = y + j;
      if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
      const std::size_t q = std::size_t(ny) * w + nx;
      const bool centre_is_own = in.centre_surface[q] == own_surface;
      for (std::size_t k = 0; k < positions.size(); ++k) {
        const Vec2 at{i + positions[k].x, j + positions[k].y};
        if (std::abs(at.x) > 1.0 || std::abs(at.y) > 1.0) continue;
        const bool similar = (in.masks[q] >> k) & 1u;
        const bool other = centre_is_own != similar;
        points.push_back({at, other, i == 0 && j == 0 ? 3 : 1});
        any_other = any_other || other;
      }
    }
  if (!any_other) return in.rsaa.at(x, y);

  // The line: `other` where dot(normal, p) > offset.
  int best_misplaced = std::numeric_limits<int>::max();
  double best_gap = -1.0, best_offset = 0.0;
  Vec2 best_normal{1.0, 0.0};
  constexpr int kDirections = 128;
  std::vector<std::pair<double, const Labelled*>> projected(points.size());
  for (int d = 0; d < kDirections; ++d) {
    const double angle = 2.0 * M_PI * d / kDirections;
    const Vec2 normal{std::cos(angle), std::sin(angle)};
    for (std::size_t k = 0; k < points.size(); ++k) projected[k] = {dot(normal, points[k].position), &points[k]};
    std::sort(projected.begin(), projected.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    // Sweep the offset upwards: points below it are counted on the pixel's surface.
    int own_above = 0, other_below = 0;
    for (const auto& [v, point] : projected) own_above += point->other ? 0 : point->weight;
    for (std::size_t m = 0; m <= projected.size(); ++m) {
      if (m > 0) {
        const Labelled& passed = *projected[m - 1].second;
        if (passed.other) other_below += passed.weight;
        else own_above -= passed.weight;
      }
      if (m > 0 && m < projected.size() && projected[m - 1].first == projected[m].first) continue;
      const double below = m > 0 ? projected[m - 1].first : projected[0].first - 1.0;
      const double above = m < projected.size() ? projected[m].first : projected.back().first + 1.0;
      const int misplaced = own_above + other_below;
      if (misplaced < best_misplaced || (misplaced == best_misplaced && above - below > best_gap))
        best_misplaced = misplaced, best_gap = above - below, best_offset = 0.5 * (below + above),
        best_normal = normal;
    }
  }
  const double beyond =
      polygon_area(clip_to_half_plane(pixel_square(), best_normal.x, best_normal.y, -best_offset));

  // Along the normal, the step whose bilinear weight on other surfaces' centres matches `beyond`.
  const auto centre_is_other = [&](int i, int j) {
    const int nx = std::clamp(x + i, 0, w - 1), ny = std::clamp(y + j, 0, h - 1);
    return in.centre_surface[std::size_t(ny) * w + nx] != own_surface;
  };
  double best_step = 0.0, best_mismatch = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= 64; ++k) {
    const double step = k / 64.0, ox = step * best_normal.x, oy = step * best_normal.y;
    const int x0 = int(std::floor(ox)), y0 = int(std::floor(oy));
    const double fx = ox - x0, fy = oy - y0;
    const double weight = (centre_is_other(x0, y0) ? (1 - fx) * (1 - fy) : 0.0) +
                          (centre_is_other(x0 + 1, y0) ? fx * (1 - fy) : 0.0) +
                          (centre_is_other(x0, y0 + 1) ? (1 - fx) * fy : 0.0) +
                          (centre_is_other(x0 + 1, y0 + 1) ? fx * fy : 0.0);
    const double mismatch = std::abs(weight - beyond);
    if (mismatch < best_mismatch - 1e-12) best_mismatch = mismatch, best_step = step;
  }
  return bilinear_fetch(in.noaa, x + best_step * best_normal.x, y + best_step * best_normal.y);
}

const char* to_string(DiagnosisClass c) {
  static const char* const names[kDiagnosisClassCount] = {
      "1 surface, left alone", "1 surface, resampled (false edge)", "2+ surfaces, unseen by the subsamples",
      "2+ surfaces, missed by the similarity test",
      "2+ surfaces, no other colour in 3x3", "2 surfaces, one-line offset", "2 surfaces, two-line offset",
      "2 surfaces, fallback/scene offset", "3+ surfaces, resampled"};
  return names[int(c)];
}

const std::array<std::array<std::uint8_t, 3>, kDiagnosisClassCount>& diagnosis_class_colours() {
  static const std::array<std::array<std::uint8_t, 3>, kDiagnosisClassCount> colours = {{
      {200, 200, 200},  // grey
      {255, 140, 0},    // orange
      {255, 0, 160},    // pink
      {255, 40, 40},    // red
      {200, 60, 255},   // violet
      {60, 200, 60},    // green
      {60, 200, 255},   // cyan
      {255, 255, 60},   // yellow
      {60, 90, 255},    // blue
  }};
  return colours;
}

Diagnosis diagnose(const DiagnosisInputs& in) {
  const int w = in.noaa.width, h = in.noaa.height;
  const std::size_t n = std::size_t(w) * std::size_t(h);
  if (!in.table) throw std::invalid_argument("diagnose: no offset table");
  if (in.rsaa.width != w || in.rsaa.height != h || in.reference.width != w || in.reference.height != h ||
      in.masks.size() != n || in.surfaces.size() != n || in.centre_surface.size() != n ||
      in.subsample_sees_other.size() != n)
    throw std::invalid_argument("diagnose: inputs of different sizes");
  const bool has_baseline = in.baseline.width != 0;
  if (has_baseline && (in.baseline.width != w || in.baseline.height != h))
    throw std::invalid_argument("diagnose: the baseline image has another size");
  const Mask all_similar = full_mask(in.table->pattern.size());
  for (Mask m : in.masks)
    if (m > all_similar) throw std::invalid_argument("diagnose: a mask does not fit the table's pattern");

  Diagnosis d;
  d.width = w, d.height = h;
  d.pixel_class.resize(n);
  d.rsaa_error.resize(n);
  d.oracle = Image(w, h);
  d.coverage = Image(w, h);
  std::vector<double> noaa_error(n), oracle_error(n), baseline_error(n), coverage_error(n), line_fit_error(n);
  parallel_for(std::uint64_t(h), 8, 0, [&](std::uint64_t begin, std::uint64_t end) {
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t p = std::size_t(y) * w + x;
        const Rgb& ref = in.reference.at(x, y);
        d.oracle.at(x, y) = oracle_fetch(in.noaa, ref, x, y);
        d.rsaa_error[p] = float(quantised_error(in.rsaa.at(x, y), ref));
        noaa_error[p] = quantised_error(in.noaa.at(x, y), ref);
        oracle_error[p] = quantised_error(d.oracle.at(x, y), ref);
        d.coverage.at(x, y) = coverage_resolve(in, x, y);
        coverage_error[p] = quantised_error(d.coverage.at(x, y), ref);
        if (has_baseline) baseline_error[p] = quantised_error(in.baseline.at(x, y), ref);
        d.pixel_class[p] = classify(in, x, y, all_similar);
        const DiagnosisClass c = d.pixel_class[p];
        const bool two_surfaces = c == DiagnosisClass::TwoSurfacesOneLine || c == DiagnosisClass::TwoSurfacesTwoLine ||
                                  c == DiagnosisClass::TwoSurfacesFallback;
        line_fit_error[p] = two_surfaces ? quantised_error(line_fit_resolve(in, x, y), ref) : d.rsaa_error[p];
      }
  });

  d.rows.resize(kDiagnosisClassCount);
  for (int c = 0; c < kDiagnosisClassCount; ++c) d.rows[c].name = to_string(DiagnosisClass(c));
  double rsaa_total = 0.0, noaa_total = 0.0, oracle_total = 0.0, baseline_total = 0.0, coverage_total = 0.0,
         line_fit_total = 0.0;
  for (std::size_t p = 0; p < n; ++p) {
    DiagnosisRow& row = d.rows[int(d.pixel_class[p])];
    ++row.pixels;
    row.rsaa_error += d.rsaa_error[p];
    row.noaa_error += noaa_error[p];
    row.oracle_error += oracle_error[p];
    row.baseline_error += baseline_error[p];
    row.coverage_error += coverage_error[p];
    row.line_fit_error += line_fit_error[p];
    line_fit_total += line_fit_error[p];
    baseline_total += baseline_error[p];
    coverage_total += coverage_error[p];
    rsaa_total += d.rsaa_error[p], noaa_total += noaa_error[p], oracle_total += oracle_error[p];
  }
  d.rsaa_psnr = psnr_of(rsaa_total, n);
  d.noaa_psnr = psnr_of(noaa_total, n);
  d.oracle_psnr = psnr_of(oracle_total, n);
  d.coverage_psnr = psnr_of(coverage_total, n);
  d.line_fit_psnr = psnr_of(line_fit_total, n);
  d.has_baseline = has_baseline;
  d.baseline_psnr = psnr_of(baseline_total, n);
  return d;
}

namespace {

// A PSNR as text: an image without error (infinite PSNR) says so rather than "inf".
std::string decibels(double psnr) {
  if (!std::isfinite(psnr)) return "no error";
  char text[32];
  std::snprintf(text, sizeof text, "%.2f dB", psnr);
  return text;
}

// A ratio to no AA's error; "-" where no AA has none to compare with.
std::string ratio_text(double error, double noaa_error) {
  if (!(noaa_error > 0.0)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", error / noaa_error);
  return text;
}

}  // namespace

std::string diagnosis_markdown(const Diagnosis& d, const std::string& title, const std::string& baseline_name) {
  double rsaa_total = 0.0, noaa_total = 0.0;
  std::size_t pixels = 0;
  for (const DiagnosisRow& r : d.rows) rsaa_total += r.rsaa_error, noaa_total += r.noaa_error, pixels += r.pixels;
  std::ostringstream out;
  out << title << ": RSAA " << decibels(d.rsaa_psnr) << ", no AA " << decibels(d.noaa_psnr)
      << ", best single fetch (oracle) " << decibels(d.oracle_psnr) << ", exact coverage of the 1x colours "
      << decibels(d.coverage_psnr) << ", the line fitted across the 3x3 masks " << decibels(d.line_fit_psnr);
  if (d.has_baseline) out << ", " << baseline_name << " " << decibels(d.baseline_psnr);
  out << "\n\n| pixel class | pixels | share of RSAA error | share of no-AA error | RSAA error / no-AA | oracle / no-AA | exact coverage / no-AA | line fit / no-AA | ";
  if (d.has_baseline) out << baseline_name << " / no-AA | ";
  out << "PSNR if this class were perfect |\n| --- | --- | --- | --- | --- | --- | --- | --- | " << (d.has_baseline ? "--- | " : "")
      << "--- |\n";
  char line[512];
  for (std::size_t c = 0; c < d.rows.size(); ++c) {
    const DiagnosisRow& r = d.rows[c];
    const double rest = rsaa_total - r.rsaa_error;
    const double if_perfect = rest > 0.0 ? 10.0 * std::log10(255.0 * 255.0 * double(pixels) / rest)
                                         : std::numeric_limits<double>::infinity();
    std::snprintf(line, sizeof line, "| %s | %zu | %.1f%% | %.1f%% | ", r.name.c_str(), r.pixels,
                  rsaa_total > 0.0 ? 100.0 * r.rsaa_error / rsaa_total : 0.0,
                  noaa_total > 0.0 ? 100.0 * r.noaa_error / noaa_total : 0.0);
    out << line << ratio_text(r.rsaa_error, r.noaa_error) << " | " << ratio_text(r.oracle_error, r.noaa_error)
        << " | " << ratio_text(r.coverage_error, r.noaa_error) << " | " << ratio_text(r.line_fit_error, r.noaa_error)
        << " | ";
    if (d.has_baseline) out << ratio_text(r.baseline_error, r.noaa_error) << " | ";
    out << decibels(if_perfect) << " |\n";
  }
  return out.str();
}

std::vector<std::uint8_t> diagnosis_picture(const Diagnosis& d) {
  std::vector<std::uint8_t> rgb(std::size_t(d.width) * d.height * 3);
  const auto& colours = diagnosis_class_colours();
  for (std::size_t p = 0; p < d.rsaa_error.size(); ++p) {
    // sqrt(error) is the RMS channel error in 8-bit steps: 12 steps or more at full brightness.
    const double brightness = std::min(1.0, std::sqrt(double(d.rsaa_error[p])) / 12.0);
    const auto& c = colours[int(d.pixel_class[p])];
    for (int k = 0; k < 3; ++k) rgb[p * 3 + k] = std::uint8_t(std::lround(c[k] * brightness));
  }
  return rgb;
}

}  // namespace rsaa
