// The real `animator` executable, run as a user runs it: output and exit codes.
#include "support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <filesystem>
#include <sstream>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <regex>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

using namespace animator;

namespace {
const std::string drop = (test::source_dir() / "assets/animations/drop.ani").string();

} // namespace

TEST_CASE("animator --help names the subcommands and each subcommand has --help") {
    auto r = test::run_animator("--help");
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("plugins") && Catch::Contains("info"));
    for (const char *sub : {"plugins", "info"}) {
        auto s = test::run_animator(std::string(sub) + " --help");
        CAPTURE(sub);
        CHECK(s.exit_code == 0);
        CHECK_THAT(s.out, Catch::Contains("Usage") || Catch::Contains("usage"));
    }
}

TEST_CASE("animator plugins lists id, kind, version and library, and why any was refused") {
    auto r = test::run_animator("plugins");
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Matches(R"([\s\S]*format\.ani +file_format +1\.0\.0 +\S*animator-io-ani\.so[\s\S]*)"));

    auto broken = test::run_animator("plugins", std::string("ANIMATOR_PLUGIN_PATH=") + ANIMATOR_BROKEN_PLUGIN_DIR);
    CHECK(broken.exit_code == 0);
    CHECK_THAT(broken.out, Catch::Contains("format.ani"));
    CHECK_THAT(broken.out, Catch::Contains("interpolator.broken"));
    CHECK_THAT(broken.out, Catch::Contains("refused ") && Catch::Contains("animator-test-wrong-major.so: was built for plugin ABI 2."));
}

TEST_CASE("animator info prints a document's settings, models and keyframes") {
    auto r = test::run_animator("info " + drop);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("read by format.ani"));
    CHECK_THAT(r.out, Catch::Contains("max time:        10000 ms"));
    CHECK_THAT(r.out, Catch::Contains("gravity:         9.81 m/s^2 toward -y"));
    CHECK_THAT(r.out, Catch::Contains("models (2):"));
    CHECK_THAT(r.out, Catch::Contains("ball: mesh sphere ("));
    CHECK_THAT(r.out, Catch::Contains("sphere.obj: "));
    CHECK_THAT(r.out, Catch::Contains("dynamics on, gravity on, mass 1"));
    // drop.ani predates the rigid-body keys: the defaults.
    CHECK_THAT(r.out, Catch::Contains("rigid body: restitution 1, friction 0, rotates off, angular velocity (0, 0, 0) rad/s"));
    CHECK_THAT(r.out, Catch::Contains("keyframes (1):"));
    CHECK_THAT(r.out, Catch::Contains("ball: center (0, 5, 0)"));
}

TEST_CASE("bad input exits 1 naming the file and usage errors exit 2") {
    const auto dir = test::fresh_dir("cli_bad");
    auto missing = test::run_animator("info " + (dir / "missing.ani").string());
    CHECK(missing.exit_code == 1);
    CHECK_THAT(missing.out, Catch::Contains("missing.ani"));

    test::write_file(dir / "bad.ani", "animator-ani 1\nmodel \"b\"\n  mass -1\nend\n");
    auto bad = test::run_animator("info " + (dir / "bad.ani").string());
    CHECK(bad.exit_code == 1);
    CHECK_THAT(bad.out, Catch::Contains("bad.ani:3: expected mass > 0"));

    CHECK(test::run_animator("info").exit_code == 2);
    CHECK(test::run_animator("frobnicate").exit_code == 2);
    CHECK(test::run_animator("info --bogus " + drop).exit_code == 2);
}

TEST_CASE("animator info prints every example with its models, keyframes and resolved meshes") {
    namespace fs = std::filesystem;
    int examples = 0;
    for (const char *folder : {"assets/animations", "assets/scenes"}) {
        for (const auto &entry : fs::directory_iterator(test::source_dir() / folder)) {
            const fs::path file = entry.path();
            if (file.extension() != ".ani" && file.extension() != ".lua") continue;
            CAPTURE(file.string());
            // Independent counts from the text: model blocks / gr.mesh calls, keyframe blocks.
            const std::string text = test::read_file(file);
            auto count = [&](const std::string &needle) {
                size_t n = 0;
                for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
                return n;
            };
            // A scene's models: its meshes and its empties (joints, and nodes but the root).
            const bool lua = file.extension() == ".lua";
            const size_t meshed = lua ? count("gr.mesh(") : count("\nmodel \"");
            const size_t models = lua ? meshed + count("gr.joint(") + count("gr.node(") - 1 : meshed;
            const size_t keyframes = file.extension() == ".ani" ? count("\nkeyframe ") : 1;
            const auto r = test::run_animator("info " + file.string());
            CHECK(r.exit_code == 0);
            CHECK_THAT(r.out, Catch::Contains("models (" + std::to_string(models) + "):"));
            CHECK_THAT(r.out, Catch::Contains("keyframes (" + std::to_string(keyframes) + "):"));
            CHECK_THAT(r.out, !Catch::Contains("not found"));
            CHECK(std::count(r.out.begin(), r.out.end(), '\n') > 10);
            // Each model's mesh was found and loaded (empties say so).
            CHECK(test::count_in(r.out, "(none: an empty)") == models - meshed);
            size_t meshes = 0;
            for (size_t at = r.out.find(" triangles, bounding sphere"); at != std::string::npos;
                 at = r.out.find(" triangles, bounding sphere", at + 1))
                ++meshes;
            CHECK(meshes == meshed);
            ++examples;
        }
    }
    CHECK(examples >= 5); // simple.lua, drop, stairs, orbs, cradle
}

