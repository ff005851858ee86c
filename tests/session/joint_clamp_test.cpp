// A course puppet's joint range in the editor (joint_clamp.hpp): a turn stops at the range's
// ends, read signed (an angle stored as 350 is -10), a drag carried on past the max stays at the
// max even after the angle comes round past 180, a range of a whole turn does not clamp, min ==
// max holds an angle still, and the key records the way inside the range. Then the session: a
// Rotate drag of a jointed model is stopped (and says so), one of a model without a joint is not.
#include "editor/editor_session.hpp"
#include "editor/joint_clamp.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

using namespace animator;
using namespace animator::test;
using Catch::Matchers::WithinAbs;

namespace fs = std::filesystem;

namespace {

Model jointed(glm::dvec3 min, glm::dvec3 max) {
    Model m;
    m.name = "arm";
    m.mesh = "cube";
    m.joint = JointRange{min, max};
    return m;
}

ModelState at(glm::dvec3 angles, glm::dvec3 turn = glm::dvec3(0.0)) {
    ModelState s;
    s.angles = angles;
    s.turn = turn;
    return s;
}

// An x joint of -30..30 with y and z held still.
Model elbow() { return jointed({-30.0, 0.0, 0.0}, {30.0, 0.0, 0.0}); }

} // namespace

TEST_CASE("angles read signed, above -180 and up to 180", "[joint]") {
    CHECK(signed_degrees(0.0) == 0.0);
    CHECK(signed_degrees(350.0) == -10.0);
    CHECK(signed_degrees(180.0) == 180.0);
    CHECK(signed_degrees(190.0) == -170.0);
    CHECK(signed_degrees(-180.0) == 180.0);
    CHECK(signed_degrees(720.0 + 45.0) == 45.0);
}

TEST_CASE("a model without a joint turns freely", "[joint]") {
    Model free;
    free.name = "ball";
    const ModelState to = at({200.0, 90.0, 300.0}, {-1.0, -1.0, -1.0});
    const JointClamp c = clamp_to_joint(free, at({0.0, 0.0, 0.0}), to);
    CHECK(c.state == to);
    CHECK_FALSE(c.any());
}

TEST_CASE("a turn past the max stops at the max, past the min at the min", "[joint]") {
    // Up from 0 to 40: held at 30, turned up (ccw: -1).
    JointClamp c = clamp_to_joint(elbow(), at({0, 0, 0}), at({40, 0, 0}, {-1, 0, 0}));
    CHECK(c.state.angles == glm::dvec3(30, 0, 0));
    CHECK(c.state.turn.x == -1.0);
    CHECK(c.stopped == std::array<bool, 3>{true, false, false});
    // Down from 0 to -45, stored as 315: held at -30, stored as 330.
    c = clamp_to_joint(elbow(), at({0, 0, 0}), at({315, 0, 0}, {1, 0, 0}));
    CHECK(c.state.angles == glm::dvec3(330, 0, 0));
    CHECK(c.state.turn.x == 1.0);
    CHECK(c.any());
    // Inside the range nothing is stopped.
    c = clamp_to_joint(elbow(), at({0, 0, 0}), at({25, 0, 0}, {-1, 0, 0}));
    CHECK(c.state.angles == glm::dvec3(25, 0, 0));
    CHECK_FALSE(c.any());
}

TEST_CASE("wrap-around: an angle stored as 350 is -10", "[joint]") {
    // 350 is inside -30..30: not stopped, and it stays stored in [0, 360).
    JointClamp c = clamp_to_joint(elbow(), at({0, 0, 0}), at({350, 0, 0}, {1, 0, 0}));
    CHECK(c.state.angles.x == 350.0);
    CHECK_FALSE(c.any());
    // From 350 (-10) down to 300 (-60): held at -30, stored 330.
    c = clamp_to_joint(elbow(), at({350, 0, 0}), at({300, 0, 0}, {1, 0, 0}));
    CHECK(c.state.angles.x == 330.0);
    CHECK(c.stopped[0]);
    // From 350 (-10) up to 20, the field's numbers saying "down" (20 < 350): inside the range the
    // key turns up, from -10 to 20, not 330 degrees down through the forbidden side.
    c = clamp_to_joint(elbow(), at({350, 0, 0}), at({20, 0, 0}, {1, 0, 0}));
    CHECK(c.state.angles.x == 20.0);
    CHECK(c.state.turn.x == -1.0);
    CHECK_FALSE(c.any());
}

TEST_CASE("a drag carried on past 180 stays at the end it was heading for", "[joint]") {
    // Up from 20 by 200: 220 reads -140, past the min as read, but the hand went up: the max.
    JointClamp c = clamp_to_joint(elbow(), at({20, 0, 0}), at({220, 0, 0}, {-1, 0, 0}));
    CHECK(c.state.angles.x == 30.0);
    // Down from -20 (340) by 210: 130 reads 130, past the max as read, but the hand went down.
    c = clamp_to_joint(elbow(), at({340, 0, 0}), at({130, 0, 0}, {1, 0, 0}));
    CHECK(c.state.angles.x == 330.0);
    // With no direction (a state not turned by hand), the signed reading's nearer end.
    c = clamp_to_joint(elbow(), at({0, 0, 0}), at({200, 0, 0}));
    CHECK(c.state.angles.x == 330.0);
    c = clamp_to_joint(elbow(), at({0, 0, 0}), at({100, 0, 0}));
    CHECK(c.state.angles.x == 30.0);
    // A full turn up from 20 lands on 20 + 340 = 0 inside the range: the key goes down to it.
    c = clamp_to_joint(elbow(), at({20, 0, 0}), at({0, 0, 0}, {-1, 0, 0}));
    CHECK(c.state.angles.x == 0.0);
    CHECK(c.state.turn.x == 1.0);
    CHECK_FALSE(c.any());
}

