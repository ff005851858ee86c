// Gases of many spheres through physics.custom's event engine (the grid broad phase, the event
// queue, cell crossings): what must hold whatever the collisions were. Energy and momentum are
// sums over the bodies the bake reports, checked against their values at t = 0; overlaps are
// checked between every pair at sampled times; the grid's events against the all-pairs oracle.
#include "assets/asset_paths.hpp"
#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "timeline/timeline.hpp"

#include "scene_support.hpp"

#include "gas_reference.hpp" // bench/: the benchmark's reference gas

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <functional>
#include <random>

using namespace animator;
using namespace physics_test;

namespace {

struct Gas {
    Document doc;
    std::vector<double> radius, mass;
    int first_ball = 0;
};

// n balls of scale `scale` on a jittered cubic lattice of spacing `spacing` around the origin,
// with random velocities (up to `speed` per axis) and masses in [0.5, 2]; optionally inside a
// closed box of half-width `box`.
Gas make_gas(int n, double scale, double spacing, double speed, double box, int broad_phase,
             uint64_t seed, bool lane = true) {
    Gas gas;
    Settings s = gas.doc.settings();
    s.gravity = 0.0;
    s.params["physics.custom"]["broad_phase"] = {static_cast<double>(broad_phase), 0, 0, 0};
    s.params["physics.custom"]["gas_lane"] = {lane ? 1.0 : 0.0, 0, 0, 0};
    gas.doc.set_settings(s);
    if (box > 0.0) {
        Model walls;
        walls.name = "box";
        walls.mesh = "cube";
        ModelState st;
        st.scale = glm::dvec3(box);
        gas.doc.add_model(walls, st);
        gas.first_ball = 1;
    }
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1), velocity(-speed, speed),
        mass(0.5, 2.0);
    const int side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(n))));
    const double r = unit_radius() * scale;
    for (int k = 0; k < n; ++k) {
        Model ball;
        ball.name = "ball" + std::to_string(k);
        ball.mesh = "sphere";
        ball.dynamics = true;
        ball.gravity = false;
        ball.mass = mass(rng);
        ball.initial_velocity = {velocity(rng), velocity(rng), velocity(rng)};
        ModelState st;
        const glm::dvec3 cell(k % side, (k / side) % side, k / (side * side));
        st.center = (cell - glm::dvec3(0.5 * (side - 1))) * spacing +
                    glm::dvec3(jitter(rng), jitter(rng), jitter(rng)) * (spacing - 2.0 * r);
        st.scale = glm::dvec3(scale);
        gas.doc.add_model(ball, st);
        gas.radius.push_back(r);
        gas.mass.push_back(ball.mass);
    }
    return gas;
}

std::unique_ptr<Timeline> baked(const Gas &gas, double until) {
    auto t = timeline_of(gas.doc);
    t->bake(until);
    return t;
}

struct Totals {
    double energy = 0.0, scale = 0.0; // kinetic energy; sum of m |v| for momentum's scale
    glm::dvec3 momentum{0.0};
    double overlap = -1e300; // the largest overlap of two balls, relative to a radius
};

Totals totals(const Gas &gas, const Timeline &timeline, double t) {
    const Frame f = timeline.evaluate(t);
    Totals out;
    const size_t n = gas.mass.size();
    for (size_t k = 0; k < n; ++k) {
        const glm::dvec3 v = f.models[k + static_cast<size_t>(gas.first_ball)].velocity;
        out.energy += 0.5 * gas.mass[k] * glm::dot(v, v);
        out.momentum += gas.mass[k] * v;
        out.scale += gas.mass[k] * glm::length(v);
    }
    for (size_t a = 0; a < n; ++a)
        for (size_t b = a + 1; b < n; ++b) {
            const double d = glm::length(f.models[a + static_cast<size_t>(gas.first_ball)].center -
                                         f.models[b + static_cast<size_t>(gas.first_ball)].center);
            out.overlap =
                std::max(out.overlap, (gas.radius[a] + gas.radius[b] - d) / gas.radius[a]);
        }
    return out;
}

} // namespace

