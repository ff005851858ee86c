// The editor's View settings (editor/view_settings.hpp): kept across runs in one small file, the
// defaults for a missing file, a line it does not understand reported with its file and line and
// otherwise ignored.
#include "editor/view_settings.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <fstream>
#include <sstream>

using namespace animator;

namespace fs = std::filesystem;

TEST_CASE("the View settings are kept across runs, one line each") {
    const fs::path dir = test::fresh_dir("view_settings");
    const fs::path file = dir / "state" / "view";
    SECTION("a missing file gives the defaults: 4x anti-aliasing, shadows and reflections on") {
        std::string warning;
        const ViewSettings s = load_view_settings(file, &warning);
        CHECK(s.msaa == 4);
        CHECK(s.shadows);
        CHECK(s.reflections);
        CHECK(s.resolution == 100);
        CHECK(warning.empty());
    }
    SECTION("what is saved is read back, the folder made") {
        ViewSettings s;
        s.msaa = 2;
        s.shadows = false;
        s.reflections = false;
        s.resolution = 75;
        std::string error;
        REQUIRE(save_view_settings(file, s, &error));
        const ViewSettings back = load_view_settings(file);
        CHECK(back.resolution == 75);
        CHECK(back.msaa == 2);
        CHECK_FALSE(back.shadows);
        CHECK_FALSE(back.reflections);
        s.reflections = true;
        REQUIRE(save_view_settings(file, s, &error));
        CHECK(load_view_settings(file).reflections);
    }
    SECTION("a line it does not understand is named, with its file and line, and ignored") {
        fs::create_directories(file.parent_path());
        std::ofstream(file) << "msaa 8\nreflections 2\nshadows 0\n";
        std::string warning;
        const ViewSettings s = load_view_settings(file, &warning);
        CHECK(s.msaa == 8);
        CHECK_FALSE(s.shadows);
        CHECK(s.reflections); // the default: 2 is not 0 or 1
        CHECK(warning.find(file.string() + ":2:") != std::string::npos);
        CHECK(warning.find("reflections 0 or 1") != std::string::npos);
    }
    SECTION("a write that fails midway leaves the file before whole, and says why") {
        ViewSettings s;
        s.msaa = 2;
        REQUIRE(save_view_settings(file, s));
        // The temporary file it writes first cannot be made (a folder has its name).
        fs::create_directories(file.parent_path() / ("view.tmp-" + std::to_string(::getpid())));
        s.msaa = 8;
        std::string error;
        CHECK_FALSE(save_view_settings(file, s, &error));
        CHECK(error.find("cannot write the View settings " + file.string() + ": ") == 0);
        CHECK(load_view_settings(file).msaa == 2);
        std::ifstream in(file);
        std::stringstream text;
        text << in.rdbuf();
        CHECK(text.str() == "msaa 2\nshadows 1\nreflections 1\nresolution 100\n");
    }
    SECTION("a resolution the View menu does not offer is named and ignored") {
        fs::create_directories(file.parent_path());
        std::ofstream(file) << "resolution 50\nresolution 60\n";
        std::string warning;
        const ViewSettings s = load_view_settings(file, &warning);
        CHECK(s.resolution == 50);
        CHECK(warning.find(file.string() + ":2:") != std::string::npos);
        CHECK(warning.find("resolution 100, 75 or 50") != std::string::npos);
    }
}
