#include "cli/cli_support.hpp"

#include "timeline/bake_file.hpp"

#include "assets/mesh.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>

namespace animator::cli {

std::string csv_field(const std::string &s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string number(double x) {
    char buf[32];
    (void)std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)), tty_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
    if (shown_) std::cerr << "\r" << std::string(60, ' ') << "\r" << std::flush;
}

bool ProgressBar::operator()(double fraction) {
    if (!tty_) return true;
    const auto elapsed = std::chrono::steady_clock::now() - start_;
    if (elapsed < std::chrono::seconds(1)) return true;
    shown_ = true;
    const int filled = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 40.0);
    std::cerr << "\r" << label_ << " [" << std::string(static_cast<size_t>(filled), '#')
              << std::string(static_cast<size_t>(40 - filled), '.') << "] "
              << static_cast<int>(fraction * 100.0) << "%" << std::flush;
    return true;
}

// "NAME=VALUE" or "NAME=V1,V2,V3" for a parameter of the chosen backend.
void apply_params(Document &doc, const std::string &backend,
                  const std::vector<std::string> &params) {
    Settings settings = doc.settings();
    for (const std::string &p : params) {
        const auto eq = p.find('=');
        if (eq == std::string::npos || eq == 0)
            throw std::invalid_argument("--param needs NAME=VALUE, got '" + p + "'");
        ParamValue value{};
        size_t i = 0, at = eq + 1;
        while (at <= p.size() && i < 4) {
            const size_t comma = std::min(p.find(',', at), p.size());
            const std::string part = p.substr(at, comma - at);
            char *end = nullptr;
            value[i++] = std::strtod(part.c_str(), &end);
            if (part.empty() || *end != '\0' || !std::isfinite(value[i - 1]))
                throw std::invalid_argument("--param " + p.substr(0, eq) + ": '" + part +
                                            "' is not a number");
            at = comma + 1;
        }
        settings.params[backend][p.substr(0, eq)] = value;
    }
    doc.set_settings(settings);
}

namespace {
std::size_t warnings_said = 0;
} // namespace

bool &strict_mode() {
    static bool strict = false;
    return strict;
}

void warn(const std::string &message) {
    std::cerr << "animator: warning: " << message << "\n";
    ++warnings_said;
}

void count_warnings(std::size_t n) { warnings_said += n; }

void stop_if_strict(const std::string &file) {
    if (strict_mode() && warnings_said > 0)
        throw std::runtime_error(file + ": " + std::to_string(warnings_said) +
                                 (warnings_said == 1 ? " warning" : " warnings") +
                                 " (said above), which --strict makes errors");
}

std::optional<OpenedDocument> open_or_report(PluginRegistry &plugins, const std::string &file) {
    std::optional<OpenedDocument> opened;
    try {
        opened = open_document(plugins, file);
    } catch (const DocumentIoError &e) {
        std::cerr << "animator: " << e.what() << "\n";
        return std::nullopt;
    }
    count_warnings(opened->warnings.size());
    stop_if_strict(file);
    return opened;
}

std::optional<double> bake_end(const Document &doc, const std::string &file, double until) {
    const double max_time = static_cast<double>(doc.settings().max_time_ms) / 1000.0;
    const double end = until < 0.0 ? max_time : until;
    if (end > max_time) {
        std::cerr << "animator: " << file << ": --until " << end
                  << " s is past the animation's max time " << max_time << " s\n";
        return std::nullopt;
    }
    return end;
}

std::vector<std::string> param_names(PluginRegistry &plugins, const std::string &plugin_id) {
    std::vector<std::string> names;
    const PluginInfo *info = plugins.find(plugin_id);
    if (!info || !info->descriptor) return names;
    for (uint32_t k = 0; k < info->descriptor->param_count; ++k)
        names.emplace_back(info->descriptor->params[k].id);
    return names;
}

std::vector<std::shared_ptr<const Mesh>> load_document_meshes(Timeline &timeline, const Environment &env,
                                                              const std::filesystem::path &file,
                                                              const std::vector<std::string> &said) {
    std::vector<std::string> mesh_ids, warnings;
    for (const Model &m : timeline.document().models()) mesh_ids.push_back(m.mesh);
    auto meshes = load_meshes(mesh_ids, env.assets, file, warnings);
    for (const std::string &w : not_said_before(std::move(warnings), said)) warn(w);
    stop_if_strict(file.string());
    timeline.set_meshes(meshes);
    return meshes;
}

bool bake_or_load(Timeline &timeline, const std::string &file, const std::string &bake_file, double until) {
    if (bake_file.empty()) {
        ProgressBar bar("baking");
        timeline.bake(until, [&](double f) { return bar(f); });
        return true;
    }
    try {
        load_bake(timeline, bake_file, until);
        return true;
    } catch (const BakeFileError &e) {
        std::cerr << "animator: " << file << ": --bake " << e.what() << "\n";
        return false;
    }
}

const char *const kBakeOptionHelp =
    "use this bake (animator bake FILE --save FILE.bake) instead of baking: the machines of a render farm share "
    "one; refused unless it was made from this document, backend, parameters and meshes and reaches as far as "
    "needed (docs/render-farm.md)";

} // namespace animator::cli
