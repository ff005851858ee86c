// The Timeline's edits of keys (document/key_edits.hpp): retime, delete and paste move states
// between keyframes, make keyframes where keys land and remove those left keying nothing (never
// t = 0); each reverts to exactly the document before, and goes back and forth in the history.
#include "document/history.hpp"
#include "document/key_edits.hpp"

#include <catch2/catch.hpp>

using namespace animator;

namespace {

ModelState at(double x) {
    ModelState s;
    s.center = {x, 0.0, 0.0};
    return s;
}

CameraState camera_at(double z) {
    CameraState c;
    c.position = {0.0, 0.0, z};
    return c;
}

// Two balls and the camera: "a" keyed at 0, 1000 and 2000 ms; "b" at 0 and 2000; the camera at 0
// and 1000. Each state's x is its keyframe's time in seconds (a) or ten times it (b).
Document keyed_document() {
    Document doc;
    Model m;
    m.mesh = "sphere";
    m.name = "a";
    doc.add_model(m, at(0.0));
    m.name = "b";
    doc.add_model(m, at(0.0));
    doc.set_settings([] {
        Settings s;
        s.max_time_ms = 5000;
        return s;
    }());
    Keyframe k1;
    k1.time_ms = 1000;
    k1.states = {at(1.0), std::nullopt};
    k1.camera = camera_at(5.0);
    doc.insert_keyframe(k1);
    Keyframe k2;
    k2.time_ms = 2000;
    k2.states = {at(2.0), at(20.0)};
    doc.insert_keyframe(k2);
    return doc;
}

std::vector<std::int64_t> times(const Document &doc) {
    std::vector<std::int64_t> out;
    for (const Keyframe &k : doc.keyframes()) out.push_back(k.time_ms);
    return out;
}

// Applies and reverts twice (as undo and redo do): after apply the document is `after`
// (checked by the caller once), after revert it is the original.
void round_trip(Document &doc, Edit &edit) {
    const Document before = doc;
    edit.apply(doc);
    const Document after = doc;
    edit.revert(doc);
    CHECK(doc == before);
    edit.apply(doc);
    CHECK(doc == after);
    edit.revert(doc);
    CHECK(doc == before);
    edit.apply(doc);
}

} // namespace

TEST_CASE("the keys of a document, and their values", "[key_edits]") {
    const Document doc = keyed_document();
    const std::vector<KeyRef> keys = all_keys(doc);
    const std::vector<KeyRef> expected = {{0, KeyRef::kCamera}, {0, 0}, {0, 1}, {1000, KeyRef::kCamera}, {1000, 0},
                                          {2000, 0}, {2000, 1}};
    CHECK(keys == expected);
    CHECK(has_key(doc, {1000, 0}));
    CHECK_FALSE(has_key(doc, {1000, 1}));
    CHECK_FALSE(has_key(doc, {1500, 0}));
    CHECK_FALSE(has_key(doc, {2000, KeyRef::kCamera}));
    CHECK_FALSE(has_key(doc, {0, 7}));
    CHECK(key_value(doc, {2000, 1}).state.center.x == 20.0);
    CHECK(key_value(doc, {1000, KeyRef::kCamera}).camera.position.z == 5.0);
    CHECK_THROWS_AS(key_value(doc, {1000, 1}), DocumentError);
}

TEST_CASE("retiming a key to a free time makes a keyframe there and removes the emptied one", "[key_edits]") {
    Document doc = keyed_document();
    // b's key at 2000 to 3000: 2000 still keys a, 3000 is new.
    RetimeKeysEdit edit({{2000, 1}}, 1000);
    round_trip(doc, edit);
    CHECK(times(doc) == std::vector<std::int64_t>{0, 1000, 2000, 3000});
    CHECK_FALSE(doc.keyframe_at(2000).states[1].has_value());
    CHECK(doc.keyframe_at(2000).states[0]->center.x == 2.0);
    CHECK(doc.keyframe_at(3000).states[1]->center.x == 20.0);
    CHECK_FALSE(doc.keyframe_at(3000).states[0].has_value());
    CHECK_FALSE(doc.keyframe_at(3000).camera.has_value());
    CHECK(edit.result() == std::vector<KeyRef>{{3000, 1}});
    CHECK(edit.creates_keyframes() == std::vector<std::int64_t>{3000});

    // Both of 2000's keys on by 500 ms: 2000 keys nothing and goes.
    Document d2 = keyed_document();
    RetimeKeysEdit both({{2000, 0}, {2000, 1}}, 500);
    round_trip(d2, both);
    CHECK(times(d2) == std::vector<std::int64_t>{0, 1000, 2500});
    CHECK(d2.keyframe_at(2500).states[0]->center.x == 2.0);
    CHECK(d2.keyframe_at(2500).states[1]->center.x == 20.0);
}

