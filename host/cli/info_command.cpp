// `animator info FILE`: a document's settings, models and keyframes, as text.
#include "cli/cli_support.hpp"
#include "cli/commands.hpp"

#include "assets/mesh.hpp"
#include "io/document_io.hpp"
#include "io/environment.hpp"

#include <map>

#include <glm/gtc/quaternion.hpp>

#include <iostream>
#include <sstream>

namespace animator::cli {

namespace {

std::string vec(const glm::dvec3 &v) {
    std::ostringstream out;
    out << "(" << v.x + 0.0 << ", " << v.y + 0.0 << ", " << v.z + 0.0 << ")"; // no "-0"
    return out.str();
}

const char *on_off(bool b) { return b ? "on" : "off"; }

// A mesh line: where the mesh was found, its size and the seed's bounding sphere.
std::string describe_mesh(const AssetPaths &assets, const std::string &id, const std::string &document,
                          std::map<std::string, std::string> &cache) {
    if (id.empty()) return "(none: an empty)";
    auto it = cache.find(id);
    if (it != cache.end()) return it->second;
    std::ostringstream out;
    out << id;
    if (auto path = assets.resolve(ANI_ASSET_MESH, id, document)) {
        try {
            const LoadedMesh loaded = load_mesh(*path);
            for (const std::string &w : loaded.warnings) warn(w);
            out << " (" << path->string() << ": " << loaded.mesh.triangle_count()
                << " triangles, bounding sphere " << vec(loaded.mesh.bound_center) << " r "
                << loaded.mesh.bound_radius << ")";
        } catch (const AssetError &e) {
            out << " (" << e.what() << ")";
        }
    } else {
        out << " (not found: " << assets.searched(ANI_ASSET_MESH, id, document) << ")";
    }
    return cache[id] = out.str();
}

void print_document(std::ostream &out, const Document &doc, const AssetPaths &assets, const std::string &file) {
    std::map<std::string, std::string> meshes;
    const Settings &s = doc.settings();
    const char *axes = "xyz";
    out << "settings:\n"
        << "  max time:        " << s.max_time_ms << " ms\n"
        << "  gravity:         " << s.gravity << " m/s^2 toward -" << axes[static_cast<int>(s.down_axis)] << "\n"
        << "  cel shading:     " << on_off(s.cel_shading) << "\n"
        << "  skybox:          " << (s.skybox.empty() ? "(none)" : s.skybox) << "\n"
        << "  physics backend: " << s.physics_backend << "\n"
        << "  interpolation:   " << s.interpolation << "\n";
    for (const auto &[plugin, values] : s.params)
        for (const auto &[param, v] : values)
            out << "  parameter:       " << plugin << " " << param << " = " << v[0] << " " << v[1]
                << " " << v[2] << " " << v[3] << "\n";

    out << "models (" << doc.models().size() << "):\n";
    for (const Model &m : doc.models()) {
        out << "  " << m.name << ": mesh " << describe_mesh(assets, m.mesh, file, meshes) << ", parent "
            << (m.parent < 0 ? std::string("(root)") : doc.models()[static_cast<size_t>(m.parent)].name)
            << "\n    physics: dynamics " << on_off(m.dynamics) << ", gravity " << on_off(m.gravity)
            << ", mass " << m.mass << ", velocity " << vec(m.initial_velocity)
            << "\n    rigid body: restitution " << m.restitution << ", friction " << m.friction
            << ", rotates " << on_off(m.rotates) << ", angular velocity " << vec(m.angular_velocity)
            << " rad/s"
            << "\n    material: kd " << vec(m.material.kd) << ", ks " << vec(m.material.ks)
            << ", shininess " << m.material.shininess << ", texture "
            << (m.texture.empty() ? "(none)" : m.texture) << ", tint " << m.tint
            << "\n    optics: reflectivity " << m.reflectivity << ", transparency "
            << m.transparency << ", refractive index " << m.refractive_index
            << "\n    sounds: collision " << (m.collision_sound.empty() ? "(none)" : m.collision_sound)
            << ", moving " << (m.moving_sound.empty() ? "(none)" : m.moving_sound) << "\n";
    }

    out << "keyframes (" << doc.keyframes().size() << "):\n";
    for (const Keyframe &k : doc.keyframes()) {
        out << "  t = " << k.time_ms << " ms:";
        if (k.camera) {
            const glm::dvec3 euler = glm::degrees(glm::eulerAngles(k.camera->rotation));
            out << " camera at " << vec(k.camera->position) << ", rotation (deg) " << vec(euler)
                << ", fov " << k.camera->fov_degrees;
        }
        out << "\n";
        for (size_t i = 0; i < k.states.size(); ++i) {
            if (!k.states[i]) continue; // not keyed here
            const ModelState &st = *k.states[i];
            out << "    " << doc.models()[i].name << ": center " << vec(st.center) << ", angles "
                << vec(st.angles) << ", scale " << vec(st.scale) << "\n";
        }
    }
}

} // namespace

void add_info_command(CLI::App &app, std::function<int()> &run) {
    CLI::App *cmd = app.add_subcommand("info", "Print a document's models, keyframes and settings");
    auto file = std::make_shared<std::string>();
    cmd->add_option("FILE", *file, "an animation (.ani) or scene file")->required();
    cmd->callback([&run, file] {
        run = [file] {
            Environment env;
            try {
                OpenedDocument opened = open_document(env.plugins, *file);
                count_warnings(opened.warnings.size());
                std::cout << "file: " << *file << " (read by " << opened.format_id << ")\n";
                print_document(std::cout, opened.document, env.assets, *file);
                stop_if_strict(*file); // after the meshes' warnings too
                return static_cast<int>(kSuccess);
            } catch (const DocumentIoError &e) {
                std::cerr << "animator: " << e.what() << "\n";
                return static_cast<int>(kBadInput);
            }
        };
    });
}

} // namespace animator::cli
