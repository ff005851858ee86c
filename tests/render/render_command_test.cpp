// `animator render` as a user runs it, with no display: every example animation and scene
// becomes numbered PNG frames of the asked size.
#include "assets/image.hpp"
#include "image_compare.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
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
    for (const char *samples : {"3", "16", "0", "four"}) {
        CAPTURE(samples);
        auto msaa = test::run_animator("render " + drop + " --out " + out.string() +
                                       " --to 0 --msaa " + samples);
        CHECK(msaa.exit_code == 2);
        CHECK_THAT(msaa.out, Catch::Contains("--msaa takes the samples per pixel, 1, 2, 4 or 8"));
    }
    // --no-shadows: the same frame without the ball's shadow on the floor, so other pixels (at
    // 0.88 s the ball, dropped from 4 m above the floor, is about to land: its shadow, cast by the
    // camera's light, is just behind it).
    auto shadowless =
        test::run_animator("render " + drop + " --out " + (out / "shadowless").string() +
                               " --from 0.88 --to 0.88 --size 64x48 --no-shadows",
                           kNoDisplay);
    CHECK(shadowless.exit_code == 0);
    auto shadowed = test::run_animator("render " + drop + " --out " + (out / "shadowed").string() +
                                           " --from 0.88 --to 0.88 --size 64x48",
                                       kNoDisplay);
    CHECK(shadowed.exit_code == 0);
    const Image with = load_image(out / "shadowed" / "frame_00000.png");
    const Image without = load_image(out / "shadowless" / "frame_00000.png");
    CHECK(test::compare_images(with, without).max > 20.0);
    // More samples than the OpenGL gives (llvmpipe: 4) draws with fewer, saying so, not a failure.
    auto eight = test::run_animator(
        "render " + drop + " --out " + (out / "eight").string() + " --to 0 --msaa 8", kNoDisplay);
    CHECK(eight.exit_code == 0);
    CHECK(count_frames(out / "eight") == 1);
    auto help = test::run_animator("render --help");
    CHECK(help.exit_code == 0);
    CHECK_THAT(help.out,
               Catch::Contains("--out") && Catch::Contains("--size") && Catch::Contains("--fps"));
}

TEST_CASE("animator render --compression writes the same pixels at every zlib level, smaller at "
          "higher ones") {
    const std::string drop = (test::source_dir() / "assets/animations/drop.ani").string();
    const fs::path out = test::fresh_dir("render_compression");
    std::map<int, std::uintmax_t> bytes;
    for (const int level : {1, 3, 9}) {
        const fs::path dir = out / std::to_string(level);
        const auto r = test::run_animator("render " + drop + " --out " + dir.string() +
                                              " --from 0.88 --to 0.88 --size 320x240 --compression " +
                                              std::to_string(level),
                                          kNoDisplay);
        REQUIRE(r.exit_code == 0);
        bytes[level] = fs::file_size(dir / "frame_00000.png");
    }
    // Read back by stb's decoder (not the encoder's library): the same image at each level.
    const Image fastest = load_image(out / "1" / "frame_00000.png");
    CHECK(fastest.width == 320);
    CHECK(fastest.height == 240);
    for (const int level : {3, 9}) {
        CAPTURE(level);
        CHECK(test::compare_images(load_image(out / std::to_string(level) / "frame_00000.png"), fastest)
                  .max == 0.0);
    }
    CHECK(bytes[9] < bytes[1]);
    for (const char *level : {"0", "10"}) {
        CAPTURE(level);
        CHECK(test::run_animator("render " + drop + " --out " + out.string() + " --to 0 --compression " +
                                 level)
                  .exit_code == 2);
    }
}

