#include "scene_print.hpp"

#include <cmath>
#include <cstddef>

namespace physics_custom {

ScenePrint scene_print(const ani_physics_scene &scene, const KeyedEvaluator &evaluate) {
    ScenePrint print;
    std::vector<double> &x = print.numbers;
    x.push_back(scene.gravity);
    x.push_back(scene.down_axis);
    x.push_back(scene.model_count);
    print.meshes.reserve(2 * static_cast<std::size_t>(scene.model_count));
    x.reserve(32 * static_cast<std::size_t>(scene.model_count)); // a model keyed once: 29

    for (uint32_t i = 0; i < scene.model_count; ++i) {
        const ani_physics_model &m = scene.models[i];
        print.meshes.push_back(m.mesh);
        print.meshes.push_back(m.mesh ? m.mesh->positions : nullptr);
        if (m.mesh)
            x.insert(x.end(), {double(m.mesh->vertex_count), double(m.mesh->triangle_count)});
        else
            x.insert(x.end(), {-1.0, -1.0});
        x.push_back(m.group);
        if (m.desc) {
            x.insert(x.end(), {double(m.desc->dynamics), double(m.desc->gravity), m.desc->mass});
            if (ANI_MODEL_DESC_HAS_BODY(m.desc))
                x.insert(x.end(), {1.0, m.desc->restitution, m.desc->friction,
                                   double(m.desc->rotates), m.desc->angular_velocity.x,
                                   m.desc->angular_velocity.y, m.desc->angular_velocity.z});
            else
                x.push_back(0.0);
        } else {
            x.push_back(-1.0);
        }
        x.push_back(m.keyed_span_count);
        for (uint32_t k = 0; k < m.keyed_span_count; ++k)
            x.insert(x.end(), {m.keyed_spans[k].begin, m.keyed_spans[k].end});
        const bool has_keys =
            m.struct_size >= offsetof(ani_physics_model, key_count) + sizeof(m.key_count) &&
            m.key_times;
        x.push_back(has_keys ? m.key_count : 0);
        for (uint32_t k = 0; has_keys && k < m.key_count; ++k) {
            x.push_back(m.key_times[k]);
            ani_model_state s{};
            ani_vec3 v{};
            const bool known = evaluate ? evaluate(i, m.key_times[k], s, v)
                                        : scene.evaluate_keyed(scene.host_context, i,
                                                               m.key_times[k], &s, &v) == ANI_OK;
            if (!known) x.push_back(std::nan("")); // equal to nothing
            x.insert(x.end(), {s.center.x, s.center.y, s.center.z, s.angles.x, s.angles.y,
                               s.angles.z, s.scale.x, s.scale.y, s.scale.z, v.x, v.y, v.z});
        }
    }
    return print;
}

} // namespace physics_custom
