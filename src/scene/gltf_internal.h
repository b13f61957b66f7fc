// Private to the glTF loader's files (gltf_loader.cpp, gltf_accessors.cpp, gltf_scene.cpp), not
// part of the public API: the error their checks throw, the small helpers they share and the two
// calls that cross between them. Include it only from those files.
#pragma once

#include <cctype>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <tiny_gltf.h>  // implementation compiled in src/thirdparty/thirdparty_impl.cpp

#include "scene/gltf_loader.h"
#include "scene/scene.h"

namespace penumbra::scene::gltf_internal {

// Thrown through fail() by the checks in gltf_accessors.cpp and gltf_scene.cpp with a message
// naming the offending glTF element; load_gltf catches it and prefixes the file name. Keeps every
// check a one-liner at its call site.
struct GltfError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] inline void fail(const std::string& what) { throw GltfError(what); }

inline std::string lower(std::string s) {
    for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

template <typename T>
bool in_range(int index, const std::vector<T>& v) {
    return index >= 0 && static_cast<size_t>(index) < v.size();
}

// Primitive p of mesh mesh_index as a scene Mesh: validated indices, unit normals (computed when
// the file has none) and TEXCOORD_0 if present. In gltf_accessors.cpp.
Mesh convert_primitive(const tinygltf::Model& model, int mesh_index, size_t p);

// Fills result.scene from a parsed model (objects, materials, textures, camera, light, ground),
// adding warnings for what it leaves out; throws GltfError on a malformed model. In gltf_scene.cpp.
void build_scene(const tinygltf::Model& model, LoadResult& result, const std::string& path);

}  // namespace penumbra::scene::gltf_internal
