// rsaa diagnose: the pixel classes and the oracle on hand-made inputs, the surface grouping on
// built-in geometry, and the command on a tiny image.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "runtime/scene.h"
#include "tests/test_util.h"
#include "tools/bench/diagnosis.h"

namespace rsaa {
namespace {

TEST(Diagnosis, SmoothSurfacesGroupATessellatedSphereAndSplitABox) {
  const Scene scene = load_scene("builtin:grazing");
  const std::vector<std::uint32_t> ids = smooth_surface_ids(scene);
  ASSERT_EQ(ids.size(), scene.triangle_count());
  // The floor quad (2 triangles) is one surface; the red sphere (the next 24 x 48 x 2 - 96
  // triangles) is one surface; the blue box after the three spheres has six.
  EXPECT_EQ(ids[0], ids[1]);
  const std::size_t sphere_begin = 2, sphere_end = sphere_begin + 24 * 48 * 2 - 2 * 48;
  for (std::size_t t = sphere_begin; t < sphere_end; ++t) ASSERT_EQ(ids[t], ids[sphere_begin]) << t;
  EXPECT_NE(ids[sphere_begin], ids[0]);
}

// A 3x3 image: a vertical edge between a white left column and black rest. The centre pixel sees
// both surfaces; RSAA resampled it with a one-line offset.
TEST(Diagnosis, ClassesOracleAndTable) {
  const SamplePattern pattern = builtin_pattern("d3d8x");
  OffsetTable table = fallback_table(pattern);
  DiagnosisInputs in;
  in.noaa = Image(3, 3);
  in.reference = Image(3, 3);
  for (int y = 0; y < 3; ++y) {
    in.noaa.at(0, y) = {1, 1, 1};
    in.reference.at(0, y) = {1, 1, 1};
    in.reference.at(1, y) = {0.25f, 0.25f, 0.25f};  // a quarter of the centre column is white
  }
  in.rsaa = in.noaa;
  in.masks.assign(9, full_mask(8));
  const Mask edge_mask = full_mask(8) & ~Mask{0x01};
  in.masks[4] = edge_mask;
  table.sources[edge_mask] = OffsetSource::OneLine;
  in.table = &table;
  in.surfaces.resize(9);
  in.centre_surface.assign(9, 2);
  in.subsample_sees_other.assign(9, 0);
  for (int y = 0; y < 3; ++y) {
    in.centre_surface[y * 3] = 1;
    in.surfaces[y * 3] = {{1}, 1};
    in.surfaces[y * 3 + 1] = {{2, 1}, 2};
    in.surfaces[y * 3 + 2] = {{2}, 1};
  }
  in.subsample_sees_other[1] = 1;  // top middle: seen by a subsample, yet left alone
  const Diagnosis d = diagnose(in);
  EXPECT_EQ(d.pixel_class[4], DiagnosisClass::TwoSurfacesOneLine);
  EXPECT_EQ(d.pixel_class[1], DiagnosisClass::Missed);
  EXPECT_EQ(d.pixel_class[7], DiagnosisClass::Unsampled);
  EXPECT_EQ(d.pixel_class[0], DiagnosisClass::OneSurfaceUntouched);
  EXPECT_EQ(d.rows[int(DiagnosisClass::OneSurfaceUntouched)].pixels, 6u);
  // The oracle fetches a quarter of white: within a few 8-bit steps of the reference.
  EXPECT_LT(d.rows[int(DiagnosisClass::TwoSurfacesOneLine)].oracle_error, 4.0);
  EXPECT_GT(d.rows[int(DiagnosisClass::TwoSurfacesOneLine)].noaa_error, 1000.0);
  EXPECT_GT(d.oracle_psnr, d.noaa_psnr + 20.0);
  // Without sample counts the exact-coverage blend knows nothing: the 1x colour.
  EXPECT_EQ(coverage_resolve(in, 1, 1).r, 0.0f);
  const std::string md = diagnosis_markdown(d, "test");
  EXPECT_NE(md.find("2 surfaces, one-line offset | 1 |"), std::string::npos) << md;
  EXPECT_NE(md.find("exact coverage / no-AA | line fit / no-AA"), std::string::npos) << md;
  // With them: 16 of 64 samples white (the left neighbour's colour), 48 black (the centre's).
  for (int y = 0; y < 3; ++y) in.surfaces[y * 3 + 1].samples = {48, 16}, in.surfaces[y * 3 + 1].total = 64;
  EXPECT_FLOAT_EQ(coverage_resolve(in, 1, 1).r, 0.25f);
  // A surface no neighbour centre shows takes the pixel's own colour.
  in.surfaces[4].ids = {2, 7};
  EXPECT_FLOAT_EQ(coverage_resolve(in, 1, 1).g, 0.0f);
  in.surfaces[4].ids = {2, 1};
  const Diagnosis exact = diagnose(in);
  EXPECT_LT(exact.rows[int(DiagnosisClass::TwoSurfacesOneLine)].coverage_error, 1.0);
  EXPECT_GT(exact.coverage_psnr, exact.noaa_psnr + 20.0);
  in.masks[4] = Mask{1} << 9;  // does not fit 8 samples
  EXPECT_THROW(diagnose(in), std::invalid_argument);
}

// A straight vertical edge at x = -0.25 of the centre column (pixel space): white (surface 1) to
// its left, black (2) to its right, so a quarter of each centre-column pixel is white. Every
// mask says so (the subsamples left of the line are dissimilar in the centre column, none
// elsewhere); the fitted line puts the edge there and the fetch takes a quarter of the white
// neighbour, at the image border too (neighbours outside the image are skipped).
TEST(Diagnosis, TheLineFittedAcrossNeighbouringMasksFindsAStraightEdge) {
  const SamplePattern pattern = builtin_pattern("d3d8x");
  const OffsetTable table = fallback_table(pattern);
  DiagnosisInputs in;
  in.noaa = Image(3, 3);
  in.reference = Image(3, 3);
  in.masks.assign(9, full_mask(8));
  in.centre_surface.assign(9, 2);
  Mask edge_mask = full_mask(8);
  for (int k = 0; k < pattern.size(); ++k)
    if (pattern.positions[k].x < -0.25) edge_mask &= ~(Mask{1} << k);
  ASSERT_NE(edge_mask, full_mask(8));
  for (int y = 0; y < 3; ++y) {
    in.noaa.at(0, y) = in.reference.at(0, y) = {1, 1, 1};
    in.reference.at(1, y) = {0.25f, 0.25f, 0.25f};
    in.centre_surface[y * 3] = 1;
    in.masks[y * 3 + 1] = edge_mask;
  }
  in.rsaa = in.noaa;
  in.table = &table;
  for (int y = 0; y < 3; ++y) EXPECT_NEAR(line_fit_resolve(in, 1, y).r, 0.25f, 0.02f) << y;
  // A pixel no subsample of which is labelled another surface keeps RSAA's colour.
  in.rsaa.at(2, 1) = {0.5f, 0.5f, 0.5f};
  EXPECT_EQ(line_fit_resolve(in, 2, 1).r, 0.5f);
}

TEST(Diagnosis, CommandWritesTheTableAndPictures) {
  using test::TempDir;
  using test::run_rsaa;
  TempDir dir;
  const auto r = run_rsaa("diagnose --scene builtin:edges --width 64 --height 48 --surface-samples 2 --out-dir " +
                          dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("best single fetch (oracle)"), std::string::npos) << r.output;
  for (const char* f : {"diagnosis.md", "error_map.png", "oracle.png", "coverage.png", "rsaa.png", "noaa.png", "reference.png"})
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(dir.path()) / f)) << f;
  const auto bad = run_rsaa("diagnose --technique msaa --out-dir " + dir.path());
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("rsaa"), std::string::npos) << bad.output;
}

// The table and its pictures are one set: a run whose files cannot all be put in place (here a
// directory stands where one picture goes; a full disk alike) leaves the previous run's files as
// they were, never new pictures beside an old table.
TEST(Diagnosis, ARunThatCannotWriteItsSetLeavesThePreviousOne) {
  using test::TempDir;
  using test::run_rsaa;
  TempDir dir;
  std::filesystem::create_directories(dir.file("oracle.png"));
  for (const char* f : {"diagnosis.md", "error_map.png"}) test::write_text(dir.file(f), "previous");
  const auto r = run_rsaa("diagnose --scene builtin:edges --width 64 --height 48 --surface-samples 2 --out-dir " +
                          dir.path());
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("oracle.png"), std::string::npos) << "the error names the file: " << r.output;
  for (const char* f : {"diagnosis.md", "error_map.png"}) EXPECT_EQ(test::read_text(dir.file(f)), "previous") << f;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "diagnosis.md" || name == "error_map.png" || name == "oracle.png") << "left behind: " << name;
  }
}

}  // namespace
}  // namespace rsaa