namespace {

std::vector<std::string> lines_of(const std::string &text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) out.push_back(line);
    return out;
}

} // namespace

TEST_CASE("animator bake writes a trace of every model at every step and every keyframe time") {
    namespace fs = std::filesystem;
    const fs::path dir = test::fresh_dir("cli_bake");
    const std::string stairs = (test::source_dir() / "assets/animations/stairs.ani").string();
    const auto r = test::run_animator("bake " + stairs + " --until 1 --step 0.25 --trace " +
                                      (dir / "trace.csv").string() + " --events " + (dir / "events.csv").string());
    REQUIRE(r.exit_code == 0);
    const auto rows = lines_of(test::read_file(dir / "trace.csv"));
    REQUIRE(!rows.empty());
    CHECK(rows[0] == "t,model,x,y,z,rx,ry,rz,sx,sy,sz,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz");
    // Times 0, 0.25, 0.4 (the second keyframe), 0.5, 0.75, 1: six samples of three models.
    CHECK(rows.size() == 1 + 6 * 3);
    // At the keyframe time the cube is exactly at its key, center (0.44, 2.92, 0), leaving it at
    // 2 d / T = (0.7, 0.85) m/s (kinematic keys from rest over 0.4 s).
    bool found = false;
    for (const std::string &row : rows)
        if (row.rfind("0.40000000000000002,cube,", 0) == 0) {
            found = true;
            CHECK_THAT(row, Catch::StartsWith("0.40000000000000002,cube,0.44,2.9199999999999999,0,0,0,0,0.25,0.25,0.25,"));
        }
    CHECK(found);
    // Its first landing, flat on the top step, within the first second.
    const auto events = lines_of(test::read_file(dir / "events.csv"));
    REQUIRE(events.size() == 2);
    CHECK(events[0] == "t,a,b,nx,ny,nz,speed");
    CHECK_THAT(events[1], Catch::Contains(",cube,stairs,0,1,0,"));
}

TEST_CASE("animator bake --save writes the bake through a partial file, and a run stopped part way "
          "leaves an earlier file whole") {
    namespace fs = std::filesystem;
    const fs::path dir = test::fresh_dir("cli_bake_save");
    const std::string gas = (test::source_dir() / "assets/animations/gas.ani").string();
    const fs::path bake = dir / "gas.bake";
    auto r = test::run_animator("bake " + drop + " --until 2 --save " + bake.string());
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("wrote " + bake.string() + " (the bake of 0 to 2 s)"));
    const std::string earlier = test::read_file(bake);
    CHECK(earlier.rfind(std::string("ANIBAKE\0\2\0\0\0", 12), 0) == 0); // the magic, then version 2
    // A far larger bake, killed by the file size limit (SIGXFSZ) while it writes.
    r = test::run_animator("bake " + gas + " --until 2 --save " + bake.string(), "ulimit -f 16;");
    CHECK(r.exit_code != 0);
    CHECK(test::read_file(bake) == earlier);
    // Without the limit it is written whole, and replaces the earlier file.
    r = test::run_animator("bake " + gas + " --until 2 --save " + bake.string());
    CHECK(r.exit_code == 0);
    CHECK(test::read_file(bake).size() > 16 * 1024);
    CHECK_FALSE(fs::exists(dir / ".gas.bake.partial"));
    // A folder that is not there: exit 1 naming the file.
    r = test::run_animator("bake " + drop + " --save " + (dir / "no/such/folder/x.bake").string());
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Contains((dir / "no/such/folder/x.bake").string() + ": cannot be written"));
}

