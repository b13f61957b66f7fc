#include "mipmaps_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <sstream>
#include <vector>

#include "cli_options.h"
#include "gl/caps.h"
#include "measure.h"
#include "measure/image_io.h"
#include "platform/platform.h"
#include "render/mipmaps.h"
#include "render/renderer.h"
#include "scene/marble.h"
#include "scene/printable.h"

namespace fs = std::filesystem;

namespace penumbra::tools {

namespace {

constexpr int kMaxSize = 4096;

render::MipImage load_source(const MipmapsOptions& o, bool& normal_map) {
    render::MipImage img;
    normal_map = o.source == "normals";
    if (o.source == "marble" || o.source == "normals") {
        if (const std::string p = render::mip_size_problem(o.size, kMaxSize); !p.empty())
            throw CommandError{"--size: " + p, 2};
        const scene::Image s = o.source == "marble" ? scene::make_marble(o.size) : scene::make_tile_normal_map(o.size);
        img.size = o.size;
        img.rgba = s.rgba;
        return img;
    }
    if (fs::path(o.source).extension() != ".png")
        throw CommandError{"--source: " + scene::printable(o.source) + ": expected marble, normals or a FILE.png", 2};
    measure::Pixels px;
    if (const std::string err = measure::read_png(o.source, px, 4); !err.empty()) throw CommandError{"--source: " + err, 2};
    if (px.width != px.height)
        throw CommandError{"--source: " + scene::printable(o.source) + " is " + std::to_string(px.width) + "x" +
                               std::to_string(px.height) + ": a mip chain here is square",
                           2};
    if (const std::string p = render::mip_size_problem(px.width, kMaxSize); !p.empty())
        throw CommandError{"--source: " + scene::printable(o.source) + ": " + p, 2};
    img.size = px.width;
    img.rgba = px.data;
    return img;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Milliseconds of `build` followed by glFinish, the median of `repeat` runs.
double time_ms(render::Renderer& r, int repeat, const std::function<void()>& build) {
    std::vector<double> ms;
    for (int i = 0; i < repeat; ++i) {
        const auto start = std::chrono::steady_clock::now();
        build();
        r.finish();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    return median(ms);
}

std::string fixed(double v, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

void write_level(const std::string& dir, const std::string& name, const render::MipImage& level) {
    const std::string err = measure::write_png((fs::path(dir) / name).string(), measure::from_rgba(level.rgba, level.size, level.size, 4));
    if (!err.empty()) throw CommandError{err, 2};
}

}  // namespace

CLI::App* add_mipmaps_command(CLI::App& app, MipmapsOptions& o) {
    auto* cmd = app.add_subcommand(
        "mipmaps", "render a texture's mip chain level by level on the GPU; compare with glGenerateMipmap and the CPU");
    cmd->add_option("--source", o.source, "marble, normals (a tiled normal map) or FILE.png, square, a power of two (default normals)");
    cmd->add_option("--size", o.size, "the built-in sources' size, a power of two 1..4096 (default 256)");
    cmd->add_option("--filter", o.filter, "box, normal (renormalised normals) or auto: normal for the normal map (default auto)")
        ->check(CLI::IsMember({"box", "normal", "auto"}));
    cmd->add_option("--path", o.path,
                    "levels (render into each level: OES_fbo_render_mipmap), textures (WebGL 1's way: a texture per "
                    "level, copied into the level) or auto (default auto)")
        ->check(CLI::IsMember({"levels", "textures", "auto"}));
    cmd->add_option("--out-dir", o.out_dir, "folder for the levels' PNGs, index.html and mipmaps.csv (default out/mipmaps)");
    cmd->add_option("--repeat", o.repeat, "timed builds of each kind, the median printed (default 9)")->check(CLI::Range(1, 1000));
    return cmd;
}

int run_mipmaps(const MipmapsOptions& o) {
    bool normal_map = false;
    const render::MipImage level0 = load_source(o, normal_map);
    const render::MipFilter filter = o.filter == "normal" || (o.filter == "auto" && normal_map) ? render::MipFilter::Normal
                                                                                                 : render::MipFilter::Box;
    const render::MipPath asked = o.path == "levels"     ? render::MipPath::Levels
                                  : o.path == "textures" ? render::MipPath::Textures
                                                         : render::MipPath::Auto;
    std::string error;
    auto ctx = platform::create_headless(error);
    if (!ctx) throw CommandError{error};
    render::Renderer r(gl::probe_caps(*ctx));
    if (level0.size > r.caps().max_texture_size)
        throw CommandError{"--source: " + render::mip_size_problem(level0.size, r.caps().max_texture_size), 2};
    const render::MipPathChoice choice = render::choose_mip_path(r.caps(), asked);
    if (!choice.problem.empty()) throw CommandError{choice.problem, 2};
    prepare_output_dir("--out-dir", o.out_dir);

    const std::string source_name = o.source == "marble" || o.source == "normals" ? o.source : scene::printable(o.source);
    const int levels = render::mip_level_count(level0.size);
    std::printf("penumbra mipmaps: %s, %dx%d, %d levels, filter %s\npath: %s (%s)\n", source_name.c_str(), level0.size,
                level0.size, levels, render::to_string(filter).c_str(), render::to_string(choice.path).c_str(),
                choice.reason.c_str());

    // The chains: rendered along the chosen path, glGenerateMipmap, the CPU's.
    render::GpuMipChain rendered(r, level0), generated(r, level0);
    rendered.render(filter, choice.path);
    const std::vector<render::MipImage> got = rendered.read(choice.path);
    generated.generate();
    const std::vector<render::MipImage> gen = generated.read(choice.path);
    const std::vector<render::MipImage> cpu = render::cpu_mip_chain(level0, filter);

    // The other path where this context has both: the same bytes?
    std::string other_line;
    const render::MipPath other = choice.path == render::MipPath::Levels ? render::MipPath::Textures : render::MipPath::Levels;
    const bool both = r.caps().render_mipmap;
    double other_ms = 0.0;
    if (both) {
        render::GpuMipChain second(r, level0);
        second.render(filter, other);
        const std::vector<render::MipImage> got2 = second.read(other);
        int worst = 0;
        for (int l = 0; l < levels; ++l) worst = std::max(worst, render::mip_diff(got[size_t(l)], got2[size_t(l)]).max);
        other_line = "path " + render::to_string(other) + ": " +
                     (worst == 0 ? "the same bytes on every level" : "differs by up to " + std::to_string(worst) + " levels");
        other_ms = time_ms(r, o.repeat, [&] { second.render(filter, other); });
    }
    const double rendered_ms = time_ms(r, o.repeat, [&] { rendered.render(filter, choice.path); });
    const double generated_ms = time_ms(r, o.repeat, [&] { generated.generate(); });

    // The table: each level against the CPU's; the step (this level against the CPU filter of the
    // rendered level above: the filter alone, without what the levels above carried down).
    std::ostringstream table, csv;
    csv << "level,size,rendered_vs_cpu_max,rendered_vs_cpu_mean,step_max,generated_vs_cpu_max,generated_vs_cpu_mean,"
           "rendered_normal_length,generated_normal_length,cpu_normal_length\n";
    table << "level  size   rendered-CPU max/mean   step max   glGenerateMipmap-CPU max/mean"
          << (normal_map || filter == render::MipFilter::Normal ? "   normal length: rendered / generated / CPU" : "") << "\n";
    int worst_rendered = 0, worst_step = 0;
    for (int l = 0; l < levels; ++l) {
        const size_t i = static_cast<size_t>(l);
        const render::MipDiff dr = render::mip_diff(got[i], cpu[i]), dg = render::mip_diff(gen[i], cpu[i]);
        const int step = l == 0 ? 0 : render::mip_diff(got[i], render::cpu_mip_down(got[i - 1], filter)).max;
        worst_rendered = std::max(worst_rendered, dr.max);
        worst_step = std::max(worst_step, step);
        const double lr = render::mean_normal_length(got[i]), lg = render::mean_normal_length(gen[i]),
                     lc = render::mean_normal_length(cpu[i]);
        char line[256];
        std::snprintf(line, sizeof line, "%5d  %4d   %3d / %-8s           %3d        %3d / %-8s", l, got[i].size, dr.max,
                      fixed(dr.mean, 4).c_str(), step, dg.max, fixed(dg.mean, 4).c_str());
        table << line;
        if (normal_map || filter == render::MipFilter::Normal)
            table << "            " << fixed(lr, 3) << " / " << fixed(lg, 3) << " / " << fixed(lc, 3);
        table << "\n";
        csv << l << "," << got[i].size << "," << dr.max << "," << fixed(dr.mean, 5) << "," << step << "," << dg.max << ","
            << fixed(dg.mean, 5) << "," << fixed(lr, 5) << "," << fixed(lg, 5) << "," << fixed(lc, 5) << "\n";
        write_level(o.out_dir, "rendered-" + std::to_string(l) + ".png", got[i]);
        write_level(o.out_dir, "generated-" + std::to_string(l) + ".png", gen[i]);
        write_level(o.out_dir, "cpu-" + std::to_string(l) + ".png", cpu[i]);
    }
    std::ostringstream times;
    times << "build, median of " << o.repeat << ", each finished with glFinish: rendered (" << render::to_string(choice.path)
          << ") " << fixed(rendered_ms, 3) << " ms";
    if (both) times << ", rendered (" << render::to_string(other) << ") " << fixed(other_ms, 3) << " ms";
    times << ", glGenerateMipmap " << fixed(generated_ms, 3) << " ms";
    std::printf("%s", table.str().c_str());
    std::printf("rendered against the CPU: within %d level(s) on every level; one step of the filter: within %d\n",
                worst_rendered, worst_step);
    if (!other_line.empty()) std::printf("%s\n", other_line.c_str());
    std::printf("%s\n", times.str().c_str());

    // index.html: the three chains side by side, each level shown at the same width.
    std::ostringstream page;
    page << "<!doctype html><meta charset=\"utf-8\"><title>penumbra mipmaps</title>\n"
            "<style>body{font-family:sans-serif;background:#222;color:#eee}td,th{padding:4px;vertical-align:top;"
            "font-size:12px}img{width:96px;height:96px;image-rendering:pixelated}</style>\n"
         << "<h1>Mipmaps by rendering: " << source_name << ", filter " << render::to_string(filter) << "</h1>\n<p>"
         << r.caps().renderer << "; path " << render::to_string(choice.path) << " (" << choice.reason << ").<br>"
         << times.str() << ".<br>Each level is shown 96 pixels wide; under it, the largest and mean difference from the "
         << "CPU's level (bytes).</p>\n<table><tr><th></th>";
    for (int l = 0; l < levels; ++l) page << "<th>level " << l << "<br>" << got[size_t(l)].size << "&sup2;</th>";
    page << "</tr>\n";
    const struct {
        const char* name;
        const char* label;
        const std::vector<render::MipImage>* chain;
    } rows[] = {{"rendered", "rendered (each level from the one above)", &got},
                {"generated", "glGenerateMipmap", &gen},
                {"cpu", "CPU reference", &cpu}};
    for (const auto& row : rows) {
        page << "<tr><th>" << row.label << "</th>";
        for (int l = 0; l < levels; ++l) {
            const render::MipDiff d = render::mip_diff((*row.chain)[size_t(l)], cpu[size_t(l)]);
            page << "<td><img src=\"" << row.name << "-" << l << ".png\"><br>" << d.max << " / " << fixed(d.mean, 3);
            if (normal_map) page << "<br>|n| " << fixed(render::mean_normal_length((*row.chain)[size_t(l)]), 3);
            page << "</td>";
        }
        page << "</tr>\n";
    }
    page << "</table>\n";
    write_output((fs::path(o.out_dir) / "index.html").string(), page.str());
    write_output((fs::path(o.out_dir) / "mipmaps.csv").string(), csv.str());
    std::printf("wrote %d levels x 3 chains, index.html and mipmaps.csv to %s\n", levels, scene::printable(o.out_dir).c_str());
    return 0;
}

}  // namespace penumbra::tools
