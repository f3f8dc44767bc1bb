// The one uniform block of the RSAA pass, read by the pre-pass and the post-process. RsaaPass
// fills it (runtime/rsaa_pass.cpp, struct RsaaUniformHead and the per-subsample entries, the
// same std140 layout) and binds it
// at RSAA_UNIFORM_BINDING before it calls the engine's draw or runs the post-process; an engine
// using these shaders without the runtime fills it itself.
//
// Defines expected before inclusion: RSAA_SAMPLE_COUNT; optional RSAA_UNIFORM_BINDING (13).
#ifndef RSAA_UNIFORMS_GLSL
#define RSAA_UNIFORMS_GLSL

#ifndef RSAA_UNIFORM_BINDING
#define RSAA_UNIFORM_BINDING 13
#endif

layout(std140, binding = RSAA_UNIFORM_BINDING) uniform RsaaUniforms {
  mat4 rsaa_inverse_projection;  // of the unjittered camera: window position + depth -> view space
  vec2 rsaa_viewport;            // the frame's width and height in pixels
  vec2 rsaa_jitter_ndc;          // jittered pre-pass: the image translation of this draw (NDC)
  float rsaa_threshold;          // similarity above which a subsample is dissimilar
  // Jittered pre-pass: the subsample drawn; multisample pre-pass: the subsample of this draw's
  // sample 0 (m for the second draw of a union pattern); -1 in the post-process.
  int rsaa_subsample;
  // Multisample pre-pass: the offset from a sample's raster position to the point it sees, window
  // space (the second draw of a union pattern is shifted); 0 otherwise.
  vec2 rsaa_sample_shift;
  // .xy: the step from a pixel to the outside pixel nearest subsample i, window space (+y up):
  // the subsample's pixel-space position (+y down) divided by its larger absolute coordinate,
  // each coordinate rounded half away from zero, then y negated (core's outside_pixel_towards;
  // (1, 0) for a subsample at the centre);
  // .zw, union pattern, shifted subsamples: the raster pixel whose sample saw subsample i of a
  // pixel, relative to that pixel (window space); cell pattern: the cell (raster pixel) whose
  // sample saw subsample i, relative to the pixel's lower-left cell (window space).
  ivec4 rsaa_neighbours[RSAA_SAMPLE_COUNT];
};

#endif  // RSAA_UNIFORMS_GLSL
