// The Outliner and the Model Interface over several models, without a window: a change of one
// field goes to every selected model as one undoable edit and leaves their other fields alone;
// which fields are mixed; renaming (unique, non-empty, undoable); the visibility toggle (a view:
// hidden models are not framed nor drawn, yet baked and exported as before).
#include "editor/editor_session.hpp"
#include "editor/model_fields.hpp"

#include "io/document_io.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

#include <limits>

using namespace animator;
using namespace animator::test;

namespace fs = std::filesystem;

namespace {

fs::path simple_lua() { return source_dir() / "assets" / "scenes" / "simple.lua"; }
fs::path puppet_lua() { return source_dir() / "assets" / "scenes" / "puppet.lua"; }

void bake_all(EditorSession &s) {
    for (int i = 0; i < 100000 && s.bake_some(0.05); ++i) {
    }
    REQUIRE_FALSE(s.baking());
}

const Model &model(const EditorSession &s, const std::string &name) {
    const int i = s.document().find_model(name);
    REQUIRE(i >= 0);
    return s.document().models()[static_cast<size_t>(i)];
}

int index_of(const EditorSession &s, const std::string &name) {
    const int i = s.document().find_model(name);
    REQUIRE(i >= 0);
    return i;
}

} // namespace

TEST_CASE("a field changed with several models selected goes to all of them, one undo takes it back", "[session][outliner]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(simple_lua(), error));
    const Model ball_before = model(s, "ball"), cube_before = model(s, "cube");
    REQUIRE(ball_before.gravity);
    REQUIRE_FALSE(cube_before.gravity);
    REQUIRE_FALSE(model(s, "cone").gravity);

    // The cube and the cone selected with CTRL+click; the Model Interface shows the cone's values.
    s.click(index_of(s, "cube"), true);
    s.click(index_of(s, "cone"), true);
    REQUIRE(s.selection().size() == 2);
    Model draft = model(s, "cone");
    draft.gravity = true;
    REQUIRE(s.set_field(s.selection(), ModelField::Gravity, draft, &error));
    CHECK(model(s, "cube").gravity);
    CHECK(model(s, "cone").gravity);
    // Only Gravity: the cube keeps its own texture and colour, though the draft was the cone's.
    Model cube_now = model(s, "cube");
    CHECK(cube_now.texture == "wood");
    CHECK(cube_now.material == cube_before.material);
    cube_now.gravity = false;
    CHECK(cube_now == cube_before);
    CHECK(s.dirty());

    // One undo, both back.
    REQUIRE(s.undo());
    CHECK_FALSE(model(s, "cube").gravity);
    CHECK_FALSE(model(s, "cone").gravity);
    CHECK_FALSE(s.dirty());
    CHECK_FALSE(s.can_undo());
    REQUIRE(s.redo());
    CHECK(model(s, "cube").gravity);
    CHECK(model(s, "cone").gravity);
}

TEST_CASE("a multi-edit changes only the field changed, and only the models that differ", "[session][outliner]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(simple_lua(), error));
    const std::set<int> both{index_of(s, "ball"), index_of(s, "cylinder")};
    const Model ball = model(s, "ball"), cylinder = model(s, "cylinder");

    // The draft is the cylinder's with a new mass: the ball takes the mass, not the reflectivity.
    Model draft = cylinder;
    draft.mass = 5.0;
    REQUIRE(s.set_field(both, ModelField::Mass, draft, &error));
    CHECK(model(s, "ball").mass == 5.0);
    CHECK(model(s, "cylinder").mass == 5.0);
    CHECK(model(s, "ball").reflectivity == ball.reflectivity);
    CHECK(model(s, "ball").dynamics == ball.dynamics);
    CHECK(model(s, "ball").material == ball.material);
    CHECK(model(s, "ball").collision_sound == "click");
    CHECK(model(s, "cylinder").reflectivity == cylinder.reflectivity);

    // A vector field (the initial velocity) and a colour go whole.
    draft.initial_velocity = {1.0, 2.0, 3.0};
    REQUIRE(s.set_field(both, ModelField::Velocity, draft, &error));
    CHECK(model(s, "ball").initial_velocity == glm::dvec3(1.0, 2.0, 3.0));
    CHECK(model(s, "cylinder").initial_velocity == glm::dvec3(1.0, 2.0, 3.0));
    draft.material.kd = {0.1, 0.2, 0.3};
    REQUIRE(s.set_field(both, ModelField::Kd, draft, &error));
    CHECK(model(s, "ball").material.kd == glm::dvec3(0.1, 0.2, 0.3));
    CHECK(model(s, "ball").material.ks == ball.material.ks);
    CHECK(model(s, "ball").material.shininess == ball.material.shininess);

    // A value every selected model has already is no edit: nothing to undo for it.
    REQUIRE(s.undo());
    REQUIRE(s.undo());
    REQUIRE(s.undo());
    CHECK_FALSE(s.can_undo());
    Model same = ball;
    REQUIRE(s.set_field({index_of(s, "ball")}, ModelField::Mass, same, &error));
    CHECK_FALSE(s.can_undo());
    CHECK(field_edit(s.document(), both, ModelField::Dynamics, ball) != nullptr); // the cylinder has none
    Model no_dynamics = ball;
    no_dynamics.dynamics = false;
    CHECK(field_edit(s.document(), {index_of(s, "cylinder")}, ModelField::Dynamics, no_dynamics) == nullptr);

    // A value a model refuses changes none of them, and says why.
    Model bad = ball;
    bad.mass = -1.0;
    CHECK_FALSE(s.set_field(both, ModelField::Mass, bad, &error));
    CHECK_THAT(error, Catch::Contains("mass"));
    CHECK(model(s, "ball").mass == ball.mass);
    CHECK(model(s, "cylinder").mass == cylinder.mass);
    CHECK_FALSE(s.can_undo());
}

