#include "document/document.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace animator;

namespace {

Model ball(const std::string &name = "ball") {
    Model m;
    m.name = name;
    m.mesh = "sphere";
    return m;
}

Keyframe keyframe_at(const Document &doc, std::int64_t t) {
    Keyframe k;
    k.time_ms = t;
    k.states.assign(doc.models().size(), ModelState{});
    for (auto &s : k.states) s->center = glm::dvec3(static_cast<double>(t), 0.0, 0.0);
    return k;
}

std::vector<std::int64_t> times(const Document &doc) {
    std::vector<std::int64_t> out;
    for (const auto &k : doc.keyframes()) out.push_back(k.time_ms);
    return out;
}

} // namespace

TEST_CASE("a new document has the t = 0 keyframe and the seed's default settings") {
    Document doc;
    REQUIRE(times(doc) == std::vector<std::int64_t>{0});
    CHECK(doc.settings().max_time_ms == 60000);
    CHECK(doc.settings().gravity == 9.81);
    CHECK(doc.settings().down_axis == Axis::Y);
    CHECK_FALSE(doc.settings().cel_shading);
}

TEST_CASE("the t = 0 keyframe cannot be deleted") {
    Document doc;
    doc.add_model(ball(), ModelState{});
    doc.insert_keyframe(keyframe_at(doc, 500));
    CHECK_THROWS_AS(doc.delete_keyframe(0), DocumentError);
    CHECK_THROWS_WITH(doc.delete_keyframe(0), Catch::Contains("t = 0"));
    CHECK(times(doc) == std::vector<std::int64_t>{0, 500});
    doc.delete_keyframe(500);
    CHECK(times(doc) == std::vector<std::int64_t>{0});
    CHECK_THROWS_AS(doc.delete_keyframe(500), DocumentError);
}

TEST_CASE("keyframes stay in time order whatever order they are added in") {
    Document doc;
    doc.add_model(ball(), ModelState{});
    for (std::int64_t t : {5000, 1000, 3000, 2000, 4000}) doc.insert_keyframe(keyframe_at(doc, t));
    CHECK(times(doc) == std::vector<std::int64_t>{0, 1000, 2000, 3000, 4000, 5000});
    CHECK(doc.keyframe_at(3000).states[0]->center.x == 3000.0);
    CHECK(doc.find_keyframe(2500) == -1);
}

TEST_CASE("a keyframe at a taken, negative or too late time, or with missing states, is refused") {
    Document doc;
    doc.add_model(ball(), ModelState{});
    doc.insert_keyframe(keyframe_at(doc, 1000));
    const auto before = doc;
    CHECK_THROWS_AS(doc.insert_keyframe(keyframe_at(doc, 1000)), DocumentError);
    CHECK_THROWS_AS(doc.insert_keyframe(keyframe_at(doc, 0)), DocumentError);
    CHECK_THROWS_AS(doc.insert_keyframe(keyframe_at(doc, -1)), DocumentError);
    CHECK_THROWS_AS(doc.insert_keyframe(keyframe_at(doc, 60001)), DocumentError);
    Keyframe missing = keyframe_at(doc, 2000);
    missing.states.clear();
    CHECK_THROWS_AS(doc.insert_keyframe(missing), DocumentError);
    Keyframe nan_state = keyframe_at(doc, 2000);
    nan_state.states[0]->center.y = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(doc.insert_keyframe(nan_state), DocumentError);
    CHECK(doc == before);
}

TEST_CASE("shortening max time deletes the later keyframes and returns them") {
    Document doc;
    doc.add_model(ball(), ModelState{});
    for (std::int64_t t : {1000, 2000, 3000, 5000}) doc.insert_keyframe(keyframe_at(doc, t));
    Settings s = doc.settings();
    s.max_time_ms = 2500;
    const auto removed = doc.set_settings(s);
    CHECK(times(doc) == std::vector<std::int64_t>{0, 1000, 2000});
    REQUIRE(removed.size() == 2);
    CHECK(removed[0].time_ms == 3000);
    CHECK(removed[1].time_ms == 5000);

    s.max_time_ms = 2000; // a keyframe exactly at max time stays
    CHECK(doc.set_settings(s).empty());
    CHECK(times(doc).back() == 2000);
}

TEST_CASE("max time is limited to 1 s .. 300000 s") {
    Document doc;
    Settings s = doc.settings();
    s.max_time_ms = 999;
    CHECK_THROWS_AS(doc.set_settings(s), DocumentError);
    s.max_time_ms = 300000001;
    CHECK_THROWS_AS(doc.set_settings(s), DocumentError);
    s.max_time_ms = 300000000;
    CHECK_NOTHROW(doc.set_settings(s));
    s.max_time_ms = 1000;
    CHECK_NOTHROW(doc.set_settings(s));
    CHECK(doc.settings().max_time_ms == 1000);
}

