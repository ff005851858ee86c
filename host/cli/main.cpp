// animator: the command line face of the program. The editor (`animator [edit] FILE`) and the
// later subcommands (bake, render, compare, soundtrack) plug in here beside `plugins` and `info`.
#include "cli/cli_support.hpp"
#include "cli/commands.hpp"

#include <iostream>

namespace {

int run_cli(int argc, char **argv) {
    using namespace animator::cli;
    CLI::App app{"animator: a 3D keyframe animator in which models obey physics", "animator"};
    app.set_version_flag("--version", "animator 0.1.0");
    app.require_subcommand(0, 1);
    // Given before or after the subcommand (which falls through to these options).
    app.add_flag("--strict", animator::cli::strict_mode(),
                 "treat the warnings a file gives (renamed nodes, dropped shear, meshes read leniently) as errors: exit 1");
    app.fallthrough();

    std::function<int()> run;
    add_plugins_command(app, run);
    add_info_command(app, run);
    add_bake_command(app, run);
    add_compare_command(app, run);
    add_render_command(app, run);
    add_soundtrack_command(app, run);
    add_export_command(app, run);
    add_edit_command(app, run);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp &e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp &e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion &e) {
        return app.exit(e);
    } catch (const CLI::ParseError &e) {
        app.exit(e);
        return kUsage;
    }
    try {
        return run();
    } catch (const std::exception &e) {
        std::cerr << "animator: " << e.what() << "\n";
        return kBadInput;
    }
}

} // namespace

int main(int argc, char **argv) {
    try {
        return run_cli(argc, argv);
    } catch (...) {
        std::cerr << "animator: an unexpected error stopped the program\n";
        return animator::cli::kBadInput;
    }
}
