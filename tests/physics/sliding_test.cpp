// physics.custom: contacts that last (issue 19): resting and sliding with Coulomb friction, through
// the real timeline and the shipped scenes, against closed forms derived in the comments.
#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "timeline/timeline.hpp"

#include "scene_support.hpp"
#include "tipping_pendulum.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>

using namespace animator;
using namespace physics_test;

namespace {

Document shipped_scene(const std::string &name) {
    return open_document(env().plugins, test::source_dir() / "assets/scenes" / name).document;
}

const ModelState &start_of(const Document &doc, int model) {
    return *doc.keyframes().front().states[static_cast<size_t>(model)];
}

} // namespace

TEST_CASE("a box placed on a floor rests exactly for 1000 s, with no contact to follow") {
    const Document doc = shipped_scene("resting_box.lua");
    const int box = model_named(doc, "box");
    REQUIRE(doc.models()[box].restitution == 0.5);
    REQUIRE(doc.models()[box].friction == 0.5);
    REQUIRE(doc.models()[box].rotates);
    auto timeline = timeline_of(doc);
    timeline->bake(1000.0);
    const ModelState &s0 = start_of(doc, box);
    for (double t : {0.0, 1e-6, 1.0, 10.0, 100.0, 1000.0}) {
        CAPTURE(t);
        const ModelPose p = timeline->evaluate(t).models[static_cast<size_t>(box)];
        CHECK(glm::length(p.center - s0.center) <= 1e-12);
        CHECK(glm::length(p.angles - s0.angles) <= 1e-12);
        CHECK(p.velocity == glm::dvec3(0.0));
    }
    // It costs nothing: no contact, and a handful of predictions over 1000 s.
    CHECK(timeline->events().empty());
    CHECK(timeline->stats().backend_counts.at("predictions") < 20);
}

TEST_CASE("a puck slides to rest on a parabola and stops at v0 / (mu g)") {
    const Document doc = shipped_scene("sliding_puck.lua");
    const int puck = model_named(doc, "puck");
    const double mu = doc.models()[puck].friction, v0 = 3.0;
    REQUIRE(mu == 0.3);
    const glm::dvec3 c0 = start_of(doc, puck).center;
    auto timeline = timeline_of(doc);
    timeline->bake(3.0);
    // x(t) = x0 + v0 t - mu g t^2 / 2 until t_s = v0 / (mu g), then x0 + v0^2 / (2 mu g).
    const double ts = v0 / (mu * G);
    auto x_at = [&](double t) {
        const double s = std::min(t, ts);
        return c0.x + v0 * s - 0.5 * mu * G * s * s;
    };
    for (double t : {0.1, 0.25, 0.5, 0.75, 1.0, ts, 1.5, 3.0}) {
        CAPTURE(t);
        const ModelPose p = timeline->evaluate(t).models[static_cast<size_t>(puck)];
        CHECK(std::abs(p.center.x - x_at(t)) < 1e-9);
        CHECK(p.center.y == c0.y);
        CHECK(p.center.z == c0.z);
        CHECK(std::abs(p.velocity.x - std::max(0.0, v0 - mu * G * t)) < 1e-9);
    }
    CHECK(timeline->evaluate(1.5).models[static_cast<size_t>(puck)].velocity == glm::dvec3(0.0));
    // The stop: where a segment starts at rest.
    double stop = -1.0;
    for (const ani_motion_segment &s : timeline->segments(puck))
        if (stop < 0.0 && s.t0 > 0.0 && s.v0.x == 0.0 && s.a.x == 0.0) stop = s.t0;
    CHECK(std::abs(stop - ts) < 1e-9);
    CHECK(timeline->events().empty());
}

TEST_CASE("on a 20 degree ramp a box with mu = 0.2 slides down at g (sin - mu cos), one with "
          "mu = 0.5 stays still") {
    const Document doc = shipped_scene("ramp_boxes.lua");
    const int sliding = model_named(doc, "sliding"), sticking = model_named(doc, "sticking");
    REQUIRE(doc.models()[sliding].friction == 0.2);
    REQUIRE(doc.models()[sticking].friction == 0.5);
    auto timeline = timeline_of(doc);
    timeline->bake(100.0);
    const double theta = glm::radians(20.0), mu = 0.2;
    const double a = G * (std::sin(theta) - mu * std::cos(theta)); // 1.512 m/s^2
    const glm::dvec3 down_slope(-std::cos(theta), -std::sin(theta), 0.0);
    const glm::dvec3 c0 = start_of(doc, sliding).center;
    for (double t : {0.5, 1.0, 2.0, 3.0}) {
        CAPTURE(t);
        const ModelPose p = timeline->evaluate(t).models[static_cast<size_t>(sliding)];
        CHECK(glm::length(p.center - (c0 + 0.5 * a * t * t * down_slope)) < 1e-9);
        CHECK(glm::length(p.velocity - a * t * down_slope) < 1e-9);
        CHECK(glm::length(p.angles - start_of(doc, sliding).angles) < 1e-9); // it does not turn
    }
    const ModelState &s0 = start_of(doc, sticking);
    for (double t : {1.0, 10.0, 100.0}) {
        CAPTURE(t);
        const ModelPose p = timeline->evaluate(t).models[static_cast<size_t>(sticking)];
        CHECK(glm::length(p.center - s0.center) <= 1e-12);
        CHECK(glm::length(p.angles - s0.angles) <= 1e-12);
        CHECK(p.velocity == glm::dvec3(0.0));
    }
}

