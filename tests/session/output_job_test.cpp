// The editor's Render and Export jobs without a window (editor/output_job.hpp): the real
// `animator` run as a child on a snapshot of a document whose mesh sits beside it, its progress
// read line by line, the frames it writes counted against the formula, a cancel that stops it
// early and leaves no zombie, and a bad output folder reported in the child's own words.
#include "editor/output_job.hpp"

#include "io/document_io.hpp"
#include "io/environment.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <thread>

using namespace animator;
using namespace animator::test;

namespace fs = std::filesystem;

namespace {

// A ball whose mesh is a file beside the animation (found only from there), falling for
// `seconds`.
std::string ball_ani(int max_ms) {
    return "animator-ani 1\nsettings\n  max_time_ms " + std::to_string(max_ms) +
           "\n  gravity 9.81\n  down y\n  cel_shading false\n  skybox \"\"\n  physics_backend "
           "\"physics.custom\"\nend\n\n"
           "model \"ball\"\n  mesh \"my_ball.obj\"\n  kd 0.9 0.2 0.1\n  ks 0.5 0.5 0.5\n  "
           "shininess 40\n"
           "  dynamics true\n  gravity true\n  mass 1\nend\n\n"
           "keyframe 0\n  camera position 0 0 12 rotation 1 0 0 0 fov 50\n"
           "  state \"ball\" center 0 2 0 angles 0 0 0 scale 1 1 1 turn 0 0 0\nend\n";
}

fs::path write_ball(const fs::path &dir, int max_ms) {
    fs::copy_file(source_dir() / "tests" / "data" / "assets" / "meshes" / "ball.obj",
                  dir / "my_ball.obj");
    write_file(dir / "ball.ani", ball_ani(max_ms));
    return dir / "ball.ani";
}

int count_pngs(const fs::path &dir) {
    int n = 0;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
        n += it->path().extension() == ".png";
    return n;
}

// Polls as the editor does each frame, until the job ends (or a hang's outer limit).
void run_to_end(OutputJob &job, double limit_seconds = 300.0) {
    const auto until =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_seconds);
    while (job.poll() && std::chrono::steady_clock::now() < until)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    REQUIRE_FALSE(job.running());
}

fs::path animator_exe() {
    return bin_dir() / "animator";
}

} // namespace

TEST_CASE("render_frame_count is one frame at from, then one every 1/fps up to to") {
    CHECK(render_frame_count(0.0, 1.0, 10.0) == 11);
    CHECK(render_frame_count(0.0, 2.0, 30.0) == 61);
    CHECK(render_frame_count(0.5, 1.0, 4.0) == 3);
    CHECK(render_frame_count(0.0, 0.0, 30.0) == 1);
    CHECK(render_frame_count(0.0, 0.999, 1.0) == 1);
}

TEST_CASE("parse_frame_progress reads only 'frame K of N' lines") {
    int k = -1, n = -1;
    CHECK(parse_frame_progress("frame 12 of 150", k, n));
    CHECK(k == 12);
    CHECK(n == 150);
    CHECK_FALSE(parse_frame_progress("frame 12 of 150 extra", k, n));
    CHECK_FALSE(parse_frame_progress("wrote 3 frames", k, n));
    CHECK_FALSE(parse_frame_progress("frame 9 of 3", k, n));
    CHECK(k == 12);
}

TEST_CASE("a snapshot names a mesh beside the document by its absolute path, and keeps asset ids") {
    Environment env;
    const fs::path dir = fresh_dir("output_job_snapshot");
    const fs::path file = write_ball(dir, 2000);
    Document doc = open_document(env.plugins, file).document;
    Model floor = doc.models()[0];
    floor.name = "floor";
    floor.mesh = "plane"; // from the asset folders
    doc.add_model(floor, ModelState{});
    const Document snap = snapshot_document(doc, env.assets, file);
    CHECK(snap.models()[0].mesh == fs::absolute(dir / "my_ball.obj").lexically_normal().string());
    CHECK(snap.models()[1].mesh == "plane");
    CHECK(doc.models()[0].mesh == "my_ball.obj"); // the document itself is untouched

    // The snapshot reads back from its private folder, far from the mesh.
    fs::path folder;
    {
        JobSnapshot s(env.plugins, env.assets, doc, file);
        folder = s.file().parent_path();
        CHECK(s.file().filename() == "ball.ani");
        CHECK(folder != dir);
        const Document back = open_document(env.plugins, s.file()).document;
        CHECK(back.models().size() == 2);
        CHECK(back.models()[0].mesh == snap.models()[0].mesh);
    }
    CHECK_FALSE(fs::exists(folder)); // removed with the snapshot
}

