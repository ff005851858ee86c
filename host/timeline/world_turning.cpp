#include "timeline/world_turning.hpp"

#include <cmath>

namespace animator {

std::vector<Turning> world_turnings(const Timeline &timeline, const Frame &frame, double t) {
    const auto &models = timeline.document().models();
    const size_t n = models.size();
    std::vector<Turning> out(n);
    std::vector<char> done(n, 0);
    // Parents may be listed after their children: resolve each chain from its top.
    for (size_t first = 0; first < n; ++first) {
        std::vector<size_t> chain;
        for (size_t m = first; !done[m]; m = static_cast<size_t>(models[m].parent)) {
            chain.push_back(m);
            if (models[m].parent < 0) break;
        }
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            const size_t m = *it;
            Turning &o = out[m];
            if (const RotationSegment *s = timeline.rotation_at(static_cast<int>(m), t)) {
                o.q = orientation_at(*s, t);
                o.w = angular_velocity_at(*s, t);
            } else if (timeline.carried_at(static_cast<int>(m), t)) {
                const Placement p = timeline.placement(static_cast<int>(m), t);
                o.q = p.q;
                o.w = p.w;
            } else {
                keyed_turning(frame.models[m], o.q, o.w);
                if (models[m].parent >= 0) {
                    const Turning &up = out[static_cast<size_t>(models[m].parent)];
                    o.w = up.w + up.q * o.w;
                    o.q = up.q * o.q;
                }
            }
            o.q = glm::normalize(o.q);
            done[m] = 1;
        }
    }
    // Signs only after composing, so that a child's q is its parent's times its own.
    for (Turning &o : out)
        if (o.q.w < 0.0) o.q = -o.q;
    return out;
}

} // namespace animator
