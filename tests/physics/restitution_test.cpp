// physics.custom with restitution, friction and spin (issue 18), through the real timeline,
// against closed forms derived in the comments.
#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "timeline/timeline.hpp"

#include "scene_support.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>

using namespace animator;
using namespace physics_test;

namespace {

const ani_motion_segment *segment_at(const Timeline &t, int model, double time) {
    const ani_motion_segment *found = nullptr;
    for (const auto &s : t.segments(model))
        if (s.t0 <= time && time <= s.t1) found = &s;
    return found;
}

const ani_rotation_segment *rotation_at(const Timeline &t, int model, double time) {
    const ani_rotation_segment *found = nullptr;
    for (const auto &s : t.rotations(model))
        if (s.t0 <= time && time <= s.t1) found = &s;
    return found;
}

glm::dvec3 vec(const ani_vec3 &v) {
    return {v.x, v.y, v.z};
}

// A scene the project ships in assets/scenes (each test's numbers are the scene's own).
Document shipped_scene(const std::string &name) {
    return open_document(env().plugins, test::source_dir() / "assets/scenes" / name).document;
}

// A model's state at t = 0.
const ModelState &start_of(const Document &doc, int model) {
    return *doc.keyframes().front().states[static_cast<size_t>(model)];
}

} // namespace

TEST_CASE("a ball dropped with e = 0.8 bounces at the closed-form times and comes to rest at the "
          "accumulation time, then stays still for 1000 s") {
    // The scene (the floor keeps e = 1: the pair takes the lower, the ball's).
    const Document doc = shipped_scene("restitution_drop.lua");
    const double r = unit_radius(), h = start_of(doc, 1).center.y, e = doc.models()[1].restitution;
    REQUIRE(doc.models()[0].restitution == 1.0);
    REQUIRE(e == 0.8);
    REQUIRE(doc.settings().max_time_ms >= 1001000);
    auto timeline = timeline_of(doc);
    timeline->bake(1000.0);
    // First impact after falling h - r: t0 = sqrt(2 (h - r) / g) at v0 = g t0. It leaves bounce
    // k at e^(k+1) v0 and flies 2 e^(k+1) v0 / g, so bounce k is at
    // t0 + sum_{j=1..k} 2 e^j t0 = t0 (1 + 2 e (1 - e^k) / (1 - e)), met at speed e^k v0, and the
    // flights add up to t0 + 2 e t0 / (1 - e) = t0 (1 + e) / (1 - e).
    const double t0 = std::sqrt(2.0 * (h - r) / G), v0 = G * t0;
    const double rest = t0 * (1.0 + e) / (1.0 - e);
    const auto &events = timeline->events();
    REQUIRE(events.size() >= 30);
    CHECK(events.size() < 200); // the bounces below the Zeno threshold are not followed
    const auto [worst_t, worst_v] = bounce_errors(events, 30, t0, v0, e);
    CAPTURE(worst_t, worst_v, events.size());
    CHECK(worst_t < 1e-9);
    CHECK(worst_v < 1e-9);
    // At rest from the accumulation time, exactly on the floor.
    const ani_motion_segment *still = segment_at(*timeline, 1, rest + 1e-3);
    REQUIRE(still);
    CAPTURE(still->t0 - rest);
    CHECK(std::abs(still->t0 - rest) < 1e-9);
    CHECK(vec(still->v0) == glm::dvec3(0.0));
    CHECK(vec(still->a) == glm::dvec3(0.0));
    CHECK(still->p0.y == Approx(r).epsilon(1e-12));
    CHECK(events.back().t < rest);
    const glm::dvec3 at_rest = timeline->evaluate(rest + 1e-3).models[1].center;
    for (double t : {rest + 1.0, 10.0, 100.0, 567.89, 1000.0}) {
        const Frame f = timeline->evaluate(t);
        CHECK(f.models[1].center == at_rest); // bit for bit
        CHECK(f.models[1].velocity == glm::dvec3(0.0));
    }
}

