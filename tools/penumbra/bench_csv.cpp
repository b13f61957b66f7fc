// penumbra bench's results.csv: written from a sweep's rows (to_csv) and read back (read_csv,
// --from-csv: this bench's files and others' with the same columns, e.g. three.js runs).
#include <fstream>
#include <string>
#include <vector>

#include "bench.h"
#include "cli_options.h"
#include "measure/score_columns.h"

namespace penumbra::tools::bench {

// One row per scene frame and technique; the score's columns are the score table's
// (measure/score_columns.h), between the frame's and the time's.
std::string to_csv(const Sweep& w) {
    std::ostringstream o;
    o << "scene,time,width,height,technique,encoding,filter,map_size," << measure::score_csv_header()
      << ",ms_moving,ms_still,ms_shadow_pass,ms_camera_pass,frames,redrawn_moving,redrawn_still,shadow_map_bytes,texel_use_pct,"
         "silhouette_edges,volume_triangles,fill_per_pixel,zpass_casters,zfail_casters,section,segments,"
         "effects,effect_error_pct,effect_false_shadow_pct,effect_false_lit_pct,effect_valid_pixels,not_modelled_pixels,"
         "post,shading,lights,settings,gpu_ms_moving,gpu_ms_still,gpu_ms_per_pass,budget_ms,max_error_pct,predicted_pct,edge_pixels\n";
    std::vector<const Row*> rows;
    for (const Row& r : w.rows) rows.push_back(&r);
    for (const Row& r : w.silhouette) rows.push_back(&r);
    for (const Row& r : w.effects) rows.push_back(&r);
    for (const Row& r : w.lights) rows.push_back(&r);
    for (const Row& r : w.budget) rows.push_back(&r);
    for (const Row& r : w.errors) rows.push_back(&r);
    for (const Row* rp : rows) {
        const Row& r = *rp;
        const bool vol = r.silhouette_edges >= 0;
        o << r.scene << "," << fixed(r.time, 3) << "," << w.width << "," << w.height << "," << r.technique << "," << r.encoding << ","
          << r.filter << "," << r.map << "," << measure::score_csv_cells(r.score) << "," << fixed(r.ms_moving, 3) << ","
          << fixed(r.ms_still, 3) << "," << fixed(r.ms_shadow, 3) << "," << fixed(r.ms_camera, 3) << "," << r.frames << ","
          << r.redrawn_moving << "," << r.redrawn_still << "," << r.bytes << ","
          << (r.texel_use_pct >= 0.0 ? fixed(r.texel_use_pct, 1) : "") << "," << (vol ? std::to_string(r.silhouette_edges) : "") << ","
          << (vol ? std::to_string(r.volume_triangles) : "") << "," << (vol ? fixed(r.fill_per_pixel, 3) : "") << ","
          << (vol ? std::to_string(r.zpass_casters) : "") << "," << (vol ? std::to_string(r.zfail_casters) : "") << ","
          << (r.section.empty() ? "sweep" : r.section) << "," << (r.segments ? std::to_string(r.segments) : "") << ",";
        if (r.section == kEffectsSection) {
            const bool region = r.region.valid > 0;
            o << "\"" << r.effects << "\"," << (region ? fixed(r.region.error_pct, 4) : "") << ","
              << (region ? fixed(r.region.false_shadow_pct, 4) : "") << "," << (region ? fixed(r.region.false_lit_pct, 4) : "")
              << "," << r.region.valid << "," << r.not_modelled << ",\"" << r.post << "\",";
        } else {
            o << ",,,,,,,";
        }
        if (r.section == kLightsSection) o << r.shading << "," << r.lights << ",";
        else o << ",,";
        o << "\"" << r.settings << "\"," << (r.gpu_moving >= 0.0 ? fixed(r.gpu_moving, 3) : "") << ","
          << (r.gpu_still >= 0.0 ? fixed(r.gpu_still, 3) : "") << ",\"" << r.gpu_passes << "\","
          << (r.section == kBudgetSection ? fixed(r.budget_ms, 3) : "") << ",";
        if (r.section == kErrorSection)
            o << fixed(r.max_error, 3) << "," << fixed(r.predicted_pct, 4) << "," << r.edge_pixels << "\n";
        else
            o << ",,\n";
    }
    return o.str();
}

namespace {

// One CSV line into fields (double quotes protect commas; "" is a quote).
std::vector<std::string> csv_fields(const std::string& line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += '"', ++i;
            else if (c == '"') quoted = false;
            else out.back() += c;
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            out.emplace_back();
        } else if (c != '\r') {
            out.back() += c;
        }
    }
    return out;
}

}  // namespace

