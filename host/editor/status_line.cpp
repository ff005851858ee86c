#include "editor/status_line.hpp"

#include <cmath>
#include <cstdio>

namespace animator {

namespace {

// Seconds as a user reads them: "20 s", "12.3 s", "0.004 s" (%g keeps what matters).
std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g s", s);
    return text;
}

} // namespace

std::string bake_status(const EditorSession &session) {
    const std::string backend = session.backend();
    const double baked = std::min(session.timeline().baked_until(), session.max_time());
    if (!session.bake_error().empty()) return backend + ": bake failed at " + seconds(baked);
    if (session.baking()) {
        // Tenths of a second: the text changes as the bar moves, not on every slice.
        return backend + ": baked to " + seconds(std::floor(baked * 10.0) / 10.0) + " of " + seconds(session.max_time());
    }
    return backend + ": baked, " + seconds(session.max_time());
}

void FrameRate::frame(double wall) {
    times_.push_back(wall);
    while (times_.size() > 1 && times_.front() < wall - 1.0) times_.pop_front();
}

std::string FrameRate::text() const {
    if (times_.size() < 2) return "idle";
    const double span = times_.back() - times_.front();
    if (span <= 0.0) return "idle";
    char text[32];
    std::snprintf(text, sizeof text, "%.0f fps", static_cast<double>(times_.size() - 1) / span);
    return text;
}

} // namespace animator
