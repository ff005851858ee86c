// The skybox pass (Renderer::draw_skybox): sampled at one level chosen for the view's
// resolution (not each pixel's own), and covering every pixel no model does, so the view's
// colour is not cleared before it is drawn.
#include "image_compare.hpp"
#include "render_support.hpp"
#include "support.hpp"

#include "render/framebuffer.hpp"

#include <catch2/catch.hpp>
#include <glad/gl.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace animator;
using namespace animator::test;

namespace {

// A skybox whose six faces are a checker of black and white texels, `side` texels a side: any
// mipmap level but the first is an even grey (127.5), and level 0 sampled between texel
// centres at uneven steps is anything from black to white.
std::filesystem::path checker_sky(int side) {
    const auto root = fresh_dir("checker_sky_" + std::to_string(side));
    const auto folder = root / "skyboxes" / "checker";
    std::filesystem::create_directories(folder);
    Image face;
    face.width = face.height = side;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            for (int c = 0; c < 3; ++c) face.rgb.push_back((x + y) % 2 ? 255 : 0);
    for (const char *name : {"right", "left", "top", "bottom", "front", "back"})
        write_png(folder / (std::string(name) + ".png"), face);
    return root;
}

// Draws the first frame of `doc` with `assets` into `framebuffer`, and reads it back.
Image draw_with(const AssetPaths &assets, const Document &doc, OffscreenFramebuffer &framebuffer,
                RenderOptions options = {}) {
    Renderer renderer(environment().plugins, assets, std::move(options), nullptr);
    renderer.set_document(doc, meshes_of(doc));
    renderer.draw(first_frame(doc), framebuffer.target(), {}, {});
    Image image;
    image.width = framebuffer.width();
    image.height = framebuffer.height();
    framebuffer.read_rgb(image.rgb);
    return image;
}

} // namespace

TEST_CASE("the skybox is sampled at the mipmap level its pixels ask for") {
    gl_context();
    const AssetPaths assets({checker_sky(64)});
    // Looking straight at a face with a 90-degree view: 64 texels over 20 pixels, 3.2 a pixel,
    // level log2(3.2) = 1.7 everywhere (over 28: 1.2), where every level is grey. Level 0 would
    // alias.
    const Document doc =
        make_document(make_camera(glm::dvec3(0.0), 0.0, 0.0, 90.0), false, "checker");
    for (int side : {20, 28}) {
        OffscreenFramebuffer framebuffer(side, side);
        const Image image = draw_with(assets, doc, framebuffer);
        int worst = 0;
        for (std::size_t i = 0; i < image.rgb.size(); ++i)
            worst = std::max(worst, static_cast<int>(std::lround(std::abs(image.rgb[i] - 127.5))));
        CAPTURE(side);
        CHECK(worst <= 3);
    }
    // Magnified (20 pixels over 4 texels a face), the sky is its texels, black and white, still.
    const AssetPaths coarse({checker_sky(4)});
    OffscreenFramebuffer framebuffer(20, 20);
    const Image image = draw_with(coarse, doc, framebuffer);
    // (Pixels 2 and 7 are at the centres of two neighbouring texels.)
    CHECK(std::abs(pixel(image, 2, 2).r - pixel(image, 7, 2).r) > 215);
}

TEST_CASE("a frame with a skybox leaves nothing of what its framebuffer held") {
    gl_context();
    Document doc = make_document(make_camera(glm::dvec3(0.0, 1.0, 6.0)), false, "day");
    doc.add_model(make_model("ball", "sphere", {0.8, 0.2, 0.2}), make_state({0.0, 1.0, 0.0}));
    for (int samples : {1, 4}) {
        OffscreenFramebuffer framebuffer(96, 64, samples);
        // What a previous frame or another view left: magenta everywhere.
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.target().framebuffer);
        glClearColor(1.0f, 0.0f, 1.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        const Image image = draw_with(environment().assets, doc, framebuffer);
        int magenta = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const glm::ivec3 p = pixel(image, x, y);
                if (p.r > 200 && p.g < 60 && p.b > 200) ++magenta;
            }
        CAPTURE(samples);
        CHECK(magenta == 0);
        // The ball is there, in the middle (the sky is not drawn over it).
        const glm::ivec3 middle = pixel(image, 48, 32);
        CHECK(middle.r > middle.g + 40);
    }
}
