#include "measure/ray_tracer.h"

#include "scene/hash.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

#include <embree3/rtcore.h>

namespace penumbra::measure {

const char* to_string(PixelClass c) {
    switch (c) {
        case PixelClass::Valid: return "valid";
        case PixelClass::Background: return "background";
        case PixelClass::Silhouette: return "silhouette";
        case PixelClass::NotReceiver: return "not-receiver";
        case PixelClass::FacingAway: return "facing-away";
        case PixelClass::OutsideCone: return "outside-cone";
        case PixelClass::NotModelled: return "not-modelled";
    }
    return "?";
}

std::vector<std::uint8_t> TruthImage::valid_mask() const {
    std::vector<std::uint8_t> m(pixel_class.size());
    for (size_t i = 0; i < m.size(); ++i) m[i] = valid(i) ? 1 : 0;
    return m;
}

std::vector<float> TruthImage::view_depth(const glm::mat4& view) const {
    std::vector<float> d(position.size(), 0.0f);
    for (size_t i = 0; i < d.size(); ++i)
        if (object[i] >= 0) d[i] = -(view * glm::vec4(position[i], 1.0f)).z;
    return d;
}

size_t TruthImage::count(PixelClass c) const {
    return static_cast<size_t>(std::count(pixel_class.begin(), pixel_class.end(), static_cast<std::uint8_t>(c)));
}

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Per-geometry data the rays' filters read: one world-space face normal per triangle, and for an
// alpha-tested material (glTF MASK, or BLEND casting under blend_shadows) what its alpha needs.
struct GeometryData {
    std::vector<glm::vec3> face_normals;  // cross(v1 - v0, v2 - v0), normalised; zero if degenerate
    bool double_sided = false;            // both faces seen (glTF doubleSided)
    bool alpha_test = false;
    float alpha_cutoff = 0.5f;
    float base_alpha = 1.0f;              // the base colour's alpha
    const scene::Image* image = nullptr;  // the base texture (its alpha), or none
    bool repeat = false;                  // how GL wraps it (scene::repeats)
    std::vector<glm::vec2> uvs;           // per vertex, with the image
    std::vector<std::uint32_t> indices;   // three per triangle, with the image

    // Whether the hit at barycentrics (u, v) of triangle `prim` is cut away: alpha below the
    // cutoff, the texture read bilinearly at its base level (scene::sample_alpha).
    bool cut_away(unsigned prim, float u, float v) const {
        if (!alpha_test) return false;
        float alpha = base_alpha;
        if (image) {
            const glm::vec2 uv = (1.0f - u - v) * uvs[indices[3 * prim]] + u * uvs[indices[3 * prim + 1]] +
                                 v * uvs[indices[3 * prim + 2]];
            alpha *= scene::sample_alpha(*image, uv, repeat);
        }
        return alpha < alpha_cutoff;
    }
};

// The renderer's camera pass culls back faces (but of double-sided materials): skip them, so the
// ray finds what the rasteriser shows; and a cut-out's gaps let the ray through.
void camera_filter(const RTCFilterFunctionNArguments* args) {
    const auto* data = static_cast<const GeometryData*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        const glm::vec3 d(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                          RTCRayN_dir_z(args->ray, args->N, i));
        const glm::vec3& n = data->face_normals[prim];
        if (!data->double_sided && !(glm::dot(n, d) < 0.0f)) args->valid[i] = 0;
        else if (data->cut_away(prim, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i)))
            args->valid[i] = 0;
    }
}

// Shadow rays: a cut-out blocks the light only where it is kept.
void shadow_filter(const RTCFilterFunctionNArguments* args) {
    const auto* data = static_cast<const GeometryData*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        if (data->cut_away(RTCHitN_primID(args->hit, args->N, i), RTCHitN_u(args->hit, args->N, i),
                           RTCHitN_v(args->hit, args->N, i)))
            args->valid[i] = 0;
    }
}

// Van der Corput radical inverse in base 2, for the second coordinate of a Hammersley set.
float radical_inverse(std::uint32_t bits) {
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return static_cast<float>(bits) * 2.3283064365386963e-10f;
}