TEST_CASE("a render job writes the frames it counts, with an unsaved document's mesh found") {
    Environment env;
    const fs::path dir = fresh_dir("output_job_render");
    const fs::path file = write_ball(dir, 2000);
    const Document doc = open_document(env.plugins, file).document;
    JobSnapshot snapshot(env.plugins, env.assets, doc, file);

    RenderRequest r;
    r.out = dir / "frames";
    r.width = 64;
    r.height = 48;
    r.fps = 10.0;
    r.from = 0.0;
    r.to = 1.0;
    OutputJob job;
    std::string error;
    REQUIRE(job.start(animator_exe(), render_arguments(r, snapshot.file()), &error));
    CHECK(job.running());
    run_to_end(job);
    INFO(job.error_text());
    CHECK(job.state() == OutputJob::State::Succeeded);
    CHECK(job.frames_total() == 11); // (1 - 0) s at 10 fps, and the frame at 0
    CHECK(job.frames_done() == 11);
    CHECK(count_pngs(r.out) == 11);
    CHECK(fs::exists(r.out / "frame_00010.png"));
    REQUIRE_FALSE(job.said().empty());
    CHECK(job.said().back().rfind("wrote 11 frames of 64x48", 0) == 0);
}

TEST_CASE("a cancelled render stops early, leaves its frames and no zombie") {
    Environment env;
    const fs::path dir = fresh_dir("output_job_cancel");
    const fs::path file = write_ball(dir, 20000);
    const Document doc = open_document(env.plugins, file).document;
    JobSnapshot snapshot(env.plugins, env.assets, doc, file);
    RenderRequest r;
    r.out = dir / "frames";
    r.width = 320;
    r.height = 240;
    r.to = 20.0;
    OutputJob job;
    REQUIRE(job.start(animator_exe(), render_arguments(r, snapshot.file())));
    const auto limit = std::chrono::steady_clock::now() + std::chrono::seconds(300);
    // "frame K of N" says a frame is drawn; its PNG is written behind it, later on a busy
    // machine: cancel once one is on disk.
    while (job.poll() && (job.frames_done() < 3 || count_pngs(r.out) == 0) &&
           std::chrono::steady_clock::now() < limit)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    REQUIRE(job.running());
    const pid_t pid = job.pid();
    job.cancel();
    CHECK(job.state() == OutputJob::State::Cancelled);
    CHECK_FALSE(job.running());
    CHECK(job.frames_total() == 601);
    // Reaped: no child of this process by that id remains, not even a zombie.
    errno = 0;
    CHECK(waitpid(pid, nullptr, WNOHANG) == -1);
    CHECK(errno == ECHILD);
    CHECK(kill(pid, 0) == -1);
    const int written = count_pngs(r.out);
    CHECK(written >= 1);
    CHECK(written < 601);
}

TEST_CASE("a render into a folder that cannot be made fails with the child's message") {
    Environment env;
    const fs::path dir = fresh_dir("output_job_bad_out");
    const fs::path file = write_ball(dir, 2000);
    const Document doc = open_document(env.plugins, file).document;
    JobSnapshot snapshot(env.plugins, env.assets, doc, file);
    write_file(dir / "not_a_folder", "x");
    RenderRequest r;
    r.out = dir / "not_a_folder" / "frames";
    r.width = 32;
    r.height = 32;
    r.to = 0.1;
    OutputJob job;
    REQUIRE(job.start(animator_exe(), render_arguments(r, snapshot.file())));
    run_to_end(job);
    CHECK(job.state() == OutputJob::State::Failed);
    CHECK(job.exit_code() == 1);
    const std::string text = job.error_text();
    INFO(text);
    CHECK(text.find("animator: ") != std::string::npos);
    CHECK(text.find((dir / "not_a_folder").string()) != std::string::npos);
    CHECK(count_pngs(r.out) == 0);
}