TEST_CASE("a gas of 1000 spheres in free space keeps its energy and momentum to rounding") {
    const Gas gas = make_gas(1000, 0.2, 0.5, 1.0, 0.0, 0, 7);
    const double until = 20.0;
    auto timeline = baked(gas, until);
    const auto &events = timeline->events();
    INFO(events.size() << " collisions");
    CHECK(events.size() > 2000);
    const Totals start = totals(gas, *timeline, 0.0);
    CHECK(start.overlap < 0.0);
    for (double t : {0.5, 2.0, 5.0, 10.0, 20.0}) {
        CAPTURE(t);
        const Totals now = totals(gas, *timeline, t);
        CHECK(std::abs(now.energy - start.energy) / start.energy < 1e-12);
        CHECK(glm::length(now.momentum - start.momentum) / start.scale < 1e-13);
        CHECK(now.overlap < 1e-9); // never overlapping (beyond rounding at a contact)
    }
}

TEST_CASE("a gas of 1000 spheres in a closed box keeps its energy and stays inside") {
    const double half = 4.0;
    const Gas gas = make_gas(1000, 0.15, 0.6, 2.0, half, 0, 11);
    const double until = 25.0;
    auto timeline = baked(gas, until);
    const auto &events = timeline->events();
    size_t walls = 0;
    for (const auto &e : events) walls += e.b == 0;
    INFO(events.size() << " collisions, " << walls << " with the walls");
    CHECK(events.size() > 25000);
    CHECK(walls > 5000);
    const Totals start = totals(gas, *timeline, 0.0);
    for (double t : {1.0, 3.3, 25.0}) {
        CAPTURE(t);
        const Totals now = totals(gas, *timeline, t);
        CHECK(std::abs(now.energy - start.energy) / start.energy < 1e-11);
        CHECK(now.overlap < 1e-9);
        const Frame f = timeline->evaluate(t);
        double outside = -1.0;
        for (size_t k = 0; k < gas.radius.size(); ++k)
            for (int c = 0; c < 3; ++c)
                outside =
                    std::max(outside, std::abs(f.models[k + 1].center[c]) - (half - gas.radius[k]));
        CHECK(outside < 1e-9);
    }
}

TEST_CASE("the grid broad phase finds the same collisions as testing all pairs") {
    // A dense gas in a box: the first collisions of a chaotic system agree to rounding (later
    // ones drift apart as rounding grows, which is why only the first are compared).
    // (The general engine's grid: the gas lane's is compared below.)
    const Gas grid = make_gas(200, 0.2, 0.6, 1.0, 2.5, 1, 3, false);
    const Gas pairs = make_gas(200, 0.2, 0.6, 1.0, 2.5, 2, 3);
    auto a = baked(grid, 2.0), b = baked(pairs, 2.0);
    REQUIRE(a->events().size() > 300);
    REQUIRE(b->events().size() > 300);
    for (size_t k = 0; k < 300; ++k) {
        CAPTURE(k);
        const auto &x = a->events()[k], &y = b->events()[k];
        CHECK(x.t == Approx(y.t).margin(1e-9));
        CHECK(std::min(x.a, x.b) == std::min(y.a, y.b));
        CHECK(std::max(x.a, x.b) == std::max(y.a, y.b));
    }
    // The grid tests far fewer pairs.
    const auto &ga = a->stats().backend_counts, &gb = b->stats().backend_counts;
    REQUIRE(ga.count("pair tests done"));
    REQUIRE(gb.count("pair tests done"));
    CHECK(ga.at("pair tests done") < 0.25 * gb.at("pair tests done"));
    CHECK(ga.at("cell crossings") > 0);
    CHECK(gb.count("cell crossings") == 1);
    CHECK(gb.at("cell crossings") == 0);
}

TEST_CASE("10000 spheres: the broad phase tests a few neighbours per prediction, not every pair") {
    // 10000 balls in a box: testing every pair would be 50 million tests per event.
    const Gas gas = make_gas(10000, 0.1, 0.3, 1.0, 4.0, 0, 17);
    auto timeline = baked(gas, 0.5);
    const auto &counts = timeline->stats().backend_counts;
    const double predictions = counts.at("predictions"), done = counts.at("pair tests done");
    INFO(timeline->events().size()
         << " collisions, " << predictions << " predictions, " << done << " pair tests");
    CHECK(timeline->events().size() > 2000);
    CHECK(done < 40.0 * predictions);
    CHECK(counts.at("pair tests skipped") > 1000.0 * done);
    // Nothing after a contact looks at every body: no platform to ride or riders to wake here
    // (a scan of all 10,000 after each contact made this gas 7 times slower once).
    CHECK(counts.at("bodies scanned after contacts") == 0.0);
    // Energy kept through all of it.
    double e0 = 0.0, e1 = 0.0;
    const Frame a = timeline->evaluate(0.0), b = timeline->evaluate(0.5);
    for (size_t k = 0; k < gas.mass.size(); ++k) {
        e0 += 0.5 * gas.mass[k] * glm::dot(a.models[k + 1].velocity, a.models[k + 1].velocity);
        e1 += 0.5 * gas.mass[k] * glm::dot(b.models[k + 1].velocity, b.models[k + 1].velocity);
    }
    CHECK(std::abs(e1 - e0) / e0 < 1e-12);
}

