// physics.bullet baked in slices, as the editor bakes (EditorSession::bake_some: Timeline::bake
// with a growing `until`), goes on with one Bullet world: it builds one world, takes the steps
// one whole bake takes, and bakes what the whole bake bakes (issue 16: each slice built a new
// world and restarted Bullet from the states the host kept). Measured by the backend's own
// counts and against the whole bake, never by a timing.
#include "bullet_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace animator;
using namespace animator::bullet_test;
namespace fs = std::filesystem;

namespace {

constexpr double kStep = 1.0 / 240.0; // physics.bullet's default step

double count(const Timeline &t, const std::string &name) {
    const auto &counts = t.stats().backend_counts;
    const auto it = counts.find(name);
    return it == counts.end() ? 0.0 : it->second;
}

// The largest distance between the two bakes' centers of any model, sampled every 5 ms.
double largest_gap(const Timeline &a, const Timeline &b, double until, std::size_t models) {
    double gap = 0.0;
    for (int k = 0; k <= static_cast<int>(until / 0.005); ++k) {
        const double t = std::min(until, 0.005 * k);
        const Frame fa = a.evaluate(t), fb = b.evaluate(t);
        for (std::size_t m = 0; m < models; ++m)
            gap = std::max(gap, glm::length(fa.models[m].center - fb.models[m].center));
    }
    return gap;
}

// Bakes `doc` to `until` whole, and in slices of `slice` seconds; checks the sliced bake builds
// one world, takes the whole bake's steps, and bakes its events, overlaps and motion.
void check_sliced(const Document &doc, double until, double slice) {
    auto whole = timeline_of(doc);
    whole->bake(until);
    auto sliced = timeline_of(doc);
    const int slices = static_cast<int>(std::ceil(until / slice - 1e-9));
    for (int k = 1; k <= slices; ++k) sliced->bake(std::min(until, slice * k));
    REQUIRE(sliced->baked_until() == until);
    CAPTURE(slices);
    CHECK(count(*whole, "worlds built") == 1.0);
    CHECK(count(*sliced, "worlds built") == 1.0);
    CHECK(count(*sliced, "shapes built") == count(*whole, "shapes built"));
    CHECK(count(*sliced, "steps") == count(*whole, "steps"));
    // Bullet's own steps: coasting (closed-form steps) stops at each slice's end, and the slice
    // takes at most two steps of Bullet's past it where the whole bake may have coasted.
    const double stepped_whole = count(*whole, "steps") - count(*whole, "steps coasted");
    const double stepped_sliced = count(*sliced, "steps") - count(*sliced, "steps coasted");
    CAPTURE(stepped_whole, stepped_sliced);
    CHECK(stepped_sliced <= 1.2 * stepped_whole + 2.0 * slices);

    REQUIRE(sliced->events().size() == whole->events().size());
    for (size_t k = 0; k < whole->events().size(); ++k) {
        CAPTURE(k, whole->events()[k].t);
        CHECK(sliced->events()[k].t == Approx(whole->events()[k].t).margin(kStep));
        CHECK(sliced->events()[k].a == whole->events()[k].a);
        CHECK(sliced->events()[k].b == whole->events()[k].b);
    }
    REQUIRE(sliced->overlaps().size() == whole->overlaps().size());
    for (size_t k = 0; k < whole->overlaps().size(); ++k) {
        CHECK(sliced->overlaps()[k].t == whole->overlaps()[k].t);
        CHECK(sliced->overlaps()[k].a == whole->overlaps()[k].a);
        CHECK(sliced->overlaps()[k].b == whole->overlaps()[k].b);
        CHECK(sliced->overlaps()[k].depth == whole->overlaps()[k].depth);
    }
    // Every model where the whole bake puts it (the same steps: to rounding).
    const std::size_t models = doc.models().size();
    CHECK(largest_gap(*whole, *sliced, until, models) <= 1e-9);
    // Each model's segments cover the bake once, in time order, without gaps.
    for (std::size_t m = 0; m < models; ++m) {
        const auto &segments = sliced->segments(static_cast<int>(m));
        REQUIRE_FALSE(segments.empty());
        CHECK(segments.front().t0 == 0.0);
        CHECK(segments.back().t1 == until);
        for (std::size_t k = 1; k < segments.size(); ++k)
            CHECK(segments[k].t0 == segments[k - 1].t1);
    }
}

Document open(const fs::path &file) {
    return open_document(env().plugins, file).document;
}

} // namespace

