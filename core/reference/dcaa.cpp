#include "core/reference/dcaa.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace rsaa {
namespace {

bool finite_fragment(const CoverageFragment& f) {
  return std::isfinite(f.depth.at_centre) && std::isfinite(f.depth.ddx) && std::isfinite(f.depth.ddy) &&
         std::isfinite(f.colour.r) && std::isfinite(f.colour.g) && std::isfinite(f.colour.b) &&
         std::isfinite(f.albedo.r) && std::isfinite(f.albedo.g) && std::isfinite(f.albedo.b);
}

Normal3 viewer_normal_if_bad(Normal3 n) {
  if (!(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z))) return {};
  return n;
}

// Per coverage sample, the surface that covers it with the smallest depth at the sample (ties:
// the earlier surface): how many samples each one shows.
std::vector<int> front_counts(const std::vector<DcaaSurface>& surfaces, const SamplePattern& pattern) {
  std::vector<int> counts(surfaces.size(), 0);
  for (int s = 0; s < pattern.size(); ++s) {
    int front = -1;
    float front_depth = 0.0f;
    for (int i = 0; i < int(surfaces.size()); ++i) {
      if (!is_similar(surfaces[i].coverage, s)) continue;
      const float z = surfaces[i].depth.at(pattern.positions[s]);
      if (front < 0 || z < front_depth) front = i, front_depth = z;
    }
    if (front >= 0) ++counts[front];
  }
  return counts;
}

// The largest channel difference of two surfaces' colours on a square-root scale (the first
// merge's colour test, the least-change second merge's cost). Surfaces not shaded yet compare
// albedos.
float colour_difference(const DcaaSurface& a, const DcaaSurface& b) {
  const Rgb& x = a.shaded ? a.colour : a.albedo;
  const Rgb& y = b.shaded ? b.colour : b.albedo;
  const auto d = [](float u, float v) { return std::abs(std::sqrt(std::max(u, 0.0f)) - std::sqrt(std::max(v, 0.0f))); };
  return std::max({d(x.r, y.r), d(x.g, y.g), d(x.b, y.b)});
}

// The colour test of the first merge: surfaces both shaded compare colours, both unshaded their
// albedos; a shaded and an unshaded one are not compared.
bool colours_differ(const DcaaSurface& a, const DcaaSurface& b, float tolerance) {
  return tolerance > 0.0f && a.shaded == b.shaded && colour_difference(a, b) > tolerance;
}

// ka a + kb b renormalised; opposite normals average to nothing: then the heavier one's.
Normal3 weighted_normal(Normal3 a, Normal3 b, float ka, float kb, bool a_heavier) {
  const Normal3 n{ka * a.x + kb * b.x, ka * a.y + kb * b.y, ka * a.z + kb * b.z};
  const float len = std::sqrt(dot(n, n));
  return len > 1e-6f ? Normal3{n.x / len, n.y / len, n.z / len} : (a_heavier ? a : b);
}

// DcaaSettings::second_merge_least_change: which candidate goes (`removed`) and the one it is
// merged into (`into`, -1: dropped). Dropping `least_visible` (the candidate showing the fewest
// samples, `shown` from front_counts()) costs those samples; a merge must cost less.
struct LeastChange {
  int removed = -1, into = -1;
};
LeastChange least_change(const std::vector<DcaaSurface>& candidates, const std::vector<int>& shown, int least_visible) {
  const int n = int(candidates.size());
  LeastChange best{least_visible, -1};
  // Costs as fractions (numerator, denominator), compared by cross-multiplying: no division, so
  // the GL resolve, whose division need not round as the CPU's does, breaks exact ties alike.
  float best_cost = float(shown[least_visible]), best_per = 1.0f;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (!depth_intervals_overlap(candidates[i].depth, candidates[j].depth)) continue;
      const float si = float(shown[i]), sj = float(shown[j]);
      const float cost = 2.0f * si * sj * colour_difference(candidates[i], candidates[j]), per = std::max(si + sj, 1.0f);
      if (cost * best_per < best_cost * per) best = {j, i}, best_cost = cost, best_per = per;  // the later into the earlier slot
    }
  return best;
}

}  // namespace

DcaaPixel::DcaaPixel(DcaaSettings settings, const SamplePattern* coverage_pattern, DcaaSurfaceShader shade)
    : settings_(settings), pattern_(coverage_pattern), shade_(std::move(shade)) {
  if (settings.per_sample_visibility && !coverage_pattern)
    throw std::invalid_argument("DcaaPixel: per-sample visibility needs the coverage pattern");
  if (settings.second_merge_least_change && !settings.per_sample_visibility)
    throw std::invalid_argument("DcaaPixel: the least-change second merge needs per-sample visibility");
}

