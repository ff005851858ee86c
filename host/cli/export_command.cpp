// `animator export FILE --to OUT.glb|OUT.gltf`: bakes an animation and writes it as glTF 2.0
// (docs/export.md), for Blender, game engines and web viewers.
#include "cli/cli_support.hpp"
#include "cli/commands.hpp"

#include "export/gltf_export.hpp"
#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "timeline/timeline.hpp"

#include <algorithm>
#include <iostream>

namespace animator::cli {

namespace {

struct ExportOptions {
    std::string file, out, backend, bake;
    std::vector<std::string>
        to; // the form: --to OUT.glb and --to S, told apart by the value
    std::vector<std::string> params;
    double from = 0.0, until = -1.0, fps = 0.0;
};

bool is_gltf_name(const std::string &s) {
    std::string ext = std::filesystem::path(s).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    return ext == ".glb" || ext == ".gltf";
}

// --to OUT.glb names the file, --to S (a number) the end time; --out and --until say each alone.
int sort_to_options(ExportOptions &o) {
    for (const std::string &v : o.to) {
        if (is_gltf_name(v)) {
            if (!o.out.empty()) {
                std::cerr << "animator: export: two files to write: " << o.out << " and " << v
                          << "\n";
                return kUsage;
            }
            o.out = v;
            continue;
        }
        size_t used = 0;
        double t = -1.0;
        try {
            t = std::stod(v, &used);
        } catch (const std::exception &) {
            used = 0;
        }
        if (used != v.size() || !(t >= 0.0) || o.until >= 0.0) {
            std::cerr << "animator: export: --to " << v
                      << ": expected the file to write (ending in .glb or .gltf) or, once, the end "
                         "time in seconds\n";
            return kUsage;
        }
        o.until = t;
    }
    if (o.out.empty()) {
        std::cerr
            << "animator: export: the file to write is missing: --to OUT.glb or --to OUT.gltf\n";
        return kUsage;
    }
    if (!is_gltf_name(o.out)) {
        std::cerr << "animator: export: " << o.out
                  << ": a glTF file ends in .glb (binary) or .gltf (text)\n";
        return kUsage;
    }
    return kSuccess;
}

int run_export(ExportOptions o) {
    if (const int usage = sort_to_options(o)) return usage;
    Environment env;
    std::optional<OpenedDocument> opened = open_or_report(env.plugins, o.file);
    if (!opened) return kBadInput;
    Document &doc = opened->document;
    const std::optional<double> end = bake_end(doc, o.file, o.until);
    if (!end) return kBadInput;
    if (o.from > *end) {
        std::cerr << "animator: " << o.file << ": --from " << o.from
                  << " s is after the export's end, " << *end << " s\n";
        return kBadInput;
    }
    try {
        const std::string backend = o.backend.empty() ? doc.settings().physics_backend : o.backend;
        apply_params(doc, backend, o.params);
        Timeline timeline(doc, env.plugins, o.backend);
        const auto meshes = load_document_meshes(timeline, env, o.file, opened->warnings);
        if (!bake_or_load(timeline, o.file, o.bake, *end)) return kBadInput;

        MotionKeyOptions keys;
        keys.from = o.from;
        keys.until = *end;
        keys.fps = o.fps;
        const GltfExportReport report =
            export_gltf(timeline, meshes, env.assets, o.file, o.out, keys);
        for (const std::string &n : report.notes) std::cerr << "animator: note: " << n << "\n";
        std::cout << "wrote " << o.out << ": " << report.nodes << " nodes, " << report.channels
                  << " animated channels, " << report.keys << " keys";
        if (o.fps <= 0.0) {
            const MotionKeyStats &p = report.pieces;
            std::cout << " (" << p.translation.exact + p.scale.exact << " spans exact and "
                      << p.translation.sampled + p.scale.sampled
                      << " sampled in translation and scale; " << p.rotation.exact
                      << " turns exact and " << p.rotation.sampled << " sampled)";
        }
        if (report.merged_keys > 0)
            std::cout << "; " << report.merged_keys
                      << " keys float32 could not tell from the one before merged";
        std::cout << "\n";
        return kSuccess;
    } catch (const std::exception &e) {
        std::cerr << "animator: " << o.file << ": " << e.what() << "\n";
        return kBadInput;
    }
}

} // namespace

void add_export_command(CLI::App &app, std::function<int()> &run) {
    auto o = std::make_shared<ExportOptions>();
    CLI::App *cmd = app.add_subcommand(
        "export", "Bake an animation and write it as glTF 2.0 (.glb or .gltf) for Blender, "
                  "game engines and web viewers (docs/export.md)");
    cmd->add_option("FILE", o->file, "an animation (.ani) or scene (.lua)")->required();
    cmd->add_option("--to", o->to,
                    "OUT.glb or OUT.gltf: the file to write (.glb binary; .gltf text with its "
                    "buffers inside); "
                    "given a number, S, the end of the export in seconds (default: the max time)")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    cmd->add_option("--out,-o", o->out, "the file to write, as --to OUT");
    cmd->add_option("--from", o->from,
                    "start of the export in seconds (default 0); the glTF animation starts there")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--until", o->until, "the end of the export in seconds, as --to S")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--fps", o->fps,
                    "instead of the exact keys, one LINEAR key per frame at this rate, as Blender "
                    "and Maya bake "
                    "(for clients that read only LINEAR)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--backend", o->backend,
                    "physics backend plugin id (default: the animation's)");
    cmd->add_option("--param", o->params, "a backend parameter, NAME=VALUE (repeatable)");
    cmd->add_option("--bake", o->bake, kBakeOptionHelp);
    cmd->callback([&run, o] { run = [o] { return run_export(*o); }; });
}

} // namespace animator::cli
