// Autosave and recovery without a window (editor/recovery.hpp): the clock that counts time with
// unsaved changes, where recovery files live and how they are named, the atomic write that keeps
// the previous recovery file when it fails, and recovering a named and an untitled document in a
// new session as if the editor had been killed.
#include "editor/recovery.hpp"

#include "editor/editor_session.hpp"
#include "io/document_io.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <optional>
#include <regex>

using namespace animator;
using namespace animator::test;

namespace fs = std::filesystem;

namespace {

const char *const kBall = R"(animator-ani 1
settings
  max_time_ms 2000
  gravity 9.81
  down y
  cel_shading false
  skybox ""
  physics_backend "physics.custom"
end

model "ball"
  mesh "sphere"
  kd 0.2 0.3 0.9
  ks 0.5 0.5 0.5
  shininess 40
end

keyframe 0
  camera position 0 0 12 rotation 1 0 0 0 fov 50
  state "ball" center 0 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0
end
)";

// Sets an environment variable for a scope, then puts back what was there.
struct EnvVar {
    std::string name;
    std::optional<std::string> before;
    EnvVar(std::string n, const char *value) : name(std::move(n)) {
        if (const char *v = std::getenv(name.c_str())) before = v;
        if (value) setenv(name.c_str(), value, 1);
        else unsetenv(name.c_str());
    }
    ~EnvVar() {
        if (before) setenv(name.c_str(), before->c_str(), 1);
        else unsetenv(name.c_str());
    }
};

struct InFolder {
    fs::path previous = fs::current_path();
    explicit InFolder(const fs::path &dir) { fs::current_path(dir); }
    ~InFolder() { fs::current_path(previous); }
};

bool set_gravity(EditorSession &s, double g) {
    Settings settings = s.document().settings();
    settings.gravity = g;
    return s.set_settings(settings);
}

double gravity_in(PluginRegistry &plugins, const fs::path &file) {
    return open_document(plugins, file).document.settings().gravity;
}

std::vector<std::string> names_in(const fs::path &folder) {
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto &e : fs::directory_iterator(folder, ec)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

// Makes `file` older than now by `seconds`, as a document saved before the autosave was.
void age(const fs::path &file, int seconds) {
    fs::last_write_time(file, fs::last_write_time(file) - std::chrono::seconds(seconds));
}

} // namespace

TEST_CASE("the autosave clock counts only the time with changes in no file", "[recovery]") {
    AutosaveClock c(120.0);
    c.update(0.0, false, 1);
    CHECK_FALSE(c.seconds_to_wait(0.0)); // nothing unsaved: the editor sleeps without a timer
    CHECK_FALSE(c.due(1000.0));

    c.update(10.0, true, 2); // the first change starts the clock
    REQUIRE(c.seconds_to_wait(10.0));
    CHECK(*c.seconds_to_wait(10.0) == Approx(120.0));
    c.update(70.0, true, 3); // more changes do not start it again
    CHECK(*c.seconds_to_wait(70.0) == Approx(60.0));
    CHECK_FALSE(c.due(129.9));
    CHECK(c.due(130.0));
    CHECK(*c.seconds_to_wait(200.0) == 0.0);

    c.update(100.0, false, 4); // undone back to the saved state: stopped, and from 0 next time
    CHECK_FALSE(c.seconds_to_wait(100.0));
    CHECK_FALSE(c.due(500.0));
    c.update(200.0, true, 5);
    CHECK(*c.seconds_to_wait(200.0) == Approx(120.0));
    CHECK(c.due(320.0));

    c.written(5); // the recovery file has version 5: nothing more to write however long it waits
    c.update(330.0, true, 5);
    CHECK_FALSE(c.seconds_to_wait(330.0));
    c.update(5000.0, true, 5);
    CHECK_FALSE(c.due(5000.0));
    c.update(5001.0, true, 6); // a new change starts counting again
    CHECK(*c.seconds_to_wait(5001.0) == Approx(120.0));
    CHECK(c.due(5121.0));

    c.failed(5121.0); // a failed write is tried again after another interval
    CHECK(*c.seconds_to_wait(5121.0) == Approx(120.0));
    c.update(5200.0, true, 6);
    CHECK(*c.seconds_to_wait(5200.0) == Approx(41.0));

    AutosaveClock off(0.0); // ANIMATOR_AUTOSAVE_SECONDS=0
    off.update(0.0, true, 2);
    CHECK_FALSE(off.seconds_to_wait(10.0));
    CHECK_FALSE(off.due(1e9));
}

