// The custom backend's collision mathematics against closed forms (physics.md, "Ground truth").
#include "polynomial.hpp"
#include "response.hpp"
#include "time_of_impact.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>

using namespace physics_custom;

namespace {

const double G = 9.81;
const glm::dvec3 gravity(0.0, -G, 0.0);

// A large triangle in the plane y = 0, facing +Y (counter-clockwise seen from above).
const glm::dvec3 A(-10, 0, -10), B(-10, 0, 10), C(10, 0, 0);

Path falling_from(const glm::dvec3 &p) {
    return Path{p, glm::dvec3(0.0), gravity};
}

} // namespace

TEST_CASE("first contact finds the first crossing of quadratics and quartics") {
    CHECK(*first_contact({4, 0, -1, 0, 0}, 0, 10) == Approx(2.0).epsilon(1e-15)); // 4 - t^2
    // (t - 1)(t - 2)(t - 3)(t - 4) = t^4 - 10 t^3 + 35 t^2 - 50 t + 24: first crossing at 1.
    CHECK(*first_contact({24, -50, 35, -10, 1}, 0, 10) == Approx(1.0).epsilon(1e-15));
    // From 1.5 on, where it is negative, the answer is "already in contact".
    CHECK(*first_contact({24, -50, 35, -10, 1}, 1.5, 10) == 1.5);
    // From 2.5: positive until 3. (Evaluating this expanded quartic near 3 cancels to about
    // 1e-14, which bounds how exactly its root can be known.)
    CHECK(*first_contact({24, -50, 35, -10, 1}, 2.5, 10) == Approx(3.0).epsilon(1e-13));
    // A touch without crossing: (t - 2)^2 = t^2 - 4 t + 4. A double root is known only to about
    // the square root of the rounding error, 1e-8: a grazing contact's time is ill-conditioned.
    CHECK(*first_contact({4, -4, 1, 0, 0}, 0, 10) == Approx(2.0).epsilon(1e-7));
    CHECK_FALSE(first_contact({1, 0, 1, 0, 0}, 0, 10));   // t^2 + 1 never reaches 0
    CHECK_FALSE(first_contact({4, 0, -1, 0, 0}, 0, 1.5)); // the root 2 is past the end
}

TEST_CASE("a ball dropped on a triangle's face lands at t = sqrt(2 (h - r) / G)") {
    for (double h : {0.6, 1.0, 10.0, 1000.0}) {
        const double r = 0.5;
        const auto c = sphere_triangle(falling_from({1, h, 0}), r, A, B, C, 100.0);
        REQUIRE(c);
        CHECK(c->t == Approx(std::sqrt(2.0 * (h - r) / G)).epsilon(1e-13));
        CHECK(c->normal == glm::dvec3(0, 1, 0));
        CHECK(c->point.y == Approx(0.0).margin(1e-12));
    }
}

TEST_CASE("a ball landing on an edge or a corner bounces off the rim") {
    const double r = 0.5, h = 5.0, d = 0.3; // the center passes d beyond the rim
    // The edge from C(10,0,0) to A(-10,0,-10) ... use an axis-aligned triangle instead.
    const glm::dvec3 p0(0, 0, 0), p1(0, 0, 4), p2(4, 0, 0); // the edge x = 0 from p0 to p1
    const auto edge = sphere_triangle(falling_from({-d, h, 2}), r, p0, p1, p2, 100.0);
    REQUIRE(edge);
    // Contact when the center is sqrt(r^2 - d^2) above the edge line.
    const double height = std::sqrt(r * r - d * d);
    CHECK(edge->t == Approx(std::sqrt(2.0 * (h - height) / G)).epsilon(1e-12));
    CHECK(edge->normal.x == Approx(-d / r).epsilon(1e-9));
    CHECK(edge->normal.y == Approx(height / r).epsilon(1e-9));
    CHECK(edge->normal.z == Approx(0.0).margin(1e-9));

    // Beyond the corner p0, diagonally: horizontal distance d from the corner.
    const double q = d / std::sqrt(2.0);
    const auto corner = sphere_triangle(falling_from({-q, h, -q}), r, p0, p1, p2, 100.0);
    REQUIRE(corner);
    CHECK(corner->t == Approx(std::sqrt(2.0 * (h - height) / G)).epsilon(1e-12));
    CHECK(corner->normal.y == Approx(height / r).epsilon(1e-9));
    CHECK(corner->normal.x == Approx(-q / r).epsilon(1e-9));

    // Beyond the reach of the rim: no contact at all.
    CHECK_FALSE(sphere_triangle(falling_from({-0.6, h, 2}), r, p0, p1, p2, 100.0));
}

