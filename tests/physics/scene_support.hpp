// What the physics tests that bake through the real timeline share: the build's plugins and
// assets, a timeline with the document's meshes, and short ways to make models, placements and
// keys.
#pragma once

#include "assets/asset_paths.hpp"
#include "assets/mesh.hpp"
#include "io/environment.hpp"
#include "timeline/timeline.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace physics_test {

using namespace animator;

inline constexpr double G = 9.81;

// The plugins and generated assets of this build, with a quiet log.
inline Environment &env() {
    static Environment e({test::bin_dir().parent_path() / "assets"}, {test::bin_dir()},
                         [](ani_log_level, const std::string &, const std::string &) {});
    return e;
}

// The radius of the generated unit sphere as read (single precision: within 4e-8 of 1).
inline double unit_radius() {
    return load_mesh(env().assets.resolve(ANI_ASSET_MESH, "sphere").value()).mesh.bound_radius;
}

// A timeline over the document with its meshes loaded (none may be missing).
inline std::unique_ptr<Timeline> timeline_of(const Document &doc, const std::string &backend = "") {
    auto t = std::make_unique<Timeline>(doc, env().plugins, backend);
    std::vector<std::string> ids, warnings;
    for (const Model &m : doc.models()) ids.push_back(m.mesh);
    t->set_meshes(load_meshes(ids, env().assets, {}, warnings));
    REQUIRE(warnings.empty());
    return t;
}

inline Model model(const std::string &name, const std::string &mesh, bool dynamics, bool gravity) {
    Model m;
    m.name = name;
    m.mesh = mesh;
    m.dynamics = dynamics;
    m.gravity = gravity;
    return m;
}

inline ModelState placed(glm::dvec3 center, glm::dvec3 scale = glm::dvec3(1.0),
                         glm::dvec3 angles = glm::dvec3(0.0)) {
    ModelState s;
    s.center = center;
    s.scale = scale;
    s.angles = angles;
    return s;
}

inline ModelState placed(glm::dvec3 center, double scale) {
    return placed(center, glm::dvec3(scale));
}

// Keys model `model` at `ms` milliseconds, adding the keyframe if there is none there.
inline void key(Document &doc, std::int64_t ms, int model, const ModelState &state) {
    if (doc.find_keyframe(ms) < 0) {
        Keyframe k;
        k.time_ms = ms;
        k.states.assign(doc.models().size(), std::nullopt);
        doc.insert_keyframe(k);
    }
    doc.set_state(ms, model, state);
}

// How far the first `count` events are from the bounces of a drop that first lands at t0 at
// speed v0 with restitution e: bounce k at t0 (1 + 2 e (1 - e^k) / (1 - e)), met at e^k v0
// (derived in restitution_test.cpp's first test). The largest differences in time and in speed.
inline std::pair<double, double> bounce_errors(const animator::EventList &events,
                                               size_t count, double t0, double v0, double e) {
    double worst_t = 0.0, worst_v = 0.0;
    for (size_t k = 0; k < count; ++k) {
        const double ek = std::pow(e, static_cast<double>(k));
        const double tk = t0 * (1.0 + 2.0 * e * (1.0 - ek) / (1.0 - e));
        worst_t = std::max(worst_t, std::abs(events[k].t - tk));
        worst_v = std::max(worst_v, std::abs(events[k].speed - ek * v0));
    }
    return {worst_t, worst_v};
}

// The index of the document's model of that name (the test fails without one).
inline int model_named(const Document &doc, const std::string &name) {
    const int i = doc.find_model(name);
    if (i < 0) FAIL("no model " << name);
    return i;
}

} // namespace physics_test
