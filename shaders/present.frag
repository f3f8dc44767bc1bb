// Shows a linear RGBA16F image in a window: sRGB-encodes it (the same transfer as PNG output).
uniform sampler2D u_image;
layout(location = 0) out vec4 o_colour;

float encode(float v) {
  v = clamp(v, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

void main() {
  vec3 c = texelFetch(u_image, ivec2(gl_FragCoord.xy), 0).rgb;
  if (!all(equal(c, c))) c = vec3(0.0);  // never show NaN
  o_colour = vec4(encode(c.r), encode(c.g), encode(c.b), 1.0);
}
