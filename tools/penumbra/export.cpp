// penumbra export: the scene at time t as one self-contained glTF 2.0 file.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "measure.h"
#include "scene/gltf_writer.h"
#include "scene/scene_source.h"

namespace fs = std::filesystem;

namespace penumbra::tools {

namespace {

// "WxH" -> aspect; throws CommandError naming the option.
float parse_aspect(const std::string& option, const std::string& size) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w <= 0 || h <= 0)
        throw CommandError{option + ": expected WxH with positive sizes, got '" + size + "'", 2};
    return static_cast<float>(w) / static_cast<float>(h);
}

}  // namespace

scene::SceneSource open_scene(const std::string& name, scene::Eye eye) {
    scene::SceneSource src;
    std::string error;
    std::vector<std::string> warnings;
    const bool ok = src.open(name, error, warnings);
    for (const auto& w : warnings) std::cerr << "penumbra: note: " << w << "\n";
    if (!ok) throw CommandError{"--scene: " + error, 2};
    src.set_eye(eye);
    return src;
}

void run_export(const ExportOptions& o) {
    const fs::path out(o.out);
    if (out.extension() != ".gltf") throw CommandError{"--out " + o.out + ": the file name must end in .gltf", 2};
    std::error_code ec;
    if (out.has_parent_path() && !fs::is_directory(out.parent_path(), ec))
        throw CommandError{"--out " + o.out + ": folder " + out.parent_path().string() + " does not exist", 2};
    const float aspect = parse_aspect("--size", o.size);
    scene::SceneSource src;
    std::string error;
    std::vector<std::string> warnings;
    const bool ok = src.open(o.scene, error, warnings);
    for (const auto& w : warnings) std::cerr << "penumbra: note: " << w << "\n";
    if (!ok) throw CommandError{"--scene: " + error, 2};
    const scene::Scene& s = src.at(o.time);
    scene::GltfWriteOptions wo;
    wo.aspect = aspect;
    wo.generator = "penumbra export --scene " + o.scene + " --time " + std::to_string(o.time);
    if (const std::string err = scene::write_gltf(o.out, s, wo); !err.empty()) throw CommandError{err, 1};
    size_t triangles = 0;
    for (const auto& obj : s.objects)
        if (obj.mesh >= 0 && obj.mesh < static_cast<int>(s.meshes.size()))
            triangles += s.meshes[static_cast<size_t>(obj.mesh)].indices.size() / 3;
    std::printf("wrote %s: %zu objects, %zu triangles, camera, %s light\n", o.out.c_str(), s.objects.size(), triangles,
                s.light.type == scene::LightType::Point ? "point"
                : s.light.type == scene::LightType::Spot ? "spot" : "directional");
}

}  // namespace penumbra::tools
