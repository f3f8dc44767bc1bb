// rsaa figures dcaa | agaa: the coverage family's own figures. DCAA's surface count is swept on
// the CPU reference (core/dcaa.h) replaying the fragment lists the GL geometry pass built, so
// every count sees the same fragments; the GL resolve (4 surfaces) is measured beside it as a
// check. AGAA runs on GL with each c and 4, 8 and 16 visibility samples.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "image/image_metrics.h"
#include "core/util/parallel.h"
#include "runtime/coverage_lists.h"
#include "runtime/technique_testing.h"
#include "runtime/render.h"
#include "tools/bench/figure_internal.h"

namespace rsaa::bench {

std::vector<std::size_t> dcaa_surface_histogram(const std::vector<std::vector<CoverageFragment>>& pixels,
                                                const DcaaSettings& settings, const SamplePattern& pattern,
                                                bool visible_only) {
  std::vector<std::size_t> counts(std::size_t(std::max(settings.max_surfaces, 0)) + 1, 0);
  for (const auto& fragments : pixels) {
    DcaaPixel pixel(settings, &pattern);
    for (const CoverageFragment& f : fragments) pixel.insert(f);
    std::size_t kept = pixel.surfaces().size();
    if (visible_only) {
      const std::vector<int> visible = pixel.visible_counts(pattern);
      kept = std::size_t(std::count_if(visible.begin(), visible.end(), [](int n) { return n > 0; }));
    }
    ++counts[std::min(kept, counts.size() - 1)];
  }
  return counts;
}

namespace {

constexpr int kMinSurfaces = 2, kMaxSurfaces = 8;


// The CPU reference's image of `pixels` with `settings`, as the GL resolve draws it.
DisplayImage replay_dcaa(const std::vector<std::vector<CoverageFragment>>& pixels, const DcaaSettings& settings,
                         const SamplePattern& pattern, Rgb background, int width, int height) {
  Image image(width, height);
  parallel_for(pixels.size(), 4096, 0, [&](std::uint64_t begin, std::uint64_t end) {
    for (std::uint64_t i = begin; i < end; ++i) {
      DcaaPixel pixel(settings, &pattern);
      for (const CoverageFragment& f : pixels[i]) pixel.insert(f);
      image.pixels[i] = pixel.resolve(pattern, background);
    }
  });
  return to_display(image);
}

// Pixels where two renders of the same lists differ by more than 2/255 in a channel (the tests'
// bound between the GL resolve and the CPU reference), with the length of their lists.
struct Difference {
  std::size_t pixels = 0, longest_list = 0;
  double mean_list = 0.0;
};
Difference differing_pixels(const DisplayImage& a, const DisplayImage& b,
                            const std::vector<std::vector<CoverageFragment>>& lists) {
  Difference d;
  for (std::size_t p = 0; p < lists.size(); ++p) {
    int worst = 0;
    for (std::size_t c = 3 * p; c < 3 * p + 3; ++c) worst = std::max(worst, std::abs(int(a.rgb[c]) - int(b.rgb[c])));
    if (worst <= 2) continue;
    ++d.pixels;
    d.mean_list += double(lists[p].size());
    d.longest_list = std::max(d.longest_list, lists[p].size());
  }
  if (d.pixels) d.mean_list /= double(d.pixels);
  return d;
}

}  // namespace

Figure dcaa_figure(const FigureOptions& o, const FigureProgress& progress) {
  Figure f;
  f.name = "dcaa";
  Figure::Part histogram, quality;
  histogram.stem = "dcaa-histogram";
  histogram.table.columns = {"surfaces"};
  quality.stem = "dcaa-surfaces";
  quality.table.columns = {"max_surfaces"};
  std::vector<std::vector<double>> shares, quality_columns;
  std::ostringstream checks, shading;
  for (const std::string& spec : o.scenes) {
    const std::string name = scene_short_name(spec);
    const auto frame = load_scene_frame(spec, o, progress);
    if (progress) progress("dcaa " + name + ": GL fragment lists");
    const double msaa = capped_psnr(frame->render(technique_options("msaa", 4)).image, frame->reference);
    auto dcaa = make_technique(technique_options("dcaa"), o.width, o.height);
    const DisplayImage gl_image = frame->render(*dcaa).image;
    const double gl_psnr = capped_psnr(gl_image, frame->reference);
    const CoverageFragmentLists& lists = *coverage_lists_of(*dcaa);
    const auto pixels = lists.read_back();
    const SamplePattern& pattern = lists.lut().pattern();
    const glm::vec3 bg = frame->gpu.background();
    Difference gl_differs;
    for (const char* rules : {"surface", "paper"}) {
      quality.table.columns.push_back(name + ", " + rules + " rules");
      quality_columns.emplace_back();
      for (int m = kMinSurfaces; m <= kMaxSurfaces; ++m) {
        if (progress) progress("dcaa " + name + ": " + rules + " rules, " + std::to_string(m) + " surfaces");
        DcaaSettings settings = dcaa_settings(rules);
        settings.max_surfaces = m;
        const DisplayImage image = replay_dcaa(pixels, settings, pattern, {bg.r, bg.g, bg.b}, o.width, o.height);
        quality_columns.back().push_back(capped_psnr(image, frame->reference));
        if (m == 4 && std::string(rules) == "surface") gl_differs = differing_pixels(gl_image, image, pixels);
      }
    }
    quality.table.columns.push_back(name + ", msaa 4x");
    quality_columns.emplace_back(std::size_t(kMaxSurfaces - kMinSurfaces + 1), msaa);
    // The slot count of the paper (4) replayed on the CPU must give the GL image's PSNR.
    checks << "- " << name << ": GL dcaa " << fixed(gl_psnr) << " dB, the CPU reference with 4 surfaces "
           << fixed(quality_columns[quality_columns.size() - 3][4 - kMinSurfaces]) << " dB; msaa 4x " << fixed(msaa)
           << " dB; " << lists.fragments() << " fragments (" << fixed(double(lists.fragments()) / double(pixels.size()))
           << " a pixel); " << gl_differs.pixels << " pixels where GL and CPU differ by more than 2/255 (their lists: "
           << fixed(gl_differs.mean_list) << " fragments on average, the longest " << gl_differs.longest_list << ")\n";

    // Shading invocations: one per stored fragment shading fragments; shading surfaces, one per
    // surface that shows a sample plus those a merge that shades both surfaces first makes (the
    // CPU reference counts them on the lists of a dcaa --shade surface frame).
    {
      if (progress) progress("dcaa " + name + ": shading surfaces once");
      TechniqueOptions per_surface = technique_options("dcaa");
      per_surface.shade = "surface";
      auto shaded = make_technique(per_surface, o.width, o.height);
      const double shaded_psnr = capped_psnr(frame->render(*shaded).image, frame->reference);
      const CoverageFragmentLists& shaded_lists = *coverage_lists_of(*shaded);
      const auto shaded_pixels = shaded_lists.read_back();
      std::size_t invocations = 0;
      for (std::size_t p = 0; p < shaded_pixels.size(); ++p) {
        DcaaPixel pixel(dcaa_settings("surface"), &pattern,
                        dcaa_surface_shader(frame->view, frame->scene.point_lights, int(p % std::size_t(o.width)),
                                            int(p / std::size_t(o.width))));
        for (const CoverageFragment& fr : shaded_pixels[p]) pixel.insert(fr);
        invocations += std::size_t(pixel.shading_invocations(pattern));
      }
      const double n = double(shaded_pixels.size());
      shading << "| " << name << " | " << fixed(double(lists.fragments()) / n) << " | " << fixed(gl_psnr) << " | "
              << fixed(double(invocations) / n) << " | " << fixed(shaded_psnr) << " |\n";
    }

    DcaaSettings wide = dcaa_settings("surface");
    wide.max_surfaces = kMaxSurfaces;
    // Stored: what the slots hold (hidden layers too, without the z-prepass); visible: the
    // surfaces that keep a coverage sample after the depth resolve.
    for (bool visible_only : {false, true}) {
      const auto counts = dcaa_surface_histogram(pixels, wide, pattern, visible_only);
      histogram.table.columns.push_back(name + (visible_only ? ", visible" : ", stored"));
      shares.emplace_back();
      for (std::size_t c : counts) shares.back().push_back(100.0 * double(c) / double(pixels.size()));
    }
  }
  for (int k = 0; k <= kMaxSurfaces; ++k) {
    std::vector<double> row = {double(k)};
    for (const auto& s : shares) row.push_back(s[k]);
    histogram.table.add(row, k == kMaxSurfaces ? std::to_string(k) + " (full)" : std::to_string(k));
  }
  for (int m = kMinSurfaces; m <= kMaxSurfaces; ++m) {
    std::vector<double> row = {double(m)};
    for (const auto& q : quality_columns) row.push_back(q[m - kMinSurfaces]);
    quality.table.add(row);
  }
  histogram.bars = true;
  histogram.style = {"DCAA: surfaces kept per pixel (surface rules, 8 slots)", "surfaces in the pixel", "% of pixels", false, {}};
  quality.style = {"DCAA: PSNR vs 64x SSAA against the number of surfaces per pixel", "surfaces per pixel (slots)",
                   "PSNR dB", false, {"msaa"}};

  std::ostringstream md;
  md << "Surfaces DCAA keeps per pixel (surface rules with 8 slots, no z-prepass; 0 = no fragment, the "
        "background), stored in the slots and visible after the depth resolve, % of pixels, "
     << o.width << "x" << o.height << ":\n\n";
  markdown_table_head(md, "surfaces", {histogram.table.columns.begin() + 1, histogram.table.columns.end()});
  for (std::size_t r = 0; r < histogram.table.rows.size(); ++r) {
    md << "| " << histogram.table.row_labels[r] << " |";
    for (std::size_t c = 1; c < histogram.table.columns.size(); ++c) md << " " << fixed(histogram.table.rows[r][c], 3) << " |";
    md << "\n";
  }
  md << "\nPSNR (dB) against 64x SSAA by the number of surfaces a pixel may keep (the CPU reference replaying the "
        "GL fragment lists):\n\n";
  markdown_table_head(md, "slots", {quality.table.columns.begin() + 1, quality.table.columns.end()});
  for (const auto& row : quality.table.rows) {
    md << "| " << int(row[0]) << " |";
    for (std::size_t c = 1; c < row.size(); ++c) md << " " << fixed(row[c]) << " |";
    md << "\n";
  }
  md << "\nShading invocations per pixel and PSNR (dB) against 64x SSAA, surface rules, 4 slots: `dcaa --shade "
        "fragment` shades every stored fragment, `--shade surface` each surface that shows a coverage sample once "
        "(and both surfaces of a merge that shades them first: a second merge, or shading normals beyond the cone):\n\n| scene | shading fragments: invocations | PSNR | shading surfaces: "
        "invocations | PSNR |\n| --- | --- | --- | --- | --- |\n"
     << shading.str();
  md << "\nChecks:\n\n" << checks.str();
  f.markdown = md.str();
  f.parts = {histogram, quality};
  return f;
}

Figure agaa_figure(const FigureOptions& o, const FigureProgress& progress) {
  Figure f;
  f.name = "agaa";
  Figure::Part part;
  part.stem = "agaa";
  part.table.columns = {"aggregates"};
  std::vector<std::vector<double>> columns;
  for (const std::string& spec : o.scenes) {
    const std::string name = scene_short_name(spec);
    const auto frame = load_scene_frame(spec, o, progress);
    for (int samples : {4, 8, 16}) {
      part.table.columns.push_back(name + ", agaa " + std::to_string(samples) + "x");
      columns.emplace_back();
      for (int c = 1; c <= 4; ++c) {
        TechniqueOptions t = technique_options("agaa", samples);
        t.agaa_aggregates = c;
        if (progress) progress("agaa " + name + ": " + technique_label(t));
        columns.back().push_back(capped_psnr(frame->render(t).image, frame->reference));
      }
    }
    if (progress) progress("agaa " + name + ": msaa 4x");
    part.table.columns.push_back(name + ", msaa 4x");
    columns.emplace_back(4, capped_psnr(frame->render(technique_options("msaa", 4)).image, frame->reference));
  }
  for (int c = 1; c <= 4; ++c) {
    std::vector<double> row = {double(c)};
    for (const auto& column : columns) row.push_back(column[c - 1]);
    part.table.add(row);
  }
  part.style = {"AGAA: PSNR vs 64x SSAA against the aggregates per pixel (c)", "aggregates c", "PSNR dB", false,
                {"msaa"}};
  std::ostringstream md;
  md << "PSNR (dB) against 64x SSAA by the number of aggregates c, with 4 (hardware MSAA), 8 and 16 "
        "(jittered) visibility samples, "
     << o.width << "x" << o.height << ":\n\n";
  markdown_table_head(md, "c", {part.table.columns.begin() + 1, part.table.columns.end()});
  for (const auto& row : part.table.rows) {
    md << "| " << int(row[0]) << " |";
    for (std::size_t c = 1; c < row.size(); ++c) md << " " << fixed(row[c]) << " |";
    md << "\n";
  }
  f.parts = {part};
  f.markdown = md.str();
  return f;
}

}  // namespace rsaa::bench