TEST_CASE("the autosave interval comes from ANIMATOR_AUTOSAVE_SECONDS", "[recovery]") {
    std::string warning;
    {
        EnvVar v("ANIMATOR_AUTOSAVE_SECONDS", nullptr);
        CHECK(autosave_interval(&warning) == 120.0);
    }
    {
        EnvVar v("ANIMATOR_AUTOSAVE_SECONDS", "1.5");
        CHECK(autosave_interval(&warning) == 1.5);
    }
    {
        EnvVar v("ANIMATOR_AUTOSAVE_SECONDS", "0");
        CHECK(autosave_interval(&warning) == 0.0);
    }
    CHECK(warning.empty());
    EnvVar v("ANIMATOR_AUTOSAVE_SECONDS", "soon");
    CHECK(autosave_interval(&warning) == 120.0);
    CHECK(warning.find("soon") != std::string::npos);
}

TEST_CASE("recovery files live in the XDG state folder, one per document", "[recovery]") {
    {
        EnvVar state("XDG_STATE_HOME", "/somewhere/state");
        CHECK(recovery_folder() == fs::path("/somewhere/state/animator/recovery"));
    }
    {
        EnvVar state("XDG_STATE_HOME", "relative/state"); // not absolute: ignored, as the spec says
        EnvVar home("HOME", "/home/someone");
        CHECK(recovery_folder() == fs::path("/home/someone/.local/state/animator/recovery"));
    }
    {
        EnvVar state("XDG_STATE_HOME", nullptr);
        EnvVar home("HOME", nullptr);
        CHECK(recovery_folder().empty());
    }

    const fs::path dir = fresh_dir("recovery_names");
    const fs::path folder = dir / "recovery";
    fs::create_directories(dir / "a");
    fs::create_directories(dir / "b");
    write_file(dir / "a" / "ball.ani", kBall);
    write_file(dir / "b" / "ball.ani", kBall);

    const fs::path a = recovery_file(folder, dir / "a" / "ball.ani");
    CHECK(a.parent_path() == folder);
    CHECK(std::regex_match(a.filename().string(), std::regex("ball-[0-9a-f]{16}\\.ani")));
    // Two documents of the same name in two folders do not collide.
    CHECK(recovery_file(folder, dir / "b" / "ball.ani") != a);
    // The same document by another name (relative, through "..", through a link) is the same one.
    {
        InFolder in(dir);
        CHECK(recovery_file(folder, "a/ball.ani") == a);
        CHECK(recovery_file(folder, "b/../a/ball.ani") == a);
    }
    fs::create_directory_symlink(dir / "a", dir / "link");
    CHECK(recovery_file(folder, dir / "link" / "ball.ani") == a);
    // The same in every run: a name is a function of the path alone.
    CHECK(recovery_file(folder, dir / "a" / "ball.ani") == a);
    // Names read well in a listing, and are never hidden; untitled has a name of its own.
    CHECK(recovery_file(folder, {}) == folder / "untitled.ani");
    CHECK(recovery_file(folder, dir / "my walk (v2).ani").filename().string().rfind("my_walk__v2_-", 0) == 0);
    CHECK(recovery_file(folder, dir / ".hidden.lua").filename().string().rfind("_hidden-", 0) == 0);
    // Nor do they take the names kept for quitting and discarding.
    CHECK(recovery_file(folder, dir / "quit.ani").filename() != "quit.ani");

    // The dialog names them from the home folder.
    EnvVar home("HOME", "/home/someone/");
    CHECK(home_path("/home/someone/.local/state/animator/recovery/x.ani") == "~/.local/state/animator/recovery/x.ani");
    CHECK(home_path("/home/someone2/x.ani") == "/home/someone2/x.ani");
    CHECK(home_path("/tmp/x.ani") == "/tmp/x.ani");
}