// Shirley-Chiu concentric map of the unit square onto the unit disc (area preserving).
glm::vec2 concentric_disc(float u, float v) {
    const float a = 2.0f * u - 1.0f, b = 2.0f * v - 1.0f;
    if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f};
    constexpr float kQuarterPi = 0.78539816339f;
    if (std::fabs(a) > std::fabs(b)) return a * glm::vec2(std::cos(kQuarterPi * b / a), std::sin(kQuarterPi * b / a));
    return b * glm::vec2(std::sin(kQuarterPi * a / b), std::cos(kQuarterPi * a / b));
}

void orthonormal_basis(const glm::vec3& n, glm::vec3& a, glm::vec3& b) {
    const glm::vec3 h = std::fabs(n.x) > 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    a = glm::normalize(glm::cross(h, n));
    b = glm::cross(n, a);
}

}  // namespace

struct RayTracer::Impl {
    RTCDevice device = nullptr;
    RTCScene visible = nullptr;    // every drawable object: what the camera sees
    RTCScene occluders = nullptr;  // the shadow casters: what blocks the light
    std::vector<std::unique_ptr<GeometryData>> data;  // by object index (null for objects without triangles)
    std::vector<bool> receives;
    scene::Light light;
    float epsilon = 1e-4f;

    ~Impl() {
        if (visible) rtcReleaseScene(visible);
        if (occluders) rtcReleaseScene(occluders);
        if (device) rtcReleaseDevice(device);
    }

    [[noreturn]] void fail(const std::string& what) const {
        const RTCError e = device ? rtcGetDeviceError(device) : RTC_ERROR_UNKNOWN;
        throw std::runtime_error("embree: " + what + " failed (error " + std::to_string(static_cast<int>(e)) + ")");
    }

