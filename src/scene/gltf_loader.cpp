// glTF 2.0 (.gltf / .glb) -> scene::Scene: the entry point. tinygltf parses the JSON, decodes data
// URIs and images; everything that indexes into its arrays or buffers is validated by the code in
// gltf_accessors.cpp and gltf_scene.cpp, because tinygltf checks little beyond the JSON syntax and
// a bad file must give an error, not a crash. Here: the file checks, the parse, and turning every
// failure into one line that names the file.
#include "scene/gltf_loader.h"
#include "scene/memory_budget.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <new>
#include <utility>
#include <cstring>
#include <exception>
#include <sstream>

#include <stb_image.h>

#include "scene/gltf_internal.h"
#include "scene/printable.h"

namespace penumbra::scene {
namespace {

using gltf_internal::lower;

// tinygltf reports several problems in one multi-line string, sometimes quoting a whole
// base64 data URI; the result must stay one readable line.
std::string one_line(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c == '\r') continue;
        if (c == '\n') {
            out += "; ";
        } else if (static_cast<unsigned char>(c) < 0x20) {
            out += ' ';
        } else {
            out += c;
        }
        if (c == ',' && out.size() >= 7 && out.compare(out.size() - 7, 7, "base64,") == 0) {
            size_t end = i + 1;
            while (end < s.size() && (std::isalnum(static_cast<unsigned char>(s[end])) || s[end] == '+' ||
                                      s[end] == '/' || s[end] == '='))
                ++end;
            if (end - (i + 1) > 16) {
                out += s.substr(i + 1, 16) + "...";
                i = end - 1;
            }
        }
    }
    return out;
}

std::vector<std::string> split_lines(const std::string& s) {
    std::vector<std::string> out;
    std::istringstream in(s);
    std::string line;
    while (std::getline(in, line))
        if (!line.empty()) out.push_back(line);
    return out;
}

std::string file_extension(const std::string& path) {
    const auto slash = path.find_last_of("/\\");
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    return lower(path.substr(dot));
}

// The JSON text the validation layer checks: the whole file for .gltf, the first chunk for .glb
// (null when the GLB header is malformed: tinygltf reports that).
std::pair<const char*, std::size_t> json_chunk(const std::string& ext, const unsigned char* bytes, std::size_t size) {
    if (ext == ".gltf") return {reinterpret_cast<const char*>(bytes), size};
    if (size < 20 || std::memcmp(bytes, "glTF", 4) != 0 || std::memcmp(bytes + 16, "JSON", 4) != 0) return {nullptr, 0};
    std::uint32_t length = 0;
    std::memcpy(&length, bytes + 12, 4);  // little-endian, as the machine
    if (length > size - 20) return {nullptr, 0};
    return {reinterpret_cast<const char*>(bytes + 20), length};
}

// tinygltf's image callback: stb decodes to RGBA (16-bit PNGs stay 16-bit). A truncated or
// unknown image, or one too large, is left empty with its reason kept: the material that uses
// it loses the texture with a note (gltf_scene.cpp), the scene still loads.
bool decode_image(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                  const unsigned char* bytes, int size, void* user) {
    auto& context = *static_cast<gltf_internal::LoadContext*>(user);
    image->image.clear();
    image->width = image->height = 0;
    int w = 0, h = 0, comp = 0;
    if (!stbi_info_from_memory(bytes, size, &w, &h, &comp)) {
        context.image_problems[index] = std::string("cannot be decoded (") + stbi_failure_reason() + ")";
        return true;
    }
    if (w <= 0 || h <= 0 || static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) > context.limits.max_image_pixels) {
        context.image_problems[index] = "is " + std::to_string(w) + "x" + std::to_string(h) +
                                        " pixels, over the limit of " + std::to_string(context.limits.max_image_pixels);
        return true;
    }
    const bool wide = stbi_is_16_bit_from_memory(bytes, size) != 0;
    void* data = wide ? static_cast<void*>(stbi_load_16_from_memory(bytes, size, &w, &h, &comp, 4))
                      : static_cast<void*>(stbi_load_from_memory(bytes, size, &w, &h, &comp, 4));
    if (!data) {
        context.image_problems[index] = std::string("cannot be decoded (") + stbi_failure_reason() + ")";
        return true;
    }
    const std::size_t bits = wide ? 16 : 8;
    image->width = w;
    image->height = h;
    image->component = 4;
    image->bits = static_cast<int>(bits);
    image->pixel_type = wide ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    const auto* first = static_cast<const unsigned char*>(data);
    image->image.assign(first, first + static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4 * bits / 8);
    stbi_image_free(data);
    return true;
}

}  // namespace

