// Simultaneous contacts (plugins/physics-custom/simultaneous_contact.hpp): the sum and centre of
// pressure of the impulses of several touching points, checked against the complementarity
// conditions evaluated here point by point, and a flat landing against its symmetry.
#include "simultaneous_contact.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

using namespace physics_custom;

namespace {

// A cube of side 2h and mass m (I = m (2h)^2 / 6) moving at v, turning at w.
ImpulseBody cube(double m, double h, const glm::dvec3 &v, const glm::dvec3 &w) {
    ImpulseBody b;
    b.inv_mass = 1.0 / m;
    b.inv_inertia = glm::dmat3(6.0 / (m * 4.0 * h * h));
    b.v = v;
    b.w = w;
    return b;
}

glm::dvec3 velocity_at(const ImpulseBody &b, const glm::dvec3 &com, const glm::dvec3 &x) {
    return b.v + glm::cross(b.w, x - com);
}

} // namespace

TEST_CASE("simultaneous contact: a cube landing flat on four corners is pushed straight under its "
          "centre of mass, so it does not turn") {
    const glm::dvec3 c(0.3, 0.25, -0.2), n(0.0, 1.0, 0.0);
    const double h = 0.25;
    const ImpulseBody a = cube(1.0, h, {0.0, -3.7, 0.0}, glm::dvec3(0.0));
    std::vector<glm::dvec3> corners;
    for (double x : {-h, h})
        for (double z : {-h, h}) corners.push_back(c + glm::dvec3(x, -h, z));
    const auto p = simultaneous_impulse(a, c, ImpulseBody{}, glm::dvec3(0.0), corners, n, 0.5);
    REQUIRE(p);
    // Under the centre to rounding of the corners' coordinates (their offsets from c round).
    CHECK(std::abs(p->centre.x - c.x) < 1e-15);
    CHECK(std::abs(p->centre.z - c.z) < 1e-15);
    ImpulseBody at = a;
    at.r = p->centre - c;
    const ImpulseResult r = contact_impulse_of(at, ImpulseBody{}, n, p->normal, 0.0);
    CHECK(std::abs(r.va.y - 0.5 * 3.7) < 1e-12); // it leaves at e times its speed
    CHECK(glm::length(r.wa) < 1e-14);
}

TEST_CASE(
    "simultaneous contact: random bodies touching at several points are stopped together "
    "(e = 0: complementarity at every point), leave by Poisson's law, and never gain energy") {
    std::mt19937_64 rng(18);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int solved = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const double e = trial % 3 == 0 ? 1.0 : std::abs(u(rng)), m = 0.5 + std::abs(u(rng));
        const glm::dvec3 n(0.0, 1.0, 0.0), com(u(rng), 0.5 + std::abs(u(rng)), u(rng));
        ImpulseBody a =
            cube(m, 0.5, {u(rng), -1.0 - std::abs(u(rng)), u(rng)}, {u(rng), u(rng), u(rng)});
        // A general inverse inertia (symmetric positive definite) in some trials.
        if (trial % 2 == 1) {
            glm::dmat3 q(u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng), u(rng));
            a.inv_inertia = glm::transpose(q) * q + glm::dmat3(0.1);
        }
        // Two to six points on the floor (y = 0) below the body.
        const int count = 2 + trial % 5;
        std::vector<glm::dvec3> points;
        for (int k = 0; k < count; ++k) points.push_back({com.x + u(rng), 0.0, com.z + u(rng)});
        const auto p = simultaneous_impulse(a, com, ImpulseBody{}, glm::dvec3(0.0), points, n, e);
        const auto plastic =
            simultaneous_impulse(a, com, ImpulseBody{}, glm::dvec3(0.0), points, n, 0.0);
        bool any_approaching = false;
        for (const glm::dvec3 &x : points)
            any_approaching = any_approaching || glm::dot(velocity_at(a, com, x), n) < 0.0;
        if (!any_approaching) {
            CHECK_FALSE(p);
            continue;
        }
        REQUIRE(p);
        REQUIRE(plastic);
        ++solved;
        auto after_impulse = [&](const SimultaneousImpulse &s) {
            ImpulseBody at = a;
            at.r = s.centre - com;
            const ImpulseResult r = contact_impulse_of(at, ImpulseBody{}, n, s.normal, 0.0);
            ImpulseBody out = a;
            out.v = r.va;
            out.w = r.wa;
            return out;
        };
        const ImpulseBody after = after_impulse(*p), stopped = after_impulse(*plastic);
        // The compression: no point still approaching, and one (at least) stopped exactly.
        double tightest = 1e300, speed = 0.0;
        for (const glm::dvec3 &x : points) {
            const double before = glm::dot(velocity_at(a, com, x), n),
                         at_rest = glm::dot(velocity_at(stopped, com, x), n),
                         later = glm::dot(velocity_at(after, com, x), n);
            speed = std::max(speed, std::abs(before));
            CHECK(at_rest >= -1e-9 * speed);
            tightest = std::min(tightest, std::abs(at_rest));
            // Poisson's law: e times the compression's change again.
            CHECK(std::abs(later - (at_rest + e * (at_rest - before))) <= 1e-9 * speed);
        }
        CHECK(tightest <= 1e-9 * speed);
        // Kinetic energy never grows, and e = 1 keeps it.
        const glm::dmat3 inertia = glm::inverse(a.inv_inertia);
        auto energy = [&](const ImpulseBody &b) {
            return 0.5 * glm::dot(b.v, b.v) / b.inv_mass + 0.5 * glm::dot(b.w, inertia * b.w);
        };
        CHECK(energy(after) <= energy(a) * (1.0 + 1e-12));
        if (e == 1.0) CHECK(std::abs(energy(after) - energy(a)) <= 1e-12 * energy(a));
    }
    CHECK(solved > 1000);
}
