#include "editor/time_steps.hpp"

#include <algorithm>
#include <cmath>

namespace animator {

namespace {

std::int64_t frame_ms(std::int64_t k, double fps) {
    return static_cast<std::int64_t>(std::llround(static_cast<double>(k) * 1000.0 / fps));
}

} // namespace

std::int64_t step_frames(std::int64_t time_ms, int frames, double fps, std::int64_t max_ms) {
    if (frames == 0 || fps <= 0.0) return std::clamp<std::int64_t>(time_ms, 0, max_ms);
    // The frame at or before time_ms; the estimate from floor() can be one off after rounding.
    auto k = static_cast<std::int64_t>(std::floor(static_cast<double>(time_ms) * fps / 1000.0));
    while (frame_ms(k + 1, fps) <= time_ms) ++k;
    while (k > 0 && frame_ms(k, fps) > time_ms) --k;
    // Between two frames, a step back lands on the frame before (k itself), not one further.
    const bool on_frame = frame_ms(k, fps) == time_ms;
    const std::int64_t target = frames < 0 && !on_frame ? k + frames + 1 : k + frames;
    return std::clamp<std::int64_t>(frame_ms(std::max<std::int64_t>(target, 0), fps), 0, max_ms);
}

std::int64_t neighbour_keyframe(const Document &doc, std::int64_t time_ms, int direction) {
    const auto &keys = doc.keyframes(); // sorted by time (a Document invariant)
    if (direction > 0) {
        for (const Keyframe &k : keys)
            if (k.time_ms > time_ms) return k.time_ms;
    } else if (direction < 0) {
        for (auto it = keys.rbegin(); it != keys.rend(); ++it)
            if (it->time_ms < time_ms) return it->time_ms;
    }
    return time_ms;
}

} // namespace animator
