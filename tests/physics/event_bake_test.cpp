// physics.custom's event-driven bake through the real timeline, on the generated meshes,
// against the closed forms of physics.md's exact scenes.
#include "assets/asset_paths.hpp"
#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "timeline/timeline.hpp"

#include "scene_support.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>

using namespace animator;
using namespace physics_test;
namespace fs = std::filesystem;

TEST_CASE("a ball dropped on a floor bounces 1000 times, every apex at the drop height") {
    const double r = unit_radius(), h = 1.5;
    Document doc;
    Settings s = doc.settings();
    s.max_time_ms = 700000;
    doc.set_settings(s);
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, 10.0));
    doc.add_model(model("ball", "sphere", true, true), placed({0.3, h, 0.2}));
    auto timeline = timeline_of(doc);
    const double first = std::sqrt(2.0 * (h - r) / G), period = 2.0 * first;
    const double until = first + 1000.5 * period;
    timeline->bake(until);
    const auto &events = timeline->events();
    REQUIRE(events.size() >= 1001);
    for (size_t k = 0; k < 1001; ++k) {
        CAPTURE(k);
        // Bounce k at first + k * period (physics.md scene 1).
        CHECK(events[k].t == Approx(first + static_cast<double>(k) * period).epsilon(1e-11));
        CHECK(events[k].normal.y == Approx(1.0));
        CHECK(events[k].speed == Approx(G * first).epsilon(1e-9));
    }
    // The apex after 1000 bounces, half a period after the last: at the drop height.
    const double apex_time = events[999].t + first;
    const double apex = timeline->evaluate(apex_time).models[1].center.y;
    CHECK(std::abs(apex - h) / h < 1e-9);
}

TEST_CASE(
    "Newton's cradle: after the exchanges only the last ball moves, with the striker's velocity") {
    const Document doc =
        open_document(env().plugins, test::source_dir() / "assets/animations/cradle.ani").document;
    auto timeline = timeline_of(doc);
    timeline->bake(5.0);
    const Frame end = timeline->evaluate(5.0);
    const int striker = doc.find_model("striker"), last = doc.find_model("ball4");
    for (int m = 0; m < static_cast<int>(doc.models().size()); ++m) {
        CAPTURE(doc.models()[static_cast<size_t>(m)].name);
        const glm::dvec3 v = end.models[static_cast<size_t>(m)].velocity;
        if (m == last) {
            CHECK(v.x == Approx(2.0).epsilon(1e-12));
        } else if (doc.models()[static_cast<size_t>(m)].dynamics) {
            CHECK(glm::length(v) < 1e-12);
        }
    }
    CHECK(timeline->events().size() == 4); // striker -> 1 -> 2 -> 3 -> 4
    (void)striker;
}

TEST_CASE("two equal spheres, one at rest, meeting off-centre leave at 90 degrees") {
    const double r = unit_radius();
    Document doc;
    Model a = model("a", "sphere", true, false);
    a.initial_velocity = {3, 0, 0};
    doc.add_model(a, placed({-5, 0.6 * r, 0}));
    doc.add_model(model("b", "sphere", true, false), placed({0, 0, 0}));
    auto timeline = timeline_of(doc);
    timeline->bake(10.0);
    REQUIRE(timeline->events().size() == 1);
    const Frame f = timeline->evaluate(10.0);
    const glm::dvec3 va = f.models[0].velocity, vb = f.models[1].velocity;
    CHECK(glm::dot(va, vb) == Approx(0.0).margin(1e-12));
    // Momentum and energy kept (equal masses).
    CHECK(glm::length(va + vb - glm::dvec3(3, 0, 0)) < 1e-12);
    CHECK(glm::dot(va, va) + glm::dot(vb, vb) == Approx(9.0).epsilon(1e-14));
    // The contact normal at 0.6 r offset: sin = 0.6 r / 2 r = 0.3.
    CHECK(std::abs(timeline->events()[0].normal.y) == Approx(0.3).epsilon(1e-9));
}

