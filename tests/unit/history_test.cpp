#include "document/history.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace animator;

namespace {

Document two_balls_with_keyframes() {
    Document doc;
    Model m;
    m.mesh = "sphere";
    m.name = "a";
    doc.add_model(m, ModelState{});
    m.name = "b";
    doc.add_model(m, ModelState{});
    for (std::int64_t t : {1000, 2000, 3000}) {
        Keyframe k;
        k.time_ms = t;
        k.states.assign(2, ModelState{});
        doc.insert_keyframe(k);
    }
    return doc;
}

ModelState at(double x) {
    ModelState s;
    s.center = {x, 0.0, 0.0};
    return s;
}

} // namespace

TEST_CASE("undo and redo of a model transformation") {
    Document doc = two_balls_with_keyframes();
    const Document original = doc;
    EditHistory history;
    history.perform(doc, std::make_unique<SetStateEdit>(1000, 0, at(5.0)));
    CHECK(doc.keyframe_at(1000).states[0]->center.x == 5.0);
    REQUIRE(history.undo(doc, 1000));
    CHECK(doc == original);
    REQUIRE(history.redo(doc, 1000));
    CHECK(doc.keyframe_at(1000).states[0]->center.x == 5.0);
    CHECK_FALSE(history.redo(doc, 1000));
}

TEST_CASE("each keyframe has its own undo stack") {
    Document doc = two_balls_with_keyframes();
    EditHistory history;
    history.perform(doc, std::make_unique<SetStateEdit>(1000, 0, at(1.0)));
    history.perform(doc, std::make_unique<SetStateEdit>(2000, 0, at(2.0)));
    history.perform(doc, std::make_unique<SetStateEdit>(1000, 1, at(3.0)));
    CHECK(history.undo_depth(1000) == 2);
    CHECK(history.undo_depth(2000) == 1);

    // Undo at 2000 takes back only 2000's edit, although 1000's was later.
    REQUIRE(history.undo(doc, 2000));
    CHECK(doc.keyframe_at(2000).states[0]->center.x == 0.0);
    CHECK(doc.keyframe_at(1000).states[1]->center.x == 3.0);
    CHECK_FALSE(history.undo(doc, 2000));
    CHECK_FALSE(history.can_undo(3000));

    REQUIRE(history.undo(doc, 1000));
    CHECK(doc.keyframe_at(1000).states[1]->center.x == 0.0);
    CHECK(doc.keyframe_at(1000).states[0]->center.x == 1.0);
}

TEST_CASE("a new edit clears what could be redone on its stack only") {
    Document doc = two_balls_with_keyframes();
    EditHistory history;
    history.perform(doc, std::make_unique<SetStateEdit>(1000, 0, at(1.0)));
    history.perform(doc, std::make_unique<SetStateEdit>(2000, 0, at(2.0)));
    history.undo(doc, 1000);
    history.undo(doc, 2000);
    history.perform(doc, std::make_unique<SetStateEdit>(1000, 0, at(7.0)));
    CHECK_FALSE(history.redo(doc, 1000));
    CHECK(doc.keyframe_at(1000).states[0]->center.x == 7.0);
    REQUIRE(history.redo(doc, 2000));
    CHECK(doc.keyframe_at(2000).states[0]->center.x == 2.0);
}

TEST_CASE("shortening max time is undone with the deleted keyframes restored") {
    Document doc = two_balls_with_keyframes();
    EditHistory history;
    history.perform(doc, std::make_unique<SetStateEdit>(3000, 1, at(9.0)));
    const Document before = doc;
    Settings s = doc.settings();
    s.max_time_ms = 1500;
    history.perform(doc, std::make_unique<SetSettingsEdit>(s));
    CHECK(doc.keyframes().size() == 2);
    REQUIRE(history.undo(doc, 0));
    CHECK(doc == before);
    CHECK(doc.keyframe_at(3000).states[1]->center.x == 9.0);
    REQUIRE(history.redo(doc, 0));
    CHECK(doc.keyframes().size() == 2);
}

TEST_CASE("deleting and adding keyframes and models are undoable") {
    Document doc = two_balls_with_keyframes();
    const Document original = doc;
    EditHistory history;
    history.perform(doc, std::make_unique<DeleteKeyframeEdit>(2000));
    Keyframe k;
    k.time_ms = 2500;
    k.states.assign(2, at(4.0));
    history.perform(doc, std::make_unique<AddKeyframeEdit>(k));
    Model c;
    c.name = "c";
    c.mesh = "cube";
    history.perform(doc, std::make_unique<AddModelEdit>(c, at(1.0)));
    Model changed = doc.models()[0];
    changed.dynamics = true;
    changed.mass = 3.0;
    history.perform(doc, std::make_unique<SetModelEdit>(0, changed));
    CHECK(doc.models().size() == 3);
    CHECK(doc.models()[0].mass == 3.0);
    while (history.undo(doc, 0)) {
    }
    CHECK(doc == original);
}

