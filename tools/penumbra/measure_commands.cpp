#include "measure_commands.h"

#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "cli_options.h"
#include "measure.h"
#include "plan/options.h"
#include "scene/memory_budget.h"

namespace penumbra::tools {

namespace {

// The measuring commands' own numbers, checked as the option table checks its own.
render::OptionInfo soft_samples_info() {
    render::OptionInfo o = render::make_option_info("soft-samples", render::OptionPart::Job, render::OptionType::Integer,
                                                    "area-light samples per pixel", "Area-light samples");
    o.min = 0;
    o.max = render::kMaxSoftSamples;
    return o;
}

render::OptionInfo truth_light_radius_info() {
    render::OptionInfo o = render::option_info("light-radius");
    o.type = render::OptionType::Number;  // a number only: no 'scene' here (leaving it out is the scene's)
    o.choices.clear();
    return o;
}

render::OptionInfo rounds_info() {
    render::OptionInfo o = render::make_option_info("rounds", render::OptionPart::Job, render::OptionType::Integer,
                                                    "interleaved timing rounds", "Rounds");
    o.min = 1;
    o.max = 100;
    return o;
}

std::string bounds(const render::OptionInfo& o) { return "[" + render::accepted_values(o) + "]"; }

}  // namespace

struct MeasureCommands {
    CLI::App* export_cmd = nullptr;
    CLI::App* truth_cmd = nullptr;
    CLI::App* bench_cmd = nullptr;
    ExportOptions export_options;
    TruthCommandOptions truth_options;
    BenchOptions bench_options;
};

std::shared_ptr<MeasureCommands> add_measure_commands(CLI::App& app) {
    auto m = std::make_shared<MeasureCommands>();

    m->export_cmd = app.add_subcommand("export", "write the scene at time t as one glTF 2.0 file (buffers and textures embedded)");
    auto& e = m->export_options;
    m->export_cmd->add_option("--scene", e.scene, "teapot (the course scene) or FILE.gltf / FILE.glb");
    m->export_cmd->add_option("--time", e.time, "seconds " + bounds(render::option_info("time")) + " (default 0)");
    m->export_cmd->add_option("--size", e.size, "WxH whose aspect the camera gets when the scene leaves it to the viewport " +
                                                    bounds(render::option_info("size")) + " (default 512x512)");
    m->export_cmd->add_option("--out", e.out, "FILE.gltf")->required();
    add_allow_outside(m->export_cmd, e.allow_outside);

#ifdef PENUMBRA_HAVE_TRUTH
    m->truth_cmd = app.add_subcommand("truth", "ray-trace the ground truth of one frame (Embree): visibility, validity mask, classes");
    auto& t = m->truth_options;
    m->truth_cmd->add_option("--scene", t.scene, "teapot or FILE.gltf / FILE.glb");
    m->truth_cmd->add_option("--time", t.time, "seconds " + bounds(render::option_info("time")) + " (default 0)");
    m->truth_cmd->add_option("--eye", t.eye, "scene or in-shadow, as the renderer's --eye (default scene)");
    m->truth_cmd->add_option("--blend-shadows", t.blend_shadows,
                             "on: glTF BLEND objects block light, cut at their alphaCutoff, as the renderer's "
                             "--blend-shadows on [off, on] (default off)");
    m->truth_cmd->add_option("--size", t.size, "WxH, as the renderer's --size " + bounds(render::option_info("size")) +
                                                   " (default 512x512)");
    m->truth_cmd->add_option("--out-dir", t.out_dir, "folder for the PNGs (default out/truth)");
    m->truth_cmd->add_option("--soft-samples", t.soft_samples,
                             "also an area light, this many samples per pixel " + bounds(soft_samples_info()) +
                                 " (default 0: none)");
    m->truth_cmd->add_option("--light-radius", t.light_radius,
                             "area light radius: world units (point, spot) or radians (directional) " +
                                 bounds(truth_light_radius_info()) + "; default the scene light's "
                             "(glTF extras penumbra.radius), else 1% of the scene's size (the bench's)");
    add_allow_outside(m->truth_cmd, t.allow_outside);
    m->truth_cmd->add_option("--score", t.score, "a visibility PNG of the same frame and size to score against the truth");
    m->truth_cmd->add_flag("--json", t.json,
                           "with --score: print one JSON object (scene, time, width, height and one key per score column, "
                           "null where absent) on stdout instead of the prose lines");
    m->truth_cmd->add_flag("--score-columns", t.score_columns,
                           "print the score columns (key, heading, digits, meaning, ...) as JSON and trace nothing");

    m->bench_cmd = app.add_subcommand("bench", "the sweep: error against the ray-traced truth, ms/frame and memory of every technique");
    auto& b = m->bench_options;
    m->bench_cmd->add_flag("--quick", b.quick, "small and fast (CI): 128x128, 5 frames, maps 256 and 1024, two scenes");
    m->bench_cmd->add_option("--out-dir", b.out_dir, "folder for results.csv, results.md, tradeoff.svg/.png (default results/bench; with --quick "
                             "out/bench-quick, so a quick run never overwrites the committed figures)");
    m->bench_cmd->add_option("--size", b.size, "WxH of the frames " + bounds(render::option_info("size")) + " (default 512x512)");
    m->bench_cmd->add_option("--frames", b.frames, "timed frames per run, each finished with glFinish " +
                                                       bounds(render::option_info("frames")) + " (default 20)");
    m->bench_cmd->add_option("--rounds", b.rounds, "interleaved timing rounds; the median of their medians is reported " +
                                                       bounds(rounds_info()) + " (default 3)");
    m->bench_cmd->add_option("--scenes", b.scenes, "teapot@T or FILE.gltf, comma separated")->delimiter(',');
    add_allow_outside(m->bench_cmd, b.allow_outside);
    m->bench_cmd->add_option("--maps", b.maps, "shadow map sizes, comma separated (default 256,512,1024,2048,4096)")->delimiter(',');
    m->bench_cmd->add_option("--encodings", b.encodings, "comma separated (default r8,rgba,depthtex)")->delimiter(',');
    m->bench_cmd->add_option("--filters", b.filters, "comma separated (default hard,pcf2x2,pcf4x4)")->delimiter(',');
    m->bench_cmd->add_option("--set", b.set, "any render option as name=value for every run, e.g. --set bias=auto");
    m->bench_cmd->add_option("--from-csv", b.from_csv,
                             "measure nothing: rebuild results.md and the plots from this CSV's rows (ours, or others' "
                             "with the same columns, e.g. three.js runs scored by penumbra truth --score)");
    m->bench_cmd->add_option("--soft-samples", b.soft_samples,
                             "area-light samples per pixel for the soft truth " + bounds(soft_samples_info()) +
                                 " (default 64, 0: none; with --soft 512, quick 256)");
    m->bench_cmd->add_flag("--soft", b.soft,
                           "the soft-shadow bench instead: hard, PCF, PCSS, Heckbert-Herf (and Gooch) against the area-light "
                           "truth at several light sizes -> soft.csv, soft.md, soft.svg/.png (docs/soft.md)");
    m->bench_cmd->add_option("--radii", b.radii,
                             "with --soft: light radii as fractions of the scene's size, comma separated (default "
                             "0.02,0.05,0.15; quick 0.15)")->delimiter(',');
    m->bench_cmd->add_flag("--cascades", b.cascades,
                           "cascaded shadow maps against one map instead, on --scenes FILE.gltf (default "
                           "tests/data/terrain_km.gltf): error by band of view depth, ms/frame of a pan, shimmer against "
                           "the truth's -> cascades.csv, cascades.md, cascades.svg/.png (docs/cascades.md)");
    m->bench_cmd->add_flag("--scale", b.scale,
                           "the cost against the object count instead: piled and spread scenes of 1,000, 10,000 and "
                           "100,000 objects under a point, a spot and a sun light, plan and frame time and heap at the "
                           "defaults and with no shadows -> scale.csv, scale.md, scale.svg/.png (docs/scale.md)");
    m->bench_cmd->add_flag("--truth-noise", b.truth_noise,
                           "only the area-light truth's own noise: mean |soft(N) - soft(4N)| on the course scene, N = 64, "
                           "256, 1024 -> soft_truth_noise.csv (part of a full --soft run too)");
#endif
    return m;
}

int run_measure_commands(MeasureCommands& m) {
    try {
        // The numbers as typed (CLI11 reads "nan" and "inf" as doubles, -5 as an int), before any work.
        if (m.export_cmd && *m.export_cmd) {
            check_given(*m.export_cmd, render::option_info("time"));
            run_export(m.export_options);
            return 0;
        }
#ifdef PENUMBRA_HAVE_TRUTH  // truth and bench exist only with the Embree ground truth
        if (m.truth_cmd && *m.truth_cmd) {
            check_given(*m.truth_cmd, render::option_info("time"));
            check_given(*m.truth_cmd, soft_samples_info());
            check_given(*m.truth_cmd, truth_light_radius_info());
            run_truth(m.truth_options);
            return 0;
        }
        if (m.bench_cmd && *m.bench_cmd) {
            check_given(*m.bench_cmd, render::option_info("frames"));
            check_given(*m.bench_cmd, rounds_info());
            check_given(*m.bench_cmd, soft_samples_info());
            // A quick run's timings mean nothing: unless told otherwise it stays out of the committed results/.
            if (m.bench_options.quick && m.bench_cmd->count("--out-dir") == 0) m.bench_options.out_dir = "out/bench-quick";
            run_bench(m.bench_options);
            return 0;
        }
#endif
    } catch (const CommandError& e) {
        std::fprintf(stderr, "penumbra: error: %s\n", one_line(e.message).c_str());
        return e.code;
    } catch (const memory::OverBudget& e) {
        std::fprintf(stderr, "penumbra: error: %s\n", e.what());
        return 2;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "penumbra: error: out of memory\n");
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "penumbra: error: %s\n", one_line(e.what()).c_str());
        return 1;
    }
    return -1;
}

}  // namespace penumbra::tools
