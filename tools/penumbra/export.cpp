// penumbra export: the scene at time t as one self-contained glTF 2.0 file.
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "cli_options.h"
#include "measure.h"
#include "plan/options.h"
#include "scene/gltf_writer.h"
#include "scene/printable.h"
#include "scene/scene_source.h"

namespace penumbra::tools {

scene::SceneSource open_scene(const std::string& name, scene::Eye eye, const std::vector<std::string>& allow_outside) {
    scene::SceneSource src;
    std::string error;
    std::vector<std::string> warnings;
    scene::LoadOptions load;
    load.allow_outside = allow_outside;
    const bool ok = src.open(name, error, warnings, 10, load);
    for (const auto& w : warnings) std::cerr << "penumbra: note: " << one_line(w) << "\n";
    if (!ok) throw CommandError{"--scene: " + error, 2};
    src.set_eye(eye);
    return src;
}

void run_export(const ExportOptions& o) {
    // Everything that can be checked before the scene is loaded: the numbers, the output.
    // (--time was checked as typed by run_measure_commands: finite, in the table's range.)
    render::Options checked;
    if (const std::string err = render::parse_option(checked, "size", o.size); !err.empty()) throw CommandError{err, 2};
    const float aspect = static_cast<float>(checked.job.width) / static_cast<float>(checked.job.height);
    check_output_file("--out", o.out, ".gltf");
    scene::SceneSource src = open_scene(o.scene, scene::Eye::Scene, o.allow_outside);
    const scene::Scene& s = src.at(o.time);
    scene::GltfWriteOptions wo;
    wo.aspect = aspect;
    // The file's JSON is UTF-8: a name that is not (a path's raw bytes) goes in escaped.
    wo.generator = "penumbra export --scene " + scene::printable(o.scene) + " --time " + std::to_string(o.time);
    if (const std::string err = scene::write_gltf(o.out, s, wo); !err.empty()) throw CommandError{err, 2};
    size_t triangles = 0;
    for (const auto& obj : s.objects)
        if (obj.mesh >= 0 && obj.mesh < static_cast<int>(s.meshes.size()))
            triangles += s.meshes[static_cast<size_t>(obj.mesh)].indices.size() / 3;
    std::printf("wrote %s: %zu objects, %zu triangles, camera, %s light\n", scene::printable(o.out).c_str(), s.objects.size(),
                triangles, s.light.type == scene::LightType::Point ? "point"
                           : s.light.type == scene::LightType::Spot ? "spot" : "directional");
}

}  // namespace penumbra::tools