TEST_CASE("mixed: a field whose values differ among the selected models", "[session][outliner]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(simple_lua(), error));
    const Document &doc = s.document();
    const int ball = index_of(s, "ball"), cube = index_of(s, "cube"), cone = index_of(s, "cone"),
              cylinder = index_of(s, "cylinder");
    // Ball: dynamics and gravity, red, a collision sound; cube: wood, green; cone: yellow.
    CHECK(field_mixed(doc, {ball, cube}, ModelField::Dynamics));
    CHECK(field_mixed(doc, {ball, cube}, ModelField::Gravity));
    CHECK(field_mixed(doc, {ball, cube}, ModelField::Kd));
    CHECK(field_mixed(doc, {ball, cube}, ModelField::CollisionSound));
    CHECK(field_mixed(doc, {cube, cone}, ModelField::Texture));
    CHECK_FALSE(field_mixed(doc, {cube, cone}, ModelField::Gravity));
    CHECK_FALSE(field_mixed(doc, {cube, cone}, ModelField::Mass));
    CHECK_FALSE(field_mixed(doc, {cube, cone}, ModelField::MovingSound));
    CHECK_FALSE(field_mixed(doc, {cone, cylinder}, ModelField::Transparency));
    CHECK(field_mixed(doc, {cone, cylinder}, ModelField::Reflectivity));
    // One model, or none, is never mixed.
    CHECK_FALSE(field_mixed(doc, {ball}, ModelField::Kd));
    CHECK_FALSE(field_mixed(doc, {}, ModelField::Kd));

    // Set on both, a field is no longer mixed; the others still are.
    Model draft = doc.models()[static_cast<size_t>(ball)];
    REQUIRE(s.set_field({ball, cube}, ModelField::Gravity, draft, &error));
    CHECK_FALSE(field_mixed(s.document(), {ball, cube}, ModelField::Gravity));
    CHECK(field_mixed(s.document(), {ball, cube}, ModelField::Dynamics));

    // same_field and copy_field touch one field.
    Model a, b;
    b.tint = 0.5;
    b.mass = 3.0;
    CHECK_FALSE(same_field(ModelField::Tint, a, b));
    CHECK(same_field(ModelField::Gravity, a, b));
    copy_field(ModelField::Tint, b, a);
    CHECK(a.tint == 0.5);
    CHECK(a.mass == 1.0);
}