TEST_CASE("physics.custom and the benchmark's reference gas find the same first collisions") {
    // Two programs written apart (bench/gas_reference.cpp: a cell list, collision counters and a
    // calendar queue) on the same 64 balls in a box: the same pairs and walls in the same order,
    // at the same times to rounding, until the gas's chaos has grown the rounding (here well
    // past the 300 events compared).
    const double half = 2.2;
    const Gas gas = make_gas(64, 0.2, 0.5, 1.0, half, 0, 5);
    const double until = 6.0;
    auto timeline = baked(gas, until);
    namespace ref = animator::bench::reference;
    ref::Gas start;
    start.radius = gas.radius[0];
    start.lo = {-half, -half, -half};
    start.hi = {half, half, half};
    const Frame f = timeline->evaluate(0.0);
    for (size_t k = 0; k < gas.mass.size(); ++k) {
        const glm::dvec3 p = f.models[k + 1].center, v = f.models[k + 1].velocity;
        start.position.push_back({p.x, p.y, p.z});
        start.velocity.push_back({v.x, v.y, v.z});
        start.mass.push_back(gas.mass[k]);
    }
    std::vector<ref::Collision> log;
    ref::run(start, until, &log);
    const auto &events = timeline->events();
    INFO(events.size() << " collisions in physics.custom, " << log.size() << " in the reference");
    REQUIRE(events.size() >= 300);
    REQUIRE(log.size() >= 300);
    for (size_t k = 0; k < 300; ++k) {
        CAPTURE(k);
        const ani_collision_event &e = events[k];
        const ref::Collision &c = log[k];
        // physics.custom: models (the box is model 0, ball j is model j + 1); the reference:
        // spheres, or a sphere and a wall.
        const bool wall = e.a == 0 || e.b == 0;
        REQUIRE(wall == (c.b >= ref::kWall));
        if (wall) {
            CHECK((e.a == 0 ? e.b : e.a) == c.a + 1);
        } else {
            CHECK(std::min(e.a, e.b) == std::min(c.a, c.b) + 1);
            CHECK(std::max(e.a, e.b) == std::max(c.a, c.b) + 1);
        }
        CHECK(std::abs(e.t - c.time) < 1e-9);
    }
}

namespace {

double count_of(const Timeline &t, const char *name) {
    const auto &counts = t.stats().backend_counts;
    const auto it = counts.find(name);
    return it == counts.end() ? 0.0 : it->second;
}

// The first `n` collisions of two bakes: the same pairs in the same order, at the same times to
// rounding (a chaotic gas's later ones drift apart as rounding grows).
void same_first_collisions(const Timeline &a, const Timeline &b, size_t n) {
    REQUIRE(a.events().size() >= n);
    REQUIRE(b.events().size() >= n);
    for (size_t k = 0; k < n; ++k) {
        CAPTURE(k);
        const auto &x = a.events()[k], &y = b.events()[k];
        CHECK(std::abs(x.t - y.t) < 1e-9);
        CHECK(std::min(x.a, x.b) == std::min(y.a, y.b));
        CHECK(std::max(x.a, x.b) == std::max(y.a, y.b));
        // (The normal points towards model a: a pair may be told either way round.)
        const double sign = x.a == y.a ? 1.0 : -1.0;
        CHECK(glm::length(glm::dvec3(x.normal.x - sign * y.normal.x, x.normal.y - sign * y.normal.y,
                                     x.normal.z - sign * y.normal.z)) < 1e-6);
        CHECK(std::abs(x.speed - y.speed) < 1e-6);
    }
}

// Every ball (model 1 on) where the other bake has it at t, to 1e-9 (m, m/s).
void same_places(const Timeline &a, const Timeline &b, double t) {
    const Frame fa = a.evaluate(t), fb = b.evaluate(t);
    for (size_t k = 1; k < fa.models.size(); ++k) {
        CAPTURE(k);
        CHECK(glm::length(fa.models[k].center - fb.models[k].center) < 1e-9);
        CHECK(glm::length(fa.models[k].velocity - fb.models[k].velocity) < 1e-9);
    }
}

} // namespace

