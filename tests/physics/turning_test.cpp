// physics.custom: models that are not spheres turning from their contacts (issue 18), through
// the real timeline, against closed forms and an independent root finding written here.
#include "io/document_io.hpp"
#include "timeline/timeline.hpp"
#include "timeline/world_turning.hpp"

#include "box_drop.hpp"
#include "cube_drop.hpp"
#include "scene_support.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>

using namespace animator;
using namespace physics_test;

namespace {

Document shipped_scene(const std::string &name) {
    return open_document(env().plugins, test::source_dir() / "assets/scenes" / name).document;
}

glm::dvec3 vec(const ani_vec3 &v) {
    return {v.x, v.y, v.z};
}

// The motion and rotation segments that start at t (just after an event there).
const ani_motion_segment &segment_from(const Timeline &t, int model, double time) {
    for (const auto &s : t.segments(model))
        if (s.t0 == time) return s;
    FAIL("no motion segment starts at " << time);
    throw 0;
}
const ani_rotation_segment &rotation_from(const Timeline &t, int model, double time) {
    for (const auto &s : t.rotations(model))
        if (s.t0 == time) return s;
    FAIL("no rotation segment starts at " << time);
    throw 0;
}

} // namespace

TEST_CASE("a cube dropped corner first with Rotates on, e = 1, mu = 0: its first two impacts at "
          "the times of an independent root finding, energy and momentum kept") {
    const Document doc = shipped_scene("tumbling_cube.lua");
    const ModelState &start = *doc.keyframes().front().states[1];
    const Model &cube = doc.models()[1];
    REQUIRE(cube.rotates);
    REQUIRE(cube.restitution == 1.0);
    REQUIRE(cube.friction == 0.0);
    REQUIRE(start.scale == glm::dvec3(0.5)); // side s = 1
    const double m = cube.mass;
    // The drop worked out independently (tests/cube_drop.hpp): the first impact in closed form,
    // its impulse by hand, the second impact by its own root finding.
    const cube_drop::Drop drop = cube_drop::drop(start.center, start.angles, 0.5, m, G);
    const double inertia = drop.inertia;
    auto timeline = timeline_of(doc);
    timeline->bake(3.0);
    const auto &events = timeline->events();
    REQUIRE(events.size() >= 2);
    CAPTURE(events[0].t - drop.t1);
    CHECK(std::abs(events[0].t - drop.t1) < 1e-9);
    const ani_motion_segment &after = segment_from(*timeline, 1, events[0].t);
    const ani_rotation_segment &turn = rotation_from(*timeline, 1, events[0].t);
    CHECK(glm::length(vec(after.v0) - drop.v1) < 1e-9);
    CHECK(glm::length(vec(turn.w) - drop.w1) < 1e-9);
    CAPTURE(events[1].t - drop.t2);
    CHECK(std::abs(events[1].t - drop.t2) < 1e-9);
    const glm::dvec3 w1 = drop.w1;

    // Energy (translation, rotation, height) and the momentum along the floor, after each.
    const double e0 = m * G * start.center.y;
    for (size_t k = 0; k < 2; ++k) {
        const ani_motion_segment &seg = segment_from(*timeline, 1, events[k].t);
        const ani_rotation_segment &rot = rotation_from(*timeline, 1, events[k].t);
        const glm::dvec3 v = vec(seg.v0), w = vec(rot.w);
        const double energy =
            0.5 * m * glm::dot(v, v) + 0.5 * inertia * glm::dot(w, w) + m * G * seg.p0.y;
        CAPTURE(k, energy - e0);
        CHECK(std::abs(energy - e0) < 1e-9 * e0);
        CHECK(std::abs(v.x) < 1e-12);
        CHECK(std::abs(v.z) < 1e-12);
    }
    // Angular momentum about the touching point is kept through the second impact (the floor's
    // impulse acts there): L = m (c - p) x v + I w.
    const double t = events[1].t;
    const glm::dvec3 p = vec(events[1].point);
    const ani_motion_segment &before = segment_from(*timeline, 1, events[0].t),
                             &later = segment_from(*timeline, 1, t);
    const double dt = t - before.t0;
    const glm::dvec3 c_before =
                         vec(before.p0) + vec(before.v0) * dt + 0.5 * vec(before.a) * dt * dt,
                     v_before = vec(before.v0) + vec(before.a) * dt;
    const glm::dvec3 l_before = m * glm::cross(c_before - p, v_before) + inertia * w1,
                     l_after = m * glm::cross(vec(later.p0) - p, vec(later.v0)) +
                               inertia * vec(rotation_from(*timeline, 1, t).w);
    CAPTURE(l_before.x, l_before.y, l_before.z, l_after.x, l_after.y, l_after.z);
    CHECK(glm::length(l_after - l_before) < 1e-9 * glm::length(l_before));
}

