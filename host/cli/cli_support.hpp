// What the subcommands that bake share: CSV fields, numbers that read back exactly, a progress
// bar on a terminal, backend parameters from the command line, and a document's meshes.
#pragma once

#include "document/document.hpp"
#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "timeline/timeline.hpp"

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace animator::cli {

// --strict (a flag of every subcommand, for scripts): the warnings a file gives (a renamed node,
// a dropped shear, a mesh read leniently) are errors.
bool &strict_mode();
// Says a warning on stderr ("animator: warning: ..."), and counts it.
void warn(const std::string &message);
// Counts warnings said elsewhere (a reader's, which the plugins' log said).
void count_warnings(std::size_t n);
// With --strict, after any warning: throws std::runtime_error naming the file and the count (the
// command stops there, exit 1, before it writes anything).
void stop_if_strict(const std::string &file);

// A CSV field, quoted when it has to be.
std::string csv_field(const std::string &s);

// A double with all 17 significant digits.
std::string number(double x);

// Opens a document through the file-format plugins; when it cannot, says why on stderr (the
// message names the file and line) and gives none.
std::optional<OpenedDocument> open_or_report(PluginRegistry &plugins, const std::string &file);

// Where a bake of `doc` ends: `until` seconds, or the animation's max time when `until` is
// negative. None, said on stderr, when `until` is past the max time.
std::optional<double> bake_end(const Document &doc, const std::string &file, double until);

// A progress bar on a terminal, for bakes longer than a second; nothing otherwise.
class ProgressBar {
  public:
    explicit ProgressBar(std::string label = "baking");
    ~ProgressBar();
    ProgressBar(const ProgressBar &) = delete;
    ProgressBar &operator=(const ProgressBar &) = delete;
    bool operator()(double fraction);

  private:
    std::string label_;
    bool tty_, shown_ = false;
    std::chrono::steady_clock::time_point start_;
};

// "NAME=VALUE" or "NAME=V1,V2,V3" for a parameter of `backend`, into the document's settings.
// Throws std::invalid_argument for a malformed one.
void apply_params(Document &doc, const std::string &backend,
                  const std::vector<std::string> &params);

// The names of the parameters that a plugin declares.
std::vector<std::string> param_names(PluginRegistry &plugins, const std::string &plugin_id);

// Gives the timeline the meshes of the document's models (found next to `file` too) and returns
// them (one per model, null for an empty); warnings go to stderr, but for those its reader `said`
// already. With --strict, a warning stops it (stop_if_strict).
std::vector<std::shared_ptr<const Mesh>> load_document_meshes(Timeline &timeline, const Environment &env,
                                                              const std::filesystem::path &file,
                                                              const std::vector<std::string> &said);

// Bakes the timeline up to `until` seconds (with a progress bar), or, with a `bake_file`
// (`--bake`, from `animator bake --save`), takes that bake instead. False, said on stderr naming
// `file` and the bake file, when the bake file is refused (docs/render-farm.md).
bool bake_or_load(Timeline &timeline, const std::string &file, const std::string &bake_file, double until);

// The help of a subcommand's --bake option.
extern const char *const kBakeOptionHelp;

} // namespace animator::cli
