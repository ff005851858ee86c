// The .ani format plugin through the host's document I/O: round trips, strict errors with file
// and line, version refusal, and atomic saving.
#include "io/document_io.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <csignal>
#include <random>
#include <sys/resource.h>

using namespace animator;
namespace fs = std::filesystem;

namespace {

PluginRegistry &registry() {
    static PluginRegistry r({test::bin_dir()}, {});
    return r;
}

std::vector<fs::path> temp_files_in(const fs::path &dir) {
    std::vector<fs::path> out;
    for (const auto &e : fs::directory_iterator(dir))
        if (e.path().filename().string().find(".tmp-") != std::string::npos) out.push_back(e.path());
    return out;
}

const char *kValidHeader = "animator-ani 1\n";

} // namespace

TEST_CASE("read(write(doc)) == doc over documents with many models and keyframes") {
    std::mt19937 rng(42);
    const fs::path dir = test::fresh_dir("ani_round_trip");
    for (auto [models, keyframes] : {std::pair{0, 1}, {1, 1}, {3, 10}, {12, 60}, {40, 200}}) {
        CAPTURE(models, keyframes);
        const Document doc = test::random_document(rng, models, keyframes);
        const fs::path path = dir / ("doc" + std::to_string(models) + ".ani");
        save_document(registry(), doc, path);
        // Version 2 only where its keys are used (random_document uses them from 3 models on).
        CHECK(test::read_file(path).rfind(models >= 3 ? "animator-ani 2\n" : kValidHeader, 0) == 0);
        const OpenedDocument opened = open_document(registry(), path);
        CHECK(opened.format_id == "format.ani");
        CHECK(opened.document == doc);
        // Writing what was read gives the same bytes: the format has one spelling of a document.
        const fs::path again = dir / "again.ani";
        save_document(registry(), opened.document, again);
        CHECK(test::read_file(again) == test::read_file(path));
    }
}

TEST_CASE("every example animation loads and round trips") {
    const fs::path dir = test::fresh_dir("ani_examples");
    int count = 0;
    for (const auto &entry : fs::directory_iterator(test::source_dir() / "assets" / "animations")) {
        if (entry.path().extension() != ".ani") continue;
        CAPTURE(entry.path());
        const Document doc = open_document(registry(), entry.path()).document;
        CHECK(doc.keyframes().front().time_ms == 0);
        const fs::path copy = dir / entry.path().filename();
        save_document(registry(), doc, copy);
        CHECK(open_document(registry(), copy).document == doc);
        ++count;
    }
    CHECK(count >= 1);
}

