// Two-sided shading, decided once per triangle by the geometry stages (scene.geom,
// coverage_fragments.geom): -1 when the triangle's normals are clearly on its far side from the
// eye (a back face seen, a model whose normals point inwards), else +1; the fragment stage turns
// the interpolated normal by it (scene_shading_normal()). Decided per fragment by the
// interpolated normal itself, as it was, the side flipped inside triangles that face the eye
// wherever a smooth normal turns away from it (near silhouettes, across the faces of a box with
// averaged normals): hard light/dark lines across one surface, which no antialiasing can smooth
// and which the bench counted as edge error. "Clearly": normals about perpendicular to their
// triangle (a thin face between large ones, averaged) are kept as they are, so that the two
// triangles of one face cannot land on different sides.
#ifndef RSAA_SCENE_NORMAL_SIDE_GLSL
#define RSAA_SCENE_NORMAL_SIDE_GLSL

// face: the triangle's unit normal (either orientation); normal_sum: the sum of its vertex
// normals; point: one of its vertices, view space (the eye at the origin).
float scene_normal_side(vec3 face, vec3 normal_sum, vec3 point) {
  vec3 seen = dot(face, point) > 0.0 ? -face : face;  // the face's normal towards the eye
  // Beyond about 107 degrees from the seen side (cos < -0.3): on the far side.
  return dot(seen, normal_sum) < -0.3 * length(normal_sum) ? -1.0 : 1.0;
}

#endif  // RSAA_SCENE_NORMAL_SIDE_GLSL
