#include "export/export_motion.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace animator {

using motion_keys::Piece;

glm::dquat euler_rotation(const glm::dvec3 &degrees) {
    const glm::dvec3 r = glm::radians(degrees);
    return glm::angleAxis(r.x, glm::dvec3(1, 0, 0)) * glm::angleAxis(r.y, glm::dvec3(0, 1, 0)) *
           glm::angleAxis(r.z, glm::dvec3(0, 0, 1));
}

namespace {

double seconds(std::int64_t ms) {
    return static_cast<double>(ms) / 1000.0;
}

glm::dvec3 vec(const ani_vec3 &v) {
    return glm::dvec3(v.x, v.y, v.z);
}

// [from, until] cut at every time of `cuts` strictly inside it.
std::vector<double> breakpoints(const std::set<double> &cuts, double from, double until) {
    std::vector<double> out{from};
    for (double t : cuts)
        if (t > from && t < until) out.push_back(t);
    if (until > from) out.push_back(until);
    return out;
}

class ModelMotion {
  public:
    ModelMotion(const Timeline &timeline, int model, const MotionKeyOptions &options,
                MotionKeyStats &stats)
        : timeline_(timeline), m_(model), options_(options), stats_(stats) {
        for (const Keyframe *k : timeline.document().keys_of(model))
            key_times_.insert(seconds(k->time_ms));
    }

    void translation(std::vector<motion_keys::VecKey> &keys) const {
        const bool root = timeline_.document().models()[static_cast<size_t>(m_)].parent < 0;
        std::set<double> cuts = key_times_;
        const auto &segments = timeline_.segments(m_);
        bool pivot = false;
        if (root) {
            for (const ani_motion_segment &s : segments) {
                cuts.insert(s.t0);
                cuts.insert(s.t1);
            }
            for (const RotationSegment &r : timeline_.rotations(m_)) {
                if (r.pivot == glm::dvec3(0.0)) continue;
                pivot = true;
                cuts.insert(r.t0);
                cuts.insert(r.t1);
            }
        }
        const std::vector<double> times = breakpoints(cuts, options_.from, options_.until);
        for (size_t i = 0; i + 1 < times.size() || (i == 0 && times.size() == 1); ++i) {
            const double a = times[i], b = i + 1 < times.size() ? times[i + 1] : a;
            const double mid = 0.5 * (a + b);
            const ani_motion_segment *s = root ? timeline_.segment_at(m_, mid) : nullptr;
            Piece piece;
            if (!s || s->motion == ANI_MOTION_KEYED) {
                piece.value = [this](double t) { return timeline_.keyed().model(m_, t).center; };
            } else if (s->motion == ANI_MOTION_CARRIED) {
                // Where its carrier takes it (sampled as its carrier's keys are).
                piece.value = [this](double t) { return timeline_.placement(m_, t).center; };
                piece.rate = [this](double t) { return timeline_.placement(m_, t).velocity; };
            } else {
                const ani_motion_segment seg = *s;
                const RotationSegment *r = pivot ? timeline_.rotation_at(m_, mid) : nullptr;
                if (!r || r->pivot == glm::dvec3(0.0)) {
                    // Free flight or rest: p0 + v0 tau + a tau^2 / 2, one Hermite span exactly.
                    piece.value = [seg](double t) {
                        const double tau = t - seg.t0;
                        return vec(seg.p0) + vec(seg.v0) * tau + 0.5 * vec(seg.a) * tau * tau;
                    };
                    piece.rate = [seg](double t) {
                        return vec(seg.v0) + vec(seg.a) * (t - seg.t0);
                    };
                } else {
                    // The origin of a model turned about its centre of mass: c(t) - R(t) pivot.
                    const RotationSegment turn = *r;
                    piece.value = [seg, turn](double t) {
                        const double tau = t - seg.t0;
                        const glm::dvec3 c =
                            vec(seg.p0) + vec(seg.v0) * tau + 0.5 * vec(seg.a) * tau * tau;
                        return c - orientation_at(turn, t) * turn.pivot;
                    };
                    piece.rate = [seg, turn](double t) {
                        const glm::dvec3 v = vec(seg.v0) + vec(seg.a) * (t - seg.t0);
                        return v - glm::cross(angular_velocity_at(turn, t),
                                              orientation_at(turn, t) * turn.pivot);
                    };
                }
            }
            append(keys, a, b, piece, stats_.translation);
        }
    }

    void scale(std::vector<motion_keys::VecKey> &keys) const {
        const std::vector<double> times = breakpoints(key_times_, options_.from, options_.until);
        Piece piece;
        piece.value = [this](double t) { return timeline_.keyed().model(m_, t).scale; };
        for (size_t i = 0; i + 1 < times.size(); ++i)
            append(keys, times[i], times[i + 1], piece, stats_.scale);
        if (times.size() == 1) append(keys, times[0], times[0], piece, stats_.scale);
    }

