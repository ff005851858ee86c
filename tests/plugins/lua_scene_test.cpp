// The Lua scene plugin through the host's document I/O: the CS488 API and its extensions, the
// meaning of transforms (against a direct matrix product), the sandbox, and error messages.
#include "assets/mesh.hpp"
#include "io/document_io.hpp"
#include "io/environment.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/euler_angles.hpp>

#include <cmath>
#include <random>

using namespace animator;
namespace fs = std::filesystem;

namespace {

PluginRegistry &registry() {
    static PluginRegistry r({test::bin_dir()}, [](ani_log_level, const std::string &, const std::string &) {});
    return r;
}

Document load(const std::string &name, const std::string &lua) {
    const fs::path path = test::fresh_dir("lua_" + name) / (name + ".lua");
    test::write_file(path, lua);
    return open_document(registry(), path).document;
}

std::string load_error_at(const fs::path &path) {
    try {
        open_document(registry(), path);
    } catch (const DocumentIoError &e) {
        return e.what();
    }
    return "(no error)";
}

std::string load_error(const std::string &name, const std::string &lua) {
    const fs::path path = test::fresh_dir("lua_" + name) / (name + ".lua");
    test::write_file(path, lua);
    return load_error_at(path);
}

// The model matrix the document model promises: T(center) Rx Ry Rz S(scale).
glm::dmat4 matrix_of(const ModelState &s) {
    return glm::translate(glm::dmat4(1.0), s.center) *
           glm::eulerAngleXYZ(glm::radians(s.angles.x), glm::radians(s.angles.y), glm::radians(s.angles.z)) *
           glm::scale(glm::dmat4(1.0), s.scale);
}

} // namespace

TEST_CASE("the seed-style simple scene loads with its six models, materials, physics and camera") {
    const Document doc = open_document(registry(), test::source_dir() / "assets/scenes/simple.lua").document;
    REQUIRE(doc.models().size() == 6);
    const int ball = doc.find_model("ball");
    REQUIRE(ball >= 0);
    const Model &b = doc.models()[static_cast<size_t>(ball)];
    CHECK(b.mesh == "sphere");
    CHECK(b.dynamics);
    CHECK(b.gravity);
    CHECK(b.collision_sound == "click");
    CHECK(b.material.kd == glm::dvec3(0.9, 0.2, 0.2));
    CHECK(doc.keyframe_at(0).states[static_cast<size_t>(ball)]->center == glm::dvec3(-4, 3, 0));
    const Model &torus = doc.models()[static_cast<size_t>(doc.find_model("torus"))];
    CHECK(torus.transparency == 0.6);
    CHECK(torus.refractive_index == 1.33);
    CHECK(doc.settings().max_time_ms == 20000);
    CHECK(doc.settings().skybox == "day");

    // The camera at eye looks at look_at: its -Z axis points there, its +Y is up-ish.
    const CameraState &cam = *doc.keyframe_at(0).camera;
    CHECK(cam.position == glm::dvec3(0, 4, 14));
    const glm::dvec3 forward = cam.rotation * glm::dvec3(0, 0, -1);
    const glm::dvec3 expected = glm::normalize(glm::dvec3(0, 1, 0) - glm::dvec3(0, 4, 14));
    CHECK(glm::length(forward - expected) < 1e-12);
    CHECK((cam.rotation * glm::dvec3(0, 1, 0)).y > 0.9);
    CHECK(cam.fov_degrees == 50.0);
}