TEST_CASE("animator soundtrack and export take a shared bake (--bake) and write what they write when they bake") {
    namespace fs = std::filesystem;
    const fs::path dir = test::fresh_dir("cli_shared_bake");
    const std::string cradle = (test::source_dir() / "assets/animations/cradle.ani").string();
    const fs::path bake = dir / "cradle.bake";
    REQUIRE(test::run_animator("bake " + cradle + " --save " + bake.string()).exit_code == 0);
    for (const std::string &command : {std::string("soundtrack ") + cradle + " --out " + (dir / "X.wav").string(),
                                       std::string("export ") + cradle + " --to " + (dir / "X.glb").string()}) {
        CAPTURE(command);
        auto own = test::run_animator(std::regex_replace(command, std::regex("X\\."), "own."));
        REQUIRE(own.exit_code == 0);
        auto shared = test::run_animator(std::regex_replace(command, std::regex("X\\."), "shared.") + " --bake " + bake.string());
        INFO(shared.out);
        REQUIRE(shared.exit_code == 0);
        const std::string ext = command.find("soundtrack") == 0 ? ".wav" : ".glb";
        CHECK(test::read_file(dir / ("own" + ext)) == test::read_file(dir / ("shared" + ext)));
        // Another animation's bake is refused, naming it, and nothing is written.
        const std::string drop_bake = (dir / "drop.bake").string();
        if (!fs::exists(drop_bake)) REQUIRE(test::run_animator("bake " + drop + " --save " + drop_bake).exit_code == 0);
        auto refused = test::run_animator(std::regex_replace(command, std::regex("X\\."), "refused.") + " --bake " + drop_bake);
        CHECK(refused.exit_code == 1);
        CHECK_THAT(refused.out, Catch::Contains("--bake " + drop_bake));
        CHECK_FALSE(fs::exists(dir / ("refused" + ext)));
    }
}

TEST_CASE("animator bake runs on every example and reports its statistics") {
    namespace fs = std::filesystem;
    for (const char *folder : {"assets/animations", "assets/scenes"})
        for (const auto &entry : fs::directory_iterator(test::source_dir() / folder)) {
            CAPTURE(entry.path().string());
            const auto r = test::run_animator("bake " + entry.path().string() + " --stats");
            CHECK(r.exit_code == 0);
            CHECK_THAT(r.out, Catch::Contains("backend:   physics.custom"));
            CHECK_THAT(r.out, Catch::Contains("segments:  "));
            CHECK_THAT(r.out, Catch::Contains("skipped:   "));
        }
}

TEST_CASE("animator bake --stats reports the pair tests the broad phase did and skipped") {
    const std::string gas = (test::source_dir() / "assets/animations/gas.ani").string();
    auto count = [](const std::string &out, const std::string &name) {
        const auto at = out.find("  " + name + ": ");
        REQUIRE(at != std::string::npos);
        return std::stod(out.substr(at + name.size() + 4));
    };
    const auto grid = test::run_animator("bake " + gas + " --until 5 --stats");
    const auto pairs = test::run_animator("bake " + gas + " --until 5 --stats --param broad_phase=2");
    REQUIRE(grid.exit_code == 0);
    REQUIRE(pairs.exit_code == 0);
    // 125 balls: the grid tests a few neighbours per prediction, all pairs every other ball.
    CHECK(count(grid.out, "pair tests done") > 0);
    CHECK(count(grid.out, "pair tests skipped") > 5 * count(grid.out, "pair tests done"));
    CHECK(count(grid.out, "cell crossings") > 0);
    CHECK(count(pairs.out, "pair tests done") > 3 * count(grid.out, "pair tests done"));
    CHECK(count(pairs.out, "cell crossings") == 0);
    CHECK(count(grid.out, "collisions") > 1000);
}

TEST_CASE("animator bake refuses a bad backend, time, step or parameter") {
    auto bad_backend = test::run_animator("bake " + drop + " --backend physics.nope");
    CHECK(bad_backend.exit_code == 1);
    CHECK_THAT(bad_backend.out, Catch::Contains("drop.ani: no physics backend 'physics.nope'"));
    auto late = test::run_animator("bake " + drop + " --until 11");
    CHECK(late.exit_code == 1);
    CHECK_THAT(late.out, Catch::Contains("past the animation's max time 10 s"));
    CHECK(test::run_animator("bake " + drop + " --step 0").exit_code == 2);
    auto param = test::run_animator("bake " + drop + " --param restitution=0.5");
    CHECK(param.exit_code == 1);
    CHECK_THAT(param.out, Catch::Contains("physics.custom") && Catch::Contains("restitution"));
}

