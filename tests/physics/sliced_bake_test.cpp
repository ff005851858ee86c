// physics.custom baked in slices, as the editor bakes (EditorSession::bake_some: Timeline::bake
// with a growing `until`), does the work of one whole bake, not more: a slice never redoes what
// an earlier slice finished (issue 16: a keyed model touching the floor made a sliced bake 1000
// times slower). Measured by the backend's own counts, never by a timing.
#include "io/document_io.hpp"

#include "scene_support.hpp"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace animator;
using namespace physics_test;
namespace fs = std::filesystem;

namespace {

double count(const Timeline &t, const std::string &name) {
    const auto &counts = t.stats().backend_counts;
    const auto it = counts.find(name);
    return it == counts.end() ? 0.0 : it->second;
}

Document with_custom(Document doc) {
    Settings s = doc.settings();
    s.physics_backend = "physics.custom";
    doc.set_settings(s);
    return doc;
}

// Bakes `doc` to `until` whole, and in slices of `slice` seconds; checks the sliced bake's
// predictions and conservative advancements are at most 1.2 times the whole bake's, and that
// both bake the same collisions at the same times.
void check_sliced(const Document &doc, double until, double slice) {
    auto whole = timeline_of(doc);
    whole->bake(until);
    auto sliced = timeline_of(doc);
    const int slices = static_cast<int>(std::ceil(until / slice));
    for (int k = 1; k <= slices; ++k) sliced->bake(std::min(until, slice * k));
    for (const char *name : {"predictions", "conservative advancements"}) {
        CAPTURE(name, count(*whole, name), count(*sliced, name), slices);
        CHECK(count(*sliced, name) <= 1.2 * count(*whole, name));
    }
    REQUIRE(sliced->events().size() == whole->events().size());
    for (size_t k = 0; k < whole->events().size(); ++k) {
        CAPTURE(k);
        CHECK(sliced->events()[k].t == Approx(whole->events()[k].t).margin(1e-9));
        CHECK(sliced->events()[k].a == whole->events()[k].a);
        CHECK(sliced->events()[k].b == whole->events()[k].b);
    }
}

} // namespace

TEST_CASE("a bake in many slices does the work of one bake, on every example") {
    std::vector<fs::path> files = {test::source_dir() / "assets/scenes/simple.lua"};
    for (const auto &entry : fs::directory_iterator(test::source_dir() / "assets/animations"))
        if (entry.path().extension() == ".ani") files.push_back(entry.path());
    for (const fs::path &file : files) {
        CAPTURE(file.filename().string());
        const Document doc = with_custom(open_document(env().plugins, file).document);
        const double end = static_cast<double>(doc.settings().max_time_ms) / 1000.0;
        check_sliced(doc, std::min(end, 10.0), 0.05);
    }
}

TEST_CASE("a bake in many slices does the work of one bake: a keyed model sliding on the floor") {
    // Issue 16's reproduction: simple.lua, the cylinder (resting on the floor) keyed at 3 s two
    // metres along the floor, so that for 3 s its keys slide it along the floor, touching it.
    Document doc = with_custom(
        open_document(env().plugins, test::source_dir() / "assets/scenes/simple.lua").document);
    const int cylinder = doc.find_model("cylinder");
    REQUIRE(cylinder >= 0);
    ModelState moved = *doc.keyframes().front().states[static_cast<size_t>(cylinder)];
    moved.center.z += 2.0;
    key(doc, 3000, cylinder, moved);
    check_sliced(doc, 6.0, 0.05);
}

TEST_CASE("a bake in many slices does the work of one bake: a cube tipping over its edge") {
    // The hinge (bake_hinge.cpp) spans eleven slices of 0.05 s: each slice reports its part of
    // the hinge segment, and the landing is where the whole bake has it.
    const Document doc = with_custom(
        open_document(env().plugins, test::source_dir() / "assets/scenes/tipping_cube.lua").document);
    check_sliced(doc, 1.0, 0.05);
}

TEST_CASE("a die dropped on a moving platform lands where one bake has it, in slices of any length") {
    // The editor's platform_drop case: platform_ride.ani's box made a die (Rotates on) held
    // 0.25 m over the moving platform. The editor bakes in slices as long as a frame allows, so
    // under load they are uneven: the same events at the same times, whatever the slices.
    Document doc = with_custom(
        open_document(env().plugins, test::source_dir() / "assets/animations/platform_ride.ani")
            .document);
    const int box = doc.find_model("box");
    REQUIRE(box >= 0);
    Model die = doc.models()[static_cast<size_t>(box)];
    die.rotates = true;
    doc.set_model(box, die);
    ModelState held = *doc.keyframes().front().states[static_cast<size_t>(box)];
    held.center = {-2.0, 1.6, 0.0};
    key(doc, 0, box, held);
    auto whole = timeline_of(doc);
    whole->bake(7.0);
    for (const double first : {0.013, 0.05, 0.071}) {
        auto sliced = timeline_of(doc);
        double until = 0.0;
        for (int k = 0; until < 7.0; ++k) {
            until = std::min(7.0, until + first * (1.0 + 0.7 * ((k * 7) % 5)));
            sliced->bake(until);
        }
        CAPTURE(first);
        REQUIRE(sliced->events().size() == whole->events().size());
        for (size_t k = 0; k < whole->events().size(); ++k) {
            CAPTURE(k);
            CHECK(sliced->events()[k].t == Approx(whole->events()[k].t).margin(1e-9));
            CHECK(sliced->events()[k].a == whole->events()[k].a);
            CHECK(sliced->events()[k].b == whole->events()[k].b);
        }
    }
}
