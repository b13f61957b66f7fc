#include "measure/image_io.h"

#include <cstddef>

#include <stb_image.h>
#include <stb_image_write.h>

#include "scene/file_write.h"
#include "scene/printable.h"

namespace penumbra::measure {

namespace {
void append(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}
}  // namespace

std::string write_png(const std::string& path, const Pixels& px) {
    const std::string name = scene::printable(path);  // one line, valid UTF-8, whatever the path's bytes
    if (px.width <= 0 || px.height <= 0 || px.channels < 1 || px.channels > 4 ||
        px.data.size() < static_cast<size_t>(px.width) * static_cast<size_t>(px.height) * static_cast<size_t>(px.channels))
        return name + ": no image to write";
    std::string encoded;
    if (!stbi_write_png_to_func(append, &encoded, px.width, px.height, px.channels, px.data.data(),
                                px.width * px.channels))
        return name + ": could not encode PNG";
    return scene::write_file(path, encoded);
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