TEST_CASE("rename: one undoable edit, an empty name or another model's is refused and says why", "[session][outliner]") {
    const fs::path dir = fresh_dir("session_rename");
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(puppet_lua(), error));
    const int shoulder = index_of(s, "left_shoulder"), arm = index_of(s, "left_arm");
    REQUIRE(s.document().models()[static_cast<size_t>(arm)].parent == shoulder);
    REQUIRE(s.document().models()[static_cast<size_t>(shoulder)].mesh.empty()); // a joint

    REQUIRE(s.rename_model(shoulder, "  hinge ", &error)); // surrounding spaces are not kept
    CHECK(s.document().models()[static_cast<size_t>(shoulder)].name == "hinge");
    CHECK(s.document().find_model("left_shoulder") < 0);
    CHECK(s.document().models()[static_cast<size_t>(arm)].parent == shoulder); // children keep it
    CHECK(s.dirty());
    CHECK(s.can_undo());

    // Refused: nothing changes, and the message says what is wrong.
    const Document before = s.document();
    CHECK_FALSE(s.rename_model(shoulder, "head", &error));
    CHECK_THAT(error, Catch::Contains("'head'") && Catch::Contains("unique"));
    CHECK(s.document() == before);
    CHECK_FALSE(s.rename_model(shoulder, "", &error));
    CHECK_THAT(error, Catch::Contains("needs a name"));
    CHECK_FALSE(s.rename_model(shoulder, "   ", &error));
    CHECK(s.document() == before);
    CHECK_FALSE(s.rename_model(99, "x", &error));
    // Its own name again is no edit.
    REQUIRE(s.rename_model(shoulder, "hinge", &error));
    CHECK(s.document() == before);

    // Exported, the file has the new name, and the arm hangs under it.
    {
        const fs::path previous = fs::current_path();
        fs::current_path(dir);
        const auto r = s.export_animation();
        fs::current_path(previous);
        REQUIRE(r.ok);
    }
    const Document saved = open_document(env.plugins, dir / "animations" / "new.ani").document;
    REQUIRE(saved.find_model("hinge") == shoulder);
    CHECK(saved.models()[static_cast<size_t>(arm)].parent == shoulder);
    CHECK(saved == s.document());

    // One undo gives the old name back.
    REQUIRE(s.undo());
    CHECK(s.document().models()[static_cast<size_t>(shoulder)].name == "left_shoulder");
    CHECK_FALSE(s.can_undo());

    CHECK(check_rename(s.document(), arm, "right_arm") != "");
    CHECK(check_rename(s.document(), arm, "left_arm") == "");
    CHECK(trim_name("\t a b \n") == "a b");
}

TEST_CASE("visibility is a view: a hidden model and what hangs under it are not shown, yet baked and exported", "[session][outliner]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(puppet_lua(), error));
    const int puppet = index_of(s, "puppet"), shoulder = index_of(s, "left_shoulder"), arm = index_of(s, "left_arm"),
              head = index_of(s, "head");
    const int count = static_cast<int>(s.document().models().size());
    const std::size_t spheres = s.model_spheres(false).size(); // every model with a mesh
    CHECK(s.hidden_models().empty());

    s.click(arm, false);
    s.click(head, true);
    s.set_hidden(shoulder, true);
    CHECK(s.hidden(shoulder));
    CHECK_FALSE(s.hidden(arm));   // its own flag is on
    CHECK_FALSE(s.shown(arm));    // but it hangs under a hidden joint
    CHECK(s.shown(head));
    CHECK(s.hidden_models() == std::set<int>{shoulder, arm});
    CHECK(s.selection() == std::set<int>{head}); // what it hid was deselected
    CHECK(s.last_selected() == head);
    CHECK(s.model_spheres(false).size() == spheres - 1); // the arm is not framed (the joint has no mesh)
    // Not an edit: no undo, no " *".
    CHECK_FALSE(s.dirty());
    CHECK_FALSE(s.can_undo());

    // The whole puppet hidden: nothing left to frame; Home says so.
    s.set_hidden(puppet, true);
    CHECK(static_cast<int>(s.hidden_models().size()) == count);
    CHECK(s.model_spheres(false).empty());
    CHECK_FALSE(s.frame_models(false, 1.5));
    CHECK(s.selection().empty());
    CHECK(s.last_selected() == -1);
    // Still selectable from the Outliner (to edit its properties), shown again one by one.
    s.click(head, false);
    CHECK(s.last_selected() == head);
    s.set_hidden(puppet, false);
    CHECK(s.hidden_models() == std::set<int>{shoulder, arm});
    s.set_hidden(shoulder, false);
    CHECK(s.hidden_models().empty());
    CHECK(s.model_spheres(false).size() == spheres);
    s.set_hidden(-1, true); // not a model: nothing
    s.set_hidden(count, true);
    CHECK(s.hidden_models().empty());

    // Opening a file shows everything again.
    s.set_hidden(head, true);
    REQUIRE(s.open(puppet_lua(), error));
    CHECK(s.hidden_models().empty());
}

