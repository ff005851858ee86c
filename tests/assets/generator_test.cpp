// The generator as a program: it writes every documented file, deterministically.
#include "asset_readers.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <map>
#include <string>
#include <sys/wait.h>

namespace fs = std::filesystem;
using namespace animator::test::assets;

namespace {

// Relative path -> contents, for every regular file under `root` except the build's stamp.
std::map<std::string, std::string> snapshot(const fs::path &root) {
    std::map<std::string, std::string> files;
    for (const auto &entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file() || entry.path().filename() == ".stamp") continue;
        files[fs::relative(entry.path(), root).generic_string()] =
            animator::test::read_file(entry.path());
    }
    return files;
}

int run_generator(const std::string &args) {
    const std::string command =
        std::string("\"") + ANIMATOR_ASSET_GEN + "\" " + args + " >/dev/null 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

TEST_CASE("the build generated every documented asset and nothing else") {
    const auto files = snapshot(generated_dir());
    for (const auto &name : documented_files()) {
        INFO(name);
        CHECK(files.count(name) == 1);
    }
    CHECK(files.size() == documented_files().size());
}

TEST_CASE("running the generator again writes byte-identical files") {
    const fs::path out = animator::test::fresh_dir("asset_gen_determinism");
    REQUIRE(run_generator("\"" + out.string() + "\"") == 0);
    const auto again = snapshot(out), built = snapshot(generated_dir());
    REQUIRE(again.size() == built.size());
    for (const auto &[name, bytes] : built) {
        INFO(name);
        REQUIRE(again.count(name) == 1);
        CHECK((again.at(name) == bytes)); // not CHECK(a == b): Catch would print megabytes
    }
}

TEST_CASE("the generator refuses to run without exactly one output folder") {
    CHECK(run_generator("") == 2);
    CHECK(run_generator("a b") == 2);
}