    RTCGeometry make_geometry(const std::vector<glm::vec3>& world, const std::vector<std::uint32_t>& indices) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        if (!g) fail("rtcNewGeometry");
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), world.size()));
        auto* ix = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                       3 * sizeof(std::uint32_t), indices.size() / 3));
        if (!v || !ix) fail("rtcSetNewGeometryBuffer");
        std::memcpy(v, world.data(), world.size() * sizeof(glm::vec3));
        std::memcpy(ix, indices.data(), indices.size() / 3 * 3 * sizeof(std::uint32_t));
        return g;
    }

    void build(const scene::Scene& s, bool blend_shadows) {
        device = rtcNewDevice(nullptr);
        if (!device) throw std::runtime_error("embree: rtcNewDevice failed");
        visible = rtcNewScene(device);
        occluders = rtcNewScene(device);
        if (!visible || !occluders) fail("rtcNewScene");
        rtcSetSceneBuildQuality(visible, RTC_BUILD_QUALITY_HIGH);
        rtcSetSceneBuildQuality(occluders, RTC_BUILD_QUALITY_HIGH);
        light = s.light;
        const scene::Bounds bounds = scene::scene_bounds(s);
        epsilon = bounds.empty() ? 1e-4f : 1e-4f * std::max(glm::length(bounds.max - bounds.min), 1e-6f);
        data.resize(s.objects.size());
        receives.assign(s.objects.size(), false);
        for (size_t i = 0; i < s.objects.size(); ++i) {
            const scene::Object& o = s.objects[i];
            receives[i] = o.receives_shadow;
            if (o.mesh < 0 || o.mesh >= static_cast<int>(s.meshes.size())) continue;
            const scene::Mesh& m = s.meshes[static_cast<size_t>(o.mesh)];
            if (m.positions.empty() || m.indices.size() < 3) continue;
            std::vector<glm::vec3> world(m.positions.size());
            for (size_t k = 0; k < world.size(); ++k) world[k] = glm::vec3(o.world * glm::vec4(m.positions[k], 1.0f));
            auto d = std::make_unique<GeometryData>();
            const scene::Material* mat = o.material >= 0 && o.material < static_cast<int>(s.materials.size())
                                             ? &s.materials[static_cast<size_t>(o.material)]
                                             : nullptr;
            const scene::AlphaMode mode = mat ? mat->alpha_mode : scene::AlphaMode::Opaque;
            if (mat) {
                d->double_sided = mat->double_sided;
                // BLEND is tested at its cutoff where it casts (blend_shadows), as the GL passes do.
                d->alpha_test = mode != scene::AlphaMode::Opaque;
                d->alpha_cutoff = mat->alpha_cutoff;
                d->base_alpha = mat->base_color.a;
                const int img = mat->base_color_texture;
                if (img >= 0 && img < static_cast<int>(s.images.size()) && m.uvs.size() == m.positions.size()) {
                    d->image = &s.images[static_cast<size_t>(img)];
                    d->repeat = scene::repeats(*d->image);
                    d->uvs = m.uvs;
                    d->indices = m.indices;
                }
            }
            d->face_normals.resize(m.indices.size() / 3);
            for (size_t t = 0; t < d->face_normals.size(); ++t) {
                const glm::vec3 a = world[m.indices[3 * t]], b = world[m.indices[3 * t + 1]], c = world[m.indices[3 * t + 2]];
                const glm::vec3 n = glm::cross(b - a, c - a);
                const float len = glm::length(n);
                d->face_normals[t] = len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0.0f);
            }
            const unsigned id = static_cast<unsigned>(i);
            // BLEND objects are not seen by camera rays (the visibility AOV leaves them out: it shows
            // the opaque surfaces) and cast only with blend_shadows.
            if (mode != scene::AlphaMode::Blend) {
                RTCGeometry g = make_geometry(world, m.indices);
                rtcSetGeometryUserData(g, d.get());
                rtcSetGeometryIntersectFilterFunction(g, camera_filter);
                rtcCommitGeometry(g);
                rtcAttachGeometryByID(visible, g, id);
                rtcReleaseGeometry(g);
            }
            if (o.casts_shadow && (mode != scene::AlphaMode::Blend || blend_shadows)) {
                RTCGeometry c = make_geometry(world, m.indices);
                if (d->alpha_test) {
                    rtcSetGeometryUserData(c, d.get());
                    rtcSetGeometryOccludedFilterFunction(c, shadow_filter);
                }
                rtcCommitGeometry(c);
                rtcAttachGeometryByID(occluders, c, id);
                rtcReleaseGeometry(c);
            }
            data[i] = std::move(d);
        }
        rtcCommitScene(visible);
        rtcCommitScene(occluders);
        if (rtcGetDeviceError(device) != RTC_ERROR_NONE) fail("building the scenes");
    }

    // True when nothing between `origin` and `target` (or along `dir` forever) blocks the light.
    bool unblocked(const glm::vec3& origin, const glm::vec3& dir, float tfar) const {
        // Embree asserts on a ray that is not finite (a direction from tan(radius) near pi/2, say):
        // no light arrives along it.
        if (!std::isfinite(origin.x + origin.y + origin.z) || !std::isfinite(dir.x + dir.y + dir.z) ||
            std::isnan(tfar))
            return false;
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRay ray;
        ray.org_x = origin.x;
        ray.org_y = origin.y;
        ray.org_z = origin.z;
        ray.dir_x = dir.x;
        ray.dir_y = dir.y;
        ray.dir_z = dir.z;
        ray.tnear = 0.0f;
        ray.tfar = tfar;
        ray.time = 0.0f;
        ray.mask = 0xFFFFFFFFu;
        ray.id = 0;
        ray.flags = 0;
        rtcOccluded1(occluders, &ctx, &ray);
        return ray.tfar >= 0.0f;  // set to -inf on a hit
    }

    // unblocked() for a shadow ray leaving the surface at `p` (normal `n`, n . dir > 0). The ray
    // starts off the surface along its own line, `epsilon / n.dir` on (at most 10 x epsilon, where
    // the light grazes), so that it does not hit its own triangle: moved along the normal instead,
    // it would run beside the true ray, and every shadow edge would move by epsilon x cot(the
    // light's elevation), a third of a pixel on bench_hard's ground, where shadow volumes then
    // disagreed with the truth on 0.44 % of the frame (0.003 % with the ray on its line).
    bool unblocked_from_surface(const glm::vec3& p, const glm::vec3& n, const glm::vec3& dir, float tfar) const {
        const float along = epsilon / std::max(glm::dot(n, dir), 0.1f);
        return unblocked(p + along * dir, dir, std::max(tfar - along, 0.0f));
    }

    // Direction to the light from p and how far the shadow ray runs.
    void towards_light(const glm::vec3& p, glm::vec3& dir, float& tfar) const {
        if (light.type == scene::LightType::Directional) {
            dir = -glm::normalize(light.direction);
            tfar = kInf;
        } else {
            const glm::vec3 to = light.position - p;
            const float dist = glm::length(to);
            dir = dist > 0.0f ? to / dist : glm::vec3(0.0f, 1.0f, 0.0f);
            tfar = dist * (1.0f - 1e-5f);
        }
    }

    float soft_visibility(const glm::vec3& p, const glm::vec3& n, const glm::vec3& l, int samples, float radius,
                          std::uint32_t seed) const {
        glm::vec3 a, b;
        orthonormal_basis(l, a, b);
        // Cranley-Patterson rotation per pixel of one Hammersley set: stratified, deterministic.
        const float r1 = static_cast<float>(scene::hash32(seed) & 0xFFFFFFu) / 16777216.0f;
        const float r2 = static_cast<float>(scene::hash32(seed ^ 0x9e3779b9u) & 0xFFFFFFu) / 16777216.0f;
        int open = 0;
        for (int k = 0; k < samples; ++k) {
            float u = (static_cast<float>(k) + 0.5f) / static_cast<float>(samples) + r1;
            float v = radical_inverse(static_cast<std::uint32_t>(k)) + r2;
            u -= std::floor(u);
            v -= std::floor(v);
            const glm::vec2 d = concentric_disc(u, v);
            glm::vec3 dir;
            float tfar;
            if (light.type == scene::LightType::Directional) {
                dir = glm::normalize(l + std::tan(radius) * (d.x * a + d.y * b));
                tfar = kInf;
            } else {
                const glm::vec3 q = light.position + radius * (d.x * a + d.y * b);
                const glm::vec3 to = q - p;
                const float dist = glm::length(to);
                if (!(dist > 0.0f)) continue;
                dir = to / dist;
                tfar = dist * (1.0f - 1e-5f);
            }
            // Light from below the surface's horizon does not reach it.
            if (glm::dot(dir, n) <= 0.0f) continue;
            open += unblocked_from_surface(p, n, dir, tfar) ? 1 : 0;
        }
        return static_cast<float>(open) / static_cast<float>(samples);
    }
};