TEST_CASE("animator compare reports the largest differences and the unmatched events of two backends") {
    namespace fs = std::filesystem;
    const fs::path dir = test::fresh_dir("cli_compare");
    const std::string cradle = (test::source_dir() / "assets/animations/cradle.ani").string();
    // A backend against itself: nothing apart, every event matched.
    const auto same = test::run_animator("compare " + cradle + " --backends physics.custom,physics.custom --csv " +
                                         (dir / "diff.csv").string());
    REQUIRE(same.exit_code == 0);
    CHECK_THAT(same.out, Catch::Contains("striker") && Catch::Contains("0 m at 0 s"));
    CHECK_THAT(same.out, Catch::Contains("events: 4 in A, 4 in B"));
    CHECK_THAT(same.out, Catch::Contains("only in A: 0") && Catch::Contains("only in B: 0"));
    const auto rows = lines_of(test::read_file(dir / "diff.csv"));
    REQUIRE(rows.size() > 100);
    CHECK(rows[0] == "t,model,dx,dy,dz,dvx,dvy,dvz");
    // Different settings of the same backend: a parameter goes to the backends that have it.
    const auto grid = test::run_animator("compare " + cradle + " --backends physics.custom,physics.custom --param broad_phase=1");
    CHECK(grid.exit_code == 0);
    const auto unknown = test::run_animator("compare " + cradle + " --backends physics.custom,physics.custom --param nope=1");
    CHECK(unknown.exit_code == 1);
    CHECK_THAT(unknown.out, Catch::Contains("--param nope: neither physics.custom nor physics.custom"));
    const auto bad = test::run_animator("compare " + cradle + " --backends physics.custom,physics.nope");
    CHECK(bad.exit_code == 1);
    CHECK_THAT(bad.out, Catch::Contains("no physics backend 'physics.nope'"));
    const auto one = test::run_animator("compare " + cradle + " --backends physics.custom");
    CHECK(one.exit_code == 2);
}

TEST_CASE("animator compare of the exact and the Bullet backend on the cradle matches every event") {
    const std::string cradle = (test::source_dir() / "assets/animations/cradle.ani").string();
    const auto r = test::run_animator("compare " + cradle + " --backends physics.custom,physics.bullet --until 4");
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("compared physics.custom (A) with physics.bullet (B)"));
    CHECK_THAT(r.out, Catch::Contains("events: 4 in A, 4 in B"));
    CHECK_THAT(r.out, Catch::Contains("only in A: 0") && Catch::Contains("only in B: 0"));
    // A Bullet parameter reaches Bullet only; one out of its range is refused.
    const auto fine = test::run_animator("compare " + cradle + " --until 2 --param step=0.001");
    CHECK(fine.exit_code == 0);
    const auto coarse = test::run_animator("compare " + cradle + " --until 2 --param step=0.5");
    CHECK(coarse.exit_code == 1);
    CHECK_THAT(coarse.out, Catch::Contains("step"));
}

TEST_CASE("animator info prints each model's rigid-body settings") {
    const auto dir = test::fresh_dir("cli_info_body");
    test::write_file(dir / "body.ani",
                     "animator-ani 1\nmodel \"top\"\n  mesh \"cube\"\n  restitution 0.5\n  friction 0.75\n"
                     "  rotates true\n  angular_velocity 0 -1.5 6.25\nend\nkeyframe 0\n"
                     "  camera position 0 0 0 rotation 1 0 0 0 fov 50\n"
                     "  state \"top\" center 0 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0\nend\n");
    auto r = test::run_animator("info " + (dir / "body.ani").string());
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("top: mesh cube") &&
                          Catch::Contains("    rigid body: restitution 0.5, friction 0.75, rotates on, "
                                          "angular velocity (0, -1.5, 6.25) rad/s\n"));
}