TEST_CASE("a node's transform calls give the same matrix as the CS488 product") {
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> any(-10.0, 10.0), angle(-720.0, 720.0), factor(0.2, 3.0);
    for (int round = 0; round < 50; ++round) {
        std::string lua = "local root = gr.node('root')\nlocal m = gr.mesh('sphere', 'm')\n";
        glm::dmat4 expected(1.0);
        const char *axes[] = {"x", "y", "z"};
        for (int call = 0; call < 6; ++call) {
            const int what = static_cast<int>(rng() % 3);
            char line[200];
            if (what == 0) {
                const glm::dvec3 v(any(rng), any(rng), any(rng));
                std::snprintf(line, sizeof line, "m:translate(%.17g, %.17g, %.17g)\n", v.x, v.y, v.z);
                expected = glm::translate(glm::dmat4(1.0), v) * expected;
            } else if (what == 1) {
                const int a = static_cast<int>(rng() % 3);
                const double deg = angle(rng);
                std::snprintf(line, sizeof line, "m:rotate('%s', %.17g)\n", axes[a], deg);
                glm::dvec3 axis(0.0);
                axis[a] = 1.0;
                expected = glm::rotate(glm::dmat4(1.0), glm::radians(deg), axis) * expected;
            } else {
                const double s = factor(rng); // uniform, so no shear arises
                std::snprintf(line, sizeof line, "m:scale(%.17g, %.17g, %.17g)\n", s, s, s);
                expected = glm::scale(glm::dmat4(1.0), glm::dvec3(s)) * expected;
            }
            lua += line;
        }
        lua += "root:add_child(m)\nreturn root\n";
        const Document doc = load("transform", lua);
        const ModelState &s = *doc.keyframe_at(0).states[0];
        const glm::dmat4 got = matrix_of(s);
        CAPTURE(lua);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 3; ++r) CHECK(got[c][r] == Approx(expected[c][r]).margin(1e-9));
        for (int i = 0; i < 3; ++i) {
            CHECK(s.angles[i] >= 0.0);
            CHECK(s.angles[i] < 360.0);
        }
    }
}

TEST_CASE("children keep their parent, states are local to it, and a bare root is folded away") {
    const Document doc = load("tree", R"(
        local root = gr.node('root')
        root:translate(0, 10, 0)
        local arm = gr.joint('arm', {-90, 45, 90}, {0, 0, 0})
        local upper = gr.mesh('cylinder', 'upper')
        upper:translate(0, 1, 0)
        local hand = gr.mesh('sphere', 'hand')
        hand:translate(0, 2, 0)
        root:add_child(arm)
        arm:add_child(upper)
        upper:add_child(hand)
        return root)");
    REQUIRE(doc.models().size() == 3);
    CHECK(doc.models()[0].name == "arm");
    CHECK(doc.models()[0].mesh.empty()); // a joint is an empty
    CHECK(doc.models()[0].parent == -1);
    CHECK(doc.models()[1].parent == 0);
    CHECK(doc.models()[2].parent == 1);
    const auto &states = doc.keyframe_at(0).states;
    CHECK(states[0]->center == glm::dvec3(0, 10, 0)); // the root's translation moved into arm
    CHECK(states[0]->angles.x == Approx(45.0));
    CHECK(states[1]->center == glm::dvec3(0, 1, 0));
    CHECK(states[2]->center == glm::dvec3(0, 2, 0));
}

TEST_CASE("a scene cannot escape its sandbox") {
    struct Escape {
        const char *name;
        const char *lua;
        const char *expected;
    };
    const std::vector<Escape> escapes = {
        {"os_execute", "os.execute('touch /tmp/animator-escaped')", "global 'os'"},
        {"io_open", "io.open('/etc/passwd')", "global 'io'"},
        {"require", "require('os')", "global 'require'"},
        {"dofile", "dofile('/etc/passwd')", "global 'dofile'"},
        {"loadfile", "loadfile('/etc/passwd')", "global 'loadfile'"},
        {"package", "package.loadlib('libc.so.6', 'system')", "global 'package'"},
        {"debug", "debug.sethook()", "global 'debug'"},
        {"string_dump", "string.dump(function() end)", "field 'dump'"},
        {"load_bytecode", "assert(load('\\27Lua\\84\\0'))", "binary chunk"},
        {"collectgarbage", "collectgarbage('stop')", "global 'collectgarbage'"},
        {"endless_loop", "while true do end", "budget of 200000000 instructions"},
        {"memory_bomb", "local t = {} for i = 1, 1e9 do t[i] = string.rep('x', 1 << 20) .. i end",
         "memory budget of 256 MiB"},
    };
    for (const Escape &e : escapes) {
        CAPTURE(e.name);
        const std::string error = load_error(e.name, std::string("\n") + e.lua + "\nreturn gr.node('r')\n");
        CHECK_THAT(error, Catch::Contains(e.expected));
        CHECK_THAT(error, Catch::Contains(std::string(e.name) + ".lua"));
    }
    CHECK_FALSE(fs::exists("/tmp/animator-escaped"));
}

