#include "fly_camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "plan/options.h"
#include "scenes/room_scene.h"
#include "scenes/terrain_scene.h"

namespace penumbra::examples {

namespace {

constexpr double kPiD = 3.14159265358979323846;
// Degrees to radians in float: yaw and pitch are floats, and float trigonometry keeps the pages'
// modules free of double-precision sine, cosine and arc tangent (docs/payload.md).
constexpr float kRadPerDeg = static_cast<float>(kPiD / 180.0);
constexpr float kDegPerRad = static_cast<float>(180.0 / kPiD);
constexpr float kMaxPitch = 89.0f;  // the fly camera never looks straight up or down

// Yaw within (-180, 180].
float wrap_degrees(double deg) {
    double d = std::fmod(deg, 360.0);
    if (d > 180.0) d -= 360.0;
    if (d <= -180.0) d += 360.0;
    return static_cast<float>(d);
}

void keep_in(FlyCamera& c, const FlyBounds& b) {
    c.eye.x = std::clamp(c.eye.x, b.keep_min.x, b.keep_max.x);
    c.eye.z = std::clamp(c.eye.z, b.keep_min.z, b.keep_max.z);
    const float lowest = b.ground ? std::max(b.keep_min.y, b.ground(c.eye.x, c.eye.z) + b.above) : b.keep_min.y;
    c.eye.y = std::clamp(c.eye.y, lowest, b.keep_max.y);
    c.pitch = std::clamp(c.pitch, -kMaxPitch, kMaxPitch);
    c.yaw = wrap_degrees(static_cast<double>(c.yaw));
}

FlyBounds make_terrain_bounds() {
    constexpr float kMaxFromCentre = 2000.0f;
    FlyBounds b;
    b.allowed_min = b.keep_min = glm::vec3(-kMaxFromCentre);
    b.allowed_max = b.keep_max = glm::vec3(kMaxFromCentre);
    b.ground = scene::terrain_km_height;
    b.above = 0.3f;  // never under the terrain
    b.step = 2.0;
    b.where = "within 2000 m of the centre";
    return b;
}

FlyBounds make_room_bounds() {
    constexpr float kFromWalls = 0.2f;
    FlyBounds b;
    b.allowed_min = glm::vec3(-scene::kBulbRoomHalfWidth, 0.0f, -scene::kBulbRoomHalfDepth);
    b.allowed_max = glm::vec3(scene::kBulbRoomHalfWidth, scene::kBulbRoomHeight, scene::kBulbRoomHalfDepth);
    b.keep_min = b.allowed_min + glm::vec3(kFromWalls);
    b.keep_max = b.allowed_max - glm::vec3(kFromWalls);
    b.step = 0.25;
    b.where = "inside the room (x -4..4, y 0..3, z -3..3)";
    return b;
}

}  // namespace

const FlyBounds& terrain_fly_bounds() {
    static const FlyBounds b = make_terrain_bounds();
    return b;
}

const FlyBounds& room_fly_bounds() {
    static const FlyBounds b = make_room_bounds();
    return b;
}

glm::vec3 fly_forward(const FlyCamera& c) {
    const float yaw = c.yaw * kRadPerDeg, pitch = c.pitch * kRadPerDeg;
    return glm::vec3(std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch));
}

glm::mat4 fly_view(const FlyCamera& c) {
    return glm::lookAt(c.eye, c.eye + fly_forward(c), glm::vec3(0.0f, 1.0f, 0.0f));
}

FlyCamera fly_from_view(const glm::mat4& view) {
    const glm::mat4 inv = glm::inverse(view);
    const glm::vec3 f = -glm::normalize(glm::vec3(inv[2]));
    FlyCamera c;
    c.eye = glm::vec3(inv[3]);
    c.yaw = wrap_degrees(static_cast<double>(std::atan2(f.x, -f.z) * kDegPerRad));
    c.pitch = std::asin(std::clamp(f.y, -1.0f, 1.0f)) * kDegPerRad;
    return c;
}