TEST_CASE("a model is added to every keyframe, with a unique name and valid properties") {
    Document doc;
    doc.add_model(ball("a"), ModelState{});
    doc.insert_keyframe(keyframe_at(doc, 1000));
    ModelState s;
    s.center = {1, 2, 3};
    doc.add_model(ball("b"), s);
    for (const auto &k : doc.keyframes()) {
        REQUIRE(k.states.size() == 2);
        CHECK(k.states[1]->center == glm::dvec3(1, 2, 3));
    }
    CHECK_THROWS_WITH(doc.add_model(ball("a"), ModelState{}), Catch::Contains("already exists"));
    Model heavy = ball("c");
    heavy.mass = 0.0;
    CHECK_THROWS_WITH(doc.add_model(heavy, ModelState{}), Catch::Contains("mass"));
    Model orphan = ball("d");
    orphan.parent = 7;
    CHECK_THROWS_AS(doc.add_model(orphan, ModelState{}), DocumentError);
    Model child = ball("e");
    child.parent = 0;
    CHECK_NOTHROW(doc.add_model(child, ModelState{}));
    CHECK(doc.models().size() == 3);
}

TEST_CASE("models are found by name through renames, removals and copies") {
    Document doc;
    for (int k = 0; k < 5; ++k) doc.add_model(ball("m" + std::to_string(k)), ModelState{});
    CHECK(doc.find_model("m3") == 3);
    CHECK(doc.find_model("m9") == -1);
    doc.set_model(3, ball("renamed"));
    CHECK(doc.find_model("m3") == -1);
    CHECK(doc.find_model("renamed") == 3);
    CHECK_THROWS_WITH(doc.set_model(1, ball("renamed")), Catch::Contains("already exists"));
    CHECK(doc.find_model("m1") == 1);
    doc.set_model(2, ball("m2")); // its own name again
    CHECK(doc.find_model("m2") == 2);
    doc.remove_last_model();
    CHECK(doc.find_model("m4") == -1);
    CHECK_NOTHROW(doc.add_model(ball("m4"), ModelState{}));
    const Document copy = doc;
    CHECK(copy.find_model("m4") == 4);
    CHECK(copy.find_model("renamed") == 3);
    // Many models (names looked up in an index: adding them one by one is not quadratic).
    Document big;
    for (int k = 0; k < 20000; ++k) big.add_model(ball("b" + std::to_string(k)), ModelState{});
    CHECK(big.find_model("b19999") == 19999);
    CHECK(big.find_model("b0") == 0);
}

TEST_CASE("states are checked: finite centers, angles in 0..360, positive scale") {
    ModelState s;
    CHECK(check_state(s).empty());
    s.angles.x = 360.0;
    CHECK_FALSE(check_state(s).empty());
    s.angles.x = 359.5;
    s.scale.z = 0.0;
    CHECK_FALSE(check_state(s).empty());
    s.scale.z = 1.0;
    s.center.x = std::numeric_limits<double>::infinity();
    CHECK_FALSE(check_state(s).empty());
}

TEST_CASE("angles wrap into 0..360 as the seed stores them") {
    CHECK(wrap_degrees(-10.0) == Approx(350.0));
    CHECK(wrap_degrees(360.0) == 0.0);
    CHECK(wrap_degrees(725.0) == Approx(5.0));
    CHECK(wrap_degrees(-1e-20) < 360.0);
    CHECK(wrap_degrees(20.0) == 20.0);
}

TEST_CASE("the camera needs a unit rotation and a field of view in (0, 180)") {
    Document doc;
    CameraState c;
    c.rotation = glm::dquat(2.0, 0.0, 0.0, 0.0);
    CHECK_THROWS_AS(doc.set_camera(0, c), DocumentError);
    c.rotation = glm::dquat(1.0, 0.0, 0.0, 0.0);
    c.fov_degrees = 180.0;
    CHECK_THROWS_AS(doc.set_camera(0, c), DocumentError);
    c.fov_degrees = 60.0;
    doc.set_camera(0, c);
    CHECK(doc.keyframe_at(0).camera->fov_degrees == 60.0);
}

TEST_CASE("keyframes key some models: t = 0 keys everything, later keyframes what they list") {
    Document doc;
    doc.add_model(ball("a"), ModelState{});
    doc.add_model(ball("b"), ModelState{});
    Keyframe k;
    k.time_ms = 1000;
    k.states = {ModelState{}, std::nullopt}; // keys a only, and not the camera
    doc.insert_keyframe(k);
    CHECK(doc.keys_of(0).size() == 2);
    CHECK(doc.keys_of(1).size() == 1);
    CHECK(doc.keys_of(-1).size() == 1); // the camera: only at t = 0

    // A model added later is keyed at t = 0 only.
    doc.add_model(ball("c"), ModelState{});
    CHECK(doc.keys_of(2).size() == 1);
    CHECK_FALSE(doc.keyframe_at(1000).states[2].has_value());

    // Keying and unkeying at a later keyframe; never unkeying at t = 0.
    doc.set_state(1000, 1, ModelState{});
    CHECK(doc.keys_of(1).size() == 2);
    doc.set_state(1000, 1, std::nullopt);
    CHECK(doc.keys_of(1).size() == 1);
    CHECK_THROWS_WITH(doc.set_state(0, 1, std::nullopt), Catch::Contains("t = 0"));
    CHECK_THROWS_WITH(doc.set_camera(0, std::nullopt), Catch::Contains("t = 0"));

    Keyframe partial_zero;
    partial_zero.time_ms = 0;
    partial_zero.states.assign(3, std::nullopt);
    Document other;
    CHECK_THROWS_AS(other.insert_keyframe(partial_zero), DocumentError); // t = 0 is taken anyway
}
