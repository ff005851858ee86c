#include "render/frame_rate_note.hpp"

#include <cmath>
#include <vector>

namespace animator {

std::string slow_frames_note(double seconds_per_frame, int samples, bool shadows,
                             bool reflections) {
    constexpr double kAim = 30.0; // frames a second
    if (!(seconds_per_frame > 0.0) || 1.0 / seconds_per_frame >= kAim) return "";
    std::vector<std::string> faster;
    if (samples > 1) faster.emplace_back("--msaa 1");
    if (shadows) faster.emplace_back("--no-shadows");
    if (reflections) faster.emplace_back("--reflections 0");
    if (faster.empty()) return "";
    std::string options;
    for (std::size_t i = 0; i < faster.size(); ++i)
        options += (i == 0 ? "" : i + 1 == faster.size() ? " or " : ", ") + faster[i];
    const long fps = std::lround(std::floor(1.0 / seconds_per_frame));
    const long ms = std::lround(seconds_per_frame * 1000.0);
    return "drew the frames at " + std::to_string(fps) + " fps (" + std::to_string(ms) +
           " ms each, the median), below " + std::to_string(static_cast<int>(kAim)) + ": " +
           options + " draws faster";
}

} // namespace animator