TEST_CASE("a ball launched without spin skids, then rolls from t* = 2 v0 / (7 mu g) at 5/7 v0") {
    const Document doc = shipped_scene("rolling_ball.lua");
    const int ball = model_named(doc, "ball");
    const double mu = doc.models()[ball].friction, v0 = 4.0;
    REQUIRE(mu == 0.2);
    REQUIRE(doc.models()[ball].rotates);
    auto timeline = timeline_of(doc);
    timeline->bake(3.0);
    // Its radius as the backend holds it on the floor: its centre's height (the mesh's radius, in
    // single precision).
    const double r = timeline->evaluate(0.0).models[static_cast<size_t>(ball)].center.y;
    REQUIRE(std::abs(r - 0.5) < 1e-7);
    // Skidding: v = v0 - mu g t, w = -(5 mu g / 2r) t about z (the slip v - r w x n falls at
    // 7/2 mu g), so the orientation is a turn of -(5 mu g / 4r) t^2 about z; it ends at t*.
    const double ts = 2.0 * v0 / (7.0 * mu * G), v1 = 5.0 / 7.0 * v0;
    const glm::dquat q0 = timeline->rotation_at(ball, 0.0)
                              ? orientation_at(*timeline->rotation_at(ball, 0.0), 0.0)
                              : glm::dquat(1.0, 0.0, 0.0, 0.0);
    for (double t : {0.1, 0.3, 0.5}) {
        CAPTURE(t);
        const ModelPose p = timeline->evaluate(t).models[static_cast<size_t>(ball)];
        CHECK(std::abs(p.velocity.x - (v0 - mu * G * t)) < 1e-9);
        const RotationSegment *s = timeline->rotation_at(ball, t);
        REQUIRE(s);
        CHECK(glm::length(angular_velocity_at(*s, t) - glm::dvec3(0, 0, -2.5 * mu * G / r * t)) <
              1e-9);
        const glm::dquat expected =
            glm::angleAxis(-1.25 * mu * G / r * t * t, glm::dvec3(0, 0, 1)) * q0;
        const glm::dquat d = orientation_at(*s, t) * glm::conjugate(expected);
        CHECK(2.0 * std::atan2(glm::length(glm::dvec3(d.x, d.y, d.z)), std::abs(d.w)) < 1e-12);
    }
    // Rolling: where a motion segment starts without acceleration.
    double rolls = -1.0;
    for (const ani_motion_segment &s : timeline->segments(ball))
        if (rolls < 0.0 && s.t0 > 0.0 && s.a.x == 0.0) rolls = s.t0;
    CHECK(std::abs(rolls - ts) < 1e-9);
    for (double t : {ts + 1e-6, 1.0, 2.0, 3.0}) {
        CAPTURE(t);
        const ModelPose p = timeline->evaluate(t).models[static_cast<size_t>(ball)];
        CHECK(std::abs(p.velocity.x - v1) < 1e-9);
        CHECK(p.velocity.y == 0.0);
        CHECK(p.center.y == r);
        const RotationSegment *s = timeline->rotation_at(ball, t);
        REQUIRE(s);
        CHECK(glm::length(angular_velocity_at(*s, t) - glm::dvec3(0, 0, -v1 / r)) < 1e-9);
    }
    // Where it is: v0 t* - mu g t*^2 / 2, then v1 a second.
    const double x_ts = -4.0 + v0 * ts - 0.5 * mu * G * ts * ts;
    CHECK(std::abs(timeline->evaluate(2.0).models[static_cast<size_t>(ball)].center.x -
                   (x_ts + v1 * (2.0 - ts))) < 1e-9);
    CHECK(timeline->events().empty());
}

TEST_CASE("a ball dropped from rest onto a box placed on a floor meets it at sqrt(2 h / g)") {
    // The box rests from t = 0 and never moves before the ball arrives, so the ball's only
    // prediction is the one it makes at rest at t = 0: it has to see the box it falls onto
    // (it used to take no speed for no motion, and fell through the box).
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, 10.0));
    Model box = model("box", "cube", true, true);
    box.rotates = true;
    doc.add_model(box, placed({0, 0.5, 0}, 0.5));
    doc.add_model(model("ball", "sphere", true, true), placed({0.4, 4, 0.1}, 0.3));
    auto timeline = timeline_of(doc);
    timeline->bake(1.0);
    const double r = 0.3 * unit_radius(), fall = 4.0 - r - 1.0;
    REQUIRE(!timeline->events().empty());
    const ani_collision_event &first = timeline->events().front();
    CHECK(std::abs(first.t - std::sqrt(2.0 * fall / G)) < 1e-12);
    CHECK(((first.a == 1 && first.b == 2) || (first.a == 2 && first.b == 1)));
}

