// libFuzzer harness of the Lua scene reader (plugins/io-lua), through the plugin's C entry as
// the host calls it: each input is written to a .lua file, probed, read (run in the plugin's
// sandbox), turned into the host's document and released.
//
// The plugin's sources are compiled into this executable, as in ani_fuzzer.cpp. The Lua
// interpreter is Debian's shared library and is not instrumented: libFuzzer is guided by the
// plugin's own code (the gr.* API, the node tree, the sandbox's hooks), not by Lua's parser.
#include "format_plugin_driver.hpp"
#include "fuzz_host.hpp"
#include "input_file.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

extern "C" const ani_plugin_entry animator_plugin_entry;

extern "C" int LLVMFuzzerInitialize(int *, char ***) {
    // The plugin runs each scene in a child process with resource limits; a child's coverage
    // and crashes are invisible to libFuzzer, so run scenes in this process (for fuzzing and
    // debugging only).
    setenv("ANIMATOR_LUA_IN_PROCESS", "1", 1);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace animator::fuzz;
    static FormatPluginDriver plugin(animator_plugin_entry, fuzz_host());
    plugin.open(write_input(data, size, ".lua"), data, size);
    return 0;
}