DcaaSettings dcaa_settings(const std::string& rules) {
  DcaaSettings s;
  if (rules == "paper") return s;
  if (rules != "surface") throw std::invalid_argument("dcaa --rules must be paper or surface, not '" + rules + "'");
  s.per_sample_visibility = true;
  s.merge_hidden = false;
  s.merge_disjoint_only = true;
  // Into the most overlapping surface only: measured +0.1 dB on the engine, +0.4 on distant boxes,
  // equal elsewhere, against into every overlapping one.
  s.second_merge_into_all = false;
  s.merge_colour_tolerance = kMergeColourToleranceDefault;
  s.second_merge_by_visible = true;
  return s;
}

DcaaSurface merge_surfaces(const DcaaSurface& a, const DcaaSurface& b) {
  return merge_surfaces(a, b, float(similar_count(a.coverage)), float(similar_count(b.coverage)));
}

DcaaSurface merge_surfaces(const DcaaSurface& a, const DcaaSurface& b, float seen_a, float seen_b) {
  const float wa = float(similar_count(a.coverage)), wb = float(similar_count(b.coverage));
  const float sum = wa + wb, seen = seen_a + seen_b;
  const float ka = sum > 0.0f ? wa / sum : 0.5f, kb = 1.0f - ka;        // geometry
  const float ca = seen > 0.0f ? seen_a / seen : 0.5f, cb = 1.0f - ca;  // what is seen
  DcaaSurface m;
  m.coverage = a.coverage | b.coverage;
  m.depth = {ka * a.depth.at_centre + kb * b.depth.at_centre, ka * a.depth.ddx + kb * b.depth.ddx,
             ka * a.depth.ddy + kb * b.depth.ddy};
  m.normal = weighted_normal(a.normal, b.normal, ka, kb, wa >= wb);
  m.shading_normal = weighted_normal(a.shading_normal, b.shading_normal, ca, cb, seen_a >= seen_b);
  m.colour = {ca * a.colour.r + cb * b.colour.r, ca * a.colour.g + cb * b.colour.g, ca * a.colour.b + cb * b.colour.b};
  m.albedo = {ca * a.albedo.r + cb * b.albedo.r, ca * a.albedo.g + cb * b.albedo.g, ca * a.albedo.b + cb * b.albedo.b};
  m.shaded = a.shaded && b.shaded;
  return m;
}

DcaaSurface DcaaPixel::shaded(const DcaaSurface& s) {
  if (s.shaded) return s;
  DcaaSurface out = s;
  out.colour = shade_(s);
  out.shaded = true;
  ++merge_shadings_;
  return out;
}

