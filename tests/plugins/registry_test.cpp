#include "plugin/descriptor_check.hpp"
#include "plugin/instance.hpp"
#include "plugin/registry.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <map>
#include <set>

using namespace animator;
namespace fs = std::filesystem;

namespace {

const fs::path example_dir = ANIMATOR_EXAMPLE_PLUGIN_DIR;
const fs::path broken_dir = ANIMATOR_BROKEN_PLUGIN_DIR;

PluginRegistry::LogSink quiet() {
    return [](ani_log_level, const std::string &, const std::string &) {};
}

std::map<std::string, std::string> refusals_by_file(const PluginRegistry &r) {
    std::map<std::string, std::string> out;
    for (const auto &refusal : r.refusals()) out[refusal.library.filename().string()] = refusal.reason;
    return out;
}

} // namespace

TEST_CASE("every built plugin loads, with a valid descriptor and finite parameters") {
    PluginRegistry registry({test::bin_dir(), example_dir}, quiet());
    registry.load_all();
    INFO((registry.refusals().empty() ? "" : registry.refusals()[0].reason));
    CHECK(registry.refusals().empty());
    std::map<std::string, const PluginInfo *> by_id;
    for (const PluginInfo *p : registry.loaded()) by_id[p->id] = p;
    REQUIRE(by_id.count("format.ani"));
    REQUIRE(by_id.count("interpolator.step"));
    CHECK(by_id["format.ani"]->kind == ANI_KIND_FILE_FORMAT);
    CHECK(by_id["interpolator.step"]->kind == ANI_KIND_INTERPOLATOR);
    for (const PluginInfo *p : registry.loaded()) {
        CAPTURE(p->id);
        CHECK(check_plugin_descriptor(*p->descriptor).empty());
        for (uint32_t i = 0; i < p->descriptor->param_count; ++i) {
            const ani_param_descriptor &param = p->descriptor->params[i];
            CHECK(std::isfinite(param.min_value));
            CHECK(std::isfinite(param.max_value));
            CHECK(param.min_value <= param.default_value.value[0]);
            CHECK(param.default_value.value[0] <= param.max_value);
        }
        // Every plugin makes an instance and gives back its parameters' defaults.
        PluginInstance instance(*p, registry.host());
        for (uint32_t i = 0; i < p->descriptor->param_count; ++i) {
            const ani_param_descriptor &param = p->descriptor->params[i];
            CHECK(instance.get_param(param.id)[0] == param.default_value.value[0]);
        }
    }
}

TEST_CASE("each kind of broken plugin is refused with its file and reason while the others work") {
    PluginRegistry registry({test::bin_dir(), broken_dir}, quiet());
    registry.load_all();
    auto refused = refusals_by_file(registry);

    CHECK_THAT(refused["animator-test-wrong-major.so"],
               Catch::Contains("ABI 2.") &&
                   Catch::Contains("this host has ABI 1." + std::to_string(ANI_ABI_MINOR)));
    CHECK_THAT(refused["animator-test-newer-minor.so"], Catch::Contains("ABI 1." + std::to_string(ANI_ABI_MINOR + 1)));
    CHECK_THAT(refused["animator-test-no-entry.so"], Catch::Contains("no entry symbol"));
    CHECK_THAT(refused["animator-test-duplicate-id.so"],
               Catch::Contains("'format.ani'") && Catch::Contains("already provided"));
    CHECK_THAT(refused["animator-test-bad-param.so"], Catch::Contains("min > max"));
    CHECK_THAT(refused["animator-test-bad-id.so"], Catch::Contains("'Bad Id!'"));
    CHECK_THAT(refused["animator-test-missing-function.so"], Catch::Contains("lacks evaluate"));
    CHECK_THAT(refused["animator-test-init-fails.so"],
               Catch::Contains("failed to initialise") && Catch::Contains("fails on purpose"));
    CHECK_THAT(refused["animator-test-bad-kind.so"], Catch::Contains("kind 42"));
    CHECK_THAT(refused["animator-test-not-a-library.so"], Catch::Contains("cannot be opened"));
    CHECK(refused.count("animator-test-valid.so") == 0);
    CHECK(refused.size() == 10);

    // The valid control and the real plugins keep working.
    CHECK(registry.find("interpolator.broken") != nullptr);
    const PluginInfo *ani = registry.find("format.ani");
    REQUIRE(ani != nullptr);
    CHECK(ani->library.filename() == "animator-io-ani.so");
}

