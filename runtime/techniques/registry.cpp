// The registered techniques, in the order help texts list them: one line each. Each name N is a
// file techniques/N.cpp (or, for ssaa, supersample.cpp) that defines `TechniqueKind N_technique()`.
#include "runtime/techniques/techniques.h"

#define RSAA_REGISTERED_TECHNIQUES(X) \
  X(noaa)                             \
  X(fxaa)                             \
  X(msaa)                             \
  X(ssaa)                             \
  X(filtered_ssaa)                    \
  X(rsaa)                             \
  X(dcaa)                             \
  X(dyncov)                           \
  X(agaa)

namespace rsaa {

#define RSAA_DECLARE_TECHNIQUE(name) TechniqueKind name##_technique();
RSAA_REGISTERED_TECHNIQUES(RSAA_DECLARE_TECHNIQUE)

const std::vector<TechniqueKind>& registered_techniques() {
#define RSAA_LIST_TECHNIQUE(name) name##_technique(),
  static const std::vector<TechniqueKind> kinds = {RSAA_REGISTERED_TECHNIQUES(RSAA_LIST_TECHNIQUE)};
  return kinds;
}

}  // namespace rsaa
