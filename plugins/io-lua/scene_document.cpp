#include "scene_document.hpp"

#include <animator/assets.h>

#include <algorithm>

namespace lua_scene {

namespace {

// A warning for each model, by line, whose mesh the host cannot find (a mesh the author made and
// did not publish): the host shows a stand-in until it is there, and the document keeps its id.
// The scene ran where no file is seen, so its meshes are looked for here.
void resolve_meshes(const SceneResult &scene, const std::string &path, const ani_host *host,
                    std::vector<std::string> &warnings) {
    const auto *assets = host && host->get_extension
                             ? static_cast<const ani_assets_ext *>(host->get_extension(host, ANI_EXT_ASSETS))
                             : nullptr;
    if (!assets) return;
    std::vector<const SceneModel *> by_line;
    for (const SceneModel &m : scene.models)
        if (!m.mesh.empty()) by_line.push_back(&m);
    std::stable_sort(by_line.begin(), by_line.end(),
                     [](const SceneModel *a, const SceneModel *b) { return a->line < b->line; });
    // One warning per line and mesh: the models of an instance (one node under several parents)
    // share both, and are counted.
    for (size_t i = 0; i < by_line.size();) {
        const SceneModel *m = by_line[i];
        size_t uses = 1;
        while (i + uses < by_line.size() && by_line[i + uses]->line == m->line && by_line[i + uses]->mesh == m->mesh)
            ++uses;
        i += uses;
        char where[2048];
        if (!assets->resolve(host, ANI_ASSET_MESH, m->mesh.c_str(), path.c_str(), where, sizeof where))
            // (The host's own words for it end the line, so that it does not say them twice.)
            warnings.push_back(path + ":" + std::to_string(m->line) + ": " +
                               (uses > 1 ? std::to_string(uses) + " models (an instance): " : "") + "mesh '" +
                               m->mesh + "' not found (" + where + "); shown as a stand-in cube until it is there");
    }
}

} // namespace

void build_document(const SceneResult &scene, const std::string &path, const ani_host *host,
                    ani::OwnedDocument &doc) {
    std::vector<std::string> warnings = scene.warnings;
    resolve_meshes(scene, path, host, warnings);
    if (host && host->log)
        for (const std::string &warning : warnings) host->log(host, ANI_LOG_WARNING, "format.lua", warning.c_str());

    std::vector<ani_model_state> states;
    for (const SceneModel &n : scene.models) {
        ani_model_desc m = doc.default_model(n.name, n.mesh);
        m.parent = n.parent;
        m.kd = n.kd;
        m.ks = n.ks;
        m.shininess = n.shininess;
        m.texture = doc.keep(n.texture);
        m.tint = n.tint;
        m.reflectivity = n.reflectivity;
        m.transparency = n.transparency;
        m.refractive_index = n.refractive_index;
        m.dynamics = n.dynamics;
        m.gravity = n.gravity;
        m.mass = n.mass;
        m.initial_velocity = n.initial_velocity;
        m.restitution = n.restitution;
        m.friction = n.friction;
        m.rotates = n.rotates ? 1 : 0;
        m.angular_velocity = n.angular_velocity;
        m.collision_sound = doc.keep(n.collision_sound);
        m.moving_sound = doc.keep(n.moving_sound);
        std::copy(std::begin(n.rest), std::end(n.rest), m.rest);
        m.has_joint = n.has_joint ? 1 : 0;
        m.joint_min = n.joint_min;
        m.joint_max = n.joint_max;
        doc.models.push_back(m);
        states.push_back(n.state);
    }

    doc.default_settings();
    ani_settings_view &s = doc.view.settings;
    s.max_time_ms = scene.max_time_ms;
    s.gravity = scene.gravity;
    s.down_axis = scene.down_axis;
    s.cel_shading = scene.cel_shading ? 1 : 0;
    s.skybox = doc.keep(scene.skybox);
    s.physics_backend = doc.keep(scene.backend);
    s.interpolation = doc.keep(scene.interpolation);
    for (const SceneLight &l : scene.lights)
        doc.lights.push_back(ani_light{doc.keep(l.name), l.position, l.colour, l.falloff});
    doc.view.ambient = scene.ambient;
    doc.view.render_output = doc.keep(scene.render_output);
    doc.view.render_width = scene.render_width;
    doc.view.render_height = scene.render_height;
    ani_keyframe_view k{};
    k.struct_size = sizeof k;
    k.time_ms = 0;
    k.camera = scene.camera;
    k.camera_keyed = 1;
    doc.keyed.emplace_back(states.size(), 1);
    doc.keyframes.push_back(k);
    doc.states.push_back(std::move(states));
    doc.finish();
}

} // namespace lua_scene
