// The Bullet bake (docs/physics-bullet.md): the scene in a btDiscreteDynamicsWorld stepped at a
// fixed step, free models with Dynamics as dynamic rigid bodies, keyed models (and models without
// Dynamics, which nothing can push) as kinematic bodies, static models as static ones. Bullet's
// steps are reported as closed-form segments, one per stretch between contacts (track.hpp).
#pragma once

#include <animator/physics.h>

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <utility>

namespace physics_bullet {

struct BakeOptions {
    double step = 1.0 / 240.0; // seconds
    int solver_iterations = 10;
    bool ccd = true;
    bool rotate_on_contact = false;
    double friction = 0.0;
    double restitution = 1.0;
    double margin = 0.04; // the collision margin of convex hulls (m), at most 0.2 x inner radius
};

// What a bake has said in the log (the overlapping pairs, models lower first, to when it found
// them; the models whose shape it described), kept by the instance from one slice of a bake to
// the next so that each is said once per bake, not once per slice, also when a slice starts a
// new world: a bake from 0 starts afresh, and one from a later time forgets the overlaps found
// from then on.
class SaidInBake {
  public:
    void begin(double t_begin) {
        for (auto it = found_.begin(); it != found_.end();)
            it = t_begin <= 0.0 || it->second >= t_begin ? found_.erase(it) : std::next(it);
        if (t_begin <= 0.0) described_.clear();
    }
    // Whether to say it: not said before in this bake.
    bool first(uint32_t a, uint32_t b, double t) {
        return found_.emplace(a < b ? std::make_pair(a, b) : std::make_pair(b, a), t).second;
    }
    bool first_description(uint32_t model) { return described_.insert(model).second; }

  private:
    std::map<std::pair<uint32_t, uint32_t>, double> found_;
    std::set<uint32_t> described_;
};

// What a backend instance keeps from one bake call to the next: the editor bakes in slices, each
// call going on from where the last stopped. The last slice's bake (Bullet's world, its bodies
// and shapes, each model's track, what lies past the slice's end), to go on with when the next
// call continues it (the same scene and options, from where it stopped, not from 0): the slices
// then take the steps one whole bake takes. And what was said in the log.
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

// Bakes [t_begin, t_end]: keyed spans, Bullet's steps, collision events. Throws ani::Failure.
// With `in_progress` (the instance's), a call that continues the last one goes on with its
// world; without it, every call is a bake of its own.
void bake_scene(const ani_physics_scene &scene, double t_begin, double t_end,
                const ani_bake_sink &sink, const ani_host *host, const BakeOptions &options,
                BakeInProgress *in_progress = nullptr);

} // namespace physics_bullet