TEST_CASE("a hidden model is still simulated: the bake, its collisions and the export are the same", "[session][outliner]") {
    Environment env;
    EditorSession shown(env), hidden(env);
    std::string error;
    REQUIRE(shown.open(simple_lua(), error));
    REQUIRE(hidden.open(simple_lua(), error));
    const int ball = index_of(hidden, "ball"), floor = index_of(hidden, "floor");
    hidden.set_hidden(ball, true);
    hidden.set_hidden(floor, true);
    bake_all(shown);
    bake_all(hidden);
    for (std::int64_t ms : {0, 700, 1500, 4000}) {
        shown.set_time_ms(ms);
        hidden.set_time_ms(ms);
        const Frame a = shown.frame(), b = hidden.frame();
        // To rounding, not bit for bit: each session bakes in slices of its own size (they
        // follow the time a slice took), and a sliced bake meets the whole one to rounding.
        const glm::dvec3 d = a.models[static_cast<size_t>(ball)].center - b.models[static_cast<size_t>(ball)].center;
        CHECK(glm::length(d) < 1e-9);
    }
    // The ball fell and bounced on the hidden floor: it moved, and it hit the floor.
    hidden.set_time_ms(700);
    CHECK(hidden.frame().models[static_cast<size_t>(ball)].center.y < 2.9);
    CHECK(hidden.frame().models[static_cast<size_t>(ball)].center.y > 0.99);
    CHECK(hidden.timeline().events().size() == shown.timeline().events().size());
    bool hit_floor = false;
    for (const ani_collision_event &c : hidden.timeline().events())
        hit_floor |= (static_cast<int>(c.a) == ball && static_cast<int>(c.b) == floor) ||
                     (static_cast<int>(c.a) == floor && static_cast<int>(c.b) == ball);
    CHECK(hit_floor);
    CHECK(hidden.document() == shown.document());
    CHECK_FALSE(hidden.dirty());
}

TEST_CASE("the rigid-body fields: each a multi-edit of one undo, mixed when they differ, bad values refused",
          "[session][outliner]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(simple_lua(), error));
    const int ball = index_of(s, "ball"), cube = index_of(s, "cube");
    const std::set<int> both{ball, cube};
    const Model b0 = model(s, "ball"), c0 = model(s, "cube");
    // simple.lua sets none of them: the defaults, so none is mixed yet.
    for (ModelField f : {ModelField::Restitution, ModelField::Friction, ModelField::Rotates, ModelField::AngularVelocity})
        CHECK_FALSE(field_mixed(s.document(), both, f));

    // The draft is the cube's with new rigid-body values; each field goes alone to both models.
    Model draft = c0;
    draft.restitution = 0.5;
    draft.friction = 0.75;
    draft.rotates = true;
    draft.angular_velocity = {0.0, 0.0, 6.28};
    draft.mass = 42.0; // not set by any of these edits
    REQUIRE(s.set_field(both, ModelField::Restitution, draft, &error));
    CHECK(model(s, "ball").restitution == 0.5);
    CHECK(model(s, "cube").restitution == 0.5);
    CHECK(model(s, "ball").friction == 0.0);
    REQUIRE(s.set_field(both, ModelField::Friction, draft, &error));
    REQUIRE(s.set_field(both, ModelField::Rotates, draft, &error));
    REQUIRE(s.set_field(both, ModelField::AngularVelocity, draft, &error));
    for (const char *name : {"ball", "cube"}) {
        CAPTURE(name);
        const Model &m = model(s, name);
        CHECK(m.friction == 0.75);
        CHECK(m.rotates);
        CHECK(m.angular_velocity == glm::dvec3(0.0, 0.0, 6.28));
    }
    CHECK(model(s, "ball").mass == b0.mass);
    CHECK(model(s, "ball").material == b0.material);
    CHECK(model(s, "ball").dynamics == b0.dynamics);

    // Set on one only, a field is mixed among the two.
    Model one = draft;
    one.friction = 1.25;
    REQUIRE(s.set_field({ball}, ModelField::Friction, one, &error));
    CHECK(field_mixed(s.document(), both, ModelField::Friction));
    CHECK_FALSE(field_mixed(s.document(), both, ModelField::Restitution));

    // Each was one edit: five undos give the models back as they were.
    for (int i = 0; i < 5; ++i) REQUIRE(s.undo());
    CHECK_FALSE(s.can_undo());
    CHECK(model(s, "ball") == b0);
    CHECK(model(s, "cube") == c0);

    // Values the document refuses change no model and say why.
    Model bad = draft;
    bad.restitution = 1.5;
    CHECK_FALSE(s.set_field(both, ModelField::Restitution, bad, &error));
    CHECK_THAT(error, Catch::Contains("restitution"));
    bad.friction = -0.1;
    CHECK_FALSE(s.set_field(both, ModelField::Friction, bad, &error));
    CHECK_THAT(error, Catch::Contains("friction"));
    bad.angular_velocity = {0.0, std::numeric_limits<double>::infinity(), 0.0};
    CHECK_FALSE(s.set_field(both, ModelField::AngularVelocity, bad, &error));
    CHECK_THAT(error, Catch::Contains("angular velocity"));
    CHECK(model(s, "ball") == b0);
    CHECK_FALSE(s.can_undo());
}
