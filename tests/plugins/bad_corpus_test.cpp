// The corpus of malformed files in tests/data/bad: each must fail with a message that names the
// file and says what is wrong (its first line, "# expect: ..." or "-- expect: ...", or a
// FILE.expect beside it, holds a part of that message), and nothing may crash.
#include "assets/mesh.hpp"
#include "io/document_io.hpp"
#include "io/environment.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

using namespace animator;
namespace fs = std::filesystem;

namespace {

std::string expectation(const fs::path &file) {
    const fs::path sidecar = fs::path(file.string() + ".expect");
    std::string first;
    if (fs::exists(sidecar)) {
        first = test::read_file(sidecar);
    } else {
        const std::string text = test::read_file(file);
        first = text.substr(0, text.find('\n'));
    }
    for (const char *prefix : {"# expect: ", "-- expect: "})
        if (first.rfind(prefix, 0) == 0) return first.substr(std::string(prefix).size());
    while (!first.empty() && (first.back() == '\n' || first.back() == '\r')) first.pop_back();
    return first;
}

} // namespace

TEST_CASE("every malformed file gives a clear error naming it, and no crash") {
    const fs::path dir = test::source_dir() / "tests/data/bad";
    Environment env({test::source_dir() / "tests/data/assets"}, {test::bin_dir()},
                    [](ani_log_level, const std::string &, const std::string &) {});
    int count = 0;
    for (const auto &entry : fs::directory_iterator(dir)) {
        const fs::path file = entry.path();
        if (file.extension() == ".expect") continue;
        const std::string expected = expectation(file);
        CAPTURE(file.filename().string(), expected);
        REQUIRE_FALSE(expected.empty());
        std::string error;
        try {
            if (file.extension() == ".obj")
                load_mesh(file);
            else
                open_document(env.plugins, file);
        } catch (const std::exception &e) {
            error = e.what();
        }
        CHECK_THAT(error, Catch::StartsWith(file.string()));
        CHECK_THAT(error, Catch::Contains(expected));
        ++count;
    }
    CHECK(count >= 30);
}