TEST_CASE("a stack of three boxes stands exactly still for 1000 s, and a ball dropped on it comes "
          "to rest on top") {
    const Document doc = shipped_scene("box_stack.lua");
    const int ball = model_named(doc, "ball");
    const int boxes[] = {model_named(doc, "bottom"), model_named(doc, "middle"),
                         model_named(doc, "top")};
    for (int b : boxes) {
        REQUIRE(doc.models()[b].restitution == 0.5);
        REQUIRE(doc.models()[b].friction == 0.5);
        REQUIRE(doc.models()[b].rotates);
    }
    auto timeline = timeline_of(doc);
    timeline->bake(1000.0);
    for (double t : {0.0, 0.5, 1.0, 2.0, 10.0, 100.0, 1000.0}) {
        CAPTURE(t);
        const Frame f = timeline->evaluate(t);
        for (int b : boxes) {
            CAPTURE(b);
            const ModelState &s0 = start_of(doc, b);
            CHECK(glm::length(f.models[static_cast<size_t>(b)].center - s0.center) <= 1e-12);
            CHECK(glm::length(f.models[static_cast<size_t>(b)].angles - s0.angles) <= 1e-12);
            CHECK(f.models[static_cast<size_t>(b)].velocity == glm::dvec3(0.0));
        }
    }
    // The ball falls 5 - r - 3 onto the top box, bounces there as on a floor (e = 0.5: the
    // stack under it rests on the floor, which takes the blows), and rests on it from the
    // accumulation time t0 (1 + e) / (1 - e).
    const double r = 0.3 * unit_radius(), e = 0.5;
    const double t0 = std::sqrt(2.0 * (5.0 - r - 3.0) / G);
    REQUIRE(!timeline->events().empty());
    CHECK(std::abs(timeline->events().front().t - t0) < 1e-12);
    CHECK(std::abs(timeline->events()[1].t - t0 * (1.0 + 2.0 * e)) < 1e-12);
    for (double t : {t0 * (1.0 + e) / (1.0 - e) + 1e-3, 10.0, 1000.0}) {
        CAPTURE(t);
        const ModelPose p = timeline->evaluate(t).models[static_cast<size_t>(ball)];
        CHECK(std::abs(p.center.y - (3.0 + r)) < 1e-9);
        CHECK(p.velocity == glm::dvec3(0.0));
    }
    // All of it at little cost: no contact after the ball's last, a few dozen predictions.
    CHECK(timeline->events().back().t < t0 * (1.0 + e) / (1.0 - e) + 1e-6);
    CHECK(timeline->events().size() < 40);
    CHECK(timeline->stats().backend_counts.at("predictions") < 100);
}

namespace {

// The contact force that holds a cube of side s turning about its edge from phi0 at rest, over its
// weight, at phi: its centre, rho = s / sqrt(2) from the edge, at (rho sin phi, rho cos phi) moves
// with phi'' = w2 sin phi and phi'^2 = 2 w2 (cos phi0 - cos phi); F = m a_x, N = m (g + a_y).
void edge_force(double w2, double phi0, double phi, double &F, double &N) {
    const double rho = 1.0 / std::sqrt(2.0), acc = w2 * std::sin(phi),
                 rate2 = 2.0 * w2 * (std::cos(phi0) - std::cos(phi));
    F = rho * (acc * std::cos(phi) - rate2 * std::sin(phi));
    N = G + rho * (-acc * std::sin(phi) - rate2 * std::cos(phi));
}

} // namespace

TEST_CASE("a cube leaning on its edge tips over as the pendulum equation says, and rests on its "
          "face") {
    // The cube (side s = 1 m) stands on its edge along z, turned 30 degrees: its centre of mass
    // is 15 degrees past the vertical through the edge. Held at the edge by friction (it needs
    // F / N up to 0.397, at 36 degrees, below the scene's mu = 0.5), it turns about it as an
    // upside-down pendulum (tipping_pendulum.hpp), from phi = 15 degrees at rest, until phi = 45
    // degrees, when its face lands. The bake tips it in closed form (physics.md, "Tipping"): one
    // hinge, no contact on the way.
    const Document doc = shipped_scene("tipping_cube.lua");
    const int box = model_named(doc, "box");
    auto timeline = timeline_of(doc);
    timeline->bake(5.0);
    const double w2 = tipping::pendulum_rate(G, 1.0), deg = M_PI / 180.0;
    double phi = 15.0 * deg, rate = 0.0, t = 0.0;
    const double h = 1e-6;
    double next_check = 0.01;
    while (phi < 44.0 * deg) {
        tipping::step(w2, h, phi, rate);
        t += h;
        if (t >= next_check - 0.5 * h) {
            // The cube's turn about z is 45 degrees less phi; its centre stays 1/sqrt(2) from
            // the edge, which stays where it was (x = -0.5 (cos 30 - sin 30)).
            const ModelPose p = timeline->evaluate(t).models[static_cast<size_t>(box)];
            const double err = std::abs(p.angles.z - (45.0 - phi / deg));
            const glm::dvec3 arm =
                p.center -
                glm::dvec3(-0.5 * (std::cos(30 * deg) - std::sin(30 * deg)), 0.0, p.center.z);
            CAPTURE(t, err);
            CHECK(err < 1e-8);
            // (The edge is where the first contact found it, 1e-6 s after the start, 5e-12 m
            // lower: within the contacts' slack.)
            CHECK(std::abs(glm::length(arm) - std::sqrt(0.5)) < 1e-10);
            CHECK(std::abs(p.center.z) < 1e-12);
            next_check += 0.01;
        }
    }
    // The face lands when phi reaches 45 degrees: the first contact after the start, at the
    // speed of its far edge, s phi'.
    const double landing =
        tipping::until(w2, 15.0 * deg, [&](double p) { return p >= 45.0 * deg; });
    const ani_collision_event *landed = nullptr;
    for (const ani_collision_event &e : timeline->events())
        if (e.t > 1e-3) {
            landed = &e;
            break;
        }
    REQUIRE(landed);
    CAPTURE(landed->t - landing);
    CHECK(std::abs(landed->t - landing) < 1e-9);
    CHECK(std::abs(landed->speed - std::sqrt(2.0 * w2 * (std::cos(15 * deg) - std::cos(45 * deg)))) <
          1e-9);
    CHECK(timeline->stats().backend_counts.at("tips about an edge") == 1);
    // Then it bounces on its face, slides and rests on it: flat, still, its centre s / 2 up.
    const ModelPose end = timeline->evaluate(5.0).models[static_cast<size_t>(box)];
    CHECK(end.velocity == glm::dvec3(0.0));
    CHECK(std::abs(end.center.y - 0.5) < 1e-6);
    CHECK(std::abs(std::remainder(end.angles.z, 90.0)) < 1e-4);
    CHECK(timeline->events().size() < 30000); // measured: 16,907, the face's bounces
}

