// The scenes and examples the project ships (assets/scenes/*.lua, assets/animations/*.ani, the
// latter partly written by tools/examples/*.py) start with no two models inside each other, and
// stairs.ani does what its comment says.
#include "io/document_io.hpp"

#include "scene_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>

using namespace animator;
using namespace physics_test;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> shipped_files() {
    std::vector<fs::path> files;
    for (const char *folder : {"assets/scenes", "assets/animations"})
        for (const auto &entry : fs::directory_iterator(test::source_dir() / folder))
            if (entry.path().extension() == ".lua" || entry.path().extension() == ".ani")
                files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

// What physics.custom says about the models of `doc` overlapping at t = 0. Its check looks at
// each model that can move against every other; a model that cannot move (a floor, a model
// with no physics ticked) is checked by ticking its Gravity, as a user would, one model at a
// time (so that the others stay static models, against which every mesh is checked).
std::vector<std::string> overlaps_at_start(const Document &doc) {
    std::vector<std::string> said;
    Environment logged({test::bin_dir().parent_path() / "assets"}, {test::bin_dir()},
                       [&](ani_log_level, const std::string &, const std::string &m) {
                           if (m.find("overlap") != std::string::npos) said.push_back(m);
                       });
    std::vector<std::string> ids, warnings;
    for (const Model &m : doc.models()) ids.push_back(m.mesh);
    const auto meshes = load_meshes(ids, logged.assets, {}, warnings);
    REQUIRE(warnings.empty());
    for (int probe = -1; probe < static_cast<int>(doc.models().size()); ++probe) {
        Document d = doc;
        Settings s = d.settings();
        s.physics_backend = "physics.custom";
        d.set_settings(s);
        if (probe >= 0) {
            const Model &m = d.models()[static_cast<size_t>(probe)];
            if (m.mesh.empty() || m.parent >= 0 || m.gravity || m.dynamics) continue;
            Model moving = m;
            moving.gravity = true;
            d.set_model(probe, moving);
        }
        Timeline t(d, logged.plugins);
        t.set_meshes(meshes);
        t.bake(0.0);
    }
    std::sort(said.begin(), said.end());
    said.erase(std::unique(said.begin(), said.end()), said.end());
    return said;
}

} // namespace

TEST_CASE("the overlap check finds a cube sunk into a floor, and not one resting on it") {
    // The check the next test relies on, against a hand-made answer.
    for (const double y : {0.5, 1.0}) {
        Document doc;
        doc.add_model(model("floor", "plane", false, false), placed({0, 0, 0}, 12.0));
        doc.add_model(model("cube", "cube", false, false),
                      placed({-1.5, y, 0}, glm::dvec3(1.0), {0, 30, 0}));
        const auto said = overlaps_at_start(doc);
        CAPTURE(said);
        CHECK(said.empty() == (y >= 1.0));
        for (const std::string &line : said) // with either as the one that moves
            CHECK(
                (line.find("'cube' and 'floor' overlap at t = 0 s by 0.5 m") != std::string::npos ||
                 line.find("'floor' and 'cube' overlap at t = 0 s by 0.5 m") != std::string::npos));
    }
}

TEST_CASE("every shipped scene and example starts with no two models overlapping") {
    const auto files = shipped_files();
    REQUIRE(files.size() >= 6);
    for (const fs::path &file : files) {
        CAPTURE(file.filename().string());
        const Document doc = open_document(env().plugins, file).document;
        const auto said = overlaps_at_start(doc);
        CAPTURE(said); // names the pair
        CHECK(said.empty());
    }
}

TEST_CASE("stairs.ani: the cube bounces down the stairs step by step and stays in view") {
    // Its comment: a hop off the top step, then elastic, frictionless bounces on each tread in
    // turn (tops at 2.5, 2, 1.5, 1, 0.5), and the floor. The cube (half-size 0.25) leaves its keys
    // at 0.4 s at (0.44, 2.92) with velocity 2 d / T = (0.7, 0.85) (kinematic keys from rest).
    const Document doc =
        open_document(env().plugins, test::source_dir() / "assets/animations/stairs.ani").document;
    const int cube = doc.find_model("cube");
    auto t = timeline_of(doc);
    const double end = static_cast<double>(doc.settings().max_time_ms) / 1000.0;
    t->bake(end);
    const auto &events = t->events();
    REQUIRE(events.size() >= 6);
    double tread = 2.5;       // the highest step it may land on next
    std::vector<double> tops; // each tread it lands on, in order
    for (const ani_collision_event &e : events) {
        CAPTURE(e.t);
        CHECK(e.a == static_cast<uint32_t>(cube));
        CHECK(e.normal.y == Approx(1.0)); // flat on a tread, never an edge or a riser
        const glm::dvec3 c = t->evaluate(e.t).models[static_cast<size_t>(cube)].center;
        const double top = c.y - 0.25;
        // On a tread's top, at most as high as the last one: down, step by step.
        CHECK(top == Approx(std::round(2.0 * top) / 2.0).margin(1e-9));
        CHECK(top <= tread + 1e-9);
        tread = std::min(tread, top);
        const double step = std::round(2.0 * top) / 2.0 + 0.0; // +0: no -0
        if (tops.empty() || tops.back() != step) tops.push_back(step);
        // The tread under it: step k spans x in [k, k + 1] at height 2.5 - 0.5 k; the floor
        // beyond x = 5.
        const double k = (2.5 - top) / 0.5;
        CHECK(c.x + 0.25 >= k - 1e-9);
        // Elastic and frictionless: its speed there from its energy when it left its keys.
        CHECK(e.speed == Approx(std::sqrt(0.85 * 0.85 + 2.0 * G * (2.92 - c.y))).epsilon(1e-9));
        CHECK(t->evaluate(e.t).models[static_cast<size_t>(cube)].velocity.x ==
              Approx(0.7).epsilon(1e-12));
    }
    // Every step, from the top one to the floor, in turn.
    CHECK(tops == std::vector<double>{2.5, 2.0, 1.5, 1.0, 0.5, 0.0});
    // The same baked in slices, as the editor does (a slice starts with the cube over a step's
    // edge: touching nothing).
    auto sliced = timeline_of(doc);
    for (int k = 1; k <= 160; ++k) sliced->bake(std::min(end, 0.05 * k));
    REQUIRE(sliced->events().size() == events.size());
    for (size_t k = 0; k < events.size(); ++k)
        CHECK(sliced->events()[k].t == Approx(events[k].t).margin(1e-9));
    // In view to the end: over the stairs (x in [0, 5], z in [-1, 1]) or the floor just past them.
    for (int k = 0; k <= 800; ++k) {
        const glm::dvec3 c = t->evaluate(end * k / 800.0).models[static_cast<size_t>(cube)].center;
        CHECK(c.x >= 0.0);
        CHECK(c.x <= 6.0);
        CHECK(c.z == 0.0);
        CHECK(c.y >= 0.25 - 1e-9);
    }
}
