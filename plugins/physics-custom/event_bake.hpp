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

#include <memory>

namespace physics_custom {

enum class BroadPhase { kAutomatic = 0, kGrid = 1, kAllPairs = 2 };

struct BakeOptions {
    BroadPhase broad_phase = BroadPhase::kAutomatic;
    // A scene of plain free spheres in the grid is baked by the gas lane (gas_lane.hpp).
    bool gas_lane = true;
};

// What a backend instance keeps from one bake call to the next: the editor bakes in slices,
// each call going on from where the last stopped. The last slice's bake, to go on with when the
// next call continues it (the same scene, from where it stopped): a slice never redoes what an
// earlier one did. And the overlapping pairs found, for a slice that starts anew.
class BakeInProgress {
  public:
    BakeInProgress();
    ~BakeInProgress();
    struct State;

  private:
    friend void bake_scene(const ani_physics_scene &, double, double, const ani_bake_sink &,
                           const ani_host *, const BakeOptions &, BakeInProgress *);
    std::unique_ptr<State> state_;
};

// Bakes [t_begin, t_end]: keyed spans, free flight, collisions. Throws ani::Failure. With
// `in_progress` (the instance's), a call that continues the last one goes on with its bake;
// without it, every call is a bake of its own.
void bake_scene(const ani_physics_scene &scene, double t_begin, double t_end, const ani_bake_sink &sink,
                const ani_host *host, const BakeOptions &options = {},
                BakeInProgress *in_progress = nullptr);

} // namespace physics_custom