TEST_CASE("two spheres of unequal mass meeting obliquely with e = 0.5: the normal relative "
          "velocity reversed and halved, the tangential kept, momentum kept") {
    const Document doc = shipped_scene("oblique_spheres.lua");
    REQUIRE(doc.settings().gravity == 0.0);
    const double r = unit_radius(), ma = doc.models()[0].mass, mb = doc.models()[1].mass,
                 e = std::min(doc.models()[0].restitution, doc.models()[1].restitution);
    REQUIRE(ma != mb);
    REQUIRE(e == 0.5);
    const glm::dvec3 pa = start_of(doc, 0).center, pb = start_of(doc, 1).center,
                     va = doc.models()[0].initial_velocity;
    REQUIRE(doc.models()[1].initial_velocity == glm::dvec3(0.0));
    auto timeline = timeline_of(doc);
    timeline->bake(10.0);
    REQUIRE(timeline->events().size() == 1);
    // They meet when |d + va t| = 2r (d = pa - pb), with n = (d + va t) / 2r from b to a.
    const glm::dvec3 d = pa - pb;
    const double R = 2.0 * r, qa = glm::dot(va, va), qb = glm::dot(d, va),
                 qc = glm::dot(d, d) - R * R;
    const double t = (-qb - std::sqrt(qb * qb - qa * qc)) / qa;
    const glm::dvec3 n = (d + va * t) / R;
    // Newton: j = -(1 + e) u_n / (1/ma + 1/mb), u_n = va . n; va' = va + j/ma n, vb' = -j/mb n.
    const double un = glm::dot(va, n), j = -(1.0 + e) * un / (1.0 / ma + 1.0 / mb);
    const Frame f = timeline->evaluate(10.0);
    const glm::dvec3 va1 = f.models[0].velocity, vb1 = f.models[1].velocity;
    CHECK(glm::length(va1 - (va + j / ma * n)) < 1e-12);
    CHECK(glm::length(vb1 - (-j / mb * n)) < 1e-12);
    CHECK(std::abs(glm::dot(va1 - vb1, n) + e * un) < 1e-12);
    CHECK(glm::length((va1 - glm::dot(va1, n) * n) - (va - un * n)) < 1e-12);
    CHECK(glm::length(ma * va1 + mb * vb1 - ma * va) < 1e-12);
}