bool fly_move(FlyCamera& c, const FlyBounds& b, double forward, double right, double up, double yaw, double pitch) {
    for (const double v : {forward, right, up, yaw, pitch})
        if (!std::isfinite(v)) return false;
    const glm::vec3 f = fly_forward(c);
    const float yaw_rad = c.yaw * kRadPerDeg;
    const glm::vec3 side(std::cos(yaw_rad), 0.0f, std::sin(yaw_rad));
    c.eye += static_cast<float>(forward) * f + static_cast<float>(right) * side + glm::vec3(0.0f, static_cast<float>(up), 0.0f);
    c.yaw = wrap_degrees(static_cast<double>(c.yaw) + yaw);
    c.pitch = static_cast<float>(static_cast<double>(c.pitch) + pitch);
    keep_in(c, b);
    return true;
}

std::string fly_value(const FlyCamera& c) {
    // Millimetres and hundredths of a degree: what a reload needs to show the same frame.
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.3f,%.3f,%.3f,%.2f,%.2f", static_cast<double>(c.eye.x),
                  static_cast<double>(c.eye.y), static_cast<double>(c.eye.z), static_cast<double>(c.yaw),
                  static_cast<double>(c.pitch));
    const std::string v = buf;
    // Trailing zeros off each number ("-60.000" -> "-60").
    std::string out, part;
    const auto flush = [&] {
        if (part.find('.') != std::string::npos) {
            while (!part.empty() && part.back() == '0') part.pop_back();
            if (!part.empty() && part.back() == '.') part.pop_back();
        }
        if (part == "-0") part = "0";
        out += (out.empty() ? "" : ",") + part;
        part.clear();
    };
    for (const char ch : v) {
        if (ch == ',') flush();
        else part += ch;
    }
    flush();
    return out;
}

std::string parse_fly(std::string_view value, const FlyBounds& b, FlyCamera& out) {
    // X,Y,Z,YAW,PITCH: five finite numbers, the eye where the bounds allow, the pitch within +-89 degrees.
    double v[5];
    size_t at = 0;
    const std::string text(value);
    for (int i = 0; i < 5; ++i) {
        const size_t end = i < 4 ? text.find(',', at) : text.size();
        const std::string part = end == std::string::npos ? std::string() : text.substr(at, end - at);
        // Spaces before a number are allowed ("1, 2, 3"), as strtod allowed them.
        const size_t first = part.find_first_not_of(" \t\n\v\f\r");
        if (first == std::string::npos || !render::parse_number(std::string_view(part).substr(first), v[i]) ||
            (i == 4 && end != text.size()))
            return "camera=" + text + ": needs five numbers X,Y,Z,YAW,PITCH (metres, degrees)";
        at = end + 1;
    }
    for (int k = 0; k < 3; ++k)
        if (v[k] < static_cast<double>(b.allowed_min[k]) || v[k] > static_cast<double>(b.allowed_max[k]))
            return "camera=" + text + ": the eye must be " + std::string(b.where);
    if (std::fabs(v[4]) > static_cast<double>(kMaxPitch))
        return "camera=" + text + ": the pitch must be within -89..89 degrees";
    out.eye = glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
    out.yaw = wrap_degrees(v[3]);
    out.pitch = static_cast<float>(v[4]);
    keep_in(out, b);
    return {};
}

bool FlyRig::move(double forward, double right, double up, double yaw, double pitch) {
    if (!fly_move(at, *bounds, forward, right, up, yaw, pitch)) return false;
    moved = true;
    return true;
}

void FlyRig::reset() {
    at = start;
    moved = false;
}

std::string FlyRig::set(std::string_view value) {
    if (std::string err = parse_fly(value, *bounds, at); !err.empty()) return err;
    moved = true;
    return {};
}

}  // namespace penumbra::examples
