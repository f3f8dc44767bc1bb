// Adds a batch of jittered passes (layers of an array texture), weighted, into an accumulation
// target (additive blending). Batching keeps program switches between scene passes rare, which
// llvmpipe makes expensive on heavy scenes.
uniform sampler2DArray u_passes;
uniform int u_count;
uniform float u_weight;
layout(location = 0) out vec4 o_colour;
void main() {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < u_count; ++i) sum += texelFetch(u_passes, ivec3(gl_FragCoord.xy, i), 0).rgb;
  o_colour = vec4(u_weight * sum, u_weight * float(u_count));
}