TEST_CASE("a cube tipping on a floor too slippery to hold its edge turns about it until friction "
          "gives way, then slides and rests") {
    // tipping_cube.lua with mu = 0.3: the edge holds while F <= mu N, to phi = 23.4 degrees
    // (edge_force), and then slips: the hinge ends there, in closed form, at the time the
    // pendulum reaches that angle.
    Document doc = shipped_scene("tipping_cube.lua");
    const int box = model_named(doc, "box");
    Model m = doc.models()[static_cast<size_t>(box)];
    m.friction = 0.3;
    doc.set_model(box, m);
    auto timeline = timeline_of(doc);
    timeline->bake(5.0);
    const double w2 = tipping::pendulum_rate(G, 1.0), deg = M_PI / 180.0;
    const double slips = tipping::until(w2, 15.0 * deg, [&](double p) {
        double F, N;
        edge_force(w2, 15.0 * deg, p, F, N);
        return F > 0.3 * N;
    });
    const RotationSegment *hinge = nullptr;
    for (const RotationSegment &r : timeline->rotations(box))
        if (r.hinge) hinge = &r;
    REQUIRE(hinge);
    CAPTURE(hinge->t1 - slips);
    CHECK(std::abs(hinge->t1 - slips) < 1e-9);
    CHECK(slips > 0.3);
    const ModelPose end = timeline->evaluate(5.0).models[static_cast<size_t>(box)];
    CHECK(end.velocity == glm::dvec3(0.0));
    CHECK(std::abs(end.center.y - 0.5) < 1e-6);
    CHECK(std::abs(std::remainder(end.angles.z, 90.0)) < 1e-4);
}

TEST_CASE("a box left overhanging a table's edge turns about that edge as the pendulum equation "
          "says, until friction gives way") {
    // table_edge.lua: a 1 m box lying on the table's top (y = 1), its centre of mass d = 0.06 m
    // past the edge (x = 1.5). It pivots about the table's edge, which stays on the line of its
    // bottom face it first touched: phi'' = w2 sin(phi), phi the angle of its centre of mass from
    // the vertical through the edge (rho = |(d, s / 2)| from it), w2 = g rho / (s^2 / 6 + rho^2).
    // The edge pushes along the bottom face's normal, tilted by phi - phi0 with it; it holds while
    // the force along the face is within mu = 0.5 of the force across it. The bake does this in
    // closed form (physics.md, "Tipping"): one hinge about the table's edge, no contact on the way.
    const Document doc = shipped_scene("table_edge.lua");
    const int box = model_named(doc, "box");
    auto timeline = timeline_of(doc);
    timeline->bake(1.5);
    const double d = 0.06, rho = std::hypot(d, 0.5), w2 = G * rho / (1.0 / 6.0 + rho * rho);
    const double phi0 = std::atan2(d, 0.5), mu = 0.5;
    const double slip = tipping::until(w2, phi0, [&](double phi) {
        return tipping::over_edge_slips(G, w2, rho, phi0, mu, phi);
    });
    const RotationSegment *hinge = nullptr;
    for (const RotationSegment &r : timeline->rotations(box))
        if (r.hinge && !hinge) hinge = &r;
    REQUIRE(hinge);
    CAPTURE(hinge->t0, hinge->t1, slip);
    // (Its first contact, 1e-6 s in, finds it lying on the table, its centre of mass past the
    // edge: the hinge starts there, with the angular momentum of that microsecond's fall.)
    CHECK(hinge->t0 < 1e-5);
    CHECK(std::abs(hinge->t1 - slip) < 1e-8);
    // Its centre of mass on the pendulum's circle, at the pendulum's angle, until then.
    tipping::follow(w2, phi0, slip - 0.02, 0.02, [&](double t, double phi, double) {
        const ModelPose p = timeline->evaluate(t).models[static_cast<size_t>(box)];
        const glm::dvec3 arm = p.center - glm::dvec3(1.5, 1.0, p.center.z);
        CAPTURE(t);
        CHECK(std::abs(glm::length(arm) - rho) < 1e-9);
        CHECK(std::abs(std::atan2(arm.x, arm.y) - phi) < 1e-8);
        CHECK(std::abs(p.center.z) < 1e-12);
    });
    // No contact on the way (microcollisions took 16,072: physics.md, "Tipping").
    for (const ani_collision_event &e : timeline->events()) CHECK(!(e.t > 1e-3 && e.t < slip));
    CHECK(slip > 0.5);
    // Then it slides off the edge and falls to the floor.
    const ModelPose end = timeline->evaluate(1.5).models[static_cast<size_t>(box)];
    CHECK(end.center.y < 0.5 + 1e-6);
    CHECK(end.center.x > 1.5);
}