TEST_CASE("animator bake --trace gives each model's world orientation and angular velocity") {
    namespace fs = std::filesystem;
    const fs::path dir = test::fresh_dir("cli_trace_turning");
    // Linear keys: "spin" turns about Z from 0 to 90 degrees in 1 s; "arm", its child, is turned
    // 90 degrees about its own X and keyed still; "tumble" turns about X (0 -> 60) and Z (0 -> 90).
    test::write_file(dir / "turn.ani",
                     "animator-ani 1\nsettings\n  max_time_ms 2000\n  interpolation \"interpolation.linear\"\nend\n"
                     "model \"spin\"\n  mesh \"cube\"\nend\n"
                     "model \"arm\"\n  mesh \"cube\"\n  parent \"spin\"\nend\n"
                     "model \"tumble\"\n  mesh \"cube\"\nend\n"
                     "keyframe 0\n  camera position 0 0 10 rotation 1 0 0 0 fov 50\n"
                     "  state \"spin\" center 0 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0\n"
                     "  state \"arm\" center 2 0 0 angles 90 0 0 scale 1 1 1 turn 0 0 0\n"
                     "  state \"tumble\" center 5 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0\nend\n"
                     "keyframe 1000\n"
                     "  state \"spin\" center 0 0 0 angles 0 0 90 scale 1 1 1 turn 0 0 0\n"
                     "  state \"arm\" center 2 0 0 angles 90 0 0 scale 1 1 1 turn 0 0 0\n"
                     "  state \"tumble\" center 5 0 0 angles 60 0 90 scale 1 1 1 turn 0 0 0\nend\n");
    const auto r = test::run_animator("bake " + (dir / "turn.ani").string() + " --until 1.5 --step 0.001 --trace " +
                                      (dir / "trace.csv").string());
    REQUIRE(r.exit_code == 0);
    const auto rows = lines_of(test::read_file(dir / "trace.csv"));
    REQUIRE(!rows.empty());
    CHECK(rows[0] == "t,model,x,y,z,rx,ry,rz,sx,sy,sz,vx,vy,vz,qw,qx,qy,qz,wx,wy,wz");
    // [sample][model] -> q (w, x, y, z) and w.
    struct Turn {
        double q[4], w[3];
    };
    std::map<long, std::map<std::string, Turn>> at;
    for (size_t i = 1; i < rows.size(); ++i) {
        std::vector<std::string> f;
        std::istringstream in(rows[i]);
        for (std::string cell; std::getline(in, cell, ',');) f.push_back(cell);
        REQUIRE(f.size() == 21);
        Turn t{};
        for (int k = 0; k < 4; ++k) t.q[k] = std::stod(f[14 + static_cast<size_t>(k)]);
        for (int k = 0; k < 3; ++k) t.w[k] = std::stod(f[18 + static_cast<size_t>(k)]);
        at[std::lround(std::stod(f[0]) * 1000.0)][f[1]] = t;
    }
    REQUIRE(at.size() == 1501);
    const double pi = 3.14159265358979323846;
    for (long k : {250L, 500L, 750L, 1250L}) {
        CAPTURE(k);
        const double t = static_cast<double>(k) / 1000.0;
        // spin: q = (cos(theta/2), 0, 0, sin(theta/2)), theta = (pi/2) t until 1 s, then held;
        // w = (0, 0, pi/2) while turning, 0 after.
        const double theta = pi / 2 * std::min(t, 1.0), rate = t < 1.0 ? pi / 2 : 0.0;
        const Turn &s = at[k]["spin"];
        CHECK(s.q[0] == Approx(std::cos(theta / 2)).margin(1e-12));
        CHECK(s.q[1] == Approx(0.0).margin(1e-12));
        CHECK(s.q[2] == Approx(0.0).margin(1e-12));
        CHECK(s.q[3] == Approx(std::sin(theta / 2)).margin(1e-12));
        CHECK(s.w[0] == Approx(0.0).margin(1e-12));
        CHECK(s.w[1] == Approx(0.0).margin(1e-12));
        CHECK(s.w[2] == Approx(rate).margin(1e-12));
        // arm: its parent's turn about Z followed by its own 90 degrees about X:
        // qz * qx = (cz cx, cz sx, sz sx, sz cx) with cx = sx = sqrt(1/2); it turns with its parent.
        const double cz = std::cos(theta / 2), sz = std::sin(theta / 2), h = std::sqrt(0.5);
        const Turn &a = at[k]["arm"];
        CHECK(a.q[0] == Approx(cz * h).margin(1e-12));
        CHECK(a.q[1] == Approx(cz * h).margin(1e-12));
        CHECK(a.q[2] == Approx(sz * h).margin(1e-12));
        CHECK(a.q[3] == Approx(sz * h).margin(1e-12));
        CHECK(a.w[2] == Approx(rate).margin(1e-12));
    }
    // tumble at 0.5 s: a = 30 degrees about X at 60 deg/s, c = 45 about Z at 90 deg/s. By hand,
    // w = a' X + Rx(a) c' Z = (pi/3, -(pi/2) sin 30, (pi/2) cos 30).
    const Turn &half = at[500]["tumble"];
    CHECK(half.w[0] == Approx(pi / 3).margin(1e-12));
    CHECK(half.w[1] == Approx(-pi / 4).margin(1e-12));
    CHECK(half.w[2] == Approx(pi / 2 * std::sqrt(3.0) / 2).margin(1e-12));
    // And everywhere inside the key span, w agrees with a central difference of the trace's own
    // orientations: w = 2 (q(t+h) - q(t-h)) / (2h) q(t)* (vector part), error O(h^2) ~ 1e-6.
    for (long k = 2; k <= 998; k += 4) {
        CAPTURE(k);
        const Turn &p = at[k + 1]["tumble"], &m = at[k - 1]["tumble"], &c = at[k]["tumble"];
        double d[4];
        for (int i = 0; i < 4; ++i) d[i] = (p.q[i] - m.q[i]) / 0.002;
        // (d) * conj(c), vector part: d0 (-c_v) + c0 d_v + d_v x (-c_v)
        const double cw = c.q[0], cx = -c.q[1], cy = -c.q[2], cz2 = -c.q[3];
        const double vx = d[0] * cx + cw * d[1] + (d[2] * cz2 - d[3] * cy);
        const double vy = d[0] * cy + cw * d[2] + (d[3] * cx - d[1] * cz2);
        const double vz = d[0] * cz2 + cw * d[3] + (d[1] * cy - d[2] * cx);
        CHECK(c.w[0] == Approx(2 * vx).margin(1e-5));
        CHECK(c.w[1] == Approx(2 * vy).margin(1e-5));
        CHECK(c.w[2] == Approx(2 * vz).margin(1e-5));
        const double norm = std::sqrt(c.q[0] * c.q[0] + c.q[1] * c.q[1] + c.q[2] * c.q[2] + c.q[3] * c.q[3]);
        CHECK(norm == Approx(1.0).margin(1e-12));
        CHECK(c.q[0] >= 0.0);
    }
}

