// `animator soundtrack FILE --out PATH.wav`: bakes an animation and mixes every collision and
// moving sound at its exact time and volume into a 16-bit stereo WAV file, the same mix that
// live playback makes (docs/sound.md), to go under a rendered video.
#include "cli/cli_support.hpp"
#include "cli/commands.hpp"

#include "audio/mixer.hpp"
#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "timeline/timeline.hpp"

#include <iostream>

namespace animator::cli {

namespace {

struct SoundtrackOptions {
    std::string file, out, backend, bake;
    std::vector<std::string> params;
    double until = -1.0;
    int rate = 44100;
};

int run_soundtrack(const SoundtrackOptions &o) {
    Environment env;
    std::optional<OpenedDocument> opened = open_or_report(env.plugins, o.file);
    if (!opened) return kBadInput;
    Document &doc = opened->document;
    const std::optional<double> end = bake_end(doc, o.file, o.until);
    if (!end) return kBadInput;
    try {
        const std::string backend = o.backend.empty() ? doc.settings().physics_backend : o.backend;
        apply_params(doc, backend, o.params);
        // Every sound is read before the bake, so a missing one is said at once.
        audio::SoundBank bank(env.assets);
        audio::load_document_sounds(doc, bank);

        Timeline timeline(doc, env.plugins, o.backend);
        load_document_meshes(timeline, env, o.file, opened->warnings);
        if (!bake_or_load(timeline, o.file, o.bake, *end)) return kBadInput;
        audio::MixOptions mix;
        mix.rate = o.rate;
        mix.until = *end;
        ProgressBar bar("mixing");
        const audio::MixStats stats =
            audio::write_soundtrack(timeline, bank, mix, o.out, [&](double f) { return bar(f); });
        const auto frames = std::llround(*end * o.rate);
        std::cout << "wrote " << o.out << ": " << frames << " stereo frames at " << o.rate
                  << " Hz (" << *end << " s), " << stats.collision_cues << " collision sound"
                  << (stats.collision_cues == 1 ? "" : "s") << ", "
                  << stats.voices.refused + stats.voices.dropped << " dropped by the limit of "
                  << audio::kVoiceLimit << " voices";
        if (stats.clipped > 0) std::cout << ", " << stats.clipped << " samples clipped";
        std::cout << "\n";
        return kSuccess;
    } catch (const std::exception &e) {
        std::cerr << "animator: " << o.file << ": " << e.what() << "\n";
        return kBadInput;
    }
}

} // namespace

void add_soundtrack_command(CLI::App &app, std::function<int()> &run) {
    auto o = std::make_shared<SoundtrackOptions>();
    CLI::App *cmd = app.add_subcommand(
        "soundtrack",
        "Bake an animation and mix its collision and moving sounds into a 16-bit stereo WAV file");
    cmd->add_option("FILE", o->file, "an animation (.ani) or scene (.lua)")->required();
    cmd->add_option("--out", o->out, "the WAV file to write (replaced only when complete)")
        ->required();
    cmd->add_option("--backend", o->backend,
                    "physics backend plugin id (default: the animation's)");
    cmd->add_option("--rate", o->rate, "frames per second (default 44100)")
        ->check(CLI::Range(8000, 192000));
    cmd->add_option("--until", o->until, "mix up to this time in seconds (default: the max time)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--param", o->params, "a backend parameter, NAME=VALUE (repeatable)");
    cmd->add_option("--bake", o->bake, kBakeOptionHelp);
    cmd->callback([&run, o] { run = [o] { return run_soundtrack(*o); }; });
}

} // namespace animator::cli