TEST_CASE("animator render --detail 0 draws every mesh whole, the picture the levels of detail keep") {
    const std::string gas = (test::source_dir() / "assets/animations/gas.ani").string();
    const fs::path out = test::fresh_dir("render_detail");
    for (const char *detail : {"0", "0.5"})
        REQUIRE(test::run_animator("render " + gas + " --out " + (out / detail).string() +
                                       " --to 0 --size 320x180 --msaa 1 --detail " + detail,
                                   kNoDisplay)
                    .exit_code == 0);
    const Image whole = load_image(out / "0" / "frame_00000.png");
    const Image levels = load_image(out / "0.5" / "frame_00000.png");
    // The 125 balls are drawn with fewer triangles (some pixels change), the picture the same
    // as the golden images judge it.
    const test::ImageDifference d = test::compare_images(levels, whole, 48.0);
    CHECK(d.max > 0.0);
    CHECK(d.over < 0.005);
    CHECK(d.mean < 1.0);
    auto negative = test::run_animator("render " + gas + " --out " + out.string() + " --to 0 --detail -1");
    CHECK(negative.exit_code == 2);
    CHECK_THAT(negative.out, Catch::Contains("--detail"));
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

TEST_CASE("animator render without --out writes the document's own still at its own size, lit by "
          "its lights") {
    // A course scene's gr.render, as saved in an .ani: the still "out.png" at 64x48 (relative to
    // the document's folder), one red light over a grey floor and no ambient light.
    const fs::path dir = test::fresh_dir("render_own_output");
    test::write_file(
        dir / "lit.ani",
        "animator-ani 2\n"
        "settings\n"
        "  max_time_ms 2000\n"
        "  ambient 0 0 0\n"
        "  light \"red\" position 0 1.5 0 colour 1 0 0 falloff 1 0 0.1\n"
        "  render \"stills/out.png\" 64 48\n"
        "end\n"
        "model \"floor\"\n"
        "  mesh \"plane\"\n"
        "  kd 0.8 0.8 0.8\n"
        "  ks 0 0 0\n"
        "  shininess 128\n"
        "end\n"
        "keyframe 0\n"
        "  camera position 0 4 0 rotation 0.7071067811865476 -0.7071067811865476 0 0 fov 60\n"
        "  state \"floor\" center 0 0 0 angles 0 0 0 scale 10 1 10 turn 0 0 0\n"
        "end\n");
    const std::string file = (dir / "lit.ani").string();
    const auto r = test::run_animator("render " + file, kNoDisplay);
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out,
               Catch::Contains("wrote " + (dir / "stills" / "out.png").string() + " (64x48"));
    const Image still = load_image(dir / "stills" / "out.png");
    CHECK(still.width == 64);
    CHECK(still.height == 48);
    // Straight under the light, 1.5 away: 0.8 / (1 + 0.1 * 1.5^2) of red = 0.653 (167 of 255),
    // and no green or blue at all: the camera's white light is not there.
    const size_t centre = 3 * (24 * 64 + 32);
    CAPTURE(int(still.rgb[centre]), int(still.rgb[centre + 1]), int(still.rgb[centre + 2]));
    CHECK(std::abs(int(still.rgb[centre]) - 167) <= 3);
    CHECK(still.rgb[centre + 1] == 0);
    CHECK(still.rgb[centre + 2] == 0);

    // Frames into --out take the document's size too, unless --size says otherwise.
    const auto frames = test::run_animator(
        "render " + file + " --out " + (dir / "frames").string() + " --to 0", kNoDisplay);
    CHECK(frames.exit_code == 0);
    CHECK_THAT(frames.out, Catch::Contains("wrote 1 frame of 64x48"));
    const auto sized = test::run_animator("render " + file + " --out " + (dir / "sized").string() +
                                              " --to 0 --size 40x30",
                                          kNoDisplay);
    CHECK(sized.exit_code == 0);
    CHECK(load_image(dir / "sized" / "frame_00000.png").width == 40);
    // And --size applies to the still as well.
    fs::remove(dir / "stills" / "out.png");
    CHECK(test::run_animator("render " + file + " --size 32x20", kNoDisplay).exit_code == 0);
    CHECK(load_image(dir / "stills" / "out.png").height == 20);

    // A still is one frame: --to, --fps and --video need --out.
    CHECK(test::run_animator("render " + file + " --to 1").exit_code == 2);
    CHECK(test::run_animator("render " + file + " --fps 10").exit_code == 2);
    auto help = test::run_animator("render --help");
    CHECK_THAT(help.out, Catch::Contains("gr.render"));
}

