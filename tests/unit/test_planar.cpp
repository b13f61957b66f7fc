// Planar projected shadows (seed 001): the flattening matrix puts every point on the plane, on
// the line from the light through the point, for point and directional lights.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "shadow/planar.h"

using penumbra::shadow::planar_projection;

namespace {

const std::vector<glm::vec3> kAbove = {{0.5f, 1.0f, 0.3f}, {-1.0f, 3.0f, 2.0f}, {3.0f, 0.5f, -2.0f}, {0.0f, 7.5f, 0.0f}};

// M x after the divide; also checks w > 0, so GL keeps the projected triangle.
glm::vec3 project(const glm::mat4& m, const glm::vec3& p) {
    const glm::vec4 s = m * glm::vec4(p, 1.0f);
    EXPECT_GT(s.w, 0.0f) << p.x << " " << p.y << " " << p.z;
    return glm::vec3(s) / s.w;
}

float plane_distance(const glm::vec4& plane, const glm::vec3& p) { return glm::dot(glm::vec3(plane), p) + plane.w; }

}  // namespace

TEST(Planar, PointLightProjectsOntoTheGround) {
    const glm::vec4 ground(0, 1, 0, 0);
    const glm::vec3 light(2.0f, 10.0f, 1.0f);
    const glm::mat4 m = planar_projection(ground, glm::vec4(light, 1.0f));
    for (const auto& p : kAbove) {
        const glm::vec3 s = project(m, p);
        EXPECT_LT(std::fabs(s.y), 1e-4f);
        // Collinear with the light and p, and beyond p as seen from the light.
        const glm::vec3 a = p - light, b = s - light;
        EXPECT_LT(glm::length(glm::cross(glm::normalize(a), glm::normalize(b))), 1e-5f);
        EXPECT_GE(glm::length(b), glm::length(a) - 1e-4f);
        EXPECT_GT(glm::dot(a, b), 0.0f);
    }
}

TEST(Planar, DirectionalLightProjectsAlongTheDirection) {
    const glm::vec4 ground(0, 1, 0, 0);
    const glm::vec3 dir = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));  // where the light travels
    const glm::mat4 m = planar_projection(ground, glm::vec4(-dir, 0.0f));
    for (const auto& p : kAbove) {
        const glm::vec3 s = project(m, p);
        EXPECT_LT(std::fabs(s.y), 1e-4f);
        const glm::vec3 d = s - p;
        EXPECT_LT(glm::length(glm::cross(glm::normalize(d), dir)), 1e-5f);
        EXPECT_GT(glm::dot(d, dir), 0.0f);  // downstream of the point
    }
}

TEST(Planar, PointsOnThePlaneStayPut) {
    const glm::vec4 ground(0, 1, 0, 0);
    for (const glm::vec4 light : {glm::vec4(2, 10, 1, 1), glm::vec4(glm::normalize(glm::vec3(-0.3f, 1, -0.2f)), 0)}) {
        const glm::mat4 m = planar_projection(ground, light);
        for (const glm::vec3 p : {glm::vec3(0.0f), glm::vec3(3, 0, -4), glm::vec3(-7.5f, 0, 2)}) {
            const glm::vec3 s = project(m, p);
            EXPECT_LT(glm::length(s - p), 1e-4f);
        }
    }
}

TEST(Planar, TiltedPlaneAndLightOnTheNegativeSide) {
    const glm::vec3 n = glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f));
    const glm::vec4 plane(n, -1.0f);
    // On the positive side, and (with the plane flipped) the same light on the negative side:
    // the matrix must still give w > 0 for points between the light and the plane.
    const glm::vec3 light = n * 12.0f;
    for (const glm::vec4 pl : {plane, -plane}) {
        const glm::mat4 m = planar_projection(pl, glm::vec4(light, 1.0f));
        for (const auto& q : kAbove) {
            const glm::vec3 p = q + n * 2.0f;  // lift above the tilted plane
            ASSERT_GT(plane_distance(plane, p), 0.0f);
            const glm::vec3 s = project(m, p);
            EXPECT_LT(std::fabs(plane_distance(plane, s)), 1e-4f);
            EXPECT_LT(glm::length(glm::cross(glm::normalize(p - light), glm::normalize(s - light))), 1e-5f);
        }
    }
}
