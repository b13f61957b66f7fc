// libFuzzer target: the glTF / GLB loader from memory (scene::load_gltf_memory). Input that starts
// with "glTF" is read as a .glb, anything else as a .gltf. The base folder is empty, so no uri may
// name an external file: the loader must refuse it (data: uris are read). Whatever the bytes, the
// loader must return (ok or a one-line error), never crash, hang or read a file.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "scene/gltf_loader.h"

using namespace penumbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    scene::LoadOptions options;
    // Smaller than the defaults, so one input cannot take seconds or gigabytes legitimately.
    options.limits.max_file_bytes = std::size_t{1} << 24;
    options.limits.max_total_bytes = std::size_t{1} << 25;
    options.limits.max_vertices = std::size_t{1} << 20;
    const scene::LoadResult r =
        scene::load_gltf_memory(glb ? "fuzz.glb" : "fuzz.gltf", data, size, std::string(), options);
    // A failure names the problem on one line.
    if (!r.ok && (r.error.empty() || r.error.find('\n') != std::string::npos)) {
        std::fprintf(stderr, "fuzz_gltf: error message empty or not one line: '%s'\n", r.error.c_str());
        std::abort();
    }
    return 0;
}