    void rotation(std::vector<motion_keys::QuatKey> &keys) const {
        std::set<double> cuts = key_times_;
        for (const RotationSegment &r : timeline_.rotations(m_)) {
            cuts.insert(r.t0);
            cuts.insert(r.t1);
        }
        for (const ani_carried_segment &c : timeline_.carried(m_)) {
            cuts.insert(c.t0);
            cuts.insert(c.t1);
        }
        const std::vector<double> times = breakpoints(cuts, options_.from, options_.until);
        auto keyed = [this](double t) {
            return euler_rotation(timeline_.keyed().model(m_, t).angles);
        };
        for (size_t i = 0; i + 1 < times.size() || (i == 0 && times.size() == 1); ++i) {
            const double a = times[i], b = i + 1 < times.size() ? times[i + 1] : a;
            const RotationSegment *r = timeline_.rotation_at(m_, 0.5 * (a + b));
            std::function<glm::dquat(double)> f = keyed;
            if (r) {
                const RotationSegment turn = *r;
                f = [turn](double t) { return orientation_at(turn, t); };
            } else if (timeline_.carried_at(m_, 0.5 * (a + b))) {
                f = [this](double t) { return timeline_.placement(m_, t).q; };
            }
            motion_keys::append_rotation(keys, a, b, f, options_.rotation_tolerance,
                                         &stats_.rotation);
        }
    }

  private:
    void append(std::vector<motion_keys::VecKey> &keys, double a, double b, const Piece &piece,
                motion_keys::PieceStats &stats) const {
        const double tolerance = options_.position_tolerance * (1.0 + glm::length(piece.value(a)));
        motion_keys::append_piece(keys, a, b, piece, tolerance, &stats);
    }

    const Timeline &timeline_;
    int m_;
    const MotionKeyOptions &options_;
    MotionKeyStats &stats_;
    std::set<double> key_times_;
};

void camera_keys(const Timeline &timeline, const MotionKeyOptions &options, MotionKeys &out) {
    std::set<double> cuts;
    for (const Keyframe *k : timeline.document().keys_of(-1)) cuts.insert(seconds(k->time_ms));
    const std::vector<double> times = breakpoints(cuts, options.from, options.until);
    Piece piece;
    piece.value = [&timeline](double t) { return timeline.keyed().camera(t).position; };
    auto rotation = [&timeline](double t) {
        return glm::normalize(timeline.keyed().camera(t).rotation);
    };
    for (size_t i = 0; i + 1 < times.size() || (i == 0 && times.size() == 1); ++i) {
        const double a = times[i], b = i + 1 < times.size() ? times[i + 1] : a;
        const double tolerance = options.position_tolerance * (1.0 + glm::length(piece.value(a)));
        motion_keys::append_piece(out.camera.translation, a, b, piece, tolerance,
                                  &out.stats.translation);
        motion_keys::append_rotation(out.camera.rotation, a, b, rotation,
                                     options.rotation_tolerance, &out.stats.rotation);
    }
}

// One LINEAR key per frame, from what the timeline shows at each.
MotionKeys frame_keys(const Timeline &timeline, const MotionKeyOptions &options) {
    MotionKeys out;
    const size_t n = timeline.document().models().size();
    out.models.resize(n);
    const auto frames =
        static_cast<long long>(std::floor((options.until - options.from) * options.fps + 1e-9));
    auto add = [](std::vector<motion_keys::VecKey> &keys, double t, const glm::dvec3 &v) {
        if (!keys.empty()) {
            const glm::dvec3 slope = (v - keys.back().value) / (t - keys.back().t);
            keys.back().out = slope;
            keys.push_back(motion_keys::VecKey{t, slope, v, slope});
        } else {
            keys.push_back(motion_keys::VecKey{t, glm::dvec3(0.0), v, glm::dvec3(0.0)});
        }
    };
    auto add_turn = [](std::vector<motion_keys::QuatKey> &keys, double t, glm::dquat q) {
        if (!keys.empty() && glm::dot(q, keys.back().q) < 0.0) q = -q;
        keys.push_back(motion_keys::QuatKey{t, q});
    };
    for (long long k = 0; k <= frames; ++k) {
        const double t = options.from + static_cast<double>(k) / options.fps;
        const Frame frame = timeline.evaluate(t);
        for (size_t m = 0; m < n; ++m) {
            const ModelPose &p = frame.models[m];
            add(out.models[m].translation, t, p.center);
            add(out.models[m].scale, t, p.scale);
            add_turn(out.models[m].rotation, t, euler_rotation(p.angles));
        }
        add(out.camera.translation, t, frame.camera.position);
        add_turn(out.camera.rotation, t, glm::normalize(frame.camera.rotation));
    }
    return out;
}

} // namespace

MotionKeys motion_keys_of(const Timeline &timeline, const MotionKeyOptions &options) {
    if (options.fps > 0.0) return frame_keys(timeline, options);
    MotionKeys out;
    const int n = static_cast<int>(timeline.document().models().size());
    out.models.resize(static_cast<size_t>(n));
    for (int m = 0; m < n; ++m) {
        const ModelMotion motion(timeline, m, options, out.stats);
        NodeKeys &keys = out.models[static_cast<size_t>(m)];
        motion.translation(keys.translation);
        motion.rotation(keys.rotation);
        motion.scale(keys.scale);
    }
    camera_keys(timeline, options, out);
    return out;
}

} // namespace animator