TEST_CASE("a box tipping over a table's edge stays on its hinge when a ball that was coming at "
          "it turns away first") {
    // table_edge.lua's tipping box, and a ball (no gravity) sent at its side along z at 20 m/s,
    // whose path a small static block cuts at z = -3: the ball bounces back off the block at
    // about 0.125 s, so the contact the box had predicted with it (about 0.26 s) never happens.
    // That prediction, stale when its time comes, must not end the hinge: the box turns about
    // the edge as the pendulum says, with no contact, as without the ball.
    Document doc = shipped_scene("table_edge.lua");
    const int box = model_named(doc, "box");
    const glm::dvec3 c = doc.keyframes()[0].states[static_cast<size_t>(box)]->center;
    Model ball = model("ball", "sphere", true, false);
    ball.initial_velocity = {0.0, 0.0, 20.0};
    doc.add_model(ball, placed({c.x, c.y, -6.0}, 0.2));
    doc.add_model(model("block", "cube", false, false), placed({c.x, c.y, -3.0}, 0.3));
    auto timeline = timeline_of(doc);
    timeline->bake(0.5);
    const double d = 0.06, rho = std::hypot(d, 0.5), w2 = G * rho / (1.0 / 6.0 + rho * rho);
    const double phi0 = std::atan2(d, 0.5);
    // The ball's bounce off the block, then nothing but the tip until 0.5 s.
    const uint32_t ball_index = static_cast<uint32_t>(doc.models().size() - 2);
    const ani_collision_event *bounce = nullptr;
    for (const ani_collision_event &e : timeline->events())
        if ((e.a == ball_index || e.b == ball_index) && !bounce) bounce = &e;
    REQUIRE(bounce);
    CHECK(std::abs(bounce->t - (6.0 - 3.0 - 0.3 - 0.2 * unit_radius()) / 20.0) < 1e-9);
    for (const ani_collision_event &e : timeline->events()) CHECK(!(e.t > 0.15 && e.t < 0.5));
    tipping::follow(w2, phi0, 0.5, 0.02, [&](double t, double phi, double) {
        const ModelPose p = timeline->evaluate(t).models[static_cast<size_t>(box)];
        const glm::dvec3 arm = p.center - glm::dvec3(1.5, 1.0, p.center.z);
        CAPTURE(t);
        CHECK(std::abs(glm::length(arm) - rho) < 1e-9);
        CHECK(std::abs(std::atan2(arm.x, arm.y) - phi) < 1e-8);
    });
    // The ball flies back along -z at its speed, past where it started.
    CHECK(timeline->evaluate(0.5).models[ball_index].center.z < -6.0 + 1e-9);
}

TEST_CASE("a box left overhanging a step's nose turns about it as the pendulum equation says, "
          "and lands on the step below when its far corner reaches it") {
    // The stairs of stairs.ani: the top step's tread at y = 2.5 ends at the nose, x = 1; the next
    // tread is H = 0.5 lower. A box of side s = 1.6 (mu 1, Rotates on) lies on the top step with
    // its centre of mass d = 0.05 past the nose. It turns about the nose as the upside-down
    // pendulum (w2 = g rho / (s^2 / 6 + rho^2), rho = |(d, s / 2)|), the lower steps within its
    // reach: its far bottom corner, L = s / 2 + d from the nose along its face, comes down on the
    // circle about the nose and meets the next tread when L sin(delta) = H, delta the turn.
    const double s = 1.6, d = 0.05, H = 0.5, L = 0.5 * s + d;
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(20, 1, 20)));
    doc.add_model(model("stairs", "stairs", false, false), placed({0, 0, 0}));
    Model m = model("box", "cube", true, true);
    m.friction = 1.0;
    m.restitution = 0.5;
    m.rotates = true;
    doc.add_model(m, placed({1.0 + d, 2.5 + 0.5 * s, 0.0}, 0.5 * s));
    const double rho = std::hypot(d, 0.5 * s), w2 = G * rho / (s * s / 6.0 + rho * rho),
                 phi0 = std::atan2(d, 0.5 * s), delta = std::asin(H / L);
    const double lands = tipping::until(w2, phi0, [&](double phi) { return phi - phi0 >= delta; });
    // Baked a little past the landing only: the tumble down the stairs after it is not checked
    // here (stairs_tumble.ani's tests are), and it was nine tenths of this test's time.
    REQUIRE(lands < 1.9);
    auto timeline = timeline_of(doc);
    timeline->bake(lands + 0.1);
    // (The edge holds it all the way: friction 1 is enough.)
    REQUIRE(tipping::until(w2, phi0, [&](double phi) {
                return tipping::over_edge_slips(G, w2, rho, phi0, 1.0, phi) || phi - phi0 >= delta;
            }) == lands);
    const RotationSegment *hinge = nullptr;
    for (const RotationSegment &r : timeline->rotations(2))
        if (r.hinge && !hinge) hinge = &r;
    REQUIRE(hinge);
    CAPTURE(hinge->t0, hinge->t1, lands);
    CHECK(hinge->t0 < 1e-5);
    tipping::follow(w2, phi0, lands - 0.01, 0.02, [&](double t, double phi, double) {
        const ModelPose p = timeline->evaluate(t).models[2];
        const glm::dvec3 arm = p.center - glm::dvec3(1.0, 2.5, p.center.z);
        CAPTURE(t);
        CHECK(std::abs(glm::length(arm) - rho) < 1e-9);
        CHECK(std::abs(std::atan2(arm.x, arm.y) - phi) < 1e-8);
    });
    // Its first contact after the start: the far corner on the next tread, at the pendulum's time.
    const ani_collision_event *landed = nullptr;
    for (const ani_collision_event &e : timeline->events())
        if (e.t > 1e-3 && !landed) landed = &e;
    REQUIRE(landed);
    CAPTURE(landed->t - lands);
    CHECK(std::abs(landed->t - lands) < 1e-8);
    CHECK(std::abs(hinge->t1 - lands) < 1e-8);
    CHECK(std::abs(landed->point.y - (2.5 - H)) < 1e-9);
    CHECK(std::abs(landed->point.x - (1.0 + L * std::cos(delta))) < 1e-6);
    CHECK(timeline->stats().backend_counts.at("tips about an edge") >= 1);
}

