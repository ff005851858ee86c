#include "timeline/world_turning.hpp"

#include <algorithm>
#include <cmath>

namespace animator {

namespace {

const glm::dvec3 kX{1.0, 0.0, 0.0}, kY{0.0, 1.0, 0.0}, kZ{0.0, 0.0, 1.0};

// The backend's segment turning the model at t, as Timeline::rotation_at finds it.
const ani_rotation_segment *segment_at(const std::vector<ani_rotation_segment> &turns, double t) {
    const auto r = std::upper_bound(turns.begin(), turns.end(), t,
                                    [](double time, const ani_rotation_segment &x) { return time < x.t0; });
    return r != turns.begin() && t <= (r - 1)->t1 ? &*(r - 1) : nullptr;
}

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
            if (const ani_rotation_segment *s = segment_at(timeline.rotations(static_cast<int>(m)), t)) {
                const glm::dvec3 w(s->w.x, s->w.y, s->w.z);
                const double speed = glm::length(w);
                const glm::dquat q0(s->q0.w, s->q0.x, s->q0.y, s->q0.z);
                o.q = speed > 0.0 ? glm::angleAxis(speed * (t - s->t0), w / speed) * q0 : q0;
                o.w = w;
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
