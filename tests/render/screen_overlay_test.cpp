// The screen overlay the editor draws the transform gizmo with (render/screen_overlay.hpp),
// golden-free: a 3 px line and a filled square in the view's pixels (y down) land on exactly
// those pixels of the framebuffer, in their colours, over whatever was drawn, and nowhere else.
#include "render/framebuffer.hpp"
#include "render/screen_overlay.hpp"
#include "render_support.hpp"

#include <catch2/catch.hpp>

#include <glad/gl.h>

#include <cstdint>
#include <vector>

using namespace animator;
using namespace animator::test;

TEST_CASE("the screen overlay draws lines and squares on the pixels it is given, y down") {
    constexpr int kWidth = 200, kHeight = 150;
    gl_context();
    OffscreenFramebuffer framebuffer(kWidth, kHeight);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.target().framebuffer);
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glClearDepth(0.0); // a depth buffer that would hide everything: the overlay is on top anyway
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glClearDepth(1.0);

    const glm::vec3 red(1.0f, 0.0f, 0.0f), blue(0.0f, 0.0f, 1.0f);
    OverlayTriangles t;
    t.line({20.0f, 30.0f}, {180.0f, 30.0f}, 3.0f, red); // rows 28.5 .. 31.5: rows 29, 30, 31
    t.convex({{100.0f, 80.0f}, {120.0f, 80.0f}, {120.0f, 100.0f}, {100.0f, 100.0f}}, blue);
    ScreenOverlay overlay;
    overlay.draw(t, static_cast<float>(kWidth), static_cast<float>(kHeight));

    std::vector<std::uint8_t> rgb;
    framebuffer.read_rgb(rgb);
    auto at = [&](int x, int y) {
        const size_t i = 3 * (static_cast<size_t>(y) * kWidth + static_cast<size_t>(x));
        return glm::ivec3(rgb[i], rgb[i + 1], rgb[i + 2]);
    };
    for (int x = 22; x < 178; x += 7) {
        INFO("column " << x);
        for (int y = 29; y <= 31; ++y) CHECK(at(x, y) == glm::ivec3(255, 0, 0));
        CHECK(at(x, 26) == glm::ivec3(0, 0, 0));
        CHECK(at(x, 34) == glm::ivec3(0, 0, 0));
    }
    CHECK(at(10, 30) == glm::ivec3(0, 0, 0)); // before the line's start (less its half width)
    for (int y = 81; y < 99; y += 3)
        for (int x = 101; x < 119; x += 3) CHECK(at(x, y) == glm::ivec3(0, 0, 255));
    CHECK(at(98, 90) == glm::ivec3(0, 0, 0));
    CHECK(at(110, 102) == glm::ivec3(0, 0, 0));
    // Upside down (GL's rows go up) the square would be at rows 50..70.
    CHECK(at(110, 60) == glm::ivec3(0, 0, 0));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}
