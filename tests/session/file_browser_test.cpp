// The file browser's model (editor/file_browser.hpp) against a folder made here: what it lists
// and in which order, the keys' selection, going in and up, what typing a name or a path does,
// and a folder it cannot read (said, never a crash).
#include "editor/file_browser.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

using namespace animator;
using namespace animator::test;

namespace fs = std::filesystem;

namespace {

std::vector<std::string> names(const FileBrowser &b) {
    std::vector<std::string> out;
    for (const BrowserEntry &e : b.entries()) out.push_back(e.folder ? e.name + "/" : e.name);
    return out;
}

// A folder of scenes, animations, meshes and clutter, by hand, so the expected listing is known.
fs::path make_tree(const std::string &name) {
    const fs::path dir = fresh_dir(name);
    for (const char *f : {"walk.ani", "Ball.ani", "ball2.ani", "scene.lua", "notes.txt", "model.obj", ".hidden.ani",
                          "UPPER.ANI"})
        write_file(dir / f, "x\n");
    fs::create_directories(dir / "shots");
    fs::create_directories(dir / "Animations");
    fs::create_directories(dir / ".cache");
    write_file(dir / "shots" / "take1.ani", "x\n");
    return dir;
}

} // namespace

TEST_CASE("the browser lists folders first, then the files the filter lets through, sorted, hidden ones left out",
          "[file_browser]") {
    const fs::path dir = make_tree("browser_listing");
    FileBrowser b;
    b.start(FileBrowser::Purpose::Open, dir, {".ani", ".lua"});
    CHECK(b.folder() == dir);
    CHECK(b.error().empty());
    CHECK(names(b) == std::vector<std::string>{"Animations/", "shots/", "Ball.ani", "ball2.ani", "scene.lua",
                                               "UPPER.ANI", "walk.ani"});
    CHECK(b.filter_text() == "*.ani *.lua");
    CHECK(b.selected() == -1);

    // Another filter (the meshes to add, later): the same folders, other files.
    b.start(FileBrowser::Purpose::Open, dir, {".obj"});
    CHECK(names(b) == std::vector<std::string>{"Animations/", "shots/", "model.obj"});
}

TEST_CASE("Up and Down move the selection within the list, a file selected fills the name field", "[file_browser]") {
    const fs::path dir = make_tree("browser_keys");
    FileBrowser b;
    b.start(FileBrowser::Purpose::Open, dir, {".ani", ".lua"});
    b.move(1); // from nothing, Down starts at the top
    CHECK(b.selected() == 0);
    CHECK(b.name().empty()); // a folder leaves the name as it was
    b.move(1);
    b.move(1);
    CHECK(b.selected() == 2);
    CHECK(b.name() == "Ball.ani");
    for (int i = 0; i < 20; ++i) b.move(1);
    CHECK(b.selected() == 6); // stops at the end
    CHECK(b.name() == "walk.ani");
    for (int i = 0; i < 20; ++i) b.move(-1);
    CHECK(b.selected() == 0);
    b.select(-1);
    b.move(-1); // from nothing, Up starts at the bottom
    CHECK(b.selected() == 6);
    // Typing in the name field: Enter takes what is typed, not the selection.
    b.set_name("scene.lua");
    CHECK(b.selected() == -1);
}

TEST_CASE("Enter opens a folder or chooses a file, going up selects the folder left", "[file_browser]") {
    const fs::path dir = make_tree("browser_enter");
    FileBrowser b;
    b.start(FileBrowser::Purpose::Open, dir, {".ani", ".lua"});
    b.select(1); // shots/
    CHECK_FALSE(b.enter());
    CHECK(b.folder() == dir / "shots");
    CHECK(names(b) == std::vector<std::string>{"take1.ani"});
    b.move(1);
    const auto chosen = b.enter();
    REQUIRE(chosen);
    CHECK(*chosen == dir / "shots" / "take1.ani");

    REQUIRE(b.go_up());
    CHECK(b.folder() == dir);
    REQUIRE(b.selected() == 1);
    CHECK(b.entries()[1].name == "shots");
    // Up to the root and no further.
    while (b.go_up()) {
    }
    CHECK(b.folder() == fs::path("/"));
    CHECK(b.error().empty());
}