TEST_CASE("malformed .ani files fail with the file, the line and what was expected") {
    const fs::path dir = test::fresh_dir("ani_bad");
    const std::string model = "model \"ball\"\n  mesh \"sphere\"\nend\n";
    const std::string key0 = "keyframe 0\n  camera position 0 0 0 rotation 1 0 0 0 fov 50\n"
                             "  state \"ball\" center 0 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0\nend\n";
    struct Case {
        const char *name;
        std::string text;
        const char *expected;
    };
    const std::vector<Case> cases = {
        {"empty", "", ":1: the file is empty"},
        {"no_magic", "hello 1\n", ":1: expected 'animator-ani'"},
        {"newer_version", "animator-ani 3\n", ":1: format version 3 was written by a newer animator"},
        {"version_word", "animator-ani one\n", ":1: expected a whole number for the format version"},
        {"unknown_block", std::string(kValidHeader) + "models\n", ":2: expected 'settings', 'model' or 'keyframe'"},
        {"unknown_setting", std::string(kValidHeader) + "settings\n  speed 3\nend\n", ":3: unknown settings key 'speed'"},
        {"max_time_low", std::string(kValidHeader) + "settings\n  max_time_ms 10\nend\n", ":3: expected max_time_ms between 1000"},
        {"gravity_nan", std::string(kValidHeader) + "settings\n  gravity nan\nend\n", ":3: expected a finite number for gravity"},
        {"down_w", std::string(kValidHeader) + "settings\n  down w\nend\n", ":3: expected x, y or z"},
        {"bool_yes", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  dynamics yes\nend\n", ":4: expected true or false for dynamics"},
        {"mass_zero", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  mass 0\nend\n", ":4: expected mass > 0"},
        {"mass_word", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  mass heavy\nend\n", ":4: expected a number for mass, got 'heavy'"},
        {"restitution_high", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  restitution 1.5\nend\n", ":4: expected restitution in [0, 1], got '1.5'"},
        {"restitution_nan", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  restitution nan\nend\n", ":4: expected a finite number for restitution"},
        {"friction_negative", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  friction -0.1\nend\n", ":4: expected friction >= 0, got '-0.1'"},
        {"friction_inf", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  friction inf\nend\n", ":4: expected a finite number for friction"},
        {"rotates_yes", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  rotates yes\nend\n", ":4: expected true or false for rotates"},
        {"angular_two", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  angular_velocity 1 2\nend\n", ":4: expected three numbers after 'angular_velocity'"},
        {"angular_word", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  angular_velocity 1 fast 3\nend\n", ":4: expected a number for angular_velocity, got 'fast'"},
        {"no_mesh", std::string(kValidHeader) + "model \"b\"\n  mass 2\nend\n", ":2: model \"b\" has no 'mesh'"},
        {"unclosed_string", std::string(kValidHeader) + "model \"b\n", ":2: a string is not closed"},
        {"duplicate_model", std::string(kValidHeader) + model + model, ":5: a model named \"ball\" already exists"},
        {"duplicate_key", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  mesh \"t\"\nend\n", ":4: 'mesh' is given twice"},
        {"kd_range", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  kd 1 -2 0\nend\n", ":4: expected kd components >= 0"},
        {"light_words", std::string(kValidHeader) + "settings\n  light \"l\" at 0 0 0 colour 1 1 1 falloff 1 0 0\nend\n", ":3: expected 'position', got 'at'"},
        {"light_falloff", std::string(kValidHeader) + "settings\n  light \"l\" position 0 0 0 colour 1 1 1 falloff 0 0 0\nend\n", ":3: expected a falloff that is not all 0"},
        {"render_size", std::string(kValidHeader) + "settings\n  render \"a.png\" -1 10\nend\n", ":3: expected a render size of 0"},
        {"rest_mirror", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  rest -1 0 0 0 1 0 0 0 1\nend\n", ":4: expected a rest shape with determinant > 0"},
        {"joint_order", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  joint x 10 -10 y 0 0 z 0 0\nend\n", ":4: expected each joint range as MIN MAX with MIN <= MAX"},
        {"missing_number", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n  velocity 1 2\nend\n", ":4: expected three numbers after 'velocity'"},
        {"no_keyframe", std::string(kValidHeader) + model, ":5: the file ends without a 'keyframe 0' block"},
        {"first_not_zero", std::string(kValidHeader) + "keyframe 5\nend\n", ":2: expected the first keyframe at 0 ms"},
        {"missing_state", std::string(kValidHeader) + model + "keyframe 0\n  camera position 0 0 0 rotation 1 0 0 0 fov 50\nend\n", ":5: keyframe 0 has no state for model \"ball\""},
        {"angle_360", std::string(kValidHeader) + model + "keyframe 0\n  camera position 0 0 0 rotation 1 0 0 0 fov 50\n  state \"ball\" center 0 0 0 angles 360 0 0 scale 1 1 1 turn 0 0 0\nend\n", ":7: expected angles in [0, 360)"},
        {"unknown_model", std::string(kValidHeader) + model + "keyframe 0\n  camera position 0 0 0 rotation 1 0 0 0 fov 50\n  state \"bal\" center 0 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0\nend\n", ":7: no model named \"bal\""},
        {"keyframe_order", std::string(kValidHeader) + model + key0 + "keyframe 0\nend\n", ":9: expected keyframe times to increase"},
        {"quaternion", std::string(kValidHeader) + "keyframe 0\n  camera position 0 0 0 rotation 2 0 0 0 fov 50\nend\n", ":3: expected a unit quaternion"},
        {"past_max_time", std::string(kValidHeader) + "settings\n  max_time_ms 1000\nend\n" + model + key0 + "keyframe 2000\nend\n", ":12: keyframe 2000 ms is past the max time"},
        {"unterminated_block", std::string(kValidHeader) + "model \"b\"\n  mesh \"s\"\n", ":3: the file ends inside model \"b\""},
    };
    for (const Case &c : cases) {
        CAPTURE(c.name);
        const fs::path path = dir / (std::string(c.name) + ".ani");
        test::write_file(path, c.text);
        try {
            open_document(registry(), path);
            FAIL("no error for " << c.name);
        } catch (const DocumentIoError &e) {
            const std::string message = e.what();
            CHECK_THAT(message, Catch::StartsWith(path.string()));
            CHECK_THAT(message, Catch::Contains(c.expected));
        }
    }
}

TEST_CASE("a file no plugin reads is named in the error") {
    const fs::path dir = test::fresh_dir("ani_unknown");
    test::write_file(dir / "notes.txt", "just some text\n");
    CHECK_THROWS_WITH(open_document(registry(), dir / "notes.txt"),
                      Catch::Contains("notes.txt") && Catch::Contains("no file-format plugin reads"));
    CHECK_THROWS_WITH(open_document(registry(), dir / "missing.ani"),
                      Catch::Contains("missing.ani: cannot open"));
    CHECK_THROWS_WITH(save_document(registry(), Document{}, dir / "out.xyz"),
                      Catch::Contains("no file-format plugin writes '.xyz'"));
}

TEST_CASE("a save that fails midway leaves the previous file intact") {
    const fs::path dir = test::fresh_dir("ani_atomic");
    const fs::path path = dir / "work.ani";
    std::mt19937 rng(7);
    const Document small = test::random_document(rng, 1, 1);
    save_document(registry(), small, path);
    const std::string before = test::read_file(path);

    // A full disk, as far as this process can tell: writes past 4 KiB fail with EFBIG.
    const Document big = test::random_document(rng, 20, 100);
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit old{};
    getrlimit(RLIMIT_FSIZE, &old);
    rlimit tiny = old;
    tiny.rlim_cur = 4096;
    setrlimit(RLIMIT_FSIZE, &tiny);
    std::string error;
    try {
        save_document(registry(), big, path);
    } catch (const DocumentIoError &e) {
        error = e.what();
    }
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, SIG_DFL);

    CHECK_THAT(error, Catch::Contains("work.ani") && Catch::Contains("previous file is unchanged"));
    CHECK(test::read_file(path) == before);
    CHECK(temp_files_in(dir).empty());
    CHECK(open_document(registry(), path).document == small);
}

TEST_CASE("a save that cannot replace the target says why and leaves no temporary file") {
    const fs::path dir = test::fresh_dir("ani_atomic_dir");
    fs::create_directories(dir / "taken.ani" / "inside");
    CHECK_THROWS_WITH(save_document(registry(), Document{}, dir / "taken.ani"),
                      Catch::Contains("cannot replace the file"));
    CHECK(fs::is_directory(dir / "taken.ani" / "inside"));
    CHECK(temp_files_in(dir).empty());
    CHECK_THROWS_WITH(save_document(registry(), Document{}, dir / "no" / "such" / "folder.ani"),
                      Catch::Contains("cannot create a temporary file"));
}

TEST_CASE("a line longer than 1 MiB is refused at its number, however harmless its words") {
    // A comment of 2 MiB in an otherwise valid file: the reader stops once it has read 1 MiB of
    // it instead of holding a hostile file's single line (of any length) in memory.
    const fs::path path = test::fresh_dir("ani_long_line") / "long.ani";
    test::write_file(path, std::string(kValidHeader) + "# a note\n#" + std::string(2u << 20, 'x') +
                               "\nkeyframe 0\n  camera position 0 0 0 rotation 1 0 0 0 fov 50\nend\n");
    CHECK_THROWS_WITH(open_document(registry(), path),
                      Catch::StartsWith(path.string() + ":3: the line is longer than 1048576 bytes"));
}

TEST_CASE("models x keyframes past 2^20 model states is refused at the keyframe that crosses it") {
    // Every keyframe holds a state for every model, so a file of a few MB naming 1024 models and
    // thousands of keyframes would need gigabytes: 1024 x 1024 states is the most a file holds.
    const int models = 1024;
    std::string text = kValidHeader;
    for (int m = 0; m < models; ++m) text += "model \"m" + std::to_string(m) + "\"\n  mesh \"\"\nend\n";
    text += "keyframe 0\n  camera position 0 0 0 rotation 1 0 0 0 fov 50\n";
    for (int m = 0; m < models; ++m)
        text += "  state \"m" + std::to_string(m) + "\" center 0 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0\n";
    text += "end\n";
    for (int k = 1; k < 1024; ++k) text += "keyframe " + std::to_string(k) + "\nend\n";
    // Lines so far: 1 header, 3 per model, keyframe 0's 3 + models, 2 per later keyframe.
    const int crossing_line = 1 + 3 * models + (3 + models) + 2 * 1023 + 1;
    text += "keyframe 1024\nend\n";
    const fs::path path = test::fresh_dir("ani_too_many_states") / "many.ani";
    test::write_file(path, text);
    CHECK_THROWS_WITH(open_document(registry(), path),
                      Catch::StartsWith(path.string() + ":" + std::to_string(crossing_line) +
                                        ": the document grows past its limits here: 1024 models "
                                        "and 1025 keyframes"));
}

TEST_CASE("a document with a line the reader would refuse is not saved") {
    const fs::path dir = test::fresh_dir("ani_save_long_name");
    std::mt19937 rng(11);
    Document doc = test::random_document(rng, 1, 1);
    Model named = doc.models()[0];
    named.name = std::string((1u << 20) + 1, 'n');
    doc.set_model(0, named);
    CHECK_THROWS_WITH(save_document(registry(), doc, dir / "long.ani"),
                      Catch::Contains("long.ani") &&
                          Catch::Contains("would be longer than the 1048576 bytes a reader takes"));
    CHECK_FALSE(fs::exists(dir / "long.ani"));
    CHECK(temp_files_in(dir).empty());
}

TEST_CASE("a model's rigid-body keys: absent (older files) read as the defaults, given read exactly") {
    const fs::path dir = test::fresh_dir("ani_body");
    const std::string key0 = "keyframe 0\n  camera position 0 0 0 rotation 1 0 0 0 fov 50\n"
                             "  state \"old\" center 0 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0\n"
                             "  state \"new\" center 0 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0\nend\n";
    const fs::path path = dir / "body.ani";
    test::write_file(path, std::string(kValidHeader) + "model \"old\"\n  mesh \"sphere\"\n  dynamics true\nend\n" +
                               "model \"new\"\n  mesh \"sphere\"\n  restitution 0.25\n  friction 1.5\n"
                               "  rotates true\n  angular_velocity 0 -2.5 6.28\nend\n" + key0);
    const Document doc = open_document(registry(), path).document;
    REQUIRE(doc.models().size() == 2);
    const Model &old = doc.models()[0], &now = doc.models()[1];
    CHECK(old.restitution == 1.0); // the seed's elastic, frictionless world, turned by keys only
    CHECK(old.friction == 0.0);
    CHECK_FALSE(old.rotates);
    CHECK(old.angular_velocity == glm::dvec3(0.0));
    CHECK(now.restitution == 0.25);
    CHECK(now.friction == 1.5);
    CHECK(now.rotates);
    CHECK(now.angular_velocity == glm::dvec3(0.0, -2.5, 6.28));
    // The writer writes every key, the defaults too.
    const fs::path again = dir / "again.ani";
    save_document(registry(), doc, again);
    const std::string text = test::read_file(again);
    CHECK_THAT(text, Catch::Contains("model \"old\"\n") && Catch::Contains("  restitution 1\n  friction 0\n"
                                                                           "  rotates false\n  angular_velocity 0 0 0\n"));
    CHECK_THAT(text, Catch::Contains("  restitution 0.25\n  friction 1.5\n  rotates true\n  angular_velocity 0 -2.5 6.28\n"));
}

TEST_CASE("lights, ambient, render output, rest shapes and joint ranges round trip, only then is the file version 2") {
    const fs::path dir = test::fresh_dir("ani_scene_keys");
    Document doc;
    Model m;
    m.name = "arm";
    m.mesh = "cube";
    m.material.kd = {1.5, 0.25, 0.0}; // above 1: the course allowed it
    m.rest = glm::dmat3(1.0);
    m.rest[1][0] = 0.75; // x += 0.75 y: a shear
    m.rest[2][1] = -0.125;
    m.joint = JointRange{{-90.0, 0.0, 0.0}, {45.5, 0.0, 10.0}};
    doc.add_model(m, ModelState{});
    const fs::path plain = dir / "plain.ani";
    save_document(registry(), Document(), plain);
    CHECK(test::read_file(plain).rfind("animator-ani 1\n", 0) == 0); // older readers still take it

    Settings s = doc.settings();
    s.lights = {Light{"key", {1.0, 2.0, 3.0}, {0.9, 0.8, 0.7}, {1.0, 0.0, 0.25}},
                Light{"fill", {-4.0, 0.5, 1e-3}, {0.2, 0.2, 1.25}, {0.5, 0.125, 0.0}}};
    s.ambient = {0.3, 0.1, 0.05};
    s.render_output = "still.png";
    s.render_width = 640;
    s.render_height = 480;
    doc.set_settings(s);
    const fs::path path = dir / "scene.ani";
    save_document(registry(), doc, path);
    const std::string text = test::read_file(path);
    CHECK(text.rfind("animator-ani 2\n", 0) == 0);
    CHECK_THAT(text, Catch::Contains("  light \"key\" position 1 2 3 colour 0.9 0.8 0.7 falloff 1 0 0.25\n"));
    CHECK_THAT(text, Catch::Contains("  render \"still.png\" 640 480\n"));
    CHECK_THAT(text, Catch::Contains("  rest 1 0.75 0 0 1 -0.125 0 0 1\n")); // row by row
    CHECK_THAT(text, Catch::Contains("  joint x -90 45.5 y 0 0 z 0 10\n"));
    const Document read = open_document(registry(), path).document;
    CHECK(read == doc);
    CHECK(read.models()[0].rest[1][0] == 0.75);
    CHECK(read.settings().lights[1].falloff == glm::dvec3(0.5, 0.125, 0.0));
}