TEST_CASE("a fast sphere never passes through a thin triangle, at any speed") {
    const glm::dvec3 w0(0, -1, -1), w1(0, 1, -1), w2(0, 0, 1); // a wall in the plane x = 0
    for (double speed : {1.0, 1e3, 1e6, 1e9}) {
        CAPTURE(speed);
        const double r = 0.05;
        const Path p{{-1, 0, 0}, {speed, 0, 0}, {0, 0, 0}};
        const auto c = sphere_triangle(p, r, w0, w1, w2, 10.0);
        REQUIRE(c);
        CHECK(c->t == Approx((1.0 - r) / speed).epsilon(1e-12));
        CHECK(c->normal == glm::dvec3(-1, 0, 0));
    }
}

TEST_CASE("two spheres meet when their centers are ra + rb apart") {
    // Head-on at 1 m/s each from 10 m apart, radii 1: the gap closes at 2 m/s from 8 m.
    const auto c = sphere_sphere({{0, 0, 0}, {1, 0, 0}, {0, 0, 0}}, 1.0,
                                 {{10, 0, 0}, {-1, 0, 0}, {0, 0, 0}}, 1.0, 100.0);
    REQUIRE(c);
    CHECK(c->t == Approx(4.0).epsilon(1e-15));
    CHECK(c->normal == glm::dvec3(-1, 0, 0));
    CHECK(c->point.x == Approx(5.0).epsilon(1e-15));
    // One falls onto the other at rest: 10 - G t^2 / 2 = 1 when t = sqrt(18 / G).
    const auto fall =
        sphere_sphere(falling_from({0, 10, 0}), 0.5, {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, 0.5, 100.0);
    REQUIRE(fall);
    CHECK(fall->t == Approx(std::sqrt(18.0 / G)).epsilon(1e-13));
    // Both falling: gravity cancels in their relative motion.
    const auto both = sphere_sphere({{0, 10, 0}, {0, -3, 0}, gravity}, 0.5,
                                    {{0, 0, 0}, {0, 0, 0}, gravity}, 0.5, 100.0);
    REQUIRE(both);
    CHECK(both->t == Approx(3.0).epsilon(1e-14));
    // Touching but moving apart (just after a bounce): no contact, no sticking.
    CHECK_FALSE(sphere_sphere({{0, 0, 0}, {-1, 0, 0}, {0, 0, 0}}, 1.0,
                              {{2, 0, 0}, {1, 0, 0}, {0, 0, 0}}, 1.0, 100.0));
    // Passing by farther apart than the radii: none.
    CHECK_FALSE(sphere_sphere({{0, 0, 0}, {1, 0, 0}, {0, 0, 0}}, 1.0,
                              {{10, 2.5, 0}, {-1, 0, 0}, {0, 0, 0}}, 1.0, 100.0));
}

TEST_CASE("the seed's ray-triangle test") {
    const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0); // counter-clockwise seen from +Z
    CHECK(*ray_triangle({0.25, 0.25, 1}, {0, 0, -2}, a, b, c) == Approx(0.5));
    CHECK_FALSE(ray_triangle({0.25, 0.25, 1}, {0, 0, -0.5}, a, b, c)); // stops short: t > 1
    CHECK_FALSE(ray_triangle({0.25, 0.25, 1}, {0, 0, 2}, a, b, c));    // points away: t < 0
    CHECK_FALSE(ray_triangle({0.9, 0.9, 1}, {0, 0, -2}, a, b, c));     // misses the triangle
    CHECK_FALSE(ray_triangle({0.25, 0.25, 1}, {1, 0, 0}, a, b, c));    // parallel
    CHECK(*ray_triangle({0.0, 0.0, 1}, {0, 0, -1}, a, b, c) ==
          Approx(1.0)); // on a corner: inside (>= 0)
}

