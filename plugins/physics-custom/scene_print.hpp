// What a scene must keep for a bake to go on with it (event_bake.hpp, BakeInProgress): the host
// builds the scene anew for every bake call, so a slice that continues a bake is recognised by
// comparing what the bake depends on: the models, their meshes, physics flags, keyed spans, key
// times and the states at their keys, and gravity.
#pragma once

#include <animator/physics.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace physics_custom {

// All of it, model after model, in two flat lists (one allocation each, not several per model:
// a gas of 100,000 balls is printed at every bake's start): the meshes' addresses, and every
// number with the count of each variable-length part before it.
struct ScenePrint {
    std::vector<const void *> meshes; // per model: its mesh view and its positions
    std::vector<double> numbers;
    bool operator==(const ScenePrint &o) const {
        return meshes == o.meshes && numbers == o.numbers;
    }
};

// The keys' state of model m at t and their velocity there, or false when they cannot say.
using KeyedEvaluator = std::function<bool(uint32_t m, double t, ani_model_state &, ani_vec3 &)>;

// A key that cannot be evaluated makes a print equal to no other (the bake starts anew). Keys are
// evaluated by the scene's evaluate_keyed, or by `evaluate` when given.
ScenePrint scene_print(const ani_physics_scene &scene, const KeyedEvaluator &evaluate = {});

} // namespace physics_custom