TEST_CASE("a name or a path typed opens a folder, or chooses a file that exists (Open)", "[file_browser]") {
    const fs::path dir = make_tree("browser_typed_open");
    FileBrowser b;
    b.start(FileBrowser::Purpose::Open, dir, {".ani", ".lua"});
    auto chosen = b.choose_typed("walk.ani");
    REQUIRE(chosen);
    CHECK(*chosen == dir / "walk.ani");
    chosen = b.choose_typed((dir / "shots" / "take1.ani").string()); // absolute
    REQUIRE(chosen);
    CHECK(*chosen == dir / "shots" / "take1.ani");
    CHECK_FALSE(b.choose_typed("shots")); // a folder: gone into
    CHECK(b.folder() == dir / "shots");
    CHECK_FALSE(b.choose_typed("../nothing.ani"));
    CHECK(b.error() == "no file " + (dir / "nothing.ani").string());
    CHECK(b.folder() == dir / "shots"); // nothing moved
    chosen = b.choose_typed("../scene.lua");
    REQUIRE(chosen);
    CHECK(*chosen == dir / "scene.lua");
    CHECK_FALSE(b.choose_typed(""));
    CHECK_FALSE(b.error().empty());

    // "~" is the home folder, as in a shell.
    const char *home = std::getenv("HOME");
    if (home && fs::is_directory(home)) {
        CHECK(b.go_to_typed("~"));
        CHECK(fs::equivalent(b.folder(), home));
    }
}

TEST_CASE("Save: a name typed gets .ani when it has none, and may be a file that does not exist yet", "[file_browser]") {
    const fs::path dir = make_tree("browser_typed_save");
    FileBrowser b;
    b.start(FileBrowser::Purpose::Save, dir, {".ani"}, "untitled.ani");
    CHECK(b.name() == "untitled.ani");
    b.set_name("bounce");
    auto chosen = b.enter();
    REQUIRE(chosen);
    CHECK(*chosen == dir / "bounce.ani");
    chosen = b.choose_typed("shots/Take2.ANI"); // its own extension, in any case, stays
    REQUIRE(chosen);
    CHECK(*chosen == dir / "shots" / "Take2.ANI");
    chosen = b.choose_typed("walk.ani"); // an existing file is the caller's to ask about
    REQUIRE(chosen);
    CHECK(*chosen == dir / "walk.ani");
    CHECK_FALSE(b.choose_typed("nowhere/x"));
    CHECK(b.error() == "no folder " + (dir / "nowhere").string() + " to save in");
    CHECK(with_extension("a.lua", ".ani") == fs::path("a.lua.ani"));
    CHECK(with_extension("a.Ani", ".ani") == fs::path("a.Ani"));
}

TEST_CASE("a folder that cannot be read is said in the browser, which keeps what it showed", "[file_browser]") {
    const fs::path dir = make_tree("browser_unreadable");
    fs::create_directories(dir / "locked");
    write_file(dir / "locked" / "secret.ani", "x\n");
    ::chmod((dir / "locked").c_str(), 0);
    FileBrowser b;
    b.start(FileBrowser::Purpose::Open, dir, {".ani"});
    const auto before = names(b);
    const bool readable = ::access((dir / "locked").c_str(), R_OK) == 0; // root reads anything
    const bool went = b.go_to("locked");
    if (!readable) {
        CHECK_FALSE(went);
        CHECK(b.error().find("cannot read the folder " + (dir / "locked").string()) == 0);
        CHECK(b.folder() == dir);
        CHECK(names(b) == before);
    } else {
        CHECK(went);
    }
    const fs::path here = b.folder();
    CHECK_FALSE(b.go_to("no-such-folder"));
    CHECK(b.error() == "no folder " + (here / "no-such-folder").string());
    CHECK(b.folder() == here);
    ::chmod((dir / "locked").c_str(), 0755);

    // Starting in a folder that is gone: said, an empty list, no crash.
    b.start(FileBrowser::Purpose::Open, dir / "gone", {".ani"});
    CHECK(b.entries().empty());
    CHECK_FALSE(b.error().empty());
}