TEST_CASE("a failed autosave says why and keeps the previous recovery file", "[recovery]") {
    Environment env;
    const fs::path dir = fresh_dir("recovery_atomic");
    const fs::path folder = dir / "state" / "recovery";
    const fs::path file = folder / "ball-0000000000000000.ani";
    write_file(dir / "ball.ani", kBall);
    Document doc = open_document(env.plugins, dir / "ball.ani").document;
    Settings s = doc.settings();
    s.gravity = 1.25;
    doc.set_settings(s);

    std::string error;
    REQUIRE(write_recovery(env.plugins, doc, file, error));
    CHECK(gravity_in(env.plugins, file) == 1.25);
    // The work is the user's alone: the folder is made 0700.
    struct stat st {};
    REQUIRE(::stat(folder.c_str(), &st) == 0);
    CHECK((st.st_mode & 0777) == 0700);

    SECTION("a document the writer refuses (a line too long for a reader)") {
        Document big = doc;
        Settings b = big.settings();
        b.skybox = std::string(std::size_t{2} << 20, 'x');
        big.set_settings(b);
        CHECK_FALSE(write_recovery(env.plugins, big, file, error));
        CHECK(error.find("line") != std::string::npos);
    }
    SECTION("a folder that cannot be made (a file is in the way)") {
        write_file(dir / "blocked", "not a folder");
        CHECK_FALSE(write_recovery(env.plugins, doc, dir / "blocked" / "recovery" / "x.ani", error));
        CHECK(error.find("cannot make the folder") != std::string::npos);
    }
    SECTION("an unwritable folder") {
        if (::geteuid() == 0) {
            WARN("running as root, who writes in any folder: the unwritable folder is not tried");
        } else {
            fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec);
            Document other = doc;
            Settings o = other.settings();
            o.gravity = 2.5;
            other.set_settings(o);
            const bool wrote = write_recovery(env.plugins, other, file, error);
            fs::permissions(folder, fs::perms::owner_all);
            CHECK_FALSE(wrote);
            CHECK(error.find("Permission denied") != std::string::npos);
        }
    }
    // The previous recovery file, whole, and no temporary file left beside it.
    CHECK(gravity_in(env.plugins, file) == 1.25);
    CHECK(names_in(folder) == std::vector<std::string>{"ball-0000000000000000.ani"});
}

TEST_CASE("a failed autosave in the editor says why, keeps the work and tries again later", "[recovery]") {
    Environment env;
    const fs::path dir = fresh_dir("recovery_failed_tick");
    write_file(dir / "ball.ani", kBall);
    write_file(dir / "state", "a file where the recovery folder would be");
    EditorSession s(env);
    std::string error;
    REQUIRE(s.open(dir / "ball.ani", error));
    Autosaver saver(env.plugins, dir / "state" / "recovery", 2.0);
    saver.tick(s, 0.0);
    REQUIRE(set_gravity(s, 3.0));
    CHECK(saver.tick(s, 0.5).empty());
    bool failed = false;
    const std::string said = saver.tick(s, 3.0, &failed);
    CHECK(failed);
    CHECK(said.rfind("autosave failed", 0) == 0);
    CHECK(said.find("cannot make the folder") != std::string::npos);
    CHECK(s.dirty()); // the work stays in the editor
    CHECK(s.document().settings().gravity == 3.0);
    REQUIRE(saver.seconds_to_wait(3.0));
    CHECK(*saver.seconds_to_wait(3.0) == Approx(2.0));
    CHECK_FALSE(saver.current());
}

