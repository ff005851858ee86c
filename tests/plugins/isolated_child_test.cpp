// The child process that runs untrusted scenes (plugins/io-lua/isolated_child.hpp), and the
// decoder of what it sends back (scene_wire.hpp), tested directly: whatever the work in the
// child does, the caller gets a reply, a time-out or a crash report, and nothing else.
#include "isolated_child.hpp"
#include "scene_wire.hpp"

#include <catch2/catch.hpp>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <random>

#include <fcntl.h>
#include <linux/futex.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <unistd.h>

using namespace lua_scene;

namespace {

ChildLimits quick_limits() {
    ChildLimits limits;
    limits.cpu_seconds = 1;
    limits.wall_seconds = 30;
    return limits;
}

// What a system call did, as the child reports it.
std::string outcome_of(long result) { return result >= 0 ? "allowed" : std::string("refused: ") + std::strerror(errno); }

SceneResult sample_scene() {
    SceneResult s;
    s.max_time_ms = 12345;
    s.gravity = -3.5;
    s.down_axis = ANI_AXIS_Z;
    s.cel_shading = true;
    s.skybox = "day";
    s.backend = "physics.bullet";
    s.interpolation = "interpolation.smooth";
    s.camera = {{1, 2, 3}, {0.5, 0.5, 0.5, 0.5}, 33.0};
    s.warnings = {"a.lua:3: sheared", ""};
    for (int i = 0; i < 3; ++i) {
        SceneModel m;
        m.name = "model" + std::to_string(i);
        m.mesh = i == 1 ? "" : "sphere";
        m.line = 10 + i;
        m.parent = i - 1;
        m.kd = {0.1 * i, 0.2, 0.3};
        m.shininess = 7.0 + i;
        m.texture = "brick";
        m.tint = 0.5;
        m.dynamics = i % 2 == 0;
        m.gravity = true;
        m.mass = 2.5 * (i + 1);
        m.initial_velocity = {1, -1, 0.25};
        m.restitution = 0.125 * (i + 1);
        m.friction = 0.3 + i;
        m.rotates = i % 2 == 1;
        m.angular_velocity = {0.5 * i, -2, 6.28};
        m.collision_sound = "click";
        m.moving_sound = std::string("h\0m", 3); // any bytes
        m.state.center = {double(i), 2, 3};
        m.state.angles = {10, 20, 30};
        m.state.scale = {1, 2, 3};
        s.models.push_back(m);
    }
    return s;
}

bool same_vec3(const ani_vec3 &a, const ani_vec3 &b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

} // namespace

TEST_CASE("isolated child: what the work returns comes back whole, however large") {
    const std::string big(10u << 20, 'x');
    const auto child = run_in_isolated_child([&] { return big + "end"; }, quick_limits());
    REQUIRE(child.end == ChildEnd::replied);
    CHECK(child.reply.size() == big.size() + 3);
    CHECK(child.reply.compare(big.size(), 3, "end") == 0);
}

TEST_CASE("isolated child: no file, socket or process can be opened, and no limit raised") {
    const auto child = run_in_isolated_child(
        [] {
            std::string report;
            report += "open " + outcome_of(open("/etc/hostname", O_RDONLY)) + "\n";
            report += "create " + outcome_of(open("/tmp/animator-isolation-probe", O_WRONLY | O_CREAT, 0600)) + "\n";
            report += "socket " + outcome_of(socket(AF_UNIX, SOCK_STREAM, 0)) + "\n";
            report += "fork " + outcome_of(fork()) + "\n";
            const rlimit unlimited{RLIM_INFINITY, RLIM_INFINITY};
            report += "setrlimit " + outcome_of(setrlimit(RLIMIT_CPU, &unlimited)) + "\n";
            report += "kill " + outcome_of(kill(getppid(), 0)) + "\n";
            return report;
        },
        quick_limits());
    REQUIRE(child.end == ChildEnd::replied);
    CAPTURE(child.reply);
    for (const char *call : {"open", "create", "socket", "fork", "setrlimit", "kill"})
        CHECK_THAT(child.reply, Catch::Contains(std::string(call) + " refused"));
    CHECK(access("/tmp/animator-isolation-probe", F_OK) != 0);
}

TEST_CASE("isolated child: descriptors the caller had open are closed in the child") {
    int fds[2];
    REQUIRE(pipe(fds) == 0); // inherited across fork, not close-on-exec
    const auto child = run_in_isolated_child(
        [&] { return outcome_of(write(fds[1], "escaped", 7)); }, quick_limits());
    close(fds[1]);
    char buffer[16];
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    close(fds[0]);
    REQUIRE(child.end == ChildEnd::replied);
    CHECK_THAT(child.reply, Catch::StartsWith("refused"));
    CHECK(n == 0); // nothing came through, and the pipe's last writer is gone
}

TEST_CASE("isolated child: endless computing is stopped by its processor time") {
    const auto child = run_in_isolated_child(
        [] {
            volatile unsigned long spin = 0;
            for (;;) spin = spin + 1;
            return std::string();
        },
        quick_limits());
    CHECK(child.end == ChildEnd::out_of_time);
    CHECK(child.detail == "used up its 1 s of processor time");
    CHECK(child.reply.empty());
}

TEST_CASE("isolated child: a child that waits forever is killed at the wall-time limit") {
    ChildLimits limits = quick_limits();
    limits.wall_seconds = 2;
    const auto child = run_in_isolated_child(
        [] {
            int word = 0;
            for (;;) syscall(SYS_futex, &word, FUTEX_WAIT, 0, nullptr, nullptr, 0); // uses no processor time
            return std::string();
        },
        limits);
    CHECK(child.end == ChildEnd::out_of_time);
    CHECK(child.detail == "did not finish within 2 s");
}

TEST_CASE("isolated child: a crash is reported as one, and the caller goes on") {
    const auto child = run_in_isolated_child(
        [] {
            volatile int *nowhere = nullptr;
            *nowhere = 1;
            return std::string("unreachable");
        },
        quick_limits());
    CHECK(child.end == ChildEnd::crashed);
    CHECK_THAT(child.detail, Catch::StartsWith("died of signal") || Catch::StartsWith("exited with code"));
}

#if !defined(__SANITIZE_ADDRESS__)
TEST_CASE("isolated child: memory beyond its address-space limit is refused") {
    // Without the sanitizers (which reserve terabytes up front) the child may grow its address
    // space by extra_address_space only.
    ChildLimits limits = quick_limits();
    limits.extra_address_space = 256u << 20;
    const auto child = run_in_isolated_child(
        [] {
            void *block = std::malloc(size_t(1) << 30);
            const bool got = block != nullptr;
            std::free(block);
            return std::string(got ? "allocated" : "refused");
        },
        limits);
    REQUIRE(child.end == ChildEnd::replied);
    CHECK(child.reply == "refused");
}
#endif

TEST_CASE("scene wire: a scene survives encoding and decoding exactly") {
    const SceneResult s = sample_scene();
    SceneResult back;
    std::string error;
    REQUIRE(decode_reply(encode_result(s), "x.lua", back, error));
    CHECK(back.max_time_ms == s.max_time_ms);
    CHECK(back.gravity == s.gravity);
    CHECK(back.down_axis == s.down_axis);
    CHECK(back.cel_shading == s.cel_shading);
    CHECK(back.skybox == s.skybox);
    CHECK(back.backend == s.backend);
    CHECK(back.interpolation == s.interpolation);
    CHECK(same_vec3(back.camera.position, s.camera.position));
    CHECK(back.camera.rotation.w == 0.5);
    CHECK(back.camera.fov_degrees == 33.0);
    CHECK(back.warnings == s.warnings);
    REQUIRE(back.models.size() == s.models.size());
    for (size_t i = 0; i < s.models.size(); ++i) {
        const SceneModel &a = s.models[i], &b = back.models[i];
        CHECK(b.name == a.name);
        CHECK(b.mesh == a.mesh);
        CHECK(b.line == a.line);
        CHECK(b.parent == a.parent);
        CHECK(same_vec3(b.kd, a.kd));
        CHECK(b.shininess == a.shininess);
        CHECK(b.texture == a.texture);
        CHECK(b.tint == a.tint);
        CHECK(b.dynamics == a.dynamics);
        CHECK(b.mass == a.mass);
        CHECK(same_vec3(b.initial_velocity, a.initial_velocity));
        CHECK(b.restitution == a.restitution);
        CHECK(b.friction == a.friction);
        CHECK(b.rotates == a.rotates);
        CHECK(same_vec3(b.angular_velocity, a.angular_velocity));
        CHECK(b.moving_sound == a.moving_sound);
        CHECK(same_vec3(b.state.center, a.state.center));
        CHECK(same_vec3(b.state.scale, a.state.scale));
    }

    REQUIRE_FALSE(decode_reply(encode_error("x.lua:3: boom"), "x.lua", back, error));
    CHECK(error == "x.lua:3: boom");
    // Found by the scene wire fuzzer: an error reply without a message left the user a blank error.
    REQUIRE_FALSE(decode_reply(encode_error(""), "x.lua", back, error));
    CHECK(error == "x.lua: the scene reader's reply is malformed (an error without a message)");
}

TEST_CASE("scene wire: every truncation and random corruption of a reply is an error, not a crash") {
    const std::string good = encode_result(sample_scene());
    SceneResult out;
    std::string error;
    for (size_t n = 0; n < good.size(); ++n) {
        CAPTURE(n);
        REQUIRE_FALSE(decode_reply(good.substr(0, n), "x.lua", out, error));
        REQUIRE_THAT(error, Catch::StartsWith("x.lua: the scene reader's reply is malformed ("));
    }
    REQUIRE_FALSE(decode_reply(good + "!", "x.lua", out, error));
    CHECK_THAT(error, Catch::Contains("bytes after the scene"));

    std::mt19937 rng(15);
    int decoded = 0;
    for (int round = 0; round < 20000; ++round) {
        std::string bad = good;
        for (int flips = 1 + round % 4; flips > 0; --flips)
            bad[rng() % bad.size()] = static_cast<char>(rng());
        if (decode_reply(bad, "x.lua", out, error)) ++decoded; // a flipped number is still a number
        else CHECK_THAT(error, Catch::StartsWith("x.lua:"));
    }
    CHECK(decoded < 20000);
}

TEST_CASE("scene wire: a count larger than the reply reserves nothing and is refused") {
    std::string bytes = encode_result(SceneResult{});
    // The model count is the last 8 bytes of a scene without models: claim 2^60 of them.
    const uint64_t lie = uint64_t(1) << 60;
    bytes.replace(bytes.size() - 8, 8, reinterpret_cast<const char *>(&lie), 8);
    SceneResult out;
    std::string error;
    REQUIRE_FALSE(decode_reply(bytes, "x.lua", out, error));
    CHECK_THAT(error, Catch::Contains("a count larger than the reply"));
}
