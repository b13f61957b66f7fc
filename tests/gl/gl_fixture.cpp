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

ImageDiff compare(const measure::Pixels& a, const measure::Pixels& b) {
    ImageDiff d;
    double sum = 0.0;
    for (size_t i = 0; i < a.data.size(); ++i) {
        const int v = std::abs(int(a.data[i]) - int(b.data[i]));
        d.max = std::max(d.max, v);
        sum += v;
    }
    d.mean = a.data.empty() ? 0.0 : sum / static_cast<double>(a.data.size());
    return d;
}

void expect_matches_golden(const std::string& name, const measure::Pixels& actual, int max_threshold,
                           double mean_threshold) {
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
    const ImageDiff d = compare(actual, golden);
    if (d.max <= max_threshold && d.mean <= mean_threshold) return;

    // The diff image: per pixel the largest channel difference, amplified x4, as grey.
    measure::Pixels diff;
    diff.width = actual.width;
    diff.height = actual.height;
    diff.channels = 1;
    const size_t n = static_cast<size_t>(actual.width) * static_cast<size_t>(actual.height);
    diff.data.resize(n);
    for (size_t p = 0; p < n; ++p) {
        int m = 0;
        for (int c = 0; c < actual.channels; ++c) {
            const size_t i = p * static_cast<size_t>(actual.channels) + static_cast<size_t>(c);
            m = std::max(m, std::abs(int(actual.data[i]) - int(golden.data[i])));
        }
        diff.data[p] = static_cast<std::uint8_t>(std::min(255, m * 4));
    }
    EXPECT_EQ(measure::write_png(actual_path, actual), "");
    EXPECT_EQ(measure::write_png(diff_path, diff), "");
    ADD_FAILURE() << name << ": max difference " << d.max << " (threshold " << max_threshold << "), mean " << d.mean
                  << " (threshold " << mean_threshold << ")\n  actual: " << actual_path << "\n  diff:   " << diff_path
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
