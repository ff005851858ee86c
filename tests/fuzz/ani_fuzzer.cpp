// libFuzzer harness of the .ani reader (plugins/io-ani), through the plugin's C entry as the
// host calls it: each input is written to a .ani file, probed, read, turned into the host's
// document and released.
//
// The plugin's sources are compiled into this executable (tests/fuzz/CMakeLists.txt) rather
// than dlopen'ed from an instrumented .so: libFuzzer then sees their coverage from the first
// input, no shared ASan runtime is needed, and `animator_plugin_entry` is the very symbol the
// host resolves with dlsym.
#include "format_plugin_driver.hpp"
#include "fuzz_host.hpp"
#include "input_file.hpp"

#include <cstddef>
#include <cstdint>

extern "C" const ani_plugin_entry animator_plugin_entry;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace animator::fuzz;
    static FormatPluginDriver plugin(animator_plugin_entry, fuzz_host());
    plugin.open(write_input(data, size, ".ani"), data, size);
    return 0;
}