TEST_CASE("a box thrown spinning with Rotates on, e = 1, mu = 0: it turns as Euler's equations "
          "say, lands when they say, keeps its energy and angular momentum") {
    const Document doc = shipped_scene("tumbling_box.lua");
    const ModelState &start = *doc.keyframes().front().states[1];
    const Model &box = doc.models()[1];
    REQUIRE(box.rotates);
    REQUIRE(box.restitution == 1.0);
    REQUIRE(box.friction == 0.0);
    REQUIRE(start.scale == glm::dvec3(0.2, 0.5, 0.8)); // the cube mesh spans [-1, 1]
    const double m = box.mass;
    const box_drop::Box reference(start.scale, m);
    const glm::dvec3 I = reference.moments(); // principal, along the box's own axes
    REQUIRE(I.x != I.y);
    REQUIRE(I.y != I.z);
    const glm::dquat q0 = glm::normalize(glm::quat_cast(cube_drop::turn_of(start.angles)));
    const glm::dvec3 w0 = box.angular_velocity;
    auto timeline = timeline_of(doc);
    timeline->bake(10.0);
    const auto &events = timeline->events();
    REQUIRE(events.size() >= 5);

    // The host draws it by the backend's free-rotation segments (the closed form).
    bool free_segments = false;
    for (const RotationSegment &r : timeline->rotations(1)) free_segments |= r.free != nullptr;
    CHECK(free_segments);
    const auto turning_at = [&](double t) {
        return world_turnings(*timeline, timeline->evaluate(t), t)[1];
    };
    // In flight, its orientation and angular velocity are those of Euler's equations integrated
    // here; its angular velocity changes (a spherical top's would not).
    const double t1 = reference.first_impact(start.center.y, G, q0, w0);
    CAPTURE(events[0].t - t1);
    CHECK(std::abs(events[0].t - t1) < 1e-9);
    for (double t : {0.1, 0.25, 0.4, 0.55}) {
        const Turning got = turning_at(t);
        const box_drop::Rotation want = reference.at(q0, w0, t);
        const double dq = std::min(glm::length(glm::dvec4(got.q.x - want.q.x, got.q.y - want.q.y,
                                                          got.q.z - want.q.z, got.q.w - want.q.w)),
                                   glm::length(glm::dvec4(got.q.x + want.q.x, got.q.y + want.q.y,
                                                          got.q.z + want.q.z, got.q.w + want.q.w)));
        CAPTURE(t, dq);
        CHECK(dq < 1e-9);
        CHECK(glm::length(got.w - want.q * want.w) < 1e-9);
    }
    CHECK(glm::length(turning_at(0.5).w - w0) > 0.1);

    // Energy (translation, rotation about the centre, height) and angular momentum about the
    // centre, every 2 ms to 10 s: the floor's impulses are vertical (mu = 0), so they change
    // neither the momentum along the floor nor L's vertical part, and nothing changes L between
    // impacts. It never goes below the floor.
    const double e0 = m * G * start.center.y + 0.5 * glm::dot(glm::conjugate(q0) * w0, I * (glm::conjugate(q0) * w0));
    const glm::dvec3 l0 = q0 * (I * (glm::conjugate(q0) * w0));
    double worst_energy = 0.0, worst_l = 0.0, worst_between = 0.0, lowest = 1e300;
    size_t seen = 0;
    glm::dvec3 l_last = l0;
    for (int k = 0; k <= 5000; ++k) {
        const double t = 0.002 * k;
        const Frame f = timeline->evaluate(t);
        const Turning turning = world_turnings(*timeline, f, t)[1];
        const glm::dvec3 v = f.models[1].velocity, wb = glm::conjugate(turning.q) * turning.w;
        const glm::dvec3 l = turning.q * (I * wb);
        const double energy = 0.5 * m * glm::dot(v, v) + 0.5 * glm::dot(wb, I * wb) + m * G * f.models[1].center.y;
        worst_energy = std::max(worst_energy, std::abs(energy - e0) / e0);
        worst_l = std::max(worst_l, std::abs(l.y - l0.y));
        CHECK(std::abs(v.x) < 1e-12);
        CHECK(std::abs(v.z) < 1e-12);
        size_t now = 0;
        while (now < events.size() && events[now].t <= t) ++now;
        if (now == seen) worst_between = std::max(worst_between, glm::length(l - l_last));
        seen = now;
        l_last = l;
        lowest = std::min(lowest, reference.lowest(f.models[1].center.y, turning.q));
    }
    CAPTURE(worst_energy, worst_l, worst_between, lowest);
    CHECK(worst_energy < 1e-12);
    CHECK(worst_l < 1e-12);
    CHECK(worst_between < 1e-12);
    CHECK(lowest > -1e-9);
}

