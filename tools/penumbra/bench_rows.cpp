// penumbra bench's extra rows beside the sweep's encodings x filters x maps: the defaults as they
// were before issue 9.
#include <algorithm>
#include <string>
#include <vector>

#include "bench.h"

namespace penumbra::tools::bench {

// The defaults as they were before issue 9 ("Better than three.js on the same frames"): the
// sheet's constant bias, both faces into the map, the frustum fitted around the whole scene and
// PCF's full kernel. With the references, and unless --set changes one of these options itself,
// the sweep also runs rgba hard and rgba pcf4x4 at those of the map sizes 512, 1024 and 2048 it sweeps,
// labelled "... (before)", so the report can set the defaults against them.
std::vector<Planned> before_rows(const Sweep& w) {
    std::vector<Planned> out;
    const char* const kBefore[][2] = {{"bias", "sheet"}, {"map-faces", "both"}, {"light-fit", "scene"}, {"pcf-kernel", "full"}};
    if (!w.o.references || std::find(w.encodings.begin(), w.encodings.end(), shadow::Encoding::RGBA) == w.encodings.end())
        return out;
    for (const auto& kv : w.o.set)
        for (const auto& b : kBefore)
            if (kv.rfind(std::string(b[0]) + "=", 0) == 0) return out;
    for (auto f : {shadow::Filter::Hard, shadow::Filter::PCF4x4}) {
        if (std::find(w.filters.begin(), w.filters.end(), f) == w.filters.end()) continue;
        for (int m : w.o.maps) {
            if (m != 512 && m != 1024 && m != 2048) continue;
            render::Settings s = w.base.settings;
            s.technique = render::technique_named("shadowmap");
            s.encoding = shadow::Encoding::RGBA;
            s.filter = f;
            s.map_size = m;
            for (const auto& b : kBefore)
                if (const std::string err = render::parse_option(s, b[0], b[1]); !err.empty()) throw CommandError{err, 1};
            out.push_back({s, technique_label(s) + std::string(kBeforeSuffix)});
        }
    }
    return out;
}

}  // namespace penumbra::tools::bench
