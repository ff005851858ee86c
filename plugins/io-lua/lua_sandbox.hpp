// A Lua state in which a scene file someone sent you is safe to run: no files, no programs, no
// C modules, no bytecode, and a budget of instructions and memory after which it stops with a
// clear error.
#pragma once

// Debian's lua5.4-c++ build: Lua compiled as C++, so its headers are included without
// extern "C" and lua_error unwinds with an exception instead of longjmp.
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>

#include <cstddef>
#include <string>

namespace lua_scene {

struct SandboxLimits {
    std::size_t memory_bytes = 256u << 20;  // 256 MiB
    long long instructions = 200'000'000;   // a few seconds of Lua at most
};

class Sandbox {
  public:
    explicit Sandbox(SandboxLimits limits = {});
    ~Sandbox();
    Sandbox(const Sandbox &) = delete;
    Sandbox &operator=(const Sandbox &) = delete;

    lua_State *state() const { return L_; }

    // Loads `text` as a text chunk named `@path` (bytecode is refused) and runs it, leaving its
    // results on the stack. Returns false with "path:line: message" in `error`.
    bool run(const std::string &path, const std::string &text, int results, std::string &error);

  private:
    static void *allocate(void *ud, void *ptr, std::size_t old_size, std::size_t new_size);
    static void count_hook(lua_State *L, lua_Debug *ar);

    SandboxLimits limits_;
    std::size_t used_ = 0;
    long long executed_ = 0;
    bool out_of_memory_ = false;
    lua_State *L_ = nullptr;
};

} // namespace lua_scene