TEST_CASE("a spinning ball hitting a rough floor obliquely leaves with the hand-derived velocity "
          "and spin, sticking and slipping") {
    // No gravity: the ball (radius r, mass 2) reaches the floor with v = (1, -2, 0), w = (0, 0, 4).
    // The contact point slips at u = v_x + w r. Normal: v_y' = e 2 = 1 (e = 0.5), J_n = 3 m.
    // Sticking (mu = 1: |J_t| = 2 m u / 7 <= mu J_n): v_x' = (5 v_x - 2 r w) / 7,
    // w' = (2 r w - 5 v_x) / (7 r). Slipping (mu = 0.1): J_t = -mu J_n, v_x' = v_x - 0.3,
    // w' = w + r J_t / I = w - 5 (0.3) / (2 r).
    const double r = unit_radius() * 0.5;
    const Document scene = shipped_scene("spinning_ball.lua");
    {
        const Model &ball = scene.models()[1];
        REQUIRE(scene.settings().gravity == 0.0);
        REQUIRE(scene.models()[0].friction == 1.0);
        REQUIRE((ball.mass == 2.0 && ball.restitution == 0.5 && ball.rotates));
        REQUIRE(ball.angular_velocity == glm::dvec3(0, 0, 4));
        REQUIRE(ball.initial_velocity == glm::dvec3(1, -2, 0));
        REQUIRE(start_of(scene, 1).center == glm::dvec3(0, 2, 0));
        REQUIRE(start_of(scene, 1).scale == glm::dvec3(0.5));
    }
    for (const double mu : {1.0, 0.1}) { // the scene's floor, and one that lets it slip
        CAPTURE(mu);
        Document doc = scene;
        Model floor = doc.models()[0];
        floor.friction = mu;
        doc.set_model(0, floor);
        auto timeline = timeline_of(doc);
        timeline->bake(3.0);
        REQUIRE(timeline->events().size() == 1);
        const double t = timeline->events()[0].t;
        CHECK(t == Approx((2.0 - r) / 2.0).epsilon(1e-9));
        const bool sticks = 2.0 * 2.0 * (1.0 + 4.0 * r) / 7.0 <= mu * 6.0;
        CHECK(sticks == (mu == 1.0));
        const double vx = sticks ? (5.0 - 2.0 * r * 4.0) / 7.0 : 0.7;
        const double wz = sticks ? (2.0 * r * 4.0 - 5.0) / (7.0 * r) : 4.0 - 5.0 * 0.3 / (2.0 * r);
        const Frame f = timeline->evaluate(t + 0.5);
        CHECK(glm::length(f.models[1].velocity - glm::dvec3(vx, 1.0, 0.0)) < 1e-12);
        const ani_rotation_segment *before = rotation_at(*timeline, 1, 0.5 * t);
        const ani_rotation_segment *after = rotation_at(*timeline, 1, t + 0.5);
        REQUIRE(before);
        REQUIRE(after);
        CHECK(glm::length(vec(before->w) - glm::dvec3(0, 0, 4)) == 0.0);
        CHECK(glm::length(vec(after->w) - glm::dvec3(0, 0, wz)) < 1e-12);
        CHECK(after->t0 == Approx(t).epsilon(1e-15));
        // Orientation continuous at the contact: turned 4 t about z from the keys' identity.
        const glm::dquat q(after->q0.w, after->q0.x, after->q0.y, after->q0.z);
        const glm::dquat expect = glm::angleAxis(4.0 * t, glm::dvec3(0, 0, 1));
        CHECK(std::abs(std::abs(glm::dot(q, expect)) - 1.0) < 1e-12);
    }
}

TEST_CASE("a ball struck by a keyed paddle with e = 0.5 leaves at (1 + e) times its speed") {
    // v1 - u = -e (v0 - u) along the normal with v0 = 0: v1 = (1 + e) u.
    const double r = unit_radius() * 0.5, u = 2.0, e = 0.5;
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    doc.add_model(model("paddle", "cube", false, false), placed({-3, 0, 0}, {0.1, 1, 1}));
    Model ball = model("ball", "sphere", true, false);
    ball.restitution = e;
    doc.add_model(ball, placed({0, 0, 0}, glm::dvec3(0.5)));
    key(doc, 2000, 0, placed({1, 0, 0}, {0.1, 1, 1}));
    auto timeline = timeline_of(doc);
    timeline->bake(4.0);
    const double contact = (-r - 0.1 + 3.0) / u;
    REQUIRE(timeline->events().size() == 1);
    CHECK(timeline->events()[0].t == Approx(contact).epsilon(1e-11));
    const Frame after = timeline->evaluate(contact + 0.5);
    CHECK(after.models[1].velocity.x == Approx((1.0 + e) * u).epsilon(1e-9));
    CHECK(std::abs(after.models[1].velocity.y) < 1e-12);
}

TEST_CASE("a ball that rotates turns at its angular velocity in free flight, one rotation segment "
          "from t = 0, and its keys' orientation at the start") {
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    Model ball = model("ball", "sphere", true, false);
    ball.rotates = true;
    ball.angular_velocity = {0, 1.5, 0};
    doc.add_model(ball, placed({0, 0, 0}, glm::dvec3(1.0), {90, 0, 0}));
    auto timeline = timeline_of(doc);
    timeline->bake(4.0);
    REQUIRE(timeline->rotations(0).size() == 1);
    const ani_rotation_segment &seg = timeline->rotations(0)[0];
    CHECK(seg.t0 == 0.0);
    CHECK(seg.t1 == 4.0);
    CHECK(vec(seg.w) == glm::dvec3(0, 1.5, 0));
    // 90 degrees about x: q = (cos 45, sin 45, 0, 0).
    const glm::dquat q(seg.q0.w, seg.q0.x, seg.q0.y, seg.q0.z);
    CHECK(std::abs(std::abs(glm::dot(q, glm::dquat(std::sqrt(0.5), std::sqrt(0.5), 0, 0))) - 1.0) <
          1e-12);
}

