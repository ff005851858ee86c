// The F1 overlay (editor/help.hpp) and docs/manual.md list the same keys: every row of the
// manual's Keys table and of its free view table is in the overlay, and the overlay has no key
// the manual does not document.
#include "editor/help.hpp"

#include "support.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <set>
#include <sstream>

using namespace animator;

namespace {

// The first cells of the markdown table that follows the heading `heading` in the manual.
std::set<std::string> first_cells(const std::string &heading) {
    std::ifstream in(test::source_dir() / "docs" / "manual.md");
    REQUIRE(in);
    std::string line;
    bool in_section = false, in_table = false;
    std::set<std::string> cells;
    while (std::getline(in, line)) {
        if (line.rfind("## ", 0) == 0) {
            if (in_section) break;
            in_section = line == "## " + heading;
            continue;
        }
        if (!in_section) continue;
        if (line.rfind("|", 0) == 0) {
            in_table = true;
            const std::string cell = line.substr(1, line.find('|', 1) - 1);
            const auto b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
            const std::string trimmed = cell.substr(b, e - b + 1);
            if (trimmed.find("---") == std::string::npos && trimmed != "key" && trimmed != "control") cells.insert(trimmed);
        } else if (in_table) {
            break;
        }
    }
    return cells;
}

std::set<std::string> overlay_keys(const std::string &title_start) {
    for (const HelpSection &s : help_sections())
        if (s.title.rfind(title_start, 0) == 0) {
            std::set<std::string> keys;
            for (const HelpRow &r : s.rows) keys.insert(r.keys);
            return keys;
        }
    FAIL("no section " << title_start);
    return {};
}

} // namespace

TEST_CASE("the F1 overlay lists exactly the manual's keys", "[help]") {
    const auto manual = first_cells("Keys");
    CHECK(manual.size() > 10);
    CHECK(overlay_keys("Keys") == manual);
}

TEST_CASE("the F1 overlay lists exactly the manual's free view controls", "[help]") {
    const auto manual = first_cells("Looking around (free view)");
    CHECK(manual.size() >= 5);
    CHECK(overlay_keys("Free view") == manual);
}

TEST_CASE("the F1 overlay lists exactly the manual's Timeline controls", "[help]") {
    const auto manual = first_cells("The Timeline (dope sheet)");
    CHECK(manual.size() >= 10);
    CHECK(overlay_keys("Timeline") == manual);
}

TEST_CASE("the keys other programs bind say what the manual says they do here", "[help]") {
    const auto manual = first_cells("Coming from Blender or Maya");
    CHECK(manual.size() >= 4);
    CHECK(overlay_keys("Coming from Blender or Maya") == manual);
    // Each of them has a hint for the status line, starting with the key; other keys have none.
    for (const std::string &cell : manual) {
        std::string key;
        for (char c : cell)
            if (c != '`') key += c;
        const auto hint = familiar_key_hint(key);
        REQUIRE(hint);
        CHECK(hint->rfind(key + ": ", 0) == 0);
    }
    CHECK_FALSE(familiar_key_hint("i"));
    CHECK_FALSE(familiar_key_hint("q"));
}
