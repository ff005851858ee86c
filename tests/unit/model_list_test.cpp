// Models copied and removed as a whole (host/document/model_list.hpp): the document after holds
// what it should (kept order, renumbered parents, copied keys moved by the offset), names are
// made unique as Blender makes them, and the edit undoes and redoes exactly.
#include "document/history.hpp"
#include "document/model_list.hpp"

#include <catch2/catch.hpp>

using namespace animator;

namespace {

Model named(const std::string &name, int parent = -1, const std::string &mesh = "cube") {
    Model m;
    m.name = name;
    m.parent = parent;
    m.mesh = mesh;
    return m;
}

ModelState at(double x, double y = 0.0, double z = 0.0) {
    ModelState s;
    s.center = {x, y, z};
    return s;
}

// A scene tree: arm (0) with hand (1) under it and finger (2) under that; ball (3); a key at
// 2 s for the hand and the ball.
Document tree() {
    Document doc;
    doc.add_model(named("arm"), at(0));
    doc.add_model(named("hand", 0), at(1));
    doc.add_model(named("finger", 1), at(0.5));
    doc.add_model(named("ball", -1, "sphere"), at(5));
    Keyframe k;
    k.time_ms = 2000;
    k.states = {std::nullopt, at(2), std::nullopt, at(6, 1)};
    doc.insert_keyframe(k);
    return doc;
}

} // namespace

TEST_CASE("a model's descendants are everything under it at any depth", "[models]") {
    const Document doc = tree();
    CHECK(with_descendants(doc, {0}) == std::set<int>{0, 1, 2});
    CHECK(with_descendants(doc, {1}) == std::set<int>{1, 2});
    CHECK(with_descendants(doc, {3}) == std::set<int>{3});
    CHECK(with_descendants(doc, {1, 3}) == std::set<int>{1, 2, 3});
}

TEST_CASE("removing models keeps the others in order, their keys and renumbered parents", "[models]") {
    const Document doc = tree();
    const Document after = without_models(doc, {1, 2});
    REQUIRE(after.models().size() == 2);
    CHECK(after.models()[0].name == "arm");
    CHECK(after.models()[1].name == "ball");
    CHECK(after.models()[1].parent == -1);
    CHECK(after.keyframes().size() == 2);
    CHECK(*after.keyframe_at(2000).states[1] == at(6, 1));
    CHECK_FALSE(after.keyframe_at(2000).states[0].has_value());
    CHECK(after.keyframe_at(0).camera == doc.keyframe_at(0).camera);
    CHECK(after.settings() == doc.settings());

    // Removing the ball renumbers nobody but must keep the hand under the arm.
    const Document no_ball = without_models(doc, {3});
    CHECK(no_ball.models()[2].parent == 1);
    // A parent without its children would leave them hanging: refused.
    CHECK_THROWS_AS(without_models(doc, {1}), DocumentError);
}

TEST_CASE("copies have their originals' properties and keys, moved by the offset, children follow their parent's copy", "[models]") {
    Document doc = tree();
    Model ball = doc.models()[3];
    ball.mass = 3.5;
    ball.dynamics = true;
    doc.set_model(3, ball);
    const Document after = with_copies(doc, {{1, "hand.001", {2, 0, 0}}, {2, "finger.001", {0, 0, 0}}, {3, "ball.001", {0, 0, 4}}});
    REQUIRE(after.models().size() == 7);
    CHECK(after.models()[4].name == "hand.001");
    CHECK(after.models()[4].parent == 0);  // the arm, not copied
    CHECK(after.models()[5].parent == 4);  // the hand's copy
    CHECK(after.models()[6].mass == 3.5);
    CHECK(after.models()[6].dynamics);
    CHECK(after.models()[6].mesh == "sphere");
    CHECK(after.keyframe_at(0).states[4]->center == glm::dvec3(3, 0, 0));
    CHECK(after.keyframe_at(2000).states[4]->center == glm::dvec3(4, 0, 0));
    CHECK(after.keyframe_at(0).states[5]->center == glm::dvec3(0.5, 0, 0));
    CHECK_FALSE(after.keyframe_at(2000).states[5].has_value()); // not keyed there, as the finger
    CHECK(after.keyframe_at(2000).states[6]->center == glm::dvec3(6, 1, 4));
    // The originals untouched.
    for (size_t m = 0; m < 4; ++m) CHECK(after.models()[m] == doc.models()[m]);
    CHECK_THROWS_AS(with_copies(doc, {{3, "arm", {}}}), DocumentError);
}

TEST_CASE("unique names count on in Blender's style", "[models]") {
    Document doc;
    CHECK(unique_model_name(doc, "cube") == "cube");
    doc.add_model(named("cube"), at(0));
    CHECK(unique_model_name(doc, "cube") == "cube.001");
    doc.add_model(named("cube.001"), at(0));
    CHECK(unique_model_name(doc, "cube") == "cube.002");
    CHECK(unique_model_name(doc, "cube.001") == "cube.002");
    CHECK(unique_model_name(doc, "cube", {"cube.002"}) == "cube.003");
    CHECK(unique_model_name(doc, "v1.5") == "v1.5");
    CHECK(unique_model_name(doc, "") == "model");
}

TEST_CASE("a whole-document edit undoes and redoes exactly, and only over the document it saw", "[models]") {
    Document doc = tree();
    const Document before = doc;
    EditHistory history;
    history.perform(doc, std::make_unique<ReplaceDocumentEdit>("delete models", doc, without_models(doc, {0, 1, 2})));
    CHECK(doc.models().size() == 1);
    REQUIRE(history.undo(doc, 0));
    CHECK(doc == before);
    REQUIRE(history.redo(doc, 2000));
    CHECK(doc.models().size() == 1);

    ReplaceDocumentEdit stale("x", before, Document());
    CHECK_THROWS_AS(stale.apply(doc), DocumentError);
    CHECK(doc.models().size() == 1);
}
