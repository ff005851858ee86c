// `animator render` as a user runs it, with no display: every example animation and scene
// becomes numbered PNG frames of the asked size.
#include "assets/image.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace animator;
namespace fs = std::filesystem;

namespace {
// No DISPLAY and no WAYLAND_DISPLAY: the off-screen context must not need one.
const std::string kNoDisplay = "env -u DISPLAY -u WAYLAND_DISPLAY";

int count_frames(const fs::path &dir) {
    int n = 0;
    for (const auto &entry : fs::directory_iterator(dir)) n += entry.path().extension() == ".png";
    return n;
}
} // namespace

TEST_CASE("animator render writes every example's frames as PNG files of the asked size") {
    int examples = 0;
    for (const char *folder : {"assets/animations", "assets/scenes"}) {
        for (const auto &entry : fs::directory_iterator(test::source_dir() / folder)) {
            const fs::path file = entry.path();
            if (file.extension() != ".ani" && file.extension() != ".lua") continue;
            CAPTURE(file.string());
            ++examples;
            const fs::path out = test::fresh_dir("render_" + file.stem().string());
            // 0.1 s to 0.3 s at 10 fps: three frames.
            const auto r = test::run_animator("render " + file.string() + " --out " + out.string() +
                                                  " --from 0.1 --to 0.3 --fps 10 --size 64x48",
                                              kNoDisplay);
            INFO(r.out);
            REQUIRE(r.exit_code == 0);
            CHECK_THAT(r.out, Catch::Contains("wrote 3 frames of 64x48"));
            CHECK(count_frames(out) == 3);
            for (int k = 0; k < 3; ++k) {
                char name[32];
                std::snprintf(name, sizeof name, "frame_%05d.png", k);
                const Image image = load_image(out / name);
                CHECK(image.width == 64);
                CHECK(image.height == 48);
                // Not a blank frame: more than one colour.
                bool varied = false;
                for (size_t i = 3; i < image.rgb.size() && !varied; ++i)
                    varied = image.rgb[i] != image.rgb[i % 3];
                CHECK(varied);
            }
        }
    }
    CHECK(examples >= 6);
}

TEST_CASE("animator render takes shading parameters and reports bad input") {
    const std::string drop = (test::source_dir() / "assets/animations/drop.ani").string();
    const fs::path out = test::fresh_dir("render_options");

    auto cel =
        test::run_animator("render " + drop + " --out " + (out / "cel").string() +
                               " --to 0 --size 32x24 --param cel_bands=4 --param cel_outline=1",
                           kNoDisplay);
    CHECK(cel.exit_code == 0);
    CHECK(count_frames(out / "cel") == 1);

    auto bogus = test::run_animator(
        "render " + drop + " --out " + out.string() + " --to 0 --param bogus=1", kNoDisplay);
    CHECK(bogus.exit_code == 1);
    CHECK_THAT(bogus.out, Catch::Contains("bogus"));

    auto shading = test::run_animator(
        "render " + drop + " --out " + out.string() + " --to 0 --shading shading.nope", kNoDisplay);
    CHECK(shading.exit_code == 1);
    CHECK_THAT(shading.out, Catch::Contains("no shading plugin 'shading.nope'"));

    auto late =
        test::run_animator("render " + drop + " --out " + out.string() + " --to 11", kNoDisplay);
    CHECK(late.exit_code == 1);
    CHECK_THAT(late.out, Catch::Contains("drop.ani"));

    CHECK(test::run_animator("render " + drop + " --out " + out.string() + " --size 0x10")
              .exit_code == 2);
    CHECK(
        test::run_animator("render " + drop + " --out " + out.string() + " --size 640").exit_code ==
        2);
    CHECK(test::run_animator("render " + drop).exit_code == 2); // no --out
    auto help = test::run_animator("render --help");
    CHECK(help.exit_code == 0);
    CHECK_THAT(help.out,
               Catch::Contains("--out") && Catch::Contains("--size") && Catch::Contains("--fps"));
}