TEST_CASE("a box sent across a rough 20 degree slope curves down it as the rough incline's closed "
          "form says, and stops when it says") {
    // On a slope of angle theta, with a = g sin(theta) down the fall line d and friction
    // b = mu g cos(theta) against the velocity, the angle phi between the velocity and d obeys
    // v phi' = -a sin(phi) and v' = a cos(phi) - b, so dv/dphi = -v (cos(phi) - k) / sin(phi),
    // k = b / a = mu / tan(theta), and v sin(phi) / tan(phi / 2)^k = C along the path. Sent
    // across at v0 (phi = 90 degrees), C = v0. With u = tan(phi / 2), dt = -v dphi / (a sin(phi))
    // integrates to t(phi) = C / (2 a) ((1 - u^(k-1)) / (k - 1) + (1 - u^(k+1)) / (k + 1)), and
    // for k > 1 it stops (phi -> 0) at C k / (a (k^2 - 1)). The bake follows the turning slip in
    // pieces of 1e-3 rad (physics.md, "Sliding, skidding and rolling"), to about 1e-7 here.
    const double theta = glm::radians(20.0), mu = 0.5, v0 = 3.0;
    Document doc;
    doc.add_model(model("slope", "plane", false, false),
                  placed({0, 0, 0}, glm::dvec3(10, 1, 10), {0, 0, 20}));
    Model box = model("box", "cube", true, true);
    box.friction = mu;
    box.restitution = 0.5;
    box.initial_velocity = {0, 0, v0};
    const glm::dvec3 n(-std::sin(theta), std::cos(theta), 0.0),
        d(-std::cos(theta), -std::sin(theta), 0.0);
    doc.add_model(box, placed(0.5 * n, glm::dvec3(0.5), {0, 0, 20}));
    auto timeline = timeline_of(doc);
    timeline->bake(3.0);
    const double a = G * std::sin(theta), k = mu / std::tan(theta);
    const double t_stop = v0 * k / (a * (k * k - 1.0)); // 1.3845 s
    // While phi > 0.18 (to t = 0.9 s; closer to the fall line phi, and so C and t(phi), are
    // ill-conditioned in the velocity).
    for (double t = 0.01; t < 0.9; t += 0.01) {
        CAPTURE(t);
        const ModelPose p = timeline->evaluate(t).models[1];
        const double v = glm::length(p.velocity);
        const double cos_phi = glm::dot(p.velocity, d) / v,
                     sin_phi = glm::length(glm::cross(p.velocity, d)) / v;
        const double u = sin_phi / (1.0 + cos_phi);       // tan(phi / 2)
        CHECK(std::abs(glm::dot(p.velocity, n)) < 1e-12); // along the slope
        CHECK(std::abs(v * sin_phi / std::pow(u, k) - v0) < 3e-6);
        const double t_phi =
            v0 / (2.0 * a) *
            ((1.0 - std::pow(u, k - 1.0)) / (k - 1.0) + (1.0 - std::pow(u, k + 1.0)) / (k + 1.0));
        CHECK(std::abs(t_phi - t) < 1e-6);
    }
    // It stops: the last time it moves, found by bisection, is the closed form's.
    double lo = 0.5, hi = 3.0;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (timeline->evaluate(mid).models[1].velocity == glm::dvec3(0.0) ? hi : lo) = mid;
    }
    CAPTURE(hi - t_stop);
    CHECK(std::abs(hi - t_stop) < 1e-6);
    // Then static friction holds it (mu >= tan(theta)).
    const glm::dvec3 rest = timeline->evaluate(t_stop + 0.01).models[1].center;
    CHECK(glm::length(timeline->evaluate(3.0).models[1].center - rest) == 0.0);
}

TEST_CASE("a cube tips over on a slab of twelve triangles as on a floor of two") {
    // The same tip as tipping_cube.lua's on the top face of a box (a mesh of more than four
    // triangles, whose time of impact tests only the triangles within reach of a short window,
    // bake_prediction.cpp) and on a plane: the same landing, within the method's own error.
    const double deg = M_PI / 180.0, lift = 0.5 * (std::cos(30 * deg) + std::sin(30 * deg));
    double landed[2] = {-1.0, -1.0};
    glm::dvec3 rest[2];
    for (int slab = 0; slab < 2; ++slab) {
        Document doc;
        if (slab)
            doc.add_model(model("floor", "cube", false, false),
                          placed({0, -0.5, 0}, glm::dvec3(5, 0.5, 5)));
        else
            doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, 10.0));
        Model box = model("box", "cube", true, true);
        box.rotates = true;
        box.restitution = 0.3;
        box.friction = 0.5;
        doc.add_model(box, placed({0, lift, 0}, glm::dvec3(0.5), {0, 0, 30}));
        auto timeline = timeline_of(doc);
        timeline->bake(1.2);
        for (const ani_collision_event &e : timeline->events())
            if (e.speed > 0.1) {
                landed[slab] = e.t;
                break;
            }
        rest[slab] = timeline->evaluate(1.2).models[1].center;
        CHECK(timeline->evaluate(1.2).models[1].velocity == glm::dvec3(0.0));
    }
    CHECK(landed[0] > 0.55);
    CHECK(std::abs(landed[1] - landed[0]) < 1e-5); // measured: 1e-6
    CHECK(glm::length(rest[1] - rest[0]) < 1e-4);  // measured: 4e-6
}

