// Open Recent's list (editor/recent_files.hpp): where it lives, newest first without repeats, at
// most 10, kept across runs in a file written atomically, and a list file that is not there or
// cannot be written. Also the session's Save As and New (editor_session.hpp), which the list
// follows.
#include "editor/recent_files.hpp"

#include "editor/editor_session.hpp"
#include "editor/recovery.hpp"
#include "io/document_io.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <optional>

using namespace animator;
using namespace animator::test;

namespace fs = std::filesystem;

namespace {

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

} // namespace

TEST_CASE("the recent files list lives in the XDG state folder", "[recent]") {
    {
        EnvVar state("XDG_STATE_HOME", "/tmp/state-here");
        CHECK(recent_files_path() == fs::path("/tmp/state-here/animator/recent"));
    }
    {
        EnvVar state("XDG_STATE_HOME", "relative/state"); // not absolute: ignored, as the XDG spec says
        EnvVar home("HOME", "/home/someone");
        CHECK(recent_files_path() == fs::path("/home/someone/.local/state/animator/recent"));
    }
    {
        EnvVar state("XDG_STATE_HOME", nullptr);
        EnvVar home("HOME", nullptr);
        CHECK(recent_files_path().empty());
    }
}

TEST_CASE("recent files: newest first, each once, at most 10, kept across runs", "[recent]") {
    const fs::path dir = fresh_dir("recent_list");
    const fs::path list = dir / "state" / "animator" / "recent";
    RecentFiles r(list);
    REQUIRE(r.load()); // no file yet: an empty list
    CHECK(r.paths().empty());
    for (int i = 0; i < 12; ++i) r.add(dir / ("f" + std::to_string(i) + ".ani"));
    r.add(dir / "sub" / ".." / "f5.ani"); // the same file again: to the front, not twice
    REQUIRE(r.paths().size() == 10);
    CHECK(r.paths()[0] == dir / "f5.ani");
    CHECK(r.paths()[1] == dir / "f11.ani");
    CHECK(r.paths()[9] == dir / "f2.ani"); // f0 and f1 fell off the end; f5 moved up, once
    REQUIRE(r.save());
    // The file a person (or another run) reads: one absolute path a line, newest first.
    std::string expected = (dir / "f5.ani").string() + "\n";
    for (int i = 11; i >= 2; --i)
        if (i != 5) expected += (dir / ("f" + std::to_string(i) + ".ani")).string() + "\n";
    CHECK(read_file(list) == expected);
    CHECK((fs::status(list.parent_path()).permissions() & fs::perms::all) == fs::perms::owner_all);

    RecentFiles again(list);
    REQUIRE(again.load());
    CHECK(again.paths() == r.paths());
    again.remove(dir / "f11.ani");
    CHECK(again.paths().size() == 9);
    again.clear();
    REQUIRE(again.save());
    CHECK(read_file(list).empty());
    // No temporary file left beside it.
    int files = 0;
    for (const auto &e : fs::directory_iterator(list.parent_path())) files += e.is_regular_file() ? 1 : 0;
    CHECK(files == 1);

    // A relative path from the command line is kept as the absolute one.
    struct InFolder {
        fs::path previous = fs::current_path();
        explicit InFolder(const fs::path &d) { fs::current_path(d); }
        ~InFolder() { fs::current_path(previous); }
    } here(dir);
    again.add("rel.ani");
    CHECK(again.paths().front() == dir / "rel.ani");
}

TEST_CASE("a recent files list that cannot be written says why and keeps the file before", "[recent]") {
    const fs::path dir = fresh_dir("recent_unwritable");
    write_file(dir / "blocker", "a file where the folder should be\n");
    RecentFiles r(dir / "blocker" / "animator" / "recent");
    r.add(dir / "a.ani");
    std::string error;
    CHECK_FALSE(r.save(&error));
    CHECK(error.find("cannot write the recent files list " + (dir / "blocker").string()) == 0);

    // A list file with junk lines: they are skipped.
    write_file(dir / "recent", "\nnot/absolute.ani\n" + (dir / "b.ani").string() + "\r\n");
    RecentFiles junk(dir / "recent");
    REQUIRE(junk.load());
    REQUIRE(junk.paths().size() == 1);
    CHECK(junk.paths()[0] == dir / "b.ani");
}

