// `animator compare FILE --backends A,B`: bakes an animation with two physics backends and
// reports how far apart they are: per model, the largest difference of position and of
// velocity and when it happens, and the collision events that one backend has and the other
// lacks. It reports, it does not judge: the exit code is 0 unless an input is bad.
#include "cli/cli_support.hpp"
#include "cli/commands.hpp"

#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "timeline/timeline.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

namespace animator::cli {

namespace {

struct CompareOptions {
    std::string file, backends = "physics.custom,physics.bullet", csv;
    std::vector<std::string> params;
    double until = -1.0;
    double step = 1.0 / 240.0;
    double tolerance = 0.01;
};

std::vector<std::string> split(const std::string &list) {
    std::vector<std::string> out;
    std::stringstream in(list);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

struct Largest {
    double value = 0.0, t = 0.0;
    void offer(double v, double time) {
        if (v > value) {
            value = v;
            t = time;
        }
    }
};

// Events of `a` with no event of `b` between the same two models within `tolerance` seconds.
std::vector<const ani_collision_event *> unmatched(const EventList &a,
                                                   const EventList &b,
                                                   double tolerance) {
    std::vector<bool> used(b.size(), false);
    std::vector<const ani_collision_event *> out;
    for (const ani_collision_event &e : a) {
        const auto key = std::minmax(e.a, e.b);
        bool found = false;
        // b is in time order: look from the first event not earlier than e.t - tolerance.
        auto it = std::lower_bound(b.begin(), b.end(), e.t - tolerance,
                                   [](const ani_collision_event &x, double t) { return x.t < t; });
        for (; it != b.end() && it->t <= e.t + tolerance; ++it) {
            const size_t k = static_cast<size_t>(it - b.begin());
            if (!used[k] && std::minmax(it->a, it->b) == key) {
                used[k] = true;
                found = true;
                break;
            }
        }
        if (!found) out.push_back(&e);
    }
    return out;
}

int run_compare(const CompareOptions &o) {
    const std::vector<std::string> backends = split(o.backends);
    if (backends.size() != 2) {
        std::cerr << "animator: --backends needs two backend ids separated by a comma, got '"
                  << o.backends << "'\n";
        return kUsage;
    }
    Environment env;
    std::optional<OpenedDocument> opened = open_or_report(env.plugins, o.file);
    if (!opened) return kBadInput;
    Document &doc = opened->document;
    const std::optional<double> end = bake_end(doc, o.file, o.until);
    if (!end) return kBadInput;
    const double until = *end;
    try {
        // Each --param goes to the backends that declare it; one that none declares is an error.
        for (const std::string &p : o.params) {
            const std::string name = p.substr(0, p.find('='));
            bool taken = false;
            for (const std::string &b : backends) {
                const auto names = param_names(env.plugins, b);
                if (std::find(names.begin(), names.end(), name) == names.end()) continue;
                apply_params(doc, b, {p});
                taken = true;
            }
            if (!taken)
                throw std::invalid_argument("--param " + name + ": neither " + backends[0] +
                                            " nor " + backends[1] +
                                            " has a parameter of that name");
        }
        std::vector<std::unique_ptr<Timeline>> timelines;
        for (const std::string &b : backends) {
            timelines.push_back(std::make_unique<Timeline>(doc, env.plugins, b));
            load_document_meshes(*timelines.back(), env, o.file, opened->warnings);
            ProgressBar bar("baking with " + b);
            timelines.back()->bake(until, [&](double f) { return bar(f); });
        }
        const Timeline &a = *timelines[0], &b = *timelines[1];
        const auto &models = doc.models();
        std::vector<Largest> position(models.size()), velocity(models.size());
        std::ofstream csv;
        if (!o.csv.empty()) {
            csv.open(o.csv);
            if (!csv) throw std::runtime_error(o.csv + ": cannot be written");
            csv << "t,model,dx,dy,dz,dvx,dvy,dvz\n";
        }
        const auto samples = static_cast<long long>(std::floor(until / o.step + 1e-9));
        for (long long k = 0; k <= samples; ++k) {
            const double t = std::min(until, static_cast<double>(k) * o.step);
            const Frame fa = a.evaluate(t), fb = b.evaluate(t);
            for (size_t m = 0; m < models.size(); ++m) {
                const glm::dvec3 dp = fa.models[m].center - fb.models[m].center;
                const glm::dvec3 dv = fa.models[m].velocity - fb.models[m].velocity;
                position[m].offer(glm::length(dp), t);
                velocity[m].offer(glm::length(dv), t);
                if (csv.is_open())
                    csv << number(t) << "," << csv_field(models[m].name) << "," << number(dp.x)
                        << "," << number(dp.y) << "," << number(dp.z) << "," << number(dv.x) << ","
                        << number(dv.y) << "," << number(dv.z) << "\n";
            }
        }
        if (csv.is_open() && !csv) throw std::runtime_error(o.csv + ": writing failed");

        std::cout << "compared " << backends[0] << " (A) with " << backends[1] << " (B) over "
                  << until << " s, sampled every " << o.step << " s\n";
        std::cout << std::left << std::setw(24) << "model" << std::setw(30)
                  << "largest |position A - B|"
                  << "largest |velocity A - B|\n";
        for (size_t m = 0; m < models.size(); ++m) {
            std::ostringstream p, v;
            p << std::setprecision(6) << position[m].value << " m at " << position[m].t << " s";
            v << std::setprecision(6) << velocity[m].value << " m/s at " << velocity[m].t << " s";
            std::cout << std::left << std::setw(24) << models[m].name << std::setw(30) << p.str()
                      << v.str() << "\n";
        }
        auto name = [&](uint32_t i) {
            return i < models.size() ? models[i].name : std::string("(world)");
        };
        std::cout << "events: " << a.events().size() << " in A, " << b.events().size()
                  << " in B (matched by models and time within " << o.tolerance << " s)\n";
        for (int side = 0; side < 2; ++side) {
            const auto missing = side == 0 ? unmatched(a.events(), b.events(), o.tolerance)
                                           : unmatched(b.events(), a.events(), o.tolerance);
            std::cout << "only in " << (side == 0 ? "A" : "B") << ": " << missing.size() << "\n";
            for (const ani_collision_event *e : missing)
                std::cout << "  t = " << std::setprecision(9) << e->t << " s  " << name(e->a)
                          << " / " << name(e->b) << "  speed " << std::setprecision(6) << e->speed
                          << " m/s\n";
        }
        return kSuccess;
    } catch (const std::exception &e) {
        std::cerr << "animator: " << o.file << ": " << e.what() << "\n";
        return kBadInput;
    }
}

} // namespace

void add_compare_command(CLI::App &app, std::function<int()> &run) {
    auto o = std::make_shared<CompareOptions>();
    CLI::App *cmd =
        app.add_subcommand("compare", "Bake an animation with two physics backends and report the "
                                      "largest differences and unmatched events");
    cmd->add_option("FILE", o->file, "an animation (.ani) or scene (.lua)")->required();
    cmd->add_option("--backends", o->backends,
                    "two backend ids, A,B (default physics.custom,physics.bullet)");
    cmd->add_option("--until", o->until,
                    "compare up to this time in seconds (default: the max time)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--step", o->step, "sampling step of the comparison in seconds (default 1/240)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--tolerance", o->tolerance,
                    "events match within this many seconds (default 0.01)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--csv", o->csv,
                    "write every sample's differences as CSV: t,model,dx,dy,dz,dvx,dvy,dvz");
    cmd->add_option("--param", o->params,
                    "a backend parameter, NAME=VALUE, for the backends that have it (repeatable)");
    cmd->callback([&run, o] { run = [o] { return run_compare(*o); }; });
}

} // namespace animator::cli