TEST_CASE("a model without Dynamics stops at the moment of contact") {
    const double r = unit_radius(), h = 3.0;
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, 10.0));
    doc.add_model(model("stone", "sphere", false, true), placed({0, h, 0}));
    auto timeline = timeline_of(doc);
    timeline->bake(5.0);
    const double landing = std::sqrt(2.0 * (h - r) / G);
    REQUIRE(timeline->events().size() == 1);
    CHECK(timeline->events()[0].t == Approx(landing).epsilon(1e-12));
    const Frame f = timeline->evaluate(4.0);
    CHECK(f.models[1].center.y == Approx(r).epsilon(1e-12));
    CHECK(f.models[1].velocity == glm::dvec3(0.0));
}

TEST_CASE("a small fast sphere reflects off a thin wall at any speed, never passing") {
    const double r = unit_radius() * 0.1;
    for (double speed : {1.0, 100.0, 1e4, 1e6}) {
        CAPTURE(speed);
        Document doc;
        // The plane stood up: rotated 90 degrees about Z, its face is the plane x = 0.
        ModelState wall = placed({0, 0, 0}, 2.0);
        wall.angles = {0, 0, 90};
        doc.add_model(model("wall", "plane", false, false), wall);
        Model ball = model("ball", "sphere", true, false);
        ball.initial_velocity = {-speed, 0, 0};
        doc.add_model(ball, placed({1, 0.1, 0.1}, 0.1));
        auto timeline = timeline_of(doc);
        const double hit = (1.0 - r) / speed;
        timeline->bake(std::min(60.0, 3.0 * hit));
        REQUIRE(!timeline->events().empty());
        CHECK(timeline->events()[0].t == Approx(hit).epsilon(1e-9));
        const Frame f = timeline->evaluate(timeline->baked_until());
        CHECK(f.models[1].center.x > 0.0);
        CHECK(f.models[1].velocity.x == Approx(speed).epsilon(1e-12));
    }
}

TEST_CASE(
    "a ball in a closed box for 300000 s: each coordinate an exact triangle wave, energy kept") {
    const double r = unit_radius() * 0.5, half = 5.0, L = half - r;
    Document doc;
    Settings s = doc.settings();
    s.max_time_ms = 300000000;
    doc.set_settings(s);
    doc.add_model(model("box", "cube", false, false),
                  placed({0, 0, 0}, half)); // the inside of a cube
    Model ball = model("ball", "sphere", true, false);
    const glm::dvec3 v0(0.13, 0.07, 0.03); // a 300000 s run of 7,666 bounces
    ball.initial_velocity = v0;
    doc.add_model(ball, placed({0.5, -1.0, 2.0}, 0.5));
    auto timeline = timeline_of(doc);
    timeline->bake(300000.0);
    // The closed form: unfold the motion along each axis onto a line of period 4 L.
    auto wave = [&](double x0, double v, double t) {
        const double period = 4.0 * L;
        double u = std::fmod(x0 + L + v * t, period);
        if (u < 0.0) u += period;
        return -L + (u <= 2.0 * L ? u : period - u);
    };
    const glm::dvec3 p0(0.5, -1.0, 2.0);
    for (double t : {0.0, 1234.5, 99999.0, 250000.25, 300000.0}) {
        CAPTURE(t);
        const ModelPose pose = timeline->evaluate(t).models[1];
        for (int c = 0; c < 3; ++c) {
            CHECK(pose.center[c] == Approx(wave(p0[c], v0[c], t)).margin(1e-9));
            CHECK(std::abs(pose.center[c]) <= L + 1e-12); // inside the box
        }
        // Reflections off axis-aligned faces negate one component exactly: the speed is kept.
        CHECK(glm::length(pose.velocity) == glm::length(v0));
    }
    // Wall hits per axis: the unfolded coordinate, from x0 + L, passes 2 L k for k = 1, 2, ...
    size_t hits = 0;
    for (int c = 0; c < 3; ++c)
        hits += static_cast<size_t>(std::floor((p0[c] + L + v0[c] * 300000.0) / (2.0 * L)));
    CHECK(timeline->events().size() == hits);
}

