// W09P2b: the scene rendered into a framebuffer object (or into the window and copied out with
// glCopyTexImage2D: rtt=copy), and that texture on the ground quad.
#include "common.h"
#include "scene/primitives.h"

namespace penumbra::examples::exercises {

namespace {

constexpr float kTableSize = 4.0f;  // the course scene's table top (scenes/course_scene.cpp)
constexpr const char* kFboTexture = "w09p2b";
constexpr std::string_view kQuad = "table (W09P2b)", kMaterial = "off-screen buffer";

// The ground: the table quad again with uvs 0..1, so the FBO's picture lies on the table once, and
// a white material whose texture (a 1x1 placeholder) the FBO's texture replaces.
void extend_course(scene::Scene& s) {
    scene::Mesh quad = scene::make_quad(kTableSize, 1.0f);
    quad.name = std::string(kQuad);
    // GL stores a rendered texture bottom row first: flip v so the picture stands upright to the
    // camera, its top towards the back of the table.
    for (auto& uv : quad.uvs) uv.y = 1.0f - uv.y;
    s.meshes.push_back(std::move(quad));
    const int image = static_cast<int>(s.images.size());
    s.images.push_back(scene::Image{1, 1, {255, 255, 255, 255}});
    scene::Material m;
    m.name = std::string(kMaterial);
    m.base_color = glm::vec4(1.0f);
    m.base_color_texture = image;
    m.specular = 0.1f;
    m.shininess = 16.0f;
    s.materials.push_back(m);
}

template <typename T>
int index_of(const std::vector<T>& v, std::string_view name) {
    for (size_t i = 0; i < v.size(); ++i)
        if (v[i].name == name) return static_cast<int>(i);
    return -1;
}

// 1. The scene into a texture (the ground with its marble), 2. the scene from the camera with that
// texture where the table's material has its placeholder.
void draw(Host& host, render::Settings s, render::FrameInputs in) {
    s.aov = render::Aov::Color;
    const Toggles& toggles = host.toggles();
    int size = std::clamp(host.settings().fixed_map_size(), 1, host.gl_caps().max_target_size());
    if (toggles.rtt_copy) {
        // glCopyTexImage2D copies what the window holds: the texture is no larger than the
        // window. The largest power of two that fits (WebGL 1 repeats only those).
        const int fit = std::min(host.width(), host.height());
        if (size > fit) {
            int p = 1;
            while (p * 2 <= fit) p *= 2;
            host.note_frame("rtt=copy: the texture is copied from the window, so it can be no larger than the "
                            "window's " + std::to_string(fit) + " pixels: " + std::to_string(p) + "x" +
                            std::to_string(p) + " instead of " + std::to_string(size) + "x" + std::to_string(size));
            size = p;
        }
    }
    const bool pot = (size & (size - 1)) == 0;  // WebGL 1 repeats only power-of-two textures
    const gl::Wrap wrap = pot ? gl::Wrap::Repeat : gl::Wrap::Clamp;
    const render::Output texture =
        toggles.rtt_copy ? render::Output::copied_texture(kFboTexture, size, size, gl::Sampling::Linear, wrap)
                         : render::Output::texture(kFboTexture, size, size, gl::Sampling::Linear, wrap);
    render::Output into_output = texture;
    if (toggles.rtt_copy) {  // drawn in the window's corner, copied, then drawn over
        into_output = render::Output::window_region(0, 0, size, size);
        into_output.copy_to = kFboTexture;
        into_output.sampling = texture.sampling;
        into_output.wrap = texture.wrap;
    }
    render::FrameInputs into;
    if (toggles.fbo_light) into = host.light_view(into_output, false, in.output);
    else into.output = into_output;
    host.render(s, into, "texture");
    const scene::CourseScene& course = host.course();
    const int material = index_of(course.scene.materials, kMaterial);
    in.objects.push_back({course.table, index_of(course.scene.meshes, kQuad), material});
    in.images.push_back({course.scene.materials[static_cast<size_t>(material)].base_color_texture, texture});
    host.render(s, in);
}

}  // namespace

Exercise w09p2b() {
    const Control light = light_toggle(), jump = jump_toggle();
    Exercise x{"w09p2b", "W09P2b: Drawing to an off-screen buffer",
         "Each frame the scene is first rendered into a framebuffer object (a colour texture with a depth "
         "renderbuffer), then drawn from the camera with that texture applied to the ground quad.",
         "The scene rendered into a framebuffer object, and that texture applied to the ground quad.",
         "The scene with the off-screen buffer's picture on the ground quad",
         "The table shows what the off-screen buffer holds; set its texture size to 256 and the picture turns "
         "blocky.",
         {light, jump, {"fbo-view", "Off-screen buffer", K::Select},
          {"rtt", "Off-screen buffer", K::Radio, {}, {}, "a copy is no larger than the window"},
          {"map-size", "Off-screen buffer", K::Select, {"256", "512", "1024", "2048"}, "Texture size"}},
         {{"map-size", "1024"}}};  // the buffer's size: nothing here to match to the screen
    x.frame = {{"technique", "none"}};
    x.extend_course = extend_course;
    x.draw = draw;
    x.modules = {};  // no shadows: the module every page has
    return x;
}

}  // namespace penumbra::examples::exercises