TEST_CASE("an export's trace has the unsaved edits, as `animator bake --trace` of them saved") {
    Environment env;
    const fs::path dir = fresh_dir("output_job_trace");
    const fs::path file = write_ball(dir, 2000);
    Document doc = open_document(env.plugins, file).document;
    // An unsaved edit: the animation shortened to 1 s. The snapshot has it; the file does not.
    Settings settings = doc.settings();
    settings.max_time_ms = 1000;
    doc.set_settings(settings);
    save_document(env.plugins, doc, dir / "edited.ani");
    JobSnapshot snapshot(env.plugins, env.assets, doc, file);
    OutputJob job;
    REQUIRE(job.start(animator_exe(), trace_arguments(dir / "editor.csv", snapshot.file())));
    run_to_end(job);
    INFO(job.error_text());
    REQUIRE(job.state() == OutputJob::State::Succeeded);
    const auto cli = run_animator("bake " + (dir / "edited.ani").string() + " --trace " +
                                  (dir / "cli.csv").string());
    REQUIRE(cli.exit_code == 0);
    const std::string ours = read_file(dir / "editor.csv"), theirs = read_file(dir / "cli.csv");
    CHECK(ours.rfind("t,model,x,y,z", 0) == 0);
    CHECK(std::count(ours.begin(), ours.end(), '\n') == 62); // a header, and t = 0 .. 1 s at 1/60 s
    CHECK(ours == theirs);
}

TEST_CASE("a program that cannot start is said at once") {
    OutputJob job;
    std::string error;
    CHECK_FALSE(job.start("/nonexistent/animator", {"render"}, &error));
    CHECK(error.find("/nonexistent/animator") != std::string::npos);
    CHECK(job.state() == OutputJob::State::Idle);
}

TEST_CASE("a render job with a video has ffmpeg put the frames together") {
    if (!find_ffmpeg()) {
        WARN(
            "ffmpeg is not installed: the video render is not tested (the editor greys Video out)");
        return;
    }
    Environment env;
    const fs::path dir = fresh_dir("output_job_video");
    const fs::path file = write_ball(dir, 2000);
    const Document doc = open_document(env.plugins, file).document;
    JobSnapshot snapshot(env.plugins, env.assets, doc, file);
    RenderRequest r;
    r.out = dir / "frames";
    r.video = dir / "ball.mp4";
    r.width = 64;
    r.height = 48;
    r.fps = 10.0;
    r.to = 1.0;
    OutputJob job;
    REQUIRE(job.start(animator_exe(), render_arguments(r, snapshot.file())));
    run_to_end(job);
    INFO(job.error_text());
    REQUIRE(job.state() == OutputJob::State::Succeeded);
    CHECK(count_pngs(r.out) == 11);
    REQUIRE(fs::exists(r.video));
    // ffprobe (installed with ffmpeg) decodes it: 11 frames, as many as the PNGs.
    const fs::path frames = dir / "frames.txt";
    const std::string probe =
        "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames "
        "-of csv=p=0 " +
        r.video.string() + " > " + frames.string();
    REQUIRE(std::system(probe.c_str()) == 0);
    CHECK(read_file(frames).substr(0, 3) == "11\n");
}

TEST_CASE("a job that goes away while its render runs stops it (the editor closing)") {
    Environment env;
    const fs::path dir = fresh_dir("output_job_closed");
    const fs::path file = write_ball(dir, 20000);
    const Document doc = open_document(env.plugins, file).document;
    JobSnapshot snapshot(env.plugins, env.assets, doc, file);
    RenderRequest r;
    r.out = dir / "frames";
    r.width = 320;
    r.height = 240;
    r.to = 20.0;
    pid_t pid = -1;
    {
        OutputJob job;
        REQUIRE(job.start(animator_exe(), render_arguments(r, snapshot.file())));
        const auto limit = std::chrono::steady_clock::now() + std::chrono::seconds(300);
        while (job.poll() && job.frames_done() < 2 && std::chrono::steady_clock::now() < limit)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        REQUIRE(job.running());
        pid = job.pid();
    }
    errno = 0;
    CHECK(waitpid(pid, nullptr, WNOHANG) == -1);
    CHECK(errno == ECHILD);
    const int written = count_pngs(r.out);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    CHECK(count_pngs(r.out) == written);
    CHECK(written < 601);
}
