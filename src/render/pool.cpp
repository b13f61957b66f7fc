#include "render/pool.h"

#include <vector>

#include "gl/check.h"

namespace penumbra::render {

struct ResourcePool::Entry {
    ResourceDesc desc;
    gl::Texture color;
    gl::Texture more_colors[gl::kMaxExtraColors];
    gl::Texture depth_texture;
    gl::Renderbuffer depth;
    gl::Framebuffer fb;
    gl::Framebuffer cube_faces[5];  // a cube's faces +x.. -z: fb is face 0's, these 1..5
};

ResourcePool::ResourcePool() = default;
ResourcePool::~ResourcePool() = default;

std::unique_ptr<ResourcePool::Entry> ResourcePool::make(const ResourceDesc& d) {
    auto e = std::make_unique<Entry>();
    e->desc = d;
    const std::string label = d.name;
    gl::TextureDesc td;
    td.width = d.width;
    td.height = d.height;
    td.sampling = d.sampling;
    td.wrap = d.wrap;
    td.label = label.c_str();
    td.cube = d.cube;
    gl::FramebufferDesc fd;
    const std::string fb_label = d.name + " framebuffer";
    fd.label = fb_label.c_str();
    if (d.color) {
        gl::TextureDesc cd = td;
        if (d.half_float) cd.format = gl::TextureFormat::RGBA16F;
        e->color = gl::Texture(cd);
        fd.color = &e->color;
        for (int i = 1; i < d.colors && i <= gl::kMaxExtraColors; ++i) {
            e->more_colors[i - 1] = gl::Texture(cd);
            fd.more_colors[i - 1] = &e->more_colors[i - 1];
        }
    }
    if (d.depth_texture) {
        gl::TextureDesc dd = td;
        dd.format = gl::TextureFormat::Depth;
        e->depth_texture = gl::Texture(dd);
        fd.depth_texture = &e->depth_texture;
    }
    if (d.depth_buffer) {
        const std::string depth_label = d.name + " depth";
        e->depth = gl::Renderbuffer(*d.depth_buffer, d.width, d.height, depth_label.c_str());
        fd.depth = &e->depth;
    }
    e->fb = gl::Framebuffer(fd);
    for (int f = 1; d.cube && f < 6; ++f) {
        fd.color_face = f;
        e->cube_faces[f - 1] = gl::Framebuffer(fd);
    }
    return e;
}

void ResourcePool::prepare(const FramePlan& plan) {
    std::map<std::string, std::unique_ptr<Entry>> kept;
    for (const PlannedResource& r : plan.resources) {
        auto it = entries_.find(r.desc.name);
        if (it != entries_.end() && it->second->desc == r.desc) {
            kept.emplace(r.desc.name, std::move(it->second));
        } else {
            if (it != entries_.end()) it->second.reset();  // free the old one before making its successor
            kept.emplace(r.desc.name, make(r.desc));
        }
    }
    entries_ = std::move(kept);  // what the plan no longer declares is freed here
}

const ResourcePool::Entry& ResourcePool::entry(const std::string& name) const {
    const auto it = entries_.find(name);
    if (it == entries_.end()) throw gl::Error("resource '" + name + "' is not in the pool (no plan declared it)");
    return *it->second;
}

gl::Target ResourcePool::target(const FramePlan& plan, const TargetRef& ref) const {
    const gl::Framebuffer* fb = nullptr;
    if (ref.resource >= 0) {
        const Entry& e = entry(plan.resources[static_cast<size_t>(ref.resource)].desc.name);
        fb = e.desc.cube && ref.face > 0 && ref.face < 6 ? &e.cube_faces[ref.face - 1] : &e.fb;
    }
    return gl::Target{fb, ref.width, ref.height, ref.x, ref.y, ref.clip};
}

gl::Target ResourcePool::whole(const std::string& name, int face) const {
    const Entry& e = entry(name);
    return gl::Target{e.desc.cube && face > 0 && face < 6 ? &e.cube_faces[face - 1] : &e.fb, e.desc.width, e.desc.height};
}

const gl::Texture& ResourcePool::texture(const std::string& name, int attachment) const {
    const Entry& e = entry(name);
    if (attachment > 0 && attachment < e.desc.colors && attachment <= gl::kMaxExtraColors)
        return e.more_colors[attachment - 1];
    return e.desc.color ? e.color : e.depth_texture;
}

void ResourcePool::copy_into(const std::string& name, int x, int y, int width, int height) {
    entry(name);  // throws, naming it, when no plan declared it
    entries_.at(name)->color.copy_framebuffer(0, x, y, width, height, false);
}

void ResourcePool::clear() { entries_.clear(); }

std::size_t ResourcePool::bytes() const {
    std::size_t b = 0;
    for (const auto& [name, e] : entries_) b += e->desc.bytes();
    return b;
}

}  // namespace penumbra::render
