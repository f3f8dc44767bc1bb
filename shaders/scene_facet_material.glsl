// The material a triangle writes into RSAA's centre primitive target and passes to the pre-pass
// (material edges): the draw's, or with SCENE_FACET_MATERIALS (RsaaSettings::facet_materials,
// ours) for a facet, one made from its facet colour. A flat-shaded mesh (a faceted sphere, a
// low-poly rod, an STL part) draws a colour edge at every crease of its shading, but two facets
// meeting at a gentle angle are one surface to the geometric similarity (SADP calls creases below
// about 24 degrees similar: it has to, or every tessellated curved surface would be all edges).
// The facets are found once per scene from the shading normals on both sides of each edge
// (runtime/smoothing_groups.h): a triangle's facet value is 0 where its smooth group is neither
// parted from another by a crease nor flat (it keeps the draw's material: smooth meshes, and flat
// faces continued by smooth bevels, add no edge), else 0x80 | colour (1..127, differing from
// every facet met across a crease; a flat facet's from its normal where it can: a floor).
// The material: bit 7 set (a facet's low byte never equals a draw material below 128), the low 7
// bits the colour plus the draw's material (flat surfaces of two draws differ as the draws do),
// the high 24 bits a hash of the draw's material (docs/conventions.md).
#ifndef SCENE_FACET_MATERIAL_GLSL
#define SCENE_FACET_MATERIAL_GLSL

uniform uint u_material;  // the draw's material (Scene::draws)

#ifdef SCENE_FACET_MATERIALS
uniform usamplerBuffer u_facet_colours;  // per triangle of the scene (GpuScene)
uniform uint u_primitive_base;           // the draw's first triangle
#endif

// Called from a geometry shader (gl_PrimitiveIDIn: the triangle within its draw).
uint scene_facet_material() {
#ifdef SCENE_FACET_MATERIALS
  int triangle = int(u_primitive_base + uint(gl_PrimitiveIDIn));
  // Past the buffer (a scene larger than the driver's buffer textures, uploaded as one texel): 0.
  uint facet = triangle < textureSize(u_facet_colours) ? texelFetch(u_facet_colours, triangle).r : 0u;
  if (facet != 0u) {
    uint h = (u_material + 1u) * 2654435761u;
    h ^= h >> 15u;
    h *= 0x5bd1e995u;
    h ^= h >> 13u;
    return (h & 0xFFFFFF00u) | 0x80u | ((facet + u_material) & 0x7Fu);
  }
#endif
  return u_material;
}

#endif  // SCENE_FACET_MATERIAL_GLSL
