// Private to the glTF loader's files (gltf_loader.cpp, gltf_accessors.cpp, gltf_scene.cpp), not
// part of the public API: the error their checks throw, the small helpers they share and the two
// calls that cross between them. Include it only from those files.
#pragma once

#include <cctype>
#include <cstddef>
#include <map>
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

// The files one load may read (gltf_files.cpp): regular files only, opened without blocking,
// inside the scene's folder or an allowed one, within the limits' byte budget.
bool read_regular_file(const std::string& path, std::size_t max_bytes, std::vector<unsigned char>& out,
                       std::string& problem);

class FileAccess {
public:
    // scene_dir "": nothing may be read (a scene from memory without a folder).
    FileAccess(const std::string& scene_dir, const LoadOptions& options);
    // "" when `path` (existing) lies inside the scene's folder or an allowed one, else why not.
    std::string check_inside(const std::string& path) const;
    // check_inside + read_regular_file within the remaining budget.
    bool read_named(const std::string& path, std::vector<unsigned char>& out, std::string& problem);
    tinygltf::FsCallbacks callbacks();  // for tinygltf, pointing at this object
    const std::string& folder() const { return folder_; }

private:
    LoadLimits limits_;
    std::string folder_;              // canonical scene folder ("" if none)
    std::vector<std::string> roots_;  // folder_ and the allowed paths, canonical
    std::size_t used_ = 0;
};

// The JSON checks that come before tinygltf sees the text (gltf_validate.cpp): nesting depth,
// counts, asset version, finite and sane numbers, offsets and indices, uris inside the folder.
// Throws GltfError naming the JSON path (e.g. nodes[3].scale[0]) and the rule.
void validate_json(const char* text, std::size_t size, const LoadLimits& limits, const FileAccess& files);

// Primitive p of mesh mesh_index as a scene Mesh: validated indices, unit normals (computed when
// the file has none) and TEXCOORD_0 if present. In gltf_accessors.cpp.
Mesh convert_primitive(const tinygltf::Model& model, int mesh_index, size_t p);

// What one load carries from the parse to the conversion: the limits, and why an image was left
// undecoded (by index), for the note when a material drops its texture.
struct LoadContext {
    LoadLimits limits;
    std::map<int, std::string> image_problems;
};

// Fills result.scene from a parsed model (objects, materials, textures, camera, light, ground),
// adding warnings for what it leaves out; throws GltfError on a malformed model or one whose
// world-space geometry exceeds the limits. In gltf_scene.cpp.
void build_scene(const tinygltf::Model& model, LoadResult& result, const std::string& path, const LoadContext& context);

}  // namespace penumbra::scene::gltf_internal
