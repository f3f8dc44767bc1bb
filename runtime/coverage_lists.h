// The per-pixel fragment lists shared by the coverage-based techniques (DCAA, dynamic coverage).
// The papers merge fragments in a critical section ordered by fragment-shader interlock; llvmpipe
// has none, so a geometry pass appends every fragment (shaded once, with its coverage mask from
// the half-plane LUT, its depth plane and facet normal) to a linked list per pixel with atomics,
// and the technique's resolve pass replays each list sorted by primitive order. Same result as
// the interlocked design; the cost is memory proportional to the fragment count (32-40 B per
// fragment + 4 B per pixel, instead of the technique's fixed per-pixel state), and no early
// merge: every fragment is stored, then sorted.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/reference/coverage_fragment.h"
#include "core/reference/halfplane_lut.h"
#include "runtime/gl_objects.h"
#include "runtime/gpu_scene.h"
#include "runtime/scene_renderer.h"
#include "runtime/technique.h"

namespace rsaa {

class CoverageFragmentLists {
 public:
  static constexpr int kInitialRecordsPerPixel = 2;

  // `coverage_pattern`: the coverage samples of the technique (64 for DCAA, 16 for dynamic
  // coverage), whose half-plane LUT the geometry pass uses. `shading_inputs`: records carry the
  // albedo and shading normal instead of a shaded colour (dcaa --shade surface).
  CoverageFragmentLists(const SamplePattern& coverage_pattern, int width, int height, bool shading_inputs = false);
  bool shading_inputs() const { return shading_inputs_; }
  // coverage_record.glsl's layout for these lists: its #defines and the bytes of a record
  // (36 for 64 samples, 32 for at most 32, 4 more with shading inputs).
  std::string record_defines() const;
  int record_bytes() const { return 4 * record_uints_; }

  // From now on build() stores only fragments not behind the farthest of the pixel's 4 hardware
  // MSAA depths, which z_prepass() draws (DCAA's section 4.2 with 4 samples; llvmpipe has no 8).
  void enable_z_prepass();
  bool z_prepass_enabled() const { return bool(max_depth_.get()); }
  void z_prepass(const GpuScene& scene, const View& view);

  // Draws the scene into the lists; grows the record buffer and draws again when it overflowed
  // (shrinks it first when the last frame used less than half). Returns the fragments stored.
  std::size_t build(const GpuScene& scene, const View& view);

  // Binds the head image (unit 0, read-only) and the record buffers for a resolve program.
  void bind_for_resolve(GLuint program) const;

  // Every pixel's fragments, in primitive order (row-major, row 0 = top): for the tests' CPU
  // oracle.
  std::vector<std::vector<CoverageFragment>> read_back() const;

  const HalfPlaneLut& lut() const { return lut_; }
  // Bytes per pixel of the buffers as allocated (heads + record capacity + the z-prepass's).
  double bytes_per_pixel() const;
  std::size_t fragments() const { return fragments_; }
  glm::ivec2 size() const { return {width_, height_}; }

 private:
  void allocate_records(std::size_t capacity);

  int width_, height_;
  bool shading_inputs_;
  bool narrow_;  // at most 32 coverage samples: one coverage word
  int record_uints_;
  HalfPlaneLut lut_;
  gl::Program program_;
  gl::Texture lut_texture_, heads_;
  gl::Buffer counter_, records_;
  gl::Framebuffer empty_target_;
  std::size_t capacity_ = 0, fragments_ = 0;
  bool built_ = false;
  // z-prepass (enable_z_prepass)
  gl::Texture prepass_depth_, max_depth_;
  gl::Framebuffer prepass_target_, max_depth_target_;
  gl::Program max_depth_program_;
  std::optional<SceneRenderer> depth_renderer_;
};

// A coverage technique: the lists, then `resolve_define`'s variant of coverage_resolve.frag
// drawn fullscreen with the scene's background as the clear colour. dcaa and dyncov are this
// with their coverage pattern and per-pixel update. A list longer than the resolve sorts
// locally (32 records) becomes a pending entry (kPendingUints uints: the technique's state and
// how far its replay got; an R32UI image maps pixels to entries), resumed by fullscreen
// continuation passes until every entry is done: each pass does bounded work (llvmpipe silently ends a shader invocation's
// loops after 65535 iterations), so any list is replayed whole and in order.
class CoverageListTechnique : public Technique {
 public:
  // shade_surfaces: the lists carry shading inputs and the resolve shades each surface once
  // (DCAA_SHADE_SURFACES; only with COVERAGE_DCAA).
  CoverageListTechnique(const SamplePattern& coverage_pattern, const std::string& resolve_define, int width,
                        int height, bool z_prepass = false, bool shade_surfaces = false);
  void render(const GpuScene& scene, const View& view, GLuint output) override;
  double bytes_per_pixel() const override;
  CoverageFragmentLists* coverage_lists() { return &lists_; }
  // Both resolve programs (the first pass, the continuation) take the technique's uniforms.
  std::vector<GLuint> resolve_programs() const { return {resolve_.get(), continue_.get()}; }
  // Entries the last render left pending (lists longer than the local sort) and its
  // continuation passes.
  std::size_t pending_pixels() const { return pending_; }
  int continuation_passes() const { return continuation_passes_; }

  static constexpr int kPendingUints = 96;  // coverage_resolve.frag's PENDING_UINTS

 protected:
  void allocate_pending(std::size_t capacity);

  CoverageFragmentLists lists_;
  gl::Program resolve_, continue_;
  gl::CachedFramebuffer output_target_;
  gl::Texture pending_index_;
  gl::Buffer pending_counter_, pending_entries_;
  std::size_t pending_capacity_ = 0, pending_ = 0;
  int continuation_passes_ = 0;
};

}  // namespace rsaa
