// physics.custom's gas lane (gas_lane.hpp) driven directly, on scenes small enough to know every
// number: a head-on pair, and the events it does not take and stops before (the general engine's
// to handle: tests/physics/gas_test.cpp has the whole bakes).
#include "calendar_queue.hpp"
#include "gas_lane.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <random>
#include <set>
#include <utility>
#include <vector>

using physics_custom::GasLane;

namespace {

struct Recorder : GasLane::Sink {
    std::vector<ani_motion_segment> segments;
    std::vector<ani_collision_event> collisions;
    void segment(const ani_motion_segment &s) override { segments.push_back(s); }
    void collision(const ani_collision_event &e) override { collisions.push_back(e); }
    void progress(double) override {}
};

// Cells 1.5 m wide from (-5, -5, -5), 7 a side: spheres of radius 0.5 (2r = 1 <= 1.5).
GasLane::Grid grid() {
    GasLane::Grid g;
    g.origin = glm::dvec3(-5.0);
    g.cell = 1.5;
    g.counts = {7, 7, 7};
    return g;
}

GasLane::Start ball(uint32_t model, glm::dvec3 p, glm::dvec3 v) {
    GasLane::Start s;
    s.model = model;
    s.p = p;
    s.v = v;
    return s;
}

// A floor: one large triangle in the plane y = 0, facing up.
GasLane::Triangle floor_triangle() {
    GasLane::Triangle t;
    t.a = {-10.0, 0.0, 10.0};
    t.b = {10.0, 0.0, 10.0};
    t.c = {0.0, 0.0, -10.0};
    t.normal = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
    t.offset = glm::dot(t.normal, t.a);
    t.box = {{-10.0, 0.0, -10.0}, {10.0, 0.0, 10.0}};
    t.model = 9;
    return t;
}

} // namespace

TEST_CASE("the gas lane exchanges a head-on pair's velocities at the time they touch") {
    // Centres 3 m apart closing at 2 m/s, radius 0.5: they touch after (3 - 1) / 2 = 1 s.
    GasLane lane(
        0.5, glm::dvec3(0.0), grid(), {},
        {ball(1, {-1.5, 0.0, 0.0}, {1.0, 0.0, 0.0}), ball(2, {1.5, 0.0, 0.0}, {-1.0, 0.0, 0.0})},
        0.0);
    Recorder out;
    REQUIRE(lane.run(0.0, 2.0, out));
    REQUIRE(out.collisions.size() == 1);
    const ani_collision_event &e = out.collisions[0];
    CHECK(e.t == 1.0);
    CHECK(e.speed == 2.0);
    CHECK(std::abs(e.normal.x) == 1.0);
    lane.close(0.0, 2.0, out);
    // Equal masses: the velocities are exchanged; each ball's segments, to the collision then on.
    CHECK(lane.state(0).v == glm::dvec3(-1.0, 0.0, 0.0));
    CHECK(lane.state(1).v == glm::dvec3(1.0, 0.0, 0.0));
    CHECK(lane.state(0).p == glm::dvec3(-0.5, 0.0, 0.0));
    REQUIRE(out.segments.size() == 4);
    CHECK(out.segments[0].t1 == 1.0);
    CHECK(out.segments[3].t1 == 2.0);
    CHECK(lane.counts().events >= 1);
}

TEST_CASE("the gas lane stops before a grazing contact") {
    // A ball passing another at exactly 2r, its velocity along the touching plane: the general
    // engine leaves such a pair alone until it is apart, the lane hands it over at t = 2.
    GasLane lane(
        0.5, glm::dvec3(0.0), grid(), {},
        {ball(1, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}), ball(2, {2.0, 1.0, 0.0}, {0.0, 0.0, 0.0})},
        0.0);
    Recorder out;
    CHECK_FALSE(lane.run(0.0, 5.0, out));
    CHECK(lane.stopped_at() == 2.0);
    CHECK(out.collisions.empty());
    // Where it stopped, nothing moved on: the ball is still on its first segment.
    CHECK(lane.state(0).t0 == 0.0);
    CHECK(lane.state(0).p == glm::dvec3(0.0));
}

TEST_CASE("the gas lane stops before a contact that would leave a ball touching a face without "
          "speed along it") {
    // Two balls standing on a floor, one pushed into the other: after the blow the other would
    // slide along the floor touching it, which the general engine puts on the floor (a support).
    GasLane lane(
        0.5, glm::dvec3(0.0), grid(), {floor_triangle()},
        {ball(1, {0.0, 0.5, 0.0}, {0.0, 0.0, 0.0}), ball(2, {-2.0, 0.5, 0.0}, {1.0, 0.0, 0.0})},
        0.0);
    Recorder out;
    CHECK_FALSE(lane.run(0.0, 5.0, out));
    CHECK(lane.stopped_at() == 1.0);
    CHECK(out.collisions.empty());
    // Checked for the start as well: not apart from the floor, such balls are not the lane's.
    GasLane checked(
        0.5, glm::dvec3(0.0), grid(), {floor_triangle()},
        {ball(1, {0.0, 0.5, 0.0}, {0.0, 0.0, 0.0}), ball(2, {-2.0, 0.5, 0.0}, {1.0, 0.0, 0.0})},
        0.0, true);
    CHECK_FALSE(checked.admissible());
}