namespace {

// The second moment of a closed mesh's solid about the origin, integral of x x^T dV, and its
// volume and first moment, summed over the tetrahedra (0, a, b, c) of its triangles (signed):
// each V / 20 (sum v v^T + s s^T), s = a + b + c (the origin a vertex at 0).
struct Moments {
    double volume = 0.0;
    glm::dvec3 first{0.0};
    glm::dmat3 second{0.0};
};
Moments solid_moments(const std::vector<glm::dvec3> &v, const std::vector<uint32_t> &triangles) {
    Moments out;
    for (size_t k = 0; k + 2 < triangles.size(); k += 3) {
        const glm::dvec3 &a = v[triangles[k]], &b = v[triangles[k + 1]], &c = v[triangles[k + 2]];
        const double volume = glm::dot(a, glm::cross(b, c)) / 6.0;
        const glm::dvec3 sum = a + b + c;
        out.volume += volume;
        out.first += volume * sum / 4.0;
        out.second += volume / 20.0 *
                      (glm::outerProduct(a, a) + glm::outerProduct(b, b) +
                       glm::outerProduct(c, c) + glm::outerProduct(sum, sum));
    }
    return out;
}

} // namespace

TEST_CASE("a cone thrown spinning with Rotates on turns about its centre of mass, which falls "
          "and bounces straight up and down, energy kept, baked whole or in slices") {
    const Document doc = shipped_scene("tumbling_cone.lua");
    const ModelState &start = *doc.keyframes().front().states[1];
    const Model &cone = doc.models()[1];
    REQUIRE(cone.rotates);
    REQUIRE(cone.restitution == 1.0);
    REQUIRE(cone.friction == 0.0);
    const double m = cone.mass;
    std::vector<std::string> warnings;
    const auto meshes = load_meshes({cone.mesh}, env().assets, {}, warnings);
    REQUIRE(meshes.at(0));
    // The cone as its keys scale it, its centre of mass and inertia about it, computed here.
    std::vector<glm::dvec3> vertices;
    for (const glm::dvec3 &p : meshes[0]->positions) vertices.push_back(start.scale * p);
    const Moments solid = solid_moments(vertices, meshes[0]->triangles);
    const double density = m / solid.volume;
    const glm::dvec3 com = solid.first / solid.volume;
    // A pyramid's centre of mass is a quarter of its height above its base: the mesh spans
    // y in [-1, 1], scaled by 0.6.
    CHECK(std::abs(com.y - (-0.6 + 0.25 * 1.2)) < 1e-12);
    const glm::dmat3 c = density * solid.second - m * glm::outerProduct(com, com);
    const glm::dmat3 inertia = glm::dmat3(c[0][0] + c[1][1] + c[2][2]) - c;

    auto whole = timeline_of(doc), sliced = timeline_of(doc);
    whole->bake(10.0);
    for (double t = 0.25; t <= 10.0; t += 0.25) sliced->bake(t);
    const auto &events = whole->events();
    REQUIRE(events.size() >= 10);
    bool pivoted = false;
    for (const RotationSegment &r : whole->rotations(1))
        pivoted |= glm::length(r.pivot - com) < 1e-12;
    CHECK(pivoted);

    struct State {
        glm::dvec3 com, com_velocity, w;
        glm::dquat q;
    };
    const auto state = [&](const Timeline &t, double time) {
        const Frame f = t.evaluate(time);
        const Turning turning = world_turnings(t, f, time)[1];
        const glm::dvec3 arm = turning.q * com;
        return State{f.models[1].center + arm,
                     f.models[1].velocity + glm::cross(turning.w, arm), turning.w, turning.q};
    };
    const State first = state(*whole, 0.0);
    CHECK(glm::length(first.com_velocity) < 1e-12); // thrown from rest at its centre of mass
    const auto energy = [&](const State &s) {
        const glm::dmat3 r = glm::mat3_cast(s.q);
        const glm::dmat3 world = r * inertia * glm::transpose(r);
        return 0.5 * m * glm::dot(s.com_velocity, s.com_velocity) +
               0.5 * glm::dot(s.w, world * s.w) + m * G * s.com.y;
    };
    const double e0 = energy(first);
    double worst_drift = 0.0, worst_energy = 0.0, worst_slices = 0.0, lowest = 1e300;
    for (int k = 0; k <= 2000; ++k) {
        const double t = 0.005 * k;
        const State s = state(*whole, t), other = state(*sliced, t);
        worst_drift = std::max({worst_drift, std::abs(s.com.x - first.com.x),
                                std::abs(s.com.z - first.com.z), std::abs(s.com_velocity.x),
                                std::abs(s.com_velocity.z)});
        worst_energy = std::max(worst_energy, std::abs(energy(s) - e0) / e0);
        worst_slices = std::max(worst_slices, glm::length(s.com - other.com));
        const Frame f = whole->evaluate(t);
        const glm::dmat3 r = glm::mat3_cast(world_turnings(*whole, f, t)[1].q);
        for (const glm::dvec3 &p : vertices) lowest = std::min(lowest, (f.models[1].center + r * p).y);
    }
    CAPTURE(worst_drift, worst_energy, worst_slices, lowest);
    CHECK(worst_drift < 1e-12);
    CHECK(worst_energy < 1e-12);
    CHECK(worst_slices < 1e-9);
    CHECK(lowest > -1e-9);
}