TEST_CASE("Save As writes the .ani and makes it the session's file, New opens a scene untitled", "[recent][session]") {
    const fs::path dir = fresh_dir("session_save_as");
    Environment env;
    EditorSession s(env);
    std::string error;
    REQUIRE(s.new_from_scene(source_dir() / "assets" / "scenes" / "simple.lua", error));
    CHECK(s.title() == "animator - untitled");
    CHECK(s.path().empty());
    CHECK_FALSE(s.saves_to_path()); // Save asks where
    CHECK_FALSE(s.dirty());
    REQUIRE(s.document().models().size() == 6);

    Settings heavier = s.document().settings();
    heavier.gravity = 20.0;
    REQUIRE(s.set_settings(heavier, &error));
    CHECK(s.title() == "animator - untitled *");
    const auto r = s.save_as(dir / "mine.ani");
    REQUIRE(r.ok);
    CHECK(s.title() == "animator - mine.ani");
    CHECK(s.path() == dir / "mine.ani");
    CHECK(s.saves_to_path());
    CHECK_FALSE(s.dirty());
    // What a fresh reader finds in the file: the document as edited.
    const Document written = open_document(env.plugins, dir / "mine.ani").document;
    CHECK(written == s.document());
    CHECK(written.settings().gravity == 20.0);
    // The next Save (export) goes to it.
    heavier.gravity = 3.0;
    REQUIRE(s.set_settings(heavier, &error));
    CHECK(s.export_animation().path == dir / "mine.ani");
    CHECK(open_document(env.plugins, dir / "mine.ani").document.settings().gravity == 3.0);

    // A Save As that cannot write: nothing changes, the file before stays.
    const std::string before = read_file(dir / "mine.ani");
    heavier.gravity = 4.0;
    REQUIRE(s.set_settings(heavier, &error));
    const auto failed = s.save_as(dir / "no-such-folder" / "x.ani");
    CHECK_FALSE(failed.ok);
    CHECK(failed.message.find("no-such-folder") != std::string::npos);
    CHECK(s.path() == dir / "mine.ani");
    CHECK(s.dirty());
    CHECK(read_file(dir / "mine.ani") == before);

    // New from a file that is not a scene: the document stays.
    write_file(dir / "broken.lua", "this is not lua (\n");
    CHECK_FALSE(s.new_from_scene(dir / "broken.lua", error));
    CHECK(error.find("broken.lua") != std::string::npos);
    CHECK(s.path() == dir / "mine.ani");
    CHECK(s.document().settings().gravity == 4.0);
}

TEST_CASE("autosave follows Save As: the untitled recovery file goes, the next one is the new file's", "[recent][recovery]") {
    const fs::path dir = fresh_dir("session_save_as_autosave");
    const fs::path folder = dir / "recovery";
    Environment env;
    EditorSession s(env);
    Autosaver autosaver(env.plugins, folder, 1.0);
    std::string error;
    REQUIRE(s.new_from_scene(source_dir() / "assets" / "scenes" / "simple.lua", error));
    Settings settings = s.document().settings();
    settings.gravity = 5.0;
    REQUIRE(s.set_settings(settings, &error));
    CHECK(autosaver.tick(s, 0.0).empty());
    CHECK(autosaver.tick(s, 1.5) == "autosaved");
    const fs::path untitled = recovery_file(folder, {});
    CHECK(untitled.filename() == "untitled.ani");
    REQUIRE(fs::exists(untitled));

    REQUIRE(s.save_as(dir / "mine.ani").ok);
    autosaver.tick(s, 2.0);
    CHECK_FALSE(fs::exists(untitled)); // the work is in mine.ani now

    settings.gravity = 6.0;
    REQUIRE(s.set_settings(settings, &error));
    CHECK(autosaver.tick(s, 3.0).empty());
    CHECK(autosaver.tick(s, 4.5) == "autosaved");
    const fs::path mine = recovery_file(folder, dir / "mine.ani");
    REQUIRE(fs::exists(mine));
    CHECK(open_document(env.plugins, mine).document.settings().gravity == 6.0);
    CHECK(open_document(env.plugins, dir / "mine.ani").document.settings().gravity == 5.0);
}
