// The selection outline (render/selection_outline.hpp), golden-free: a yellow ball, selected,
// on which the yellow tint alone shows nothing. Around its silhouette the ring has the outline's
// colours (the light band next to the ball, the dark band outside it); inside, the ball's pixels
// are exactly those drawn without the outline; an unselected ball gets no ring. A flagged ball
// (the editor flags models found overlapping) gets a wider red ring, and both when selected too.
#include "render_support.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace animator;
using namespace animator::test;

namespace {

constexpr int kWidth = 200, kHeight = 150;

// The yellow ball, 1.5 m in radius, 8 m in front of the camera.
Document yellow_ball() {
    Document doc = make_document(make_camera({0, 0, 8}));
    doc.add_model(make_model("ball", "sphere", {1.0, 0.9, 0.0}), make_state({0, 0, 0}, glm::dvec3(1.5)));
    return doc;
}

// Its silhouette's radius in pixels: a sphere of radius r at distance d subtends asin(r / d);
// the vertical field of view (50 degrees) spans the height.
double silhouette_radius() {
    const double half = std::asin(1.5 / 8.0);
    return std::tan(half) / std::tan(25.0 * M_PI / 180.0) * kHeight / 2.0;
}

glm::ivec3 at_angle(const Image &image, double angle, double radius) {
    const int x = static_cast<int>(std::lround(kWidth / 2.0 + radius * std::cos(angle) - 0.5));
    const int y = static_cast<int>(std::lround(kHeight / 2.0 + radius * std::sin(angle) - 0.5));
    return pixel(image, x, y);
}

bool near_colour(glm::ivec3 c, glm::vec3 ref, int tol = 30) {
    const glm::ivec3 r = glm::ivec3(glm::round(ref * 255.0f));
    return std::abs(c.x - r.x) <= tol && std::abs(c.y - r.y) <= tol && std::abs(c.z - r.z) <= tol;
}

} // namespace

TEST_CASE("a selected model is outlined in two colours, just outside its silhouette") {
    const Document doc = yellow_ball();
    const OutlineStyle style; // the editor's
    const Image outlined = render_document(doc, kWidth, kHeight, {0}).image;
    const double r = silhouette_radius();
    int inner = 0, outer = 0, beyond = 0;
    const int samples = 72;
    for (int i = 0; i < samples; ++i) {
        const double a = 2.0 * M_PI * i / samples;
        inner += near_colour(at_angle(outlined, a, r + 1.0), style.inner);
        outer += near_colour(at_angle(outlined, a, r + 3.3), style.outer);
        // Past the ring: the background again.
        beyond += near_colour(at_angle(outlined, a, r + 7.0), RenderOptions{}.background, 4);
    }
    INFO("of " << samples << " directions: inner band " << inner << ", outer band " << outer << ", background beyond " << beyond);
    CHECK(inner >= samples * 9 / 10);
    CHECK(outer >= samples * 9 / 10);
    CHECK(beyond == samples);
}

TEST_CASE("the outline never covers the model's own pixels") {
    const Document doc = yellow_ball();
    RenderOptions without;
    without.selection_outline = false;
    const Image outlined = render_document(doc, kWidth, kHeight, {0}).image;
    const Image plain = render_document(doc, kWidth, kHeight, {0}, without).image;
    const double r = silhouette_radius();
    int inside = 0, differ = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            if (std::hypot(x + 0.5 - kWidth / 2.0, y + 0.5 - kHeight / 2.0) > r - 1.5) continue;
            ++inside;
            differ += pixel(outlined, x, y) != pixel(plain, x, y);
        }
    CHECK(inside > 2500);
    CHECK(differ == 0);
    // And the ball is drawn: its pixels are yellowish, not the outline's colours.
    const glm::ivec3 centre = pixel(outlined, kWidth / 2, kHeight / 2);
    CHECK(centre.x > centre.z + 60);
    CHECK(centre.y > centre.z + 60);
}

