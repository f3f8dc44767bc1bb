// The registered techniques: one line each (their files define them).
#include "runtime/techniques/techniques.h"

namespace rsaa {

const std::vector<TechniqueKind>& registered_techniques() {
  static const std::vector<TechniqueKind> kinds = {
      noaa_technique(),   fxaa_technique(), msaa_technique(), ssaa_technique(),   filtered_ssaa_technique(),
      rsaa_technique(),   dcaa_technique(), dyncov_technique(), agaa_technique(),
  };
  return kinds;
}

}  // namespace rsaa
