// glTF 2.0 scenes through tinygltf: meshes, node transforms, base colour factor and texture,
// the first perspective camera and the first KHR_lights_punctual light.
#pragma once

#include <cstddef>
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

// What a scene file may do. A scene reads only regular files, opened without blocking, inside its
// own folder (its buffers' and images' uris); `allow_outside` names further folders (or files) it
// may read. The limits bound what a hostile file can make the loader spend.
struct LoadLimits {
    std::size_t max_file_bytes = std::size_t{1} << 30;     // any one file: the scene, a buffer, an image
    std::size_t max_total_bytes = std::size_t{2} << 30;    // all the files one load reads together
    int max_json_depth = 64;                               // nesting of JSON objects and arrays
    std::size_t max_elements = 1u << 20;                   // entries in any one top-level array (nodes, accessors...)
    std::size_t max_vertices = std::size_t{1} << 26;       // per accessor
    double max_coordinate = 1e12;                          // |world-space vertex, translation, light position|
    std::size_t max_image_pixels = std::size_t{1} << 26;   // per decoded texture (256 MiB as RGBA8)
};

struct LoadOptions {
    std::vector<std::string> allow_outside;
    LoadLimits limits;
};

LoadResult load_gltf(const std::string& path, const LoadOptions& options = {});
// The same from bytes already in memory (the fuzz target, tests): `name`'s extension picks .gltf
// or .glb and names the file in messages; relative uris resolve against `base_dir` under the same
// rules (an empty base_dir: no external file may be read).
LoadResult load_gltf_memory(const std::string& name, const unsigned char* bytes, std::size_t size,
                            const std::string& base_dir, const LoadOptions& options = {});

}  // namespace penumbra::scene
