#include "lua_sandbox.hpp"

#include <cstdlib>

namespace lua_scene {

namespace {

constexpr int kHookEvery = 10000; // instructions between budget checks
constexpr lua_Integer kRandomSeed = 0; // math.randomseed(0), as docs/scene-lua.md says
// The chunk's name in Lua's messages; replaced by the file's full path afterwards, because Lua
// cuts source names to LUA_IDSIZE (60) characters.
constexpr const char *kChunkMarker = "<scene>";

// Only what computes; nothing that reaches files, programs, modules or the debug library.
const char *const kRemovedGlobals[] = {"dofile", "loadfile", "require", "collectgarbage",
                                       "load", "loadstring", "module"};

// `load` for text only, without access to an outside environment (it is given the sandbox's).
int safe_load(lua_State *L) {
    size_t size = 0;
    const char *text = luaL_checklstring(L, 1, &size);
    const char *name = luaL_optstring(L, 2, "=(load)");
    if (luaL_loadbufferx(L, text, size, name, "t") != LUA_OK) {
        lua_pushnil(L);
        lua_insert(L, -2);
        return 2;
    }
    return 1;
}

} // namespace

Sandbox::Sandbox(SandboxLimits limits) : limits_(limits) {
    L_ = lua_newstate(&Sandbox::allocate, this);
    if (!L_) return;
    // The safe standard libraries, one by one (luaL_openlibs would open io, os, package, debug).
    const luaL_Reg libs[] = {{LUA_GNAME, luaopen_base},       {LUA_TABLIBNAME, luaopen_table},
                             {LUA_STRLIBNAME, luaopen_string}, {LUA_MATHLIBNAME, luaopen_math},
                             {LUA_UTF8LIBNAME, luaopen_utf8}};
    for (const auto &lib : libs) {
        luaL_requiref(L_, lib.name, lib.func, 1);
        lua_pop(L_, 1);
    }
    for (const char *name : kRemovedGlobals) {
        lua_pushnil(L_);
        lua_setglobal(L_, name);
    }
    lua_pushcfunction(L_, safe_load);
    lua_setglobal(L_, "load");
    // Lua seeds math.random from the clock and addresses; a scene that scatters models with it
    // would open differently each time, and its keyframes would no longer match. A fixed seed
    // makes every opening the same (a scene may still call math.randomseed itself).
    lua_getglobal(L_, "math");
    lua_getfield(L_, -1, "randomseed");
    lua_pushinteger(L_, kRandomSeed);
    lua_call(L_, 1, 0);
    lua_pop(L_, 1);
    // string.dump makes bytecode, which a scene never needs.
    lua_getglobal(L_, "string");
    lua_pushnil(L_);
    lua_setfield(L_, -2, "dump");
    lua_pop(L_, 1);
    lua_sethook(L_, &Sandbox::count_hook, LUA_MASKCOUNT, kHookEvery);
    lua_pushlightuserdata(L_, this);
    lua_setfield(L_, LUA_REGISTRYINDEX, "animator.sandbox");
}

Sandbox::~Sandbox() {
    if (L_) lua_close(L_);
}

void *Sandbox::allocate(void *ud, void *ptr, std::size_t old_size, std::size_t new_size) {
    auto *self = static_cast<Sandbox *>(ud);
    const std::size_t old_bytes = ptr ? old_size : 0;
    if (new_size == 0) {
        std::free(ptr);
        self->used_ -= old_bytes;
        return nullptr;
    }
    if (new_size > old_bytes && self->used_ + (new_size - old_bytes) > self->limits_.memory_bytes) {
        self->out_of_memory_ = true;
        return nullptr; // Lua raises a memory error
    }
    void *grown = std::realloc(ptr, new_size);
    if (grown) self->used_ = self->used_ - old_bytes + new_size;
    return grown;
}

void Sandbox::count_hook(lua_State *L, lua_Debug *) {
    lua_getfield(L, LUA_REGISTRYINDEX, "animator.sandbox");
    auto *self = static_cast<Sandbox *>(lua_touserdata(L, -1));
    lua_pop(L, 1);
    self->executed_ += kHookEvery;
    if (self->executed_ <= self->limits_.instructions) return;
    lua_Debug where;
    int line = 0;
    if (lua_getstack(L, 0, &where) && lua_getinfo(L, "l", &where)) line = where.currentline;
    luaL_error(L, "%s:%d: the scene ran past its budget of %I instructions (an endless loop?)",
               kChunkMarker, line, static_cast<lua_Integer>(self->limits_.instructions));
}

bool Sandbox::run(const std::string &path, const std::string &text, int results, std::string &error) {
    if (!L_) {
        error = path + ": cannot create a Lua state";
        return false;
    }
    const std::string chunk = std::string("=") + kChunkMarker;
    const int loaded = luaL_loadbufferx(L_, text.data(), text.size(), chunk.c_str(), "t");
    const int status = loaded == LUA_OK ? lua_pcall(L_, 0, results, 0) : loaded;
    if (status == LUA_OK) return true;
    if (status == LUA_ERRMEM || out_of_memory_) {
        error = path + ": the scene used more than its memory budget of " +
                std::to_string(limits_.memory_bytes >> 20) + " MiB";
    } else if (loaded != LUA_OK && !text.empty() && text[0] == LUA_SIGNATURE[0]) {
        // Lua takes any chunk starting with ESC as binary, and says so without a chunk name.
        error = path + ": is Lua bytecode; scenes must be Lua source text";
    } else {
        const char *message = lua_tostring(L_, -1);
        error = message ? message : std::string(kChunkMarker) + ": unknown Lua error";
        const std::string marker = std::string(kChunkMarker) + ":";
        for (size_t at = error.find(marker); at != std::string::npos;
             at = error.find(marker, at + path.size() + 1))
            error.replace(at, marker.size(), path + ":");
        if (error.rfind(path, 0) != 0) error = path + ": " + error; // every message names the file
    }
    lua_pop(L_, 1);
    return false;
}

} // namespace lua_scene
