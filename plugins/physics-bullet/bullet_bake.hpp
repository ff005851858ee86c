// The Bullet bake (docs/physics-bullet.md): the scene in a btDiscreteDynamicsWorld stepped at a
// fixed step, free models with Dynamics as dynamic rigid bodies, keyed models (and models without
// Dynamics, which nothing can push) as kinematic bodies, static models as static ones. Bullet's
// steps are reported as closed-form segments, one per stretch between contacts (track.hpp).
#pragma once

#include <animator/physics.h>

#include <cstdint>
#include <map>
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
};

// What a bake has said in the log (the overlapping pairs, models lower first, to when it found
// them; the models whose shape it described), kept by the instance from one slice of a bake to
// the next so that each is said once per bake, not once per slice: a bake from 0 starts afresh,
// and one from a later time forgets the overlaps found from then on.
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

// Bakes [t_begin, t_end]: keyed spans, Bullet's steps, collision events. Throws ani::Failure.
// `reported` is the instance's (without it, every call is a bake of its own).
void bake_scene(const ani_physics_scene &scene, double t_begin, double t_end,
                const ani_bake_sink &sink, const ani_host *host, const BakeOptions &options,
                SaidInBake *reported = nullptr);

} // namespace physics_bullet