namespace {
// Which side of the 2D convex polygon `hull` (counter-clockwise) `p` is on, in pixels: > 0 inside
// by that distance, < 0 outside.
double inside_by(const std::vector<glm::dvec2> &hull, glm::dvec2 p) {
    double least = 1e300;
    for (size_t i = 0; i < hull.size(); ++i) {
        const glm::dvec2 a = hull[i], b = hull[(i + 1) % hull.size()], e = b - a;
        least = std::min(least, (e.x * (p.y - a.y) - e.y * (p.x - a.x)) / glm::length(e));
    }
    return least;
}

// The convex hull (Andrew's monotone chain, counter-clockwise) of points in the plane.
std::vector<glm::dvec2> convex_hull(std::vector<glm::dvec2> p) {
    std::sort(p.begin(), p.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    auto cross = [](glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::dvec2> h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);
    return h;
}
} // namespace

TEST_CASE("animator render draws a course puppet's sheared part as its author saw it") {
    // A joint turned, then scaled unevenly (CS488: M = call M, so its matrix is S R: a shear), and
    // a cube under it, moved along the joint's sheared x. The truth is the course's matrices,
    // multiplied here with glm, and the camera's projection from the scene's own gr.camera: the
    // cube's eight corners projected, their hull filled. Pixels well inside it must be the cube,
    // pixels well outside it background, among them those that the cube would cover were the
    // shear dropped (T R S alone).
    const fs::path dir = test::fresh_dir("render_sheared");
    test::write_file(dir / "sheared.lua", "gr.camera{eye = {0, 0, 9}, look_at = {0, 0, 0}, up = {0, 1, 0}, fov = 50}\n"
                                          "local root = gr.node('root')\n"
                                          "local joint = gr.joint('joint', {-90, 0, 90}, {-90, 0, 90})\n"
                                          "joint:rotate('z', 40)\n"
                                          "joint:scale(2.2, 0.6, 1)\n"
                                          "root:add_child(joint)\n"
                                          "local box = gr.mesh('cube', 'box')\n"
                                          "box:translate(0.4, 0, 0)\n"
                                          "box:set_material(gr.material({0.1, 0.9, 0.1}, {0, 0, 0}, 10))\n"
                                          "joint:add_child(box)\n"
                                          "return root\n");
    const int width = 200, height = 150;
    const auto r = test::run_animator("render " + (dir / "sheared.lua").string() + " --out " +
                                          (dir / "frames").string() + " --to 0 --size 200x150",
                                      kNoDisplay);
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    const Image image = load_image(dir / "frames" / "frame_00000.png");
    REQUIRE(image.width == width);

    const glm::dmat4 I(1.0);
    const glm::dmat4 joint = glm::scale(I, {2.2, 0.6, 1.0}) * glm::rotate(I, glm::radians(40.0), {0, 0, 1});
    const glm::dmat4 sheared = joint * glm::translate(I, {0.4, 0, 0});
    // The same parts with the shear dropped: turned, then scaled along the turned axes.
    const glm::dmat4 dropped =
        glm::rotate(I, glm::radians(40.0), {0, 0, 1}) * glm::scale(I, {2.2, 0.6, 1.0}) * glm::translate(I, {0.4, 0, 0});
    const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 0, 9), glm::dvec3(0), glm::dvec3(0, 1, 0));
    const glm::dmat4 projection = glm::perspective(glm::radians(50.0), double(width) / height, 0.1, 100.0);
    auto outline = [&](const glm::dmat4 &world) {
        std::vector<glm::dvec2> corners;
        for (int i = 0; i < 8; ++i) {
            const glm::dvec4 c = projection * view * world * glm::dvec4(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1, 1);
            corners.push_back({(c.x / c.w + 1.0) / 2.0 * width, (1.0 - c.y / c.w) / 2.0 * height});
        }
        return convex_hull(corners);
    };
    const std::vector<glm::dvec2> truth = outline(sheared), without = outline(dropped);
    auto is_cube = [&](int x, int y) {
        const size_t at = 3 * (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x));
        const int red = image.rgb[at], green = image.rgb[at + 1], blue = image.rgb[at + 2];
        return green > 40 && green > 2 * red && green > 2 * blue;
    };
    int inside = 0, outside = 0, wrong = 0, only_dropped = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::dvec2 p(x + 0.5, y + 0.5);
            const double d = inside_by(truth, p);
            if (std::abs(d) < 2.0) continue; // the edge's pixels: antialiasing and rounding
            const bool cube = is_cube(x, y);
            if (d > 0) ++inside;
            else ++outside;
            if (cube != (d > 0)) ++wrong;
            if (d < 0 && inside_by(without, p) > 2.0) ++only_dropped;
        }
    CAPTURE(inside, outside, wrong, only_dropped);
    CHECK(inside > 1000);
    CHECK(only_dropped > 300); // the shear matters here: dropping it would cover these pixels
    CHECK(wrong == 0);
}