TEST_CASE("a cube with Rotates on landing flat with e = 0.5 does not turn at all and comes to "
          "rest at the closed-form time") {
    const Document doc = shipped_scene("cube_landing_flat.lua");
    const ModelState &start = *doc.keyframes().front().states[1];
    const double e = doc.models()[1].restitution, half = start.scale.x, h = start.center.y;
    REQUIRE(doc.models()[1].rotates);
    REQUIRE(e == 0.5);
    REQUIRE(half == 0.25);
    auto timeline = timeline_of(doc);
    timeline->bake(1000.0);
    // Its centre moves as a ball's of radius `half` (restitution_test.cpp derives these).
    const double t0 = std::sqrt(2.0 * (h - half) / G), v0 = G * t0;
    const double rest = t0 * (1.0 + e) / (1.0 - e);
    const auto &events = timeline->events();
    REQUIRE(events.size() >= 10);
    CHECK(events.size() < 100);
    const auto [worst_t, worst_v] = bounce_errors(events, 10, t0, v0, e);
    CAPTURE(worst_t, worst_v);
    CHECK(worst_t < 1e-9);
    CHECK(worst_v < 1e-9);
    // No rotation at all: every rotation segment keeps its start orientation, at w = 0 exactly.
    REQUIRE_FALSE(timeline->rotations(1).empty());
    for (const auto &r : timeline->rotations(1)) {
        CHECK(vec(r.w) == glm::dvec3(0.0));
        CHECK(std::abs(std::abs(r.q0.w) - 1.0) == 0.0);
    }
    // Resting from the accumulation time, its bottom face on the floor, still to 1000 s.
    const ani_motion_segment *still = nullptr;
    for (const auto &s : timeline->segments(1))
        if (s.t0 <= rest + 1e-3 && rest + 1e-3 <= s.t1) still = &s;
    REQUIRE(still);
    CAPTURE(still->t0 - rest);
    CHECK(std::abs(still->t0 - rest) < 1e-9);
    CHECK(vec(still->v0) == glm::dvec3(0.0));
    CHECK(still->p0.y == Approx(half).epsilon(1e-12));
    const glm::dvec3 at_rest = timeline->evaluate(rest + 1e-3).models[1].center;
    for (double t : {rest + 1.0, 100.0, 1000.0}) {
        const Frame f = timeline->evaluate(t);
        CHECK(f.models[1].center == at_rest);
        CHECK(f.models[1].velocity == glm::dvec3(0.0));
        CHECK(f.models[1].angles == glm::dvec3(0.0));
    }
}