TEST_CASE("an edit that fails changes nothing and is not recorded") {
    Document doc = two_balls_with_keyframes();
    const Document original = doc;
    EditHistory history;
    ModelState bad = at(1.0);
    bad.scale.x = -1.0;
    CHECK_THROWS_AS(history.perform(doc, std::make_unique<SetStateEdit>(1000, 0, bad)), DocumentError);
    CHECK_THROWS_AS(history.perform(doc, std::make_unique<DeleteKeyframeEdit>(0)), DocumentError);
    CHECK(doc == original);
    CHECK_FALSE(history.can_undo(1000));
    CHECK_FALSE(history.can_undo(0));
}

TEST_CASE("undo takes the latest of the keyframe's and the document's edits") {
    Document doc = two_balls_with_keyframes();
    EditHistory history;
    history.perform(doc, std::make_unique<SetStateEdit>(1000, 0, at(1.0)));
    Settings s = doc.settings();
    s.gravity = 3.0;
    history.perform(doc, std::make_unique<SetSettingsEdit>(s));
    history.perform(doc, std::make_unique<SetStateEdit>(1000, 0, at(2.0)));

    history.undo(doc, 1000);
    CHECK(doc.keyframe_at(1000).states[0]->center.x == 1.0);
    CHECK(doc.settings().gravity == 3.0);
    history.undo(doc, 1000);
    CHECK(doc.settings().gravity == 9.81);
    CHECK(doc.keyframe_at(1000).states[0]->center.x == 1.0);
    history.undo(doc, 1000);
    CHECK(doc.keyframe_at(1000).states[0]->center.x == 0.0);
    // Redo brings them back in the order they were undone, latest first.
    history.redo(doc, 1000);
    CHECK(doc.keyframe_at(1000).states[0]->center.x == 1.0);
    CHECK(doc.settings().gravity == 9.81);
    history.redo(doc, 1000);
    CHECK(doc.settings().gravity == 3.0);
}

TEST_CASE("a keyframe created anew starts with an empty undo stack") {
    Document doc = two_balls_with_keyframes();
    EditHistory history;
    history.perform(doc, std::make_unique<SetStateEdit>(2000, 0, at(1.0)));
    history.perform(doc, std::make_unique<DeleteKeyframeEdit>(2000));
    Keyframe k;
    k.time_ms = 2000;
    k.states.assign(2, at(5.0));
    history.perform(doc, std::make_unique<AddKeyframeEdit>(k));
    CHECK(history.undo_depth(2000) == 0);
}

TEST_CASE("any sequence of edits undone in full gives back the original, redone the result") {
    std::mt19937 rng(1234);
    for (int round = 0; round < 20; ++round) {
        Document doc = test::random_document(rng, 3, 5);
        const Document original = doc;
        EditHistory history;
        std::vector<std::int64_t> keys;
        for (const auto &k : doc.keyframes()) keys.push_back(k.time_ms);
        for (int i = 0; i < 50; ++i) {
            const std::int64_t t = keys[rng() % keys.size()];
            if (doc.find_keyframe(t) < 0) continue;
            const int kind = static_cast<int>(rng() % 3);
            if (kind == 0) {
                history.perform(doc, std::make_unique<SetStateEdit>(t, static_cast<int>(rng() % 3),
                                                                    at(static_cast<double>(i))));
            } else if (kind == 1) {
                CameraState c;
                c.position = {0.0, static_cast<double>(i), 0.0};
                history.perform(doc, std::make_unique<SetCameraEdit>(t, c));
            } else {
                Settings s = doc.settings();
                s.gravity = static_cast<double>(i);
                history.perform(doc, std::make_unique<SetSettingsEdit>(s));
            }
        }
        const Document edited = doc;
        // Undo everywhere until nothing is left, keyframe by keyframe.
        bool any = true;
        while (any) {
            any = false;
            for (std::int64_t t : keys)
                while (history.undo(doc, t)) any = true;
        }
        CHECK(doc == original);
        any = true;
        while (any) {
            any = false;
            for (std::int64_t t : keys)
                while (history.redo(doc, t)) any = true;
        }
        CHECK(doc == edited);
    }
}

TEST_CASE("keying and unkeying a model at a keyframe is undoable") {
    Document doc = two_balls_with_keyframes();
    doc.set_state(2000, 1, std::nullopt);
    const Document before = doc;
    EditHistory history;
    history.perform(doc, std::make_unique<SetStateEdit>(2000, 1, at(4.0)));
    CHECK(doc.keys_of(1).size() == 4);
    history.perform(doc, std::make_unique<SetStateEdit>(1000, 0, std::nullopt));
    CHECK(doc.keys_of(0).size() == 3);
    history.undo(doc, 1000);
    history.undo(doc, 2000);
    CHECK(doc == before);
}