void read_csv(Sweep& w, const std::string& path) {
    std::ifstream f(path);
    if (!f) throw CommandError{"--from-csv " + path + ": cannot open", 2};
    std::string line;
    if (!std::getline(f, line)) throw CommandError{"--from-csv " + path + ": empty file", 2};
    const auto header = csv_fields(line);
    std::map<std::string, size_t> col;
    for (size_t i = 0; i < header.size(); ++i) col[header[i]] = i;
    std::vector<std::string> needed = {"scene", "time", "width", "height", "technique", "map_size"};
    for (const auto& key : measure::missing_required_columns([&](std::string_view k) { return col.count(std::string(k)) > 0; }))
        needed.push_back(key);
    needed.insert(needed.end(), {"ms_moving", "ms_still"});
    for (const auto& need : needed)
        if (!col.count(need)) throw CommandError{"--from-csv " + path + ": no column '" + need + "'", 2};
    size_t line_no = 1;
    std::vector<std::string> labels;
    std::set<int> maps;
    while (std::getline(f, line)) {
        ++line_no;
        if (line.empty()) continue;
        const auto v = csv_fields(line);
        const auto get = [&](const char* name) -> std::string {
            const auto it = col.find(name);
            return it != col.end() && it->second < v.size() ? v[it->second] : std::string();
        };
        const auto num = [&](const char* name, double fallback) {
            const std::string t = get(name);
            if (t.empty()) return fallback;
            char* end = nullptr;
            const double d = std::strtod(t.c_str(), &end);
            if (end != t.c_str() + t.size())
                throw CommandError{"--from-csv " + path + ":" + std::to_string(line_no) + ": " + name + " '" + t + "' is not a number", 2};
            return d;
        };
        Row r;
        r.scene = get("scene");
        r.time = num("time", 0.0);
        w.width = static_cast<int>(num("width", w.width));
        w.height = static_cast<int>(num("height", w.height));
        r.technique = get("technique");
        r.encoding = get("encoding");
        r.filter = get("filter");
        r.map = static_cast<int>(num("map_size", 0));
        r.settings = get("settings");
        try {
            r.score = measure::score_from_cells([&](std::string_view key) -> std::optional<std::string> {
                const auto it = col.find(std::string(key));
                if (it == col.end()) return std::nullopt;
                return it->second < v.size() ? v[it->second] : std::string();
            });
        } catch (const std::invalid_argument& e) {
            throw CommandError{"--from-csv " + path + ":" + std::to_string(line_no) + ": " + e.what(), 2};
        }
        r.ms_moving = num("ms_moving", 0);
        r.ms_still = num("ms_still", 0);
        r.ms_shadow = num("ms_shadow_pass", std::max(0.0, r.ms_moving - r.ms_still));
        r.ms_camera = num("ms_camera_pass", r.ms_still);
        r.frames = static_cast<int>(num("frames", 0));
        r.redrawn_moving = static_cast<int>(num("redrawn_moving", 0));
        r.redrawn_still = static_cast<int>(num("redrawn_still", 0));
        r.bytes = static_cast<std::size_t>(num("shadow_map_bytes", 0));
        r.texel_use_pct = num("texel_use_pct", -1.0);
        r.silhouette_edges = static_cast<int>(num("silhouette_edges", -1));
        r.volume_triangles = static_cast<int>(num("volume_triangles", 0));
        r.fill_per_pixel = num("fill_per_pixel", 0.0);
        r.zpass_casters = static_cast<int>(num("zpass_casters", 0));
        r.zfail_casters = static_cast<int>(num("zfail_casters", 0));
        r.segments = static_cast<int>(num("segments", 0));
        r.gpu_moving = num("gpu_ms_moving", -1.0);
        r.gpu_still = num("gpu_ms_still", -1.0);
        r.gpu_passes = get("gpu_ms_per_pass");
        if (get("section") == kSilhouetteSection) {
            r.section = kSilhouetteSection;
            w.silhouette.push_back(r);
            continue;
        }
        if (get("section") == kLightsSection) {
            r.section = kLightsSection;
            r.shading = get("shading");
            r.lights = static_cast<int>(num("lights", 0));
            w.lights.push_back(r);
            continue;
        }
        if (get("section") == kBudgetSection) {
            r.section = kBudgetSection;
            r.budget_ms = num("budget_ms", 0.0);
            w.budget.push_back(r);
            continue;
        }
        if (get("section") == kErrorSection) {
            r.section = kErrorSection;
            r.max_error = num("max_error_pct", 0.0);
            r.predicted_pct = num("predicted_pct", -1.0);
            r.edge_pixels = static_cast<long>(num("edge_pixels", -1.0));
            w.errors.push_back(r);
            continue;
        }
        if (get("section") == kEffectsSection) {
            r.section = kEffectsSection;
            r.effects = get("effects");
            r.region.valid = static_cast<std::size_t>(num("effect_valid_pixels", 0));
            r.region.error_pct = num("effect_error_pct", 0.0);
            r.region.false_shadow_pct = num("effect_false_shadow_pct", 0.0);
            r.region.false_lit_pct = num("effect_false_lit_pct", 0.0);
            r.not_modelled = static_cast<std::size_t>(num("not_modelled_pixels", 0));
            r.post = get("post");
            w.effects_frame = r.scene;
            w.effects.push_back(r);
            continue;
        }
        if (r.scene.empty() || r.technique.empty())
            throw CommandError{"--from-csv " + path + ":" + std::to_string(line_no) + ": no scene or technique", 2};
        if (std::find(labels.begin(), labels.end(), r.scene) == labels.end()) labels.push_back(r.scene);
        if (r.map > 0) maps.insert(r.map);
        w.rows.push_back(r);
    }
    if (w.rows.empty()) throw CommandError{"--from-csv " + path + ": no rows", 2};
    w.scenes.clear();
    for (const auto& l : labels) w.scenes.push_back({l, 0.0, l});
    w.o.maps.assign(maps.begin(), maps.end());
    if (w.o.maps.empty()) w.o.maps = {0};
}

}  // namespace penumbra::tools::bench