TEST_CASE("the gas lane finds the same collisions as the general engine and as testing all pairs") {
    // A gas in a box is what the lane takes (gas_lane.hpp): it bakes every event, its walls
    // included, and hands nothing back.
    const Gas lane = make_gas(300, 0.2, 0.6, 1.0, 3.0, 0, 23);
    const Gas general = make_gas(300, 0.2, 0.6, 1.0, 3.0, 0, 23, false);
    const Gas pairs = make_gas(300, 0.2, 0.6, 1.0, 3.0, 2, 23);
    auto a = baked(lane, 2.0), b = baked(general, 2.0), c = baked(pairs, 2.0);
    INFO(a->events().size() << " collisions in the lane");
    size_t walls = 0;
    for (size_t k = 0; k < 400; ++k) walls += a->events()[k].a == 0 || a->events()[k].b == 0;
    CHECK(walls > 10);
    same_first_collisions(*a, *b, 400);
    same_first_collisions(*a, *c, 400);
    CHECK(count_of(*a, "gas lane events") >= static_cast<double>(a->events().size()));
    CHECK(count_of(*a, "gas lane hand-offs") == 0.0);
    CHECK(count_of(*b, "gas lane events") == 0.0);
    CHECK(count_of(*c, "gas lane events") == 0.0);
    // Every ball where the general engine has it, to rounding grown by the chaos, early on.
    same_places(*a, *b, 0.3);
    // Energy kept to rounding, no overlap, all along.
    const Totals start = totals(lane, *a, 0.0);
    for (double t : {0.5, 1.0, 2.0}) {
        CAPTURE(t);
        const Totals now = totals(lane, *a, t);
        CHECK(std::abs(now.energy - start.energy) / start.energy < 1e-12);
        CHECK(now.overlap < 1e-9);
    }
}

TEST_CASE("the gas lane of 5000 balls starts in two halves and finds the general engine's "
          "collisions") {
    // From 4,096 balls the lane's first predictions are made in two halves at once, below and
    // above the middle layers of its cells (GasLane::predict_all_pairs): every ball must still
    // get the earliest collision of its own, wherever its partner is.
    const Gas lane = make_gas(5000, 0.2, 0.6, 1.0, 6.0, 0, 29);
    const Gas general = make_gas(5000, 0.2, 0.6, 1.0, 6.0, 0, 29, false);
    auto a = baked(lane, 0.2), b = baked(general, 0.2);
    CHECK(count_of(*a, "gas lane events") >= static_cast<double>(a->events().size()));
    CHECK(count_of(*b, "gas lane events") == 0.0);
    INFO(a->events().size() << " collisions");
    REQUIRE(a->events().size() == b->events().size());
    same_first_collisions(*a, *b, a->events().size());
    same_places(*a, *b, 0.2);
}

TEST_CASE("the gas lane's work per collision does not grow with the number of balls") {
    // Issue 22: time per collision growing no faster than log N. The work counted (pair tests,
    // predictions, cell crossings, stale events) per collision, at 27 times the balls in a box
    // 3 times as wide (the same density), over about as many collisions per ball; each ball's
    // first predictions counted in. No more than log N grows: log(27000) / log(1000) = 1.48.
    const auto work = [](int side, uint64_t seed) {
        const int n = side * side * side;
        const Gas gas = make_gas(n, 0.2, 0.6, 1.0, 0.3 * side, 0, seed);
        auto t = baked(gas, 2.0);
        const double collisions = static_cast<double>(t->events().size());
        INFO(n << " balls: " << collisions << " collisions");
        CHECK(count_of(*t, "gas lane events") >= collisions);
        CHECK(collisions > 2.0 * n);
        return (count_of(*t, "pair tests done") + count_of(*t, "predictions") +
                count_of(*t, "cell crossings") + count_of(*t, "stale predictions")) /
               collisions;
    };
    const double small = work(10, 43), large = work(30, 43);
    CAPTURE(small, large);
    CHECK(large <= std::log(27000.0) / std::log(1000.0) * small);
}

