// animator-render-bench FILE... [--size WxH] [--frames N] [--runs R] [--only TEXT]: how fast
// the renderer draws and reads back frames of each document off screen (what `animator render`
// does before PNG encoding), with shadows, anti-aliasing and reflections of other models on and
// off, compared within one run (docs/performance.md, "Shadows and anti-aliasing"). Prints one line
// per document and setting: the median over R runs of N frames each of the frames drawn per
// second, and the triangles drawn in the last frame. --only keeps the settings whose names
// contain TEXT ("plain", "shadows", "coarse").
#include "bench.hpp"

#include "cli/cli_support.hpp"
#include "render/framebuffer.hpp"
#include "render/offscreen_context.hpp"
#include "render/renderer.hpp"

#include <cstdio>
#include <cstring>
#include <iostream>

using namespace animator;

namespace {

struct Setting {
    const char *name;
    bool shadows;
    int samples;
    int reflections; // the side of the models' cube maps of the others (0: the skybox only)
    double detail = RenderOptions{}.detail_pixels; // levels of detail (0: whole meshes)
    bool mirror_levels = false; // mirrors and glass at levels of detail too
};

const Setting kSettings[] = {
    {"plain, whole meshes (detail 0)", false, 1, 0, 0.0},
    {"plain (msaa 1, skybox only)", false, 1, 0},
    {"msaa 4", false, 4, 0},
    {"shadows", true, 1, 0},
    {"reflections 128", false, 1, 128},
    {"reflections 64", false, 1, 64},
    // Two of the three together: what each costs with anti-aliasing on (docs/performance.md).
    {"msaa 4 + shadows", true, 4, 0},
    {"msaa 4 + reflections 128", false, 4, 128},
    {"all (the default)", true, 4, 128},
    // The editor's frame budget's levels of detail while playing (editor/frame_budget.hpp).
    {"plain, coarse (detail 2, mirrors too)", false, 1, 0, 2.0, true},
    {"shadows, coarse (detail 2, mirrors too)", true, 1, 0, 2.0, true},
};

} // namespace

int main(int argc, char **argv) {
    int width = 1280, height = 720, frames = 60, runs = 5;
    std::vector<std::string> files;
    std::string only;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--size" && i + 1 < argc)
            std::sscanf(argv[++i], "%dx%d", &width, &height);
        else if (a == "--frames" && i + 1 < argc)
            frames = std::atoi(argv[++i]);
        else if (a == "--runs" && i + 1 < argc)
            runs = std::atoi(argv[++i]);
        else if (a == "--only" && i + 1 < argc)
            only = argv[++i];
        else
            files.push_back(a);
    }
    Environment env;
    OffscreenContext context;
    std::vector<std::uint8_t> pixels;
    std::printf("%-28s %-40s %8s %8s %10s\n", "document", "setting", "fps", "ms", "triangles");
    for (const std::string &file : files) {
        auto opened = cli::open_or_report(env.plugins, file);
        if (!opened) return 1;
        Document &doc = opened->document;
        Timeline timeline(doc, env.plugins, "");
        const auto meshes = cli::load_document_meshes(timeline, env, file, opened->warnings);
        const double max_time = static_cast<double>(doc.settings().max_time_ms) / 1000.0;
        timeline.bake(max_time);
        for (const Setting &s : kSettings) {
            if (std::strstr(s.name, only.c_str()) == nullptr) continue;
            RenderOptions options;
            options.shadows = s.shadows;
            options.reflection_size = s.reflections;
            options.detail_pixels = s.detail;
            options.mirror_levels = s.mirror_levels;
            Renderer renderer(env.plugins, env.assets, options);
            renderer.set_document(doc, meshes);
            OffscreenFramebuffer framebuffer(width, height, supported_samples(s.samples));
            std::vector<double> rates;
            for (int run = 0; run < runs; ++run) {
                const auto start = std::chrono::steady_clock::now();
                for (int k = 0; k < frames; ++k) {
                    renderer.draw(timeline.evaluate(max_time * k / frames), framebuffer.target());
                    framebuffer.read_rgb(pixels);
                }
                rates.push_back(frames / bench::seconds_since(start));
            }
            const double fps = bench::median(rates);
            std::printf("%-28s %-40s %8.1f %8.1f %10zu\n", std::filesystem::path(file).filename().c_str(),
                        s.name, fps, 1000.0 / fps, renderer.stats().triangles);
            std::fflush(stdout);
        }
    }
    return 0;
}