TEST_CASE("retiming onto a time already keyed joins that keyframe, replacing the model's own key", "[key_edits]") {
    Document doc = keyed_document();
    // The camera's key at 1000 to 2000 (which keys the balls only), and a's key at 1000 onto its
    // key at 2000 (replaced): 1000 keys nothing then and goes.
    RetimeKeysEdit edit({{1000, KeyRef::kCamera}, {1000, 0}}, 1000);
    round_trip(doc, edit);
    CHECK(times(doc) == std::vector<std::int64_t>{0, 2000});
    CHECK(doc.keyframe_at(2000).camera->position.z == 5.0);
    CHECK(doc.keyframe_at(2000).states[0]->center.x == 1.0);
    CHECK(doc.keyframe_at(2000).states[1]->center.x == 20.0);
    CHECK(edit.creates_keyframes().empty());
}

TEST_CASE("keys moved past each other keep their own values", "[key_edits]") {
    Document doc = keyed_document();
    // a's keys at 1000 and 2000 back by 500 ms: to 500 and 1500, each with its value.
    RetimeKeysEdit edit({{2000, 0}, {1000, 0}}, -500);
    round_trip(doc, edit);
    CHECK(times(doc) == std::vector<std::int64_t>{0, 500, 1000, 1500, 2000});
    CHECK(doc.keyframe_at(500).states[0]->center.x == 1.0);
    CHECK(doc.keyframe_at(1500).states[0]->center.x == 2.0);
    CHECK_FALSE(doc.keyframe_at(1000).states[0].has_value()); // still the camera's
    CHECK_FALSE(doc.keyframe_at(2000).states[0].has_value()); // still b's
    const std::vector<KeyRef> moved = {{500, 0}, {1500, 0}};
    CHECK(edit.result() == moved);
}

TEST_CASE("a retime that cannot be done changes nothing", "[key_edits]") {
    const Document original = keyed_document();
    Document doc = original;
    // The initial placement stays.
    CHECK_THROWS_AS(RetimeKeysEdit({{0, 0}}, 500).apply(doc), DocumentError);
    // Past the max time (5000 ms), or before 0.
    CHECK_THROWS_AS(RetimeKeysEdit({{1000, 0}, {2000, 1}}, 3500).apply(doc), DocumentError);
    CHECK_THROWS_AS(RetimeKeysEdit({{1000, 0}}, -1500).apply(doc), DocumentError);
    // A key the document has not.
    CHECK_THROWS_AS(RetimeKeysEdit({{1000, 1}}, 500).apply(doc), DocumentError);
    CHECK(doc == original);
}

TEST_CASE("a retime onto t = 0 replaces the initial placement, and reverting restores it", "[key_edits]") {
    Document doc = keyed_document();
    RetimeKeysEdit edit({{1000, 0}, {1000, KeyRef::kCamera}}, -1000);
    round_trip(doc, edit);
    CHECK(times(doc) == std::vector<std::int64_t>{0, 2000});
    CHECK(doc.keyframe_at(0).states[0]->center.x == 1.0);
    CHECK(doc.keyframe_at(0).camera->position.z == 5.0);
}

TEST_CASE("deleting keys removes keyframes left keying nothing, never t = 0", "[key_edits]") {
    Document doc = keyed_document();
    DeleteKeysEdit edit({{1000, 0}, {2000, 1}});
    round_trip(doc, edit);
    CHECK(times(doc) == std::vector<std::int64_t>{0, 1000, 2000});
    CHECK_FALSE(doc.keyframe_at(1000).states[0].has_value());
    CHECK(doc.keyframe_at(1000).camera.has_value());
    CHECK_FALSE(doc.keyframe_at(2000).states[1].has_value());

    Document d2 = keyed_document();
    DeleteKeysEdit all({{1000, 0}, {1000, KeyRef::kCamera}});
    round_trip(d2, all);
    CHECK(times(d2) == std::vector<std::int64_t>{0, 2000});

    const Document original = keyed_document();
    Document d3 = original;
    CHECK_THROWS_AS(DeleteKeysEdit({{0, 1}}).apply(d3), DocumentError);
    CHECK_THROWS_AS(DeleteKeysEdit({{1000, 0}, {1500, 0}}).apply(d3), DocumentError);
    CHECK(d3 == original);
}

