#include "editor/motion_paths.hpp"

#include "render/scene_math.hpp"

#include <algorithm>
#include <cmath>

namespace animator {

namespace {

glm::dvec3 origin(const glm::dmat4 &world) { return glm::dvec3(world[3]); }

} // namespace

std::vector<MotionPath> sample_motion_paths(const Document &doc, const Timeline &timeline, const std::vector<int> &models,
                                            double until, double fps, std::size_t max_frames) {
    std::vector<MotionPath> paths;
    const int count = static_cast<int>(doc.models().size());
    for (int m : models)
        if (m >= 0 && m < count) paths.push_back(MotionPath{m, {}, {}, {}});
    if (paths.empty() || !(fps > 0.0)) return paths;
    until = std::min(until, timeline.baked_until());
    if (!(until >= 0.0)) return paths;

    std::vector<glm::dmat4> world;
    auto at = [&](double t) {
        const Frame f = timeline.evaluate(t);
        world_matrices(doc.models(), f.models, world);
    };
    const auto frames = static_cast<std::size_t>(std::floor(until * fps + 1e-9)) + 1;
    const std::size_t stride = std::max<std::size_t>(1, (frames + max_frames - 1) / max_frames);
    for (std::size_t k = 0; k < frames; k += stride) {
        at(static_cast<double>(k) / fps);
        for (MotionPath &p : paths) p.frames.push_back(origin(world[static_cast<size_t>(p.model)]));
    }
    // A model's keys: its own, or (for a model under another) the keys that move it.
    for (MotionPath &p : paths) {
        for (const Keyframe *k : doc.keys_of(p.model)) {
            const double t = static_cast<double>(k->time_ms) / 1000.0;
            if (t > until) break;
            at(t);
            p.keys.push_back(origin(world[static_cast<size_t>(p.model)]));
        }
    }
    for (const ani_collision_event &e : timeline.events()) {
        if (e.t > until) break;
        bool any = false;
        for (const MotionPath &p : paths) any |= static_cast<uint32_t>(p.model) == e.a || static_cast<uint32_t>(p.model) == e.b;
        if (!any) continue;
        at(e.t);
        for (MotionPath &p : paths)
            if (static_cast<uint32_t>(p.model) == e.a || static_cast<uint32_t>(p.model) == e.b)
                p.hits.push_back(origin(world[static_cast<size_t>(p.model)]));
    }
    return paths;
}

} // namespace animator