TEST_CASE("stairs_tumble.ani: the cube slides to the top step's nose, tips over it when its centre "
          "of mass passes it, tumbles down the stairs and rests on the floor, losing energy all "
          "the way") {
    // The cube (side s = 0.5 m, 1 kg, e = 0.4, mu = 0.5, Rotates on) is placed on the top step
    // (y = 2.5) at x = 0.3 and pushed at 4 m/s along +x. It slides flat, slowing at mu g:
    // x(t) = 0.3 + 4 t - mu g t^2 / 2, until its centre of mass passes the nose at x = 1, at the
    // root of that quadratic; nothing touches it before then. From there it is chaotic (the two
    // backends part at its first blow on a step's edge), so the rest is checked by what must hold
    // whatever the path: its energy never rises, and it ends still, flat on a face, on the floor
    // beyond the stairs, in view.
    const Document doc =
        open_document(env().plugins, test::source_dir() / "assets/animations/stairs_tumble.ani")
            .document;
    const int cube = model_named(doc, "cube");
    REQUIRE(doc.models()[cube].rotates);
    const double mu = doc.models()[cube].friction, s = 0.5, m = 1.0, v0 = 4.0, x0 = 0.3;
    REQUIRE(mu == 0.5);
    const double end = static_cast<double>(doc.settings().max_time_ms) / 1000.0;
    const double a = mu * G;
    const double t_nose = (v0 - std::sqrt(v0 * v0 - 2.0 * a * (1.0 - x0))) / a;
    auto energy = [&](const Timeline &t, double at) {
        const ModelPose p = t.evaluate(at).models[static_cast<size_t>(cube)];
        const RotationSegment *r = t.rotation_at(cube, at);
        const glm::dvec3 w = r ? angular_velocity_at(*r, at) : glm::dvec3(0.0);
        // A cube's inertia is m s^2 / 6 about every axis through its centre.
        return 0.5 * m * glm::dot(p.velocity, p.velocity) +
               0.5 * (m * s * s / 6.0) * glm::dot(w, w) + m * G * p.center.y;
    };
    SECTION("physics.custom: the slide in closed form, then down to rest exactly") {
        auto timeline = timeline_of(doc);
        timeline->bake(end);
        for (double t : {0.05, 0.1, 0.15, t_nose - 1e-3}) {
            CAPTURE(t);
            const ModelPose p = timeline->evaluate(t).models[static_cast<size_t>(cube)];
            CHECK(std::abs(p.center.x - (x0 + v0 * t - 0.5 * a * t * t)) < 1e-9);
            CHECK(std::abs(p.center.y - 2.75) < 1e-12);
            CHECK(std::abs(p.velocity.x - (v0 - a * t)) < 1e-9);
            CHECK(glm::length(glm::mod(p.angles + 180.0, 360.0) - 180.0) < 1e-9);
        }
        REQUIRE_FALSE(timeline->events().empty());
        CAPTURE(t_nose, timeline->events().front().t);
        CHECK(timeline->events().front().t >= t_nose - 1e-9); // nothing touched it on the step
        CHECK(timeline->events().front().t < t_nose + 0.05);  // and it tips over there at once
        const double e0 = energy(*timeline, 0.0);
        for (int k = 1; k <= 1200; ++k) {
            const double t = end * k / 1200.0;
            CAPTURE(t);
            CHECK(energy(*timeline, t) <= e0 + 1e-6);
            const glm::dvec3 c = timeline->evaluate(t).models[static_cast<size_t>(cube)].center;
            CHECK(c.y >= s / 2 - 1e-6);                              // never in the floor
            CHECK((c.x > -1.0 && c.x < 9.0 && std::abs(c.z) < 3.0)); // in view
        }
        // At rest on the floor beyond the stairs (x > 5), flat on a face: its centre s / 2 up,
        // every turn a multiple of 90 degrees, still to the last digit.
        const ModelPose p5 = timeline->evaluate(end - 1.0).models[static_cast<size_t>(cube)];
        const ModelPose p6 = timeline->evaluate(end).models[static_cast<size_t>(cube)];
        CHECK(p6.velocity == glm::dvec3(0.0));
        CHECK(p6.center == p5.center);
        // (Its last bounces, too small to follow, end at the Zeno rule's accumulation time: within
        // 1e-9 of the coordinates' size, here about 7 m.)
        CHECK(std::abs(p6.center.y - s / 2) < 1e-8);
        CHECK(p6.center.x > 5.0 + s / 2);
        const glm::dquat q = orientation_at(*timeline->rotation_at(cube, end), end);
        const glm::dvec3 up =
            glm::conjugate(q) * glm::dvec3(0, 1, 0); // the world's up, in the cube
        const double largest = std::max({std::abs(up.x), std::abs(up.y), std::abs(up.z)});
        CHECK(largest > 1.0 - 1e-9);
        CHECK(energy(*timeline, end) < e0 - m * G * 2.5); // the height of the stairs, and more
        // The work is bounded: measured 9,656 predictions and 1,447,659 pairs of triangles
        // measured (stairs.ani's nose crawled through 10,000 advancement steps a prediction
        // before the turning planes of turning_contact.cpp).
        CHECK(timeline->stats().backend_counts.at("predictions") < 20000);
        CHECK(timeline->stats().backend_counts.at("mesh feature tests") < 4000000);
    }
    SECTION("Bullet: the same slide to its step's resolution, and down to rest on a tread or the "
            "floor") {
        auto timeline = timeline_of(doc, "physics.bullet");
        timeline->bake(end);
        for (double t : {0.05, 0.1, 0.15}) {
            CAPTURE(t);
            const ModelPose p = timeline->evaluate(t).models[static_cast<size_t>(cube)];
            CHECK(std::abs(p.center.x - (x0 + v0 * t - 0.5 * a * t * t)) < 0.01);
        }
        // Where it ends is its own (chaos), but it ends still and flat on a tread (tops at 2.5,
        // 2, ..., 0.5 over x in [k, k + 1]) or on the floor, with less energy than it had. (Its
        // energy is not kept from rising on the way: a contact's push-out can add joules.)
        const ModelPose p = timeline->evaluate(end).models[static_cast<size_t>(cube)];
        CAPTURE(p.center);
        CHECK(glm::length(p.velocity) < 1e-2);
        const double top = p.center.y - s / 2;
        CHECK(std::abs(top - std::round(2.0 * top) / 2.0) < 0.01);
        if (top > 0.25) CHECK(std::abs(top - (2.5 - 0.5 * std::floor(p.center.x))) < 0.01);
        CHECK(energy(*timeline, end) < energy(*timeline, 0.0) - m * G * 2.0);
    }
}

