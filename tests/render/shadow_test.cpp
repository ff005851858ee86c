// Shadows (docs/rendering.md), checked against geometry worked out here apart from the shaders: a
// floor seen straight from above, one point light to the side, and a sphere hovering (or a cube
// resting) over the floor. For each pixel the test finds the floor point it sees (the camera's
// pinhole), whether that point is seen at all (the ray from the camera misses the model), and
// whether the segment from it to the light clearly misses the model (lit) or clearly passes
// through it (in shadow). Lit pixels must be the lighting formula's value, to within 2 of 255
// (so no shadow acne anywhere on the lit floor, right up to the shadow); shadowed ones the
// ambient light's alone (so the shadow is there, dark, and reaches the cube's foot: no
// peter-panning).
#include "image_compare.hpp"
#include "render_support.hpp"

#include <catch2/catch.hpp>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>

using namespace animator;
using namespace animator::test;

namespace {

constexpr int kSize = 128;           // a square image, so the aspect ratio is 1
constexpr double kHeight = 6.0;      // the camera above the floor at y = 0
constexpr double kFov = 60.0;        // degrees, vertical
const glm::dvec3 kKd{0.6, 0.6, 0.6}; // the floor's, no specular light
const glm::dvec3 kAmbient{0.15, 0.15, 0.15};
const Light kLight{"side", {3.0, 5.0, 0.5}, {1.0, 1.0, 1.0}, {1.0, 0.0, 0.0}};
// How clearly a segment must miss or cross a model's surface (world units) to count, with maps of
// 1024 texels: the sphere mesh's facets lie up to 1% inside its radius, and the filtered shadow
// edge is soft over a few of the map's texels (about 0.017 each here, 5 m from the light through
// a 120-degree cone). Texels twice as wide (a map of 512) need twice the margin.
constexpr double kMargin = 0.08;

// A sphere or an axis-aligned box, in world space, grown (or shrunk, for a negative `grow`).
struct Shape {
    bool sphere;
    glm::dvec3 centre;
    glm::dvec3 half; // the sphere's radius in x; the box's half sizes
};

// Whether the segment a..b meets `shape` grown by `grow`.
bool meets(const Shape &shape, const glm::dvec3 &a, const glm::dvec3 &b, double grow) {
    if (shape.sphere) {
        const glm::dvec3 ab = b - a;
        const double t = glm::clamp(glm::dot(shape.centre - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
        return glm::length(a + t * ab - shape.centre) < shape.half.x + grow;
    }
    // Slabs (Kay and Kajiya): the parameter range inside each pair of planes must overlap.
    double enter = 0.0, leave = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double low = shape.centre[axis] - shape.half[axis] - grow;
        const double high = shape.centre[axis] + shape.half[axis] + grow;
        const double d = b[axis] - a[axis];
        if (std::abs(d) < 1e-12) {
            if (a[axis] < low || a[axis] > high) return false;
            continue;
        }
        double t0 = (low - a[axis]) / d, t1 = (high - a[axis]) / d;
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
    }
    return enter <= leave;
}

// The floor point seen at the centre of pixel (x, y) from the top left (as in lights_test).
glm::dvec3 floor_point(int x, int y) {
    const double half = std::tan(glm::radians(kFov / 2.0));
    const double right = ((x + 0.5) / kSize * 2.0 - 1.0) * half;
    const double up = (1.0 - (y + 0.5) / kSize * 2.0) * half;
    return {right * kHeight, 0.0, -up * kHeight};
}

// ambient kd, plus (when lit) the light's colour times kd times the cosine to the floor's normal.
glm::dvec3 expected(const glm::dvec3 &p, bool lit) {
    glm::dvec3 c = kAmbient * kKd;
    if (lit) {
        const glm::dvec3 to_light = kLight.position - p;
        c += kLight.colour * kKd * (to_light.y / glm::length(to_light));
    }
    return glm::clamp(c, 0.0, 1.0) * 255.0;
}

Document scene(const Shape &shape) {
    Document doc = make_document(make_camera({0, kHeight, 0}, 0, -90, kFov));
    Settings s = doc.settings();
    s.lights = {kLight};
    s.ambient = kAmbient;
    doc.set_settings(s);
    doc.add_model(make_model("floor", "plane", kKd), make_state({0, 0, 0}, {5, 1, 5}));
    // Black: whatever of it is seen is told from the floor at once.
    doc.add_model(make_model("caster", shape.sphere ? "sphere" : "cube", {0, 0, 0}),
                  make_state(shape.centre, shape.half));
    return doc;
}

struct Counts {
    int lit = 0, shadowed = 0;
};

// Every pixel that clearly sees the floor, lit or clearly in shadow, against the formula.
Counts check_floor(const Image &image, const Shape &shape, bool shadows, double margin = kMargin) {
    const glm::dvec3 eye(0.0, kHeight, 0.0);
    Counts n;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::dvec3 p = floor_point(x, y);
            if (std::abs(p.x) > 4.9 || std::abs(p.z) > 4.9) continue; // beyond the floor
            if (meets(shape, eye, p, margin)) continue;               // the model in the way
            const bool lit = !meets(shape, p, kLight.position, margin);
            const bool shadowed = meets(shape, p, kLight.position, -margin);
            if (!lit && !shadowed) continue; // the soft edge between
            const glm::dvec3 want = expected(p, lit || !shadows);
            const glm::ivec3 got = pixel(image, x, y);
            CAPTURE(x, y, p.x, p.z, lit, want.r, got.r, got.g, got.b);
            for (int c = 0; c < 3; ++c) CHECK(std::abs(got[c] - want[c]) <= 2.0);
            ++(lit ? n.lit : n.shadowed);
        }
    }
    return n;
}

