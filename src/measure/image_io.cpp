#include "measure/image_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include <stb_image.h>
#include <stb_image_write.h>

#include "scene/printable.h"

namespace penumbra::measure {

namespace {
void append(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}
}  // namespace

std::string write_png(const std::string& path, const Pixels& px) {
    const std::string name = scene::printable(path);  // one line, valid UTF-8, whatever the path's bytes
    if (px.width <= 0 || px.height <= 0 || px.channels < 1 || px.channels > 4 ||
        px.data.size() < static_cast<size_t>(px.width) * static_cast<size_t>(px.height) * static_cast<size_t>(px.channels))
        return name + ": no image to write";
    namespace fs = std::filesystem;
    const fs::path target(path);
    std::error_code ec;
    if (target.has_parent_path() && !fs::is_directory(target.parent_path(), ec))
        return name + ": folder " + scene::printable(target.parent_path().string()) + " does not exist";
    if (fs::is_directory(target, ec)) return name + ": cannot write (" + std::strerror(EISDIR) + ")";
    std::vector<std::uint8_t> encoded;
    if (!stbi_write_png_to_func(append, &encoded, px.width, px.height, px.channels, px.data.data(),
                                px.width * px.channels))
        return name + ": could not encode PNG";
    std::random_device rd;
    const fs::path tmp = target.string() + ".tmp" + std::to_string(rd() % 1000000u);
    {
        std::ofstream f(tmp, std::ios::binary);
        if (!f) return name + ": cannot write (" + std::strerror(errno) + ")";
        f.write(reinterpret_cast<const char*>(encoded.data()), static_cast<std::streamsize>(encoded.size()));
        f.close();
        if (!f) {
            const std::string why = std::strerror(errno);
            fs::remove(tmp, ec);
            return name + ": write failed (" + why + ")";
        }
    }
    fs::rename(tmp, target, ec);
    if (ec) {
        const std::string why = ec.message();
        fs::remove(tmp, ec);
        return name + ": cannot move the written file into place (" + why + ")";
    }
    return {};
}

std::string read_png(const std::string& path, Pixels& out, int channels) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, channels);
    if (!data)
        return scene::printable(path) + ": " + (stbi_failure_reason() ? stbi_failure_reason() : "cannot read PNG");
    out.width = w;
    out.height = h;
    out.channels = channels ? channels : n;
    out.data.assign(data, data + static_cast<size_t>(w) * static_cast<size_t>(h) * static_cast<size_t>(out.channels));
    stbi_image_free(data);
    return {};
}

Pixels from_rgba(const std::vector<std::uint8_t>& rgba, int width, int height, int channels) {
    Pixels p;
    p.width = width;
    p.height = height;
    p.channels = channels;
    const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
    p.data.resize(n * static_cast<size_t>(channels));
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < channels; ++c) p.data[i * static_cast<size_t>(channels) + static_cast<size_t>(c)] = rgba[i * 4 + static_cast<size_t>(c)];
    return p;
}

}  // namespace penumbra::measure
