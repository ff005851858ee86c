// A bake saved to a file and read back (timeline/bake_file.hpp) gives a timeline that answers
// exactly as the one that baked, bit for bit, for the example scenes with bounces and with
// turning bodies (free rotation, spin-up, hinge), and a file that does not fit is refused.
#include "assets/mesh.hpp"
#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "timeline/bake_file.hpp"
#include "timeline/world_turning.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <cstring>
#include <memory>

using namespace animator;
namespace fs = std::filesystem;

namespace {

Environment &env() {
    static Environment e({test::bin_dir().parent_path() / "assets"}, {test::bin_dir()},
                         [](ani_log_level, const std::string &, const std::string &) {});
    return e;
}

// The example's document in a timeline with its meshes, not baked.
std::unique_ptr<Timeline> timeline_of(const fs::path &file) {
    const OpenedDocument opened = open_document(env().plugins, file);
    auto t = std::make_unique<Timeline>(opened.document, env().plugins);
    std::vector<std::string> ids, warnings;
    for (const Model &m : opened.document.models()) ids.push_back(m.mesh);
    t->set_meshes(load_meshes(ids, env().assets, file, warnings));
    REQUIRE(warnings.empty());
    return t;
}

struct Bits {
    std::vector<std::uint64_t> words;
    void add(double x) {
        std::uint64_t b;
        std::memcpy(&b, &x, 8);
        words.push_back(b);
    }
    void add(const glm::dvec3 &v) {
        for (int i = 0; i < 3; ++i) add(v[i]);
    }
    void add(const glm::dquat &q) {
        for (double x : {q.w, q.x, q.y, q.z}) add(x);
    }
    void add(const ani_vec3 &v) { add(glm::dvec3(v.x, v.y, v.z)); }
};

// Everything the timeline answers at t, as bits: every model's pose and motion, the camera, and
// each model's world orientation and angular velocity (from the rotation segments' closed forms).
Bits answers_at(const Timeline &timeline, double t) {
    const Frame f = timeline.evaluate(t);
    Bits b;
    for (size_t m = 0; m < f.models.size(); ++m) {
        const ModelPose &p = f.models[m];
        for (const glm::dvec3 *v : {&p.center, &p.angles, &p.scale, &p.velocity, &p.angle_rates})
            b.add(*v);
        b.words.push_back(static_cast<std::uint64_t>(f.motion[m]));
    }
    b.add(f.camera.position);
    b.add(f.camera.rotation);
    b.add(f.camera.fov_degrees);
    for (const Turning &turning : world_turnings(timeline, f, t)) {
        b.add(turning.q);
        b.add(turning.w);
    }
    return b;
}

// The events and overlaps, as bits.
Bits findings(const Timeline &timeline) {
    Bits b;
    for (const ani_collision_event &e : timeline.events()) {
        b.add(e.t);
        b.words.push_back(e.a);
        b.words.push_back(e.b);
        b.add(e.normal);
        b.add(e.point);
        b.add(e.speed);
    }
    for (const ani_overlap &o : timeline.overlaps()) {
        b.add(o.t);
        b.words.push_back(o.a);
        b.words.push_back(o.b);
        b.add(o.normal);
        b.add(o.depth);
    }
    return b;
}

} // namespace

TEST_CASE("a bake saved and loaded answers as the original, bit for bit, with bounces and turning "
          "bodies") {
    const fs::path dir = test::fresh_dir("bake_file_round_trip");
    int free = 0, hinge = 0, spin_up = 0, events = 0;
    struct Example {
        const char *file;
        double until;
    };
    for (const Example &example :
         {Example{"assets/animations/drop.ani", 10.0}, Example{"assets/animations/cradle.ani", 4.0},
          Example{"assets/animations/gas.ani", 2.0}, Example{"assets/scenes/tipping_cube.lua", 5.0},
          Example{"assets/scenes/tumbling_cube.lua", 3.0},
          Example{"assets/scenes/rolling_ball.lua", 3.0},
          Example{"assets/scenes/tumbling_box.lua", 1.0},
          Example{"assets/scenes/box_stack.lua", 2.0}}) {
        const fs::path file = test::source_dir() / example.file;
        CAPTURE(file.string());
        auto original = timeline_of(file);
        original->bake(example.until);
        const fs::path saved = dir / (file.stem().string() + ".bake");
        save_bake(*original, saved);
        CHECK_FALSE(fs::exists(dir / ("." + saved.filename().string() + ".partial")));

        auto loaded = timeline_of(file);
        load_bake(*loaded, saved, example.until);
        CHECK(loaded->baked_until() == original->baked_until());
        CHECK(loaded->stats().bake_calls == 0); // nothing was baked again

        // Every time on a fine grid, and each segment's start and end, where a look-up changes.
        std::vector<double> times;
        for (int k = 0; k <= 997; ++k) times.push_back(example.until * k / 997.0);
        const size_t n = original->document().models().size();
        for (size_t m = 0; m < n; ++m) {
            for (const ani_motion_segment &s : original->segments(static_cast<int>(m)))
                for (double t : {s.t0, s.t1}) times.push_back(std::min(t, example.until));
            for (const RotationSegment &r : original->rotations(static_cast<int>(m))) {
                for (double t : {r.t0, (r.t0 + r.t1) / 2, r.t1})
                    times.push_back(std::min(t, example.until));
                free += r.free != nullptr;
                hinge += r.hinge != nullptr;
                spin_up += r.alpha != glm::dvec3(0.0);
                CHECK(loaded->rotations(static_cast<int>(m)).size() ==
                      original->rotations(static_cast<int>(m)).size());
            }
        }
        int differing = 0;
        for (double t : times)
            differing += answers_at(*original, t).words != answers_at(*loaded, t).words;
        CHECK(differing == 0);
        CHECK(findings(*original).words == findings(*loaded).words);
        CHECK(loaded->events().size() == original->events().size());
        events += static_cast<int>(original->events().size());
    }
    // The examples cover every kind of segment the file holds.
    CHECK(free > 0);
    CHECK(hinge > 0);
    CHECK(spin_up > 0);
    CHECK(events > 10);
}

