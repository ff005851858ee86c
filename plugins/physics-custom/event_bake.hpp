// The event-driven bake (physics.md, "The two backends"): between events every free body follows
// its closed form; the bake advances to the earliest time of impact, responds, and repeats, so
// every contact is found at its exact time and no speed can tunnel.
//
// Covered: spheres (Dynamics or Gravity on) against each other and against the triangles of
// static models (neither Dynamics nor Gravity, not re-keyed). A free model that is not a sphere
// moves without collisions, and the host's log says so.
#pragma once

#include "overlap_memory.hpp"

#include <animator/physics.h>

namespace physics_custom {

enum class BroadPhase { kAutomatic = 0, kGrid = 1, kAllPairs = 2 };

struct BakeOptions {
    BroadPhase broad_phase = BroadPhase::kAutomatic;
};

// Bakes [t_begin, t_end]: keyed spans, free flight, collisions. Throws ani::Failure. `memory`
// carries the overlaps found from one slice of a bake to the next (the instance's); without it,
// every call is a bake of its own.
void bake_scene(const ani_physics_scene &scene, double t_begin, double t_end, const ani_bake_sink &sink,
                const ani_host *host, const BakeOptions &options = {},
                OverlapMemory *memory = nullptr);

} // namespace physics_custom
