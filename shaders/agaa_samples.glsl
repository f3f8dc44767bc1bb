// AGAA's visibility samples: per sample depth, compressed facet normal and primitive id (+1,
// 0 = background), from a hardware multisampled pre-pass (AGAA_MULTISAMPLE, n = 4) or from n
// jittered single-sample passes stored as array layers (n = 8 or 16).
#ifndef RSAA_AGAA_SAMPLES_GLSL
#define RSAA_AGAA_SAMPLES_GLSL

uniform int u_samples;
#ifdef AGAA_MULTISAMPLE
uniform sampler2DMS u_sample_depth;
uniform usampler2DMS u_sample_normal;
uniform usampler2DMS u_sample_primitive;
float agaa_sample_depth(ivec2 p, int s) { return texelFetch(u_sample_depth, p, s).x; }
uvec2 agaa_sample_normal(ivec2 p, int s) { return texelFetch(u_sample_normal, p, s).xy; }
uint agaa_sample_primitive(ivec2 p, int s) { return texelFetch(u_sample_primitive, p, s).x; }
#else
uniform sampler2DArray u_sample_depth;
uniform usampler2DArray u_sample_normal;
uniform usampler2DArray u_sample_primitive;
float agaa_sample_depth(ivec2 p, int s) { return texelFetch(u_sample_depth, ivec3(p, s), 0).x; }
uvec2 agaa_sample_normal(ivec2 p, int s) { return texelFetch(u_sample_normal, ivec3(p, s), 0).xy; }
uint agaa_sample_primitive(ivec2 p, int s) { return texelFetch(u_sample_primitive, ivec3(p, s), 0).x; }
#endif

const int AGAA_MAX_SAMPLES = 16;

// Aggregate metadata, one RG32UI per pixel (16 samples of 2 bits need a word of their own):
// x: bits 2s and 2s + 1 = the aggregate (0..3) of sample s; y: bit s = sample s sees a surface,
// bits 24-26 = the number of aggregates.
uint agaa_aggregate_of(uvec2 meta, int s) { return (meta.x >> uint(2 * s)) & 3u; }

#endif  // RSAA_AGAA_SAMPLES_GLSL
