// The editor's overlap fix without a window (issue 16's reproduction): the demo scene's cube as
// it was, half inside the floor. With Gravity ticked the backend finds the pair overlapping, the
// session lists it (the view flags both), and one click lifts the cube out the shortest way, by
// the depth the hand computes (the cube mesh spans -1..1, its center 0.5 above the floor: 0.5 m
// up), as one edit that Undo takes back at any time. In both backends.
#include "editor/editor_session.hpp"
#include "editor/overlap_fix.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <fstream>

using namespace animator;
using namespace animator::test;
using Catch::Matchers::WithinAbs;

namespace fs = std::filesystem;

namespace {

const char *kSunkCube = R"(
gr.settings{gravity = 9.81, down = 'y', max_time = 4}
gr.camera{eye = {0, 4, 14}, look_at = {0, 1, 0}, up = {0, 1, 0}, fov = 50}
local root = gr.node('root')
local floor = gr.mesh('plane', 'floor')
floor:scale(12, 1, 12)
root:add_child(floor)
local cube = gr.mesh('cube', 'cube')
cube:rotate('y', 30)
cube:translate(-1.5, 0.5, 0) -- half inside the floor, as simple.lua had it
root:add_child(cube)
local ball = gr.mesh('sphere', 'ball')
ball:translate(3, 2, 0) -- clear of everything
root:add_child(ball)
return root
)";

void bake_all(EditorSession &s) {
    for (int i = 0; i < 100000 && s.bake_some(0.05); ++i) {
    }
    REQUIRE_FALSE(s.baking());
}

double placed_y(const EditorSession &s, int model) {
    return s.document().keyframes()[0].states[static_cast<size_t>(model)]->center.y;
}

} // namespace

TEST_CASE("a model found inside another is flagged and lifted out the shortest way, one undoable edit", "[session][overlap]") {
    const fs::path dir = fresh_dir("overlap_fix");
    const fs::path scene = dir / "sunk.lua";
    std::ofstream(scene) << kSunkCube;

    // The depth each backend measures: the custom one exactly, Bullet within its contact slop.
    for (const auto &[backend, tolerance] : {std::pair<std::string, double>{"physics.custom", 1e-9},
                                             std::pair<std::string, double>{"physics.bullet", 0.01}}) {
        CAPTURE(backend);
        Environment env;
        EditorSession s(env);
        std::string error;
        REQUIRE(s.open(scene, error));
        REQUIRE(s.use_backend(backend, error));
        const int floor = s.document().find_model("floor"), cube = s.document().find_model("cube"),
                  ball = s.document().find_model("ball");
        bake_all(s);
        // Nothing moves: two static models inside each other are left as they are.
        CHECK(s.overlaps().empty());
        CHECK(s.overlapping_models().empty());

        Model m = s.document().models()[static_cast<size_t>(cube)];
        m.gravity = true;
        REQUIRE(s.set_model(cube, m, &error));
        bake_all(s);
        REQUIRE(s.overlaps().size() == 1);
        CHECK(s.overlapping_models() == std::set<int>{floor, cube});
        CHECK_THAT(s.overlaps()[0].depth, WithinAbs(0.5, tolerance));
        // It does not sink: it stays where it started, inside.
        s.set_time_ms(3000);
        CHECK_THAT(s.frame().models[static_cast<size_t>(cube)].center.y, WithinAbs(0.5, tolerance));

        // The fix moves the cube (Gravity moves it, not the floor) 0.5 m up, at its placement.
        const auto plan = plan_lift_out(s.document(), s.meshes(), s.overlaps()[0]);
        REQUIRE(plan);
        CHECK(plan->moved == cube);
        CHECK(plan->other == floor);
        CHECK(plan->keyframe_ms == 0);
        CHECK(plan->label == "lift 'cube' out of 'floor'");
        const glm::dvec3 x_before = s.document().keyframes()[0].states[static_cast<size_t>(cube)]->center;
        REQUIRE(s.lift_out(0, &error));
        const glm::dvec3 x_after = s.document().keyframes()[0].states[static_cast<size_t>(cube)]->center;
        CHECK_THAT(x_after.y, WithinAbs(1.0, tolerance));
        CHECK_THAT(x_after.x, WithinAbs(x_before.x, tolerance));
        CHECK_THAT(x_after.z, WithinAbs(x_before.z, tolerance));
        CHECK(s.document().keyframes().size() == 1); // no keyframe made
        CHECK(s.dirty());
        bake_all(s);
        CHECK(s.overlaps().empty());
        // Now it rests on the floor: its bottom face (y = center - 1) on the plane, at any time.
        for (std::int64_t ms : {0, 1000, 3000}) {
            s.set_time_ms(ms);
            CHECK_THAT(s.frame().models[static_cast<size_t>(cube)].center.y, WithinAbs(x_after.y, 1e-9 + tolerance));
        }
        CHECK_THAT(placed_y(s, ball), WithinAbs(2.0, 1e-12)); // nothing else moved

        // Undo at another time than the key's: the cube goes back inside, flagged again.
        s.set_time_ms(2000);
        REQUIRE(s.undo());
        CHECK(placed_y(s, cube) == x_before.y);
        bake_all(s);
        CHECK(s.overlaps().size() == 1);
        REQUIRE(s.redo());
        CHECK(placed_y(s, cube) == x_after.y);
        bake_all(s);
        CHECK(s.overlaps().empty());
    }
}