TEST_CASE(
    "a bake in 50 ms slices builds one world and bakes what one bake does, on every example") {
    std::vector<fs::path> files = {fs::path(ANIMATOR_SOURCE_DIR) / "assets/scenes/simple.lua"};
    for (const auto &entry :
         fs::directory_iterator(fs::path(ANIMATOR_SOURCE_DIR) / "assets/animations"))
        if (entry.path().extension() == ".ani") files.push_back(entry.path());
    for (const fs::path &file : files) {
        CAPTURE(file.filename().string());
        const Document doc = open(file);
        const double end = static_cast<double>(doc.settings().max_time_ms) / 1000.0;
        check_sliced(doc, std::min(end, 10.0), 0.05);
    }
}

TEST_CASE("a bake in slices off the step's grid builds one world and bakes what one bake does") {
    // The editor's slices halve and double from 0.25 s: 31.25 ms is 7.5 steps of 1/240 s.
    const Document doc = open(fs::path(ANIMATOR_SOURCE_DIR) / "assets/animations/drop.ani");
    check_sliced(doc, 6.0, 0.03125);
    check_sliced(doc, 3.0, 0.001); // slices shorter than a step
}

TEST_CASE("a bake in slices: a keyed model sliding on the floor, an overlap at the start") {
    // Issue 16's reproduction: simple.lua, the cylinder (resting on the floor) keyed at 3 s two
    // metres along the floor, so that for 3 s its keys slide it along the floor, touching it.
    Document doc = open(fs::path(ANIMATOR_SOURCE_DIR) / "assets/scenes/simple.lua");
    const int cylinder = doc.find_model("cylinder");
    REQUIRE(cylinder >= 0);
    ModelState moved = *doc.keyframes().front().states[static_cast<size_t>(cylinder)];
    moved.center.z += 2.0;
    key(doc, 3000, cylinder, moved);
    check_sliced(doc, 6.0, 0.05);

    // A ball sunk into a floor, moving down: a contact at once, the overlap reported once.
    Document sunk;
    sunk.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    Model ball = model("ball", "sphere", true, true);
    ball.initial_velocity = {0, -1, 0};
    sunk.add_model(ball, placed({0.3, 0.3, 0.2}, glm::dvec3(0.5)));
    check_sliced(sunk, 4.0, 0.05);
}

TEST_CASE("a slice that does not continue the last one builds a new world") {
    // A ball dropped on a floor, and a cube keyed at 0, 2 and 5 s.
    Document doc;
    doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, glm::dvec3(10.0)));
    doc.add_model(model("ball", "sphere", true, true), placed({0, 3, 0}, glm::dvec3(0.5)));
    doc.add_model(model("cube", "cube", false, false), placed({5, 1, 0}));
    key(doc, 2000, 2, placed({5, 2, 0}));
    key(doc, 5000, 2, placed({5, 3, 0}));
    auto t = timeline_of(doc);
    for (int k = 1; k <= 20; ++k) t->bake(0.05 * k);
    CHECK(count(*t, "worlds built") == 1.0);

    // An edit after what is baked (the key at 5 s; it changes the motion from 2 s): the next
    // slice starts where the last stopped, but the scene is another.
    Document edited = doc;
    key(edited, 5000, 2, placed({5, 4, 0}));
    t->edit(edited);
    REQUIRE(t->baked_until() == 1.0);
    t->bake(1.05);
    CHECK(count(*t, "worlds built") == 2.0);
    t->bake(1.1);
    CHECK(count(*t, "worlds built") == 2.0);

    // An edit before it (the key at 2 s): baked again from 0.
    Document earlier = edited;
    key(earlier, 2000, 2, placed({5, 2.5, 0}));
    t->edit(earlier);
    REQUIRE(t->baked_until() == 0.0);
    t->bake(0.05);
    CHECK(count(*t, "worlds built") == 3.0);
}