TEST_CASE("random cubes with Rotates on, dropped on a rough floor with e < 1, tumble and come to "
          "rest in bounded time, never inside the floor and never gaining energy",
          "[stress]") {
    std::mt19937_64 rng(1918);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 6; ++trial) {
        Document doc;
        doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
        Model cube = model("cube", "cube", true, true);
        cube.rotates = true;
        cube.restitution = 0.6 * u(rng);
        cube.friction = u(rng);
        cube.angular_velocity = {4.0 * u(rng) - 2.0, 4.0 * u(rng) - 2.0, 4.0 * u(rng) - 2.0};
        const glm::dvec3 angles(360.0 * u(rng), 360.0 * u(rng), 360.0 * u(rng));
        const double half = 0.25, h = 1.0 + 2.0 * u(rng), m = cube.mass;
        doc.add_model(cube, placed({0.0, h, 0.0}, glm::dvec3(half), angles));
        auto t = timeline_of(doc);
        CAPTURE(trial, cube.restitution, cube.friction, angles.x, angles.y, angles.z);
        t->bake(20.0);
        CHECK(t->events().size() < 100000);
        // I = m s^2 / 6 for the cube of side 2 half; w from its rotation segment.
        const double inertia = m * 4.0 * half * half / 6.0;
        auto energy = [&](double at) {
            const Frame f = t->evaluate(at);
            const ani_rotation_segment *r = t->rotation_at(1, at);
            const glm::dvec3 v = f.models[1].velocity, w = r ? vec(r->w) : glm::dvec3(0.0);
            return 0.5 * m * glm::dot(v, v) + 0.5 * inertia * glm::dot(w, w) +
                   m * G * f.models[1].center.y;
        };
        const double e0 = energy(0.0);
        double lowest = 1e300, most = 0.0;
        // Every 1/240 s while it tumbles, every 0.1 s after.
        for (double at = 0.0; at <= 20.0; at += at < 6.0 ? 1.0 / 240.0 : 0.1) {
            const Frame f = t->evaluate(at);
            const glm::dmat3 turn = cube_drop::turn_of(f.models[1].angles);
            for (const glm::dvec3 &p : cube_drop::corners(half))
                lowest = std::min(lowest, f.models[1].center.y + (turn * p).y);
            most = std::max(most, energy(at));
            REQUIRE(std::isfinite(f.models[1].center.y));
        }
        CAPTURE(lowest, most - e0, t->events().size());
        CHECK(lowest > -1e-9);
        CHECK(most <= e0 * (1.0 + 1e-9));
        // At rest by the end: still, its lowest face on the floor.
        const Frame last = t->evaluate(20.0);
        CHECK(glm::length(last.models[1].velocity) < 1e-3);
        CHECK(std::abs(last.models[1].center.y - half) < 1e-6);
    }
}