TEST_CASE("golden: a course ray-tracer scene file, rendered as it asks, lit by its own two lights") {
    // tests/data/cs488/a4_frames.lua: every primitive of A4, gr.render's camera, ambient light
    // and two lights (a white key light and a blue rim light), through the Lua reader and
    // `animator render` with no --out (the still gr.render names), at a quarter of its size.
    const fs::path dir = test::fresh_dir("render_a4_golden");
    fs::copy_file(test::source_dir() / "tests/data/cs488/a4_frames.lua", dir / "a4_frames.lua");
    const auto r = test::run_animator("render " + (dir / "a4_frames.lua").string() + " --size 160x100", kNoDisplay);
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    const Image image = load_image(dir / "frame00.png");
    // The golden tests' tolerance (golden_test.cpp): a few edge pixels may flip on another CPU.
    const std::string problem = test::check_golden("a4_frames", image, test::Tolerance{48.0, 0.005, 1.0});
    INFO(problem);
    CHECK(problem.empty());
    // Under the camera's light instead of its own (the lights dropped from the scene), it must
    // not pass for the golden.
    std::string text = test::read_file(dir / "a4_frames.lua");
    const std::string lights = "{key, rim})";
    REQUIRE(text.find(lights) != std::string::npos);
    text.replace(text.find(lights), lights.size(), "{})");
    test::write_file(dir / "unlit.lua", text);
    REQUIRE(test::run_animator("render " + (dir / "unlit.lua").string() + " --size 160x100", kNoDisplay).exit_code == 0);
    const Image unlit = load_image(dir / "frame00.png");
    const Image golden = load_image(test::source_dir() / "tests/render/golden/a4_frames.png");
    const test::ImageDifference d = test::compare_images(unlit, golden, 48.0);
    CAPTURE(d.over, d.mean);
    CHECK((d.over > 0.005 || d.mean > 1.0));
}

TEST_CASE("animator render --frames A-B renders a share of the frames, the same bits as the whole "
          "render's") {
    // drop.ani's ball falls and bounces (physics after its keys): frames 0 to 11 at 10 fps, whole,
    // then as two shares of a render farm, 0-4 and 5-11, each baking only as far as it draws.
    const std::string drop = (test::source_dir() / "assets/animations/drop.ani").string();
    const fs::path whole = test::fresh_dir("render_frames_whole"), shares = test::fresh_dir("render_frames_shares");
    const std::string common = " --to 1.1 --fps 10 --size 64x48";
    auto r = test::run_animator("render " + drop + " --out " + whole.string() + common, kNoDisplay);
    REQUIRE(r.exit_code == 0);
    REQUIRE(count_frames(whole) == 12);
    r = test::run_animator("render " + drop + " --out " + shares.string() + common + " --frames 0-4", kNoDisplay);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("wrote 5 frames of 64x48 to " + shares.string() +
                                      " (frame_00000.png .. frame_00004.png)"));
    r = test::run_animator("render " + drop + " --out " + shares.string() + common + " --frames 5-11", kNoDisplay);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("(frame_00005.png .. frame_00011.png)"));
    REQUIRE(count_frames(shares) == 12);
    for (int k = 0; k < 12; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05d.png", k);
        CAPTURE(k);
        // Decoded pixels, bit for bit (the PNG bytes may differ only if the encoder did).
        CHECK(load_image(whole / name).rgb == load_image(shares / name).rgb);
    }
    // The ball moves between the shares' frames: they are not all one picture.
    CHECK(load_image(whole / "frame_00000.png").rgb != load_image(whole / "frame_00011.png").rgb);
    // Out of the sequence, malformed, or with --video: refused.
    r = test::run_animator("render " + drop + " --out " + shares.string() + common + " --frames 5-12", kNoDisplay);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Contains("--frames 5-12: the frames are 0 to 11"));
    CHECK(test::run_animator("render " + drop + " --out " + shares.string() + " --frames 4-2").exit_code == 2);
    CHECK(test::run_animator("render " + drop + " --out " + shares.string() + " --frames 3").exit_code == 2);
    CHECK(test::run_animator("render " + drop + " --out " + shares.string() + " --frames 0-1 --video x.mp4").exit_code ==
          2);
}