TEST_CASE("the gas lane meets a box's faces as the general engine does, around every ball or not") {
    // A box closed around every ball (the cube mesh, its faces along the axes) the lane knows as
    // such and meets its faces directly (GasLane::find_box); with a ball outside it, or turned
    // off the axes, its faces are triangles like any other. Either way: the general engine's
    // collisions, its walls among them.
    // (300 balls on a lattice 3.6 m wide, in a box 6 m wide: inside it turned too.)
    const auto same = [](const std::function<void(Gas &)> &change) {
        Gas lane = make_gas(300, 0.2, 0.6, 1.0, 3.0, 0, 47);
        Gas general = make_gas(300, 0.2, 0.6, 1.0, 3.0, 0, 47, false);
        change(lane);
        change(general);
        auto a = baked(lane, 2.0), b = baked(general, 2.0);
        CHECK(count_of(*a, "gas lane events") >= static_cast<double>(a->events().size()));
        CHECK(count_of(*b, "gas lane events") == 0.0);
        size_t walls = 0;
        for (size_t k = 0; k < 400; ++k) walls += a->events()[k].a == 0 || a->events()[k].b == 0;
        CHECK(walls > 5);
        same_first_collisions(*a, *b, 400);
        same_places(*a, *b, 0.3);
    };
    SECTION("every ball inside") {
        same([](Gas &) {});
    }
    SECTION("a ball outside, still") {
        same([](Gas &gas) {
            Model ball;
            ball.name = "outside";
            ball.mesh = "sphere";
            ball.dynamics = true;
            ball.gravity = false;
            ModelState st;
            st.center = {4.0, 0.0, 0.0};
            st.scale = glm::dvec3(0.2);
            gas.doc.add_model(ball, st);
        });
    }
    SECTION("the box turned about y") {
        same([](Gas &gas) {
            ModelState st = *gas.doc.keyframes().front().states[0];
            st.angles = {0.0, 30.0, 0.0};
            gas.doc.set_state(0, 0, st);
        });
    }
}

TEST_CASE("the gas lane hands the bake to the general engine when a ball leaves its grid") {
    // In free space the balls that fly off leave the grid, which the lane does not follow: it
    // stops there and the general engine goes on from where it left every ball.
    const Gas lane = make_gas(500, 0.2, 0.5, 1.0, 0.0, 0, 29);
    const Gas general = make_gas(500, 0.2, 0.5, 1.0, 0.0, 0, 29, false);
    auto a = baked(lane, 8.0), b = baked(general, 8.0);
    CHECK(count_of(*a, "gas lane hand-offs") == 1.0);
    CHECK(count_of(*a, "gas lane events") > 100.0);
    CHECK(count_of(*a, "gas lane events") <
          static_cast<double>(a->events().size()) + count_of(*a, "cell crossings"));
    same_first_collisions(*a, *b, std::min<size_t>(b->events().size(), 600));
    const Totals start = totals(lane, *a, 0.0), end = totals(lane, *a, 8.0);
    CHECK(std::abs(end.energy - start.energy) / start.energy < 1e-12);
    CHECK(glm::length(end.momentum - start.momentum) / start.scale < 1e-13);
    CHECK(end.overlap < 1e-9);
}

TEST_CASE("the gas lane bakes in slices as in one bake") {
    // The editor bakes in slices, each going on from the last (issue 16): the lane goes on too.
    const Gas gas = make_gas(200, 0.2, 0.6, 1.0, 2.5, 0, 31);
    auto whole = baked(gas, 3.0);
    auto sliced = timeline_of(gas.doc);
    for (double until : {0.25, 0.5, 1.0, 1.7, 3.0}) sliced->bake(until);
    CHECK(count_of(*sliced, "gas lane events") > 0.0);
    REQUIRE(sliced->events().size() == whole->events().size());
    for (size_t k = 0; k < whole->events().size(); ++k) {
        CAPTURE(k);
        CHECK(std::abs(sliced->events()[k].t - whole->events()[k].t) < 1e-12);
        CHECK(sliced->events()[k].a == whole->events()[k].a);
        CHECK(sliced->events()[k].b == whole->events()[k].b);
    }
    // (A segment that goes on into the next slice starts again where the slice starts, moved
    // there: positions agree to rounding.)
    for (double t : {0.1, 0.5, 1.3, 2.9, 3.0}) {
        const Frame a = sliced->evaluate(t), b = whole->evaluate(t);
        for (size_t k = 0; k < a.models.size(); ++k)
            CHECK(glm::length(a.models[k].center - b.models[k].center) < 1e-12);
    }
}