TEST_CASE("a bake file is refused, leaving the timeline as it was, when it does not fit") {
    const fs::path dir = test::fresh_dir("bake_file_refused");
    const fs::path drop = test::source_dir() / "assets/animations/drop.ani";
    auto original = timeline_of(drop);
    original->bake(2.0);
    save_bake(*original, dir / "drop.bake");
    const std::string bytes = test::read_file(dir / "drop.bake");

    auto refused = [&](const std::string &content, const std::string &message,
                       double needed = 1.0) {
        test::write_file(dir / "bad.bake", content);
        auto t = timeline_of(drop);
        t->bake(0.5);
        CHECK_THROWS_WITH(load_bake(*t, dir / "bad.bake", needed),
                          Catch::Contains((dir / "bad.bake").string()) && Catch::Contains(message));
        CHECK(t->baked_until() == 0.5); // as it was
    };
    refused(bytes, "holds a bake to 2 s, and 3 s is needed", 3.0);
    refused(bytes.substr(0, bytes.size() - 1), "is truncated");
    refused(bytes.substr(0, 5), "is truncated");
    refused("", "not a bake file");
    refused("animator-ani 1\n", "not a bake file");
    std::string flipped = bytes;
    flipped[bytes.size() / 2] = static_cast<char>(flipped[bytes.size() / 2] ^ 0x10);
    refused(flipped, "is corrupt: its checksum does not match");
    std::string later = bytes;
    later[8] = static_cast<char>(kBakeFormatVersion + 1); // little-endian after the 8 bytes of magic
    refused(later, "format version " + std::to_string(kBakeFormatVersion + 1) + ", and this animator reads version " +
                       std::to_string(kBakeFormatVersion));

    // Another backend, a parameter, an edit that moves something, another mesh.
    Document doc = original->document();
    auto refused_for = [&](const Document &d, const std::string &message,
                           const std::string &backend = "") {
        Timeline t(d, env().plugins, backend);
        std::vector<std::string> ids, warnings;
        for (const Model &m : d.models()) ids.push_back(m.mesh);
        t.set_meshes(load_meshes(ids, env().assets, drop, warnings));
        CHECK_THROWS_WITH(load_bake(t, dir / "drop.bake", 1.0), Catch::Contains(message));
    };
    refused_for(doc, "was baked with physics backend 'physics.custom', not 'physics.bullet'",
                "physics.bullet");
    Document heavier = doc;
    Model ball = heavier.models()[1];
    ball.mass = 2.0;
    heavier.set_model(1, ball);
    refused_for(heavier, "the models' physics differs");
    Document moved = doc;
    ModelState s = *moved.keyframes()[0].states[1];
    s.center.y += 1.0;
    moved.set_state(0, 1, s);
    refused_for(moved, "the models' keyframes differ");
    Document other_mesh = doc;
    ball.mass = 1.0;
    ball.mesh = "cube";
    other_mesh.set_model(1, ball);
    refused_for(other_mesh, "another mesh for model 'ball'");

    // A change that moves nothing (a colour, the camera) keeps the bake.
    Document recoloured = doc;
    Model red = recoloured.models()[1];
    red.material.kd = {1.0, 0.0, 0.0};
    recoloured.set_model(1, red);
    Timeline t(recoloured, env().plugins);
    std::vector<std::string> ids{"plane", "sphere"}, warnings;
    t.set_meshes(load_meshes(ids, env().assets, drop, warnings));
    load_bake(t, dir / "drop.bake", 2.0);
    CHECK(t.baked_until() == 2.0);
    CHECK(answers_at(t, 1.7).words == answers_at(*original, 1.7).words);
}
