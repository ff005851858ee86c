// The Lua scene plugin (id format.lua): reads CS488-style .lua scene files (docs/scene-lua.md)
// in a sandbox. Scenes are a starting point; work is saved as .ani, so this format only reads.
#include "lua_scene.hpp"

#include <animator/file_format.h>
#include <animator/plugin_cpp.hpp>

#include <cstring>
#include <map>
#include <memory>

namespace {

constexpr char kPluginId[] = "format.lua";

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
        auto doc = std::make_unique<ani::OwnedDocument>();
        std::string error;
        if (!lua_scene::read_scene(path, self->host, *doc, error)) throw ani::Failure(ANI_ERR_PARSE, error);
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