TEST_CASE("a gas of 5000 balls baked in slices goes on from each slice as one bake") {
    // From 4,096 models the scene's print, by which a slice is known to go on from the last, is
    // made on a thread of its own beside the setup (EventBake::run): a slice not recognised would
    // start again, predicting every ball anew.
    const Gas gas = make_gas(5000, 0.2, 0.6, 1.0, 0.0, 0, 41);
    auto whole = baked(gas, 0.3);
    auto sliced = timeline_of(gas.doc);
    for (double until : {0.1, 0.2, 0.3}) sliced->bake(until);
    CHECK(count_of(*whole, "gas lane events") > 1000.0);
    CAPTURE(count_of(*sliced, "predictions"), count_of(*whole, "predictions"));
    CHECK(count_of(*sliced, "predictions") <= 1.05 * count_of(*whole, "predictions"));
    REQUIRE(sliced->events().size() == whole->events().size());
    size_t different = 0;
    for (size_t k = 0; k < whole->events().size(); ++k)
        different += std::abs(sliced->events()[k].t - whole->events()[k].t) > 1e-12 ||
                     sliced->events()[k].a != whole->events()[k].a ||
                     sliced->events()[k].b != whole->events()[k].b;
    CHECK(different == 0);
}

TEST_CASE("the gas lane takes only the plain elastic gas") {
    // What it does not do (gravity, restitution, friction, spin, another radius) is the general
    // engine's: with any of it, the lane bakes nothing and the events are the general engine's.
    auto lane_events = [](Gas gas) {
        auto t = baked(gas, 0.5);
        return count_of(*t, "gas lane events");
    };
    CHECK(lane_events(make_gas(100, 0.2, 0.6, 1.0, 2.0, 0, 37)) > 0.0);
    {
        Gas gas = make_gas(100, 0.2, 0.6, 1.0, 2.0, 0, 37);
        Settings s = gas.doc.settings();
        s.gravity = 9.81;
        gas.doc.set_settings(s);
        Model m = gas.doc.models()[5];
        m.gravity = true;
        gas.doc.set_model(5, m);
        CHECK(lane_events(gas) == 0.0);
    }
    {
        Gas gas = make_gas(100, 0.2, 0.6, 1.0, 2.0, 0, 37);
        Model m = gas.doc.models()[7];
        m.restitution = 0.9;
        gas.doc.set_model(7, m);
        CHECK(lane_events(gas) == 0.0);
    }
    {
        Gas gas = make_gas(100, 0.2, 0.6, 1.0, 2.0, 0, 37);
        Model box = gas.doc.models()[0];
        box.friction = 0.3;
        gas.doc.set_model(0, box);
        CHECK(lane_events(gas) == 0.0);
    }
    {
        Gas gas = make_gas(100, 0.2, 0.6, 1.0, 2.0, 0, 37);
        ModelState st = *gas.doc.keyframes().front().states[3];
        st.scale = glm::dvec3(0.19);
        gas.doc.set_state(0, 3, st);
        CHECK(lane_events(gas) == 0.0);
    }
    {
        // Two balls overlapping where the bake starts: the general engine's overlap rules.
        Gas gas = make_gas(100, 0.2, 0.6, 1.0, 2.0, 0, 37);
        ModelState st = *gas.doc.keyframes().front().states[2];
        st.center = gas.doc.keyframes().front().states[1]->center + glm::dvec3(0.1, 0.0, 0.0);
        gas.doc.set_state(0, 2, st);
        CHECK(lane_events(gas) == 0.0);
    }
}

