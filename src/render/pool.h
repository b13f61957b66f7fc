// The render targets the plans declare, made from their descriptions (plan/plan.h): one per
// name, kept while each new plan declares it unchanged, made again when its description changes,
// freed as soon as a plan no longer declares it. N maps (cascades, cube faces, area-light samples)
// are N descriptions: no member of the renderer changes for them.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "gl/device.h"
#include "gl/objects.h"
#include "plan/plan.h"

namespace penumbra::render {

class ResourcePool {
public:
    ResourcePool();
    ~ResourcePool();
    ResourcePool(const ResourcePool&) = delete;
    ResourcePool& operator=(const ResourcePool&) = delete;

    // Makes the plan's resources exist as described, and frees every other one.
    void prepare(const FramePlan& plan);
    // Where a pass of `plan` draws (a resource's framebuffer, or the window's).
    gl::Target target(const FramePlan& plan, const TargetRef& ref) const;
    // The whole of a resource's framebuffer (for reading it back); a cube's face `face` (0..5).
    gl::Target whole(const std::string& name, int face = 0) const;
    // The texture a pass samples: the colour texture, or the depth texture of a depth-only target.
    // `attachment`: which colour texture of a target with several (ResourceDesc::colors).
    const gl::Texture& texture(const std::string& name, int attachment = 0) const;
    // A resource's colour texture filled from the bound framebuffer's region (x, y, width, height)
    // by glCopyTexImage2D, RGB (a window may have no alpha to copy). The caller's Device must
    // forget its texture bindings (the copy binds it).
    void copy_into(const std::string& name, int x, int y, int width, int height);
    bool has(const std::string& name) const { return entries_.count(name) > 0; }
    std::size_t count() const { return entries_.size(); }
    std::size_t bytes() const;  // the GPU memory of every resource held
    void clear();

private:
    struct Entry;
    static std::unique_ptr<Entry> make(const ResourceDesc& desc);
    const Entry& entry(const std::string& name) const;
    std::map<std::string, std::unique_ptr<Entry>> entries_;
};

}  // namespace penumbra::render
