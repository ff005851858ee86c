// The editor's session without a window, as a user drives it: open, select, drag at a new time
// (a keyframe appears), undo and redo on the keyframe's stack, play, bake in slices, swap the
// backend, export without overwriting what the user did not open.
#include "editor/editor_session.hpp"

#include "io/document_io.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

#include <unistd.h>

using namespace animator;
using namespace animator::test;
using Catch::Matchers::WithinAbs;

namespace fs = std::filesystem;

namespace {

// Runs a test in a fresh working folder (export writes ./animations/new.ani), then goes back.
struct InFolder {
    fs::path previous = fs::current_path();
    explicit InFolder(const fs::path &dir) { fs::current_path(dir); }
    ~InFolder() { fs::current_path(previous); }
};

fs::path drop_ani() { return source_dir() / "assets" / "animations" / "drop.ani"; }

void bake_all(EditorSession &s) {
    for (int i = 0; i < 100000 && s.bake_some(0.05); ++i) {
    }
    REQUIRE_FALSE(s.baking());
}

int ball(const EditorSession &s) { return s.document().find_model("ball"); }

} // namespace

TEST_CASE("a drag in Translate mode at a new time creates a keyframe keying only the dragged model", "[session]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    CHECK(s.title() == "animator - drop.ani");
    bake_all(s);

    s.set_time_ms(1500);
    REQUIRE(s.keyframe_here() < 0);
    const glm::dvec3 before = s.frame().models[static_cast<size_t>(ball(s))].center;
    s.click(ball(s), false);
    s.set_mode(EditMode::Translate);
    s.begin_drag(DragButton::Right, 720);
    s.update_drag({100.0, -50.0});
    // The preview moves the ball before anything is recorded.
    const glm::dvec3 preview = s.frame().models[static_cast<size_t>(ball(s))].center;
    CHECK(preview.x > before.x);
    CHECK(preview.y > before.y);
    CHECK(s.document().keyframes().size() == 1);
    s.end_drag();

    REQUIRE(s.document().keyframes().size() == 2);
    const Keyframe &k = s.document().keyframes()[1];
    CHECK(k.time_ms == 1500);
    REQUIRE(k.states[static_cast<size_t>(ball(s))].has_value());
    CHECK(k.states[static_cast<size_t>(ball(s))]->center == preview);
    CHECK_FALSE(k.states[static_cast<size_t>(s.document().find_model("floor"))].has_value());
    CHECK(s.dirty());
    CHECK(s.title() == "animator - drop.ani *");
    // The bake is kept up to the earliest time the new key can change (the ball's key at 0).
    CHECK(s.baking());
    bake_all(s);
    CHECK_THAT(s.frame().models[static_cast<size_t>(ball(s))].center.x, WithinAbs(preview.x, 1e-9));

    // Undo takes the keyframe back (its creation was on the document's stack); redo restores it.
    REQUIRE(s.undo());
    CHECK(s.document().keyframes().size() == 1);
    CHECK_FALSE(s.dirty());
    REQUIRE(s.redo());
    CHECK(s.document().keyframes().size() == 2);
}

TEST_CASE("a drag at a keyframe edits it, one undo per drag, on that keyframe's own stack", "[session]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    s.set_time_ms(2000);
    s.click(ball(s), false);
    s.set_mode(EditMode::Translate);
    s.begin_drag(DragButton::Right, 720);
    s.update_drag({40.0, 0.0});
    s.end_drag(); // creates the keyframe at 2000 ms
    REQUIRE(s.document().keyframes().size() == 2);
    const ModelState first = *s.document().keyframe_at(2000).states[static_cast<size_t>(ball(s))];

    s.set_mode(EditMode::Scale);
    s.begin_drag(DragButton::Right, 720);
    s.update_drag({69.0, 0.0});
    s.end_drag(); // edits it
    REQUIRE(s.document().keyframes().size() == 2);
    const ModelState second = *s.document().keyframe_at(2000).states[static_cast<size_t>(ball(s))];
    CHECK(second.center == first.center);
    CHECK_THAT(second.scale.x, WithinAbs(first.scale.x * std::exp(0.69), 1e-12));

    // At t = 0 there is nothing of this keyframe's to undo, and the document's stack has the
    // keyframe's creation: undo there removes it... but first, at 2000 ms, the scale goes.
    REQUIRE(s.undo());
    CHECK(*s.document().keyframe_at(2000).states[static_cast<size_t>(ball(s))] == first);
    REQUIRE(s.undo());
    CHECK(s.document().find_keyframe(2000) < 0);
    CHECK_FALSE(s.undo());
    REQUIRE(s.redo());
    REQUIRE(s.redo());
    CHECK(*s.document().keyframe_at(2000).states[static_cast<size_t>(ball(s))] == second);
}

