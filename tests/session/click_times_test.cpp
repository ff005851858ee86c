// Counting clicks (editor/click_times.hpp) by when the X server says each press happened, not
// by when the editor's frames took it: the rule is ImGui's (within 0.5 s and 6 px of the last
// press of the button adds one), the times the server's. The window end to end, with frames of
// 0.7 s, is tests/editor's outliner_rename_slow.
#include "editor/click_times.hpp"

#include <catch2/catch.hpp>

using namespace animator;

namespace {
PressStamp at(std::optional<std::uint32_t> server_ms, double taken_s, double x = 100.0, double y = 50.0) {
    return PressStamp{server_ms, taken_s, x, y};
}
} // namespace

TEST_CASE("click counter: two presses 80 ms apart are a double-click though taken 0.7 s apart", "[clicks]") {
    ClickCounter clicks(0.5, 6.0);
    CHECK(clicks.press(0, at(10000u, 1.0)) == 1);
    CHECK(clicks.press(0, at(10080u, 1.7)) == 2);
    // A third within the time is a triple-click, as ImGui counts; a fourth later starts again.
    CHECK(clicks.press(0, at(10300u, 2.4)) == 3);
    CHECK(clicks.press(0, at(10900u, 2.4)) == 1);
}

TEST_CASE("click counter: presses a second apart are two clicks though taken in one frame", "[clicks]") {
    ClickCounter clicks(0.5, 6.0);
    CHECK(clicks.press(0, at(5000u, 3.0)) == 1);
    CHECK(clicks.press(0, at(6000u, 3.0)) == 1);
    // Just under and just over the limit.
    CHECK(clicks.press(0, at(6499u, 3.0)) == 2);
    CHECK(clicks.press(0, at(7100u, 3.0)) == 1);
    CHECK(clicks.press(0, at(7600u, 3.0)) == 1); // 0.5 s exactly is not within
}

TEST_CASE("click counter: the pointer moved more than 6 px, another button, the clock wrapping", "[clicks]") {
    ClickCounter clicks(0.5, 6.0);
    CHECK(clicks.press(0, at(1000u, 0.0, 100.0, 50.0)) == 1);
    CHECK(clicks.press(0, at(1050u, 0.0, 106.5, 50.0)) == 1); // 6.5 px away
    CHECK(clicks.press(0, at(1100u, 0.0, 105.0, 50.0)) == 2); // 1.5 px from the last
    // The right button counts on its own: its first press is a click.
    CHECK(clicks.press(1, at(1150u, 0.0, 105.0, 50.0)) == 1);
    CHECK(clicks.press(1, at(1200u, 0.0, 105.0, 50.0)) == 2);
    // The server's clock wraps at 2^32 ms: 0xFFFFFFF0 then 0x40 is 80 ms.
    ClickCounter wrapped(0.5, 6.0);
    CHECK(wrapped.press(0, at(0xFFFFFFF0u, 0.0)) == 1);
    CHECK(wrapped.press(0, at(0x40u, 0.0)) == 2);
}

TEST_CASE("click counter: without the server's time of both presses, the editor's times count", "[clicks]") {
    ClickCounter clicks(0.5, 6.0);
    CHECK(clicks.press(0, at(std::nullopt, 10.0)) == 1);
    CHECK(clicks.press(0, at(20000u, 10.2)) == 2);       // 0.2 s by the editor's clock
    CHECK(clicks.press(0, at(std::nullopt, 11.0)) == 1); // 0.8 s
    CHECK(clicks.press(2, at(std::nullopt, 11.0)) == 1);
    CHECK(clicks.press(2, at(std::nullopt, 10.9)) == 1); // a clock going back is no double-click
}
