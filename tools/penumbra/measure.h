// What the measuring subcommands run (see measure_commands.h for the command line).
#pragma once

#include <string>
#include <vector>

#include "scene/scene_source.h"

namespace penumbra::tools {

// A problem that ends a command with one line on stderr and this exit status.
struct CommandError {
    std::string message;
    int code = 1;
};

// Opens "teapot" or a glTF file, seen from `eye` (--eye); the scene's files may be read under its
// own folder and under `allow_outside` (--allow-outside); the loader's notes go to stderr; a
// failure is a CommandError (exit status 2) naming the file.
scene::SceneSource open_scene(const std::string& name, scene::Eye eye = scene::Eye::Scene,
                              const std::vector<std::string>& allow_outside = {});

struct ExportOptions {
    std::string scene = "teapot";
    double time = 0.0;
    std::string size = "512x512";  // written as the camera's aspect ratio when the scene leaves it to the viewport
    std::string out;
    std::vector<std::string> allow_outside;  // --allow-outside
};
void run_export(const ExportOptions& o);

struct TruthCommandOptions {
    std::string scene = "teapot";
    double time = 0.0;
    std::string size = "512x512";
    std::string eye = "scene";
    std::string blend_shadows = "off";  // on: BLEND objects block light (cut at their cutoff), as render's
    std::string out_dir = "out/truth";
    int soft_samples = 0;
    float light_radius = -1.0f;  // < 0: the bench's default for the scene
    std::string score;           // a visibility PNG (red channel) to compare with the truth
    bool json = false;           // with score: one JSON object on stdout (the score columns' keys)
    bool score_columns = false;  // print the score table as JSON and trace nothing
    std::vector<std::string> allow_outside;  // --allow-outside
};
void run_truth(const TruthCommandOptions& o);

struct BenchOptions {
    bool quick = false;
    std::string out_dir = "results/bench";
    std::string size;                 // default 512x512 (quick 128x128)
    int frames = 0;                   // default 20 (quick 5)
    int rounds = 0;                   // interleaved timing rounds, default 3 (quick 1)
    std::vector<std::string> scenes;  // "teapot@T" or FILE.gltf[@T]; default: the course at four t and three glTF files
    std::vector<int> maps;            // default 256 512 1024 2048 4096 (quick 256 1024)
    std::vector<std::string> encodings, filters;  // default: all
    std::vector<std::string> set;     // extra Settings options as name=value (e.g. bias=auto)
    int soft_samples = -1;            // default 64 (quick 16)
    bool references = true;           // also the techniques none and planar
    std::string from_csv;             // rebuild the table and plots from these rows instead of measuring
    // --soft: the soft-shadow bench instead (soft_bench.cpp): every soft method against the
    // area-light truth at light radii of these fractions of the scene's size (default 0.02 0.05 0.15).
    bool soft = false;
    std::vector<double> radii;
    // --truth-noise: only the area-light truth's own noise, mean |soft(N) - soft(4N)| (soft_bench.cpp).
    bool truth_noise = false;
    // --cascades: cascaded shadow maps against one map on a large scene instead (cascades_bench.cpp).
    bool cascades = false;
    // --scale: plan and frame time and heap against the object count instead (scale_bench.cpp).
    bool scale = false;
    std::vector<std::string> allow_outside;  // --allow-outside: for every scene of --scenes
};
void run_bench(const BenchOptions& o);

}  // namespace penumbra::tools