TEST_CASE("finding a plugin by id opens only the library that provides it") {
    PluginRegistry registry({test::bin_dir(), example_dir}, quiet());
    CHECK(registry.libraries_opened().empty());
    const PluginInfo *step = registry.find("interpolator.step");
    REQUIRE(step != nullptr);
    REQUIRE(registry.libraries_opened().size() == 1);
    CHECK(registry.libraries_opened()[0].filename() == "animator-example-step.so");

    // Asking for every file format opens the format libraries (and only those) besides it.
    const auto formats = registry.find_kind(ANI_KIND_FILE_FORMAT);
    std::set<fs::path> format_libraries;
    for (const PluginInfo *p : formats) format_libraries.insert(p->library);
    CHECK(format_libraries.size() >= 2); // .ani and .lua
    CHECK(registry.libraries_opened().size() == 1 + format_libraries.size());
    CHECK(registry.refusals().empty());

    const auto opened = registry.libraries_opened().size();
    CHECK(registry.find("physics.nonexistent") == nullptr);
    CHECK(registry.libraries_opened().size() == opened);
}

TEST_CASE("a library without a manifest is opened when a plugin is not found otherwise") {
    const fs::path dir = test::fresh_dir("no_manifest");
    fs::copy_file(example_dir / "animator-example-step.so", dir / "animator-example-step.so");
    PluginRegistry registry({dir}, quiet());
    const PluginInfo *step = registry.find("interpolator.step");
    REQUIRE(step != nullptr);
    CHECK(step->library == dir / "animator-example-step.so");
}

TEST_CASE("a library whose manifest names plugins it lacks is refused") {
    const fs::path dir = test::fresh_dir("lying_manifest");
    fs::copy_file(example_dir / "animator-example-step.so", dir / "animator-example-step.so");
    test::write_file(dir / "animator-example-step.so.plugins",
                     "animator-plugin-manifest 1\ninterpolator.other interpolator\n");
    PluginRegistry registry({dir}, quiet());
    CHECK(registry.find("interpolator.other") == nullptr);
    REQUIRE(registry.refusals().size() == 1);
    CHECK_THAT(registry.refusals()[0].reason, Catch::Contains("manifest does not name"));
}

TEST_CASE("ANIMATOR_PLUGIN_PATH folders are searched after the executable's folder") {
    const std::string path = example_dir.string() + ":" + broken_dir.string();
    setenv("ANIMATOR_PLUGIN_PATH", path.c_str(), 1);
    const auto dirs = PluginRegistry::default_search_dirs();
    unsetenv("ANIMATOR_PLUGIN_PATH");
    REQUIRE(dirs.size() == 3);
    CHECK(dirs[1] == example_dir);
    CHECK(dirs[2] == broken_dir);
}

TEST_CASE("plugins log through the host services") {
    std::vector<std::string> lines;
    PluginRegistry registry({}, [&](ani_log_level level, const std::string &id, const std::string &msg) {
        lines.push_back(std::to_string(level) + " " + id + " " + msg);
    });
    const ani_host *host = registry.host();
    REQUIRE(host->struct_size == sizeof(ani_host));
    CHECK(host->abi.major == ANI_ABI_MAJOR);
    host->log(host, ANI_LOG_WARNING, "physics.test", "step too large");
    CHECK(host->get_extension(host, "no.such.extension") == nullptr);
    REQUIRE(lines.size() == 1);
    CHECK(lines[0] == "2 physics.test step too large");
}

TEST_CASE("parameter values are checked before they reach the plugin") {
    PluginRegistry registry({example_dir}, quiet());
    const PluginInfo *step = registry.find("interpolator.step");
    REQUIRE(step != nullptr);
    PluginInstance instance(*step, registry.host());
    CHECK(instance.get_param("hold")[0] == 1.0);
    instance.set_param("hold", {0.0, 0.0, 0.0, 0.0});
    CHECK(instance.get_param("hold")[0] == 0.0);
    CHECK_THROWS_WITH(instance.set_param("hold", {2.0, 0.0, 0.0, 0.0}), Catch::Contains("outside"));
    CHECK_THROWS_WITH(instance.set_param("hold", {0.5, 0.0, 0.0, 0.0}), Catch::Contains("whole number"));
    CHECK_THROWS_WITH(instance.set_param("speed", {0.0, 0.0, 0.0, 0.0}), Catch::Contains("no parameter 'speed'"));
    CHECK(instance.get_param("hold")[0] == 0.0);
}