TEST_CASE("restitution or friction out of range is refused with the model's name") {
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, 10.0));
    Model ball = model("odd ball", "sphere", true, true);
    doc.add_model(ball, placed({0, 2, 0}));
    // The document refuses them itself; the backend checks too (material.cpp) for other hosts.
    Model bad = ball;
    bad.restitution = 1.5;
    CHECK_THROWS(doc.set_model(1, bad));
}

TEST_CASE("a ball that rotates keeps turning after its last key at the rate its keys gave it") {
    // Keyed (linear interpolation) from 0 to 90 degrees about y over 1 s, centre held: after the
    // key it turns at pi/2 rad/s about y, starting from a quarter turn, without moving.
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    Model ball = model("ball", "sphere", true, false);
    ball.rotates = true;
    doc.add_model(ball, placed({0, 0, 0}));
    key(doc, 1000, 0, placed({0, 0, 0}, glm::dvec3(1.0), {0, 90, 0}));
    auto timeline = timeline_of(doc);
    timeline->bake(3.0);
    const ani_rotation_segment *seg = rotation_at(*timeline, 0, 2.0);
    REQUIRE(seg);
    CHECK(seg->t0 == 1.0);
    const double rate = std::acos(-1.0) / 2.0;
    CAPTURE(seg->w.x, seg->w.y, seg->w.z);
    CHECK(glm::length(vec(seg->w) - glm::dvec3(0, rate, 0)) < 1e-8); // backward difference
    const glm::dquat q(seg->q0.w, seg->q0.x, seg->q0.y, seg->q0.z);
    CHECK(std::abs(std::abs(glm::dot(q, glm::angleAxis(rate, glm::dvec3(0, 1, 0)))) - 1.0) < 1e-12);
    CHECK(timeline->evaluate(3.0).models[0].center == glm::dvec3(0.0));
}

TEST_CASE("a bake cut into slices bounces, turns and comes to rest exactly as one bake") {
    auto scene = [] {
        Document doc;
        doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, 10.0));
        Model ball = model("ball", "sphere", true, true);
        ball.restitution = 0.7;
        ball.friction = 0.3;
        ball.rotates = true;
        ball.angular_velocity = {0, 2.0, 0}; // about the normal: the touching point does not slip
        doc.add_model(ball, placed({0.3, 2.0, 0.2}, 0.5));
        return doc;
    };
    const Document doc = scene();
    auto whole = timeline_of(doc), sliced = timeline_of(doc);
    whole->bake(12.0);
    for (double t = 0.37; t < 12.0; t += 0.37) sliced->bake(t);
    sliced->bake(12.0);
    const auto &a = whole->events(), &b = sliced->events();
    REQUIRE(a.size() == b.size());
    REQUIRE(a.size() > 10);
    for (size_t k = 0; k < a.size(); ++k) {
        CHECK(a[k].t == b[k].t);
        CHECK(a[k].speed == b[k].speed);
    }
    for (double t : {0.5, 1.0, 3.0, 6.0, 11.9}) {
        CAPTURE(t);
        // (A slice reports a segment from its own start: rounding of the same parabola.)
        CHECK(glm::length(whole->evaluate(t).models[1].center -
                          sliced->evaluate(t).models[1].center) < 1e-12);
        const ani_rotation_segment *ra = rotation_at(*whole, 1, t),
                                   *rb = rotation_at(*sliced, 1, t);
        REQUIRE(ra);
        REQUIRE(rb);
        CHECK(vec(ra->w) == vec(rb->w));
    }
    // Resting from t0 (1 + e) / (1 - e) with its spin about the normal kept (no friction acts
    // on a spin about the normal at a point contact in this model).
    const double r = unit_radius() * 0.5, e = 0.7, t0 = std::sqrt(2.0 * (2.0 - r) / G);
    const ani_motion_segment *still = segment_at(*whole, 1, 11.0);
    REQUIRE(still);
    CHECK(std::abs(still->t0 - t0 * (1.0 + e) / (1.0 - e)) < 1e-9);
    CHECK(vec(still->v0) == glm::dvec3(0.0));
    CHECK(vec(rotation_at(*whole, 1, 11.0)->w) == glm::dvec3(0, 2.0, 0));
}

