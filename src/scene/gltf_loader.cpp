// glTF 2.0 (.gltf / .glb) -> scene::Scene: the entry point. tinygltf parses the JSON, decodes data
// URIs and images; everything that indexes into its arrays or buffers is validated by the code in
// gltf_accessors.cpp and gltf_scene.cpp, because tinygltf checks little beyond the JSON syntax and
// a bad file must give an error, not a crash. Here: the file checks, the parse, and turning every
// failure into one line that names the file.
#include "scene/gltf_loader.h"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <sstream>

#include "scene/gltf_internal.h"

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

}  // namespace

LoadResult load_gltf_memory(const std::string& name, const unsigned char* bytes, std::size_t size,
                            const std::string& base_dir, const LoadOptions& options) {
    (void)options;
    LoadResult result;
    const std::string& path = name;
    try {
        const std::string ext = file_extension(path);
        if (ext != ".gltf" && ext != ".glb") {
            result.error = path + ": unknown file extension '" + ext + "' (expected .gltf or .glb)";
            return result;
        }
        tinygltf::TinyGLTF loader;
        tinygltf::Model model;
        std::string err, warn;
        const bool parsed =
            ext == ".glb"
                ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes, static_cast<unsigned int>(size), base_dir)
                : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes),
                                             static_cast<unsigned int>(size), base_dir);
        for (const auto& w : split_lines(warn)) result.warnings.push_back(path + ": " + w);
        if (!parsed) {
            result.error = path + ": invalid glTF: " + (err.empty() ? "tinygltf could not parse it" : one_line(err));
            return result;
        }
        gltf_internal::build_scene(model, result, path);
        result.ok = true;
    } catch (const std::exception& e) {  // GltfError, and bad_alloc on absurd sizes
        result.error = path + ": " + e.what();
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
        result.error = path + ": unknown file extension '" + ext + "' (expected .gltf or .glb)";
        return result;
    }
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        result.error = path + ": cannot open file: " + (errno ? std::strerror(errno) : "unreadable");
        return result;
    }
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto slash = path.find_last_of('/');
    return load_gltf_memory(path, bytes.data(), bytes.size(), slash == std::string::npos ? "." : path.substr(0, slash),
                            options);
}

}  // namespace penumbra::scene