TEST_CASE("a named document's autosave is recovered at the next start, then removed when exported", "[recovery]") {
    Environment env;
    const fs::path dir = fresh_dir("recovery_named");
    const fs::path folder = dir / "state";
    const fs::path ball = dir / "ball.ani";
    write_file(ball, kBall);
    age(ball, 60);
    const fs::path file = recovery_file(folder, ball);
    std::string error, said;

    {
        // A run that is killed: it autosaves, and never quits.
        EditorSession s(env);
        REQUIRE(s.open(ball, error));
        Autosaver saver(env.plugins, folder, 2.0);
        CHECK(saver.tick(s, 0.0).empty());
        CHECK_FALSE(saver.seconds_to_wait(0.0)); // nothing unsaved: no timer
        REQUIRE(set_gravity(s, 3.0));
        CHECK(saver.tick(s, 1.0).empty());
        REQUIRE(saver.seconds_to_wait(1.0));
        CHECK(*saver.seconds_to_wait(1.0) == Approx(2.0));
        CHECK(saver.tick(s, 2.9).empty());
        CHECK(saver.tick(s, 3.0) == "autosaved");
        CHECK(saver.current() == file);
        CHECK(gravity_in(env.plugins, file) == 3.0);
        CHECK_FALSE(saver.seconds_to_wait(3.0)); // written: asleep again
        CHECK(saver.tick(s, 100.0).empty());
        REQUIRE(set_gravity(s, 4.0)); // more work, not yet autosaved when it is killed
        CHECK(saver.tick(s, 101.0).empty());
    }
    CHECK(gravity_in(env.plugins, ball) == 9.81);

    SECTION("Recover: the autosaved work, unsaved, keeping the document's path") {
        EditorSession s(env);
        REQUIRE(s.open(ball, error));
        Autosaver saver(env.plugins, folder, 2.0);
        const auto offer = saver.offer(ball);
        REQUIRE(offer);
        CHECK(offer->file == file);
        CHECK(offer->document == ball);
        CHECK(std::abs(offer->written - std::time(nullptr)) < 60);
        // Nothing is autosaved (nor removed) while the question waits.
        CHECK(saver.tick(s, 0.0).empty());
        CHECK_FALSE(saver.seconds_to_wait(0.0));
        REQUIRE(saver.recover(s, said));
        CHECK(said.find("recovered the unsaved work from " + local_time_label(offer->written)) == 0);
        CHECK(s.document().settings().gravity == 3.0);
        CHECK(s.dirty());
        CHECK(s.title() == "animator - ball.ani *");
        CHECK(s.path() == ball);
        CHECK_FALSE(s.can_undo());
        // Already in the recovery file: no autosave until it changes, and the file stays.
        CHECK(saver.tick(s, 10.0).empty());
        CHECK_FALSE(saver.seconds_to_wait(10.0));
        CHECK(fs::exists(file));
        // Undo back to the document on disk is possible through edits as usual; an export writes
        // the recovered work to the document, and the recovery file goes.
        const auto r = s.export_animation();
        REQUIRE(r.ok);
        CHECK(r.path == ball);
        CHECK(gravity_in(env.plugins, ball) == 3.0);
        CHECK_FALSE(s.dirty());
        CHECK(saver.tick(s, 11.0).empty());
        CHECK_FALSE(fs::exists(file));
        CHECK_FALSE(saver.current());
        // And the next start has nothing to offer.
        Autosaver next(env.plugins, folder, 2.0);
        CHECK_FALSE(next.offer(ball));
    }
    SECTION("the recovered work undone back to the file on disk is no longer unsaved") {
        EditorSession s(env);
        REQUIRE(s.open(ball, error));
        Autosaver saver(env.plugins, folder, 2.0);
        REQUIRE(saver.offer(ball));
        REQUIRE(saver.recover(s, said));
        REQUIRE(set_gravity(s, 9.81));
        CHECK_FALSE(s.dirty());
        CHECK(saver.tick(s, 1.0).empty());
        CHECK_FALSE(fs::exists(file));
    }
    SECTION("Discard: set aside, and not asked again") {
        Autosaver saver(env.plugins, folder, 2.0);
        REQUIRE(saver.offer(ball));
        REQUIRE(saver.discard(said));
        CHECK(said.find("discarded.ani") != std::string::npos);
        CHECK_FALSE(fs::exists(file));
        CHECK(gravity_in(env.plugins, folder / "discarded.ani") == 3.0);
        CHECK_FALSE(saver.offer_pending());
        Autosaver next(env.plugins, folder, 2.0);
        CHECK_FALSE(next.offer(ball));
    }
    SECTION("a document saved after its autosave: not offered") {
        write_file(ball, kBall); // newer than the recovery file
        fs::last_write_time(ball, fs::last_write_time(file) + std::chrono::seconds(5));
        Autosaver saver(env.plugins, folder, 2.0);
        CHECK_FALSE(saver.offer(ball));
        CHECK(fs::exists(file)); // left alone; this run's first autosave replaces it
    }
    SECTION("a document gone since: offered, and exported where it was") {
        fs::remove(ball);
        EditorSession s(env);
        CHECK_FALSE(s.open(ball, error));
        Autosaver saver(env.plugins, folder, 2.0);
        REQUIRE(saver.offer(ball));
        REQUIRE(saver.recover(s, said));
        CHECK(s.path() == ball);
        CHECK(s.dirty());
        REQUIRE(s.export_animation().ok);
        CHECK(gravity_in(env.plugins, ball) == 3.0);
    }
}