TEST_CASE("a Lua bytecode file is refused with a clear message") {
    const fs::path path = test::fresh_dir("lua_bytecode") / "scene.lua";
    test::write_file(path, std::string("\x1bLua\x54\x00\x19\x93\r\n\x1a\n", 12));
    CHECK_THROWS_WITH(open_document(registry(), path), Catch::Contains("is Lua bytecode"));
}

TEST_CASE("scene errors name the file and the line") {
    struct Bad {
        const char *name;
        const char *lua;
        const char *expected;
    };
    const std::vector<Bad> bad = {
        {"syntax", "local root = gr.node('root'\nreturn root\n", "syntax.lua:2:"},
        {"arg_type", "local r = gr.node('r')\nr:translate('up', 0, 0)\nreturn r\n",
         "arg_type.lua:2: bad argument #1 to 'translate' (number expected, got string)"},
        {"unknown_key", "local r = gr.node('r')\nr:set_physics{dynamic = true}\nreturn r\n",
         "unknown_key.lua:2: unknown key 'dynamic' in set_physics; expected dynamics, gravity, mass, velocity"},
        {"bad_restitution", "local r = gr.node('r')\n\nr:set_physics{restitution = 1.5}\nreturn r\n",
         "bad_restitution.lua:3: 'restitution' must be in [0.0, 1.0], got 1.5"},
        {"bad_friction", "local r = gr.node('r')\nr:set_physics{friction = -0.25}\nreturn r\n",
         "bad_friction.lua:2: 'friction' must be in [0.0, 1e+30], got -0.25"},
        {"nan_friction", "local r = gr.node('r')\nr:set_physics{friction = 0/0}\nreturn r\n",
         "nan_friction.lua:2: 'friction' must be a number"},
        {"bad_rotates", "local r = gr.node('r')\nr:set_physics{rotates = 1}\nreturn r\n",
         "bad_rotates.lua:2: 'rotates' must be true or false"},
        {"bad_angular", "local r = gr.node('r')\nr:set_physics{angular_velocity = {1, 2}}\nreturn r\n",
         "bad_angular.lua:2: angular_velocity must be a table of 3 numbers"},
        {"bad_mass", "local r = gr.node('r')\nr:set_physics{mass = -2}\nreturn r\n", "bad_mass.lua:2:"},
        {"bad_axis", "local r = gr.node('r')\nr:rotate('w', 10)\nreturn r\n", "bad_axis.lua:2: rotate's axis must be"},
        {"no_return", "local r = gr.node('r')\n", "the scene must return its root node"},
        {"cycle", "local a = gr.node('a')\nlocal b = gr.node('b')\na:add_child(b)\nb:add_child(a)\nreturn a\n",
         "cycle.lua:4: adding 'a' under 'b' would make a cycle"},
        {"instance_cycle",
         "local a = gr.node('a')\nlocal b = gr.node('b')\nlocal c = gr.node('c')\na:add_child(c)\nb:add_child(c)\n"
         "c:add_child(b)\nreturn a\n",
         "instance_cycle.lua:6: adding 'b' under 'c' would make a cycle"},
        {"settings_down", "gr.settings{down = 'w'}\nreturn gr.node('r')\n", "settings_down.lua:1: 'down' must be"},
        {"max_time", "gr.settings{max_time = 0.5}\nreturn gr.node('r')\n", "max_time.lua:1: 'max_time' must be in"},
        {"camera_same", "gr.camera{eye = {1, 1, 1}, look_at = {1, 1, 1}}\nreturn gr.node('r')\n",
         "camera_same.lua:1: the camera's look_at must differ"},
        {"material", "local m = gr.material({0.5, -0.1, 0}, {0, 0, 0}, 10)\nreturn gr.node('r')\n",
         "material.lua:1: material colours must be >= 0"},
        {"runtime", "local r = gr.node('r')\nlocal x = nil\nx.y = 1\nreturn r\n", "runtime.lua:3: attempt to index"},
    };
    for (const Bad &b : bad) {
        CAPTURE(b.name);
        CHECK_THAT(load_error(b.name, b.lua), Catch::Contains(b.expected));
    }
}