TEST_CASE("stack_knock.lua: a ball falling onto the edge of a sleeping stack's top box wakes it "
          "and knocks it off, with energy and momentum kept to rounding (e = 1, mu = 0)") {
    // Every model elastic and frictionless. The ball (r = 0.3 m, 2 kg) is dropped from (0.6, 5)
    // onto the top box's edge at (0.5, 3): it meets it when its centre is r from the edge,
    // 3 + sqrt(r^2 - 0.1^2) high, at t = sqrt(2 (5 - that) / g), the normal (0.1, sqrt(0.08)) / r
    // from the edge, its speed along it g t times the normal's y. The support, frictionless,
    // cannot take that slanting blow: the top box moves. The horizontal blows are between the
    // ball and the top box only (the box under it, frictionless, pushes straight up), so their
    // x momentum stays 0 through the blows.
    const Document doc = shipped_scene("stack_knock.lua");
    const int ball = model_named(doc, "ball"), top = model_named(doc, "top"),
              middle = model_named(doc, "middle"), bottom = model_named(doc, "bottom");
    for (int m : {ball, top, middle, bottom}) {
        REQUIRE(doc.models()[m].restitution == 1.0);
        REQUIRE(doc.models()[m].friction == 0.0);
    }
    auto timeline = timeline_of(doc);
    const double end = 2.0;
    REQUIRE(doc.settings().max_time_ms == 2000);
    timeline->bake(end);
    const double r = 0.3 * unit_radius(), y_hit = 3.0 + std::sqrt(r * r - 0.01);
    const double t_hit = std::sqrt(2.0 * (5.0 - y_hit) / G);
    const glm::dvec3 n(0.1 / r, (y_hit - 3.0) / r, 0.0); // from the edge towards the ball
    const auto &events = timeline->events();
    REQUIRE(events.size() >= 3);
    const ani_collision_event &hit = events.front();
    CHECK((hit.a == static_cast<uint32_t>(top) || hit.b == static_cast<uint32_t>(top)));
    CHECK((hit.a == static_cast<uint32_t>(ball) || hit.b == static_cast<uint32_t>(ball)));
    CAPTURE(hit.t - t_hit);
    CHECK(std::abs(hit.t - t_hit) < 1e-8);
    CHECK(std::abs(std::abs(hit.normal.x) - n.x) < 1e-7);
    CHECK(std::abs(std::abs(hit.normal.y) - n.y) < 1e-7);
    CHECK(std::abs(hit.speed - G * t_hit * n.y) < 1e-7);
    // Asleep until then: nothing below moved.
    for (int m : {top, middle, bottom})
        CHECK(timeline->evaluate(0.5).models[static_cast<size_t>(m)].velocity == glm::dvec3(0.0));
    // The blows at that instant done, the top box moves off sideways (away from the ball), the
    // ball the other way, their x momentum 0.
    const double after = hit.t + 1e-6;
    const ModelPose b1 = timeline->evaluate(after).models[static_cast<size_t>(ball)],
                    t1 = timeline->evaluate(after).models[static_cast<size_t>(top)];
    CHECK(t1.velocity.x < -1.0);
    CHECK(b1.velocity.x > 0.0);
    CHECK(std::abs(2.0 * b1.velocity.x + t1.velocity.x) < 1e-9);
    // Energy, kinetic (both turning) and potential, kept to rounding all the way.
    auto energy = [&](double t) {
        double e = 0.0;
        for (int m : {ball, top, middle, bottom}) {
            const ModelPose p = timeline->evaluate(t).models[static_cast<size_t>(m)];
            const double mass = m == ball ? 2.0 : 1.0;
            const double inertia = m == ball ? 0.4 * mass * r * r : mass / 6.0;
            const RotationSegment *rot = timeline->rotation_at(m, t);
            const glm::dvec3 w = rot ? angular_velocity_at(*rot, t) : glm::dvec3(0.0);
            e += 0.5 * mass * glm::dot(p.velocity, p.velocity) + 0.5 * inertia * glm::dot(w, w) +
                 mass * G * p.center.y;
        }
        return e;
    };
    const double e0 = energy(0.0);
    double worst = 0.0;
    for (int k = 1; k <= 600; ++k) worst = std::max(worst, std::abs(energy(end * k / 600.0) - e0));
    CAPTURE(e0, worst); // (Catch prints both to 1e-10: measured, worst is 1e-13 of 142 J)
    CHECK(worst < 1e-12 * e0);
    // The top box is knocked off the stack and never inside the box under it; the boxes under
    // it stay exactly where they stood.
    for (int k = 0; k <= 600; ++k) {
        const double t = end * k / 600.0;
        const glm::dvec3 c = timeline->evaluate(t).models[static_cast<size_t>(top)].center;
        if (std::abs(c.x) < 1.0 && std::abs(c.z) < 1.0) CHECK(c.y >= 2.5 - 1e-9);
        CHECK(c.y >= 0.5 - 1e-9);
    }
    CHECK(timeline->evaluate(end).models[static_cast<size_t>(top)].center.x < -1.0);
    for (int m : {middle, bottom}) {
        const ModelPose p = timeline->evaluate(end).models[static_cast<size_t>(m)];
        CHECK(glm::length(p.center - start_of(doc, m).center) < 1e-12);
        CHECK(p.velocity == glm::dvec3(0.0));
    }
}
