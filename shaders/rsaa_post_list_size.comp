// The edge list's dispatch size for rsaa_post_resolve.comp, from its pixel count: one invocation
// between the two (an atomicMax per listed pixel in the classify pass cost more).
#include "rsaa_post_list.glsl"

layout(local_size_x = 1) in;

void main() {
  uint groups = (rsaa_list_count + RSAA_RESOLVE_GROUP - 1u) / RSAA_RESOLVE_GROUP;
  rsaa_list_groups_x = min(groups, RSAA_MAX_GROUPS_X);
  rsaa_list_groups_y = (groups + RSAA_MAX_GROUPS_X - 1u) / RSAA_MAX_GROUPS_X;
}