namespace {
// The frame_NNNNN.png files of a folder, name -> bytes.
std::map<std::string, std::string> frame_files(const fs::path &dir) {
    std::map<std::string, std::string> files;
    for (const auto &entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".png") files[entry.path().filename().string()] = test::read_file(entry.path());
    return files;
}
} // namespace

TEST_CASE("animator render --bake draws with a saved bake the same PNG files, bit for bit, whole or in "
          "shares") {
    // drop.ani's ball bounces; tipping_cube.lua's cube tips over its edge (a hinge), lands and
    // slides; tumbling_cube.lua's cube turns freely (torque-free rotation) as it flies and lands.
    for (const char *example : {"assets/animations/drop.ani", "assets/scenes/tipping_cube.lua",
                                "assets/scenes/tumbling_cube.lua"}) {
        const fs::path file = test::source_dir() / example;
        CAPTURE(file.string());
        const fs::path dir = test::fresh_dir("render_bake_" + file.stem().string());
        const std::string bake = (dir / "anim.bake").string();
        auto r = test::run_animator("bake " + file.string() + " --save " + bake);
        INFO(r.out);
        REQUIRE(r.exit_code == 0);
        CHECK_THAT(r.out, Catch::Contains("wrote " + bake + " (the bake of 0 to "));

        const std::string common = " --to 1.1 --fps 10 --size 64x48";
        r = test::run_animator("render " + file.string() + " --out " + (dir / "baked_here").string() + common, kNoDisplay);
        REQUIRE(r.exit_code == 0);
        r = test::run_animator("render " + file.string() + " --out " + (dir / "whole").string() + common + " --bake " + bake,
                               kNoDisplay);
        REQUIRE(r.exit_code == 0);
        for (const char *range : {"0-4", "5-11"}) {
            r = test::run_animator("render " + file.string() + " --out " + (dir / "shares").string() + common + " --frames " +
                                       range + " --bake " + bake,
                                   kNoDisplay);
            REQUIRE(r.exit_code == 0);
        }
        const auto expected = frame_files(dir / "baked_here");
        REQUIRE(expected.size() == 12);
        CHECK(frame_files(dir / "whole") == expected);
        CHECK(frame_files(dir / "shares") == expected);
        // Something moves: the frames are not all one picture.
        CHECK(expected.begin()->second != expected.rbegin()->second);
    }
}