TEST_CASE("an unselected model gets no outline") {
    const Document doc = yellow_ball();
    const OutlineStyle style;
    const Image image = render_document(doc, kWidth, kHeight, {}).image;
    const double r = silhouette_radius();
    for (int i = 0; i < 72; ++i) {
        const double a = 2.0 * M_PI * i / 72;
        CHECK(near_colour(at_angle(image, a, r + 3.3), RenderOptions{}.background, 4));
        CHECK_FALSE(near_colour(at_angle(image, a, r + 1.0), style.inner));
    }
}

TEST_CASE("a flagged model gets a wider red ring, and a selected one both rings") {
    const Document doc = yellow_ball();
    const RenderOptions options;
    const OutlineStyle &flag = options.flagged_style, &select = options.outline_style;
    const double r = silhouette_radius();
    const Image flagged = render_document(doc, kWidth, kHeight, {}, options, {0}).image;
    const Image both = render_document(doc, kWidth, kHeight, {0}, options, {0}).image;
    const int samples = 72;
    int red_near = 0, red_far = 0, white = 0, beyond = 0, both_select = 0, both_red = 0;
    for (int i = 0; i < samples; ++i) {
        const double a = 2.0 * M_PI * i / samples;
        red_near += near_colour(at_angle(flagged, a, r + 1.0), flag.inner);
        red_far += near_colour(at_angle(flagged, a, r + 5.5), flag.inner);
        white += near_colour(at_angle(flagged, a, r + 8.0), flag.outer);
        beyond += near_colour(at_angle(flagged, a, r + 12.0), options.background, 4);
        // Selected too: the selection's bands next to the ball, the red one outside them.
        both_select += near_colour(at_angle(both, a, r + 1.0), select.inner) &&
                       near_colour(at_angle(both, a, r + 3.3), select.outer);
        both_red += near_colour(at_angle(both, a, r + 5.5), flag.inner);
    }
    INFO("of " << samples << ": red near " << red_near << ", red far " << red_far << ", white " << white
               << ", background beyond " << beyond << "; selected too: selection " << both_select
               << ", red " << both_red);
    CHECK(red_near >= samples * 9 / 10);
    CHECK(red_far >= samples * 9 / 10);
    CHECK(white >= samples * 9 / 10);
    CHECK(beyond == samples);
    CHECK(both_select >= samples * 9 / 10);
    CHECK(both_red >= samples * 9 / 10);
}

TEST_CASE("a flagged model in front of a flagged wall is ringed over the wall") {
    // The editor flags both models of an overlapping pair: a cube sunk in a floor has the
    // floor's pixels all around it, and its ring must still show.
    Document doc = yellow_ball();
    doc.add_model(make_model("wall", "plane", {0.2, 0.3, 0.9}), make_state({0, 0, -4}, glm::dvec3(30.0), {90, 0, 0}));
    const RenderOptions options;
    const Image image = render_document(doc, kWidth, kHeight, {}, options, {0, 1}).image;
    const double r = silhouette_radius();
    int red = 0;
    for (int i = 0; i < 72; ++i) red += near_colour(at_angle(image, 2.0 * M_PI * i / 72, r + 3.0), options.flagged_style.inner);
    // And the wall is there behind: far from the ball, its blue.
    const glm::ivec3 corner = pixel(image, 5, 5);
    CHECK(corner.z > corner.x + 40);
    CHECK(red >= 72 * 9 / 10);
}

TEST_CASE("a flagged model's ring shows over a selected wall behind it") {
    Document doc = yellow_ball();
    doc.add_model(make_model("wall", "plane", {0.2, 0.3, 0.9}), make_state({0, 0, -4}, glm::dvec3(30.0), {90, 0, 0}));
    const RenderOptions options;
    const Image image = render_document(doc, kWidth, kHeight, {1}, options, {0, 1}).image;
    const double r = silhouette_radius();
    int red = 0;
    for (int i = 0; i < 72; ++i) red += near_colour(at_angle(image, 2.0 * M_PI * i / 72, r + 3.0), options.flagged_style.inner);
    CHECK(red >= 72 * 9 / 10);
}
