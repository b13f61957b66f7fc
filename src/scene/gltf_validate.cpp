// The validation layer between a glTF file and tinygltf: the JSON is checked before tinygltf
// parses it, because tinygltf trusts it. nlohmann's parser recurses, so the nesting depth is
// measured first with a flat scan; then one walk over the document checks what tinygltf would
// convert blindly (indices and sizes through static_cast<int>, numbers into matrices, cameras and
// lights) and where its uris point. Every failure names the JSON path and the rule.
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string_view>
#include <sys/stat.h>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "scene/gltf_internal.h"
#include "scene/printable.h"

namespace penumbra::scene::gltf_internal {
namespace {

using nlohmann::json;

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// Deepest nesting of [ and { outside strings; stops counting at `limit` + 1.
void check_depth(const char* text, std::size_t size, int limit) {
    int depth = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < size; ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') ++i;
            else if (c == '"') in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > limit)
                fail("the JSON is nested deeper than " + std::to_string(limit) + " levels (at byte " +
                     std::to_string(i) + ")");
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

// glTF properties whose values tinygltf reads as int (indices, counts, enums, byte sizes):
// they must be whole numbers in 0..2^31-1, or tinygltf's conversion is undefined.
const std::unordered_set<std::string_view>& integer_keys() {
    static const std::unordered_set<std::string_view> keys = {
        "scene", "mesh", "camera", "skin", "children", "nodes", "joints", "bufferView", "buffer",
        "byteOffset", "byteLength", "byteStride", "count", "componentType", "indices", "material",
        "mode", "source", "sampler", "index", "texCoord", "light", "width", "height", "target",
        "input", "output", "magFilter", "minFilter", "wrapS", "wrapT", "inverseBindMatrices"};
    return keys;
}

bool whole(const json& v) {
    if (v.is_number_unsigned()) return v.get<std::uint64_t>() <= 0x7FFFFFFFu;
    if (v.is_number_integer()) return v.get<std::int64_t>() >= 0 && v.get<std::int64_t>() <= 0x7FFFFFFF;
    if (v.is_number_float()) {
        const double d = v.get<double>();
        return d >= 0.0 && d <= 2147483647.0 && std::floor(d) == d;
    }
    return true;  // not a number: tinygltf reports the type
}

class Validator {
public:
    Validator(const LoadLimits& limits, const FileAccess& files) : limits_(limits), files_(files) {}

    void run(const json& doc) {
        if (!doc.is_object()) fail("the JSON is not an object");
        check_asset(doc);
        for (auto it = doc.begin(); it != doc.end(); ++it)
            if (it->is_array() && it->size() > limits_.max_elements)
                fail(it.key() + " has " + std::to_string(it->size()) + " entries, over the limit of " +
                     std::to_string(limits_.max_elements));
        walk(doc);
        if (doc.contains("extensions") && doc["extensions"].is_object()) {
            const json& ext = doc["extensions"];
            if (ext.contains("KHR_lights_punctual") && ext["KHR_lights_punctual"].is_object()) {
                const json& k = ext["KHR_lights_punctual"];
                if (k.contains("lights") && k["lights"].is_array()) {
                    lights_ = k["lights"].size();
                    for (std::size_t i = 0; i < k["lights"].size(); ++i) check_light(k["lights"][i], i);
                }
            }
        }
        each(doc, "nodes", [&](const json& n, const std::string& at) { check_node(n, at); });
        each(doc, "cameras", [&](const json& c, const std::string& at) { check_camera(c, at); });
        each(doc, "materials", [&](const json& m, const std::string& at) { check_material(m, at); });
        each(doc, "accessors", [&](const json& a, const std::string& at) { check_accessor(a, at); });
        each(doc, "buffers", [&](const json& b, const std::string& at) { check_uri(b, at); });
        each(doc, "images", [&](const json& b, const std::string& at) { check_uri(b, at); });
    }

private:
    template <typename F>
    static void each(const json& doc, const char* key, F f) {
        if (!doc.contains(key) || !doc[key].is_array()) return;
        const json& arr = doc[key];
        for (std::size_t i = 0; i < arr.size(); ++i)
            if (arr[i].is_object()) f(arr[i], std::string(key) + "[" + std::to_string(i) + "]");
    }