TEST_CASE("animator render --bake refuses a bake that does not fit, saying why, with exit 1") {
    const fs::path dir = test::fresh_dir("render_bake_refused");
    fs::copy_file(test::source_dir() / "assets/animations/drop.ani", dir / "drop.ani");
    const std::string drop = (dir / "drop.ani").string(), bake = (dir / "drop.bake").string();
    REQUIRE(test::run_animator("bake " + drop + " --save " + bake).exit_code == 0);
    const std::string bytes = test::read_file(bake);
    const std::string out = (dir / "frames").string();

    auto refused = [&](const std::string &doc, const std::string &bake_file, const std::string &options,
                       const std::string &message) {
        const auto r = test::run_animator("render " + doc + " --out " + out + " --to 1 --fps 10 --size 32x24 --bake " +
                                              bake_file + options,
                                          kNoDisplay);
        INFO(r.out);
        CHECK(r.exit_code == 1);
        CHECK_THAT(r.out, Catch::Contains("--bake " + bake_file) && Catch::Contains(message));
        CHECK_FALSE(fs::exists(out)); // refused before any frame
    };
    // Another document; another backend; other parameters.
    refused((test::source_dir() / "assets/animations/cradle.ani").string(), bake, "",
            "was baked from another document, or from this one before an edit that changes motion");
    refused(drop, bake, " --backend physics.bullet", "was baked with physics backend 'physics.custom', not 'physics.bullet'");
    refused(drop, bake, " --param broad_phase=2", "was baked with physics.custom's parameter 'broad_phase' = 0, not 2");
    // Another version of the format, truncated, corrupt, not a bake, missing.
    std::string later = bytes;
    later[8] = 9;
    test::write_file(dir / "later.bake", later);
    refused(drop, (dir / "later.bake").string(), "", "format version 9, and this animator reads version 2");
    test::write_file(dir / "short.bake", bytes.substr(0, bytes.size() / 2));
    refused(drop, (dir / "short.bake").string(), "", "is truncated");
    std::string flipped = bytes;
    flipped[bytes.size() - 20] = static_cast<char>(flipped[bytes.size() - 20] ^ 1);
    test::write_file(dir / "flipped.bake", flipped);
    refused(drop, (dir / "flipped.bake").string(), "", "is corrupt: its checksum does not match its contents");
    refused(drop, drop, "", "not a bake file");
    refused(drop, (dir / "none.bake").string(), "", "cannot be read (No such file or directory)");
    // A bake that ends before the frames do; a share within it is drawn.
    REQUIRE(test::run_animator("bake " + drop + " --until 0.5 --save " + (dir / "half.bake").string()).exit_code == 0);
    refused(drop, (dir / "half.bake").string(), "", "holds a bake to 0.5 s, and 1 s is needed");
    auto share = test::run_animator("render " + drop + " --out " + out + " --to 1 --fps 10 --size 32x24 --frames 0-5 --bake " +
                                        (dir / "half.bake").string(),
                                    kNoDisplay);
    CHECK(share.exit_code == 0);
    fs::remove_all(out);

    // The document edited: a key moved is refused; a colour changed moves nothing and is not.
    std::string text = test::read_file(dir / "drop.ani");
    const std::string key = "state \"ball\" center 0 5 0", colour = "kd 0.9 0.2 0.1";
    REQUIRE(text.find(key) != std::string::npos);
    REQUIRE(text.find(colour) != std::string::npos);
    test::write_file(dir / "drop.ani", std::string(text).replace(text.find(key), key.size(), "state \"ball\" center 0 4 0"));
    refused(drop, bake, "", "the models' keyframes differ");
    test::write_file(dir / "drop.ani", std::string(text).replace(text.find(colour), colour.size(), "kd 0.1 0.2 0.9"));
    const auto recoloured =
        test::run_animator("render " + drop + " --out " + out + " --to 1 --fps 10 --size 32x24 --bake " + bake, kNoDisplay);
    CHECK(recoloured.exit_code == 0);
    // A mesh file beside the document, changed after the bake (one vertex moved).
    fs::copy_file(test::bin_dir().parent_path() / "assets/meshes/sphere.obj", dir / "ball.obj");
    test::write_file(dir / "drop.ani", std::string(text).replace(text.find("mesh \"sphere\""), 13, "mesh \"ball.obj\""));
    REQUIRE(test::run_animator("bake " + drop + " --save " + bake).exit_code == 0);
    REQUIRE(test::run_animator("render " + drop + " --out " + out + " --to 0 --size 32x24 --bake " + bake, kNoDisplay)
                .exit_code == 0);
    std::string mesh = test::read_file(dir / "ball.obj");
    const auto v = mesh.find("\nv ") + 1, end = mesh.find('\n', v);
    REQUIRE((v > 0 && end != std::string::npos));
    test::write_file(dir / "ball.obj", mesh.replace(v, end - v, "v 0 0 0.9"));
    fs::remove_all(out);
    refused(drop, bake, "", "was baked with another mesh for model 'ball'");
}