namespace fs = std::filesystem;

TEST_CASE("with --strict, on any subcommand, a file's warnings are errors: exit 1, nothing written") {
    const fs::path dir = test::fresh_dir("cli_strict");
    const fs::path scene = dir / "puppet.lua";
    test::write_file(scene, "local root = gr.node('root')\nlocal a = gr.mesh('cube', 'arm')\nroot:add_child(a)\n"
                            "local b = gr.mesh('cube', 'arm')\nroot:add_child(b)\nreturn root\n");
    const std::string rename = "puppet.lua:4: 1 node name was used before or empty, renamed to be unique: line 4 'arm' -> 'arm.001'.";
    // Without it: a warning, and the work done.
    auto info = test::run_animator("info " + scene.string());
    CHECK(info.exit_code == 0);
    CHECK_THAT(info.out, Catch::Contains(rename));
    CHECK_THAT(info.out, Catch::Contains("arm.001: mesh cube"));
    auto bake = test::run_animator("bake " + scene.string() + " --until 0.1 --trace " + (dir / "a.csv").string());
    CHECK(bake.exit_code == 0);
    CHECK(fs::exists(dir / "a.csv"));
    // With it, before or after the subcommand: the warning, an error that names the file, exit 1.
    for (const std::string &args :
         {"--strict info " + scene.string(), "info --strict " + scene.string(),
          "bake --strict " + scene.string() + " --until 0.1 --trace " + (dir / "b.csv").string(),
          "render " + scene.string() + " --strict --to 0.1 --out " + (dir / "frames").string(),
          "soundtrack --strict " + scene.string() + " --out " + (dir / "s.wav").string()}) {
        CAPTURE(args);
        auto r = test::run_animator(args);
        CHECK(r.exit_code == 1);
        CHECK_THAT(r.out, Catch::Contains(rename));
        CHECK_THAT(r.out, Catch::Contains(scene.string() + ": 1 warning (said above), which --strict makes errors"));
    }
    CHECK_FALSE(fs::exists(dir / "b.csv"));
    CHECK_FALSE(fs::exists(dir / "frames"));
    CHECK_FALSE(fs::exists(dir / "s.wav"));
    // A file without warnings is not refused.
    CHECK(test::run_animator("--strict info " + drop).exit_code == 0);
}

TEST_CASE("animator info --json gives the whole document, each model's world matrix at t = 0 as the "
          "CS488 transform stack makes it") {
    // A puppet: the root moved (folded into its children), a sheared-free chain of a joint, a
    // scaled and turned mesh under it, and a duplicate name. The truth: the course's own rule,
    // written here apart from the reader: each call multiplies on the left of the node's matrix
    // (M = call M), and a node's world matrix is its parent's times its own.
    const fs::path dir = test::fresh_dir("cli_info_json");
    const fs::path scene = dir / "puppet.lua";
    test::write_file(scene, "local root = gr.node('root')\n"
                            "root:translate(0, 10, 0)\n"
                            "local arm = gr.joint('arm', {-90, 45, 90}, {-30, 20, 30})\n"
                            "arm:translate(1, 2, 3)\n"
                            "root:add_child(arm)\n"
                            "local upper = gr.mesh('cube', 'upper')\n"
                            "upper:scale(0.5, 0.5, 0.5)\n"
                            "upper:rotate('z', 30)\n"
                            "upper:translate(0, 1, 0)\n"
                            "arm:add_child(upper)\n"
                            "local twin = gr.mesh('sphere', 'upper')\n"
                            "twin:translate(2, 0, 0)\n"
                            "root:add_child(twin)\n"
                            "return root\n");
    auto r = test::run_animator("info --json " + scene.string());
    REQUIRE(r.exit_code == 0);
    // (The output holds stderr too: the rename's warning line, before the JSON.)
    const size_t start = r.out.find("{\n");
    REQUIRE(start != std::string::npos);
    const nlohmann::json doc = nlohmann::json::parse(r.out.substr(start));
    CHECK(doc["format"] == "format.lua");
    CHECK(doc["settings"]["down"] == "y");
    REQUIRE(doc["models"].size() == 3);
    CHECK(doc["warnings"].size() == 1); // the second 'upper', renamed
    auto T = [](double x, double y, double z) { return glm::translate(glm::dmat4(1.0), glm::dvec3(x, y, z)); };
    auto R = [](double degrees, glm::dvec3 axis) { return glm::rotate(glm::dmat4(1.0), glm::radians(degrees), axis); };
    const glm::dmat4 root = T(0, 10, 0);
    const glm::dmat4 arm = root * (T(1, 2, 3) * R(20, {0, 1, 0}) * R(45, {1, 0, 0}));
    const glm::dmat4 upper = arm * (T(0, 1, 0) * R(30, {0, 0, 1}) * glm::scale(glm::dmat4(1.0), glm::dvec3(0.5)));
    const glm::dmat4 twin = root * T(2, 0, 0);
    const std::vector<std::tuple<std::string, std::string, std::string, glm::dmat4>> expected = {
        {"arm", "", "", arm}, {"upper", "cube", "arm", upper}, {"upper.001", "sphere", "", twin}};
    for (size_t i = 0; i < expected.size(); ++i) {
        const auto &[name, mesh, parent, world] = expected[i];
        const nlohmann::json &m = doc["models"][i];
        CAPTURE(name);
        CHECK(m["name"] == name);
        CHECK(m["mesh"] == mesh);
        if (parent.empty())
            CHECK(m["parent"].is_null());
        else
            CHECK(m["parent"] == parent);
        REQUIRE(m["world"].size() == 16);
        for (int c = 0; c < 4; ++c)
            for (int k = 0; k < 4; ++k) CHECK(std::abs(m["world"][4 * c + k].get<double>() - world[c][k]) < 1e-12);
    }
    CHECK(doc["keyframes"][0]["time_ms"] == 0);
    CHECK(doc["keyframes"][0]["states"].contains("upper.001"));
    CHECK(doc["lights"].empty());
}