const Shape kHoveringSphere{true, {0.0, 1.2, 0.0}, glm::dvec3(0.6)};
const Shape kRestingCube{false, {0.0, 0.5, 0.0}, glm::dvec3(0.5)};

} // namespace

TEST_CASE("shadows: a sphere over a floor shades the floor where the light's rays pass through it, "
          "and nowhere else") {
    const Document doc = scene(kHoveringSphere);
    const Rendered r = render_document(doc, kSize, kSize);
    CHECK(r.log.empty());
    CHECK(r.stats.shadow_maps == 1);
    const Counts n = check_floor(r.image, kHoveringSphere, true);
    CHECK(n.lit > 5000);
    CHECK(n.shadowed > 100);

    // The editor's frame budget halves the maps (editor/frame_budget.hpp): the same holds.
    RenderOptions smaller;
    smaller.shadow_map_size = 512;
    const Rendered coarse = render_document(doc, kSize, kSize, {}, smaller);
    const Counts m = check_floor(coarse.image, kHoveringSphere, true, 2.0 * kMargin);
    CHECK(m.lit > 5000);
    CHECK(m.shadowed > 100);

    // Off, the same floor pixels are all lit: the darkness was the shadow's.
    RenderOptions off;
    off.shadows = false;
    const Rendered unshadowed = render_document(doc, kSize, kSize, {}, off);
    CHECK(unshadowed.stats.shadow_maps == 0);
    check_floor(unshadowed.image, kHoveringSphere, false);
}

TEST_CASE("shadows: a cube resting on the floor casts a shadow that starts at its foot (no "
          "peter-panning) and leaves the lit floor beside it unblemished (no acne)") {
    const Rendered r = render_document(scene(kRestingCube), kSize, kSize);
    CHECK(r.log.empty());
    const Counts n = check_floor(r.image, kRestingCube, true);
    CHECK(n.lit > 5000);
    CHECK(n.shadowed > 100);
    // The floor right beside the foot, on the shadow's side, and in the shadow: 0.1 to 0.3 out
    // from the face at x = -0.5 (where the top face no longer hides it).
    for (int x = 0; x < kSize; ++x) {
        const glm::dvec3 p = floor_point(x, kSize / 2);
        if (p.x < -0.8 || p.x > -0.62) continue;
        const glm::ivec3 got = pixel(r.image, x, kSize / 2);
        CAPTURE(x, p.x, got.r);
        CHECK(std::abs(got.r - expected(p, false).r) <= 2.0);
    }
}

TEST_CASE("shadows: closed casters go into the map one-sided while the light is outside them, "
          "two-sided once it is inside") {
    // The sphere is closed, the floor open: one caster of two drawn one-sided, and the floor's
    // shadow as the geometry says (the faces turned away from the light were never the nearest).
    const Rendered r = render_document(scene(kHoveringSphere), kSize, kSize);
    CHECK(r.stats.shadow_casters == 2);
    CHECK(r.stats.shadow_one_sided == 1);
    check_floor(r.image, kHoveringSphere, true);
    // A closed sphere around the light: every ray from it leaves through the sphere's inside,
    // faces turned away from the light, so all of the floor is in its shadow; drawn one-sided
    // (as a caster seen from outside is), the sphere would cast none.
    const Shape around{true, kLight.position, glm::dvec3(0.5)};
    const Rendered enclosed = render_document(scene(around), kSize, kSize);
    CHECK(enclosed.stats.shadow_casters == 2);
    CHECK(enclosed.stats.shadow_one_sided == 0);
    const Counts n = check_floor(enclosed.image, around, true);
    CHECK(n.lit == 0);
    CHECK(n.shadowed > 5000);
}

TEST_CASE("golden: a sphere over a floor and its soft-edged shadow, anti-aliased") {
    Document doc = make_document(make_camera({0, 2.2, 6}, 0, -18));
    Settings s = doc.settings();
    s.lights = {Light{"key", {-3.0, 5.0, 2.0}, {1.0, 0.95, 0.9}, {1.0, 0.0, 0.0}}};
    doc.set_settings(s);
    doc.add_model(make_model("floor", "plane", {0.55, 0.55, 0.55}),
                  make_state({0, -1, 0}, {6, 1, 6}));
    doc.add_model(make_model("ball", "sphere", {0.8, 0.2, 0.1}, {0.6, 0.6, 0.6}, 30),
                  make_state({0, 0, 0}));
    doc.add_model(make_model("box", "cube", {0.2, 0.5, 0.8}),
                  make_state({1.8, -0.5, -0.5}, glm::dvec3(0.5), {0, 30, 0}));
    const Rendered r = render_document(doc, 160, 120, {}, {}, {}, 4);
    CHECK(r.log.empty());
    const std::string problem = check_golden("shadows", r.image, Tolerance{48.0, 0.005, 1.0});
    INFO(problem);
    CHECK(problem.empty());
}