TEST_CASE("a backspinning ball dropped on a rough floor sticks at its first bounce, then rolls "
          "without slipping, and comes to rest on the floor rolling at the closed-form speed") {
    // First bounce: v_x = 0, w_z = 4, slip u = w r. Sticking (|J_t| = 2 m u / 7 is far inside
    // mu J_n): v_x' = (5 * 0 - 2 r w) / 7 = -8 r / 7, w' = (2 r w - 0) / (7 r) = 8 / 7, no slip
    // after, so no later bounce rubs: it rolls at -8 r / 7 from t0 (1 + e) / (1 - e) on.
    const double r = unit_radius() * 0.5, h = 2.0, e = 0.6;
    Document doc;
    Model floor = model("floor", "plane", false, false);
    floor.friction = 1.0;
    doc.add_model(floor, placed({0, 0, 0}, 10.0));
    Model ball = model("ball", "sphere", true, true);
    ball.restitution = e;
    ball.rotates = true;
    ball.angular_velocity = {0, 0, 4};
    doc.add_model(ball, placed({0, h, 0}, 0.5));
    auto timeline = timeline_of(doc);
    timeline->bake(8.0);
    const double t0 = std::sqrt(2.0 * (h - r) / G), rest = t0 * (1.0 + e) / (1.0 - e);
    const ani_motion_segment *rolling = segment_at(*timeline, 1, rest + 1.0);
    REQUIRE(rolling);
    CHECK(std::abs(rolling->t0 - rest) < 1e-9);
    CHECK(std::abs(rolling->v0.x + 8.0 * r / 7.0) < 1e-12);
    CHECK(rolling->v0.y == 0.0);
    CHECK(vec(rolling->a) == glm::dvec3(0.0));
    CHECK(rolling->p0.y == Approx(r).epsilon(1e-12));
    const ani_rotation_segment *spin = rotation_at(*timeline, 1, rest + 1.0);
    REQUIRE(spin);
    CHECK(std::abs(spin->w.z - 8.0 / 7.0) < 1e-12);
    CHECK(std::abs(rolling->v0.x + spin->w.z * r) < 1e-12); // rolling: the contact point is still
    CHECK(timeline->events().size() < 200);
}

TEST_CASE("an open mesh with Rotates on is refused naming the model, a cone (its centre of mass "
          "off its origin) and a cylinder spun about its axis turn, without a warning") {
    std::vector<std::string> lines;
    Environment logged(
        {test::bin_dir().parent_path() / "assets"}, {test::bin_dir()},
        [&](ani_log_level, const std::string &, const std::string &m) { lines.push_back(m); });
    const auto bake = [&](const Document &doc) {
        Timeline t(doc, logged.plugins);
        std::vector<std::string> ids, warnings;
        for (const Model &m : doc.models()) ids.push_back(m.mesh);
        t.set_meshes(load_meshes(ids, logged.assets, {}, warnings));
        REQUIRE(warnings.empty());
        t.bake(2.0);
        return t.rotations(1).size();
    };
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, 10.0));
    Model sheet = model("sheet", "plane", true, true); // the plane: one open square
    sheet.rotates = true;
    doc.add_model(sheet, placed({0, 3, 0}));
    try {
        bake(doc);
        FAIL("an open mesh that rotates was baked");
    } catch (const std::exception &e) {
        CHECK_THAT(e.what(),
                   Catch::Contains("model 'sheet' cannot rotate: its mesh is not closed"));
    }
    // The cone mesh: apex at y = 1, base at y = -1, so its centre of mass is at y = -1/2 (a
    // quarter of the height above the base): it turns about that point (turning_test.cpp).
    Model cone = model("cone", "cone", true, true);
    cone.rotates = true;
    cone.angular_velocity = {0.0, 2.0, 0.0};
    doc.set_model(1, cone);
    lines.clear();
    CHECK(bake(doc) >= 1);
    CHECK(lines.empty());
    // A cylinder (its principal moments differ) spun about its axis of symmetry turns steadily
    // (Euler's equations: nothing changes w) until it lands flat on its base: one segment at w.
    Model can = model("can", "cylinder", true, true);
    can.rotates = true;
    can.angular_velocity = {0.0, 2.0, 0.0};
    doc.set_model(1, can);
    lines.clear();
    CHECK(bake(doc) >= 1);
    CHECK(lines.empty());
}

