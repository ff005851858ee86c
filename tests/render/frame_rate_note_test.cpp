// What `animator render` says about frames drawn slower than 30 a second.
#include "render/frame_rate_note.hpp"

#include <catch2/catch.hpp>

using namespace animator;

TEST_CASE("animator render's note on slow frames names the rate and the settings that cost time") {
    // 58 ms a frame: 17.2 a second, said as 17 (never rounded up to the aim).
    CHECK(slow_frames_note(0.058, 4, true, true) ==
          "drew the frames at 17 fps (58 ms each, the median), below 30: --msaa 1, --no-shadows "
          "or --reflections 0 draws faster");
    CHECK(slow_frames_note(0.0334, 4, false, false) ==
          "drew the frames at 29 fps (33 ms each, the median), below 30: --msaa 1 draws faster");
    CHECK(slow_frames_note(0.05, 1, true, false) ==
          "drew the frames at 20 fps (50 ms each, the median), below 30: --no-shadows draws faster");
    // At 30 a second or more, or with nothing on that could go: nothing to say.
    CHECK(slow_frames_note(1.0 / 30.0, 4, true, true).empty());
    CHECK(slow_frames_note(0.010, 4, true, true).empty());
    CHECK(slow_frames_note(0.2, 1, false, false).empty());
    CHECK(slow_frames_note(0.0, 4, true, true).empty());
}
