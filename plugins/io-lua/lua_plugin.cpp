// The Lua scene plugin (id format.lua): reads CS488-style .lua scene files (docs/scene-lua.md)
// in a Lua sandbox inside a child process with limits (isolated_child.hpp), then makes the
// document here. Scenes are a starting point; work is saved as .ani, so this format only reads.
#include "isolated_child.hpp"
#include "lua_scene.hpp"
#include "scene_document.hpp"
#include "scene_wire.hpp"

#include <animator/file_format.h>
#include <animator/plugin_cpp.hpp>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

namespace {

constexpr char kPluginId[] = "format.lua";
constexpr std::streamoff kMaxSceneFileBytes = 64 << 20; // a scene is a script, not data

using lua_scene::ChildEnd;

// ANIMATOR_LUA_IN_PROCESS=1 runs scenes in the calling process, unprotected: for the fuzzers
// (which see no coverage of a child) and for debugging only.
bool run_in_process() {
    const char *value = std::getenv("ANIMATOR_LUA_IN_PROCESS");
    return value && std::strcmp(value, "1") == 0;
}

std::string read_text(const std::string &path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw ani::Failure(ANI_ERR_IO, path + ": cannot open the file");
    if (in.tellg() > kMaxSceneFileBytes)
        throw ani::Failure(ANI_ERR_PARSE, path + ": is larger than a scene file may be (" +
                                              std::to_string(kMaxSceneFileBytes >> 20) + " MiB)");
    in.seekg(0);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Runs the scene in a child process (isolated_child.hpp) and reads its reply.
bool run_scene_isolated(const std::string &path, const std::string &text, lua_scene::SceneResult &out,
                        std::string &error) {
    const lua_scene::ChildLimits limits;
    const auto child = lua_scene::run_in_isolated_child(
        [&]() -> std::string {
            try {
                lua_scene::SceneResult scene;
                std::string scene_error;
                return lua_scene::run_scene(path, text, scene, scene_error) ? lua_scene::encode_result(scene)
                                                                            : lua_scene::encode_error(scene_error);
            } catch (const std::bad_alloc &) {
                return lua_scene::encode_error(path + ": the scene used more memory than it may (" +
                                               std::to_string(limits.extra_address_space >> 20) + " MiB)");
            } catch (const std::exception &e) {
                return lua_scene::encode_error(path + ": " + e.what());
            }
        },
        limits);
    switch (child.end) {
    case ChildEnd::replied:
        return lua_scene::decode_reply(child.reply, path, out, error);
    case ChildEnd::out_of_time:
        error = path + ": the scene was stopped: it " + child.detail +
                " (a call into Lua's library, such as a string pattern search, can run for hours)";
        return false;
    case ChildEnd::crashed:
        error = path + ": the scene reader crashed: it " + child.detail +
                "; this is a bug in animator, please report it with the scene file";
        return false;
    case ChildEnd::cannot_start:
        error = path + ": cannot run the scene: " + child.detail;
        return false;
    }
    return false;
}

struct LuaInstance {
    const ani_host *host = nullptr;
    std::map<const ani_document_view *, std::unique_ptr<ani::OwnedDocument>> read_documents;
};

void *lua_create(const ani_host *host, ani_status *status) {
    LuaInstance *self = nullptr;
    ani::guarded(status, [&] {
        self = new LuaInstance();
        self->host = host;
    });
    return self;
}

void lua_destroy(void *instance) { delete static_cast<LuaInstance *>(instance); }

int32_t lua_probe(void *, const char *path, const unsigned char *head, size_t head_size) {
    const size_t n = path ? std::strlen(path) : 0;
    if (n >= 4 && std::strcmp(path + n - 4, ".lua") == 0) return 90;
    // Lua bytecode starts with ESC "Lua": say we read it, to refuse it with a clear message.
    if (head_size >= 4 && std::memcmp(head, "\x1bLua", 4) == 0) return 60;
    return 0;
}

ani_status_code lua_read(void *instance, const char *path, const ani_document_view **document,
                         ani_status *status) {
    auto *self = static_cast<LuaInstance *>(instance);
    return ani::guarded(status, [&] {
        const std::string file = path;
        const std::string text = read_text(file);
        lua_scene::SceneResult scene;
        std::string error;
        const bool ran = run_in_process() ? lua_scene::run_scene(file, text, scene, error)
                                          : run_scene_isolated(file, text, scene, error);
        auto doc = std::make_unique<ani::OwnedDocument>();
        if (!ran) throw ani::Failure(ANI_ERR_PARSE, error);
        lua_scene::build_document(scene, file, self->host, *doc);
        *document = &doc->view;
        self->read_documents[&doc->view] = std::move(doc);
    });
}

void lua_release(void *instance, const ani_document_view *document) {
    static_cast<LuaInstance *>(instance)->read_documents.erase(document);
}

const char *const lua_extensions[] = {"lua"};

const ani_file_format_api lua_api = {
    sizeof(ani_file_format_api),
    {sizeof(ani_instance_api), lua_create, lua_destroy, ani::no_param_get<kPluginId>, ani::no_param_set<kPluginId>},
    ANI_FORMAT_CAN_READ,
    lua_extensions,
    1,
    lua_probe,
    lua_read,
    lua_release,
    nullptr,
};

const ani_plugin_descriptor lua_descriptor = {
    sizeof(ani_plugin_descriptor),
    kPluginId,
    ANI_KIND_FILE_FORMAT,
    "Lua scene (.lua)",
    {1, 0, 0},
    "Reads CS488-style Lua scene files, with animator's extensions, in a sandbox.",
    nullptr,
    0,
    &lua_api,
};

const ani_plugin_descriptor *const kPlugins[] = {&lua_descriptor};

} // namespace

ANI_PLUGIN_ENTRY(kPlugins)
