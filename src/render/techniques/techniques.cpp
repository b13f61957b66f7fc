// The technique modules by Technique value, the module of no shadows, and the content key.
#include <cstdio>

#include "render/techniques/technique.h"

namespace penumbra::render {

const Module& shadow_map_module();  // shadow_map.cpp
const Module& planar_module();      // planar.cpp
const Module& volumes_module();     // volumes.cpp
const Module& gooch_module();       // gooch.cpp
const Module& outline_module();     // outline.cpp
const Module& mirror_module();      // mirror.cpp
const Module& portal_module();      // portal.cpp

namespace {

class NoShadows : public Module {
public:
    std::string_view name() const override { return "none"; }
    void shade(PlanContext&, Pass& cam, std::vector<CameraItem>&) const override { cam.detail += ", no shadows"; }
};

}  // namespace

const Module& technique_module(Technique t) {
    static const NoShadows none;
    switch (t) {
        case Technique::ShadowMap: return shadow_map_module();
        case Technique::Planar: return planar_module();
        case Technique::Volumes: return volumes_module();
        case Technique::Gooch: return gooch_module();
        case Technique::None: return none;
    }
    return none;
}

const Module& effect_module(Effect e) {
    switch (e) {
        case Effect::Outline: return outline_module();
        case Effect::Mirror: return mirror_module();
        case Effect::Portal: return portal_module();
    }
    return outline_module();
}

void ContentKey::add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
        h_ ^= p[i];
        h_ *= 1099511628211ull;
    }
}

std::string ContentKey::str() const {
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h_));
    return buf;
}

}  // namespace penumbra::render