TEST_CASE("scene files written as CS488 students write them open, each model where the course's "
          "transform stack puts it, and A4's lights, ambient, image and camera as gr.render gave them "
          "(an independent evaluation by lua5.4, to 1e-12)") {
    // tests/data/cs488: puppets with helper functions, loops, locals, names used twice or
    // empty, CRLF line endings and tabs, block comments, inline materials, extra arguments, a z
    // joint range, ranges in radians, colours above 1, a sheared puppet, meshes the author did not
    // publish, initial angles outside their ranges, a chain twelve joints deep; and the ray
    // tracer's (A4) scenes: primitives, instances, CSG, lights and gr.render. shim.lua evaluates
    // the course's stack apart from animator, in Debian's Lua 5.4 interpreter (installed by
    // tools/install-deps.sh).
    REQUIRE(std::system("command -v lua5.4 > /dev/null") == 0); // else: install lua5.4
    const fs::path corpus = test::source_dir() / "tests/data/cs488";
    int files = 0, a4_files = 0;
    auto near = [](const nlohmann::json &got, const std::vector<double> &want, size_t from, size_t count) {
        double worst = 0.0;
        for (size_t k = 0; k < count; ++k) worst = std::max(worst, std::abs(got[k].get<double>() - want[from + k]));
        return worst;
    };
    for (const auto &entry : fs::directory_iterator(corpus)) {
        const fs::path file = entry.path();
        if (file.extension() != ".lua" || file.filename() == "shim.lua") continue;
        ++files;
        CAPTURE(file.filename().string());
        const fs::path truth_file = test::fresh_dir("cs488_" + file.stem().string()) / "truth.txt";
        REQUIRE(std::system(("lua5.4 " + (corpus / "shim.lua").string() + " " + file.string() + " > " +
                             truth_file.string())
                                .c_str()) == 0);
        // The shim's lines: "world m1..m16" per model, then "light NAME x y z r g b c0 c1 c2" per
        // light, "ambient r g b", "render FILE W H" and "camera eye forward up fov".
        std::ifstream in(truth_file);
        std::vector<std::vector<double>> worlds, lights, cameras, ambients;
        std::vector<std::string> light_names;
        std::string render_file;
        int render_width = -1, render_height = -1;
        for (std::string line; std::getline(in, line);) {
            std::istringstream words(line);
            std::string kind;
            words >> kind;
            if (kind == "light") {
                light_names.emplace_back();
                words >> light_names.back();
            } else if (kind == "render") {
                words >> render_file >> render_width >> render_height;
                continue;
            }
            std::vector<double> numbers{std::istream_iterator<double>(words), std::istream_iterator<double>()};
            if (kind == "world") worlds.push_back(numbers);
            else if (kind == "light") lights.push_back(numbers);
            else if (kind == "ambient") ambients.push_back(numbers);
            else if (kind == "camera") cameras.push_back(numbers);
            else FAIL("shim.lua wrote an unknown line: " << line);
        }
        REQUIRE(ambients.size() == 1);
        REQUIRE(cameras.size() == 1);
        REQUIRE(render_width >= 0);
        auto r = test::run_animator("info --json " + file.string());
        REQUIRE(r.exit_code == 0);
        const size_t start = r.out.find("{\n");
        REQUIRE(start != std::string::npos);
        const nlohmann::json doc = nlohmann::json::parse(r.out.substr(start));
        REQUIRE(doc["models"].size() == worlds.size());
        for (size_t i = 0; i < worlds.size(); ++i) {
            CAPTURE(i, doc["models"][i]["name"].get<std::string>());
            REQUIRE(worlds[i].size() == 16);
            CHECK(near(doc["models"][i]["world"], worlds[i], 0, 16) < 1e-12);
        }
        // What gr.render set: the lights (each once, in its order), the ambient light, the image.
        REQUIRE(doc["lights"].size() == lights.size());
        for (size_t i = 0; i < lights.size(); ++i) {
            const nlohmann::json &l = doc["lights"][i];
            CAPTURE(i);
            CHECK(l["name"] == light_names[i]);
            CHECK(near(l["position"], lights[i], 0, 3) < 1e-12);
            CHECK(near(l["colour"], lights[i], 3, 3) < 1e-12);
            CHECK(near(l["falloff"], lights[i], 6, 3) < 1e-12);
        }
        CHECK(near(doc["settings"]["ambient"], ambients[0], 0, 3) < 1e-12);
        CHECK(doc["settings"]["render"]["output"] == (render_file == "-" ? "" : render_file));
        CHECK(doc["settings"]["render"]["width"] == render_width);
        CHECK(doc["settings"]["render"]["height"] == render_height);
        if (render_file != "-") ++a4_files;
        // The camera at t = 0: its eye, and the quaternion turning -Z to the view direction and +Y
        // to the up the shim made square to it, and the vertical fov.
        const nlohmann::json &camera = doc["keyframes"][0]["camera"];
        const std::vector<double> &c = cameras[0];
        REQUIRE(c.size() == 10);
        CHECK(near(camera["position"], c, 0, 3) < 1e-12);
        const glm::dquat q(camera["rotation"][0].get<double>(), camera["rotation"][1].get<double>(),
                           camera["rotation"][2].get<double>(), camera["rotation"][3].get<double>());
        const glm::dvec3 forward = q * glm::dvec3(0, 0, -1), up = q * glm::dvec3(0, 1, 0);
        CHECK(glm::length(forward - glm::dvec3(c[3], c[4], c[5])) < 1e-12);
        CHECK(glm::length(up - glm::dvec3(c[6], c[7], c[8])) < 1e-12);
        CHECK(std::abs(camera["fov"].get<double>() - c[9]) < 1e-12);
    }
    CHECK(files >= 15);
    CHECK(a4_files >= 4);
}

