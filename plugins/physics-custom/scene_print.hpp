// What a scene must keep for a bake to go on with it (event_bake.hpp, BakeInProgress): the host
// builds the scene anew for every bake call, so a slice that continues a bake is recognised by
// comparing what the bake depends on: the models, their meshes, physics flags, keyed spans, key
// times and the states at their keys, and gravity.
#pragma once

#include <animator/physics.h>

#include <cstdint>
#include <functional>

namespace physics_custom {

// All of it, model after model, folded into two 64-bit hashes as it is read
// (nothing stored: the numbers of a gas of 100,000 balls took 25 MB, written at every bake's
// start, a tenth of the bake's time at that size; docs/performance.md, the gas), with how many
// numbers went in. Two prints of different scenes are equal only if both hashes collide at once
// (about 2^-128 for unrelated numbers; not a defence against a scene made to collide).
struct ScenePrint {
    uint64_t a = 0x60ea27eeadc0b5d6ull, b = 0x61c8864e7a143579ull; // two unrelated starting values
    uint64_t count = 0;
    bool unknown = false; // a key that could not be evaluated, or a number that is NaN
    bool operator==(const ScenePrint &o) const {
        return !unknown && !o.unknown && a == o.a && b == o.b && count == o.count;
    }
    bool operator!=(const ScenePrint &o) const { return !(*this == o); }
    // Adds a number (0 and -0 alike, as == has them; a NaN makes the print equal to no other)
    // and an address (a mesh and its positions: the same view is the same mesh).
    void add(double x);
    void add(const void *p);

  private:
    void add_word(uint64_t w);
};

// The keys' state of model m at t and their velocity there, or false when they cannot say.
using KeyedEvaluator = std::function<bool(uint32_t m, double t, ani_model_state &, ani_vec3 &)>;

// A key that cannot be evaluated makes a print equal to no other (the bake starts anew). Keys are
// evaluated by the scene's evaluate_keyed, or by `evaluate` when given.
ScenePrint scene_print(const ani_physics_scene &scene, const KeyedEvaluator &evaluate = {});

} // namespace physics_custom
