// The shadow map's projection (render/shadow_projection.hpp): the scene's sphere inside the
// map, the light's near and far around it, and a texel's width from the cone's angle.
#include "render/shadow_projection.hpp"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

using namespace animator;

namespace {
glm::dvec3 to_map(const ShadowProjection &p, const glm::dvec3 &world) {
    const glm::dvec4 q = p.world_to_map * glm::dvec4(world, 1.0);
    return glm::dvec3(q) / q.w;
}
} // namespace

TEST_CASE("shadow projection: a light outside the scene's sphere sees all of it, in 0..1") {
    const glm::dvec3 light(4.0, 9.0, -3.0), centre(1.0, 0.5, 2.0);
    const double radius = 2.5;
    const ShadowProjection p = shadow_projection(light, centre, radius, 1024);
    CHECK(p.holds_scene);
    const glm::dvec3 c = to_map(p, centre);
    CHECK(c.x == Approx(0.5).margin(1e-9));
    CHECK(c.y == Approx(0.5).margin(1e-9));
    // Points on the sphere in every direction land inside the map, depth inside 0..1, and nearer
    // points of a ray from the light get smaller depths.
    for (int i = 0; i < 200; ++i) {
        const double a = i * 2.399963, z = 1.0 - 2.0 * (i + 0.5) / 200.0; // a Fibonacci sphere
        const glm::dvec3 dir(std::cos(a) * std::sqrt(1 - z * z), z,
                             std::sin(a) * std::sqrt(1 - z * z));
        const glm::dvec3 m = to_map(p, centre + radius * dir);
        CAPTURE(i, m.x, m.y, m.z);
        CHECK((m.x > 0.0 && m.x < 1.0 && m.y > 0.0 && m.y < 1.0 && m.z > 0.0 && m.z < 1.0));
    }
    const glm::dvec3 way = glm::normalize(centre - light);
    CHECK(to_map(p, centre - way).z < to_map(p, centre).z);
    // A texel at distance 1: the map's width there over its size, 2 tan(half angle) / size, with
    // sin(half angle) = r / d (and the 2% margin the fit keeps).
    const double half = std::asin(radius / glm::length(centre - light)) * 1.02;
    CHECK(p.texel_per_distance == Approx(2.0 * std::tan(half) / 1024).epsilon(1e-9));
}

TEST_CASE("shadow projection: a light inside the scene's sphere covers a cone about its centre") {
    const ShadowProjection p = shadow_projection({0.0, 3.0, 0.0}, {0.0, 0.0, 0.0}, 8.0, 512);
    CHECK_FALSE(p.holds_scene);
    // Straight towards the centre: the middle of the map; 60 degrees off the axis: its edge.
    CHECK(to_map(p, {0.0, 0.0, 0.0}).x == Approx(0.5).margin(1e-9));
    const double edge = 3.0 * std::tan(glm::radians(kWidestShadowDegrees / 2.0));
    const glm::dvec3 at_edge = to_map(p, {edge, 0.0, 0.0});
    CHECK(std::min(std::abs(at_edge.x - 0.5), std::abs(at_edge.y - 0.5)) ==
          Approx(0.0).margin(1e-9));
    CHECK(std::max(std::abs(at_edge.x - 0.5), std::abs(at_edge.y - 0.5)) ==
          Approx(0.5).margin(1e-9));
}
