// A document's lights, checked against the lighting formula worked out here, apart from the
// shaders: a flat floor seen straight from above, lit by lights at known places with known
// falloff, and the colour read back at floor points whose world position the test computes from
// the camera itself. The framebuffer is plain RGBA8 (no sRGB), so a pixel is the shaded value
// times 255, rounded.
#include "render_support.hpp"
#include "support.hpp"

#include "render/framebuffer.hpp"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include <cmath>

using namespace animator;
using namespace animator::test;

namespace {

constexpr int kSize = 64;            // a square image, so the aspect ratio is 1
constexpr double kHeight = 4.0;      // the camera above the floor at y = 0
constexpr double kFov = 60.0;        // degrees, vertical
const glm::dvec3 kKd{0.6, 0.5, 0.4}; // the floor's, and ks 0: no specular light
const glm::dvec3 kAmbient{0.1, 0.15, 0.2};

// A camera at (0, kHeight, 0) looking straight down (-Y), so the image's right is +X and its up
// is -Z; a floor 10 by 10 at y = 0 fills the view.
Document floor_document(const std::vector<Light> &lights) {
    Document doc = make_document(make_camera({0, kHeight, 0}, 0, -90, kFov));
    Settings s = doc.settings();
    s.lights = lights;
    s.ambient = kAmbient;
    doc.set_settings(s);
    doc.add_model(make_model("floor", "plane", kKd), make_state({0, 0, 0}, {5, 1, 5}));
    return doc;
}

// The floor point seen at the centre of pixel (x, y) from the top left: the pixel's ray through a
// pinhole whose image plane spans tan(fov / 2) either way at distance 1.
glm::dvec3 floor_point(int x, int y) {
    const double half = std::tan(glm::radians(kFov / 2.0));
    const double right = ((x + 0.5) / kSize * 2.0 - 1.0) * half;
    const double up = (1.0 - (y + 0.5) / kSize * 2.0) * half;
    return {right * kHeight, 0.0, -up * kHeight};
}

// What the floor's colour is at `p`: ambient * kd, plus for each light its colour times kd times
// the cosine between the floor's normal (+Y) and the way to the light, over c0 + c1 d + c2 d^2.
glm::dvec3 expected(const glm::dvec3 &p, const std::vector<Light> &lights) {
    glm::dvec3 c = kAmbient * kKd;
    for (const Light &l : lights) {
        const glm::dvec3 to_light = l.position - p;
        const double d = glm::length(to_light);
        const double cosine = std::max(0.0, to_light.y / d);
        c += l.colour * kKd * cosine / (l.falloff.x + l.falloff.y * d + l.falloff.z * d * d);
    }
    return glm::clamp(c, 0.0, 1.0) * 255.0;
}

// The pixels read at: under the first light, beside it, and towards three corners.
const std::pair<int, int> kPixels[] = {{40, 40}, {32, 32}, {8, 8}, {56, 10}, {12, 54}, {48, 24}};

// Every probed pixel within 2 of 255 of the formula in each channel: 0.5 for rounding to 8 bits
// and the rest for single-precision shading.
void check_against_formula(const Document &doc, const std::vector<Light> &lights,
                           const std::string &shading) {
    RenderOptions options;
    options.shading = shading;
    const Rendered r = render_document(doc, kSize, kSize, {}, options);
    for (const std::string &line : r.log) UNSCOPED_INFO(line);
    CHECK(r.log.empty());
    for (const auto &[x, y] : kPixels) {
        const glm::dvec3 want = expected(floor_point(x, y), lights);
        const glm::ivec3 got = pixel(r.image, x, y);
        CAPTURE(shading, x, y, want.r, want.g, want.b, got.r, got.g, got.b);
        for (int c = 0; c < 3; ++c) CHECK(std::abs(got[c] - want[c]) <= 2.0);
    }
}

// A warm light over the pixel (40, 40), with all three falloff terms, and a blue one elsewhere.
const Light kWarm{"warm", {0.0, 1.5, 0.0}, {1.6, 1.1, 0.7}, {0.5, 0.3, 0.2}};
const Light kBlue{"blue", {-1.5, 2.5, 1.0}, {0.1, 0.3, 1.2}, {1.0, 0.0, 0.15}};

} // namespace

TEST_CASE("one document light lights a floor as ambient * kd + colour * kd * cos / (c0 + c1 d + c2 "
          "d^2)") {
    // The warm light straight above the floor point seen at pixel (40, 40).
    Light warm = kWarm;
    warm.position = floor_point(40, 40) + glm::dvec3(0, 1.5, 0);
    const std::vector<Light> lights{warm};
    for (const char *shading : {"shading.phong", ""}) // the plugin, and the built-in fallback
        check_against_formula(floor_document(lights), lights, shading);

    // The test's geometry is right: the brightest probe is the one under the light, and the
    // light falls off visibly towards the corners.
    const Rendered r = render_document(floor_document(lights), kSize, kSize);
    CHECK(pixel(r.image, 40, 40).r > pixel(r.image, 32, 32).r + 20);
    CHECK(pixel(r.image, 32, 32).r > pixel(r.image, 8, 8).r + 20);
}