TEST_CASE("an untitled document's autosave is recovered as untitled work", "[recovery]") {
    Environment env;
    const fs::path dir = fresh_dir("recovery_untitled");
    const fs::path folder = dir / "state";
    std::string said;
    {
        EditorSession s(env); // no file: the editor without its demo scene
        Autosaver saver(env.plugins, folder, 1.0);
        saver.tick(s, 0.0);
        REQUIRE(set_gravity(s, 2.0));
        saver.tick(s, 0.5);
        CHECK(saver.tick(s, 1.5) == "autosaved");
        CHECK(saver.current() == folder / "untitled.ani");
    }
    InFolder in(dir);
    EditorSession s(env);
    Autosaver saver(env.plugins, folder, 1.0);
    const auto offer = saver.offer({});
    REQUIRE(offer);
    CHECK(offer->file == folder / "untitled.ani");
    REQUIRE(saver.recover(s, said));
    CHECK(s.title() == "animator - untitled *");
    CHECK(s.path().empty());
    CHECK(s.document().settings().gravity == 2.0);
    // Its export goes where an untitled one's does, never into the recovery folder.
    const auto r = s.export_animation();
    REQUIRE(r.ok);
    CHECK(r.path == fs::path("animations") / "new.ani");
    CHECK(gravity_in(env.plugins, dir / "animations" / "new.ani") == 2.0);
    saver.tick(s, 2.0);
    CHECK_FALSE(fs::exists(folder / "untitled.ani"));
}

TEST_CASE("quitting: unsaved work goes to quit.ani, saved work leaves nothing behind", "[recovery]") {
    Environment env;
    const fs::path dir = fresh_dir("recovery_quit");
    const fs::path folder = dir / "state";
    const fs::path ball = dir / "ball.ani";
    write_file(ball, kBall);
    std::string error;
    EditorSession s(env);
    REQUIRE(s.open(ball, error));
    Autosaver saver(env.plugins, folder, 1.0);
    saver.tick(s, 0.0);
    REQUIRE(set_gravity(s, 5.0));
    saver.tick(s, 0.1);
    REQUIRE(saver.tick(s, 1.2) == "autosaved");
    REQUIRE(set_gravity(s, 6.0));

    SECTION("quit without exporting") {
        bool failed = true;
        const std::string said = saver.quit(s, &failed);
        CHECK_FALSE(failed);
        CHECK(said.find("quit.ani") != std::string::npos);
        CHECK(names_in(folder) == std::vector<std::string>{"quit.ani"});
        CHECK(gravity_in(env.plugins, folder / "quit.ani") == 6.0);
        // Never offered at a start.
        Autosaver next(env.plugins, folder, 1.0);
        CHECK_FALSE(next.offer(ball));
    }
    SECTION("export, then quit") {
        REQUIRE(s.export_animation().ok);
        CHECK(saver.quit(s).empty());
        CHECK(names_in(folder).empty());
    }
}
