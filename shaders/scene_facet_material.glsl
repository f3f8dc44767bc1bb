// The material a triangle writes into RSAA's centre primitive target and passes to the pre-pass
// (material edges): the draw's, or with SCENE_FACET_MATERIALS (RsaaSettings::facet_materials,
// ours) for a flat-shaded triangle, one made from its shading normal. A flat-shaded mesh (a
// faceted sphere, a low-poly rod, an STL part) draws a colour edge at every facet crease, but
// two facets meeting at a gentle angle are one surface to the geometric similarity (SADP calls
// creases below about 24 degrees similar: it has to, or every tessellated curved surface would be
// all edges); their shading normals tell them apart. A triangle is flat-shaded when its three
// vertex normals are equal, as flat-shading exporters and loaders write them (one normal repeated
// per facet); normals that merely agree closely are a smooth mesh's, finely tessellated, whose
// triangles must keep one material. Its material is then a hash of that normal in world space
// (the same in every view: no crease that flickers in motion) quantised to about 0.6 degrees and
// of the draw's material, so that the coplanar triangles of one facet share it, two facets
// differ, and so do coplanar parts of two materials (unless hashes collide: 1 in 2^31 in the
// G-buffer, 1 in 128 where a pre-pass keeps the material's low 8 bits; docs/conventions.md).
// Bit 7 is always set: a facet's low byte never equals a draw material below 128. Smooth-shaded
// triangles keep the draw's material, so that only flat shading adds edges.
#ifndef SCENE_FACET_MATERIAL_GLSL
#define SCENE_FACET_MATERIAL_GLSL

uniform uint u_material;  // the draw's material (Scene::draws)
uniform mat4 u_view;      // world to view (rigid), as scene.vert reads it

// The vertex normals in view space, as scene.vert writes them.
uint scene_facet_material(vec3 normal0, vec3 normal1, vec3 normal2) {
#ifdef SCENE_FACET_MATERIALS
  // NaN normals (broken models) fail the comparison: the draw's material.
  if (all(equal(normal0, normal1)) && all(equal(normal0, normal2))) {
    vec3 world = normalize(transpose(mat3(u_view)) * normal0);
    ivec3 q = ivec3(round(world * 96.0)) + 128;  // each component in [32, 224]
    uint h = uint(q.x) * 73856093u ^ uint(q.y) * 19349663u ^ uint(q.z) * 83492791u ^ u_material * 2654435761u;
    h ^= h >> 13u;
    h *= 0x5bd1e995u;
    h ^= h >> 15u;
    return h | 0x80u;
  }
#endif
  return u_material;
}

#endif  // SCENE_FACET_MATERIAL_GLSL
