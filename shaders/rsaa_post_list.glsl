// The edge list shared by rsaa_post_classify.comp, rsaa_post_list_size.comp,
// rsaa_post_resolve.comp and rsaa_post_scatter.comp: an indirect dispatch's three group counts (x
// and y set from the count by rsaa_post_list_size.comp, x at most 65535, the least maximum GL
// guarantees; z is 1), the number of pixels, then the pixels (x in the low 16 bits, y in the high
// 16).
#ifndef RSAA_POST_LIST_GLSL
#define RSAA_POST_LIST_GLSL
#ifndef RSAA_LIST_BINDING
#define RSAA_LIST_BINDING 0
#endif
#define RSAA_RESOLVE_GROUP 64u
layout(std430, binding = RSAA_LIST_BINDING) buffer RsaaEdgeList {
  uint rsaa_list_groups_x, rsaa_list_groups_y, rsaa_list_groups_z;
  uint rsaa_list_count;
  uint rsaa_list_pixels[];
};
#define RSAA_MAX_GROUPS_X 65535u

// The list entry of this invocation, in a dispatch of RSAA_RESOLVE_GROUP-wide groups laid out as
// rsaa_post_list_size.comp sets them; at or past rsaa_list_count for the last group's spare lanes.
uint rsaa_list_index() {
  return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * RSAA_RESOLVE_GROUP + gl_LocalInvocationID.x;
}
#endif