TEST_CASE("the gas lane bounces a ball off a face and stops where a ball leaves its grid") {
    // Thrown down at 1 m/s from y = 2.5 onto the floor, a ball bounces straight back up at t = 2
    // (its lowest point touching y = 0); thrown sideways at 1 m/s from x = 2, the other leaves the
    // grid (x < 5.5) through the last cell's wall at t = 3.5, where the lane stops.
    GasLane lane(
        0.5, glm::dvec3(0.0), grid(), {floor_triangle()},
        {ball(1, {0.0, 2.5, 0.0}, {0.0, -1.0, 0.0}), ball(2, {2.0, 3.0, 3.0}, {1.0, 0.0, 0.0})},
        0.0);
    Recorder out;
    CHECK_FALSE(lane.run(0.0, 5.0, out));
    REQUIRE(out.collisions.size() == 1);
    CHECK(out.collisions[0].t == 2.0);
    CHECK(out.collisions[0].b == 9u);
    CHECK(out.collisions[0].speed == 1.0);
    CHECK(lane.state(0).v == glm::dvec3(0.0, 1.0, 0.0));
    // The grid's last cell along x ends at -5 + 7 * 1.5 = 5.5: reached after 3.5 s.
    CHECK(lane.stopped_at() == 3.5);
}

TEST_CASE("the gas lane takes balls only when every pair is apart by the general engine's "
          "allowance") {
    // Radius 0.5: two balls closer than 2r (1 - 1e-6) overlap for the general engine, and are not
    // the lane's; farther, they are. Each pair whichever ball comes first, in one cell or two.
    const auto admissible = [](glm::dvec3 p, glm::dvec3 q) {
        return GasLane(0.5, glm::dvec3(0.0), grid(), {},
                       {ball(1, p, glm::dvec3(0.0)), ball(2, {3.0, 3.0, 3.0}, glm::dvec3(0.0)),
                        ball(3, q, glm::dvec3(0.0))},
                       0.0, true)
            .admissible();
    };
    const double inside = 1.0 * (1.0 - 2e-6), outside = 1.0 * (1.0 - 0.5e-6);
    for (const glm::dvec3 at : {glm::dvec3(0.1, 0.2, 0.3), glm::dvec3(-0.7, -0.05, 0.0)}) {
        for (const glm::dvec3 dir : {glm::dvec3(1.0, 0.0, 0.0), glm::normalize(glm::dvec3(1.0, -2.0, 2.0))}) {
            CAPTURE(at.x, dir.y);
            CHECK_FALSE(admissible(at, at + inside * dir));
            CHECK_FALSE(admissible(at + inside * dir, at));
            CHECK(admissible(at, at + outside * dir));
            CHECK(admissible(at + outside * dir, at));
        }
    }
}

TEST_CASE(
    "the gas lane's start in two halves finds two balls too close in either half or between") {
    // 4,913 balls of radius 0.5 on a lattice 1.6 m apart (17 a side), cells 1.5 m wide: the start
    // checks its pairs in two halves at once from 4,096 balls, below and above the middle layers
    // of cells, then the layer between (GasLane::predict_all_pairs). One ball moved to 2r (1 -
    // 2e-6) from its neighbour along x, low, in the middle or high, is found wherever it is.
    const int side = 17;
    GasLane::Grid g;
    g.origin = glm::dvec3(-1.0);
    g.cell = 1.5;
    g.counts = {20, 20, 20};
    const auto lattice = [&](int moved) {
        std::vector<GasLane::Start> balls;
        for (int k = 0; k < side * side * side; ++k) {
            const glm::dvec3 at(k % side, (k / side) % side, k / (side * side));
            balls.push_back(ball(static_cast<uint32_t>(k), at * 1.6, glm::dvec3(0.0, 0.0, 0.1)));
        }
        if (moved >= 0)
            balls[static_cast<size_t>(moved)].p =
                balls[static_cast<size_t>(moved) + 1].p - glm::dvec3(1.0 - 2e-6, 0.0, 0.0);
        return balls;
    };
    const auto admissible = [&](int moved) {
        const std::vector<GasLane::Start> balls = lattice(moved);
        return GasLane(0.5, glm::dvec3(0.0), g, {},
                       ani::HugeVector<GasLane::Start>(balls.begin(), balls.end()), 0.0, true)
            .admissible();
    };
    CHECK(admissible(-1));
    // Ball k's layer of cells is floor((1 + 1.6 z) / 1.5): z = 1 (layer 1, below), z = 8 (layer
    // 9, the one between the halves: 20 / 2 - 1), z = 15 (layer 16, above).
    for (int z : {1, 8, 15}) {
        CAPTURE(z);
        CHECK_FALSE(admissible(z * side * side + 3 * side + 5));
    }
}

TEST_CASE("the calendar queue's second item is the one after its top") {
    // The lane fetches the next event's records ahead from second(): checked against every time
    // kept sorted, through 20,000 events of 2,000 items each moved later by a random time.
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> later(0.0, 1.0);
    const uint32_t n = 2000;
    std::vector<double> times(n);
    std::set<std::pair<double, uint32_t>> sorted;
    for (uint32_t i = 0; i < n; ++i) {
        times[i] = later(rng);
        sorted.insert({times[i], i});
    }
    physics_custom::CalendarQueue queue;
    queue.init(times.data(), n, 0.0);
    int answered = 0;
    for (int step = 0; step < 20000; ++step) {
        CAPTURE(step);
        const double now = queue.top_time();
        REQUIRE(now == sorted.begin()->first);
        const uint32_t top = queue.top(), second = queue.second();
        REQUIRE(top == sorted.begin()->second);
        if (second != 0xffffffffu) {
            ++answered;
            CHECK(second == std::next(sorted.begin())->second);
        }
        sorted.erase(sorted.begin());
        times[top] = now + later(rng);
        sorted.insert({times[top], top});
        queue.update(top, times[top]);
    }
    // (A bucket holds about 16 events: its last has no second in it.)
    CHECK(answered > 15000);
}
