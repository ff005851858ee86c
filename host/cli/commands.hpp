// The subcommands of the `animator` executable. Each registers itself on the CLI11 app and
// returns the process exit code when run: 0 success, 1 bad input, 2 usage error.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace animator::cli {

enum ExitCode { kSuccess = 0, kBadInput = 1, kUsage = 2 };

// Sets `run` to the subcommand's action when the user picks it.
void add_plugins_command(CLI::App &app, std::function<int()> &run);
void add_info_command(CLI::App &app, std::function<int()> &run);
void add_bake_command(CLI::App &app, std::function<int()> &run);
void add_compare_command(CLI::App &app, std::function<int()> &run);
void add_render_command(CLI::App &app, std::function<int()> &run);
void add_soundtrack_command(CLI::App &app, std::function<int()> &run);
void add_export_command(CLI::App &app, std::function<int()> &run);
// `animator [edit] [FILE]`: the editor, also what runs without a subcommand.
void add_edit_command(CLI::App &app, std::function<int()> &run);

} // namespace animator::cli
