#include "lua_scene.hpp"

#include "lua_sandbox.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/euler_angles.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <deque>
#include <map>
#include <optional>
#include <set>

namespace lua_scene {

namespace {

const char *kNodeMeta = "animator.node";
const char *kMaterialMeta = "animator.material";
const char *kLightMeta = "animator.light";

// What the scene may build on our side of the sandbox, beyond Lua's own memory budget: nodes,
// their names and sound and texture names are copies that outlive Lua's strings.
constexpr std::size_t kSceneDataBudget = 256u << 20; // 256 MiB
// How far up add_child looks for a cycle: deeper trees are refused, so that building one
// cannot cost time that no instruction count sees (a chain of n nodes would cost n^2 / 2).
constexpr int kMaxDepth = 1000;
// How many ancestors add_child may visit in all, looking for a cycle, once some node is under more
// than one parent (an instance): a graph of instances may have many paths up from a node.
constexpr std::size_t kWalkBudget = 50'000'000;
// Our torus mesh's tube radius (its ring's is 1).
constexpr double kTorusTube = 0.3;

struct Material {
    glm::dvec3 kd{0.7}, ks{0.3};
    double shininess = 25.0;
};

struct Node {
    std::string name;
    std::string mesh; // "" for gr.node and gr.joint
    int line = 0;     // where it was made
    glm::dmat4 local{1.0};
    // Where the node's mesh sits in the node's frame (a ray-tracer primitive's centre and size):
    // its own, not its children's.
    glm::dmat4 placement{1.0};
    // Its parents: more than one when it is an instance (the course's A4 adds one node under
    // several); each use becomes a model of its own.
    std::vector<int> parents;
    std::vector<int> children;
    unsigned mark = 0; // add_child's visit stamp
    int material = -1;
    bool dynamics = false, gravity = false;
    double mass = 1.0;
    glm::dvec3 velocity{0.0};
    double restitution = 1.0, friction = 0.0; // rigid-body settings (issue 18)
    bool rotates = false;
    glm::dvec3 angular_velocity{0.0};
    std::string texture, collision_sound, moving_sound;
    double tint = 0.0, reflectivity = 0.0, transparency = 0.0, refractive_index = 1.0;
    bool joint = false; // a gr.joint: its ranges are kept
    glm::dvec3 joint_min{0.0}, joint_max{0.0};
};

// The scene as the script builds it.
//
// Every gr.* function and node method may call back into the scene's own Lua code: reading a
// field of an options table runs its __index, an unknown key's name runs its __tostring, and any
// allocation may run a __gc finalizer. That code may call gr.* in turn. So no function holds a
// reference into `nodes` or `materials` across a Lua call: each reads and checks all of its
// arguments first, then looks its node up and writes in one step with no Lua call between. The
// deques (which never move an element when they grow) are a second line of defence.
struct Scene {
    std::deque<Node> nodes;
    std::deque<Material> materials;
    std::map<std::string, int> by_name;
    // Names used twice, or empty (the course's code allows both): each node renamed to be unique,
    // with its line, as written and as renamed.
    struct Rename {
        int line;
        std::string from, to;
    };
    std::vector<Rename> renames;
    // What the script did that the course's code allowed and we take leniently, by line (said
    // as warnings "path:line: text" at the end).
    std::vector<std::pair<int, std::string>> notes;
    std::size_t data_bytes = 0;
    std::optional<int> settings_line, camera_line;
    // gr.light's lights; those gr.render is given become the document's.
    struct Light {
        glm::dvec3 position, colour, falloff;
    };
    std::deque<Light> lights;
    std::optional<int> render_line; // gr.render's first call: its root is the scene's when none is returned
    int render_root = -1;
    bool render_again = false;
    bool instanced = false; // some node is under more than one parent
    unsigned epoch = 0;     // add_child's search for a cycle
    std::vector<int> walk;
    std::size_t walk_steps = 0;
    std::map<std::string, int> next_ending; // unique_name's: per stem, every lower ending is taken
    SceneResult settings; // the settings and camera; its models are filled at the end
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

// Counts `bytes` of scene data against kSceneDataBudget.
void charge(lua_State *L, std::size_t bytes) {
    Scene &scene = scene_of(L);
    scene.data_bytes += bytes;
    if (scene.data_bytes > kSceneDataBudget)
        luaL_error(L, "the scene made more than its budget of %d MiB of nodes and names",
                   static_cast<int>(kSceneDataBudget >> 20));
}

// The node at argument `arg`, as an index: a reference would not survive a call into Lua.
int check_node(lua_State *L, int arg) { return *static_cast<int *>(luaL_checkudata(L, arg, kNodeMeta)); }

Node &node_at(lua_State *L, int index) { return scene_of(L).nodes[static_cast<size_t>(index)]; }

// A name, a mesh, an axis, a file: text without NUL bytes. The document holds C strings, so a
// NUL would cut the name short ('ab\0cd' would be 'ab', '\0x' no name at all).
std::string checked_string(lua_State *L, int arg) {
    size_t size = 0;
    const char *s = luaL_checklstring(L, arg, &size);
    std::string out(s, size);
    if (out.find('\0') != std::string::npos)
        luaL_argerror(L, arg, "holds a NUL byte (\\0), which no name, mesh or file may");
    return out;
}

// A name no node has yet, Blender's way: the name itself when free, otherwise its stem (the name
// without a ".NNN" ending) with the first free ending .001, .002, ...; an empty name is "node".
// `taken(name)` says whether a name is used; `next` keeps, per stem, the ending to try first (names
// are never freed, so the endings below it stay taken): n uses of one name cost n, not n^2 / 2.
template <class Taken>
std::string unique_name(const std::string &wanted, std::map<std::string, int> &next, const Taken &taken) {
    if (!wanted.empty() && !taken(wanted)) return wanted;
    std::string stem = wanted.empty() ? "node" : wanted;
    const std::size_t dot = stem.size() >= 4 ? stem.size() - 4 : std::string::npos;
    if (dot != std::string::npos && stem[dot] == '.' && dot > 0 &&
        std::all_of(stem.begin() + static_cast<std::ptrdiff_t>(dot) + 1, stem.end(),
                    [](char c) { return c >= '0' && c <= '9'; }))
        stem.resize(dot);
    if (wanted.empty() && !taken(stem)) return stem;
    int &k = next[stem];
    for (k = std::max(k, 1);; ++k) {
        char ending[16];
        std::snprintf(ending, sizeof ending, ".%03d", k);
        if (!taken(stem + ending)) return stem + ending;
    }
}

int push_node(lua_State *L, Node node) {
    // The name is kept twice (in the node and as the key of by_name), with a map entry's overhead;
    // a renamed node's first name too.
    // A renamed node's stem, with an entry's overhead, may be kept once more by next_ending.
    charge(L, sizeof(Node) + 4 * node.name.size() + node.mesh.size() + 160);
    node.line = current_line(L);
    Scene &scene = scene_of(L);
    const int index = static_cast<int>(scene.nodes.size());
    const std::string name =
        unique_name(node.name, scene.next_ending, [&](const std::string &n) { return scene.by_name.count(n) > 0; });
    if (name != node.name) scene.renames.push_back({node.line, node.name, name});
    node.name = name;
    scene.by_name.emplace(node.name, index);
    scene.nodes.push_back(std::move(node));
    // The userdata's allocation may run finalizers that make nodes too: `index` is already fixed.
    *static_cast<int *>(lua_newuserdatauv(L, sizeof(int), 0)) = index;
    luaL_setmetatable(L, kNodeMeta);
    return 1;
}

// {a, b, c}: exactly `n` finite numbers (read raw: no metamethod runs).
std::vector<double> numbers(lua_State *L, int arg, int n, const char *what) {
    luaL_checktype(L, arg, LUA_TTABLE);
    if (lua_rawlen(L, arg) != static_cast<lua_Unsigned>(n))
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

// Every key of the options table at `arg` must be one of `allowed`.
void check_keys(lua_State *L, int arg, const char *function, std::initializer_list<const char *> allowed) {
    luaL_checktype(L, arg, LUA_TTABLE);
    lua_pushnil(L);
    while (lua_next(L, arg) != 0) {
        lua_pop(L, 1);
        bool known = false;
        if (lua_type(L, -1) == LUA_TSTRING) {
            size_t size = 0;
            const char *key = lua_tolstring(L, -1, &size); // a key string, not converted in place
            for (const char *a : allowed) known = known || std::string(key, size) == a;
        }
        if (!known) {
            std::string list;
            for (const char *a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
            size_t size = 0;
            const char *text = luaL_tolstring(L, -1, &size);
            std::string shown;
            for (size_t i = 0; i < size; ++i)
                shown += text[i] == '\0' ? std::string("\\0") : std::string(1, text[i]);
            luaL_error(L, "unknown key '%s' in %s; expected %s", shown.c_str(), function,
                       list.c_str());
        }
    }
}

// The optional fields of an options table, each read once (lua_getfield may run __index).
std::optional<double> number_field(lua_State *L, int table, const char *key, double lo, double hi) {
    if (lua_getfield(L, table, key) == LUA_TNIL) {
        lua_pop(L, 1);
        return std::nullopt;
    }
    int ok = 0;
    const double v = lua_tonumberx(L, -1, &ok);
    lua_pop(L, 1);
    if (!ok || !std::isfinite(v)) luaL_error(L, "'%s' must be a number", key);
    if (v < lo || v > hi) luaL_error(L, "'%s' must be in [%f, %f], got %f", key, lo, hi, v);
    return v;
}

std::optional<bool> bool_field(lua_State *L, int table, const char *key) {
    const int type = lua_getfield(L, table, key);
    const bool b = lua_toboolean(L, -1);
    lua_pop(L, 1);
    if (type == LUA_TNIL) return std::nullopt;
    if (type != LUA_TBOOLEAN) luaL_error(L, "'%s' must be true or false", key);
    return b;
}

std::optional<std::string> string_field(lua_State *L, int table, const char *key) {
    const int type = lua_getfield(L, table, key);
    if (type == LUA_TNIL) {
        lua_pop(L, 1);
        return std::nullopt;
    }
    if (type != LUA_TSTRING) luaL_error(L, "'%s' must be a string", key);
    size_t size = 0;
    const char *s = lua_tolstring(L, -1, &size);
    std::string out(s, size);
    lua_pop(L, 1);
    if (out.find('\0') != std::string::npos)
        luaL_error(L, "'%s' holds a NUL byte (\\0), which no name may", key);
    return out;
}

std::optional<glm::dvec3> vec3_field(lua_State *L, int table, const char *key) {
    if (lua_getfield(L, table, key) == LUA_TNIL) {
        lua_pop(L, 1);
        return std::nullopt;
    }
    const auto v = numbers(L, lua_gettop(L), 3, key);
    lua_pop(L, 1);
    return glm::dvec3(v[0], v[1], v[2]);
}

// ---- gr.* --------------------------------------------------------------------------------

int gr_node(lua_State *L) {
    Node n;
    n.name = checked_string(L, 1);
    return push_node(L, std::move(n));
}

// Whether `s` names a mesh file by its extension (docs/assets.md), in any case.
bool names_mesh_file(const std::string &s) {
    for (const char *ext : {".obj", ".ply", ".stl", ".glb", ".gltf"}) {
        const std::size_t n = std::char_traits<char>::length(ext);
        if (s.size() > n && std::equal(s.end() - static_cast<std::ptrdiff_t>(n), s.end(), ext,
                                       [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; }))
            return true;
    }
    return false;
}

// The mesh is named here and found later, by the plugin (the scene runs where no file is seen).
// A3 wrote gr.mesh(mesh_id, name), A4 gr.mesh(name, 'file.obj'): a second argument that names a
// mesh file when the first does not is A4's order.
int gr_mesh(lua_State *L) {
    Node n;
    n.mesh = checked_string(L, 1);
    n.name = lua_isnoneornil(L, 2) ? n.mesh : checked_string(L, 2);
    if (names_mesh_file(n.name) && !names_mesh_file(n.mesh)) std::swap(n.mesh, n.name);
    if (n.mesh.empty()) return luaL_error(L, "gr.mesh needs a mesh id");
    return push_node(L, std::move(n));
}

// Says that a call had `given` arguments where the course's API takes `takes`: the rest ignored.
void note_extra_arguments(lua_State *L, const char *call, int takes, int given) {
    if (given <= takes) return;
    const std::string text = std::string(call) + " takes " + std::to_string(takes) +
                             (takes == 1 ? " argument; the " : " arguments; the ") +
                             std::to_string(given - takes) + " more given (a student extension?) " +
                             (given - takes == 1 ? "is" : "are") + " ignored";
    charge(L, text.size() + 32);
    scene_of(L).notes.emplace_back(current_line(L), text);
}

// gr.joint(name, {xmin, xinit, xmax}, {ymin, yinit, ymax} [, {zmin, zinit, zmax}]): a node
// turned to its initial angles, its ranges kept (the editor clamps a turn to them).
int gr_joint(lua_State *L) {
    Node n;
    n.name = checked_string(L, 1);
    const int given = lua_gettop(L);
    auto x = numbers(L, 2, 3, "the joint's x range");
    auto y = numbers(L, 3, 3, "the joint's y range");
    // A fourth table of three numbers is a z range (an extension some students made): used.
    const bool has_z = given >= 4 && lua_istable(L, 4) && lua_rawlen(L, 4) == 3;
    std::vector<double> z = has_z ? numbers(L, 4, 3, "the joint's z range") : std::vector<double>{0.0, 0.0, 0.0};
    note_extra_arguments(L, "gr.joint", has_z ? 4 : 3, given);
    const char *axis = "xyz";
    int k = 0;
    for (auto *r : {&x, &y, &z}) {
        const char a = axis[k++];
        if (!((*r)[0] <= (*r)[2]))
            return luaL_error(L, "the joint's %c range must be {min, init, max} with min <= max", a);
        if ((*r)[1] < (*r)[0] || (*r)[1] > (*r)[2]) { // the course's viewer clamped it
            const double clamped = std::clamp((*r)[1], (*r)[0], (*r)[2]);
            char text[200];
            std::snprintf(text, sizeof text, "joint '%.40s': its %c angle %g is outside its range [%g, %g]; it starts at %g",
                          n.name.c_str(), a, (*r)[1], (*r)[0], (*r)[2], clamped);
            charge(L, sizeof text + 32);
            scene_of(L).notes.emplace_back(current_line(L), text);
            (*r)[1] = clamped;
        }
    }
    // Ranges all within one turn each way and not in whole degrees look like radians; the course's
    // viewer read degrees, and so do we, as its author saw them.
    bool small = true, whole = true;
    for (const auto *r : {&x, &y, &z})
        for (double v : *r) {
            small = small && std::abs(v) <= 2.0 * M_PI + 1e-9;
            whole = whole && v == std::round(v);
        }
    if (small && !whole) {
        char text[240];
        std::snprintf(text, sizeof text,
                      "joint '%.40s': its ranges look like radians (all within 2 pi, not whole degrees); they are "
                      "read as degrees, as the course's viewer read them",
                      n.name.c_str());
        charge(L, sizeof text + 32);
        scene_of(L).notes.emplace_back(current_line(L), text);
    }
    n.joint = true;
    n.joint_min = {x[0], y[0], z[0]};
    n.joint_max = {x[2], y[2], z[2]};
    n.local = glm::rotate(glm::dmat4(1.0), glm::radians(z[1]), glm::dvec3(0, 0, 1)) *
              glm::rotate(glm::dmat4(1.0), glm::radians(y[1]), glm::dvec3(0, 1, 0)) *
              glm::rotate(glm::dmat4(1.0), glm::radians(x[1]), glm::dvec3(1, 0, 0));
    return push_node(L, std::move(n));
}

int gr_material(lua_State *L) {
    Material m;
    const auto kd = numbers(L, 1, 3, "kd");
    const auto ks = numbers(L, 2, 3, "ks");
    m.kd = {kd[0], kd[1], kd[2]};
    m.ks = {ks[0], ks[1], ks[2]};
    for (double c : {kd[0], kd[1], kd[2], ks[0], ks[1], ks[2]})
        if (c < 0.0) return luaL_error(L, "material colours must be >= 0");
    if (std::max({kd[0], kd[1], kd[2], ks[0], ks[1], ks[2]}) > 1.0) { // the course allowed it
        const std::string text = "a material colour above 1 is kept as written: brighter than white, it may wash "
                                 "out to white where lit";
        charge(L, text.size() + 32);
        scene_of(L).notes.emplace_back(current_line(L), text);
    }
    m.shininess = luaL_checknumber(L, 3);
    if (!(m.shininess >= 0.0) || !std::isfinite(m.shininess)) return luaL_error(L, "shininess must be >= 0");
    note_extra_arguments(L, "gr.material", 3, lua_gettop(L));
    charge(L, sizeof(Material));
    Scene &scene = scene_of(L);
    const int index = static_cast<int>(scene.materials.size());
    scene.materials.push_back(m);
    *static_cast<int *>(lua_newuserdatauv(L, sizeof(int), 0)) = index;
    luaL_setmetatable(L, kMaterialMeta);
    return 1;
}

int gr_settings(lua_State *L) {
    {
        const Scene &scene = scene_of(L);
        if (scene.settings_line) return luaL_error(L, "gr.settings is called twice (first on line %d)", *scene.settings_line);
    }
    const int line = current_line(L);
    check_keys(L, 1, "gr.settings", {"gravity", "down", "max_time", "skybox", "cel", "backend", "interpolation"});
    const auto gravity = number_field(L, 1, "gravity", -1e6, 1e6);
    const auto down = string_field(L, 1, "down");
    if (down && *down != "x" && *down != "y" && *down != "z")
        return luaL_error(L, "'down' must be 'x', 'y' or 'z', got '%s'", down->c_str());
    const auto max_time = number_field(L, 1, "max_time", 1.0, 300000.0);
    const auto skybox = string_field(L, 1, "skybox");
    const auto cel = bool_field(L, 1, "cel");
    const auto backend = string_field(L, 1, "backend");
    const auto interpolation = string_field(L, 1, "interpolation");
    charge(L, (skybox ? skybox->size() : 0) + (backend ? backend->size() : 0) +
                  (interpolation ? interpolation->size() : 0));

    Scene &scene = scene_of(L);
    if (scene.settings_line) return luaL_error(L, "gr.settings is called twice (first on line %d)", *scene.settings_line);
    scene.settings_line = line;
    SceneResult &s = scene.settings;
    if (gravity) s.gravity = *gravity;
    if (down) s.down_axis = *down == "x" ? ANI_AXIS_X : *down == "y" ? ANI_AXIS_Y : ANI_AXIS_Z;
    if (max_time) s.max_time_ms = std::llround(1000.0 * *max_time);
    if (skybox) s.skybox = *skybox;
    if (cel) s.cel_shading = *cel;
    if (backend) s.backend = *backend;
    if (interpolation) s.interpolation = *interpolation;
    return 0;
}

int gr_camera(lua_State *L) {
    {
        const Scene &scene = scene_of(L);
        if (scene.camera_line) return luaL_error(L, "gr.camera is called twice (first on line %d)", *scene.camera_line);
    }
    const int line = current_line(L);
    check_keys(L, 1, "gr.camera", {"eye", "look_at", "up", "fov"});
    const glm::dvec3 eye = vec3_field(L, 1, "eye").value_or(glm::dvec3(0.0));
    const glm::dvec3 at = vec3_field(L, 1, "look_at").value_or(eye + glm::dvec3(0, 0, -1));
    const glm::dvec3 up = vec3_field(L, 1, "up").value_or(glm::dvec3(0, 1, 0));
    const auto fov = number_field(L, 1, "fov", 0.0, 180.0);
    const glm::dvec3 forward = at - eye;
    if (!(glm::length(forward) >= 1e-12)) return luaL_error(L, "the camera's look_at must differ from its eye");
    if (!(glm::length(glm::cross(glm::normalize(forward), up)) >= 1e-9))
        return luaL_error(L, "the camera's up must not be parallel to its view direction");
    if (fov && (*fov <= 0.0 || *fov >= 180.0))
        return luaL_error(L, "'fov' must be strictly between 0 and 180 degrees");
    const glm::dquat q = glm::quatLookAtRH(glm::normalize(forward), glm::normalize(up));

    Scene &scene = scene_of(L);
    if (scene.camera_line) return luaL_error(L, "gr.camera is called twice (first on line %d)", *scene.camera_line);
    if (scene.render_line)
        return luaL_error(L, "gr.camera sets the camera, which gr.render set on line %d", *scene.render_line);
    scene.camera_line = line;
    ani_camera_state &camera = scene.settings.camera;
    camera.position = {eye.x, eye.y, eye.z};
    camera.rotation = {q.w, q.x, q.y, q.z};
    if (fov) camera.fov_degrees = *fov;
    return 0;
}

// ---- node methods --------------------------------------------------------------------------

int node_translate(lua_State *L) {
    const int index = check_node(L, 1);
    const glm::dvec3 v(luaL_checknumber(L, 2), luaL_checknumber(L, 3), luaL_checknumber(L, 4));
    Node &n = node_at(L, index);
    n.local = glm::translate(glm::dmat4(1.0), v) * n.local; // CS488: later calls apply after earlier ones
    return 0;
}

int node_rotate(lua_State *L) {
    const int index = check_node(L, 1);
    const std::string axis = checked_string(L, 2);
    const double degrees = luaL_checknumber(L, 3);
    glm::dvec3 a;
    if (axis == "x" || axis == "X") a = {1, 0, 0};
    else if (axis == "y" || axis == "Y") a = {0, 1, 0};
    else if (axis == "z" || axis == "Z") a = {0, 0, 1};
    else return luaL_error(L, "rotate's axis must be 'x', 'y' or 'z', got '%s'", axis.c_str());
    Node &n = node_at(L, index);
    n.local = glm::rotate(glm::dmat4(1.0), glm::radians(degrees), a) * n.local;
    return 0;
}

int node_scale(lua_State *L) {
    const int index = check_node(L, 1);
    const glm::dvec3 s(luaL_checknumber(L, 2), luaL_checknumber(L, 3), luaL_checknumber(L, 4));
    if (!(s.x > 0.0 && s.y > 0.0 && s.z > 0.0)) return luaL_error(L, "scale factors must be > 0");
    Node &n = node_at(L, index);
    n.local = glm::scale(glm::dmat4(1.0), s) * n.local;
    return 0;
}

// Puts `child` under `parent`. A child under a second parent is an instance, as the course's
// code allowed (A4's scenes place one cow under several nodes): each use becomes a model of its
// own (flatten). Refused: a cycle, and a tree deeper than kMaxDepth. Reads no Lua value.
void attach(lua_State *L, int parent, int child) {
    Scene &scene = scene_of(L);
    // The checks copy what their messages need: luaL_error allocates, and so may run Lua.
    auto name = [&](int i) { return scene.nodes[static_cast<size_t>(i)].name; };
    auto cycle = [&] {
        const std::string message = "adding '" + name(child) + "' under '" + name(parent) + "' would make a cycle";
        luaL_error(L, "%s", message.c_str());
    };
    int depth = 0;
    for (int up = parent; up >= 0;) { // its first parents: the whole way up in a tree
        if (up == child) cycle();
        if (++depth > kMaxDepth) {
            const std::string message = "node '" + name(parent) + "' is more than " + std::to_string(kMaxDepth) +
                                        " levels deep; a scene tree may have at most that many";
            luaL_error(L, "%s", message.c_str());
        }
        const std::vector<int> &parents = scene.nodes[static_cast<size_t>(up)].parents;
        up = parents.empty() ? -1 : parents.front();
    }
    if (scene.instanced) { // every way up, each ancestor once
        const unsigned stamp = ++scene.epoch;
        scene.walk.assign(1, parent);
        scene.nodes[static_cast<size_t>(parent)].mark = stamp;
        while (!scene.walk.empty()) {
            const int at = scene.walk.back();
            scene.walk.pop_back();
            if (at == child) cycle();
            if (++scene.walk_steps > kWalkBudget) {
                scene.walk.clear();
                const std::string message = "adding '" + name(child) + "' under '" + name(parent) +
                                            "': the scene's instances (nodes under more than one parent) made more "
                                            "than " + std::to_string(kWalkBudget) + " steps of looking for a cycle";
                luaL_error(L, "%s", message.c_str());
            }
            for (int up : scene.nodes[static_cast<size_t>(at)].parents)
                if (scene.nodes[static_cast<size_t>(up)].mark != stamp) {
                    scene.nodes[static_cast<size_t>(up)].mark = stamp;
                    scene.walk.push_back(up);
                }
        }
    }
    charge(L, 2 * sizeof(int));
    Node &c = scene.nodes[static_cast<size_t>(child)];
    if (!c.parents.empty()) scene.instanced = true;
    c.parents.push_back(parent);
    scene.nodes[static_cast<size_t>(parent)].children.push_back(child);
}

int node_add_child(lua_State *L) {
    const int parent = check_node(L, 1);
    const int child = check_node(L, 2);
    attach(L, parent, child);
    return 0;
}

int node_set_material(lua_State *L) {
    const int index = check_node(L, 1);
    const int material = *static_cast<int *>(luaL_checkudata(L, 2, kMaterialMeta));
    node_at(L, index).material = material;
    return 0;
}

int node_set_physics(lua_State *L) {
    const int index = check_node(L, 1);
    check_keys(L, 2, "set_physics",
               {"dynamics", "gravity", "mass", "velocity", "restitution", "friction", "rotates", "angular_velocity"});
    const auto dynamics = bool_field(L, 2, "dynamics");
    const auto gravity = bool_field(L, 2, "gravity");
    const auto mass = number_field(L, 2, "mass", 0.0, 1e30);
    if (mass && *mass <= 0.0) return luaL_error(L, "'mass' must be > 0");
    const auto velocity = vec3_field(L, 2, "velocity");
    const auto restitution = number_field(L, 2, "restitution", 0.0, 1.0);
    const auto friction = number_field(L, 2, "friction", 0.0, 1e30);
    const auto rotates = bool_field(L, 2, "rotates");
    const auto angular_velocity = vec3_field(L, 2, "angular_velocity");
    Node &n = node_at(L, index);
    if (dynamics) n.dynamics = *dynamics;
    if (gravity) n.gravity = *gravity;
    if (mass) n.mass = *mass;
    if (velocity) n.velocity = *velocity;
    if (restitution) n.restitution = *restitution;
    if (friction) n.friction = *friction;
    if (rotates) n.rotates = *rotates;
    if (angular_velocity) n.angular_velocity = *angular_velocity;
    return 0;
}

int node_set_texture(lua_State *L) {
    const int index = check_node(L, 1);
    std::string texture = checked_string(L, 2);
    charge(L, texture.size());
    node_at(L, index).texture = std::move(texture);
    return 0;
}

int node_set_tint(lua_State *L) {
    const int index = check_node(L, 1);
    const double tint = luaL_checknumber(L, 2);
    if (!(tint >= 0.0 && tint <= 1.0)) return luaL_error(L, "tint must be in [0, 1]");
    node_at(L, index).tint = tint;
    return 0;
}

int node_set_optics(lua_State *L) {
    const int index = check_node(L, 1);
    check_keys(L, 2, "set_optics", {"reflectivity", "transparency", "refractive_index"});
    const auto reflectivity = number_field(L, 2, "reflectivity", 0.0, 1.0);
    const auto transparency = number_field(L, 2, "transparency", 0.0, 1.0);
    const auto refractive_index = number_field(L, 2, "refractive_index", 0.0, 100.0);
    if (refractive_index && *refractive_index <= 0.0) return luaL_error(L, "'refractive_index' must be > 0");
    Node &n = node_at(L, index);
    if (reflectivity) n.reflectivity = *reflectivity;
    if (transparency) n.transparency = *transparency;
    if (refractive_index) n.refractive_index = *refractive_index;
    return 0;
}

int node_set_sound(lua_State *L) {
    const int index = check_node(L, 1);
    check_keys(L, 2, "set_sound", {"collision", "moving"});
    auto collision = string_field(L, 2, "collision");
    auto moving = string_field(L, 2, "moving");
    charge(L, (collision ? collision->size() : 0) + (moving ? moving->size() : 0));
    Node &n = node_at(L, index);
    if (collision) n.collision_sound = std::move(*collision);
    if (moving) n.moving_sound = std::move(*moving);
    return 0;
}

// ---- the A4 ray tracer's dialect -------------------------------------------------------------

// A node that draws our mesh `mesh` where `placement` puts it in the node's frame: the course's
// primitive, its size and place, as our mesh. The placement is the node's own, not its children's.
int push_primitive(lua_State *L, std::string name, const char *mesh, const glm::dmat4 &placement) {
    Node n;
    n.name = std::move(name);
    n.mesh = mesh;
    n.placement = placement;
    return push_node(L, std::move(n));
}

glm::dmat4 translation(const glm::dvec3 &v) { return glm::translate(glm::dmat4(1.0), v); }
glm::dmat4 scaling(const glm::dvec3 &v) { return glm::scale(glm::dmat4(1.0), v); }

// gr.sphere(name), gr.cylinder(name), gr.cone(name), gr.plane(name): our mesh as it is (the unit
// sphere; the cylinder of radius 1 from y = -1 to 1; the cone of base radius 1 at y = -1, apex at
// y = 1; the plane from -1 to 1 in x and z, facing +y). Students' variants with sizes: ignored.
template <const char *Mesh, const char *Call>
int gr_unit_primitive(lua_State *L) {
    std::string name = checked_string(L, 1);
    note_extra_arguments(L, Call, 1, lua_gettop(L));
    return push_primitive(L, std::move(name), Mesh, glm::dmat4(1.0));
}
constexpr char kSphere[] = "sphere", kCylinder[] = "cylinder", kCone[] = "cone", kPlane[] = "plane";
constexpr char kGrSphere[] = "gr.sphere", kGrCylinder[] = "gr.cylinder", kGrCone[] = "gr.cone",
               kGrPlane[] = "gr.plane";

// gr.cube(name): the course's unit cube, (0, 0, 0) to (1, 1, 1); our cube is -1 to 1.
int gr_cube(lua_State *L) {
    std::string name = checked_string(L, 1);
    note_extra_arguments(L, "gr.cube", 1, lua_gettop(L));
    return push_primitive(L, std::move(name), "cube", translation(glm::dvec3(0.5)) * scaling(glm::dvec3(0.5)));
}

// gr.nh_sphere(name, {x, y, z}, radius): a sphere of `radius` about x, y, z.
int gr_nh_sphere(lua_State *L) {
    std::string name = checked_string(L, 1);
    const auto c = numbers(L, 2, 3, "the sphere's centre");
    const double r = luaL_checknumber(L, 3);
    if (!(r > 0.0) || !std::isfinite(r)) return luaL_error(L, "the sphere's radius must be > 0, got %f", r);
    note_extra_arguments(L, "gr.nh_sphere", 3, lua_gettop(L));
    return push_primitive(L, std::move(name), "sphere", translation({c[0], c[1], c[2]}) * scaling(glm::dvec3(r)));
}

// gr.nh_box(name, {x, y, z}, size): the cube of edge `size` from corner x, y, z to x + size, ....
int gr_nh_box(lua_State *L) {
    std::string name = checked_string(L, 1);
    const auto c = numbers(L, 2, 3, "the box's corner");
    const double size = luaL_checknumber(L, 3);
    if (!(size > 0.0) || !std::isfinite(size)) return luaL_error(L, "the box's size must be > 0, got %f", size);
    note_extra_arguments(L, "gr.nh_box", 3, lua_gettop(L));
    const double h = size / 2.0;
    return push_primitive(L, std::move(name), "cube",
                          translation(glm::dvec3(c[0] + h, c[1] + h, c[2] + h)) * scaling(glm::dvec3(h)));
}

// gr.torus(name [, tube]): the ring of radius 1 about the y axis (in the XZ plane), its tube of
// radius `tube` (< 1, as a fraction of the ring's: students wrote it either way). Our torus mesh's
// tube is 0.3: another is drawn as ours scaled to the same outer size and thickness, with a warning.
int gr_torus(lua_State *L) {
    std::string name = checked_string(L, 1);
    const int given = lua_gettop(L);
    glm::dmat4 placement(1.0);
    if (given >= 2 && !lua_isnil(L, 2)) {
        const double r = luaL_checknumber(L, 2);
        if (!(r > 0.0 && r < 1.0))
            return luaL_error(L, "the torus's tube radius must be > 0 and < 1 (its ring's radius), got %f", r);
        if (std::abs(r - kTorusTube) > 1e-12) {
            const double across = (1.0 + r) / (1.0 + kTorusTube);
            placement = scaling({across, r / kTorusTube, across});
            char text[240];
            std::snprintf(text, sizeof text,
                          "torus '%.40s': its tube radius %g is drawn as our torus's (%g) scaled to the same outer "
                          "size and thickness; its hole is %s",
                          name.c_str(), r, kTorusTube, r > kTorusTube ? "larger" : "smaller");
            charge(L, sizeof text + 32);
            scene_of(L).notes.emplace_back(current_line(L), text);
        }
    }
    note_extra_arguments(L, "gr.torus", 2, given);
    return push_primitive(L, std::move(name), "torus", placement);
}

// gr.union / gr.intersection / gr.difference(name, a, b), or (a, b) as some students wrote them:
// we cannot draw CSG, so a node holding both operands, with a warning.
int csg(lua_State *L, const char *operation) {
    const bool named = lua_type(L, 1) == LUA_TSTRING;
    std::string name = named ? checked_string(L, 1) : std::string(operation);
    const int first = named ? 2 : 1;
    const int a = check_node(L, first);
    const int b = check_node(L, first + 1);
    note_extra_arguments(L, (std::string("gr.") + operation).c_str(), first + 1, lua_gettop(L));
    const std::string text = "gr." + std::string(operation) + " '" + name + "' is shown as its two operands, '" +
                             node_at(L, a).name + "' and '" + node_at(L, b).name +
                             "': animator does not draw CSG";
    charge(L, text.size() + 32);
    scene_of(L).notes.emplace_back(current_line(L), text);
    Node n;
    n.name = std::move(name);
    push_node(L, std::move(n));
    const int index = *static_cast<int *>(lua_touserdata(L, -1));
    attach(L, index, a);
    attach(L, index, b);
    return 1;
}
int gr_union(lua_State *L) { return csg(L, "union"); }
int gr_intersection(lua_State *L) { return csg(L, "intersection"); }
int gr_difference(lua_State *L) { return csg(L, "difference"); }

// Three numbers >= 0, not all 0 unless `zero` is allowed.
void check_colour(lua_State *L, const std::vector<double> &v, const char *what, bool zero) {
    if (v[0] < 0.0 || v[1] < 0.0 || v[2] < 0.0) luaL_error(L, "%s must be >= 0", what);
    if (!zero && v[0] + v[1] + v[2] <= 0.0) luaL_error(L, "%s must not be all 0", what);
}

// gr.light({x, y, z}, {r, g, b} [, {c0, c1, c2}]): a point light in world space, reaching a point
// at distance d as colour / (c0 + c1 d + c2 d^2); {1, 0, 0} when not given.
int gr_light(lua_State *L) {
    const auto p = numbers(L, 1, 3, "the light's position");
    const auto c = numbers(L, 2, 3, "the light's colour");
    const auto f = lua_isnoneornil(L, 3) ? std::vector<double>{1.0, 0.0, 0.0} : numbers(L, 3, 3, "the light's falloff");
    check_colour(L, c, "the light's colour", true);
    check_colour(L, f, "the light's falloff", false);
    note_extra_arguments(L, "gr.light", 3, lua_gettop(L));
    charge(L, sizeof(Scene::Light) + 32);
    Scene &scene = scene_of(L);
    const int index = static_cast<int>(scene.lights.size());
    scene.lights.push_back({{p[0], p[1], p[2]}, {c[0], c[1], c[2]}, {f[0], f[1], f[2]}});
    *static_cast<int *>(lua_newuserdatauv(L, sizeof(int), 0)) = index;
    luaL_setmetatable(L, kLightMeta);
    return 1;
}

// gr.render(root, 'file.png', width, height, eye, view, up, fov, ambient, {lights}): the camera at
// eye looking along view (a direction) with up and a vertical fov in degrees, the ambient light,
// the lights and the image's name and size. Its root is the scene's when the file returns none.
int gr_render(lua_State *L) {
    const int given = lua_gettop(L);
    const int root = check_node(L, 1);
    std::string output = checked_string(L, 2);
    if (output.empty()) return luaL_error(L, "gr.render needs the image's file name");
    const lua_Integer width = luaL_checkinteger(L, 3), height = luaL_checkinteger(L, 4);
    if (width < 1 || width > 16384 || height < 1 || height > 16384)
        return luaL_error(L, "gr.render's image must be 1 to 16384 pixels each way, got %I x %I", width, height);
    const auto e = numbers(L, 5, 3, "the eye");
    const auto v = numbers(L, 6, 3, "the view direction");
    const auto u = numbers(L, 7, 3, "up");
    const double fov = luaL_checknumber(L, 8);
    if (!(fov > 0.0 && fov < 180.0)) return luaL_error(L, "the fov must be strictly between 0 and 180 degrees");
    const auto ambient = lua_isnoneornil(L, 9) ? std::vector<double>{0.2, 0.2, 0.2} : numbers(L, 9, 3, "ambient");
    check_colour(L, ambient, "ambient", true);
    std::vector<int> lights;
    if (!lua_isnoneornil(L, 10)) {
        luaL_checktype(L, 10, LUA_TTABLE);
        const lua_Unsigned count = lua_rawlen(L, 10);
        if (count > ANI_MAX_LIGHTS)
            return luaL_error(L, "gr.render is given %I lights; a scene may have at most %d",
                              static_cast<lua_Integer>(count), ANI_MAX_LIGHTS);
        for (lua_Integer i = 1; i <= static_cast<lua_Integer>(count); ++i) {
            lua_rawgeti(L, 10, i);
            const auto *light = static_cast<const int *>(luaL_testudata(L, -1, kLightMeta));
            if (!light) return luaL_error(L, "gr.render's light %I is not a light (gr.light), got %s", i, luaL_typename(L, -1));
            if (std::find(lights.begin(), lights.end(), *light) == lights.end()) lights.push_back(*light);
            lua_pop(L, 1);
        }
    }
    note_extra_arguments(L, "gr.render", 10, given);
    const glm::dvec3 eye(e[0], e[1], e[2]), view(v[0], v[1], v[2]), up(u[0], u[1], u[2]);
    if (!(glm::length(view) >= 1e-12)) return luaL_error(L, "gr.render's view direction must not be 0");
    if (!(glm::length(glm::cross(glm::normalize(view), up)) >= 1e-9))
        return luaL_error(L, "gr.render's up must not be parallel to its view direction");
    const glm::dquat q = glm::quatLookAtRH(glm::normalize(view), glm::normalize(up));
    const int line = current_line(L);
    {
        Scene &scene = scene_of(L);
        if (scene.camera_line)
            return luaL_error(L, "gr.render sets the camera, which gr.camera set on line %d", *scene.camera_line);
        if (scene.render_line) { // students render several images: the first is the document's
            if (scene.render_again) return 0;
            const std::string text = "gr.render is called again (first on line " + std::to_string(*scene.render_line) +
                                     "); the first call's root, camera, lights and image are kept, this one and any "
                                     "later are ignored";
            charge(L, text.size() + 32);
            scene.render_again = true;
            scene.notes.emplace_back(line, text);
            return 0;
        }
    }
    charge(L, output.size() + lights.size() * (sizeof(SceneLight) + 16));
    Scene &scene = scene_of(L);
    scene.render_line = line;
    scene.render_root = root;
    SceneResult &s = scene.settings;
    s.camera.position = {eye.x, eye.y, eye.z};
    s.camera.rotation = {q.w, q.x, q.y, q.z};
    s.camera.fov_degrees = fov;
    s.ambient = {ambient[0], ambient[1], ambient[2]};
    s.render_output = std::move(output);
    s.render_width = static_cast<int32_t>(width);
    s.render_height = static_cast<int32_t>(height);
    std::map<std::string, int> next;
    s.lights.clear();
    for (int index : lights) {
        const Scene::Light &l = scene.lights[static_cast<size_t>(index)];
        SceneLight out;
        out.name = unique_name("light", next, [&](const std::string &n) {
            return std::any_of(s.lights.begin(), s.lights.end(), [&](const SceneLight &o) { return o.name == n; });
        });
        out.position = {l.position.x, l.position.y, l.position.z};
        out.colour = {l.colour.x, l.colour.y, l.colour.z};
        out.falloff = {l.falloff.x, l.falloff.y, l.falloff.z};
        s.lights.push_back(std::move(out));
    }
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
    luaL_newmetatable(L, kLightMeta);
    lua_pushliteral(L, "locked");
    lua_setfield(L, -2, "__metatable");
    lua_pop(L, 1);

    const luaL_Reg gr[] = {{"node", gr_node},         {"mesh", gr_mesh},
                           {"joint", gr_joint},       {"material", gr_material},
                           {"settings", gr_settings}, {"camera", gr_camera},
                           // the A4 ray tracer's
                           {"sphere", gr_unit_primitive<kSphere, kGrSphere>},
                           {"cylinder", gr_unit_primitive<kCylinder, kGrCylinder>},
                           {"cone", gr_unit_primitive<kCone, kGrCone>},
                           {"plane", gr_unit_primitive<kPlane, kGrPlane>},
                           {"cube", gr_cube},         {"nh_sphere", gr_nh_sphere},
                           {"nh_box", gr_nh_box},     {"torus", gr_torus},
                           {"light", gr_light},       {"render", gr_render},
                           {"union", gr_union},       {"intersection", gr_intersection},
                           {"difference", gr_difference},
                           {nullptr, nullptr}};
    luaL_newlib(L, gr);
    lua_setglobal(L, "gr");
}

// `m` as a keyframe state and a rest shape: m = T(center) Rx Ry Rz S(scale) U, U unit upper
// triangular (the shear of a node scaled unevenly after a rotation, in CS488 call order; the
// identity otherwise). R S U is m's QR decomposition: R's columns are m's by Gram-Schmidt.
bool to_state(const glm::dmat4 &m, const Node &node, const std::string &path, SceneModel &out, glm::dmat3 &shear,
              std::string &error) {
    const glm::dmat3 l(m);
    auto fail = [&](const char *what) {
        error = path + ":" + std::to_string(node.line) + ": node '" + node.name + "' " + what;
        return false;
    };
    const glm::dvec3 r0 = l[0] / glm::length(l[0]);
    const glm::dvec3 u1 = l[1] - glm::dot(l[1], r0) * r0;
    const glm::dvec3 r1 = u1 / glm::length(u1);
    const glm::dvec3 r2 = glm::cross(r0, r1);
    const glm::dmat3 rotation(r0, r1, r2);
    const glm::dmat3 k = glm::transpose(rotation) * l; // upper triangular
    const glm::dvec3 diagonal(k[0][0], k[1][1], k[2][2]);
    for (int i = 0; i < 3; ++i)
        if (!(diagonal[i] > 1e-12) || !std::isfinite(diagonal[i]) || !std::isfinite(k[2][i]))
            return fail("has a zero or invalid scale");
    shear = glm::dmat3(1.0);
    // Column-major: shear[c][r] is row r of column c. What rounding leaves of no shear is none.
    auto keep = [](double v) { return std::abs(v) < 1e-12 ? 0.0 : v; };
    shear[1][0] = keep(k[1][0] / diagonal.x);
    shear[2][0] = keep(k[2][0] / diagonal.x);
    shear[2][1] = keep(k[2][1] / diagonal.y);
    // Without shear the scale is the columns' lengths, as exact as it gets.
    const glm::dvec3 scale = shear == glm::dmat3(1.0) ? glm::dvec3(glm::length(l[0]), glm::length(l[1]), glm::length(l[2]))
                                                      : diagonal;
    double ax = 0, ay = 0, az = 0;
    glm::extractEulerAngleXYZ(glm::dmat4(rotation), ax, ay, az);
    auto wrap = [](double radians) {
        double d = std::fmod(glm::degrees(radians), 360.0);
        if (d < 0.0) d += 360.0;
        if (d >= 360.0 || std::abs(d - 360.0) < 1e-9 || std::abs(d) < 1e-9) d = 0.0;
        return d;
    };
    out.state.center = {m[3].x, m[3].y, m[3].z};
    out.state.angles = {wrap(ax), wrap(ay), wrap(az)};
    out.state.scale = {scale.x, scale.y, scale.z};
    out.state.turn = {0.0, 0.0, 0.0};
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) out.rest[3 * c + r] = shear[c][r];
    if (!std::isfinite(out.state.center.x) || !std::isfinite(out.state.center.y) || !std::isfinite(out.state.center.z))
        return fail("is moved out of range");
    return true;
}

// The tree under the returned root as models in depth-first order, so a parent always comes
// before its children. A root without a mesh is not a model: its transform moves into its
// children's. A node used more than once (an instance) is a model each time, with everything under
// it: the first use keeps its name, the others are renamed as names used twice are.
bool flatten(const Scene &scene, int root_index, const std::string &path, SceneResult &out, std::string &error) {
    const Node &root = scene.nodes[static_cast<size_t>(root_index)];
    std::vector<std::vector<std::string>> uses(scene.nodes.size()); // each node's models' names
    std::set<std::string> copies;
    std::map<std::string, int> next;
    std::size_t bytes = 0; // the models, against the budget of the nodes they copy
    struct Visit {
        int node;
        int parent_model;
        glm::dmat4 prefix;
    };
    std::vector<Visit> stack;
    if (root.mesh.empty()) {
        for (auto it = root.children.rbegin(); it != root.children.rend(); ++it) stack.push_back({*it, -1, root.local});
    } else {
        stack.push_back({root_index, -1, glm::dmat4(1.0)});
    }
    while (!stack.empty()) {
        const Visit v = stack.back();
        stack.pop_back();
        const Node &n = scene.nodes[static_cast<size_t>(v.node)];
        SceneModel m;
        std::vector<std::string> &used = uses[static_cast<size_t>(v.node)];
        m.name = used.empty() ? n.name : unique_name(n.name, next, [&](const std::string &name) {
            return scene.by_name.count(name) > 0 || copies.count(name) > 0;
        });
        if (!used.empty()) copies.insert(m.name);
        bytes += sizeof(SceneModel) + 4 * m.name.size() + n.mesh.size() + n.texture.size() + n.collision_sound.size() +
                 n.moving_sound.size() + 96;
        if (bytes > kSceneDataBudget) {
            error = path + ": the scene's instances (nodes under more than one parent) make more than its budget of " +
                    std::to_string(kSceneDataBudget >> 20) + " MiB of models (" + std::to_string(out.models.size()) +
                    " models so far)";
            return false;
        }
        used.push_back(m.name);
        m.mesh = n.mesh;
        m.line = n.line;
        m.parent = v.parent_model;
        if (n.material >= 0) {
            const Material &mat = scene.materials[static_cast<size_t>(n.material)];
            m.kd = {mat.kd.x, mat.kd.y, mat.kd.z};
            m.ks = {mat.ks.x, mat.ks.y, mat.ks.z};
            m.shininess = mat.shininess;
        }
        m.texture = n.texture;
        m.tint = n.tint;
        m.reflectivity = n.reflectivity;
        m.transparency = n.transparency;
        m.refractive_index = n.refractive_index;
        m.dynamics = n.dynamics;
        m.gravity = n.gravity;
        m.mass = n.mass;
        m.initial_velocity = {n.velocity.x, n.velocity.y, n.velocity.z};
        m.restitution = n.restitution;
        m.friction = n.friction;
        m.rotates = n.rotates;
        m.angular_velocity = {n.angular_velocity.x, n.angular_velocity.y, n.angular_velocity.z};
        m.collision_sound = n.collision_sound;
        m.moving_sound = n.moving_sound;
        m.has_joint = n.joint;
        m.joint_min = {n.joint_min.x, n.joint_min.y, n.joint_min.z};
        m.joint_max = {n.joint_max.x, n.joint_max.y, n.joint_max.z};
        // The model's mesh is at (its parent's T R S) T R S U = (...) prefix local placement.
        glm::dmat3 shear(1.0);
        if (!to_state(v.prefix * n.local * n.placement, n, path, m, shear, error)) return false;
        const int index = static_cast<int>(out.models.size());
        out.models.push_back(std::move(m));
        // Children hang from prefix local (CS488), which is this model's T R S times U placement^-1.
        const glm::dmat4 below = glm::dmat4(shear) * glm::inverse(n.placement);
        for (auto it = n.children.rbegin(); it != n.children.rend(); ++it) stack.push_back({*it, index, below});
    }
    // A warning for each instance used more than once, by line.
    std::vector<int> instances;
    for (size_t i = 0; i < scene.nodes.size(); ++i)
        if (scene.nodes[i].parents.size() > 1 && uses[i].size() > 1) instances.push_back(static_cast<int>(i));
    std::stable_sort(instances.begin(), instances.end(), [&](int a, int b) {
        return scene.nodes[static_cast<size_t>(a)].line < scene.nodes[static_cast<size_t>(b)].line;
    });
    for (int i : instances) {
        const Node &n = scene.nodes[static_cast<size_t>(i)];
        const std::vector<std::string> &names = uses[static_cast<size_t>(i)];
        std::string w = path + ":" + std::to_string(n.line) + ": node '" + n.name + "' is used " +
                        std::to_string(names.size()) +
                        " times (an instance: it was added under more than one parent); each use is a model of its "
                        "own, with everything under it: ";
        for (size_t k = 0; k < names.size(); ++k) {
            if (names.size() > 4 && k == 2) {
                w += "..., ";
                k = names.size() - 1;
            }
            w += "'" + names[k] + "'" + (k + 1 < names.size() ? ", " : "");
        }
        out.warnings.push_back(std::move(w));
    }
    return true;
}

} // namespace

bool run_scene(const std::string &path, const std::string &text, SceneResult &out, std::string &error) {
    // The scene outlives the sandbox: closing the Lua state runs finalizers, which may call gr.*.
    Scene scene;
    Sandbox sandbox;
    lua_State *L = sandbox.state();
    if (!L) {
        error = path + ": cannot create a Lua state";
        return false;
    }
    lua_pushlightuserdata(L, &scene);
    lua_setfield(L, LUA_REGISTRYINDEX, "animator.scene");
    register_api(L);
    if (!sandbox.run(path, text, 1, error)) return false;
    const auto *returned = static_cast<const int *>(luaL_testudata(L, -1, kNodeMeta));
    // A4's scenes return nothing: they give their root to gr.render.
    const int root_index = returned ? *returned : lua_isnil(L, -1) ? scene.render_root : -1;
    if (root_index < 0) {
        error = path + ": the scene must return its root node (return rootnode) or give it to gr.render, got " +
                luaL_typename(L, -1);
        return false;
    }
    out = std::move(scene.settings);
    out.models.clear();
    out.warnings.clear();
    if (!scene.renames.empty()) { // one warning for all of them
        std::string w = path + ":" + std::to_string(scene.renames.front().line) + ": " +
                        std::to_string(scene.renames.size()) +
                        (scene.renames.size() == 1 ? " node name was" : " node names were") +
                        " used before or empty, renamed to be unique:";
        for (const Scene::Rename &r : scene.renames)
            w += " line " + std::to_string(r.line) + " '" + r.from + "' -> '" + r.to + "';";
        w.back() = '.';
        out.warnings.push_back(std::move(w));
    }
    for (const auto &[line, note] : scene.notes) out.warnings.push_back(path + ":" + std::to_string(line) + ": " + note);
    return flatten(scene, root_index, path, out, error);
}

} // namespace lua_scene