TEST_CASE("models that start overlapping are reported once and ignored until they separate") {
    std::vector<std::string> log;
    Environment logged(
        {test::bin_dir().parent_path() / "assets"}, {test::bin_dir()},
        [&](ani_log_level, const std::string &, const std::string &m) { log.push_back(m); });
    const double r = unit_radius();
    Document doc;
    Model a = model("a", "sphere", true, false), b = model("b", "sphere", true, false);
    a.initial_velocity = {-1, 0, 0};
    b.initial_velocity = {1, 0, 0};
    doc.add_model(a, placed({-0.5 * r, 0, 0})); // centers r apart: overlapping by r
    doc.add_model(b, placed({0.5 * r, 0, 0}));
    // Walls at x = -4 and x = 4 send them back towards each other.
    ModelState left = placed({-4, 0, 0}, 3.0), right = placed({4, 0, 0}, 3.0);
    left.angles = right.angles = {0, 0, 90};
    doc.add_model(model("left", "plane", false, false), left);
    doc.add_model(model("right", "plane", false, false), right);
    Timeline timeline(doc, logged.plugins);
    std::vector<std::string> ids = {"sphere", "sphere", "plane", "plane"}, warnings;
    timeline.set_meshes(load_meshes(ids, logged.assets, {}, warnings));
    timeline.bake(10.0);

    size_t reports = 0;
    for (const std::string &m : log)
        reports += m.find("'a' and 'b' overlap at t = 0") != std::string::npos;
    CHECK(reports == 1);
    // No event at t = 0 between them; each hits its wall at (4 - r - 0.5 r) s; then they meet
    // in the middle, centers 2 r apart, after travelling back.
    const auto &events = timeline.events();
    REQUIRE(events.size() >= 3);
    const double wall = 4.0 - 1.5 * r;
    CHECK(events[0].t == Approx(wall).epsilon(1e-12));
    CHECK(events[1].t == Approx(wall).epsilon(1e-12));
    const double meet = wall + (4.0 - r - r) / 1.0;
    CHECK(events[2].t == Approx(meet).epsilon(1e-12));
    CHECK(((events[2].a == 0 && events[2].b == 1) || (events[2].a == 1 && events[2].b == 0)));
}

TEST_CASE(
    "Newton's cradle with touching balls: the exchanges pass along at once, deterministically") {
    // Five balls of radius r in a row, centers exactly 2 r apart (touching), the striker at
    // 2 m/s meeting the first: the contacts are simultaneous, resolved one after the other.
    const double r = unit_radius();
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    Model striker = model("striker", "sphere", true, false);
    striker.initial_velocity = {2, 0, 0};
    doc.add_model(striker, placed({-3.0, 0, 0}));
    for (int k = 0; k < 4; ++k)
        doc.add_model(model("ball" + std::to_string(k), "sphere", true, false),
                      placed({2.0 * r * k, 0, 0}));
    auto one = timeline_of(doc), two = timeline_of(doc);
    one->bake(4.0);
    two->bake(4.0);
    const auto &events = one->events();
    REQUIRE(events.size() == 4);
    const double meet = (3.0 - 2.0 * r) / 2.0;
    for (const auto &e : events) CHECK(e.t == Approx(meet).epsilon(1e-12));
    const Frame end = one->evaluate(4.0);
    double energy = 0.0;
    for (size_t m = 0; m < 5; ++m)
        energy += 0.5 * glm::dot(end.models[m].velocity, end.models[m].velocity);
    CHECK(energy == Approx(0.5 * 4.0).epsilon(1e-12)); // no energy gained or lost
    CHECK(end.models[4].velocity.x == Approx(2.0).epsilon(1e-12));
    for (size_t m = 0; m < 4; ++m) CHECK(glm::length(end.models[m].velocity) < 1e-12);
    // The same bake twice gives the same events in the same order.
    REQUIRE(two->events().size() == events.size());
    for (size_t k = 0; k < events.size(); ++k) {
        CHECK(two->events()[k].a == events[k].a);
        CHECK(two->events()[k].b == events[k].b);
        CHECK(two->events()[k].t == events[k].t);
    }
}