TEST_CASE("animator info says a scene's lights, ambient light, render output, joint ranges and "
          "shear") {
    const fs::path dir = test::fresh_dir("cli_info_lights");
    test::write_file(dir / "lit.lua", "local root = gr.node('root')\n"
                                      "local neck = gr.joint('neck', {-20, 0, 20}, {-45, 0, 45})\n"
                                      "root:add_child(neck)\n"
                                      "local head = gr.mesh('sphere', 'head')\n"
                                      "head:rotate('z', 30)\n"
                                      "head:scale(1, 2, 1)\n"
                                      "neck:add_child(head)\n"
                                      "local lamp = gr.light({1, 2, 3}, {0.5, 1.5, 0.25}, {1, 0, 0.5})\n"
                                      "gr.render(root, 'lit.png', 320, 200, {0, 0, 10}, {0, 0, -1}, {0, 1, 0}, 40,\n"
                                      "          {0.1, 0.2, 0.3}, {lamp})\n");
    const auto r = test::run_animator("info " + (dir / "lit.lua").string());
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("  ambient light:   (0.1, 0.2, 0.3)\n"));
    CHECK_THAT(r.out, Catch::Contains("  render output:   lit.png, 320x200"));
    CHECK_THAT(r.out, Catch::Contains("lights (1):\n  light: position (1, 2, 3), colour (0.5, 1.5, 0.25), falloff "
                                      "(1, 0, 0.5)\n"));
    CHECK_THAT(r.out, Catch::Contains("    joint range (deg): x -20..20, y -45..45, z 0..0\n"));
    CHECK_THAT(r.out, Catch::Contains("    rest shape: sheared"));
    // A document without lights is lit by the camera's own light, and says so.
    const auto d = test::run_animator("info " + drop);
    CHECK_THAT(d.out, Catch::Contains("lights (0): the camera's own light\n"));
    CHECK_THAT(d.out, !Catch::Contains("render output:"));
}
