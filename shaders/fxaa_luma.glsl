// FXAA's luma, of display values (edges are judged as seen): the main pass of the fxaa technique
// writes it beside the colour (scene_shade.frag with FXAA_LUMA), so that the post-process reads
// one R16F channel, four texels a gather, instead of converting RGBA16F colour at every tap.
float fxaa_luma(vec3 linear_rgb) { return sqrt(dot(max(linear_rgb, vec3(0.0)), vec3(0.299, 0.587, 0.114))); }