TEST_CASE("two turning cubes meeting without gravity keep the pair's linear and angular momentum, "
          "and with e = 1 and mu = 0 their kinetic energy") {
    // Cube a (1 kg) spins at 3 rad/s about z and moves along +x; cube b (2 kg) comes the other
    // way, offset in y so that they meet off centre, edge or corner first.
    for (const double mu : {0.0, 0.4}) {
        Document doc;
        Settings s = doc.settings();
        s.gravity = 0.0;
        doc.set_settings(s);
        Model a = model("a", "cube", true, false), b = model("b", "cube", true, false);
        a.rotates = b.rotates = true;
        a.mass = 1.0;
        b.mass = 2.0;
        a.friction = mu;
        a.initial_velocity = {2.0, 0.0, 0.0};
        b.initial_velocity = {-1.0, 0.0, 0.0};
        a.angular_velocity = {0.0, 0.0, 3.0};
        b.angular_velocity = {0.5, 0.0, 0.0};
        doc.add_model(a, placed({-2.0, 0.0, 0.0}, glm::dvec3(0.25)));
        doc.add_model(b, placed({2.0, 0.3, 0.1}, glm::dvec3(0.25), {10.0, 20.0, 30.0}));
        auto t = timeline_of(doc);
        t->bake(3.0);
        CAPTURE(mu);
        REQUIRE(!t->events().empty());
        const double ia = 1.0 * 0.25 / 6.0, ib = 2.0 * 0.25 / 6.0; // m s^2 / 6, s = 0.5
        const double masses[2] = {1.0, 2.0}, inertias[2] = {ia, ib};
        auto totals = [&](double at, glm::dvec3 &p, glm::dvec3 &l, double &energy) {
            const Frame f = t->evaluate(at);
            p = l = glm::dvec3(0.0);
            energy = 0.0;
            for (int k = 0; k < 2; ++k) {
                const ani_rotation_segment *r = t->rotation_at(k, at);
                REQUIRE(r);
                const glm::dvec3 v = f.models[static_cast<size_t>(k)].velocity, w = vec(r->w);
                const glm::dvec3 c = f.models[static_cast<size_t>(k)].center;
                p += masses[k] * v;
                l += masses[k] * glm::cross(c, v) + inertias[k] * w; // about the origin
                energy += 0.5 * masses[k] * glm::dot(v, v) + 0.5 * inertias[k] * glm::dot(w, w);
            }
        };
        glm::dvec3 p0, l0, p1, l1;
        double e0, e1;
        totals(0.0, p0, l0, e0);
        totals(3.0, p1, l1, e1);
        CAPTURE(glm::length(p1 - p0), glm::length(l1 - l0), e1 - e0, t->events().size());
        CHECK(glm::length(p1 - p0) < 1e-12 * 4.0); // |m_a v_a| + |m_b v_b| = 4 kg m/s
        CHECK(glm::length(l1 - l0) < 1e-12 * glm::length(l0));
        if (mu == 0.0)
            CHECK(std::abs(e1 - e0) < 1e-12 * e0);
        else
            CHECK(e1 <= e0 * (1.0 + 1e-12));
        // They met and went apart: b moves towards +x less fast than before, or back.
        CHECK(t->evaluate(3.0).models[1].velocity.x > -1.0);
    }
}
