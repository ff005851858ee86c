// Multisample anti-aliasing (docs/rendering.md): a black cube turned 30 degrees about the view
// axis over the plain background (each sample count this GL gives, up to 8). Without multisampling
// each pixel is either the cube's or the background's; with N samples a pixel on an edge is covered
// by k of them (0 <= k <= N) and resolves to the background times (N - k) / N, so its colour is one
// of N + 1 known levels.
#include "image_compare.hpp"
#include "render_support.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <set>

using namespace animator;
using namespace animator::test;

namespace {

// kd, ks and the ambient are black, so the cube is (0, 0, 0) wherever it covers a sample, whatever
// the lights and shadows do.
Document black_cube_scene() {
    Document doc = make_document(make_camera({0, 0, 5}));
    doc.add_model(make_model("cube", "cube", {0, 0, 0}),
                  make_state({0, 0, 0}, glm::dvec3(1.0), {0, 0, 30}));
    return doc;
}

// The distinct red values of the image.
std::set<int> reds(const Image &image) {
    std::set<int> out;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) out.insert(pixel(image, x, y).r);
    return out;
}

} // namespace

TEST_CASE("anti-aliasing: an edge has exactly two levels without multisampling, the resolved "
          "coverage levels with it") {
    const int background = static_cast<int>(std::lround(RenderOptions{}.background.r * 255.0f));
    const Document doc = black_cube_scene();
    const Rendered plain = render_document(doc, 160, 120, {}, {}, {}, 1);
    CHECK(reds(plain.image) == std::set<int>{0, background});

    for (const int asked : {2, 4, 8}) {
        if (supported_samples(asked) != asked) continue; // llvmpipe gives at most 4
        const Rendered smooth = render_document(doc, 160, 120, {}, {}, {}, asked);
        const int samples = smooth.samples; // llvmpipe draws 2x as 4x
        CAPTURE(asked, samples);
        CHECK(samples >= asked);
        const std::set<int> levels = reds(smooth.image);
        // Every value is background * (samples - k) / samples for some k, give or take rounding.
        for (const int red : levels) {
            CAPTURE(red);
            const double k = samples * (1.0 - red / static_cast<double>(background));
            CHECK(std::abs(k - std::round(k)) * background / samples <= 1.0);
        }
        // Along edges at 30 degrees every coverage between none and all turns up.
        CHECK(levels.size() > 2);
        CHECK(static_cast<int>(levels.size()) == samples + 1);
    }
}

TEST_CASE("anti-aliasing: the fill away from edges is the same with and without it") {
    const Document doc = black_cube_scene();
    const Image plain = render_document(doc, 160, 120, {}, {}, {}, 1).image;
    const Image smooth = render_document(doc, 160, 120, {}, {}, {}, 4).image;
    int differing = 0;
    for (int y = 0; y < plain.height; ++y)
        for (int x = 0; x < plain.width; ++x)
            differing += pixel(plain, x, y) != pixel(smooth, x, y);
    // Only edge pixels change: the cube's outline is about 4 * 70 pixels long at this size.
    CHECK(differing > 0);
    CHECK(differing < 400);
}

TEST_CASE("golden: spheres on a floor with 4x anti-aliasing") {
    Document doc = make_document(make_camera({0, 1.2, 6}, 0, -10));
    doc.add_model(make_model("floor", "plane", {0.55, 0.55, 0.55}),
                  make_state({0, -1, 0}, {6, 1, 6}));
    doc.add_model(make_model("shiny", "sphere", {0.8, 0.15, 0.1}, {1, 1, 1}, 40),
                  make_state({-1.3, 0, 0}));
    doc.add_model(make_model("matte", "sphere", {0.2, 0.4, 0.8}), make_state({1.3, 0, 0}));
    // Anti-aliasing alone: shadows have their golden (shadow_test).
    RenderOptions without_shadows;
    without_shadows.shadows = false;
    const Rendered r = render_document(doc, 160, 120, {}, without_shadows, {}, 4);
    CHECK(r.log.empty());
    const std::string problem = check_golden("msaa_spheres", r.image, Tolerance{48.0, 0.005, 1.0});
    INFO(problem);
    CHECK(problem.empty());
    // The same scene without it must not pass for the golden (the tolerance sees anti-aliasing).
    const Image plain = render_document(doc, 160, 120, {}, without_shadows).image;
    const ImageDifference d = compare_images(plain, r.image, 0.0);
    CHECK(d.max > 10.0);
}
