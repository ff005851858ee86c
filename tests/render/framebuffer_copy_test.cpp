// How the editor puts an off-screen view on the window (OffscreenFramebuffer::copy_to): at its
// own size pixel for pixel, and stretched (the view drawn at a lower resolution, View >
// Resolution) with linear filtering, multisampled or not, into the target's viewport only.
#include "render/framebuffer.hpp"
#include "render_support.hpp"

#include <catch2/catch.hpp>

#include <glad/gl.h>

#include <cstdint>
#include <vector>

using namespace animator;
using namespace animator::test;

namespace {

// The left half of `from` red, the right half blue.
void halves(const OffscreenFramebuffer &from) {
    glBindFramebuffer(GL_FRAMEBUFFER, from.target().framebuffer);
    glViewport(0, 0, from.width(), from.height());
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, from.width() / 2, from.height());
    glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(from.width() / 2, 0, from.width() - from.width() / 2, from.height());
    glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

} // namespace

TEST_CASE("an off-screen view is copied pixel for pixel at its size, and stretched, filtered, "
          "into a larger viewport") {
    gl_context();
    const int samples = GENERATE(1, 4);
    INFO(samples << " samples a pixel");
    constexpr int kSmall = 32, kWidth = 100, kHeight = 40;
    // The window: green, with a viewport of 64 x 32 at (20, 4) (GL's rows go up).
    OffscreenFramebuffer window(kWidth, kHeight);
    glBindFramebuffer(GL_FRAMEBUFFER, window.target().framebuffer);
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    RenderTarget view = window.target();
    view.x = 20;
    view.y = 4;
    view.width = 2 * kSmall;
    view.height = kSmall;

    OffscreenFramebuffer half(kSmall, kSmall / 2, samples); // half the view's pixels per side
    halves(half);
    half.copy_to(view);
    std::vector<std::uint8_t> rgb;
    window.read_rgb(rgb);
    const auto at = [&](int x, int y_up) { // y counted up from the bottom, as GL's rows
        const size_t i = 3 * (static_cast<size_t>(kHeight - 1 - y_up) * kWidth + static_cast<size_t>(x));
        return glm::ivec3(rgb[i], rgb[i + 1], rgb[i + 2]);
    };
    for (int y = 5; y < 35; y += 6) {
        INFO("row " << y);
        CHECK(at(22, y) == glm::ivec3(255, 0, 0));  // the left half: red, stretched
        CHECK(at(49, y) == glm::ivec3(255, 0, 0));  // (the half ends at view x 32)
        CHECK(at(55, y) == glm::ivec3(0, 0, 255));  // the right half: blue
        CHECK(at(82, y) == glm::ivec3(0, 0, 255));
        // Where the halves meet, filtered: both colours, neither whole.
        const glm::ivec3 seam = at(51, y);
        CHECK(seam.r > 40);
        CHECK(seam.b > 40);
        CHECK(seam.g == 0);
        CHECK(at(18, y) == glm::ivec3(0, 255, 0)); // outside the viewport: untouched
        CHECK(at(86, y) == glm::ivec3(0, 255, 0));
    }
    CHECK(at(50, 2) == glm::ivec3(0, 255, 0));  // below the viewport
    CHECK(at(50, 37) == glm::ivec3(0, 255, 0)); // above it

    // At its own size: pixel for pixel, the seam sharp.
    OffscreenFramebuffer whole(2 * kSmall, kSmall, samples);
    halves(whole);
    whole.copy_to(view);
    window.read_rgb(rgb);
    for (int y = 5; y < 35; y += 6) {
        INFO("row " << y);
        CHECK(at(20 + kSmall - 1, y) == glm::ivec3(255, 0, 0));
        CHECK(at(20 + kSmall, y) == glm::ivec3(0, 0, 255));
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}
