#include "bullet_support.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <mutex>

namespace animator::bullet_test {

const double kSteps[3] = {1.0 / 60.0, 1.0 / 240.0, 1.0 / 1000.0};

namespace {
std::mutex log_mutex;
std::vector<std::string> log_lines;
} // namespace

Environment &env() {
    static Environment e({test::bin_dir().parent_path() / "assets"}, {test::bin_dir()},
                         [](ani_log_level, const std::string &plugin, const std::string &message) {
                             std::lock_guard<std::mutex> lock(log_mutex);
                             log_lines.push_back(plugin + ": " + message);
                         });
    return e;
}

std::vector<std::string> take_log() {
    std::lock_guard<std::mutex> lock(log_mutex);
    std::vector<std::string> out;
    out.swap(log_lines);
    return out;
}

std::unique_ptr<Timeline> timeline_of(const Document &doc, const std::string &backend) {
    // Each mesh is read once for all the tests (assimp takes a few milliseconds a mesh).
    static std::map<std::string, std::shared_ptr<const Mesh>> cache;
    static std::mutex cache_mutex;
    auto t = std::make_unique<Timeline>(doc, env().plugins, backend);
    std::vector<std::shared_ptr<const Mesh>> meshes;
    std::lock_guard<std::mutex> lock(cache_mutex);
    for (const Model &m : doc.models()) {
        auto it = cache.find(m.mesh);
        if (it == cache.end()) {
            std::vector<std::string> warnings;
            it = cache.emplace(m.mesh, load_meshes({m.mesh}, env().assets, {}, warnings)[0]).first;
        }
        meshes.push_back(it->second);
    }
    t->set_meshes(meshes);
    return t;
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
    return open_document(env().plugins, test::source_dir() / "assets/animations" / animation)
        .document;
}

const ani_motion_segment *segment_at(const Timeline &t, int model, double time) {
    const ani_motion_segment *found = nullptr;
    for (const auto &s : t.segments(model))
        if (s.t0 <= time) found = &s;
    return found;
}

void check_converges(const char *what, const double (&errors)[3], const double (&bounds)[3],
                     double noise) {
    INFO(what << ": errors " << errors[0] << ", " << errors[1] << ", " << errors[2]
              << " at steps 1/60, 1/240, 1/1000; bounds " << bounds[0] << ", " << bounds[1] << ", "
              << bounds[2]);
    for (int k = 0; k < 3; ++k) CHECK(errors[k] <= bounds[k]);
    for (int k = 1; k < 3; ++k) CHECK((errors[k] < errors[k - 1] || errors[k] <= noise));
}

} // namespace animator::bullet_test
