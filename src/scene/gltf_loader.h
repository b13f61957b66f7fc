// glTF 2.0 scenes through tinygltf: meshes, node transforms, base colour factor and texture,
// the first perspective camera and the first KHR_lights_punctual light.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace penumbra::scene {

struct LoadResult {
    bool ok = false;
    std::string error;                  // one line naming the problem when !ok
    std::vector<std::string> warnings;  // e.g. "no camera: using a default view of the bounds"
    Scene scene;
};

LoadResult load_gltf(const std::string& path);

}  // namespace penumbra::scene