    static void check_asset(const json& doc) {
        if (!doc.contains("asset") || !doc["asset"].is_object()) fail("asset: missing (every glTF file has one)");
        const json& a = doc["asset"];
        if (!a.contains("version") || !a["version"].is_string()) fail("asset.version: missing (expected \"2.0\")");
        const std::string v = a["version"].get<std::string>();
        if (v.size() < 3 || v[0] != '2' || v[1] != '.')
            fail("asset.version is '" + printable(v) + "': only glTF 2.x is read");
        if (a.contains("minVersion") && a["minVersion"].is_string()) {
            const std::string m = a["minVersion"].get<std::string>();
            if (m.size() < 3 || m[0] != '2' || m[1] != '.' || m > "2.0")
                fail("asset.minVersion is '" + printable(m) + "': this reader implements glTF 2.0");
        }
    }

    // Every number finite (1e400 parses as infinity), every integer property a whole number in
    // range. Iterative: the depth is bounded, but the width is not. "extras" is the user's.
    void walk(const json& doc) {
        struct Item {
            const json* v;
            std::string path;
            bool integer;
        };
        std::vector<Item> stack{{&doc, "", false}};
        while (!stack.empty()) {
            Item it = std::move(stack.back());
            stack.pop_back();
            const json& v = *it.v;
            if (v.is_object()) {
                for (auto m = v.begin(); m != v.end(); ++m) {
                    if (m.key() == "extras") continue;
                    const bool integer = integer_keys().count(m.key()) > 0 ||
                                         (it.path.size() >= 10 &&
                                          it.path.compare(it.path.size() - 10, 10, "attributes") == 0);
                    stack.push_back({&*m, it.path.empty() ? m.key() : it.path + "." + m.key(), integer});
                }
            } else if (v.is_array()) {
                for (std::size_t i = 0; i < v.size(); ++i)
                    stack.push_back({&v[i], it.path + "[" + std::to_string(i) + "]", it.integer});
            } else if (v.is_number()) {
                if (v.is_number_float() && !std::isfinite(v.get<double>()))
                    fail(it.path + " is not a finite number");
                if (it.integer && !whole(v))
                    fail(it.path + " is " + v.dump() + ": expected a whole number in 0..2147483647");
            }
        }
    }

    // A number at `at` that becomes a coordinate: |value| <= max_coordinate.
    void coordinates(const json& o, const char* key, const std::string& at) const {
        if (!o.contains(key) || !o[key].is_array()) return;
        const json& a = o[key];
        for (std::size_t i = 0; i < a.size(); ++i)
            if (a[i].is_number() && !(std::fabs(a[i].get<double>()) <= limits_.max_coordinate))
                fail(at + "." + key + "[" + std::to_string(i) + "] is " + num(a[i].get<double>()) +
                     ": over the limit of " + num(limits_.max_coordinate));
    }

    void check_node(const json& n, const std::string& at) const {
        for (const char* key : {"matrix", "translation", "rotation", "scale"}) coordinates(n, key, at);
        if (n.contains("extensions") && n["extensions"].is_object() && n["extensions"].contains("KHR_lights_punctual")) {
            const json& ref = n["extensions"]["KHR_lights_punctual"];
            const std::string where = at + ".extensions.KHR_lights_punctual.light";
            if (!ref.is_object() || !ref.contains("light") || !ref["light"].is_number())
                fail(where + ": missing (expected a light's index)");
            const double l = ref["light"].get<double>();
            if (!(l >= 0.0 && l < static_cast<double>(lights_) && std::floor(l) == l))
                fail(where + " is " + ref["light"].dump() + ": not a light's index" +
                     (lights_ ? " (0.." + std::to_string(lights_ - 1) + ")" : " (the file has no lights)"));
        }
    }

    // A number property that must lie in [lo, hi] when present.
    static void range(const json& o, const char* key, const std::string& at, double lo, double hi) {
        if (!o.contains(key) || !o[key].is_number()) return;
        const double v = o[key].get<double>();
        if (!(v >= lo && v <= hi))
            fail(at + "." + key + " is " + num(v) + ": outside " + num(lo) + ".." + num(hi));
    }

    // alphaMode one of glTF's three (tinygltf keeps any string), alphaCutoff a number in 0..1 (the
    // walk has refused one that is not finite), doubleSided a boolean.
    static void check_material(const json& m, const std::string& at) {
        if (m.contains("alphaMode")) {
            const json& a = m["alphaMode"];
            if (!a.is_string()) fail(at + ".alphaMode is " + a.dump().substr(0, 40) + ": expected \"OPAQUE\", \"MASK\" or \"BLEND\"");
            const std::string v = a.get<std::string>();
            if (v != "OPAQUE" && v != "MASK" && v != "BLEND")
                fail(at + ".alphaMode is '" + printable(v) + "': expected OPAQUE, MASK or BLEND");
        }
        if (m.contains("alphaCutoff") && !m["alphaCutoff"].is_number())
            fail(at + ".alphaCutoff is not a number");
        range(m, "alphaCutoff", at, 0.0, 1.0);
        if (m.contains("doubleSided") && !m["doubleSided"].is_boolean()) fail(at + ".doubleSided is not a boolean");
    }

