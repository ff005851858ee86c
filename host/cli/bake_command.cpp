// `animator bake FILE`: bakes an animation with a physics backend and writes what it found: a
// trace of every model's state, the collision events, statistics, and the bake itself for
// `animator render --bake` (timeline/bake_file.hpp).
#include "cli/cli_support.hpp"
#include "cli/commands.hpp"

#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "plugin/descriptor_check.hpp"
#include "timeline/bake_file.hpp"
#include "timeline/timeline.hpp"
#include "timeline/world_turning.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>

namespace animator::cli {

namespace {

struct BakeOptions {
    std::string file, backend, trace, events, save;
    std::vector<std::string> params;
    double until = -1.0;
    double step = 1.0 / 60.0;
    bool stats = false;
};

// Where a CSV is written before it is renamed to `path`: beside it, so the rename is atomic and a
// run stopped part way (a cancel in the editor, a full disk) leaves any previous file whole.
std::filesystem::path partial_of(const std::string &path) {
    const std::filesystem::path p(path);
    return p.parent_path() / ("." + p.filename().string() + ".partial");
}

void replace_with(const std::filesystem::path &partial, const std::string &path) {
    std::error_code ec;
    std::filesystem::rename(partial, path, ec);
    if (ec) {
        std::filesystem::remove(partial, ec);
        throw std::runtime_error(path + ": cannot be written (" + ec.message() + ")");
    }
}

void write_trace(const std::string &path, const Timeline &timeline, double until, double step) {
    std::set<double> times;
    const auto samples = static_cast<long long>(std::floor(until / step + 1e-9));
    for (long long k = 0; k <= samples; ++k) times.insert(static_cast<double>(k) * step);
    for (const Keyframe &k : timeline.document().keyframes()) {
        const double t = static_cast<double>(k.time_ms) / 1000.0;
        if (t <= until) times.insert(t);
    }
    const std::filesystem::path partial = partial_of(path);
    std::ofstream out(partial);
    if (!out) throw std::runtime_error(path + ": cannot be written");
    out << "t,model,x,y,z,rx,ry,rz,sx,sy,sz,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz\n";
    const auto &models = timeline.document().models();
    for (double t : times) {
        const Frame frame = timeline.evaluate(t);
        const std::vector<Turning> turns = world_turnings(timeline, frame, t);
        for (size_t m = 0; m < models.size(); ++m) {
            const ModelPose &p = frame.models[m];
            out << number(t) << "," << csv_field(models[m].name);
            for (const glm::dvec3 *v : {&p.center, &p.angles, &p.scale, &p.velocity})
                out << "," << number(v->x) << "," << number(v->y) << "," << number(v->z);
            const Turning &r = turns[m]; // world orientation and angular velocity (rad/s)
            out << "," << number(r.q.w) << "," << number(r.q.x) << "," << number(r.q.y) << "," << number(r.q.z)
                << "," << number(r.w.x) << "," << number(r.w.y) << "," << number(r.w.z) << "\n";
        }
    }
    out.close();
    if (!out) {
        std::error_code ignored;
        std::filesystem::remove(partial, ignored);
        throw std::runtime_error(path + ": writing failed");
    }
    replace_with(partial, path);
}

void write_events(const std::string &path, const Timeline &timeline) {
    std::ofstream out(path);
    if (!out) throw std::runtime_error(path + ": cannot be written");
    out << "t,a,b,nx,ny,nz,speed\n";
    const auto &models = timeline.document().models();
    auto name = [&](uint32_t i) {
        return i < models.size() ? csv_field(models[i].name) : std::string();
    };
    for (const ani_collision_event &e : timeline.events())
        out << number(e.t) << "," << name(e.a) << "," << name(e.b) << "," << number(e.normal.x)
            << "," << number(e.normal.y) << "," << number(e.normal.z) << "," << number(e.speed)
            << "\n";
    if (!out) throw std::runtime_error(path + ": writing failed");
}

void print_stats(const Timeline &timeline, double wall_seconds) {
    const auto &models = timeline.document().models();
    std::size_t keyed = 0, free = 0, rest = 0, carried = 0, key_only_at_zero = 0, never_free = 0;
    for (size_t m = 0; m < models.size(); ++m) {
        bool any_free = false;
        for (const ani_motion_segment &s : timeline.segments(static_cast<int>(m))) {
            keyed += s.motion == ANI_MOTION_KEYED;
            free += s.motion == ANI_MOTION_FREE;
            rest += s.motion == ANI_MOTION_REST;
            carried += s.motion == ANI_MOTION_CARRIED;
            any_free = any_free || s.motion == ANI_MOTION_FREE;
        }
        never_free += !any_free;
        key_only_at_zero += timeline.document().keys_of(static_cast<int>(m)).size() == 1;
    }
    const BakeStats &st = timeline.stats();
    std::cout << "backend:   " << timeline.backend_id() << "\n"
              << "wall time: " << wall_seconds << " s\n"
              << "baked:     " << st.seconds_baked << " s of animation in " << st.bake_calls
              << " bake call(s)\n"
              << "segments:  " << keyed + free + rest + carried << " (" << keyed << " keyed, " << free
              << " free, " << rest << " at rest" << (carried ? ", " + std::to_string(carried) + " carried" : "")
              << ")\n"
              << "events:    " << timeline.events().size() << "\n"
              << "skipped:   interpolation for " << key_only_at_zero << " of " << models.size()
              << " models (keyed at t = 0 only); free flight for " << never_free << " of "
              << models.size() << " models (at rest or keyed throughout)\n";
    for (const auto &[name, value] : st.backend_counts) {
        std::cout << "  " << name << ": ";
        if (value == std::floor(value) && std::abs(value) < 9e15)
            std::cout << static_cast<long long>(value) << "\n";
        else
            std::cout << value << "\n";
    }
}

int run_bake(const BakeOptions &o) {
    Environment env;
    std::optional<OpenedDocument> opened = open_or_report(env.plugins, o.file);
    if (!opened) return kBadInput;
    Document &doc = opened->document;
    const std::optional<double> end = bake_end(doc, o.file, o.until);
    if (!end) return kBadInput;
    const double until = *end;
    try {
        const std::string backend = o.backend.empty() ? doc.settings().physics_backend : o.backend;
        apply_params(doc, backend, o.params);
        const auto start = std::chrono::steady_clock::now();
        Timeline timeline(doc, env.plugins, o.backend);
        load_document_meshes(timeline, env, o.file, opened->warnings);
        ProgressBar bar;
        timeline.bake(until, [&](double f) { return bar(f); });
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!o.trace.empty()) write_trace(o.trace, timeline, until, o.step);
        if (!o.events.empty()) write_events(o.events, timeline);
        if (!o.save.empty()) {
            save_bake(timeline, o.save);
            std::cout << "wrote " << o.save << " (the bake of 0 to " << number(until) << " s)\n";
        }
        if (o.stats) print_stats(timeline, wall);
        return kSuccess;
    } catch (const std::exception &e) {
        std::cerr << "animator: " << o.file << ": " << e.what() << "\n";
        return kBadInput;
    }
}

} // namespace