TEST_CASE("selection: click selects one, CTRL+click adds and removes, empty space clears", "[session]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    const int floor = s.document().find_model("floor");
    s.click(ball(s), false);
    CHECK(s.selection() == std::set<int>{ball(s)});
    s.click(floor, true);
    CHECK(s.selection() == std::set<int>{ball(s), floor});
    CHECK(s.last_selected() == floor);
    s.click(floor, true);
    CHECK(s.selection() == std::set<int>{ball(s)});
    CHECK(s.last_selected() == ball(s));
    s.click(-1, false);
    CHECK(s.selection().empty());
    CHECK(s.last_selected() == -1);
}

TEST_CASE("a multi-model drag is one edit that moves every selected model", "[session]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    const int floor = s.document().find_model("floor");
    const Document before = s.document();
    s.click(ball(s), false);
    s.click(floor, true);
    s.set_mode(EditMode::Translate);
    s.begin_drag(DragButton::Middle, 720); // at t = 0: edits the first keyframe
    s.update_drag({0.0, 30.0});
    s.end_drag();
    const Keyframe &k0 = s.document().keyframes()[0];
    const double dz_ball = k0.states[static_cast<size_t>(ball(s))]->center.z - before.keyframes()[0].states[static_cast<size_t>(ball(s))]->center.z;
    const double dz_floor = k0.states[static_cast<size_t>(floor)]->center.z - before.keyframes()[0].states[static_cast<size_t>(floor)]->center.z;
    CHECK(dz_ball > 0.0);
    CHECK(dz_ball == dz_floor);
    REQUIRE(s.undo());
    CHECK(s.document() == before);
}

TEST_CASE("the camera drag and the scroll wheel key the camera, undoably", "[session]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    const CameraState start = *s.document().keyframes()[0].camera;
    s.set_mode(EditMode::Camera);
    s.begin_drag(DragButton::Left, 720);
    s.update_drag({50.0, 0.0});
    s.end_drag();
    const CameraState moved = *s.document().keyframes()[0].camera;
    CHECK(moved.position.x < start.position.x); // the scene went right with the cursor
    s.scroll(1.0);
    const CameraState closer = *s.document().keyframes()[0].camera;
    CHECK(glm::length(closer.position - moved.position) > 0.0);
    REQUIRE(s.undo());
    REQUIRE(s.undo());
    CHECK(*s.document().keyframes()[0].camera == start);
}

TEST_CASE("baking in slices gives the same motion as one bake", "[session]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(source_dir() / "assets" / "animations" / "cradle.ani", error));
    int slices = 0;
    while (s.bake_some(1e-6)) ++slices; // a budget of one slice per call
    CHECK(slices > 3);
    Timeline whole(s.document(), env.plugins);
    whole.set_meshes(s.meshes());
    whole.bake(s.max_time());
    for (double t : {0.0, 0.37, 1.5, 4.25, s.max_time()}) {
        s.set_time_ms(static_cast<std::int64_t>(t * 1000.0));
        const Frame a = s.frame(), b = whole.evaluate(s.time());
        for (size_t m = 0; m < a.models.size(); ++m)
            CHECK(glm::length(a.models[m].center - b.models[m].center) < 1e-9);
    }
}

TEST_CASE("playback runs in real time from the current time and stops at the max time", "[session]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    bake_all(s);
    s.set_time_ms(1000);
    s.toggle_play(100.0);
    s.tick(100.25);
    CHECK(s.time_ms() == 1250);
    s.tick(103.0);
    CHECK(s.time_ms() == 4000);
    s.tick(1000.0);
    CHECK(s.time_ms() == s.document().settings().max_time_ms);
    CHECK_FALSE(s.playing());
    // SPACE at the end plays again from the start.
    s.toggle_play(2000.0);
    s.tick(2000.5);
    CHECK(s.time_ms() == 500);
    s.toggle_play(2001.0);
    s.tick(2009.0);
    CHECK(s.time_ms() == 500); // paused
}

