#include "scene_print.hpp"

#include <cmath>
#include <cstddef>

namespace physics_custom {

bool ModelPrint::operator==(const ModelPrint &o) const {
    return mesh == o.mesh && positions == o.positions && vertex_count == o.vertex_count &&
           triangle_count == o.triangle_count && group == o.group && dynamics == o.dynamics &&
           gravity == o.gravity && mass == o.mass && body == o.body && spans == o.spans && keys == o.keys &&
           key_states == o.key_states;
}

bool ScenePrint::operator==(const ScenePrint &o) const {
    return gravity == o.gravity && down_axis == o.down_axis && models == o.models;
}

ScenePrint scene_print(const ani_physics_scene &scene) {
    ScenePrint print;
    print.gravity = scene.gravity;
    print.down_axis = scene.down_axis;
    for (uint32_t i = 0; i < scene.model_count; ++i) {
        const ani_physics_model &m = scene.models[i];
        ModelPrint p;
        p.mesh = m.mesh;
        if (m.mesh) {
            p.positions = m.mesh->positions;
            p.vertex_count = m.mesh->vertex_count;
            p.triangle_count = m.mesh->triangle_count;
        }
        p.group = m.group;
        if (m.desc) {
            p.dynamics = m.desc->dynamics;
            p.gravity = m.desc->gravity;
            p.mass = m.desc->mass;
            if (ANI_MODEL_DESC_HAS_BODY(m.desc))
                p.body = {m.desc->restitution, m.desc->friction, double(m.desc->rotates),
                          m.desc->angular_velocity.x, m.desc->angular_velocity.y,
                          m.desc->angular_velocity.z};
        }
        for (uint32_t k = 0; k < m.keyed_span_count; ++k)
            p.spans.insert(p.spans.end(), {m.keyed_spans[k].begin, m.keyed_spans[k].end});
        const bool has_keys =
            m.struct_size >= offsetof(ani_physics_model, key_count) + sizeof(m.key_count) &&
            m.key_times;
        for (uint32_t k = 0; has_keys && k < m.key_count; ++k) {
            p.keys.push_back(m.key_times[k]);
            ani_model_state s{};
            ani_vec3 v{};
            if (scene.evaluate_keyed(scene.host_context, i, m.key_times[k], &s, &v) != ANI_OK)
                p.key_states.push_back(std::nan("")); // equal to nothing
            p.key_states.insert(p.key_states.end(),
                                {s.center.x, s.center.y, s.center.z, s.angles.x, s.angles.y,
                                 s.angles.z, s.scale.x, s.scale.y, s.scale.z, v.x, v.y, v.z});
        }
        print.models.push_back(std::move(p));
    }
    return print;
}

} // namespace physics_custom