TEST_CASE("a cube dropped flat with e = 0.5 bounces at the closed-form times, comes to rest at the "
          "accumulation time without turning, then stays still for 1000 s") {
    // The cube mesh spans [-1, 1]: scaled 0.25, its bottom face is 0.25 below its center, and it
    // does not turn (no Rotates): its centre moves as a ball's of radius 0.25 would, so the
    // closed forms are the ball's (see the e = 0.8 ball above) with h - half for h - r.
    const double h = 2.0, half = 0.25, e = 0.5;
    Document doc;
    Settings s = doc.settings();
    s.max_time_ms = 1100000;
    doc.set_settings(s);
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    Model cube = model("cube", "cube", true, true);
    cube.restitution = e;
    doc.add_model(cube, placed({0.3, h, -0.2}, glm::dvec3(half)));
    auto timeline = timeline_of(doc);
    timeline->bake(1000.0);
    const double t0 = std::sqrt(2.0 * (h - half) / G), v0 = G * t0;
    const double rest = t0 * (1.0 + e) / (1.0 - e);
    const auto &events = timeline->events();
    REQUIRE(events.size() >= 10);
    CHECK(events.size() < 100); // the bounces below the Zeno threshold are not followed
    const auto [worst_t, worst_v] = bounce_errors(events, 10, t0, v0, e);
    for (size_t k = 0; k < 10; ++k) CHECK(std::abs(std::abs(events[k].normal.y) - 1.0) < 1e-12);
    CAPTURE(worst_t, worst_v, events.size());
    CHECK(worst_t < 1e-9);
    CHECK(worst_v < 1e-9);
    // Just after the first bounce it rises at e v0, straight up.
    const Frame up = timeline->evaluate(t0 + 0.01);
    CHECK(std::abs(up.models[1].velocity.y - (e * v0 - G * 0.01)) < 1e-9);
    CHECK(std::abs(up.models[1].velocity.x) < 1e-15);
    CHECK(std::abs(up.models[1].velocity.z) < 1e-15);
    // At rest from the accumulation time, its bottom face exactly on the floor.
    const ani_motion_segment *still = segment_at(*timeline, 1, rest + 1e-3);
    REQUIRE(still);
    CAPTURE(still->t0 - rest);
    CHECK(std::abs(still->t0 - rest) < 1e-9);
    CHECK(vec(still->v0) == glm::dvec3(0.0));
    CHECK(vec(still->a) == glm::dvec3(0.0));
    CHECK(still->p0.y == Approx(half).epsilon(1e-12));
    CHECK(events.back().t < rest);
    CHECK(timeline->rotations(1).empty());
    const glm::dvec3 at_rest = timeline->evaluate(rest + 1e-3).models[1].center;
    for (double t : {rest + 1.0, 10.0, 100.0, 567.89, 1000.0}) {
        const Frame f = timeline->evaluate(t);
        CHECK(f.models[1].center == at_rest); // bit for bit
        CHECK(f.models[1].velocity == glm::dvec3(0.0));
    }
}

