// support_polygon.hpp: whether a centre of mass is over the points a body stands on, seen along
// gravity, against hand-placed cases (a unit cube's corners, its edge, a tilted foot set).
#include "support_polygon.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using physics_custom::over_feet;

TEST_CASE("over_feet: a cube on its face, on an edge, on a corner") {
    const glm::dvec3 down(0, -1, 0);
    // A face: the four bottom corners of a 2 m cube around the origin, shuffled.
    const std::vector<glm::dvec3> face = {{1, -1, 1}, {-1, -1, -1}, {1, -1, -1}, {-1, -1, 1}};
    CHECK(over_feet({0, 0, 0}, face, down, 1e-12));
    CHECK(over_feet({0.999, 0.5, -0.999}, face, down, 1e-12));
    CHECK_FALSE(over_feet({1.001, 0, 0}, face, down, 1e-12));
    CHECK_FALSE(over_feet({0, 0, -1.001}, face, down, 1e-12));
    // On an edge along z: balanced only straight above it, within the slack.
    const std::vector<glm::dvec3> edge = {{0, 0, -1}, {0, 0, 1}};
    CHECK(over_feet({0, std::sqrt(2.0), 0.3}, edge, down, 1e-12));
    CHECK(over_feet({1e-13, std::sqrt(2.0), 0}, edge, down, 1e-12));
    CHECK_FALSE(over_feet({1e-9, std::sqrt(2.0), 0}, edge, down, 1e-12));
    CHECK_FALSE(over_feet({0, std::sqrt(2.0), 1.5}, edge, down, 1e-12)); // past its end
    // On a corner.
    CHECK(over_feet({0, 1.7, 0}, {{0, 0, 0}}, down, 1e-12));
    CHECK_FALSE(over_feet({0.01, 1.7, 0}, {{0, 0, 0}}, down, 1e-12));
    CHECK_FALSE(over_feet({0, 0, 0}, {}, down, 1e-12));
}

TEST_CASE("over_feet: seen along gravity, not along the face's normal") {
    // Feet on a 30 degree slope (a triangle), gravity straight down -y: a centre above the
    // middle of the triangle along y is over it even though it is not along the slope's normal.
    const double s = std::sin(M_PI / 6), c = std::cos(M_PI / 6);
    auto on_slope = [&](double u, double w) { return glm::dvec3(u * c, u * s, w); };
    const std::vector<glm::dvec3> feet = {on_slope(-1, -1), on_slope(1, -1), on_slope(0, 1)};
    CHECK(over_feet({0, 5, 0}, feet, {0, -1, 0}, 1e-12));
    CHECK_FALSE(over_feet({0.9, 5, 0.9}, feet, {0, -1, 0}, 1e-12));
    // Seen along the slope's normal the same centre projects elsewhere: 5 up the normal is
    // 2.5 m across the slope, outside the triangle.
    CHECK_FALSE(over_feet({-5 * s, 5 * c, 0}, feet, {0, -1, 0}, 1e-12));
    CHECK(over_feet({-5 * s, 5 * c, 0}, feet, {s, -c, 0}, 1e-12));
}
