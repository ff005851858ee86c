#include "lua_scene.hpp"

#include "lua_sandbox.hpp"

#include <animator/assets.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/euler_angles.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

namespace lua_scene {

namespace {

const char *kNodeMeta = "animator.node";
const char *kMaterialMeta = "animator.material";

struct Material {
    glm::dvec3 kd{0.7}, ks{0.3};
    double shininess = 25.0;
};

struct Node {
    std::string name;
    std::string mesh; // "" for gr.node and gr.joint
    int line = 0;     // where it was made
    glm::dmat4 local{1.0};
    int parent = -1;
    std::vector<int> children;
    int material = -1;
    bool dynamics = false, gravity = false;
    double mass = 1.0;
    glm::dvec3 velocity{0.0};
    std::string texture, collision_sound, moving_sound;
    double tint = 0.0, reflectivity = 0.0, transparency = 0.0, refractive_index = 1.0;
};

struct Scene {
    std::string path;
    const ani_host *host = nullptr;
    std::vector<Node> nodes;
    std::vector<Material> materials;
    std::map<std::string, int> by_name;
    std::optional<int> settings_line, camera_line;
    std::int64_t max_time_ms = 60000;
    double gravity = 9.81;
    int down = ANI_AXIS_Y;
    bool cel = false;
    std::string skybox, backend = "physics.custom", interpolation = "interpolation.linear";
    ani_camera_state camera{{0, 0, 0}, {1, 0, 0, 0}, 50.0};
};

Scene &scene_of(lua_State *L) {
    lua_getfield(L, LUA_REGISTRYINDEX, "animator.scene");
    auto *scene = static_cast<Scene *>(lua_touserdata(L, -1));
    lua_pop(L, 1);
    return *scene;
}

int current_line(lua_State *L) {
    lua_Debug ar;
    if (lua_getstack(L, 1, &ar) && lua_getinfo(L, "l", &ar)) return ar.currentline;
    return 0;
}

Node &check_node(lua_State *L, int arg) {
    auto *index = static_cast<int *>(luaL_checkudata(L, arg, kNodeMeta));
    return scene_of(L).nodes[static_cast<size_t>(*index)];
}

int node_index(lua_State *L, int arg) { return *static_cast<int *>(luaL_checkudata(L, arg, kNodeMeta)); }

int push_node(lua_State *L, Node node) {
    Scene &scene = scene_of(L);
    if (node.name.empty()) return luaL_error(L, "a node needs a non-empty name");
    auto [it, fresh] = scene.by_name.emplace(node.name, static_cast<int>(scene.nodes.size()));
    if (!fresh)
        return luaL_error(L, "a node named '%s' already exists (made on line %d)", node.name.c_str(),
                          scene.nodes[static_cast<size_t>(it->second)].line);
    node.line = current_line(L);
    scene.nodes.push_back(std::move(node));
    *static_cast<int *>(lua_newuserdatauv(L, sizeof(int), 0)) = static_cast<int>(scene.nodes.size() - 1);
    luaL_setmetatable(L, kNodeMeta);
    return 1;
}

// {a, b, c}: exactly `n` numbers.
std::vector<double> numbers(lua_State *L, int arg, int n, const char *what) {
    luaL_checktype(L, arg, LUA_TTABLE);
    if (static_cast<int>(lua_rawlen(L, arg)) != n)
        luaL_error(L, "%s must be a table of %d numbers", what, n);
    std::vector<double> out;
    for (int i = 1; i <= n; ++i) {
        lua_rawgeti(L, arg, i);
        int ok = 0;
        const double v = lua_tonumberx(L, -1, &ok);
        if (!ok || !std::isfinite(v)) luaL_error(L, "%s must hold finite numbers (item %d is not)", what, i);
        out.push_back(v);
        lua_pop(L, 1);
    }
    return out;
}

glm::dvec3 vec3_field(lua_State *L, int table, const char *key) {
    lua_getfield(L, table, key);
    const int at = lua_gettop(L);
    const auto v = numbers(L, at, 3, key);
    lua_pop(L, 1);
    return {v[0], v[1], v[2]};
}

// Every key of the options table at `arg` must be one of `allowed`.
void check_keys(lua_State *L, int arg, const char *function, std::initializer_list<const char *> allowed) {
    luaL_checktype(L, arg, LUA_TTABLE);
    lua_pushnil(L);
    while (lua_next(L, arg) != 0) {
        lua_pop(L, 1);
        bool known = false;
        if (lua_type(L, -1) == LUA_TSTRING)
            for (const char *a : allowed) known = known || std::string(lua_tostring(L, -1)) == a;
        if (!known) {
            std::string list;
            for (const char *a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
            luaL_error(L, "unknown key '%s' in %s; expected %s", luaL_tolstring(L, -1, nullptr),
                       function, list.c_str());
        }
    }
}

bool has(lua_State *L, int table, const char *key) {
    const bool present = lua_getfield(L, table, key) != LUA_TNIL;
    lua_pop(L, 1);
    return present;
}

double number_field(lua_State *L, int table, const char *key, double lo, double hi) {
    lua_getfield(L, table, key);
    int ok = 0;
    const double v = lua_tonumberx(L, -1, &ok);
    lua_pop(L, 1);
    if (!ok || !std::isfinite(v)) luaL_error(L, "'%s' must be a number", key);
    if (v < lo || v > hi) luaL_error(L, "'%s' must be in [%f, %f], got %f", key, lo, hi, v);
    return v;
}

bool bool_field(lua_State *L, int table, const char *key) {
    if (lua_getfield(L, table, key) != LUA_TBOOLEAN) luaL_error(L, "'%s' must be true or false", key);
    const bool b = lua_toboolean(L, -1);
    lua_pop(L, 1);
    return b;
}

std::string string_field(lua_State *L, int table, const char *key) {
    if (lua_getfield(L, table, key) != LUA_TSTRING) luaL_error(L, "'%s' must be a string", key);
    std::string s = lua_tostring(L, -1);
    lua_pop(L, 1);
    return s;
}

// ---- gr.* --------------------------------------------------------------------------------

int gr_node(lua_State *L) {
    Node n;
    n.name = luaL_checkstring(L, 1);
    return push_node(L, n);
}

int gr_mesh(lua_State *L) {
    Node n;
    n.mesh = luaL_checkstring(L, 1);
    n.name = luaL_optstring(L, 2, n.mesh.c_str());
    if (n.mesh.empty()) return luaL_error(L, "gr.mesh needs a mesh id");
    const Scene &scene = scene_of(L);
    const auto *assets = scene.host && scene.host->get_extension
                             ? static_cast<const ani_assets_ext *>(scene.host->get_extension(scene.host, ANI_EXT_ASSETS))
                             : nullptr;
    if (assets) {
        char where[2048];
        if (!assets->resolve(scene.host, ANI_ASSET_MESH, n.mesh.c_str(), scene.path.c_str(), where, sizeof where))
            return luaL_error(L, "unknown mesh '%s' (%s)", n.mesh.c_str(), where);
    }
    return push_node(L, n);
}

// gr.joint(name, {xmin, xinit, xmax}, {ymin, yinit, ymax}): a node turned to its initial angles.
// The ranges are checked, not kept: the document has no joint limits yet.
int gr_joint(lua_State *L) {
    Node n;
    n.name = luaL_checkstring(L, 1);
    const auto x = numbers(L, 2, 3, "the joint's x range");
    const auto y = numbers(L, 3, 3, "the joint's y range");
    for (const auto &r : {x, y})
        if (!(r[0] <= r[1] && r[1] <= r[2])) return luaL_error(L, "a joint range must be {min, init, max} with min <= init <= max");
    n.local = glm::rotate(glm::dmat4(1.0), glm::radians(y[1]), glm::dvec3(0, 1, 0)) *
              glm::rotate(glm::dmat4(1.0), glm::radians(x[1]), glm::dvec3(1, 0, 0));
    return push_node(L, n);
}

int gr_material(lua_State *L) {
    Material m;
    const auto kd = numbers(L, 1, 3, "kd");
    const auto ks = numbers(L, 2, 3, "ks");
    m.kd = {kd[0], kd[1], kd[2]};
    m.ks = {ks[0], ks[1], ks[2]};
    for (double c : {kd[0], kd[1], kd[2], ks[0], ks[1], ks[2]})
        if (c < 0.0 || c > 1.0) return luaL_error(L, "material colours must be in [0, 1]");
    m.shininess = luaL_checknumber(L, 3);
    if (!(m.shininess >= 0.0) || !std::isfinite(m.shininess)) return luaL_error(L, "shininess must be >= 0");
    Scene &scene = scene_of(L);
    scene.materials.push_back(m);
    *static_cast<int *>(lua_newuserdatauv(L, sizeof(int), 0)) = static_cast<int>(scene.materials.size() - 1);
    luaL_setmetatable(L, kMaterialMeta);
    return 1;
}

int gr_settings(lua_State *L) {
    Scene &scene = scene_of(L);
    if (scene.settings_line) return luaL_error(L, "gr.settings is called twice (first on line %d)", *scene.settings_line);
    scene.settings_line = current_line(L);
    check_keys(L, 1, "gr.settings", {"gravity", "down", "max_time", "skybox", "cel", "backend", "interpolation"});
    if (has(L, 1, "gravity")) scene.gravity = number_field(L, 1, "gravity", -1e6, 1e6);
    if (has(L, 1, "down")) {
        const std::string d = string_field(L, 1, "down");
        if (d != "x" && d != "y" && d != "z") return luaL_error(L, "'down' must be 'x', 'y' or 'z', got '%s'", d.c_str());
        scene.down = d == "x" ? ANI_AXIS_X : d == "y" ? ANI_AXIS_Y : ANI_AXIS_Z;
    }
    if (has(L, 1, "max_time"))
        scene.max_time_ms = std::llround(1000.0 * number_field(L, 1, "max_time", 1.0, 300000.0));
    if (has(L, 1, "skybox")) scene.skybox = string_field(L, 1, "skybox");
    if (has(L, 1, "cel")) scene.cel = bool_field(L, 1, "cel");
    if (has(L, 1, "backend")) scene.backend = string_field(L, 1, "backend");
    if (has(L, 1, "interpolation")) scene.interpolation = string_field(L, 1, "interpolation");
    return 0;
}

int gr_camera(lua_State *L) {
    Scene &scene = scene_of(L);
    if (scene.camera_line) return luaL_error(L, "gr.camera is called twice (first on line %d)", *scene.camera_line);
    scene.camera_line = current_line(L);
    check_keys(L, 1, "gr.camera", {"eye", "look_at", "up", "fov"});
    const glm::dvec3 eye = has(L, 1, "eye") ? vec3_field(L, 1, "eye") : glm::dvec3(0.0);
    const glm::dvec3 at = has(L, 1, "look_at") ? vec3_field(L, 1, "look_at") : eye + glm::dvec3(0, 0, -1);
    const glm::dvec3 up = has(L, 1, "up") ? vec3_field(L, 1, "up") : glm::dvec3(0, 1, 0);
    const glm::dvec3 forward = at - eye;
    if (glm::length(forward) < 1e-12) return luaL_error(L, "the camera's look_at must differ from its eye");
    if (glm::length(glm::cross(glm::normalize(forward), up)) < 1e-9)
        return luaL_error(L, "the camera's up must not be parallel to its view direction");
    const glm::dquat q = glm::quatLookAtRH(glm::normalize(forward), glm::normalize(up));
    scene.camera.position = {eye.x, eye.y, eye.z};
    scene.camera.rotation = {q.w, q.x, q.y, q.z};
    if (has(L, 1, "fov")) {
        scene.camera.fov_degrees = number_field(L, 1, "fov", 0.0, 180.0);
        if (scene.camera.fov_degrees <= 0.0 || scene.camera.fov_degrees >= 180.0)
            return luaL_error(L, "'fov' must be strictly between 0 and 180 degrees");
    }
    return 0;
}

// ---- node methods --------------------------------------------------------------------------

int node_translate(lua_State *L) {
    Node &n = check_node(L, 1);
    const glm::dvec3 v(luaL_checknumber(L, 2), luaL_checknumber(L, 3), luaL_checknumber(L, 4));
    n.local = glm::translate(glm::dmat4(1.0), v) * n.local; // CS488: later calls apply after earlier ones
    return 0;
}

int node_rotate(lua_State *L) {
    Node &n = check_node(L, 1);
    const std::string axis = luaL_checkstring(L, 2);
    const double degrees = luaL_checknumber(L, 3);
    glm::dvec3 a;
    if (axis == "x" || axis == "X") a = {1, 0, 0};
    else if (axis == "y" || axis == "Y") a = {0, 1, 0};
    else if (axis == "z" || axis == "Z") a = {0, 0, 1};
    else return luaL_error(L, "rotate's axis must be 'x', 'y' or 'z', got '%s'", axis.c_str());
    n.local = glm::rotate(glm::dmat4(1.0), glm::radians(degrees), a) * n.local;
    return 0;
}

int node_scale(lua_State *L) {
    Node &n = check_node(L, 1);
    const glm::dvec3 s(luaL_checknumber(L, 2), luaL_checknumber(L, 3), luaL_checknumber(L, 4));
    if (!(s.x > 0.0 && s.y > 0.0 && s.z > 0.0)) return luaL_error(L, "scale factors must be > 0");
    n.local = glm::scale(glm::dmat4(1.0), s) * n.local;
    return 0;
}

int node_add_child(lua_State *L) {
    const int parent = node_index(L, 1);
    const int child = node_index(L, 2);
    Scene &scene = scene_of(L);
    Node &c = scene.nodes[static_cast<size_t>(child)];
    if (c.parent >= 0)
        return luaL_error(L, "node '%s' is already a child of '%s'", c.name.c_str(),
                          scene.nodes[static_cast<size_t>(c.parent)].name.c_str());
    for (int up = parent; up >= 0; up = scene.nodes[static_cast<size_t>(up)].parent)
        if (up == child) return luaL_error(L, "adding '%s' under '%s' would make a cycle", c.name.c_str(),
                                           scene.nodes[static_cast<size_t>(parent)].name.c_str());
    c.parent = parent;
    scene.nodes[static_cast<size_t>(parent)].children.push_back(child);
    return 0;
}

int node_set_material(lua_State *L) {
    Node &n = check_node(L, 1);
    n.material = *static_cast<int *>(luaL_checkudata(L, 2, kMaterialMeta));
    return 0;
}

int node_set_physics(lua_State *L) {
    Node &n = check_node(L, 1);
    check_keys(L, 2, "set_physics", {"dynamics", "gravity", "mass", "velocity"});
    if (has(L, 2, "dynamics")) n.dynamics = bool_field(L, 2, "dynamics");
    if (has(L, 2, "gravity")) n.gravity = bool_field(L, 2, "gravity");
    if (has(L, 2, "mass")) {
        n.mass = number_field(L, 2, "mass", 0.0, 1e30);
        if (n.mass <= 0.0) return luaL_error(L, "'mass' must be > 0");
    }
    if (has(L, 2, "velocity")) n.velocity = vec3_field(L, 2, "velocity");
    return 0;
}

int node_set_texture(lua_State *L) {
    check_node(L, 1).texture = luaL_checkstring(L, 2);
    return 0;
}

int node_set_tint(lua_State *L) {
    Node &n = check_node(L, 1);
    n.tint = luaL_checknumber(L, 2);
    if (!(n.tint >= 0.0 && n.tint <= 1.0)) return luaL_error(L, "tint must be in [0, 1]");
    return 0;
}

int node_set_optics(lua_State *L) {
    Node &n = check_node(L, 1);
    check_keys(L, 2, "set_optics", {"reflectivity", "transparency", "refractive_index"});
    if (has(L, 2, "reflectivity")) n.reflectivity = number_field(L, 2, "reflectivity", 0.0, 1.0);
    if (has(L, 2, "transparency")) n.transparency = number_field(L, 2, "transparency", 0.0, 1.0);
    if (has(L, 2, "refractive_index")) {
        n.refractive_index = number_field(L, 2, "refractive_index", 0.0, 100.0);
        if (n.refractive_index <= 0.0) return luaL_error(L, "'refractive_index' must be > 0");
    }
    return 0;
}

int node_set_sound(lua_State *L) {
    Node &n = check_node(L, 1);
    check_keys(L, 2, "set_sound", {"collision", "moving"});
    if (has(L, 2, "collision")) n.collision_sound = string_field(L, 2, "collision");
    if (has(L, 2, "moving")) n.moving_sound = string_field(L, 2, "moving");
    return 0;
}

void register_api(lua_State *L) {
    const luaL_Reg node_methods[] = {
        {"translate", node_translate},     {"rotate", node_rotate},
        {"scale", node_scale},             {"add_child", node_add_child},
        {"set_material", node_set_material}, {"set_physics", node_set_physics},
        {"set_texture", node_set_texture}, {"set_tint", node_set_tint},
        {"set_optics", node_set_optics},   {"set_sound", node_set_sound},
        {nullptr, nullptr}};
    luaL_newmetatable(L, kNodeMeta);
    luaL_newlib(L, node_methods);
    lua_setfield(L, -2, "__index");
    lua_pushliteral(L, "locked");
    lua_setfield(L, -2, "__metatable");
    lua_pop(L, 1);
    luaL_newmetatable(L, kMaterialMeta);
    lua_pushliteral(L, "locked");
    lua_setfield(L, -2, "__metatable");
    lua_pop(L, 1);

    const luaL_Reg gr[] = {{"node", gr_node},         {"mesh", gr_mesh},
                           {"joint", gr_joint},       {"material", gr_material},
                           {"settings", gr_settings}, {"camera", gr_camera},
                           {nullptr, nullptr}};
    luaL_newlib(L, gr);
    lua_setglobal(L, "gr");
}

void warn(const ani_host *host, const std::string &message) {
    if (host && host->log) host->log(host, ANI_LOG_WARNING, "format.lua", message.c_str());
}

// The node's local matrix as a keyframe state: T(center) Rx Ry Rz S(scale). A shear (a
// non-uniform scale under a rotation, in CS488 call order) cannot be held and is dropped.
bool to_state(const glm::dmat4 &m, const Node &node, const std::string &path, const ani_host *host,
              ani_model_state &state, std::string &error) {
    glm::dvec3 axis[3] = {glm::dvec3(m[0]), glm::dvec3(m[1]), glm::dvec3(m[2])};
    glm::dvec3 scale(0.0);
    for (int i = 0; i < 3; ++i) {
        scale[i] = glm::length(axis[i]);
        if (!(scale[i] > 1e-12) || !std::isfinite(scale[i])) {
            error = path + ":" + std::to_string(node.line) + ": node '" + node.name + "' has a zero or invalid scale";
            return false;
        }
        axis[i] /= scale[i];
    }
    if (std::abs(glm::dot(axis[0], axis[1])) > 1e-6 || std::abs(glm::dot(axis[1], axis[2])) > 1e-6 ||
        std::abs(glm::dot(axis[0], axis[2])) > 1e-6)
        warn(host, path + ":" + std::to_string(node.line) + ": node '" + node.name +
                       "' is sheared (scaled unevenly after a rotation); the shear is dropped");
    glm::dmat4 rotation(1.0);
    rotation[0] = glm::dvec4(axis[0], 0.0);
    rotation[1] = glm::dvec4(glm::normalize(axis[1] - glm::dot(axis[1], axis[0]) * axis[0]), 0.0);
    rotation[2] = glm::dvec4(glm::cross(glm::dvec3(rotation[0]), glm::dvec3(rotation[1])), 0.0);
    double ax = 0, ay = 0, az = 0;
    glm::extractEulerAngleXYZ(rotation, ax, ay, az);
    auto wrap = [](double radians) {
        double d = std::fmod(glm::degrees(radians), 360.0);
        if (d < 0.0) d += 360.0;
        if (d >= 360.0 || std::abs(d - 360.0) < 1e-9 || std::abs(d) < 1e-9) d = 0.0;
        return d;
    };
    state.center = {m[3].x, m[3].y, m[3].z};
    state.angles = {wrap(ax), wrap(ay), wrap(az)};
    state.scale = {scale.x, scale.y, scale.z};
    state.turn = {0.0, 0.0, 0.0};
    return true;
}

} // namespace

bool read_scene(const char *path, const ani_host *host, ani::OwnedDocument &doc, std::string &error) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = std::string(path) + ": cannot open the file";
        return false;
    }
    std::ostringstream text;
    text << in.rdbuf();

