// What a scene must keep for a bake to go on with it (event_bake.hpp, BakeInProgress): the host
// builds the scene anew for every bake call, so a slice that continues a bake is recognised by
// comparing what the bake depends on: the models, their meshes, physics flags, keyed spans, key
// times and the states at their keys, and gravity.
#pragma once

#include <animator/physics.h>

#include <cstdint>
#include <vector>

namespace physics_custom {

struct ModelPrint {
    const ani_mesh_view *mesh = nullptr;
    const double *positions = nullptr;
    uint32_t vertex_count = 0, triangle_count = 0, group = 0;
    int32_t dynamics = 0, gravity = 0;
    double mass = 0.0;
    std::vector<double> body; // restitution, friction, rotates, angular velocity (ABI 1.3)
    std::vector<double> spans, keys, key_states;
    bool operator==(const ModelPrint &o) const;
};

struct ScenePrint {
    double gravity = 0.0;
    int32_t down_axis = 0;
    std::vector<ModelPrint> models;
    bool operator==(const ScenePrint &o) const;
};

// A key that cannot be evaluated makes a print equal to no other (the bake starts anew).
ScenePrint scene_print(const ani_physics_scene &scene);

} // namespace physics_custom