TEST_CASE("playback waits for the bake instead of showing what is not baked", "[session]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    REQUIRE(s.timeline().baked_until() == 0.0);
    s.toggle_play(0.0);
    s.tick(5.0);
    CHECK(s.time_ms() == 0);
    CHECK(s.playing());
}

TEST_CASE("swapping the backend keeps the document, the selection and the history", "[session]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    s.click(ball(s), false);
    s.set_time_ms(500);
    s.set_mode(EditMode::Translate);
    s.begin_drag(DragButton::Right, 720);
    s.update_drag({10.0, 0.0});
    s.end_drag();
    const Document before = s.document();
    bake_all(s);

    REQUIRE(s.use_backend("physics.bullet", error));
    CHECK(s.backend() == "physics.bullet");
    CHECK(s.document() == before);
    CHECK(s.selection() == std::set<int>{ball(s)});
    CHECK(s.can_undo());
    CHECK(s.baking()); // re-bakes with the new one
    bake_all(s);

    CHECK_FALSE(s.use_backend("physics.nonexistent", error));
    CHECK(error.find("physics.nonexistent") != std::string::npos);
    CHECK(s.backend() == "physics.bullet");
    CHECK_FALSE(s.baking()); // the bake it had is kept
}

TEST_CASE("shortening the max time deletes later keyframes, undo brings them back", "[session]") {
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    s.set_time_ms(8000);
    s.set_mode(EditMode::Camera);
    s.begin_drag(DragButton::Left, 720);
    s.update_drag({10.0, 0.0});
    s.end_drag();
    REQUIRE(s.document().find_keyframe(8000) >= 0);
    Settings shorter = s.document().settings();
    shorter.max_time_ms = 5000;
    REQUIRE(s.set_settings(shorter, &error));
    CHECK(s.document().find_keyframe(8000) < 0);
    CHECK(s.time_ms() == 5000); // the time stays within the animation
    s.set_time_ms(0);
    REQUIRE(s.undo());
    CHECK(s.document().find_keyframe(8000) >= 0);
    CHECK(s.document().settings().max_time_ms == 10000);
}

TEST_CASE("export writes the opened .ani, and the file reads back as the document", "[session]") {
    const fs::path dir = fresh_dir("session_export_ani");
    fs::copy_file(drop_ani(), dir / "mine.ani");
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(dir / "mine.ani", error));
    Settings heavier = s.document().settings();
    heavier.gravity = 20.0;
    REQUIRE(s.set_settings(heavier, &error));
    CHECK(s.dirty());
    const auto r = s.export_animation();
    REQUIRE(r.ok);
    CHECK(r.path == dir / "mine.ani");
    CHECK_FALSE(s.dirty());
    CHECK(open_document(env.plugins, dir / "mine.ani").document == s.document());
}

TEST_CASE("export never overwrites a file the user did not open: it picks a fresh name and says so", "[session]") {
    const fs::path dir = fresh_dir("session_export_new");
    InFolder here(dir);
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(source_dir() / "assets" / "scenes" / "simple.lua", error));

    auto r = s.export_animation();
    REQUIRE(r.ok);
    CHECK(r.path == fs::path("animations") / "new.ani");
    CHECK(fs::exists(dir / "animations" / "new.ani"));
    CHECK(s.title() == "animator - new.ani");

    // A second session, on the scene again: new.ani is not its file.
    const std::string first = read_file(dir / "animations" / "new.ani");
    EditorSession other(env);
    REQUIRE(other.open(source_dir() / "assets" / "scenes" / "simple.lua", error));
    r = other.export_animation();
    REQUIRE(r.ok);
    CHECK(r.path == fs::path("animations") / "new-1.ani");
    CHECK(r.message.find("fresh name") != std::string::npos);
    CHECK(read_file(dir / "animations" / "new.ani") == first);
    // Its next export goes to the file it wrote.
    CHECK(other.export_animation().path == fs::path("animations") / "new-1.ani");
}

TEST_CASE("a file that fails to open leaves the current document and says where", "[session]") {
    const fs::path dir = fresh_dir("session_bad_open");
    write_file(dir / "broken.ani", "animator-ani 1\nsettings\n  gravity banana\nend\n");
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(drop_ani(), error));
    const Document before = s.document();
    CHECK_FALSE(s.open(dir / "broken.ani", error));
    CHECK(error.find("broken.ani") != std::string::npos);
    CHECK(error.find(":3") != std::string::npos); // the line
    CHECK(s.document() == before);
    CHECK(s.path() == drop_ani());
}
