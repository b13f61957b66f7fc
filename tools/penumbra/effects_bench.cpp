// penumbra bench: the stencil effects (--effects outline, mirror, portal) beside the techniques.
// On the first course frame of the sweep's scenes, each effect alone and all three together, under
// the sweep's default technique (a shadow map) and shadow volumes: the visibility AOV scored
// against the effects' truth (measure/effect_truth.h: the mirror's pixels traced in the mirrored
// scene, the opening's in the portal's scene), over the frame and in the mirror's and opening's
// pixels alone, and ms/frame timed like the sweep's (interleaved rounds; moving: the course
// animated 1/60 s a frame; still: the same frame again).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "bench.h"
#include "cli_options.h"
#include "gl/check.h"
#include "measure/effect_truth.h"
#include "measure/metrics.h"
#include "plan/options.h"
#include "scene/scene_source.h"

namespace fs = std::filesystem;

namespace penumbra::tools::bench {

namespace {

// Each effect alone, and all three: what the table compares with "none". Then the --post passes
// (plan/post.h) under the first technique: their cost, not scored (they change the image, and
// shadow-blur's error against the area-light truth is in bench --soft).
struct EffectSet {
    const char* effects;
    const char* post;
};
constexpr EffectSet kEffectSets[] = {{"none", "none"},    {"outline", "none"},         {"mirror", "none"},
                                     {"portal", "none"},  {"outline,mirror,portal", "none"}, {"none", "blur:4"},
                                     {"none", "blur:12"}, {"none", "bloom:0.6"},       {"none", "shadow-blur:6"}};

// The bytes of the post passes' targets in a plan (plan/post.cpp's and plan.cpp's names).
std::size_t post_bytes(const render::FramePlan& plan) {
    std::size_t b = 0;
    for (const render::PlannedResource& r : plan.resources) {
        const std::string& n = r.desc.name;
        if (n.rfind("post-", 0) == 0 || n.rfind("bloom-", 0) == 0 || n.rfind("shadow-blur", 0) == 0 ||
            n == "shadow-visibility")
            b += r.desc.bytes();
    }
    return b;
}

bool has(const std::string& list, const char* effect) {
    std::string padded = "," + list + ",";
    return padded.find("," + std::string(effect) + ",") != std::string::npos;
}

}  // namespace

// The first course frame of --scenes: the one at t 0.6 if there is one (the pictures' frame).
const SceneSpec* course_frame(Sweep& w, const std::string& measured) {
    const SceneSpec* first = nullptr;
    for (const SceneSpec& s : w.scenes) {
        if (s.name != "teapot") continue;
        if (!first) first = &s;
        if (std::abs(s.time - 0.6) < 1e-9) return &s;
    }
    if (!first) w.notes.push_back(measured + " measured on the course scene (teapot@T in --scenes): none was listed");
    return first;
}

void time_course_rows(const Sweep& w, render::Renderer& r, const render::FrameInputs& in, scene::SceneSource& src,
                      const scene::Scene& still, double time, std::vector<PendingRow>& pending, std::vector<Row>& out,
                      const char* what) {
    const BenchOptions& o = w.o;
    const auto moving_at = [&](int i) -> const scene::Scene& { return src.at(time + static_cast<double>(i + 1) / 60.0); };
    const auto still_at = [&](int) -> const scene::Scene& { return still; };
    for (int round = 0; round < o.rounds; ++round) {
        r.load(still);
        for (PendingRow& p : pending) {
            const Timing moving = time_frames(r, p.s, in, 2, o.frames, moving_at);
            const Timing still_t = time_frames(r, p.s, in, 1, o.frames, still_at);
            p.moving.push_back(moving.median_ms);
            p.still.push_back(still_t.median_ms);
            p.gpu.add(moving, still_t);
        }
        gl::check_errors(what);
    }
    for (PendingRow& p : pending) {
        Row& row = p.row;
        row.ms_moving = measure::median(p.moving);
        row.ms_still = measure::median(p.still);
        row.ms_camera = row.ms_still;
        row.ms_shadow = row.map ? std::max(0.0, row.ms_moving - row.ms_still) : 0.0;
        row.frames = o.frames * o.rounds;
        p.gpu.set(row);
        out.push_back(row);
    }
}

void effects_sweep(Sweep& w, render::Renderer& r, const render::FrameInputs& in) {
    const BenchOptions& o = w.o;
    const SceneSpec* spec = course_frame(w, "the stencil effects are");
    if (!spec) return;
    w.effects_frame = spec->label;
    const auto t0 = Clock::now();
    scene::SceneSource src = open_scene(spec->name, scene::Eye::Scene, o.allow_outside);
    const scene::Scene still = src.at(spec->time);
    r.load(still);

    std::vector<Planned> techniques;
    {
        render::Settings s = w.base.settings;
        techniques.push_back({s, technique_label(s)});
        s.technique = render::technique_named("volumes");
        s.volume_method = render::VolumeMethod::Auto;
        if (techniques.front().label != technique_label(s)) techniques.push_back({s, technique_label(s)});
    }

    // One truth per (mirror, portal) pair; hard (the error columns).
    const measure::TruthOptions to = frame_truth_options(still, w.width, w.height);
    std::map<std::pair<bool, bool>, measure::EffectTruth> truths;
    const fs::path images = fs::path(o.out_dir) / "images";
    const auto truth_of = [&](bool mirror, bool portal) -> const measure::EffectTruth& {
        const auto key = std::make_pair(mirror, portal);
        auto it = truths.find(key);
        if (it != truths.end()) return it->second;
        const auto tt = Clock::now();
        it = truths.emplace(key, measure::trace_effects(still, mirror, portal, to)).first;
        const measure::EffectTruth& t = it->second;
        std::fprintf(stderr, "truth %s%s%s: hard in %.1f s (%s; mirror %zu px, opening %zu px)\n", spec->label.c_str(),
                     mirror ? " mirror" : "", portal ? " portal" : "", seconds_since(tt), class_summary(t.image).c_str(),
                     t.mirror_pixels, t.opening_pixels);
        if (mirror || portal) {
            prepare_output_dir("--out-dir", images.string());  // created, or exit status 2 with the reason
            write_or_throw((images / (spec->label + "-truth" + (mirror ? "-mirror" : "") + (portal ? "-portal" : "") + ".png")).string(),
                           classes_image(t.image));
        }
        return t;
    };

    std::vector<PendingRow> pending;
    for (const Planned& planned : techniques)
        for (const EffectSet& set : kEffectSets) {
            const char* effects = set.effects;
            const bool post = std::string(set.post) != "none";
            if (post && planned.label != techniques.front().label) continue;
            render::Settings s = planned.settings;
            if (const std::string err = render::parse_option(s, "effects", effects); !err.empty()) throw CommandError{err, 1};
            if (const std::string err = render::parse_option(s, "post", set.post); !err.empty()) throw CommandError{err, 1};
            Row row;
            row.section = kEffectsSection;
            row.scene = spec->label;
            row.time = spec->time;
            set_technique(row, s, planned.label);
            row.effects = effects;
            row.post = set.post;
            row.settings = row_args(w.base, *spec, s);
            if (const std::string problem = r.check(still, s, in); !problem.empty()) {
                w.notes.push_back(spec->label + ": " + row.technique + " --effects " + effects + " skipped: " + problem);
                continue;
            }
            if (post) {
                const render::FramePlan plan = r.plan(still, s, in);
                row.bytes = post_bytes(plan);
                if (const render::PlannedResource* m = plan.resource("shadow-map")) row.bytes += m->desc.bytes();
                std::fprintf(stderr, "post    %-12s %-14s %-22s (timed, not scored)\n", spec->label.c_str(),
                             row.technique.c_str(), set.post);
                pending.push_back({row, s, {}, {}, {}});
                continue;
            }
            const bool mirror = has(effects, "mirror"), portal = has(effects, "portal");
            const measure::EffectTruth& truth = truth_of(mirror, portal);
            s.aov = render::Aov::Visibility;  // the outline is not drawn there: the frame under it is scored
            const render::FramePlan& plan = r.render(still, s, in);
            const render::PlannedResource* m = plan.resource("shadow-map");
            row.bytes = m ? m->desc.bytes() : 0;
            if (const render::PlannedResource* pm = plan.resource("portal shadow-map")) row.bytes += pm->desc.bytes();
            const auto vis = red_channel(r.read_image());
            const auto valid = truth.image.valid_mask();
            row.score = measure::score(vis, truth.image.lit, valid);
            std::vector<std::uint8_t> in_region(valid.size());
            for (size_t i = 0; i < valid.size(); ++i) in_region[i] = valid[i] && truth.region[i];
            row.region = measure::score(vis, truth.image.lit, in_region);
            row.not_modelled = truth.image.count(measure::PixelClass::NotModelled);
            if (planned.label == techniques.front().label && (mirror || portal)) {
                std::string name = spec->label + "-" + row.technique + "-" + effects + "-errors.png";
                std::replace(name.begin(), name.end(), ' ', '-');
                std::replace(name.begin(), name.end(), ',', '-');
                write_or_throw((images / name).string(), error_image(vis, truth.image));
            }
            std::fprintf(stderr, "effects %-12s %-14s %-22s error %6.2f %% (in the effects' pixels %6.2f %% of %zu)\n",
                         spec->label.c_str(), row.technique.c_str(), effects, row.score.error_pct, row.region.error_pct,
                         row.region.valid);
            s.aov = render::Aov::Color;  // time the frame a user sees
            pending.push_back({row, s, {}, {}, {}});
        }
    gl::check_errors("the effects' accuracy pass");

    time_course_rows(w, r, in, src, still, spec->time, pending, w.effects, "the effects' timing pass");
    std::fprintf(stderr, "effects: %zu sets x %zu techniques on %s in %s\n", std::size(kEffectSets), techniques.size(),
                 spec->label.c_str(), duration_str(seconds_since(t0)).c_str());
}

}  // namespace penumbra::tools::bench
