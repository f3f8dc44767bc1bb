// The edge list shared by rsaa_post_classify.comp, rsaa_post_list_size.comp and
// rsaa_post_resolve.comp: an indirect dispatch's three group counts (x set from the count by
// rsaa_post_list_size.comp; y and z are 1), the number of pixels, then the pixels (x in the low 16
// bits, y in the high 16).
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
#endif
