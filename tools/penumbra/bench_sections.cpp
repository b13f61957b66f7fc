// penumbra bench's results.md: the tables of the sections beside the sweep (bench.h): the
// silhouette sweep's spheres and the stencil effects on the course frame.
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "bench.h"

namespace penumbra::tools::bench {

// The silhouette sweep: a sphere of a growing number of segments under a point light, volumes
// (auto) against rgba hard 1024. Empty without its rows.
std::string silhouette_table(const Sweep& w) {
    if (w.silhouette.empty()) return "";
    std::vector<int> segs;
    std::vector<std::string> techniques;
    for (const Row& r : w.silhouette) {
        if (std::find(segs.begin(), segs.end(), r.segments) == segs.end()) segs.push_back(r.segments);
        if (std::find(techniques.begin(), techniques.end(), key_label({r.technique, r.map})) == techniques.end())
            techniques.push_back(key_label({r.technique, r.map}));
    }
    const auto find = [&](int seg, const std::string& t) -> const Row* {
        for (const Row& r : w.silhouette)
            if (r.segments == seg && key_label({r.technique, r.map}) == t) return &r;
        return nullptr;
    };
    std::ostringstream o;
    o << "\n## Shadow volumes as the silhouette grows\n\n"
      << "A UV sphere (radius 1, N slices x N/2 stacks, 2 above a 10 x 10 ground quad) under a point light, "
      << w.width << "x" << w.height << ", the same run: ms/frame is the median of " << w.o.rounds << " interleaved round(s) of "
      << w.o.frames << " frames (moving: the light turning half a degree a frame; still: the same frame again, a map "
         "reused); error against the ray-traced hard truth of each frame. Silhouette edges, volume triangles and fill "
         "(stencil fragments per pixel) are the volumes'.\n\n"
      << "| segments | sphere triangles |";
    for (const auto& t : techniques) o << " " << t << " error % | " << t << " ms moving | " << t << " ms still |";
    o << " silhouette edges | volume triangles | fill per pixel |\n|---:|---:|";
    for (size_t i = 0; i < techniques.size(); ++i) o << "---:|---:|---:|";
    o << "---:|---:|---:|\n";
    for (int seg : segs) {
        o << "| " << seg << " | " << 2 * seg * (seg / 2 - 1) << " |";
        const Row* vol = nullptr;
        for (const auto& t : techniques) {
            const Row* r = find(seg, t);
            if (r && r->silhouette_edges >= 0) vol = r;
            o << " " << (r ? fixed(r->score.error_pct, 2) : "-") << " | " << (r ? fixed(r->ms_moving, 2) : "-") << " | "
              << (r ? fixed(r->ms_still, 2) : "-") << " |";
        }
        o << " " << (vol ? std::to_string(vol->silhouette_edges) : "-") << " | " << (vol ? std::to_string(vol->volume_triangles) : "-")
          << " | " << (vol ? fixed(vol->fill_per_pixel, 2) : "-") << " |\n";
    }
    return o.str();
}

// The stencil effects on the course frame (effects_bench.cpp): per technique, each effect set's
// error (the frame, and the mirror's and opening's pixels) and ms/frame beside "none". Empty
// without its rows.
std::string effects_table(const Sweep& w) {
    if (w.effects.empty()) return "";
    std::ostringstream o;
    o << "\n## The stencil effects and the post passes on " << w.effects_frame << "\n\n"
      << "Each effect alone and all three under the default technique and shadow volumes, " << w.width << "x" << w.height
      << ", the same run. Error: the visibility AOV against the effects' ray-traced hard truth (the mirror's pixels traced "
         "in the mirrored scene, the opening's in the portal's scene; the visibility AOV shows the surface seen in the "
         "mirror whole, whatever the reflectivity); \"in the mirror/opening\" counts only their valid pixels. The "
         "outline is a colour: its error is the frame's under it. Not modelled: pixels the truth leaves out because the "
         "renderer leaves them out on purpose (the mirror does not reflect the portal). ms/frame: the median of "
      << w.o.rounds << " interleaved round(s) of " << w.o.frames
      << " frames (moving: the course animated 1/60 s a frame; still: the same frame again); + ms: over \"none\" with "
         "the same technique, moving. The --post rows (plan/post.h) are timed, not scored: they change the image "
         "itself (shadow-blur is scored against the area-light truth by bench --soft); their bytes count the post "
         "passes' targets beside the map.\n\n"
      << "| technique | effects | post | error % | error % in the mirror/opening | px compared there | false lit % there | "
         "not modelled px | ms/frame moving | ms/frame still | + ms | map (+ post targets) bytes |\n"
      << "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    const auto plain = [](const Row& q) { return q.effects == "none" && (q.post.empty() || q.post == "none"); };
    for (const Row& r : w.effects) {
        const Row* none = nullptr;
        for (const Row& q : w.effects)
            if (q.technique == r.technique && plain(q)) none = &q;
        const bool region = r.region.valid > 0;
        const bool scored = r.post.empty() || r.post == "none";
        o << "| " << r.technique << " | " << r.effects << " | " << (r.post.empty() ? "none" : r.post) << " | "
          << (scored ? fixed(r.score.error_pct, 2) : "-") << " | "
          << (region ? fixed(r.region.error_pct, 2) : "-") << " | " << r.region.valid << " | "
          << (region ? fixed(r.region.false_lit_pct, 2) : "-") << " | " << r.not_modelled << " | " << fixed(r.ms_moving, 2)
          << " | " << fixed(r.ms_still, 2) << " | "
          << (none && none != &r ? (r.ms_moving >= none->ms_moving ? "+" : "") + fixed(r.ms_moving - none->ms_moving, 2) : "-")
          << " | " << bytes_str(r.bytes) << " |\n";
    }
    return o.str();
}

}  // namespace penumbra::tools::bench
