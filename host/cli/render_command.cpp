// `animator render FILE --out DIR`: bakes an animation and writes its frames as PNG files
// (DIR/frame_00000.png, ...), off screen through EGL, so it works on a machine with no display.
// With `--video PATH.mp4` it also mixes the soundtrack (docs/sound.md) and has ffmpeg, when
// installed, put frames and sound together.
#include "cli/cli_support.hpp"
#include "cli/commands.hpp"

#include "audio/mixer.hpp"
#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "render/frame_rate_note.hpp"
#include "render/framebuffer.hpp"
#include "render/offscreen_context.hpp"
#include "render/png_frame_writer.hpp"
#include "render/renderer.hpp"
#include "timeline/timeline.hpp"

#include <malloc.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <set>
#include <sstream>
#include <vector>

namespace animator::cli {

namespace {

extern "C" char **environ;

// "A-B" into the first and last frame (0-based, A <= B); "" when valid, else what is wrong.
std::string parse_frames(const std::string &s, int *first = nullptr, int *last = nullptr) {
    int a = -1, b = -1;
    char dash = 0, extra = 0;
    if (std::sscanf(s.c_str(), "%d%c%d%c", &a, &dash, &b, &extra) != 3 || dash != '-' || a < 0 || b < a)
        return "expected A-B, the first and last frame (0 is the first, A <= B), got '" + s + "'";
    if (first) *first = a;
    if (last) *last = b;
    return "";
}

// Without --size: the document's render size (a course scene's gr.render) where it gives one.
constexpr int kDefaultWidth = 1280, kDefaultHeight = 720;

struct RenderCommandOptions {
    std::string file, out, backend, shading = "shading.phong", size, video; // size "": not given
    std::string frames; // "A-B": only frames A to B of the sequence (a render farm's share)
    std::string bake;   // a bake file (animator bake --save) used in place of baking
    std::vector<std::string> params;
    double from = 0.0, to = -1.0, fps = 30.0;
    int compression = 3;
    int reflections = RenderOptions{}.reflection_size;
    double detail = RenderOptions{}.detail_pixels; // levels of detail: pixels a surface may move
    int msaa = 4; // samples a pixel (multisample anti-aliasing); 1 is none
    bool no_shadows = false;
    bool progress = false, fps_given = false;
};

// "N" samples for --msaa; "" when valid, else what is wrong (CLI11's check convention).
std::string check_msaa(const std::string &text) {
    char rest = 0;
    int n = 0;
    if (std::sscanf(text.c_str(), "%d%c", &n, &rest) != 1 || !valid_sample_count(n))
        return std::string("--msaa takes the samples per pixel, ") + sample_counts_text() +
               " (1 turns anti-aliasing off), got '" + text + "'";
    return "";
}

// "WxH" into width and height; "" when valid, else what is wrong (CLI11's check convention).
std::string parse_size(const std::string &text, int *width = nullptr, int *height = nullptr) {
    const auto x = text.find('x');
    int w = 0, h = 0;
    char rest = 0;
    if (x == std::string::npos || std::sscanf(text.c_str(), "%dx%d%c", &w, &h, &rest) != 2 ||
        w <= 0 || h <= 0 || w > 16384 || h > 16384)
        return "--size needs WIDTHxHEIGHT in pixels (1 to 16384 each), got '" + text + "'";
    if (width) *width = w;
    if (height) *height = h;
    return "";
}

// The executable `name` in a folder of PATH, or nothing.
std::optional<std::filesystem::path> find_on_path(const std::string &name) {
    const char *path = std::getenv("PATH");
    std::istringstream folders(path ? path : "");
    std::string folder;
    while (std::getline(folders, folder, ':')) {
        const std::filesystem::path candidate =
            std::filesystem::path(folder.empty() ? "." : folder) / name;
        if (::access(candidate.c_str(), X_OK) == 0 && !std::filesystem::is_directory(candidate))
            return candidate;
    }
    return std::nullopt;
}

// Runs `program` with `args` and waits; its exit status, or -1 when it could not start.
int run_program(const std::filesystem::path &program, const std::vector<std::string> &args) {
    std::vector<char *> argv;
    std::vector<std::string> storage = args;
    storage.insert(storage.begin(), program.string());
    for (std::string &a : storage) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawn(&pid, program.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return -1;
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The frames in `o.out` and the soundtrack of [from, to] into `o.video`, through ffmpeg. The
// video is written beside its final name first, so a failure leaves an old one intact.
int write_video(const RenderCommandOptions &o, const Timeline &timeline, audio::SoundBank &bank,
                double to) {
    const std::optional<std::filesystem::path> ffmpeg = find_on_path("ffmpeg");
    if (!ffmpeg) {
        std::cerr << "animator: --video needs ffmpeg to put the frames and the soundtrack "
                     "together, and it is not installed (on Debian: sudo apt-get install "
                     "ffmpeg); the frames are in "
                  << o.out << "\n";
        return kBadInput;
    }
    const std::filesystem::path sound = std::filesystem::path(o.out) / "soundtrack.wav";
    audio::MixOptions mix;
    mix.from = o.from;
    mix.until = to;
    {
        ProgressBar bar("mixing");
        audio::write_soundtrack(timeline, bank, mix, sound, [&](double f) { return bar(f); });
    }
    const std::filesystem::path video(o.video);
    const std::filesystem::path partial =
        video.parent_path() /
        ("." + video.stem().string() + ".partial" + video.extension().string());
    std::ostringstream fps;
    fps.precision(17);
    fps << o.fps;
    const int status = run_program(
        *ffmpeg, {"-y", "-loglevel", "error", "-framerate", fps.str(), "-i",
                  (std::filesystem::path(o.out) / "frame_%05d.png").string(), "-i", sound.string(),
                  // 4:2:0 video (what players expect) needs even sizes.
                  "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", "-c:a", "aac",
                  partial.string()});
    if (status != 0) {
        std::error_code ignored;
        std::filesystem::remove(partial, ignored);
        std::cerr << "animator: " << o.video << ": ffmpeg (" << ffmpeg->string() << ") failed"
                  << (status < 0 ? " to start" : "") << "; the frames and soundtrack.wav are in "
                  << o.out << "\n";
        return kBadInput;
    }
    std::filesystem::rename(partial, video);
    std::cout << "wrote " << o.video << " (the frames with " << sound.string() << ")\n";
    return kSuccess;
}

int run_render(const RenderCommandOptions &o) {
    // Run by a program that follows it (the editor's Render), the render ends with that program:
    // an editor killed or crashed must not leave it writing frames for minutes. (The editor
    // cancels it itself when it closes.)
    if (o.progress) {
        prctl(PR_SET_PDEATHSIG, SIGTERM);
        if (getppid() == 1) return kBadInput; // it ended before the line above
    }
    // stb allocates a few megabytes for every frame it encodes; without this glibc gives them
    // back to the kernel each time and faults them in again (docs/rendering.md).
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);

    Environment env;
    std::optional<OpenedDocument> opened = open_or_report(env.plugins, o.file);
    if (!opened) return kBadInput;
    Document &doc = opened->document;
    // Without --out, the still the document names (gr.render's file), relative to its folder.
    const bool still = o.out.empty();
    std::filesystem::path still_file;
    if (still) {
        if (doc.settings().render_output.empty()) {
            std::cerr << "animator: " << o.file
                      << ": --out is required: the document names no render output of its own\n";
            return kUsage;
        }
        if (o.to >= 0.0 || o.fps_given || !o.video.empty() || !o.frames.empty()) {
            std::cerr
                << "animator: --to, --fps, --frames and --video make frames: they need --out (without "
                   "it one still is drawn, at --from, into the document's render output)\n";
            return kUsage;
        }
        still_file = doc.settings().render_output;
        if (still_file.is_relative())
            still_file = std::filesystem::path(o.file).parent_path() / still_file;
    }
    if (!o.frames.empty() && !o.video.empty()) {
        std::cerr << "animator: --frames renders a share of the frames, --video needs them all: render the "
                     "shares, then put them together with ffmpeg (docs/rendering.md)\n";
        return kUsage;
    }
    const double max_time = static_cast<double>(doc.settings().max_time_ms) / 1000.0;
    const double to = still ? o.from : o.to < 0.0 ? max_time : o.to;
    if (to > max_time || o.from > to) {
        std::cerr << "animator: " << o.file << ": frames from " << o.from << " s to " << to
                  << " s are not within the animation (0 to " << max_time << " s)\n";
        return kBadInput;
    }
    // The frames: k = 0 .. count - 1 at from + k / fps, or only first .. last of them (--frames).
    const int count = render_frame_count(o.from, to, o.fps);
    int first = 0, last = count - 1;
    if (!o.frames.empty()) {
        parse_frames(o.frames, &first, &last);
        if (last >= count) {
            std::cerr << "animator: " << o.file << ": --frames " << o.frames << ": the frames are 0 to "
                      << count - 1 << " (" << o.from << " s to " << to << " s at " << o.fps << " fps)\n";
            return kBadInput;
        }
    }
    const auto frame_time = [&](int k) { return std::min(to, o.from + k / o.fps); };
    // What is baked: up to the last frame drawn (a share of a render farm bakes no further).
    const double bake_to = still ? to : frame_time(last);
    int width = doc.settings().render_width > 0 ? doc.settings().render_width : kDefaultWidth;
    int height = doc.settings().render_height > 0 ? doc.settings().render_height : kDefaultHeight;
    if (!o.size.empty()) parse_size(o.size, &width, &height);
    try {
        // A parameter the shading plugin declares goes to it; any other to the physics backend.
        const std::string backend = o.backend.empty() ? doc.settings().physics_backend : o.backend;
        const auto shading_names = param_names(env.plugins, o.shading);
        std::vector<std::string> backend_params, shading_params;
        for (const std::string &p : o.params) {
            const std::string name = p.substr(0, p.find('='));
            const bool for_shading =
                std::find(shading_names.begin(), shading_names.end(), name) != shading_names.end();
            (for_shading ? shading_params : backend_params).push_back(p);
        }
        apply_params(doc, backend, backend_params);
        apply_params(doc, o.shading, shading_params);

        // A video's sounds are read before anything is rendered, so a missing one is said at
        // once.
        audio::SoundBank sounds(env.assets);
        if (!o.video.empty()) audio::load_document_sounds(doc, sounds);

        Timeline timeline(doc, env.plugins, o.backend);
        const auto meshes = load_document_meshes(timeline, env, o.file, opened->warnings);
        if (!bake_or_load(timeline, o.file, o.bake, bake_to)) return kBadInput;

        OffscreenContext context;
        RenderOptions options;
        options.shading = o.shading;
        options.reflection_size = o.reflections;
        options.detail_pixels = o.detail;
        options.shadows = !o.no_shadows;
        Renderer renderer(env.plugins, env.assets, options);
        renderer.set_document(doc, meshes);
        std::string fewer_samples;
        OffscreenFramebuffer framebuffer(width, height, supported_samples(o.msaa, &fewer_samples));
        if (!fewer_samples.empty()) std::cerr << "animator: " << fewer_samples << "\n";
        if (still) {
            std::vector<std::uint8_t> pixels;
            renderer.draw(timeline.evaluate(o.from), framebuffer.target());
            framebuffer.read_rgb(pixels);
            if (still_file.has_parent_path())
                std::filesystem::create_directories(still_file.parent_path());
            write_png(still_file, width, height, pixels, o.compression);
            if (o.progress) std::cout << "frame 1 of 1" << std::endl;
            std::cout << "wrote " << still_file.string() << " (" << width << "x" << height
                      << ", the frame at " << o.from << " s)\n";
            return kSuccess;
        }
        std::filesystem::create_directories(o.out);
        PngFrameWriter writer(o.out, width, height, 0, o.compression);

        const int drawn = last - first + 1;
        ProgressBar bar("rendering");
        // How long each frame took to draw and read back (not to encode), and whether it drew
        // shadow maps and reflections of other models: said after when slower than 30 a second.
        std::vector<double> frame_seconds;
        bool shadowed = false, reflected = false;
        for (int k = first; k <= last; ++k) {
            const auto start = std::chrono::steady_clock::now();
            renderer.draw(timeline.evaluate(frame_time(k)), framebuffer.target());
            framebuffer.read_rgb(writer.next_buffer());
            frame_seconds.push_back(
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            shadowed = shadowed || renderer.stats().shadow_maps > 0;
            reflected = reflected || renderer.stats().reflection_maps > 0;
            writer.write(k); // named by its place in the whole sequence
            bar(static_cast<double>(k - first + 1) / drawn);
            // For a program that runs this one (the editor's Render): one line a frame handed to
            // the writer, flushed at once so the reader sees it then.
            if (o.progress) std::cout << "frame " << k - first + 1 << " of " << drawn << std::endl;
        }
        writer.finish();
        std::cout << "wrote " << drawn << " frame" << (drawn == 1 ? "" : "s") << " of " << width
                  << "x" << height << " to " << o.out << " (" << PngFrameWriter::file_name(first)
                  << (drawn > 1 ? " .. " + PngFrameWriter::file_name(last) : "") << ")\n";
        // (The median: the first frame also compiles the shading programs it needs.)
        std::nth_element(frame_seconds.begin(),
                         frame_seconds.begin() +
                             static_cast<std::ptrdiff_t>(frame_seconds.size() / 2),
                         frame_seconds.end());
        const std::string slow =
            slow_frames_note(frame_seconds[frame_seconds.size() / 2], framebuffer.actual_samples(),
                             shadowed, reflected);
        if (!slow.empty()) std::cout << slow << "\n";
        if (!o.video.empty()) return write_video(o, timeline, sounds, to);
        return kSuccess;
    } catch (const std::exception &e) {
        std::cerr << "animator: " << o.file << ": " << e.what() << "\n";
        return kBadInput;
    }
}

} // namespace

void add_render_command(CLI::App &app, std::function<int()> &run) {
    auto o = std::make_shared<RenderCommandOptions>();
    CLI::App *cmd = app.add_subcommand(
        "render",
        "Bake an animation and write its frames as PNG files (or, without --out, the still its "
        "document names), without a display");
    cmd->add_option("FILE", o->file, "an animation (.ani) or scene (.lua)")->required();
    cmd->add_option(
        "--out", o->out,
        "the folder to write frame_00000.png, ... into (default: none; without it, one still at "
        "--from is written to the document's own render output, a course scene's gr.render "
        "file, relative to the document's folder)");
    cmd->add_option("--from", o->from, "the first frame's time in seconds (default 0)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--to", o->to, "the last frame's time in seconds (default: the max time)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--frames", o->frames,
                    "A-B: only frames A to B of the sequence (0 is the frame at --from), each file "
                    "named by its place in the whole, as the whole render writes it: a render "
                    "farm's share (docs/rendering.md)")
        ->check([](const std::string &s) { return parse_frames(s); });
    cmd->add_option("--bake", o->bake, kBakeOptionHelp);
    CLI::Option *fps = cmd->add_option("--fps", o->fps, "frames per second (default 30)")
                           ->check(CLI::Range(0.001, 1000.0));
    cmd->add_option("--size", o->size,
                    "WIDTHxHEIGHT in pixels (default: the document's render size, a course scene's "
                    "gr.render, else 1280x720)")
        ->check([](const std::string &s) { return parse_size(s); });
    cmd->add_option("--msaa", o->msaa,
                    "anti-aliasing: samples per pixel, 1, 2, 4 or 8 (default 4; 1 turns it off)")
        ->check(check_msaa);
    cmd->add_flag("--no-shadows", o->no_shadows,
                  "draw without the shadows the scene's lights cast (shadow maps; on by default)");
    cmd->add_option("--backend", o->backend,
                    "physics backend plugin id (default: the animation's)");
    cmd->add_option("--shading", o->shading, "shading plugin id (default shading.phong)");
    cmd->add_option(
        "--param", o->params,
        "a parameter of the physics backend or the shading plugin, NAME=VALUE (repeatable)");
    cmd->add_option("--compression", o->compression,
                    "PNG compression, zlib's level 1..9 (default 3; 1 is the fastest, higher is "
                    "smaller and slower)")
        ->check(CLI::Range(1, 9));
    cmd->add_option("--reflections", o->reflections,
                    "the side in pixels of the cube map each reflective or transparent model sees "
                    "the models around it in, drawn every frame (default " +
                        std::to_string(o->reflections) +
                        "); 0: they show the skybox only")
        ->check(CLI::Range(0, 2048));
    cmd->add_option("--detail", o->detail,
                    "levels of detail: a model far from the camera is drawn with a simpler copy of "
                    "its mesh whose surface moves at most this many pixels (default 0.5); 0 draws "
                    "every mesh whole")
        ->check(CLI::Range(0.0, 8.0));
    cmd->add_option("--video", o->video,
                    "also put the frames and the soundtrack together into this video file "
                    "(PATH.mp4) with ffmpeg, which must be installed");
    cmd->add_flag("--progress", o->progress,
                  "print a line \"frame K of N\" on stdout as each frame is drawn, for a program "
                  "that shows the progress (the editor's Render); the render then also stops when "
                  "that program ends");
    cmd->callback([&run, o, fps] {
        o->fps_given = fps->count() > 0;
        run = [o] { return run_render(*o); };
    });
}

} // namespace animator::cli
