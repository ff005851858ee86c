// `animator [edit] [FILE]`: opens the editor on a .lua scene or an .ani animation, or on the
// demo scene without one.
#include "cli/commands.hpp"

#include "editor/editor_app.hpp"

#include <filesystem>
#include <memory>

namespace animator::cli {

void add_edit_command(CLI::App &app, std::function<int()> &run) {
    // `animator FILE` and a bare `animator` open the editor too (when no subcommand ran).
    auto top = std::make_shared<EditorOptions>();
    app.add_option("FILE", top->file, "open the editor on this animation (.ani) or scene (.lua)")
        ->check([](const std::string &file) -> std::string {
            // A mistyped subcommand is a usage error, not a file the editor fails to open.
            const std::filesystem::path p(file);
            std::error_code ec;
            if (p.extension() == ".ani" || p.extension() == ".lua" || std::filesystem::is_regular_file(p, ec)) return "";
            return "'" + file + "' is neither a subcommand nor an animation (.ani) or scene (.lua)";
        });
    app.final_callback([&run, top] {
        if (!run) run = [top] { return run_editor(*top); };
    });
    auto o = std::make_shared<EditorOptions>();
    CLI::App *cmd = app.add_subcommand("edit", "Open the editor (also: `animator FILE`, or `animator` for the demo)");
    cmd->add_option("FILE", o->file, "an animation (.ani) or scene (.lua); none opens the demo scene");
    cmd->callback([&run, o] { run = [o] { return run_editor(*o); }; });
}

} // namespace animator::cli