TEST_CASE("animator info on a bad scene exits 1 with the file and line") {
    const fs::path path = test::fresh_dir("lua_cli") / "broken.lua";
    test::write_file(path, "local r = gr.node('r')\nr:scale(0, 1, 1)\nreturn r\n");
    const auto r = test::run_animator("info " + path.string());
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Contains("broken.lua:2: scale factors must be > 0"));
}

TEST_CASE("errors carry the whole path of a scene, however long") {
    const fs::path dir = test::fresh_dir("lua_long") / std::string(120, 'd');
    fs::create_directories(dir);
    const fs::path path = dir / "deep.lua";
    test::write_file(path, "local r = gr.node('r')\nr:rotate('q', 1)\nreturn r\n");
    CHECK_THAT(load_error_at(path), Catch::StartsWith(path.string() + ":2: rotate's axis"));
    test::write_file(path, "\n\nwhile true do end\n");
    CHECK_THAT(load_error_at(path), Catch::StartsWith(path.string() + ":3: the scene ran past"));
}

TEST_CASE("a mesh the scene's author did not publish loads as a stand-in with a warning at its line, "
          "in an animation it stays an error") {
    const fs::path root = test::fresh_dir("unknown_mesh_assets");
    fs::create_directories(root / "meshes");
    test::write_file(root / "meshes" / "ball.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    Environment env({root}, {test::bin_dir()}, [](ani_log_level, const std::string &, const std::string &) {});
    const fs::path dir = test::fresh_dir("unknown_mesh_docs");

    test::write_file(dir / "ok.lua", "local r = gr.node('r')\nr:add_child(gr.mesh('ball', 'b'))\nreturn r\n");
    const OpenedDocument ok = open_document(env.plugins, dir / "ok.lua");
    CHECK(ok.document.models().size() == 1);
    CHECK(ok.warnings.empty());
    // The course's puppets name meshes their authors made (luffy-face.obj): the model loads,
    // keeping the id as written, and the warning names the line, the mesh and where it looked.
    test::write_file(dir / "face.lua", "local r = gr.node('r')\n\nr:add_child(gr.mesh('luffy-face', 'face'))\nreturn r\n");
    const OpenedDocument face = open_document(env.plugins, dir / "face.lua");
    REQUIRE(face.document.models().size() == 1);
    CHECK(face.document.models()[0].mesh == "luffy-face");
    REQUIRE(face.warnings.size() == 1);
    CHECK_THAT(face.warnings[0], Catch::StartsWith((dir / "face.lua").string() + ":3: mesh 'luffy-face' not found (") &&
                                     Catch::Contains((root / "meshes" / "luffy-face.obj").string()) &&
                                     Catch::EndsWith("); shown as a stand-in cube until it is there"));
    // The host draws and collides a stand-in for it, and does not say it a second time.
    std::vector<std::string> more;
    const auto meshes = load_meshes({"luffy-face"}, env.assets, dir / "face.lua", more);
    REQUIRE(meshes[0]);
    CHECK(meshes[0]->stand_in);
    CHECK(meshes[0]->triangle_count() == 12);
    CHECK(meshes[0]->bound_radius == Approx(std::sqrt(3.0)));
    REQUIRE(more.size() == 1);
    CHECK(not_said_before(more, face.warnings).empty());
    // Once the mesh is there, it is used, and nothing is said.
    test::write_file(dir / "luffy-face.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    CHECK(open_document(env.plugins, dir / "face.lua").warnings.empty());
    more.clear();
    const auto found = load_meshes({"luffy-face"}, env.assets, dir / "face.lua", more);
    CHECK(more.empty());
    CHECK_FALSE(found[0]->stand_in);
    CHECK(found[0]->triangle_count() == 1);

    // A node under three parents (an instance, as A4's cows) is said once, with its models counted,
    // and the host does not say it again.
    test::write_file(dir / "cows.lua", "local r = gr.node('r')\nlocal cow = gr.mesh('cow', 'cow.obj')\n"
                                       "for i = 1, 3 do\n  local at = gr.node('at')\n  at:add_child(cow)\n"
                                       "  r:add_child(at)\nend\nreturn r\n");
    const OpenedDocument cows = open_document(env.plugins, dir / "cows.lua");
    CHECK(cows.document.models().size() == 6);
    std::vector<std::string> said_by_reader;
    for (const std::string &w : cows.warnings)
        if (w.find("not found") != std::string::npos) said_by_reader.push_back(w);
    REQUIRE(said_by_reader.size() == 1);
    CHECK_THAT(said_by_reader[0], Catch::StartsWith((dir / "cows.lua").string() +
                                                    ":2: 3 models (an instance): mesh 'cow.obj' not found ("));
    more.clear();
    load_meshes({"cow.obj", "cow.obj", "cow.obj"}, env.assets, dir / "cows.lua", more);
    CHECK_FALSE(more.empty());
    CHECK(not_said_before(more, cows.warnings).empty());

    test::write_file(dir / "bad.ani", "animator-ani 1\nmodel \"t\"\n  mesh \"teapot\"\nend\n");
    CHECK_THROWS_WITH(open_document(env.plugins, dir / "bad.ani"), Catch::Contains("bad.ani:3: unknown mesh \"teapot\""));
}

TEST_CASE("set_physics sets a node's rigid-body settings, a node without them has the defaults") {
    // Read through the isolated child, so the scene wire carries them both ways.
    const Document doc = load("rigid", R"(
local root = gr.node('root')
local a = gr.mesh('sphere', 'a')
a:set_physics{dynamics = true, restitution = 0.8, friction = 0.3, rotates = true, angular_velocity = {0, 0, 6.28}}
root:add_child(a)
local b = gr.mesh('cube', 'b')
b:set_physics{dynamics = true, mass = 2}
root:add_child(b)
return root
)");
    const Model &a = doc.models()[static_cast<size_t>(doc.find_model("a"))];
    const Model &b = doc.models()[static_cast<size_t>(doc.find_model("b"))];
    CHECK(a.restitution == 0.8);
    CHECK(a.friction == 0.3);
    CHECK(a.rotates);
    CHECK(a.angular_velocity == glm::dvec3(0.0, 0.0, 6.28));
    CHECK(b.restitution == 1.0);
    CHECK(b.friction == 0.0);
    CHECK_FALSE(b.rotates);
    CHECK(b.angular_velocity == glm::dvec3(0.0));
}

TEST_CASE("names used twice or empty load as the course's code allowed, renamed Blender's way, "
          "with one warning naming every rename and its line") {
    // A puppet written as CS488 students write them: an `elbow` under each arm (made in a
    // loop), an empty name, and a name that looks like one of the renames.
    const fs::path path = test::fresh_dir("lua_renames") / "puppet.lua";
    test::write_file(path, "local root = gr.node('root')\n"
                           "for i = 1, 2 do\n"
                           "  local arm = gr.node('arm')\n"
                           "  root:add_child(arm)\n"
                           "  local elbow = gr.mesh('sphere', 'elbow')\n"
                           "  arm:add_child(elbow)\n"
                           "end\n"
                           "local e = gr.mesh('cube', '')\n"
                           "root:add_child(e)\n"
                           "local f = gr.mesh('cube', 'elbow.001')\n"
                           "root:add_child(f)\n"
                           "return root\n");
    const OpenedDocument opened = open_document(registry(), path);
    std::vector<std::string> names;
    for (const Model &m : opened.document.models()) names.push_back(m.name);
    CHECK(names == std::vector<std::string>{"arm", "elbow", "arm.001", "elbow.001", "node", "elbow.002"});
    // Each elbow under its own arm, as written (the root is the scene, not a model).
    const auto &models = opened.document.models();
    CHECK(models[1].parent == 0);
    CHECK(models[3].parent == 2);
    REQUIRE(opened.warnings.size() == 1);
    CHECK(opened.warnings[0] == path.string() +
                                    ":3: 4 node names were used before or empty, renamed to be unique: line 3 'arm' -> "
                                    "'arm.001'; line 5 'elbow' -> 'elbow.001'; line 8 '' -> 'node'; line 10 "
                                    "'elbow.001' -> 'elbow.002'.");
    // A scene without such names says nothing.
    CHECK(open_document(registry(), test::source_dir() / "assets/scenes/simple.lua").warnings.empty());
}

TEST_CASE("joints and materials as students wrote them: an angle outside its range starts clamped, "
          "a z range is used, and extra arguments are ignored, each with a warning at its line") {
    const fs::path path = test::fresh_dir("lua_joints") / "puppet.lua";
    test::write_file(path, "local root = gr.node('root')\n"
                           "local neck = gr.joint('neck', {-30, 45, 30}, {-10, 0, 10}, {-90, 20, 90})\n"
                           "root:add_child(neck)\n"
                           "local m = gr.material({0.5, 0.5, 0.5}, {0.1, 0.1, 0.1}, 10, 0.5, 'mirror')\n"
                           "local head = gr.mesh('sphere', 'head')\n"
                           "head:set_material(m)\n"
                           "neck:add_child(head)\n"
                           "local wrist = gr.joint('wrist', {0, 10, 20}, {0, 0, 0}, 'extra')\n"
                           "root:add_child(wrist)\n"
                           "return root\n");
    const OpenedDocument opened = open_document(registry(), path);
    const std::string p = path.string();
    CHECK(opened.warnings == std::vector<std::string>{
                                 p + ":2: joint 'neck': its x angle 45 is outside its range [-30, 30]; it starts at 30",
                                 p + ":4: gr.material takes 3 arguments; the 2 more given (a student extension?) are ignored",
                                 p + ":8: gr.joint takes 3 arguments; the 1 more given (a student extension?) is ignored"});
    // The neck starts turned x = 30 (clamped), then y = 0, then z = 20 (its z range's initial
    // angle): its matrix Rz(20) Ry(0) Rx(30), whatever Euler angles the document holds it by.
    const auto &states = opened.document.keyframe_at(0).states;
    const glm::dvec3 a = glm::radians(states[0]->angles);
    const glm::dmat4 held = glm::eulerAngleXYZ(a.x, a.y, a.z);
    const glm::dmat4 expected = glm::rotate(glm::dmat4(1.0), glm::radians(20.0), glm::dvec3(0, 0, 1)) *
                                glm::rotate(glm::dmat4(1.0), glm::radians(30.0), glm::dvec3(1, 0, 0));
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) CHECK(std::abs(held[c][r] - expected[c][r]) < 1e-12);
    CHECK(states[2]->angles.x == Approx(10.0)); // the wrist, within its range
    // The material's three arguments are used.
    CHECK(opened.document.models()[1].material.kd == glm::dvec3(0.5));
    CHECK(opened.document.models()[1].material.shininess == 10.0);
}

TEST_CASE("the ray tracer's scenes open: primitives, instances, CSG as its operands, lights and "
          "gr.render, each leniency with a warning at its line") {
    const fs::path path = test::fresh_dir("lua_a4") / "a4.lua";
    test::write_file(path, "local root = gr.node('root')\n"                                   // 1
                           "local ball = gr.nh_sphere('ball', {1, 2, 3}, 0.5)\n"              // 2
                           "root:add_child(ball)\n"                                           // 3
                           "local leg = gr.cube('leg')\n"                                     // 4
                           "for i = 1, 3 do\n"                                                // 5
                           "  local stand = gr.node('stand')\n"                               // 6
                           "  stand:translate(i, 0, 0)\n"                                     // 7
                           "  stand:add_child(leg)\n"                                         // 8
                           "  root:add_child(stand)\n"                                        // 9
                           "end\n"                                                            // 10
                           "local die = gr.intersection('die', gr.cube('c'), gr.sphere('s'))\n" // 11
                           "root:add_child(die)\n"                                            // 12
                           "local m = gr.material({1.5, 0.2, 0.2}, {0, 0, 0}, 10)\n"          // 13
                           "local l1 = gr.light({0, 10, 0}, {2, 2, 2}, {1, 0, 0.01})\n"       // 14
                           "local l2 = gr.light({5, 5, 5}, {0.5, 0.5, 0.5})\n"                // 15
                           "gr.render(root, 'out.png', 320, 200, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 40,\n" // 16
                           "          {0.1, 0.1, 0.1}, {l1, l2, l1})\n"                       // 17
                           "gr.render(root, 'again.png', 64, 64, {0, 0, 1}, {0, 0, -1}, {0, 1, 0}, 40)\n" // 18
                           "local shoulder = gr.joint('shoulder', {-1.57, 0.5, 1.57}, {0, 0, 0})\n" // 19
                           "root:add_child(shoulder)\n");                                     // 20
    const OpenedDocument opened = open_document(registry(), path);
    const Document &doc = opened.document;
    std::vector<std::string> names;
    for (const Model &m : doc.models()) names.push_back(m.name);
    // Each use of the instanced leg is a model of its own, under its own stand; CSG's operands
    // are under its node.
    CHECK(names == std::vector<std::string>{"ball", "stand", "leg", "stand.001", "leg.001", "stand.002", "leg.002",
                                            "die", "c", "s", "shoulder"});
    CHECK(doc.models()[4].parent == 3);
    CHECK(doc.models()[9].parent == 7);
    CHECK(doc.models()[0].mesh == "sphere");
    CHECK(doc.models()[2].mesh == "cube");
    // The sphere of radius 0.5 about (1, 2, 3): our unit sphere scaled and moved.
    const ModelState &ball = *doc.keyframe_at(0).states[0];
    CHECK(ball.center == glm::dvec3(1, 2, 3));
    CHECK(ball.scale == glm::dvec3(0.5));
    const std::string p = path.string();
    CHECK(opened.warnings ==
          std::vector<std::string>{
              p + ":6: 2 node names were used before or empty, renamed to be unique: line 6 'stand' -> 'stand.001'; "
                  "line 6 'stand' -> 'stand.002'.",
              p + ":11: gr.intersection 'die' is shown as its two operands, 'c' and 's': animator does not draw CSG",
              p + ":13: a material colour above 1 is kept as written: brighter than white, it may wash out to white "
                  "where lit",
              p + ":18: gr.render is called again (first on line 16); the first call's root, camera, lights and "
                  "image are kept, this one and any later are ignored",
              p + ":19: joint 'shoulder': its ranges look like radians (all within 2 pi, not whole degrees); they "
                  "are read as degrees, as the course's viewer read them",
              p + ":4: node 'leg' is used 3 times (an instance: it was added under more than one parent); each use "
                  "is a model of its own, with everything under it: 'leg', 'leg.001', 'leg.002'"});
    // The first gr.render: its lights once each, in order; its ambient, image and camera.
    const Settings &s = doc.settings();
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0] == Light{"light", {0, 10, 0}, {2, 2, 2}, {1, 0, 0.01}});
    CHECK(s.lights[1] == Light{"light.001", {5, 5, 5}, {0.5, 0.5, 0.5}, {1, 0, 0}});
    CHECK(s.ambient == glm::dvec3(0.1));
    CHECK(s.render_output == "out.png");
    CHECK(s.render_width == 320);
    CHECK(s.render_height == 200);
    const CameraState &camera = *doc.keyframe_at(0).camera;
    CHECK(camera.position == glm::dvec3(0, 0, 10));
    CHECK(camera.fov_degrees == 40.0);
    // The joint's range is kept, read as written (degrees).
    REQUIRE(doc.models()[10].joint);
    CHECK(doc.models()[10].joint->min == glm::dvec3(-1.57, 0, 0));
    CHECK(doc.models()[10].joint->max == glm::dvec3(1.57, 0, 0));
    // gr.render and gr.camera both set the camera: an error, at the second's line.
    CHECK_THAT(load_error("both_cameras", "gr.camera{eye = {0, 0, 5}}\nlocal r = gr.sphere('s')\n"
                                          "gr.render(r, 'x.png', 8, 8, {0, 0, 1}, {0, 0, -1}, {0, 1, 0}, 40)\n"),
               Catch::Contains("both_cameras.lua:3: gr.render sets the camera, which gr.camera set on line 1"));
}