TEST_CASE("reflection off a wall, and off a moving wall with the relative velocity") {
    const glm::dvec3 n(0, 1, 0);
    CHECK(reflect({3, -4, 5}, n) == glm::dvec3(3, 4, 5));
    // A wall rising at 2 m/s: a ball falling at 4 m/s leaves at 4 + 2 * 2 = 8 m/s.
    CHECK(reflect_off_moving_wall({1, -4, 0}, {0, 2, 0}, n) == glm::dvec3(1, 8, 0));
}

TEST_CASE("3D elastic exchange: the 1D formula along the normal, momentum and energy kept") {
    // Head-on, masses 1 and 3: v1' = ((1 - 3) 2 + 2 * 3 * 0) / 4 = -1, v2' = (2 * 1 * 2) / 4 = 1.
    auto [a1, b1] = elastic_exchange(1.0, {2, 0, 0}, 3.0, {0, 0, 0}, {1, 0, 0});
    CHECK(a1 == glm::dvec3(-1, 0, 0));
    CHECK(b1 == glm::dvec3(1, 0, 0));

    // Equal masses, one at rest, oblique: they leave at 90 degrees, the tangential part kept.
    const glm::dvec3 n = glm::normalize(glm::dvec3(1, 1, 0));
    auto [a2, b2] = elastic_exchange(2.0, {3, 0, 0}, 2.0, {0, 0, 0}, n);
    CHECK(glm::dot(a2, b2) == Approx(0.0).margin(1e-14));
    CHECK(glm::dot(a2, glm::dvec3(1, -1, 0)) ==
          Approx(glm::dot(glm::dvec3(3, 0, 0), glm::dvec3(1, -1, 0))));

    std::mt19937 rng(5);
    std::uniform_real_distribution<double> any(-10, 10), mass(0.01, 100);
    for (int i = 0; i < 1000; ++i) {
        const double ma = mass(rng), mb = mass(rng);
        const glm::dvec3 va(any(rng), any(rng), any(rng)), vb(any(rng), any(rng), any(rng));
        const glm::dvec3 normal = glm::normalize(glm::dvec3(any(rng), any(rng), any(rng)));
        auto [va1, vb1] = elastic_exchange(ma, va, mb, vb, normal);
        const glm::dvec3 p0 = ma * va + mb * vb, p1 = ma * va1 + mb * vb1;
        const double e0 = ma * glm::dot(va, va) + mb * glm::dot(vb, vb);
        const double e1 = ma * glm::dot(va1, va1) + mb * glm::dot(vb1, vb1);
        CHECK(glm::length(p1 - p0) <= 1e-12 * (glm::length(ma * va) + glm::length(mb * vb)));
        CHECK(std::abs(e1 - e0) <= 1e-12 * e0);
        // The tangential components are unchanged.
        CHECK(glm::length((va1 - va) - glm::dot(va1 - va, normal) * normal) <=
              1e-12 * glm::length(va));
    }
}

TEST_CASE("a sphere leaving a face it bounced off does not meet it again from behind") {
    const double r = 0.5;
    // Just after a bounce: touching the face from above, moving up, under gravity.
    const Path leaving{{1, r, 0}, {0, 4, 0}, gravity};
    const auto again = sphere_triangle(leaving, r, A, B, C, 100.0);
    REQUIRE(again); // it falls back onto the face after 2 v / G
    CHECK(again->t == Approx(2.0 * 4.0 / G).epsilon(1e-12));
    CHECK(again->normal == glm::dvec3(0, 1, 0));
    // Far below the face, moving down: the face is behind it, no contact.
    CHECK_FALSE(sphere_triangle({{1, -5, 0}, {0, -1, 0}, {0, 0, 0}}, r, A, B, C, 100.0));
}

TEST_CASE("a triangle without area is met on its edges, never with a normal that is not finite") {
    // Three points on the X axis: a segment. A ball falling onto it lands on it as on an edge.
    const double r = 0.5, h = 5.0;
    const glm::dvec3 p0(-1, 0, 0), p1(0, 0, 0), p2(1, 0, 0);
    const auto c = sphere_triangle(falling_from({0.2, h, 0}), r, p0, p1, p2, 100.0);
    REQUIRE(c);
    CHECK(c->t == Approx(std::sqrt(2.0 * (h - r) / G)).epsilon(1e-12));
    CHECK(std::isfinite(c->normal.x));
    CHECK(c->normal.y == Approx(1.0).epsilon(1e-12));
}
