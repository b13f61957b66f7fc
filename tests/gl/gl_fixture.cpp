#include "gl_fixture.h"

#include <cstdlib>
#include <filesystem>

namespace penumbra::test {

std::vector<std::uint8_t> GlTest::visibility_frame(const scene::Scene& scene, const render::Settings& s, int size,
                                                   const glm::mat4* view, render::FramePlan* plan_out) {
    render::FrameInputs in = render::offscreen(size, size);
    if (view) in.view = *view;
    const auto& plan = renderer->render(scene, s, in);
    if (plan_out) *plan_out = plan;
    const auto rgba = renderer->read_image();
    std::vector<std::uint8_t> v(rgba.size() / 4);
    for (size_t i = 0; i < v.size(); ++i) v[i] = rgba[i * 4];
    gl::check_errors("the visibility frame");
    return v;
}

platform::Platform& context() {
    static std::unique_ptr<platform::Platform> ctx = [] {
        std::string error;
        auto p = platform::create_headless(error);
        if (!p) {
            std::fprintf(stderr, "%s\n", error.c_str());
            std::abort();
        }
        return p;
    }();
    return *ctx;
}

void expect_matches_golden(const std::string& name, const measure::Pixels& actual, const measure::CompareRules& rules) {
    namespace fs = std::filesystem;
    const std::string golden_path = golden_dir() + "/" + name + ".png";
    const fs::path out_dir = fs::path(test_out_dir()) / "golden";
    fs::create_directories(out_dir);
    const std::string actual_path = (out_dir / (name + ".actual.png")).string();
    const std::string diff_path = (out_dir / (name + ".diff.png")).string();
    fs::remove(actual_path);
    fs::remove(diff_path);

    measure::Pixels golden;
    if (!fs::exists(golden_path)) {
        ASSERT_EQ(measure::write_png(actual_path, actual), "");
        FAIL() << "no golden " << golden_path << ": look at " << actual_path
               << ", then approve it with tools/approve_goldens.sh";
    }
    ASSERT_EQ(measure::read_png(golden_path, golden, actual.channels), "");
    ASSERT_EQ(golden.width, actual.width) << golden_path;
    ASSERT_EQ(golden.height, actual.height) << golden_path;
    const measure::ImageComparison c = measure::compare_images(actual, golden, rules);
    ::testing::Test::RecordProperty("golden_" + name, c.summary());
    if (c.passed) return;
    EXPECT_EQ(measure::write_png(actual_path, actual), "");
    EXPECT_EQ(measure::write_png(diff_path, measure::comparison_map(actual, golden, rules)), "");
    ADD_FAILURE() << name << ": " << c.summary() << " (allowed: " << 100.0 * rules.max_off_share << " % off, "
                  << 100.0 * rules.max_unexplained_share << " % unexplained, groups of " << rules.max_cluster
                  << ")\n  actual: " << actual_path << "\n  diff:   " << diff_path
                  << " (grey: off within one pixel of the golden's colour; white: unexplained)"
                  << "\n  look at both; if the change is right, run tools/approve_goldens.sh";
}

std::vector<std::pair<std::string, render::Settings>> every_technique_case() {
    std::vector<std::pair<std::string, render::Settings>> cases;
    for (render::Technique t : render::kAllTechniques) {
        render::Settings s;
        s.technique = t;
        cases.emplace_back(std::string(render::to_string(t)), s);
    }
    render::Settings s;
    s.filter = shadow::Filter::PCSS;
    s.light_radius = 0.2f;
    cases.emplace_back("shadowmap pcss", s);
    s.filter = shadow::Filter::PCF4x4;
    s.encoding = shadow::Encoding::R8;
    s.area_samples = 4;
    cases.emplace_back("shadowmap r8 area-samples 4", s);
    s.encoding = shadow::Encoding::RGBA;
    s.technique = render::Technique::Volumes;
    cases.emplace_back("volumes area-samples 4", s);
    s.technique = render::Technique::Planar;
    cases.emplace_back("planar area-samples 4", s);
    s.area_samples = 1;
    s.technique = render::Technique::Gooch;
    s.gooch_planes = 16;
    cases.emplace_back("gooch planes 16", s);
    s.gooch_method = render::GoochMethod::Texture;
    cases.emplace_back("gooch texture", s);
    s = render::Settings{};
    s.technique = render::Technique::Volumes;
    s.volume_method = render::VolumeMethod::ZFail;
    s.show_volumes = true;
    cases.emplace_back("volumes zfail shown", s);
    return cases;
}

}  // namespace penumbra::test