LoadResult load_gltf_memory(const std::string& name, const unsigned char* bytes, std::size_t size,
                            const std::string& base_dir, const LoadOptions& options) {
    LoadResult result;
    const std::string path = printable(name);  // as messages show it: one line, valid UTF-8
    try {
        const std::string ext = file_extension(name);
        if (ext != ".gltf" && ext != ".glb") {
            result.error = path + ": unknown file extension '" + printable(ext) + "' (expected .gltf or .glb)";
            return result;
        }
        if (size > options.limits.max_file_bytes || size > 0xFFFFFFFFu)
            gltf_internal::fail("is " + std::to_string(size) + " bytes, over the limit of " +
                                std::to_string(std::min<std::size_t>(options.limits.max_file_bytes, 0xFFFFFFFFu)));
        if (ext == ".glb" && size >= 12 && std::memcmp(bytes, "glTF", 4) == 0) {
            // tinygltf reads any header version as glTF 2.0's layout: a GLB 1 (KHR_binary_glTF,
            // another layout and a glTF 1.0 document) would be misread, not refused.
            std::uint32_t version = 0;
            std::memcpy(&version, bytes + 4, 4);  // little-endian, as the machine
            if (version != 2)
                gltf_internal::fail("GLB header version is " + std::to_string(version) +
                                    ": only version 2 (glTF 2.0) is read");
        }
        gltf_internal::FileAccess files(base_dir, options);
        const auto [json_text, json_size] = json_chunk(ext, bytes, size);
        if (json_text) gltf_internal::validate_json(json_text, json_size, options.limits, files);

        gltf_internal::LoadContext context;
        context.limits = options.limits;
        tinygltf::TinyGLTF loader;
        loader.SetFsCallbacks(files.callbacks());
        loader.SetImageLoader(&decode_image, &context);
        tinygltf::Model model;
        std::string err, warn;
        const std::string dir = files.folder();
        const bool parsed =
            ext == ".glb"
                ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes, static_cast<unsigned int>(size), dir)
                : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes),
                                             static_cast<unsigned int>(size), dir);
        for (const auto& w : split_lines(warn)) result.warnings.push_back(path + ": " + printable(one_line(w)));
        if (!parsed) {
            result.error = path + ": invalid glTF: " +
                           (err.empty() ? "tinygltf could not parse it" : printable(one_line(err)));
            return result;
        }
        gltf_internal::build_scene(model, result, path, context);
        result.ok = true;
    } catch (const memory::OverBudget& e) {
        result.error = path + ": " + e.what();
    } catch (const std::bad_alloc&) {
        result.error = path + ": out of memory while loading (the file asks for more than this machine has)";
    } catch (const std::exception& e) {  // GltfError, nlohmann's and tinygltf's own
        result.error = path + ": " + printable(one_line(e.what()));
    } catch (...) {
        result.error = path + ": unexpected error while loading";
    }
    if (!result.ok) result.scene = Scene{};  // no half-built scene escapes a failed load
    return result;
}

LoadResult load_gltf(const std::string& path, const LoadOptions& options) {
    LoadResult result;
    const std::string ext = file_extension(path);
    if (ext != ".gltf" && ext != ".glb") {
        result.error = printable(path) + ": unknown file extension '" + printable(ext) + "' (expected .gltf or .glb)";
        return result;
    }
    std::vector<unsigned char> bytes;
    std::string problem;
    if (!gltf_internal::read_regular_file(path, options.limits.max_file_bytes, bytes, problem)) {
        result.error = printable(path) + ": " + problem;
        return result;
    }
    const auto slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
    return load_gltf_memory(path, bytes.data(), bytes.size(), dir, options);
}

}  // namespace penumbra::scene
