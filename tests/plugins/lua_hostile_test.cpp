// Scenes written as an attacker would (issue 15): metamethods and finalizers that call back into
// gr.* while a node is being changed, errors thrown half-way, calls into Lua's C library that
// never return, and building more than the budgets allow. Each must end as a clear error or as
// the document the scene meant, with nothing written to freed memory (the ASan build would say).
#include "io/document_io.hpp"
#include "isolated_child.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

using namespace animator;
namespace fs = std::filesystem;

namespace {

PluginRegistry &registry() {
    static PluginRegistry r({test::bin_dir()}, [](ani_log_level, const std::string &, const std::string &) {});
    return r;
}

fs::path scene_file(const std::string &name, const std::string &lua) {
    const fs::path path = test::fresh_dir("lua_hostile_" + name) / (name + ".lua");
    test::write_file(path, lua);
    return path;
}

Document load(const std::string &name, const std::string &lua) {
    return open_document(registry(), scene_file(name, lua)).document;
}

std::string load_error_at(const fs::path &path) {
    try {
        open_document(registry(), path);
    } catch (const DocumentIoError &e) {
        return e.what();
    }
    return "(no error)";
}

std::string load_error(const std::string &name, const std::string &lua) { return load_error_at(scene_file(name, lua)); }

const Model &model(const Document &doc, const std::string &name) {
    const int i = doc.find_model(name);
    REQUIRE(i >= 0);
    return doc.models()[static_cast<size_t>(i)];
}

// An options table whose every field read makes 200 new nodes (the node list grows and, in a
// vector, moves) before answering from `values`.
const char *kGrowingOptions = R"(
local made = 0
local function growing(values)
  return setmetatable({}, {__index = function(_, key)
    for i = 1, 200 do made = made + 1; gr.node('grown' .. made) end
    return values[key]
  end})
end
)";

} // namespace

TEST_CASE("options whose fields make nodes while they are read still reach their node") {
    const Document doc = load("growing_options", std::string(kGrowingOptions) + R"(
local root = gr.node('root')
local a = gr.mesh('sphere', 'a')
root:add_child(a)
a:set_physics(growing{dynamics = true, gravity = true, mass = 5, velocity = {1, 2, 3}})
a:set_optics(growing{reflectivity = 0.25, transparency = 0.5, refractive_index = 1.5})
a:set_sound(growing{collision = 'click', moving = 'hum'})
return root
)");
    REQUIRE(doc.models().size() == 1);
    const Model &a = model(doc, "a");
    CHECK(a.dynamics);
    CHECK(a.gravity);
    CHECK(a.mass == 5.0);
    CHECK(a.initial_velocity == glm::dvec3(1, 2, 3));
    CHECK(a.reflectivity == 0.25);
    CHECK(a.transparency == 0.5);
    CHECK(a.refractive_index == 1.5);
    CHECK(a.collision_sound == "click");
    CHECK(a.moving_sound == "hum");
}

TEST_CASE("settings and camera read through metamethods that call gr.* again") {
    const Document doc = load("growing_settings", std::string(kGrowingOptions) + R"(
gr.settings(growing{gravity = 3, down = 'z', max_time = 12, cel = true, skybox = 'day'})
gr.camera(growing{eye = {0, 0, 5}, look_at = {0, 0, 0}, fov = 40})
local root = gr.node('root')
root:add_child(gr.mesh('cube', 'c'))
return root
)");
    CHECK(doc.settings().gravity == 3.0);
    CHECK(doc.settings().down_axis == Axis::Z);
    CHECK(doc.settings().max_time_ms == 12000);
    CHECK(doc.settings().cel_shading);
    CHECK(doc.keyframe_at(0).camera->fov_degrees == 40.0);

    // A settings table that calls gr.settings while it is read: the outer call is the second.
    CHECK_THAT(load_error("reentrant_settings", R"(
gr.settings(setmetatable({}, {__index = function() gr.settings{} end}))
return gr.node('r')
)"),
               Catch::Contains("reentrant_settings.lua:2: gr.settings is called twice (first on line 2)"));
}

TEST_CASE("an error thrown half-way through a node method leaves the node as it was") {
    const Document doc = load("half_way", R"(
local root = gr.node('root')
local a = gr.mesh('sphere', 'a')
root:add_child(a)
local ok, message = pcall(a.set_physics, a, setmetatable({}, {__index = function(_, key)
  if key == 'mass' then error('no mass for you') end
  if key == 'dynamics' or key == 'gravity' then return true end
end}))
assert(not ok and message:find('no mass for you'), message)
return root
)");
    const Model &a = model(doc, "a");
    CHECK_FALSE(a.dynamics); // read before the error, but never written
    CHECK_FALSE(a.gravity);
    CHECK(a.mass == 1.0);
}

TEST_CASE("an unknown key whose __tostring makes nodes is reported by its name") {
    CHECK_THAT(load_error("tostring_key", R"(
local root = gr.node('root')
local key = setmetatable({}, {__tostring = function()
  for i = 1, 500 do gr.node('t' .. i) end
  return 'sneaky'
end})
root:set_physics{[key] = true}
return root
)"),
               Catch::Contains("tostring_key.lua:7: unknown key 'sneaky' in set_physics"));
}