TEST_CASE("of two models that physics moves, the smaller is lifted out, the whole jointed model with it", "[session][overlap]") {
    Document doc;
    Model big;
    big.name = "big";
    big.mesh = "sphere";
    big.gravity = true;
    Model small = big;
    small.name = "small";
    ModelState at;
    at.scale = glm::dvec3(2.0);
    doc.add_model(big, at);
    Model arm;
    arm.name = "arm";
    arm.mesh = "";
    doc.add_model(arm, ModelState{});
    small.parent = doc.find_model("arm");
    at.scale = glm::dvec3(0.5);
    at.center = {0, 2.2, 0};
    doc.add_model(small, at);
    Mesh sphere;
    sphere.bound_radius = 1.0;
    const auto mesh = std::make_shared<const Mesh>(sphere);
    const std::vector<std::shared_ptr<const Mesh>> meshes{mesh, nullptr, mesh};

    // The backend's report: 'small' is 0.3 m into 'big', whose surface faces up there.
    ani_overlap o{};
    o.a = 0;
    o.b = 2;
    o.normal = {0, -1, 0}; // from small towards big
    o.depth = 0.3;
    const auto plan = plan_lift_out(doc, meshes, o);
    REQUIRE(plan);
    CHECK(plan->moved == doc.find_model("arm")); // the root of small's jointed model
    CHECK(plan->other == 0);
    CHECK(plan->offset == glm::dvec3(0, 0.3, 0)); // against the normal: up, out of 'big'

    // Neither moved by physics: the one a key put there at the overlap's time (a drag that keyed
    // it into the other), though it is the bigger; at another time, the smaller again.
    doc.set_model(0, [&] { Model m = big; m.gravity = false; return m; }());
    doc.set_model(2, [&] { Model m = small; m.gravity = false; return m; }());
    Keyframe k;
    k.time_ms = 2000;
    k.states.resize(doc.models().size());
    k.states[0] = ModelState{{0, 1, 0}, {}, glm::dvec3(2.0), {}};
    doc.insert_keyframe(k);
    o.t = 2.0;
    auto keyed = plan_lift_out(doc, meshes, o);
    REQUIRE(keyed);
    CHECK(keyed->moved == 0);
    CHECK(keyed->keyframe_ms == 2000);
    CHECK(keyed->offset == glm::dvec3(0, -0.3, 0)); // along the normal: down, out of 'small'
    o.t = 1.0;
    keyed = plan_lift_out(doc, meshes, o);
    REQUIRE(keyed);
    CHECK(keyed->moved == doc.find_model("arm"));
    CHECK(keyed->keyframe_ms == 0);

    // With no direction, no plan and a reason.
    o.normal = {0, 0, 0};
    std::string why;
    CHECK_FALSE(plan_lift_out(doc, meshes, o, &why));
    CHECK(why.find("no way out") != std::string::npos);
}