TEST_CASE("a second light of another colour adds its own term") {
    Light warm = kWarm;
    warm.position = floor_point(40, 40) + glm::dvec3(0, 1.5, 0);
    const std::vector<Light> both{warm, kBlue};
    for (const char *shading : {"shading.phong", ""})
        check_against_formula(floor_document(both), both, shading);

    // Where the blue light reaches, blue rises over the warm light alone; red barely moves.
    const Image one = render_document(floor_document({warm}), kSize, kSize).image;
    const Image two = render_document(floor_document(both), kSize, kSize).image;
    CHECK(pixel(two, 12, 54).b > pixel(one, 12, 54).b + 40);
    CHECK(std::abs(pixel(two, 12, 54).r - pixel(one, 12, 54).r) < 15);
}

TEST_CASE("ambient light is the document's, with or without lights of its own") {
    // No lights: the camera's light as before, and the document's ambient. The same floor under
    // ambient 0.2 and 0.3 differs by exactly 0.1 * kd everywhere.
    Document dim = make_document(make_camera({0, kHeight, 0}, 0, -90, kFov));
    dim.add_model(make_model("floor", "plane", kKd), make_state({0, 0, 0}, {5, 1, 5}));
    Document bright = dim;
    Settings s = bright.settings();
    s.ambient = glm::dvec3(0.3);
    bright.set_settings(s);
    CHECK(dim.settings().ambient == glm::dvec3(0.2)); // the old fixed ambient, by default
    const Image a = render_document(dim, kSize, kSize).image;
    const Image b = render_document(bright, kSize, kSize).image;
    for (const auto &[x, y] : kPixels) {
        CAPTURE(x, y);
        for (int c = 0; c < 3; ++c)
            CHECK(std::abs((pixel(b, x, y)[c] - pixel(a, x, y)[c]) - 0.1 * kKd[c] * 255.0) <= 1.5);
    }
}

TEST_CASE("eight lights are all used, a light of colour 0 adds nothing") {
    // Eight dim lights spread over the floor, each its own falloff: the formula, still.
    std::vector<Light> eight;
    for (int i = 0; i < 8; ++i) {
        const double a = glm::radians(45.0 * i);
        eight.push_back(Light{"l" + std::to_string(i),
                              {2.0 * std::cos(a), 1.0 + 0.25 * i, 2.0 * std::sin(a)},
                              {0.15 + 0.02 * i, 0.12, 0.3 - 0.03 * i},
                              {1.0, 0.1 * i, 0.05}});
    }
    for (const char *shading : {"shading.phong", ""})
        check_against_formula(floor_document(eight), eight, shading);

    std::vector<Light> dark = {Light{"off", {0, 1, 0}, glm::dvec3(0.0), {1, 0, 0}}};
    check_against_formula(floor_document(dark), dark, "shading.phong"); // ambient alone
}

TEST_CASE(
    "a shading plugin written for one light (light_position, light_colour) is lit by light 0, "
    "and one built for ABI 1.9 is not asked for shadow maps") {
    // tests/render/one_light_shading.c: ambient * kd + light_colour * kd * cos, nothing else; it
    // refuses the shadow-map bits of ABI 1.10, so a fallback would show in the log (shadows are on,
    // two maps).
    gl_context();
    Environment env(AssetPaths::default_roots(), std::vector<std::filesystem::path>{
                                                     test::bin_dir(), ANIMATOR_RENDER_PLUGIN_DIR});
    // Light 0 red, straight over pixel (40, 40); light 1 blue, straight over pixel (12, 54).
    const std::vector<Light> lights{
        Light{"red", floor_point(40, 40) + glm::dvec3(0, 1, 0), {1, 0, 0}, {1, 0, 0}},
        Light{"blue", floor_point(12, 54) + glm::dvec3(0, 1, 0), {0, 0, 1}, {1, 0, 0}}};
    const Document doc = floor_document(lights);
    std::vector<std::string> log;
    RenderOptions options;
    options.shading = "shading.one_light";
    Renderer renderer(env.plugins, env.assets, options,
                      [&](const std::string &m) { log.push_back(m); });
    renderer.set_document(doc, meshes_of(doc));
    OffscreenFramebuffer framebuffer(kSize, kSize);
    renderer.draw(first_frame(doc), framebuffer.target());
    CHECK(renderer.stats().shadow_maps == 2);
    CHECK(log.empty());
    CHECK(renderer.programs().fallbacks() == 0);
    Image image;
    image.width = image.height = kSize;
    framebuffer.read_rgb(image.rgb);
    // Under light 0: its red, kd.r * (ambient + 1); under light 1: only the ambient blue.
    CHECK(std::abs(pixel(image, 40, 40).r - (kAmbient.r + 1.0) * kKd.r * 255.0) <= 2.0);
    CHECK(std::abs(pixel(image, 12, 54).b - kAmbient.b * kKd.b * 255.0) <= 2.0);
}
