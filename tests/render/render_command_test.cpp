// `animator render` as a user runs it, with no display: every example animation and scene
// becomes numbered PNG frames of the asked size.
#include "assets/image.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <glm/vec3.hpp>

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

TEST_CASE("animator render draws a mesh that is not found as a plain magenta stand-in cube") {
    // A scene from the course naming a mesh its author did not publish, in green, straight ahead
    // of the camera; beside it a real cube in green. The stand-in is the course's unit cube,
    // plain magenta whatever its material; the real cube keeps its colour.
    const fs::path dir = test::fresh_dir("render_stand_in");
    test::write_file(dir / "face.lua",
                     "gr.camera{eye = {0, 0, 8}, look_at = {0, 0, 0}, up = {0, 1, 0}, fov = 50}\n"
                     "local root = gr.node('root')\n"
                     "local green = gr.material({0.1, 0.8, 0.1}, {0, 0, 0}, 10)\n"
                     "local face = gr.mesh('luffy-face', 'face')\n"
                     "face:translate(-1.5, 0, 0)\n"
                     "face:set_material(green)\n"
                     "root:add_child(face)\n"
                     "local cube = gr.mesh('cube', 'cube')\n"
                     "cube:translate(1.5, 0, 0)\n"
                     "cube:set_material(green)\n"
                     "root:add_child(cube)\n"
                     "return root\n");
    const auto r = test::run_animator("render " + (dir / "face.lua").string() + " --out " + (dir / "out").string() +
                                          " --to 0 --size 160x120",
                                      kNoDisplay);
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("face.lua:4: mesh 'luffy-face' not found ("));
    CHECK(test::count_in(r.out, "not found") == 1); // said once, with its line
    const Image image = load_image(dir / "out" / "frame_00000.png");
    auto at = [&](int x, int y) {
        const size_t i = 3 * (static_cast<size_t>(y) * static_cast<size_t>(image.width) + static_cast<size_t>(x));
        return glm::ivec3(image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]);
    };
    // The stand-in's centre, about 40 px left of the image's, and the cube's, 40 px right.
    const glm::ivec3 stand_in = at(80 - 40, 60), cube = at(80 + 40, 60);
    CAPTURE(stand_in.r, stand_in.g, stand_in.b, cube.r, cube.g, cube.b);
    CHECK(stand_in.r > 3 * stand_in.g + 20);
    CHECK(stand_in.b > 3 * stand_in.g + 20);
    CHECK(cube.g > 2 * cube.r + 20);
}
