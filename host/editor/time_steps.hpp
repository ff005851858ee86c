// Where the arrow keys take the current time: Left/Right one frame back or on, Up/Down to the
// previous or next keyframe. Pure functions of whole milliseconds (the Time slider's unit), so
// stepping on from a frame's time reaches the next frame exactly, without drift.
#pragma once

#include "document/document.hpp"

#include <cstdint>

namespace animator {

// Documents carry no frame rate; the editor steps at the rate `animator render` draws by
// default (--fps 30), so a step in the editor is a frame of the rendered video.
constexpr double kStepFramesPerSecond = 30.0;

// The time of the frame `frames` frames from the one at or before `time_ms` (frame k is at
// round(k * 1000 / fps) ms), clamped to [0, max_ms]. From a time between two frames, one step
// back goes to the frame before it, one step on to the frame after it.
std::int64_t step_frames(std::int64_t time_ms, int frames, double fps, std::int64_t max_ms);

// The time of the first keyframe after `time_ms` (direction > 0) or the last one before it
// (direction < 0); `time_ms` itself when there is none that way.
std::int64_t neighbour_keyframe(const Document &doc, std::int64_t time_ms, int direction);

} // namespace animator