TEST_CASE("two cubes of unequal mass meeting face to face with e = 0.5 leave with the velocities "
          "of Newton's law, momentum kept") {
    // Along x, a (mass ma, speed u) meets b (mass mb, at rest). Newton's law with the impulse
    // j on b: ma va' + mb vb' = ma u and vb' - va' = e u, so vb' = (1 + e) ma u / (ma + mb) and
    // va' = (ma - e mb) u / (ma + mb). Faces 0.25 from each centre: they touch when the centres
    // are 0.5 apart, at t = (3 - 0.5) / u.
    const double ma = 2.0, mb = 1.0, u = 3.0, e = 0.5, half = 0.25;
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    Model a = model("a", "cube", true, false), b = model("b", "cube", true, false);
    a.mass = ma;
    b.mass = mb;
    a.restitution = e; // b's 1: the pair takes the lower
    a.initial_velocity = {u, 0, 0};
    doc.add_model(a, placed({-3, 0, 0}, glm::dvec3(half)));
    doc.add_model(b, placed({0, 0, 0}, glm::dvec3(half)));
    auto timeline = timeline_of(doc);
    timeline->bake(4.0);
    REQUIRE(timeline->events().size() == 1);
    CHECK(timeline->events()[0].t == Approx((3.0 - 2.0 * half) / u).epsilon(1e-11));
    const Frame f = timeline->evaluate(4.0);
    const glm::dvec3 va = f.models[0].velocity, vb = f.models[1].velocity;
    CHECK(std::abs(va.x - (ma - e * mb) * u / (ma + mb)) < 1e-12);
    CHECK(std::abs(vb.x - (1.0 + e) * ma * u / (ma + mb)) < 1e-12);
    CHECK(std::abs((vb.x - va.x) - e * u) < 1e-12);
    CHECK(std::abs(ma * va.x + mb * vb.x - ma * u) < 1e-12);
    CHECK(glm::length(glm::dvec3(0.0, va.y, va.z)) < 1e-15);
    CHECK(glm::length(glm::dvec3(0.0, vb.y, vb.z)) < 1e-15);
    CHECK(timeline->rotations(0).empty());
    CHECK(timeline->rotations(1).empty());
}

TEST_CASE("a cube sliding obliquely into a rough wall with e = 0.5 leaves with half its normal "
          "speed and the slip friction took off") {
    // No gravity. The cube (half side 0.25) moves at v = (2, 0, 1) toward a static wall whose
    // face is the plane x = 2.9, with friction mu = 0.1 (the cube's 0: the pair takes the
    // higher). Normal impulse per unit mass (1 + e) 2 = 3; friction at most mu 3 = 0.3 < 1, the
    // slip along z, so it slips: v' = (-e 2, 0, 1 - 0.3) = (-1, 0, 0.7). Contact at
    // t = (2.9 - 0.25) / 2.
    const double e = 0.5, mu = 0.1, half = 0.25;
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    Model wall = model("wall", "cube", false, false);
    wall.friction = mu;
    doc.add_model(wall, placed({3, 0, 0}, {0.1, 2, 2}));
    Model cube = model("cube", "cube", true, false);
    cube.restitution = e;
    cube.initial_velocity = {2, 0, 1};
    doc.add_model(cube, placed({0, 0, 0}, glm::dvec3(half)));
    auto timeline = timeline_of(doc);
    timeline->bake(3.0);
    REQUIRE(timeline->events().size() == 1);
    CHECK(timeline->events()[0].t == Approx((2.9 - half) / 2.0).epsilon(1e-11));
    const glm::dvec3 v = timeline->evaluate(3.0).models[1].velocity;
    CHECK(std::abs(v.x - (-e * 2.0)) < 1e-12);
    CHECK(std::abs(v.y) < 1e-15);
    CHECK(std::abs(v.z - (1.0 - mu * (1.0 + e) * 2.0)) < 1e-12);
    CHECK(timeline->rotations(1).empty());
}

