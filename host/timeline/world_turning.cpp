#include "timeline/world_turning.hpp"

#include <cmath>

namespace animator {

namespace {

const glm::dvec3 kX{1.0, 0.0, 0.0}, kY{0.0, 1.0, 0.0}, kZ{0.0, 0.0, 1.0};

// The keyed rotation R = Rx(a) Ry(b) Rz(c) in the parent's frame, and its angular velocity
// there. From R' R^T = [w]x for a product A B C: w = a' e_x + A (b' e_y) + A B (c' e_z), exact
// from the interpolator's angle rates (no differencing).
Turning keyed(const ModelPose &p) {
    const glm::dvec3 a = glm::radians(p.angles), rate = glm::radians(p.angle_rates);
    const glm::dquat A = glm::angleAxis(a.x, kX), B = glm::angleAxis(a.y, kY), C = glm::angleAxis(a.z, kZ);
    Turning out;
    out.q = A * B * C;
    out.w = rate.x * kX + A * (rate.y * kY) + (A * B) * (rate.z * kZ);
    return out;
}

} // namespace

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
            } else {
                o = keyed(frame.models[m]);
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