TEST_CASE("vectors with __len and __index proxies are refused, not trusted") {
    CHECK_THAT(load_error("len_proxy", R"(
local root = gr.node('root')
local fake = setmetatable({}, {__len = function() return 3 end, __index = function() return 1 end})
root:set_physics{velocity = fake}
return root
)"),
               Catch::Contains("len_proxy.lua:4: velocity must be a table of 3 numbers"));
}

TEST_CASE("finalizers that make nodes while gr.* builds its messages and nodes do no harm") {
    // Garbage with __gc that calls gr.node: collection steps run inside the API's allocations
    // (userdata for new nodes, the text of error messages), so finalizers run mid-call.
    const Document doc = load("finalizers", R"(
local made = 0
local function litter(n)
  for i = 1, n do
    setmetatable({}, {__gc = function() made = made + 1; gr.node('fin' .. made) end})
  end
end
local root = gr.node('root')
local a = gr.mesh('sphere', 'a')
local b = gr.node('b')
root:add_child(a)
root:add_child(b)
for round = 1, 200 do
  litter(50)
  local ok, message = pcall(b.add_child, b, root)
  assert(not ok, 'a cycle must be refused')
  assert(message:find("adding 'root' under 'b' would make a cycle", 1, true), message)
  local n = gr.node('round' .. round)
  n:translate(round, 0, 0)
  b:add_child(n)
end
return root
)");
    // a, b and b's 200 children: the nodes the finalizers made are not in the tree.
    CHECK(doc.models().size() == 202);
    const Model &last = model(doc, "round200");
    CHECK(last.parent == doc.find_model("b"));
    CHECK(doc.keyframe_at(0).states[static_cast<size_t>(doc.find_model("round200"))]->center == glm::dvec3(200, 0, 0));
}

TEST_CASE("a scene tree deeper than 1000 levels is refused, quickly") {
    CHECK_THAT(load_error("deep_chain", R"(
local root = gr.node('root')
local last = root
for i = 1, 100000 do
  local n = gr.node('n' .. i)
  last:add_child(n)
  last = n
end
return root
)"),
               Catch::Contains("deep_chain.lua:6: node 'n1000' is more than 1000 levels deep"));
}

TEST_CASE("nodes and names beyond their budget stop the scene") {
    // A million nodes with long names: little Lua memory (the names are garbage once copied),
    // but ~500 MB of nodes on the reader's side.
    CHECK_THAT(load_error("node_bomb", R"(
local long = string.rep('n', 300)
for i = 1, 1000000 do gr.node(long .. i) end
return gr.node('r')
)"),
               Catch::Contains("node_bomb.lua:3: the scene made more than its budget of 256 MiB of nodes and names"));
}

TEST_CASE("a call into Lua's C library that never returns is stopped with a clear error") {
    // Neither is seen by the instruction budget: each is one call into C.
    struct Hang {
        const char *name;
        const char *lua;
    };
    const Hang hangs[] = {
        {"pattern", "local s = string.rep('a', 50000)\nlocal found = s:find('a*a*a*b')\n"},
        {"empty_rep", "local s = string.rep('', 1 << 50)\n"},
    };
    for (const Hang &h : hangs) {
        CAPTURE(h.name);
        const fs::path path = scene_file(h.name, std::string(h.lua) + "return gr.node('r')\n");
        const std::string error = load_error_at(path);
        CHECK_THAT(error, Catch::StartsWith(path.string() + ": the scene was stopped"));
        CHECK_THAT(error, Catch::Contains("it used up its " + std::to_string(lua_scene::kChildCpuSeconds) + " s of processor time"));
    }
}

TEST_CASE("runaway scenes of every kind end in a clear error") {
    struct Runaway {
        const char *name;
        const char *lua;
        const char *expected;
    };
    const Runaway runaways[] = {
        {"concat",
         "local t = {}\nfor i = 1, 3e6 do t[i] = 'abcdefghijklmnopqrstuvwxyz0123456789' end\n"
         "local s = table.concat(t)\nlocal u = table.concat({s, s, s, s})\n",
         "concat.lua: the scene used more than its memory budget of 256 MiB"},
        {"sort", "local t = {}\nfor i = 1, 100 do t[i] = i end\ntable.sort(t, function(a, b) while true do end end)\n",
         "sort.lua:3: the scene ran past its budget of 200000000 instructions"},
        {"load", "local f = load(string.rep('x = 1 ', 4e7))\n",
         "load.lua: the scene used more than its memory budget of 256 MiB"},
        {"gsub_loop", "local s = string.rep('a', 1e6)\nfor i = 1, 1e9 do s:gsub('a', 'b') end\n",
         "gsub_loop.lua: the scene was stopped: it used up its"},
    };
    for (const Runaway &r : runaways) {
        CAPTURE(r.name);
        CHECK_THAT(load_error(r.name, std::string(r.lua) + "return gr.node('r')\n"), Catch::Contains(r.expected));
    }
}

TEST_CASE("a scene file larger than 64 MiB is refused before it is read") {
    const fs::path path = test::fresh_dir("lua_hostile_huge") / "huge.lua";
    test::write_file(path, "return gr.node('r')\n");
    fs::resize_file(path, (64u << 20) + 1); // sparse: nothing is written
    CHECK_THAT(load_error_at(path), Catch::Equals(path.string() + ": is larger than a scene file may be (64 MiB)"));
}
