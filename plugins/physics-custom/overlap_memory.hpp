// Pairs of models found overlapping when they start to collide (physics.md, "Models that start
// overlapping"), remembered by the backend instance from one slice of a bake to the next. The
// editor bakes in slices, each bake(t_begin, t_end) going on from where the last one stopped; a
// slice must treat such a pair as the bake found it (touching at the depth they had then, not at
// the depth they have when the slice starts), and must not report it again.
#pragma once

#include <glm/vec3.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace physics_custom {

struct OverlapRecord {
    enum class Kind {
        kContactDistance, // spheres: they touch at `contact` (the distance they had when found)
        kShift,           // a mesh against a static model: it touches the model moved by -shift
        kIgnored          // anything else: left alone until apart
    };
    uint32_t model_a = 0, model_b = 0; // model_a < model_b
    Kind kind = Kind::kIgnored;
    double since = 0.0;                                     // when the bake found them
    double until = std::numeric_limits<double>::infinity(); // when they were apart again
    double contact = 0.0;
    glm::dvec3 shift{0.0};
};

class OverlapMemory {
  public:
    // A bake of [t_begin, ...]: a bake from 0 is a new one; a later t_begin goes on with what was
    // found before t_begin, and what was found from t_begin on is found again.
    void begin(double t_begin) {
        records_.erase(std::remove_if(records_.begin(), records_.end(),
                                      [&](const OverlapRecord &r) {
                                          return t_begin <= 0.0 || r.since >= t_begin;
                                      }),
                       records_.end());
        for (OverlapRecord &r : records_)
            if (r.until >= t_begin) r.until = std::numeric_limits<double>::infinity();
    }

    // The pair's record found before t and not apart by then (nor let go at t), or null.
    const OverlapRecord *active(uint32_t a, uint32_t b, double t) const {
        for (const OverlapRecord &r : records_)
            if (same(r, a, b) && r.since < t && r.until > t) return &r;
        return nullptr;
    }

    // Whether the pair was found overlapping at any time before t in this bake (it was reported).
    bool reported_before(uint32_t a, uint32_t b, double t) const {
        return std::any_of(records_.begin(), records_.end(),
                           [&](const OverlapRecord &r) { return same(r, a, b) && r.since < t; });
    }

    void add(OverlapRecord r) {
        if (r.model_a > r.model_b) std::swap(r.model_a, r.model_b);
        records_.push_back(r);
    }

    // The pair is apart at t.
    void close(uint32_t a, uint32_t b, double t) {
        for (OverlapRecord &r : records_)
            if (same(r, a, b) && r.since <= t && r.until > t) r.until = t;
    }

  private:
    static bool same(const OverlapRecord &r, uint32_t a, uint32_t b) {
        return (r.model_a == a && r.model_b == b) || (r.model_a == b && r.model_b == a);
    }
    std::vector<OverlapRecord> records_;
};

} // namespace physics_custom
