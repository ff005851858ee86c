// What `animator render` says when it drew its frames slower than 30 a second (issue 23's aim at
// 1280x720): the rate, and which of the settings it drew with cost time and can be turned off
// (docs/performance.md has what each costs). The frames are the user's to judge: it lowers
// nothing itself, as the editor's frame budget does while playing.
#pragma once

#include <string>

namespace animator {

// "drew the frames at 17 fps (58 ms each, the median), below 30: --msaa 1, --no-shadows or
// --reflections 0 draws faster" for `seconds_per_frame` (drawn and read back) with `samples`
// samples a pixel, shadow maps drawn or not, and reflections of other models drawn or not;
// "" at 30 fps or more, or when it drew with none of them.
std::string slow_frames_note(double seconds_per_frame, int samples, bool shadows, bool reflections);

} // namespace animator
