// Adds one jittered pass, weighted, into an accumulation target (additive blending).
uniform sampler2D u_pass;
uniform float u_weight;
layout(location = 0) out vec4 o_colour;
void main() { o_colour = vec4(u_weight * texelFetch(u_pass, ivec2(gl_FragCoord.xy), 0).rgb, u_weight); }