void add_bake_command(CLI::App &app, std::function<int()> &run) {
    auto o = std::make_shared<BakeOptions>();
    CLI::App *cmd = app.add_subcommand(
        "bake", "Bake an animation's physics and write its trace, events and statistics");
    cmd->add_option("FILE", o->file, "an animation (.ani) or scene (.lua)")->required();
    cmd->add_option("--backend", o->backend,
                    "physics backend plugin id (default: the animation's)");
    cmd->add_option("--until", o->until, "bake up to this time in seconds (default: the max time)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--step", o->step, "trace sample step in seconds (default 1/60)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--trace", o->trace,
                    "write every model's state as CSV: t,model,x,y,z,rx,ry,rz,sx,sy,sz,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz "
                    "(q: world orientation, w: angular velocity in rad/s about world axes)");
    cmd->add_option("--events", o->events, "write collision events as CSV: t,a,b,nx,ny,nz,speed");
    cmd->add_option("--save", o->save,
                    "write the bake itself to this file (FILE.bake), for animator render --bake: many "
                    "machines rendering shares of the frames use one bake (docs/render-farm.md)");
    cmd->add_option("--param", o->params, "a backend parameter, NAME=VALUE (repeatable)");
    cmd->add_flag("--stats", o->stats,
                  "print wall time, segments, events, skipped stages and the backend's counts "
                  "(pair tests done and skipped)");
    cmd->callback([&run, o] { run = [o] { return run_bake(*o); }; });
}

} // namespace animator::cli
