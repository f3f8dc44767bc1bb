// Filtered SSAA downsampling (seed 003): the 2x2-supersampled frame brought to the output size
// with bilinear taps. Tap offsets come from core/reference/filtered_downsample.h as uniforms (converted to
// window space there), so the CPU reference and this shader share one definition.
uniform sampler2D u_supersampled;  // 2W x 2H, GL_LINEAR, clamp to edge; alpha = filter alpha
uniform vec2 u_supersampled_size;
uniform int u_kernel;              // 1, 2 or 3
uniform vec2 u_small_taps[5];
uniform vec2 u_large_taps[5];
layout(location = 0) out vec4 o_colour;

vec4 average_of_taps(vec2 centre, vec2 taps[5]) {
  vec4 sum = vec4(0.0);
  for (int i = 0; i < 5; ++i) sum += texture(u_supersampled, (centre + taps[i]) / u_supersampled_size);
  return sum / 5.0;
}

void main() {
  // The output pixel's centre lies on the corner shared by its four supersampled texels.
  vec2 centre = 2.0 * gl_FragCoord.xy;
  if (u_kernel == 1) {
    o_colour = texture(u_supersampled, centre / u_supersampled_size);
    return;
  }
  vec4 small = average_of_taps(centre, u_small_taps);
  if (u_kernel == 2) {
    o_colour = small;
    return;
  }
  vec4 large = average_of_taps(centre, u_large_taps);
  o_colour = vec4(mix(large.rgb, small.rgb, clamp(small.a, 0.0, 1.0)), 1.0);
}