TEST_CASE("a cube thrown onto a rough floor with e = 0.5 loses speed at each bounce by friction, "
          "then slides on the floor until friction stops it") {
    // Level floor, mu = 0.1 (the floor's), e = 0.5 (the cube's), thrown at u = 3 m/s along x from
    // height h. Bounce k meets the floor at normal speed e^k v0 and takes the normal impulse
    // (1 + e) e^k v0 per unit mass; while it slips, friction takes mu times that off the speed
    // along x (it does not turn: the slip is the centre's). All bounces together take
    // mu (1 + e) v0 / (1 - e) = 1.76 < u, so it never sticks: from the bounces' accumulation
    // time it slides at u - mu (1 + e) v0 / (1 - e), less what the bounces below the Zeno
    // threshold would have taken (at most mu (1 + e) v_z / (1 - e) with v_z^2 / (2 g) <= 1e-9
    // max(1, |centre|)), and Coulomb friction decelerates it by mu g until it stops.
    const double h = 2.0, half = 0.25, e = 0.5, mu = 0.1, u = 3.0;
    Document doc;
    Model floor = model("floor", "plane", false, false);
    floor.friction = mu;
    doc.add_model(floor, placed({0, 0, 0}, glm::dvec3(100.0)));
    Model cube = model("cube", "cube", true, true);
    cube.restitution = e;
    cube.initial_velocity = {u, 0, 0};
    doc.add_model(cube, placed({0.3, h, -0.2}, glm::dvec3(half)));
    auto timeline = timeline_of(doc);
    timeline->bake(20.0);
    const double t0 = std::sqrt(2.0 * (h - half) / G), v0 = G * t0;
    const double rest = t0 * (1.0 + e) / (1.0 - e);
    const double slide = u - mu * (1.0 + e) * v0 / (1.0 - e);
    // Just after the first bounce: u - mu (1 + e) v0 along x, e v0 up.
    const Frame first = timeline->evaluate(t0 + 1e-3);
    CHECK(std::abs(first.models[1].velocity.x - (u - mu * (1.0 + e) * v0)) < 1e-12);
    CHECK(std::abs(first.models[1].velocity.y - (e * v0 - G * 1e-3)) < 1e-9);
    // Where the bounces leave it: flight k (after bounce k) lasts 2 e^(k+1) v0 / g at the speed
    // bounce k left along x.
    double x_rest = 0.3 + u * t0, along = u;
    for (int k = 0; k < 200; ++k) {
        along -= mu * (1.0 + e) * std::pow(e, k) * v0;
        x_rest += along * 2.0 * std::pow(e, k + 1) * v0 / G;
    }
    const double stop = rest + slide / (mu * G), x_stop = x_rest + slide * slide / (2.0 * mu * G);
    // What the bounces too small to follow leave out: their friction (above), and the time they
    // take, 2 v_z / (g (1 - e)), over which friction acts as mu g (1 + e) / 2 instead of mu g.
    const double vz_max = std::sqrt(2.0 * G * 1e-9 * 4.0);
    const double dv = mu * (1.0 + e) * vz_max / (1.0 - e) + 2.0 * mu * vz_max / (1.0 - e);
    for (double t : {rest + 1e-3, 0.5 * (rest + stop)}) {
        CAPTURE(t);
        const Frame f = timeline->evaluate(t);
        CHECK(f.models[1].center.y == Approx(half).epsilon(1e-12)); // on the floor, not through
        CHECK(f.models[1].velocity.y == 0.0);
        CHECK(std::abs(f.models[1].velocity.x - (slide - mu * G * (t - rest))) <= dv);
    }
    const Frame at_5 = timeline->evaluate(5.0), at_20 = timeline->evaluate(20.0);
    for (const Frame *f : {&at_5, &at_20}) {
        CHECK(f->models[1].velocity == glm::dvec3(0.0)); // stopped, exactly
        CHECK(f->models[1].center.y == Approx(half).epsilon(1e-12));
        // (dv changes the distance slid, v^2 / (2 mu g), by at most v dv / (mu g); measured
        // 2.3e-5 m of the bound's 2.5e-4.)
        CHECK(std::abs(f->models[1].center.x - x_stop) <= slide * dv / (mu * G) + 1e-9);
    }
    CHECK(at_5.models[1].center == at_20.models[1].center);
    CHECK(timeline->events().size() < 100);
    CHECK(timeline->rotations(1).empty());
}