    void check_camera(const json& c, const std::string& at) const {
        if (!c.contains("perspective") || !c["perspective"].is_object()) return;
        const json& p = c["perspective"];
        const std::string where = at + ".perspective";
        range(p, "znear", where, 1e-9, limits_.max_coordinate);
        range(p, "zfar", where, 1e-9, limits_.max_coordinate);
        range(p, "aspectRatio", where, 1e-3, 1e3);
        range(p, "yfov", where, 0.0, 2.0 * limits_.max_coordinate);  // bad angles get a default and a note
        if (p.contains("znear") && p.contains("zfar") && p["znear"].is_number() && p["zfar"].is_number()) {
            const double n = p["znear"].get<double>(), f = p["zfar"].get<double>();
            if (f / n > 1e10)
                fail(where + ": zfar / znear is " + num(f / n) + ", over the limit of 1e10 (no depth buffer resolves it)");
        }
    }

    void check_light(const json& l, std::size_t i) const {
        if (!l.is_object()) return;
        const std::string at = "extensions.KHR_lights_punctual.lights[" + std::to_string(i) + "]";
        range(l, "intensity", at, 0.0, limits_.max_coordinate);
        range(l, "range", at, 0.0, limits_.max_coordinate);
        if (l.contains("color") && l["color"].is_array())
            for (std::size_t k = 0; k < l["color"].size(); ++k) {
                const json& c = l["color"][k];
                if (c.is_number() && !(c.get<double>() >= 0.0 && c.get<double>() <= 1e6))
                    fail(at + ".color[" + std::to_string(k) + "] is " + num(c.get<double>()) + ": outside 0..1e+06");
            }
    }

    void check_accessor(const json& a, const std::string& at) const {
        if (a.contains("count") && a["count"].is_number() &&
            a["count"].get<double>() > static_cast<double>(limits_.max_vertices))
            fail(at + ".count is " + a["count"].dump() + ": over the limit of " + std::to_string(limits_.max_vertices));
    }

    // A buffer's or an image's uri: a data: URI, or a file inside the scene's folder (or an
    // allowed one) that is a regular file. Whether it exists is tinygltf's to report.
    void check_uri(const json& o, const std::string& at) const {
        if (!o.contains("uri") || !o["uri"].is_string()) return;
        const std::string uri = o["uri"].get<std::string>();
        if (uri.compare(0, 5, "data:") == 0) return;
        const std::string shown = at + ".uri '" + printable(uri) + "'";
        if (uri.find("://") != std::string::npos) fail(shown + ": only relative file names and data: URIs are read");
        const std::string path = decode(uri, shown);
        if (files_.folder().empty()) fail(shown + ": a scene from memory reads no files");
        const std::string full = !path.empty() && path[0] == '/' ? path : files_.folder() + "/" + path;
        struct stat st;
        if (::stat(full.c_str(), &st) != 0) return;  // tinygltf: "File not found"
        if (const std::string problem = files_.check_inside(full); !problem.empty()) fail(shown + " " + problem);
        if (!S_ISREG(st.st_mode)) fail(shown + " is not a regular file");
    }

    // %XX escapes as tinygltf decodes them.
    static std::string decode(const std::string& uri, const std::string& shown) {
        std::string out;
        for (std::size_t i = 0; i < uri.size(); ++i) {
            if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
                std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
                out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
                i += 2;
            } else {
                out += uri[i];
            }
        }
        if (out.find('\0') != std::string::npos) fail(shown + ": a file name cannot hold a NUL byte");
        return out;
    }

    const LoadLimits& limits_;
    const FileAccess& files_;
    std::size_t lights_ = 0;
};

}  // namespace

void validate_json(const char* text, std::size_t size, const LoadLimits& limits, const FileAccess& files) {
    check_depth(text, size, limits.max_json_depth);
    const json doc = json::parse(text, text + size, nullptr, /*allow_exceptions=*/false);
    if (doc.is_discarded()) return;  // not JSON: tinygltf names the syntax error
    Validator(limits, files).run(doc);
}

}  // namespace penumbra::scene::gltf_internal