TEST_CASE("copied keys paste at a time with their spacing, replacing keys there", "[key_edits]") {
    Document doc = keyed_document();
    // a's key at 1000 and b's at 2000: 1000 ms apart, the earliest first.
    const std::vector<CopiedKey> copied = copy_keys(doc, {{2000, 1}, {1000, 0}});
    REQUIRE(copied.size() == 2);
    CHECK(copied[0].offset_ms == 0);
    CHECK(copied[0].value.model == 0);
    CHECK(copied[0].value.state.center.x == 1.0);
    CHECK(copied[1].offset_ms == 1000);
    CHECK(copied[1].value.state.center.x == 20.0);

    // Pasted at 2000: a's at 2000 (replacing a's own there), b's at 3000 (a new keyframe).
    PasteKeysEdit edit(copied, 2000);
    round_trip(doc, edit);
    CHECK(times(doc) == std::vector<std::int64_t>{0, 1000, 2000, 3000});
    CHECK(doc.keyframe_at(2000).states[0]->center.x == 1.0);
    CHECK(doc.keyframe_at(2000).states[1]->center.x == 20.0);
    CHECK(doc.keyframe_at(3000).states[1]->center.x == 20.0);
    CHECK(doc.keyframe_at(1000).states[0]->center.x == 1.0); // the copy's source stays
    const std::vector<KeyRef> pasted = {{2000, 0}, {3000, 1}};
    CHECK(edit.result() == pasted);

    // The camera's key pastes as a camera key; past the max time nothing is pasted.
    Document d2 = keyed_document();
    PasteKeysEdit cam(copy_keys(d2, {{1000, KeyRef::kCamera}}), 4000);
    round_trip(d2, cam);
    CHECK(d2.keyframe_at(4000).camera->position.z == 5.0);
    const Document before = d2;
    CHECK_THROWS_AS(PasteKeysEdit(copied, 4500).apply(d2), DocumentError);
    CHECK(d2 == before);
}

TEST_CASE("key edits are document edits: one undo takes a retime back at any time", "[key_edits]") {
    const Document original = keyed_document();
    Document doc = original;
    EditHistory history;
    history.perform(doc, std::make_unique<RetimeKeysEdit>(std::vector<KeyRef>{{2000, 1}}, 1000));
    history.perform(doc, std::make_unique<DeleteKeysEdit>(std::vector<KeyRef>{{1000, 0}}));
    history.perform(doc, std::make_unique<PasteKeysEdit>(copy_keys(doc, {{3000, 1}}), 4000));
    CHECK(times(doc) == std::vector<std::int64_t>{0, 1000, 2000, 3000, 4000});
    // Away from any keyframe (-1 ms: the document's stack only), three undos.
    REQUIRE(history.undo(doc, -1));
    REQUIRE(history.undo(doc, -1));
    REQUIRE(history.undo(doc, -1));
    CHECK(doc == original);
    CHECK_FALSE(history.undo(doc, -1));
    REQUIRE(history.redo(doc, -1));
    CHECK(times(doc) == std::vector<std::int64_t>{0, 1000, 2000, 3000});
}

TEST_CASE("a keyframe a key edit makes starts with a fresh undo stack", "[key_edits]") {
    Document doc = keyed_document();
    EditHistory history;
    // Edits at 2000, then the keyframe at 2000 emptied and made again by a retime there.
    history.perform(doc, std::make_unique<SetStateEdit>(2000, 0, at(9.0)));
    history.perform(doc, std::make_unique<DeleteKeysEdit>(std::vector<KeyRef>{{2000, 0}, {2000, 1}}));
    CHECK(history.undo_depth(2000) == 1);
    history.perform(doc, std::make_unique<RetimeKeysEdit>(std::vector<KeyRef>{{1000, 0}}, 1000));
    CHECK(history.undo_depth(2000) == 0);
}
