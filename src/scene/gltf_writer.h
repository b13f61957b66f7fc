// scene::Scene -> glTF 2.0 (.gltf, one self-contained JSON file): every mesh with its normals and
// uvs, one node per object carrying the object's world matrix, the materials (base colour factor,
// base colour texture as an embedded PNG), the camera and the light (KHR_lights_punctual).
// Buffers and images are embedded as base64 data URIs, so the file alone is the scene: another
// renderer (three.js, a ray tracer) loading it sees the very same triangles.
#pragma once

#include <string>

#include "scene/scene.h"

namespace penumbra::scene {

struct GltfWriteOptions {
    // The camera's aspect ratio written to the file when Camera::aspect is 0 (the viewport's):
    // glTF needs one to reproduce the view; 0 leaves aspectRatio out (the loader then takes the
    // viewport's again).
    float aspect = 0.0f;
    std::string generator = "penumbra";
};

// The glTF JSON text for `scene`; the camera is written from yfov/znear/zfar. Every file it
// writes loads back: a value glTF cannot hold (a number that is not finite: JSON has no NaN, a
// camera with znear <= 0, zfar <= znear or yfov outside (0, pi)) is refused, and `error` names the
// first one ("the camera's znear is not finite (nan)"; "" when written). Names that are not valid
// UTF-8 go in escaped (scene::printable).
std::string to_gltf(const Scene& scene, const GltfWriteOptions& options, std::string& error);
// The same; a refused value throws std::invalid_argument with the message.
std::string to_gltf(const Scene& scene, const GltfWriteOptions& options = {});

// Writes to_gltf(scene) to `path` with write_file (a temporary file, every write and the close
// checked, renamed into place). Returns "" or one line naming the problem (a refused value or a
// failed write: nothing is written, no temporary file left).
std::string write_gltf(const std::string& path, const Scene& scene, const GltfWriteOptions& options = {});

}  // namespace penumbra::scene
