// Motion paths (docs/manual.md, "Motion paths"): where a model's center goes, sampled at every
// frame of the editor's rate from the timeline (keyed spans from the interpolators, free ones from
// the backend's bake), with its keys and its collisions marked. Pure: from a document and a
// timeline, so the editor samples the bake of a drag in progress the same way.
#pragma once

#include "document/document.hpp"
#include "timeline/timeline.hpp"

#include <glm/vec3.hpp>

#include <vector>

namespace animator {

struct MotionPath {
    int model = -1;
    std::vector<glm::dvec3> frames; // world position of the model's origin at frame k (k / fps s)
    std::vector<glm::dvec3> keys;   // at each of its own keys
    std::vector<glm::dvec3> hits;   // at each collision it takes part in
};

// The paths of `models` over [0, until] (at most what the timeline has baked), at `fps` frames a
// second and at most `max_frames` frames (a longer span is sampled more sparsely).
std::vector<MotionPath> sample_motion_paths(const Document &doc, const Timeline &timeline, const std::vector<int> &models,
                                            double until, double fps, std::size_t max_frames = 4000);

} // namespace animator
