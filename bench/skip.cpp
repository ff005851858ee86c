// What a scene does not need is skipped: plugins never opened, pair tests the broad phase rules
// out, feature pairs the hierarchy never looks at, and the part of a bake an edit cannot change.
#include "bench.hpp"

#include "bullet_support.hpp"
#include "io/document_io.hpp"

#include <cmath>
#include <iostream>

namespace animator::bench {

namespace bt = animator::bullet_test;

namespace {

double count(const Timeline &t, const char *name) {
    const auto &c = t.stats().backend_counts;
    const auto it = c.find(name);
    return it == c.end() ? 0.0 : it->second;
}

std::string names(const std::vector<std::filesystem::path> &libraries) {
    std::string out;
    for (const auto &l : libraries) out += (out.empty() ? "" : " ") + l.filename().string();
    return out;
}

// A full bake against the re-bake after an edit (Timeline::set_document), each timed (median).
struct EditCost {
    double full_s = 0.0, edit_s = 0.0, full_baked = 0.0, edit_baked = 0.0;
};

EditCost edit_cost(const Document &before, const Document &after, int runs) {
    const double until = static_cast<double>(before.settings().max_time_ms) / 1000.0;
    EditCost c;
    std::vector<double> full, edit;
    for (int r = 0; r < runs; ++r) {
        auto t = bt::timeline_of(before, "");
        auto start = std::chrono::steady_clock::now();
        t->bake(until);
        full.push_back(seconds_since(start));
        c.full_baked = t->stats().seconds_baked;
        start = std::chrono::steady_clock::now();
        t->set_document(after);
        edit.push_back(seconds_since(start));
        c.edit_baked = t->stats().seconds_baked - c.full_baked;
    }
    c.full_s = median(full);
    c.edit_s = median(edit);
    return c;
}

} // namespace

void run_skip(const Options &o) {
    Csv csv(o.out / "skip.csv", {"what", "example", "value", "of", "note"});
    auto row = [&](const std::string &what, const std::string &example, double value, double of,
                   const std::string &note) {
        csv << what << example << value << of << note;
        csv.end_row();
    };
    const std::filesystem::path assets = std::filesystem::path(ANIMATOR_SOURCE_DIR) / "assets";
    std::vector<std::filesystem::path> examples = {
        assets / "animations/drop.ani",  assets / "animations/cradle.ani",
        assets / "animations/gas.ani",   assets / "animations/orbs.ani",
        assets / "animations/stairs.ani", assets / "scenes/simple.lua"};
    if (o.quick) examples.resize(2);

    std::cout << "Plugins opened to open and bake each example (a fresh plugin registry each):\n"
                 "| example | libraries opened / found | opened | pair tests done | skipped by the "
                 "broad phase | mesh feature tests |\n";
    for (const auto &file : examples) {
        Environment env(AssetPaths::default_roots(), PluginRegistry::default_search_dirs(),
                        [](ani_log_level, const std::string &, const std::string &) {});
        Document doc = open_document(env.plugins, file).document;
        Timeline t(doc, env.plugins);
        std::vector<std::string> ids, warnings;
        for (const Model &m : doc.models()) ids.push_back(m.mesh);
        t.set_meshes(load_meshes(ids, env.assets, file, warnings));
        t.bake(static_cast<double>(doc.settings().max_time_ms) / 1000.0);
        const auto opened = env.plugins.libraries_opened(), found = env.plugins.libraries_found();
        const std::string name = file.filename().string();
        const double done = count(t, "pair tests done"), skipped = count(t, "pair tests skipped");
        row("plugin libraries opened", name, static_cast<double>(opened.size()),
            static_cast<double>(found.size()), names(opened));
        row("pair tests skipped by the broad phase", name, skipped, done + skipped,
            "physics.custom");
        row("mesh feature tests", name, count(t, "mesh feature tests"), 0.0, "physics.custom");
        std::cout << "| " << name << " | " << opened.size() << " / " << found.size() << " | "
                  << names(opened) << " | " << fmt(done) << " | " << fmt(skipped) << " ("
                  << fmt(done + skipped > 0 ? 100.0 * skipped / (done + skipped) : 0.0)
                  << "%) | " << fmt(count(t, "mesh feature tests")) << " |\n";
    }

    row("frames rendered while the editor is idle", "editor", 0.0, 0.0,
        "measured by the editor's frame counter, see docs/manual.md");
    std::cout << "\nFrames rendered while the editor is idle: measured by the editor's frame "
                 "counter, see docs/manual.md (not by this program).\n";

    // The cost of a small edit: Timeline::set_document re-bakes only from the earliest time the
    // edit can change (BakeStats::seconds_baked counts it).
    std::cout << "\nA small edit against a full bake (physics.custom, median of " << o.runs
              << "):\n| example | edit | full bake s | re-bake s | simulated s baked: full / "
                 "after the edit |\n";
    struct Edit {
        std::string example, what;
        Document before, after;
    };
    std::vector<Edit> edits;
    {
        Document orbs = bt::load("orbs.ani"), moved = orbs;
        const int mirror = moved.find_model("mirror");
        ModelState s = *moved.keyframe_at(6000).states[static_cast<size_t>(mirror)];
        s.center.y += 0.5;
        moved.set_state(6000, mirror, s);
        edits.push_back({"orbs.ani", "move mirror's last key (6 s) up 0.5 m", orbs, moved});
    }
    if (!o.quick) {
        // gas.ani (125 balls, 30 s) with a keyed marker (an empty) keyed at 0, 25 and 30 s.
        Document gas = bt::load("gas.ani");
        Model marker;
        marker.name = "marker";
        gas.add_model(marker, bt::placed({0, 50, 0}));
        const int m = static_cast<int>(gas.models().size()) - 1;
        bt::key(gas, 25000, m, bt::placed({0, 50, 0}));
        bt::key(gas, 30000, m, bt::placed({1, 50, 0}));
        Document moved = gas;
        moved.set_state(30000, m, bt::placed({2, 50, 0}));
        edits.push_back({"gas.ani + a keyed marker", "move the marker's last key (30 s)", gas,
                         moved});
        Document recoloured = gas;
        Model ball = recoloured.models()[1];
        ball.material.kd = {1.0, 0.0, 0.0};
        recoloured.set_model(1, ball);
        edits.push_back({"gas.ani + a keyed marker", "recolour a ball", gas, recoloured});
    }
    for (const Edit &e : edits) {
        const EditCost c = edit_cost(e.before, e.after, o.runs);
        row("re-bake after an edit: wall s", e.example + ": " + e.what, c.edit_s, c.full_s,
            "set_document against a full bake");
        row("re-bake after an edit: simulated s", e.example + ": " + e.what, c.edit_baked,
            c.full_baked, "BakeStats::seconds_baked");
        std::cout << "| " << e.example << " | " << e.what << " | " << fmt(c.full_s) << " | "
                  << fmt(c.edit_s) << " | " << fmt(c.full_baked) << " / " << fmt(c.edit_baked)
                  << " |\n";
    }
}

} // namespace animator::bench