TEST_CASE("a ball flying into the inside corner of a box meets both walls at once and comes "
          "straight back") {
    const double r = unit_radius() * 0.5, half = 3.0;
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    doc.add_model(model("box", "cube", false, false), placed({0, 0, 0}, half));
    Model ball = model("ball", "sphere", true, false);
    ball.initial_velocity = {1, 1, 0};
    doc.add_model(ball, placed({0, 0, 0}, 0.5));
    auto timeline = timeline_of(doc);
    timeline->bake(10.0);
    const double corner = half - r; // the center reaches x = y = half - r at the same time
    const auto &events = timeline->events();
    REQUIRE(events.size() >= 2);
    CHECK(events[0].t == Approx(corner).epsilon(1e-12));
    CHECK(events[1].t == Approx(corner).epsilon(1e-12));
    const ModelPose back = timeline->evaluate(corner + 1.0).models[1];
    CHECK(back.velocity.x == Approx(-1.0).epsilon(1e-12));
    CHECK(back.velocity.y == Approx(-1.0).epsilon(1e-12));
    CHECK(back.center.x == Approx(corner - 1.0).epsilon(1e-12));
}

TEST_CASE("two spheres of unequal mass meeting obliquely and slowly under gravity exchange along "
          "the normal only") {
    // Both fall under gravity, so their relative motion is a straight line: they meet when
    // |d + e t| = ra + rb. Approach speed 0.1 m/s, below Bullet's restitution threshold.
    const double ra = unit_radius() * 0.5, rb = unit_radius() * 0.8, ma = 1.0, mb = 3.5;
    const glm::dvec3 pa(-2.0, 5.0, 0.2), pb(0.0, 5.3, 0.0), va(0.1, 0.0, 0.0), vb(0.0, 0.0, 0.0);
    Document doc;
    Model a = model("a", "sphere", true, true), b = model("b", "sphere", true, true);
    a.mass = ma;
    b.mass = mb;
    a.initial_velocity = va;
    b.initial_velocity = vb;
    doc.add_model(a, placed(pa, 0.5));
    doc.add_model(b, placed(pb, 0.8));
    auto timeline = timeline_of(doc);
    timeline->bake(9.0);
    REQUIRE(timeline->events().size() == 1);
    const glm::dvec3 d = pa - pb, e = va - vb;
    const double R = ra + rb, qa = glm::dot(e, e), qb = glm::dot(d, e), qc = glm::dot(d, d) - R * R;
    const double t = (-qb - std::sqrt(qb * qb - qa * qc)) / qa;
    CHECK(timeline->events()[0].t == Approx(t).epsilon(1e-12));
    const glm::dvec3 n = (d + e * t) / R; // from b towards a
    const glm::dvec3 ga(0.0, -9.81 * t, 0.0);
    const glm::dvec3 ua = va + ga, ub = vb + ga; // velocities at the contact
    const double una = glm::dot(ua, n), unb = glm::dot(ub, n);
    const double una2 = ((ma - mb) * una + 2.0 * mb * unb) / (ma + mb);
    const double unb2 = ((mb - ma) * unb + 2.0 * ma * una) / (ma + mb);
    const glm::dvec3 expect_a = ua + (una2 - una) * n, expect_b = ub + (unb2 - unb) * n;
    const Frame f = timeline->evaluate(t + 0.5);
    const glm::dvec3 later(0.0, -9.81 * 0.5, 0.0);
    CHECK(glm::length(f.models[0].velocity - (expect_a + later)) < 1e-12);
    CHECK(glm::length(f.models[1].velocity - (expect_b + later)) < 1e-12);
    CHECK(timeline->events()[0].speed == Approx(unb - una).epsilon(1e-10)); // closing along n
}

TEST_CASE(
    "a model without Dynamics stopped by a contact stays stopped in a bake resumed after it") {
    // A stone (Dynamics off, Gravity on) falls onto a static floor and stops there; a bake
    // resumed after the landing must not let it fall again.
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, 5.0));
    doc.add_model(model("stone", "sphere", false, true), placed({0, 5, 0}, 0.5));
    auto whole = timeline_of(doc), parts = timeline_of(doc);
    whole->bake(3.0);
    const double landing = std::sqrt(2.0 * (5.0 - 0.5 * unit_radius()) / G);
    parts->bake(landing + 0.1);
    parts->bake(3.0);
    for (double t : {landing + 0.05, 1.5, 2.9}) {
        CAPTURE(t);
        CHECK(whole->evaluate(t).models[1].center.y == Approx(0.5 * unit_radius()).epsilon(1e-9));
        CHECK(parts->evaluate(t).models[1].center.y == whole->evaluate(t).models[1].center.y);
    }
}