TEST_CASE("a gas of 5000 balls is taken or refused as one pass over its models in order would") {
    // From 4,096 models the lane's look at the scene (EventBake::gas_from_scene) goes through the
    // models in two halves at once: what it finds must be what one pass in order finds.
    const auto lane_events = [](const Gas &gas) {
        auto t = baked(gas, 0.1);
        return count_of(*t, "gas lane events");
    };
    const auto with_ball = [](Gas gas, int k, const std::function<void(Model &)> &change) {
        Model m = gas.doc.models()[static_cast<size_t>(gas.first_ball + k)];
        change(m);
        gas.doc.set_model(gas.first_ball + k, m);
        return gas;
    };
    const Gas gas = make_gas(5000, 0.2, 0.6, 1.0, 6.0, 0, 43);
    CHECK(lane_events(gas) > 0.0);
    // A ball in the second half the lane does not take: the general engine bakes them all.
    CHECK(lane_events(with_ball(gas, 4700, [](Model &m) { m.restitution = 0.9; })) == 0.0);
    // Each half a radius of its own, each alike within: not one gas. (The halves split the
    // 5,001 models, the box first, at model 2,500: ball 2,499.)
    {
        Gas two = gas;
        for (int k = 2499; k < 5000; ++k) {
            ModelState st =
                *two.doc.keyframes().front().states[static_cast<size_t>(two.first_ball + k)];
            st.scale = glm::dvec3(0.19);
            two.doc.set_state(0, two.first_ball + k, st);
        }
        CHECK(lane_events(two) == 0.0);
    }
}

TEST_CASE("the gas lane under gravity finds the same collisions as the general engine") {
    // Balls under gravity in a box: one acceleration for all, so a pair's gap still closes as a
    // quadratic; the cells and walls are met on parabolas (first_exit, sphere_triangle).
    const auto falling = [](bool lane) {
        Gas gas = make_gas(300, 0.2, 0.6, 1.0, 3.0, 0, 41, lane);
        Settings s = gas.doc.settings();
        s.gravity = G;
        gas.doc.set_settings(s);
        for (int k = 1; k < static_cast<int>(gas.doc.models().size()); ++k) {
            Model m = gas.doc.models()[static_cast<size_t>(k)];
            m.gravity = true;
            gas.doc.set_model(k, m);
        }
        return gas;
    };
    const Gas lane = falling(true), general = falling(false);
    auto a = baked(lane, 3.0), b = baked(general, 3.0);
    INFO(a->events().size() << " collisions in the lane");
    CHECK(count_of(*a, "gas lane events") >= static_cast<double>(a->events().size()));
    CHECK(count_of(*a, "gas lane hand-offs") == 0.0);
    CHECK(count_of(*b, "gas lane events") == 0.0);
    same_first_collisions(*a, *b, 300);
    same_places(*a, *b, 0.2);
    // Kinetic and potential energy (y is up) kept to rounding, no overlap, all inside the box.
    const auto energy = [&](double t) {
        const Frame f = a->evaluate(t);
        double e = 0.0;
        for (size_t k = 0; k < lane.mass.size(); ++k) {
            const auto &m = f.models[k + 1];
            e += lane.mass[k] * (0.5 * glm::dot(m.velocity, m.velocity) + G * (m.center.y + 3.0));
        }
        return e;
    };
    const double e0 = energy(0.0);
    for (double t : {0.7, 1.9, 3.0}) {
        CAPTURE(t);
        CHECK(std::abs(energy(t) - e0) / e0 < 1e-12);
        CHECK(totals(lane, *a, t).overlap < 1e-9);
        const Frame f = a->evaluate(t);
        for (size_t k = 1; k < f.models.size(); ++k)
            for (int c = 0; c < 3; ++c)
                CHECK(std::abs(f.models[k].center[c]) < 3.0 - lane.radius[k - 1] + 1e-9);
    }
}

TEST_CASE("gas.ani, the example gas, is baked by the gas lane") {
    // 125 balls under gravity in a box (the example): the lane takes it, and its first
    // collisions are the general engine's.
    const auto file = test::source_dir() / "assets/animations/gas.ani";
    const Document doc = open_document(env().plugins, file).document;
    Document off = doc;
    Settings s = off.settings();
    s.params["physics.custom"]["gas_lane"] = {0.0, 0, 0, 0};
    off.set_settings(s);
    const auto bake = [](const Document &d) {
        auto t = timeline_of(d);
        t->bake(10.0);
        return t;
    };
    auto a = bake(doc), b = bake(off);
    CHECK(count_of(*a, "gas lane events") > 10000.0);
    CHECK(count_of(*a, "gas lane hand-offs") == 0.0);
    CHECK(count_of(*b, "gas lane events") == 0.0);
    same_first_collisions(*a, *b, 200);
}