DcaaEvent DcaaPixel::insert(const CoverageFragment& f) {
  if (f.coverage == 0 || !finite_fragment(f)) return DcaaEvent::Ignored;
  const DcaaSurface in{f.coverage, f.depth, viewer_normal_if_bad(f.normal), f.colour, f.albedo,
                       viewer_normal_if_bad(f.shading_normal), !shade_};

  int best = -1;
  float best_dot = 0.0f, best_overlap = 0.0f;
  for (int i = 0; i < int(surfaces_.size()); ++i) {
    const float d = dot(surfaces_[i].normal, in.normal);
    if (!(d > settings_.cos_normal_threshold) || !depth_intervals_overlap(surfaces_[i].depth, in.depth)) continue;
    if (settings_.merge_disjoint_only && (surfaces_[i].coverage & in.coverage)) continue;
    if (colours_differ(surfaces_[i], in, settings_.merge_colour_tolerance)) continue;
    const float overlap = depth_overlap_amount(surfaces_[i].depth, in.depth);
    if (best < 0 || d > best_dot || (d == best_dot && overlap > best_overlap)) best = i, best_dot = d, best_overlap = overlap;
  }
  if (best >= 0) {
    // Shading surfaces, a merge whose shading normals differ beyond the cone (a bevel's normals
    // extrapolated to the pixel centre) or into a surface already shaded shades both first.
    const bool bake = shade_ && (surfaces_[best].shaded ||
                                 !(dot(surfaces_[best].shading_normal, in.shading_normal) > settings_.cos_normal_threshold));
    if (bake) surfaces_[best] = shaded(surfaces_[best]);
    surfaces_[best] = merge_surfaces(surfaces_[best], bake ? shaded(in) : in);
    return DcaaEvent::Merged;
  }
  if (int(surfaces_.size()) < settings_.max_surfaces) {
    surfaces_.push_back(in);
    return DcaaEvent::Stored;
  }

  // Second merge attempt over the surfaces and the fragment (the last candidate).
  std::vector<DcaaSurface> candidates = surfaces_;
  candidates.push_back(in);
  const int n = int(candidates.size());
  std::vector<int> front_to_back(n);
  for (int i = 0; i < n; ++i) front_to_back[i] = i;
  std::stable_sort(front_to_back.begin(), front_to_back.end(), [&](int a, int b) {
    return candidates[a].depth.at_centre < candidates[b].depth.at_centre;
  });
  int smallest = -1, smallest_visible = 0;
  std::vector<int> counts;
  if (settings_.per_sample_visibility) {
    counts = front_counts(candidates, *pattern_);
    for (int k = n - 1; k >= 0; --k) {  // back to front: ties go to the farther
      const int i = front_to_back[k];
      if (smallest < 0 || counts[i] < smallest_visible) smallest = i, smallest_visible = counts[i];
    }
  } else {  // the coarse depth resolve, the front-most excluded
    Mask closer = 0;
    for (int k = 0; k < n; ++k) {
      const int i = front_to_back[k];
      const int visible = similar_count(candidates[i].coverage & ~closer);
      closer |= candidates[i].coverage;
      if (k > 0 && (smallest < 0 || visible <= smallest_visible)) smallest = i, smallest_visible = visible;
    }
  }
  const auto keep_all_but = [&](int removed) {
    surfaces_.clear();
    for (int i = 0; i < n; ++i)
      if (i != removed) surfaces_.push_back(candidates[i]);
  };
  if (settings_.second_merge_least_change) {
    const LeastChange change = least_change(candidates, counts, smallest);
    const int into = change.into, from = change.removed;
    if (into >= 0)
      candidates[into] = merge_surfaces(shaded(candidates[into]), shaded(candidates[from]), float(counts[into]), float(counts[from]));
    keep_all_but(from);
    return into >= 0 ? DcaaEvent::SecondMerge : DcaaEvent::Discarded;
  }
  int target = -1;
  float target_overlap = 0.0f;
  for (int i = 0; i < n && (settings_.merge_hidden || smallest_visible > 0); ++i) {
    if (i == smallest || !depth_intervals_overlap(candidates[i].depth, candidates[smallest].depth)) continue;
    const float overlap = depth_overlap_amount(candidates[i].depth, candidates[smallest].depth);
    if (settings_.second_merge_into_all) {
      candidates[smallest] = shaded(candidates[smallest]);
      candidates[i] = merge_surfaces(shaded(candidates[i]), candidates[smallest]), target = i;
    } else if (target < 0 || overlap > target_overlap) {
      target = i, target_overlap = overlap;
    }
  }
  if (target >= 0 && !settings_.second_merge_into_all) {
    const DcaaSurface into = shaded(candidates[target]), from = shaded(candidates[smallest]);
    candidates[target] = settings_.second_merge_by_visible && !counts.empty()
                             ? merge_surfaces(into, from, float(counts[target]), float(counts[smallest]))
                             : merge_surfaces(into, from);
  }
  keep_all_but(smallest);
  return target >= 0 ? DcaaEvent::SecondMerge : DcaaEvent::Discarded;
}

std::vector<int> DcaaPixel::visible_counts(const SamplePattern& pattern) const {
  return front_counts(surfaces_, pattern);
}

int DcaaPixel::shading_invocations(const SamplePattern& pattern) const {
  if (!shade_) return 0;
  const std::vector<int> counts = visible_counts(pattern);
  int n = merge_shadings_;
  for (std::size_t i = 0; i < surfaces_.size(); ++i) n += counts[i] > 0 && !surfaces_[i].shaded;
  return n;
}

Rgb DcaaPixel::resolve(const SamplePattern& pattern, Rgb background) const {
  const std::vector<int> counts = visible_counts(pattern);
  const float n = float(pattern.size());
  int covered = 0;
  Rgb c;
  for (std::size_t i = 0; i < surfaces_.size(); ++i) {
    if (counts[i] == 0) continue;  // hidden: not shaded
    const float w = float(counts[i]) / n;
    const Rgb colour = surfaces_[i].shaded ? surfaces_[i].colour : shade_(surfaces_[i]);
    c.r += w * colour.r, c.g += w * colour.g, c.b += w * colour.b;
    covered += counts[i];
  }
  const float rest = float(pattern.size() - covered) / n;
  return {c.r + rest * background.r, c.g + rest * background.g, c.b + rest * background.b};
}

}  // namespace rsaa
