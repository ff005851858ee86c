// Swapping the physics backend while the program runs: the timeline re-bakes with the new one,
// the document stays as it was, and a backend that cannot be created leaves the previous one.
#include "assets/asset_paths.hpp"
#include "io/environment.hpp"
#include "timeline/timeline.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace animator;

namespace {

Environment &env() {
    static Environment e({test::bin_dir().parent_path() / "assets"}, {test::bin_dir()},
                         [](ani_log_level, const std::string &, const std::string &) {});
    return e;
}

// Three balls in a box, gravity on: collisions for the bake to find.
Document balls_in_a_box() {
    Document doc;
    Model box;
    box.name = "box";
    box.mesh = "cube";
    ModelState s;
    s.scale = glm::dvec3(3.0);
    doc.add_model(box, s);
    for (int k = 0; k < 3; ++k) {
        Model ball;
        ball.name = "ball" + std::to_string(k);
        ball.mesh = "sphere";
        ball.dynamics = ball.gravity = true;
        ball.initial_velocity = {1.0 + k, 0.5 * k, -0.3};
        ModelState b;
        b.center = {-1.0 + k, 0.5 * k, 0.0};
        b.scale = glm::dvec3(0.3);
        doc.add_model(ball, b);
    }
    return doc;
}

std::unique_ptr<Timeline> timeline_of(const Document &doc, const std::string &backend = "") {
    auto t = std::make_unique<Timeline>(doc, env().plugins, backend);
    std::vector<std::string> ids, warnings;
    for (const Model &m : doc.models()) ids.push_back(m.mesh);
    t->set_meshes(load_meshes(ids, env().assets, {}, warnings));
    return t;
}

} // namespace

TEST_CASE("a backend that cannot be created leaves the previous one and its bake in place") {
    const Document doc = balls_in_a_box();
    auto timeline = timeline_of(doc);
    timeline->bake(5.0);
    const auto events = timeline->events().size();
    const glm::dvec3 before = timeline->evaluate(4.0).models[2].center;
    CHECK_THROWS_WITH(timeline->set_backend("physics.nope"),
                      Catch::Contains("no physics backend 'physics.nope'"));
    CHECK(timeline->backend_id() == "physics.custom");
    CHECK(timeline->events().size() == events);
    CHECK(timeline->evaluate(4.0).models[2].center == before);
    CHECK(timeline->baked_until() == 5.0);
}

TEST_CASE("swapping the backend re-bakes to where it was and keeps the document") {
    const Document doc = balls_in_a_box();
    auto timeline = timeline_of(doc);
    timeline->bake(5.0);
    const auto events = timeline->events();
    timeline->set_backend("physics.custom");
    CHECK(timeline->document() == doc);
    CHECK(timeline->baked_until() == 5.0);
    REQUIRE(timeline->events().size() == events.size());
    for (size_t k = 0; k < events.size(); ++k) CHECK(timeline->events()[k].t == events[k].t);
    CHECK(timeline->stats().bake_calls == 2);
}

TEST_CASE(
    "a changed backend parameter in the document reaches the backend when the timeline takes it") {
    Document doc = balls_in_a_box();
    auto timeline = timeline_of(doc);
    timeline->bake(3.0);
    CHECK(timeline->stats().backend_counts.at("cell crossings") == 0); // three balls: all pairs
    Settings s = doc.settings();
    s.params["physics.custom"]["broad_phase"] = {1, 0, 0, 0}; // the grid, always
    doc.set_settings(s);
    timeline->set_document(doc);
    CHECK(timeline->stats().backend_counts.at("cell crossings") > 0);
    // A value the backend refuses leaves the timeline as it was.
    Document bad = doc;
    s.params["physics.custom"]["broad_phase"] = {7, 0, 0, 0};
    bad.set_settings(s);
    CHECK_THROWS(timeline->set_document(bad));
    CHECK(timeline->document() == doc);
}

TEST_CASE("swapping to Bullet and back keeps the document and gives back the exact bake") {
    const Document doc = balls_in_a_box();
    auto timeline = timeline_of(doc);
    timeline->bake(3.0);
    const glm::dvec3 exact = timeline->evaluate(2.5).models[1].center;
    timeline->set_backend("physics.bullet");
    CHECK(timeline->backend_id() == "physics.bullet");
    CHECK(timeline->document() == doc);
    CHECK(timeline->baked_until() == 3.0);
    // Bullet's stepped bake is its own (three balls colliding are chaotic: not close to the exact
    // one after a few contacts), still inside the box.
    const glm::dvec3 stepped = timeline->evaluate(2.5).models[1].center;
    CHECK(stepped != exact);
    CHECK(std::max({std::abs(stepped.x), std::abs(stepped.y), std::abs(stepped.z)}) < 3.0);
    CHECK(timeline->stats().backend_counts.count("steps") == 1);
    timeline->set_backend("");
    CHECK(timeline->backend_id() == "physics.custom");
    CHECK(timeline->document() == doc);
    CHECK(timeline->evaluate(2.5).models[1].center == exact);
}
