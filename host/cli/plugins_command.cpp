// `animator plugins`: every plugin found, and why any library was refused.
#include "cli/commands.hpp"

#include "plugin/descriptor_check.hpp"
#include "plugin/registry.hpp"

#include <iomanip>
#include <iostream>

namespace animator::cli {

void add_plugins_command(CLI::App &app, std::function<int()> &run) {
    CLI::App *cmd = app.add_subcommand(
        "plugins", "List every plugin found beside the executable and on ANIMATOR_PLUGIN_PATH");
    cmd->callback([&run] {
        run = [] {
            PluginRegistry registry(PluginRegistry::default_search_dirs());
            registry.load_all();
            std::cout << std::left << std::setw(24) << "ID" << std::setw(14) << "KIND"
                      << std::setw(10) << "VERSION" << "LIBRARY\n";
            for (const PluginInfo *p : registry.loaded()) {
                const std::string version = std::to_string(p->version.major) + "." +
                                            std::to_string(p->version.minor) + "." +
                                            std::to_string(p->version.patch);
                std::cout << std::setw(24) << p->id << std::setw(14) << kind_name(p->kind)
                          << std::setw(10) << version << p->library.string() << "\n";
            }
            if (registry.loaded().empty()) std::cout << "(no plugins found)\n";
            for (const LibraryRefusal &r : registry.refusals())
                std::cout << "refused " << r.library.string() << ": " << r.reason << "\n";
            return static_cast<int>(kSuccess);
        };
    });
}

} // namespace animator::cli
