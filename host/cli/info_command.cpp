// `animator info FILE`: a document's settings, models and keyframes, as text, or with --json the
// whole document as JSON (docs/info-json.md).
#include "cli/cli_support.hpp"
#include "cli/commands.hpp"

#include "assets/mesh.hpp"
#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "render/scene_math.hpp"

#include <nlohmann/json.hpp>

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
        << "  interpolation:   " << s.interpolation << "\n"
        << "  ambient light:   " << vec(s.ambient) << "\n";
    if (!s.render_output.empty() || s.render_width > 0 || s.render_height > 0)
        out << "  render output:   " << (s.render_output.empty() ? "(none)" : s.render_output) << ", "
            << s.render_width << "x" << s.render_height << " (0: animator render's default)\n";
    for (const auto &[plugin, values] : s.params)
        for (const auto &[param, v] : values)
            out << "  parameter:       " << plugin << " " << param << " = " << v[0] << " " << v[1]
                << " " << v[2] << " " << v[3] << "\n";

    // No lights: the renderer's own light rides with the camera (docs/rendering.md).
    out << "lights (" << s.lights.size() << ")" << (s.lights.empty() ? ": the camera's own light" : ":") << "\n";
    for (const Light &l : s.lights)
        out << "  " << l.name << ": position " << vec(l.position) << ", colour " << vec(l.colour) << ", falloff "
            << vec(l.falloff) << "\n";

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
        if (m.joint)
            out << "    joint range (deg): x " << m.joint->min.x << ".." << m.joint->max.x << ", y " << m.joint->min.y
                << ".." << m.joint->max.y << ", z " << m.joint->min.z << ".." << m.joint->max.z << "\n";
        if (m.rest != glm::dmat3(1.0)) out << "    rest shape: sheared (a fixed shape under its transform)\n";
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

namespace {

using nlohmann::json;

json numbers(const glm::dvec3 &v) { return json::array({v.x, v.y, v.z}); }

json state_json(const ModelState &s) {
    return {{"center", numbers(s.center)}, {"angles", numbers(s.angles)}, {"scale", numbers(s.scale)}};
}

json camera_json(const CameraState &c) {
    return {{"position", numbers(c.position)},
            {"rotation", json::array({c.rotation.w, c.rotation.x, c.rotation.y, c.rotation.z})},
            {"fov", c.fov_degrees}};
}

// The whole document (docs/info-json.md): every number as read, and each model's world matrix at
// t = 0, column-major, as the renderer and the physics place it.
json document_json(const OpenedDocument &opened, const std::string &file) {
    const Document &doc = opened.document;
    const Settings &s = doc.settings();
    json settings = {{"max_time_ms", s.max_time_ms},
                     {"gravity", s.gravity},
                     {"down", std::string(1, "xyz"[static_cast<int>(s.down_axis)])},
                     {"cel_shading", s.cel_shading},
                     {"skybox", s.skybox},
                     {"physics_backend", s.physics_backend},
                     {"interpolation", s.interpolation},
                     {"ambient", numbers(s.ambient)},
                     {"render", {{"output", s.render_output}, {"width", s.render_width}, {"height", s.render_height}}}};
    json lights = json::array();
    for (const Light &l : s.lights)
        lights.push_back({{"name", l.name},
                          {"position", numbers(l.position)},
                          {"colour", numbers(l.colour)},
                          {"falloff", numbers(l.falloff)}});
    std::vector<ModelPose> poses;
    const Keyframe &first = doc.keyframe_at(0); // it keys every model
    for (const auto &state : first.states) {
        ModelPose p;
        if (state) {
            p.center = state->center;
            p.angles = state->angles;
            p.scale = state->scale;
        }
        poses.push_back(p);
    }
    std::vector<glm::dmat4> world;
    world_matrices(doc.models(), poses, world);
    apply_rest_shapes(doc.models(), world); // where each mesh is
    json models = json::array();
    for (size_t i = 0; i < doc.models().size(); ++i) {
        const Model &m = doc.models()[i];
        json w = json::array();
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) w.push_back(world[i][c][r]);
        json rest = json::array();
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) rest.push_back(m.rest[c][r]);
        json joint = m.joint ? json{{"min", numbers(m.joint->min)}, {"max", numbers(m.joint->max)}} : json(nullptr);
        models.push_back({{"name", m.name},
                          {"mesh", m.mesh},
                          {"parent", m.parent >= 0 ? json(doc.models()[static_cast<size_t>(m.parent)].name) : json(nullptr)},
                          {"world", w},
                          {"rest", rest},
                          {"joint", joint},
                          {"material", {{"kd", numbers(m.material.kd)}, {"ks", numbers(m.material.ks)},
                                        {"shininess", m.material.shininess}}},
                          {"texture", m.texture},
                          {"tint", m.tint},
                          {"reflectivity", m.reflectivity},
                          {"transparency", m.transparency},
                          {"refractive_index", m.refractive_index},
                          {"physics", {{"dynamics", m.dynamics}, {"gravity", m.gravity}, {"mass", m.mass},
                                       {"velocity", numbers(m.initial_velocity)}, {"restitution", m.restitution},
                                       {"friction", m.friction}, {"rotates", m.rotates},
                                       {"angular_velocity", numbers(m.angular_velocity)}}},
                          {"sounds", {{"collision", m.collision_sound}, {"moving", m.moving_sound}}}});
    }
    json keyframes = json::array();
    for (const Keyframe &k : doc.keyframes()) {
        json states = json::object();
        for (size_t i = 0; i < k.states.size(); ++i)
            if (k.states[i]) states[doc.models()[i].name] = state_json(*k.states[i]);
        keyframes.push_back({{"time_ms", k.time_ms},
                             {"camera", k.camera ? camera_json(*k.camera) : json(nullptr)},
                             {"states", states}});
    }
    return {{"file", file},          {"format", opened.format_id}, {"settings", settings}, {"models", models},
            {"keyframes", keyframes}, {"lights", lights},  {"warnings", opened.warnings}};
}

} // namespace

void add_info_command(CLI::App &app, std::function<int()> &run) {
    CLI::App *cmd = app.add_subcommand("info", "Print a document's models, keyframes and settings");
    auto file = std::make_shared<std::string>();
    auto as_json = std::make_shared<bool>(false);
    cmd->add_option("FILE", *file, "an animation (.ani) or scene file")->required();
    cmd->add_flag("--json", *as_json, "the whole document as JSON on stdout (docs/info-json.md): every model's name, "
                                      "mesh and world matrix at t = 0, the settings, keyframes, lights and warnings");
    cmd->callback([&run, file, as_json] {
        run = [file, as_json] {
            Environment env;
            try {
                OpenedDocument opened = open_document(env.plugins, *file);
                count_warnings(opened.warnings.size());
                if (*as_json) {
                    stop_if_strict(*file);
                    std::cout << document_json(opened, *file).dump(2) << "\n";
                    return static_cast<int>(kSuccess);
                }
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
