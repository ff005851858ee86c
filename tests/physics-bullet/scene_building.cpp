// What the exact scenes (scenes.cpp) build their documents and timelines with, shared by the
// tests (bullet_support.cpp adds Catch2's checks) and the benchmark (bench/scene_host.cpp). Each
// host defines env(): where its plugins and assets are, and what becomes of their log.
#include "bullet_support.hpp"

#include "assets/mesh.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>

namespace animator::bullet_test {

std::unique_ptr<Timeline> timeline_of(const Document &doc, const std::string &backend) {
    // Each mesh is read once (assimp takes a few milliseconds a mesh): not part of a bake's time.
    static std::map<std::string, std::shared_ptr<const Mesh>> cache;
    static std::mutex cache_mutex;
    auto t = std::make_unique<Timeline>(doc, env().plugins, backend);
    std::vector<std::shared_ptr<const Mesh>> meshes;
    std::lock_guard<std::mutex> lock(cache_mutex);
    for (const Model &m : doc.models()) {
        if (m.mesh.empty()) { // an empty: no geometry
            meshes.push_back(nullptr);
            continue;
        }
        auto it = cache.find(m.mesh);
        if (it == cache.end()) {
            std::vector<std::string> warnings;
            auto loaded = load_meshes({m.mesh}, env().assets, {}, warnings);
            if (!warnings.empty() || !loaded[0])
                throw std::runtime_error("mesh '" + m.mesh + "' not found (build animator_assets)");
            it = cache.emplace(m.mesh, loaded[0]).first;
        }
        meshes.push_back(it->second);
    }
    t->set_meshes(meshes);
    return t;
}

Document no_gravity() {
    Document doc;
    Settings s = doc.settings();
    s.gravity = 0.0;
    doc.set_settings(s);
    return doc;
}

Document with_param(Document doc, const std::string &param, double value) {
    Settings s = doc.settings();
    s.params["physics.bullet"][param] = {value, 0.0, 0.0, 0.0};
    doc.set_settings(s);
    return doc;
}

double unit_sphere_radius() {
    static const double r =
        load_mesh(env().assets.resolve(ANI_ASSET_MESH, "sphere").value()).mesh.bound_radius;
    return r;
}

Model model(const std::string &name, const std::string &mesh, bool dynamics, bool gravity) {
    Model m;
    m.name = name;
    m.mesh = mesh;
    m.dynamics = dynamics;
    m.gravity = gravity;
    return m;
}

ModelState placed(glm::dvec3 center, glm::dvec3 scale, glm::dvec3 angles) {
    ModelState s;
    s.center = center;
    s.scale = scale;
    s.angles = angles;
    return s;
}

void key(Document &doc, std::int64_t ms, int model, const ModelState &state) {
    if (doc.find_keyframe(ms) < 0) {
        Keyframe k;
        k.time_ms = ms;
        k.states.assign(doc.models().size(), std::nullopt);
        doc.insert_keyframe(k);
    }
    doc.set_state(ms, model, state);
}

Document load(const std::string &animation) {
    return open_document(env().plugins, std::filesystem::path(ANIMATOR_SOURCE_DIR) /
                                            "assets/animations" / animation)
        .document;
}

int model_named(const Document &doc, const std::string &name) {
    for (size_t i = 0; i < doc.models().size(); ++i)
        if (doc.models()[i].name == name) return static_cast<int>(i);
    throw std::runtime_error("no model " + name);
}

glm::dvec3 start_of(const Document &doc, int m) {
    return doc.keyframes().front().states[static_cast<size_t>(m)]->center;
}

double worst(double until, const std::function<double(double)> &f) {
    double e = 0.0;
    for (int k = 0; k <= static_cast<int>(std::lround(until * 120.0)); ++k)
        e = std::max(e, f(k / 120.0));
    return e;
}

double energy(const Timeline &t, const Document &doc, double at,
              const std::vector<std::tuple<std::string, double, double>> &models) {
    double e = 0.0;
    for (const auto &[name, mass, inertia] : models) {
        const int m = model_named(doc, name);
        const ModelPose p = t.evaluate(at).models[static_cast<size_t>(m)];
        const RotationSegment *r = t.rotation_at(m, at);
        const glm::dvec3 w = r ? angular_velocity_at(*r, at) : glm::dvec3(0.0);
        e += 0.5 * mass * glm::dot(p.velocity, p.velocity) + 0.5 * inertia * glm::dot(w, w) +
             mass * G * p.center.y;
    }
    return e;
}

const ani_motion_segment *segment_at(const Timeline &t, int model, double time) {
    const ani_motion_segment *found = nullptr;
    for (const auto &s : t.segments(model))
        if (s.t0 <= time) found = &s;
    return found;
}

} // namespace animator::bullet_test
