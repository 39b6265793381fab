#pragma once
// The kernel's own sections of a scene (moreau-scene/1, DESIGN §3.2 and docs/scene.md).
// Plugin sections (`type` objects, bodies' model keys, contactors' shape keys) are
// checked against the schemas their plugins declare.
#include <moreau/schema.hpp>

namespace moreau::kernel::scene_schema {

inline constexpr const char* kFormat = "moreau-scene/1";

Schema top();
Schema time();
Schema output();
Schema material();
Schema body_kernel_keys();       ///< name, model, contactors
Schema contactor_kernel_keys(int dim);  ///< shape, group, placement: offset, angle (2D) / orientation (3D)
Schema driver();
Schema interaction();
Schema detection();
/// Keys of `detection` that name a plugin (a name, or an object with "type").
inline const std::vector<std::string>& detection_plugin_keys() {
  static const std::vector<std::string> keys{"broadphase"};
  return keys;
}
Schema export_problems();  ///< steps or every, directory, min_contacts

}  // namespace moreau::kernel::scene_schema