RayTracer::RayTracer(const scene::Scene& scene, bool blend_shadows) : impl_(std::make_unique<Impl>()) {
    impl_->build(scene, blend_shadows);
}
RayTracer::~RayTracer() = default;

float RayTracer::epsilon() const { return impl_->epsilon; }

TruthImage RayTracer::render(const TruthOptions& opt) const {
    if (opt.width <= 0 || opt.height <= 0) throw std::invalid_argument("truth: image size must be positive");
    const Impl& im = *impl_;
    const size_t w = static_cast<size_t>(opt.width), h = static_cast<size_t>(opt.height), n = w * h;
    TruthImage out;
    out.width = opt.width;
    out.height = opt.height;
    out.lit.assign(n, 0);
    out.pixel_class.assign(n, static_cast<std::uint8_t>(PixelClass::Background));
    out.object.assign(n, -1);
    out.distance.assign(n, 0.0f);
    const bool soft = opt.soft_samples > 0;
    if (soft) out.soft.assign(n, 0.0f);

    // Rays in double: the unprojection of the far plane loses digits in float.
    const glm::dmat4 inv = glm::inverse(glm::dmat4(opt.view_proj));
    out.position.assign(n, glm::vec3(0.0f));
    std::vector<glm::vec3> origin(n), dir(n), normal(n);
    std::vector<glm::vec3>& hit = out.position;
    std::vector<std::uint8_t> facing_away(n, 0), outside_cone(n, 0);

    const auto trace_row = [&](size_t y) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        for (size_t x = 0; x < w; ++x) {
            const size_t i = y * w + x;
            const double nx = (static_cast<double>(x) + 0.5) / static_cast<double>(w) * 2.0 - 1.0;
            const double ny = 1.0 - (static_cast<double>(y) + 0.5) / static_cast<double>(h) * 2.0;
            const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1.0, 1.0);
            const glm::dvec4 b = inv * glm::dvec4(nx, ny, 1.0, 1.0);
            const glm::dvec3 o = glm::dvec3(a) / a.w;
            const glm::dvec3 far = glm::dvec3(b) / b.w;
            double len = glm::length(far - o);
            glm::dvec3 d = (far - o) / len;
            if (!(std::isfinite(len) && len > 0.0)) {
                // A far plane so much farther than the near one (znear 1e-9) that it unprojects to
                // infinity: aim through the middle of the depth range and run the ray to the end.
                const glm::dvec4 m = inv * glm::dvec4(nx, ny, 0.0, 1.0);
                const glm::dvec3 mid = glm::dvec3(m) / m.w - o;
                d = mid / glm::length(mid);
                len = static_cast<double>(kInf);
            }
            origin[i] = glm::vec3(o);
            dir[i] = glm::vec3(d);
            // Embree asserts on a ray that is not finite; such a pixel sees nothing.
            if (!std::isfinite(origin[i].x) || !std::isfinite(origin[i].y) || !std::isfinite(origin[i].z) ||
                !std::isfinite(dir[i].x) || !std::isfinite(dir[i].y) || !std::isfinite(dir[i].z))
                continue;
            RTCRayHit rh;
            rh.ray.org_x = origin[i].x;
            rh.ray.org_y = origin[i].y;
            rh.ray.org_z = origin[i].z;
            rh.ray.dir_x = dir[i].x;
            rh.ray.dir_y = dir[i].y;
            rh.ray.dir_z = dir[i].z;
            rh.ray.tnear = 0.0f;
            rh.ray.tfar = static_cast<float>(len);
            rh.ray.time = 0.0f;
            rh.ray.mask = 0xFFFFFFFFu;
            rh.ray.id = 0;
            rh.ray.flags = 0;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(im.visible, &ctx, &rh);
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
            const auto object = static_cast<std::int32_t>(rh.hit.geomID);
            out.object[i] = object;
            out.distance[i] = rh.ray.tfar;
            out.pixel_class[i] = static_cast<std::uint8_t>(PixelClass::Valid);
            const glm::vec3 p = origin[i] + rh.ray.tfar * dir[i];
            glm::vec3 ng = im.data[static_cast<size_t>(object)]->face_normals[rh.hit.primID];
            if (glm::dot(ng, dir[i]) > 0.0f) ng = -ng;  // towards the camera (back faces are culled anyway)
            hit[i] = p;
            normal[i] = ng;
            glm::vec3 l;
            float tfar;
            im.towards_light(p, l, tfar);
            if (!(glm::dot(ng, l) > 0.0f)) {
                facing_away[i] = 1;
                continue;
            }
            if (im.light.type == scene::LightType::Spot &&
                !(glm::dot(-l, glm::normalize(im.light.direction)) > std::cos(im.light.spot_outer_cone)))
                outside_cone[i] = 1;
            out.lit[i] = im.unblocked_from_surface(p, ng, l, tfar) ? 1 : 0;
            if (soft)
                out.soft[i] = im.soft_visibility(p, ng, l, opt.soft_samples, opt.light_radius,
                                                 static_cast<std::uint32_t>(i));
        }
    };

    const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
    const unsigned threads = opt.threads > 0 ? static_cast<unsigned>(opt.threads) : hw;
    std::atomic<size_t> next{0};
    const auto worker = [&] {
        for (size_t y = next++; y < h; y = next++) trace_row(y);
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();

    // Silhouettes: discontinuous 4-neighbour pairs mark both pixels.
    const auto predicts = [&](size_t p, size_t q) {
        // p's tangent plane intersected with q's camera ray, against the distance q's ray found.
        const float denom = glm::dot(dir[q], normal[p]);
        if (std::fabs(denom) < 1e-7f) return false;
        const float t_pred = glm::dot(hit[p] - origin[q], normal[p]) / denom;
        const float t_q = out.distance[q];
        return std::fabs(t_q - t_pred) <= opt.discontinuity * t_q + im.epsilon;
    };
    const auto discontinuous = [&](size_t p, size_t q) {
        if (out.object[p] != out.object[q]) return true;
        if (out.object[p] < 0) return false;  // both background
        return !predicts(p, q) || !predicts(q, p);
    };
    std::vector<std::uint8_t> band(n, 0);
    for (size_t y = 0; y < h; ++y)
        for (size_t x = 0; x < w; ++x) {
            const size_t i = y * w + x;
            if (x + 1 < w && discontinuous(i, i + 1)) band[i] = band[i + 1] = 1;
            if (y + 1 < h && discontinuous(i, i + w)) band[i] = band[i + w] = 1;
        }
    for (size_t i = 0; i < n; ++i) {
        if (out.object[i] < 0) continue;
        PixelClass c = PixelClass::Valid;
        if (band[i]) c = PixelClass::Silhouette;
        else if (!im.receives[static_cast<size_t>(out.object[i])]) c = PixelClass::NotReceiver;
        else if (facing_away[i]) c = PixelClass::FacingAway;
        else if (outside_cone[i]) c = PixelClass::OutsideCone;
        out.pixel_class[i] = static_cast<std::uint8_t>(c);
    }
    return out;
}

}  // namespace penumbra::measure
