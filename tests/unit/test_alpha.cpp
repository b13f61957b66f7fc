// glTF alphaMode / alphaCutoff / doubleSided: what the loader reads (tests/data/alpha_cutouts.gltf,
// made by make_alpha_gltf.py), what the validator refuses (named by the JSON path), what the
// writer writes back, the CPU alpha sampler the truth uses, and what the plan makes of each mode
// (alpha-tested variants in every caster pass, BLEND objects last, back to front, casting only
// under --blend-shadows).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "full_caps.h"
#include "gl/caps.h"
#include "plan/options.h"
#include "plan/plan.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_writer.h"
#include "../test_paths.h"

using namespace penumbra;
using scene::AlphaMode;
namespace fs = std::filesystem;

namespace {

const std::string kScene = test::test_data_dir() + "/alpha_cutouts.gltf";

scene::Scene load() {
    const scene::LoadResult r = scene::load_gltf(kScene);
    EXPECT_TRUE(r.ok) << r.error;
    return r.scene;
}

const scene::Material& material(const scene::Scene& s, const std::string& object) {
    for (const auto& o : s.objects)
        if (o.name == object) return s.materials.at(static_cast<size_t>(o.material));
    ADD_FAILURE() << "no object " << object;
    static const scene::Material none;
    return none;
}

TEST(Alpha, TheLoaderReadsModeCutoffAndDoubleSided) {
    const scene::Scene s = load();
    EXPECT_EQ(material(s, "ground").alpha_mode, AlphaMode::Opaque);
    EXPECT_FALSE(material(s, "ground").double_sided);
    const scene::Material& fence = material(s, "fence");
    EXPECT_EQ(fence.alpha_mode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(fence.alpha_cutoff, 0.5f);
    EXPECT_GE(fence.base_color_texture, 0);
    EXPECT_FALSE(fence.double_sided);
    const scene::Material& leaves = material(s, "leaves");
    EXPECT_EQ(leaves.alpha_mode, AlphaMode::Mask);
    EXPECT_TRUE(leaves.double_sided);
    const scene::Material& pane = material(s, "pane");
    EXPECT_EQ(pane.alpha_mode, AlphaMode::Blend);
    EXPECT_FLOAT_EQ(pane.base_color.a, 0.6f);
    EXPECT_FLOAT_EQ(pane.alpha_cutoff, 0.5f);  // glTF's default
    // The fence's texture has alpha: slats 255, gaps 0 (texel column 5..7 of each 8).
    const scene::Image& img = s.images.at(static_cast<size_t>(fence.base_color_texture));
    ASSERT_EQ(img.width, 32);
    EXPECT_EQ(img.rgba[(20 * 32 + 2) * 4 + 3], 255);
    EXPECT_EQ(img.rgba[(20 * 32 + 6) * 4 + 3], 0);
}

// The test scene with the fence's material (materials[1]) replaced by `material_json`.
std::string load_error(const std::string& material_json) {
    std::ifstream f(kScene);
    nlohmann::json doc = nlohmann::json::parse(f);
    // nlohmann cannot hold 1e400 (the loader's own scan must refuse it): put it in as text.
    std::string m = material_json;
    const size_t big = m.find("1e400");
    if (big != std::string::npos) m.replace(big, 5, "987654321");
    doc["materials"][1] = nlohmann::json::parse(m);
    std::string text = doc.dump();
    if (big != std::string::npos) text.replace(text.find("987654321"), 9, "1e400");
    const scene::LoadResult r = scene::load_gltf_memory(
        "m.gltf", reinterpret_cast<const unsigned char*>(text.data()), text.size(), test::test_data_dir());
    return r.ok ? "" : r.error;
}

TEST(Alpha, TheValidatorNamesABadModeOrCutoffByItsPath) {
    EXPECT_EQ(load_error(R"({"alphaMode":"MASK","alphaCutoff":0.25,"doubleSided":true})"), "");
    EXPECT_EQ(load_error(R"({"alphaMode":"BLEND"})"), "");
    EXPECT_EQ(load_error(R"({"alphaCutoff":0})"), "");
    EXPECT_EQ(load_error(R"({"alphaCutoff":1})"), "");
    const struct {
        const char* json;
        const char* says;
    } bad[] = {
        {R"({"alphaMode":"CLIP"})", "materials[1].alphaMode is 'CLIP': expected OPAQUE, MASK or BLEND"},
        {R"({"alphaMode":"mask"})", "materials[1].alphaMode is 'mask'"},
        {R"({"alphaMode":3})", "materials[1].alphaMode is 3"},
        {R"({"alphaCutoff":1.5})", "materials[1].alphaCutoff is 1.5: outside 0..1"},
        {R"({"alphaCutoff":-0.1})", "materials[1].alphaCutoff is -0.1: outside 0..1"},
        {R"({"alphaCutoff":1e400})", "1e400"},  // refused by the JSON parser already
        {R"({"alphaCutoff":"half"})", "materials[1].alphaCutoff is not a number"},
        {R"({"doubleSided":1})", "materials[1].doubleSided is not a boolean"},
    };
    for (const auto& b : bad) {
        const std::string e = load_error(b.json);
        EXPECT_NE(e.find(b.says), std::string::npos) << b.json << " -> '" << e << "'";
    }
}

TEST(Alpha, TheWriterWritesThemSoTheSceneLoadsBackTheSame) {
    scene::Scene s = load();
    // A cutoff other than the default, so the round trip is seen to carry it.
    for (auto& m : s.materials)
        if (m.alpha_mode == AlphaMode::Mask) m.alpha_cutoff = 0.375f;
    const std::string path =
        (fs::temp_directory_path() / ("penumbra_alpha_" + std::to_string(::getpid()) + ".gltf")).string();
    ASSERT_EQ(scene::write_gltf(path, s), "");
    const scene::LoadResult r = scene::load_gltf(path);
    fs::remove(path);
    ASSERT_TRUE(r.ok) << r.error;
    for (const char* name : {"ground", "fence", "leaves", "pane"}) {
        const scene::Material& a = material(s, name);
        const scene::Material& b = material(r.scene, name);
        EXPECT_EQ(a.alpha_mode, b.alpha_mode) << name;
        EXPECT_EQ(a.double_sided, b.double_sided) << name;
        EXPECT_FLOAT_EQ(a.base_color.a, b.base_color.a) << name;
        if (a.alpha_mode == AlphaMode::Mask) {
            EXPECT_FLOAT_EQ(b.alpha_cutoff, 0.375f) << name;
        }
        EXPECT_EQ(a.base_color_texture >= 0, b.base_color_texture >= 0) << name;
    }
    // The texture's alpha survives (the writer embeds the image).
    const scene::Material& fence = material(r.scene, "fence");
    const scene::Image& img = r.scene.images.at(static_cast<size_t>(fence.base_color_texture));
    EXPECT_EQ(img.rgba[(20 * 32 + 6) * 4 + 3], 0);
    EXPECT_EQ(img.rgba[(20 * 32 + 2) * 4 + 3], 255);
    // A cutoff glTF cannot hold is refused by name.
    s.materials[1].alpha_mode = AlphaMode::Mask;
    s.materials[1].alpha_cutoff = 2.0f;
    std::string error;
    EXPECT_EQ(scene::to_gltf(s, {}, error), "");
    EXPECT_NE(error.find("alpha cutoff"), std::string::npos) << error;
}

TEST(Alpha, SampleAlphaIsBilinearAtTexelCentresAsGlSamples) {
    scene::Image img;
    img.width = 2;
    img.height = 1;
    img.rgba = {0, 0, 0, 0, 0, 0, 0, 255};  // alpha 0 then 1
    // Texel centres read the texel; halfway between them, the mean.
    EXPECT_FLOAT_EQ(scene::sample_alpha(img, {0.25f, 0.5f}, false), 0.0f);
    EXPECT_FLOAT_EQ(scene::sample_alpha(img, {0.75f, 0.5f}, false), 1.0f);
    EXPECT_FLOAT_EQ(scene::sample_alpha(img, {0.5f, 0.5f}, false), 0.5f);
    EXPECT_FLOAT_EQ(scene::sample_alpha(img, {0.375f, 0.5f}, false), 0.25f);
    // At the border: clamp keeps the edge texel, repeat blends with the far side.
    EXPECT_FLOAT_EQ(scene::sample_alpha(img, {0.0f, 0.5f}, false), 0.0f);
    EXPECT_FLOAT_EQ(scene::sample_alpha(img, {0.0f, 0.5f}, true), 0.5f);
    EXPECT_FLOAT_EQ(scene::sample_alpha(img, {1.25f, 0.5f}, true), 0.0f);
    EXPECT_FLOAT_EQ(scene::sample_alpha(scene::Image{}, {0.5f, 0.5f}, true), 1.0f);
    EXPECT_TRUE(scene::repeats(img));
    img.width = 3;
    EXPECT_FALSE(scene::repeats(img));
}

using penumbra::testing::full_caps;

const render::Pass* pass(const render::FramePlan& p, const std::string& name) {
    for (const auto& x : p.passes)
        if (x.name == name) return &x;
    return nullptr;
}

const render::Draw* draw(const render::Pass& p, const std::string& label) {
    for (const auto& d : p.draws)
        if (d.label == label) return &d;
    return nullptr;
}

bool has(const render::Variant& v, const char* define) {
    return std::find(v.defines.begin(), v.defines.end(), define) != v.defines.end();
}

TEST(Alpha, ThePlanAlphaTestsCutOutsInEveryCasterPassAndDrawsBlendLast) {
    const scene::Scene s = load();
    const gl::Caps caps = full_caps();
    const auto all = render::all_variants();
    const auto listed = [&](const render::Variant& v) { return std::find(all.begin(), all.end(), v) != all.end(); };
    for (const char* technique : {"shadowmap", "planar", "gooch", "volumes", "none"})
        for (const char* blend : {"off", "on"})
            for (const char* encoding : {"rgba", "r8", "depthtex"}) {
                render::Settings st;
                ASSERT_EQ(render::parse_option(st, "technique", technique), "");
                ASSERT_EQ(render::parse_option(st, "blend-shadows", blend), "");
                ASSERT_EQ(render::parse_option(st, "encoding", encoding), "");
                st.light_radius = 0.2f;  // Gooch's planes need a light with a size
                // One map: the caster pass checked below by its name (auto gives this scene's point
                // light a cube since issue 56; its faces' passes cut out the same way: tile_pass).
                ASSERT_EQ(render::parse_option(st, "cascades", "1"), "");
                const std::string what = std::string(technique) + " blend-shadows " + blend + " " + encoding;
                const render::FramePlan p = render::plan(s, st, caps, render::offscreen(256, 256));
                // Every variant asked for is one the shader tests compile.
                for (const auto& x : p.passes)
                    for (const auto& d : x.draws) EXPECT_TRUE(listed(d.variant)) << what << ": " << d.variant.key();
                const render::Pass* cam = pass(p, "camera");
                ASSERT_NE(cam, nullptr) << what;
                ASSERT_NE(draw(*cam, "fence"), nullptr);
                EXPECT_TRUE(has(draw(*cam, "fence")->variant, "ALPHA_TEST")) << what;
                ASSERT_NE(draw(*cam, "leaves"), nullptr);
                EXPECT_TRUE(has(draw(*cam, "leaves")->variant, "DOUBLE_SIDED")) << what;
                EXPECT_EQ(draw(*cam, "leaves")->cull, gl::Cull::None) << what;
                // (planar and gooch draw the ground in their own passes)
                if (const render::Draw* g = draw(*cam, "ground")) {
                    EXPECT_FALSE(has(g->variant, "ALPHA_TEST")) << what;
                }
                EXPECT_EQ(draw(*cam, "pane"), nullptr) << what << ": BLEND in the opaque pass";
                // The blend pass comes last, blending, without depth writes.
                ASSERT_FALSE(p.passes.empty());
                const render::Pass& last = p.passes.back();
                EXPECT_EQ(last.name, "camera-blend") << what;
                EXPECT_EQ(last.state.blend, gl::Blend::Alpha);
                EXPECT_FALSE(last.state.depth_write);
                ASSERT_EQ(last.draws.size(), 1u);
                EXPECT_TRUE(has(last.draws[0].variant, "ALPHA_BLEND")) << what;
                // The casters' passes: the cut-outs alpha-tested, BLEND only with the flag.
                const char* caster_pass = std::string(technique) == "shadowmap" ? "shadow-map"
                                          : std::string(technique) == "planar"  ? "planar-stencil"
                                          : std::string(technique) == "gooch"   ? "gooch-stencil"
                                                                                : nullptr;
                if (!caster_pass) continue;
                const render::Pass* cp = pass(p, caster_pass);
                ASSERT_NE(cp, nullptr) << what;
                ASSERT_NE(draw(*cp, "fence"), nullptr) << what;
                EXPECT_TRUE(has(draw(*cp, "fence")->variant, "ALPHA_TEST")) << what;
                EXPECT_TRUE(has(draw(*cp, "fence")->variant, "TEXTURED")) << what;
                EXPECT_TRUE(draw(*cp, "fence")->alpha);
                EXPECT_GE(draw(*cp, "fence")->image, 0);
                ASSERT_NE(draw(*cp, "leaves"), nullptr) << what;
                EXPECT_TRUE(has(draw(*cp, "leaves")->variant, "ALPHA_TEST")) << what;
                if (const render::Draw* g = draw(*cp, "ground")) {
                    EXPECT_FALSE(has(g->variant, "ALPHA_TEST")) << what;
                }
                const render::Draw* pane = draw(*cp, "pane");
                if (std::string(blend) == "on") {
                    ASSERT_NE(pane, nullptr) << what;
                    EXPECT_TRUE(has(pane->variant, "ALPHA_TEST")) << what;
                } else {
                    EXPECT_EQ(pane, nullptr) << what;
                }
            }
}

TEST(Alpha, BlendObjectsAreSortedBackToFront) {
    scene::Scene s = load();
    // Two more translucent panes: one far behind, one near the camera (z grows towards it).
    scene::Object far = s.objects[3], near = s.objects[3];
    ASSERT_EQ(far.name, "pane");
    far.name = "far";
    far.world[3] = glm::vec4(0.0f, 0.0f, -4.0f, 1.0f);
    near.name = "near";
    near.world[3] = glm::vec4(0.0f, 0.0f, 3.0f, 1.0f);
    s.objects.push_back(near);
    s.objects.push_back(far);
    const gl::Caps caps = full_caps();
    const render::FramePlan p = render::plan(s, render::Settings{}, caps, render::offscreen(64, 64));
    const render::Pass& last = p.passes.back();
    ASSERT_EQ(last.draws.size(), 3u);
    EXPECT_EQ(last.draws[0].label, "far");
    EXPECT_EQ(last.draws[1].label, "pane");
    EXPECT_EQ(last.draws[2].label, "near");
    EXPECT_NE(last.detail.find("back to front"), std::string::npos) << last.detail;
    // The visibility AOV leaves them out, with a note.
    render::Settings vis;
    vis.aov = render::Aov::Visibility;
    const render::FramePlan pv = render::plan(s, vis, caps, render::offscreen(64, 64));
    EXPECT_EQ(pass(pv, "camera-blend"), nullptr);
    EXPECT_FALSE(pv.notes.empty());
}

TEST(Alpha, VolumesSayTheyCastTheWholeQuad) {
    const scene::Scene s = load();
    render::Settings st;
    st.technique = render::Technique::Volumes;
    const gl::Caps caps = full_caps();
    const render::FramePlan p = render::plan(s, st, caps, render::offscreen(64, 64));
    bool said = false;
    for (const auto& n : p.notes) said = said || n.find("fence, leaves") != std::string::npos;
    EXPECT_TRUE(said);
}

TEST(Alpha, TheOutlineLeavesCutOutsOutWithANote) {
    scene::Scene s = load();
    // An opaque copy of the fence: the only object the outline may take.
    scene::Object solid = s.objects[1];
    ASSERT_EQ(solid.name, "fence");
    solid.name = "solid";
    scene::Material opaque = s.materials[static_cast<size_t>(solid.material)];
    opaque.alpha_mode = scene::AlphaMode::Opaque;
    s.materials.push_back(opaque);
    solid.material = static_cast<int>(s.materials.size()) - 1;
    s.objects.push_back(solid);
    render::Settings st;
    ASSERT_EQ(render::parse_option(st, "effects", "outline"), "");
    ASSERT_EQ(render::parse_option(st, "blend-shadows", "on"), "");  // the pane casts: a cut-out too
    const render::FramePlan p = render::plan(s, st, full_caps(), render::offscreen(64, 64));
    for (const char* name : {"outline-mark", "outline-draw"}) {
        const render::Pass* o = pass(p, name);
        ASSERT_NE(o, nullptr) << name;
        ASSERT_EQ(o->draws.size(), 1u) << name;
        EXPECT_EQ(o->draws[0].label, "solid") << name;
    }
    bool said = false;
    for (const auto& n : p.notes) said = said || n.find("fence, leaves, pane are not outlined") != std::string::npos;
    EXPECT_TRUE(said);
}

}  // namespace