    Scene scene;
    scene.path = path;
    scene.host = host;
    Sandbox sandbox;
    lua_State *L = sandbox.state();
    if (!L) {
        error = std::string(path) + ": cannot create a Lua state";
        return false;
    }
    lua_pushlightuserdata(L, &scene);
    lua_setfield(L, LUA_REGISTRYINDEX, "animator.scene");
    register_api(L);
    if (!sandbox.run(path, text.str(), 1, error)) return false;
    auto *root_index = static_cast<int *>(luaL_testudata(L, -1, kNodeMeta));
    if (!root_index) {
        error = std::string(path) + ": the scene must return its root node (return rootnode), got " +
                luaL_typename(L, -1);
        return false;
    }

    // Models in depth-first order, so a parent always comes before its children. A root without
    // a mesh is not a model: its transform moves into its children's.
    const Node &root = scene.nodes[static_cast<size_t>(*root_index)];
    struct Visit {
        int node;
        int parent_model;
        glm::dmat4 prefix;
    };
    std::vector<Visit> stack;
    if (root.mesh.empty()) {
        for (auto it = root.children.rbegin(); it != root.children.rend(); ++it) stack.push_back({*it, -1, root.local});
    } else {
        stack.push_back({*root_index, -1, glm::dmat4(1.0)});
    }
    std::vector<ani_model_state> states;
    while (!stack.empty()) {
        const Visit v = stack.back();
        stack.pop_back();
        const Node &n = scene.nodes[static_cast<size_t>(v.node)];
        ani_model_desc m = doc.default_model(n.name, n.mesh);
        m.parent = v.parent_model;
        if (n.material >= 0) {
            const Material &mat = scene.materials[static_cast<size_t>(n.material)];
            m.kd = {mat.kd.x, mat.kd.y, mat.kd.z};
            m.ks = {mat.ks.x, mat.ks.y, mat.ks.z};
            m.shininess = mat.shininess;
        }
        m.texture = doc.keep(n.texture);
        m.tint = n.tint;
        m.reflectivity = n.reflectivity;
        m.transparency = n.transparency;
        m.refractive_index = n.refractive_index;
        m.dynamics = n.dynamics;
        m.gravity = n.gravity;
        m.mass = n.mass;
        m.initial_velocity = {n.velocity.x, n.velocity.y, n.velocity.z};
        m.collision_sound = doc.keep(n.collision_sound);
        m.moving_sound = doc.keep(n.moving_sound);
        ani_model_state state{};
        if (!to_state(v.prefix * n.local, n, path, host, state, error)) return false;
        const int index = static_cast<int>(doc.models.size());
        doc.models.push_back(m);
        states.push_back(state);
        for (auto it = n.children.rbegin(); it != n.children.rend(); ++it)
            stack.push_back({*it, index, glm::dmat4(1.0)});
    }

    doc.default_settings();
    ani_settings_view &s = doc.view.settings;
    s.max_time_ms = scene.max_time_ms;
    s.gravity = scene.gravity;
    s.down_axis = scene.down;
    s.cel_shading = scene.cel ? 1 : 0;
    s.skybox = doc.keep(scene.skybox);
    s.physics_backend = doc.keep(scene.backend);
    s.interpolation = doc.keep(scene.interpolation);
    ani_keyframe_view k{};
    k.struct_size = sizeof k;
    k.time_ms = 0;
    k.camera = scene.camera;
    k.camera_keyed = 1;
    doc.keyed.emplace_back(states.size(), 1);
    doc.keyframes.push_back(k);
    doc.states.push_back(std::move(states));
    doc.finish();
    return true;
}

} // namespace lua_scene