TEST_CASE("min == max holds an angle still, a whole turn's range does not clamp", "[joint]") {
    // y 0..0: a turn of y is undone entirely (angle and turn as they were: nothing to key).
    const ModelState from = at({10, 0, 0}, {0, 0, 0});
    JointClamp c = clamp_to_joint(elbow(), from, at({10, 15, 0}, {0, -1, 0}));
    CHECK(c.state == from);
    CHECK(c.stopped == std::array<bool, 3>{false, true, false});
    // -180..180 (and wider) is free: 200 stays 200.
    const Model free_x = jointed({-180, 0, 0}, {180, 0, 0});
    c = clamp_to_joint(free_x, at({0, 0, 0}), at({200, 0, 0}, {-1, 0, 0}));
    CHECK(c.state.angles.x == 200.0);
    CHECK_FALSE(c.any());
    const Model wide = jointed({-400, 0, 0}, {400, 0, 0});
    c = clamp_to_joint(wide, at({0, 0, 0}), at({270, 0, 0}, {-1, 0, 0}));
    CHECK(c.state.angles.x == 270.0);
}

TEST_CASE("a turn about one axis leaves another that is outside its range as it is", "[joint]") {
    // y 0..0, but the state reads y 3 (a joint under a sheared parent: its state's angles are not
    // quite its own): turning x does not jump y to 0.
    const JointClamp c = clamp_to_joint(elbow(), at({0, 3, 0}), at({10, 3, 0}, {-1, 0, 0}));
    CHECK(c.state.angles == glm::dvec3(10, 3, 0));
    CHECK_FALSE(c.any());
}

TEST_CASE("the joint's range and a stop read as text", "[joint]") {
    const Model m = jointed({-90, 0, 0}, {45, 0, 0.5});
    CHECK(joint_range_text(*m.joint) == "x -90..45, y 0..0, z 0..0.5");
    JointClamp c;
    c.stopped = {true, false, true};
    CHECK(joint_stop_text(m, c) == "'arm' stopped at its joint range (x -90..45, z 0..0.5)");
    CHECK(joint_stop_text(m, JointClamp{}).empty());
}

TEST_CASE("a Rotate drag of a jointed model stops at its range and says so", "[joint][session]") {
    const fs::path dir = fresh_dir("joint_session");
    const fs::path file = dir / "arm.ani";
    write_file(file, "animator-ani 2\n"
                     "settings\n  max_time_ms 10000\nend\n"
                     "model \"arm\"\n  mesh \"cube\"\n  joint x -30 30 y 0 0 z 0 0\nend\n"
                     "model \"box\"\n  mesh \"cube\"\nend\n"
                     "keyframe 0\n  camera position 0 0 10 rotation 1 0 0 0 fov 50\n"
                     "  state \"arm\" center 0 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0\n"
                     "  state \"box\" center 3 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0\n"
                     "end\n");
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(file, error));
    const int arm = s.document().find_model("arm"), box = s.document().find_model("box");
    REQUIRE(s.document().models()[static_cast<size_t>(arm)].joint.has_value());
    s.set_mode(EditMode::Rotate);
    // Right drag up 100 px: x turns 50 degrees, z by the 40 px sideways 20 degrees.
    s.click(arm, false);
    s.click(box, true);
    s.begin_drag(DragButton::Right, 720);
    s.update_drag({40.0, 100.0});
    CHECK(s.state_at_time(arm).angles == glm::dvec3(30.0, 0.0, 0.0)); // the preview is stopped too
    CHECK(s.joint_note() == "'arm' stopped at its joint range (x -30..30, z 0..0)");
    s.end_drag();
    CHECK(s.take_joint_note() == "'arm' stopped at its joint range (x -30..30, z 0..0)");
    CHECK(s.take_joint_note().empty());
    const Keyframe &k0 = s.document().keyframes()[0];
    CHECK(k0.states[static_cast<size_t>(arm)]->angles == glm::dvec3(30.0, 0.0, 0.0));
    CHECK(k0.states[static_cast<size_t>(box)]->angles == glm::dvec3(50.0, 0.0, 20.0)); // no joint: free
    // A drag that only pushes further against the end changes nothing of the arm.
    s.click(arm, false);
    const ModelState held = *s.document().keyframes()[0].states[static_cast<size_t>(arm)];
    s.begin_drag(DragButton::Right, 720);
    s.update_drag({0.0, 60.0});
    s.end_drag();
    CHECK(*s.document().keyframes()[0].states[static_cast<size_t>(arm)] == held);
}
