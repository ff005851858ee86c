// animator plugin SDK: an optional, header-only C++ helper for file-format plugins that read:
// the storage an ani_document_view points into, kept alive until the host calls release().
#ifndef ANIMATOR_SDK_DOCUMENT_BUILDER_HPP
#define ANIMATOR_SDK_DOCUMENT_BUILDER_HPP

#include "animator/document.h"

#include <deque>
#include <string>
#include <vector>

namespace ani {

struct OwnedDocument {
    std::deque<std::string> strings; // a deque, so that c_str() pointers stay valid as it grows
    std::vector<ani_model_desc> models;
    std::vector<std::vector<ani_model_state>> states; // per keyframe, one per model
    std::vector<std::vector<int32_t>> keyed;          // per keyframe, one per model
    std::vector<ani_keyframe_view> keyframes;
    std::vector<ani_param_setting> params;
    std::vector<ani_light> lights;
    ani_document_view view{};

    const char *keep(const std::string &s) {
        strings.push_back(s);
        return strings.back().c_str();
    }

    // The settings' defaults (the same as a new document's).
    void default_settings() {
        ani_settings_view &s = view.settings;
        s.struct_size = sizeof s;
        s.max_time_ms = 60000;
        s.gravity = 9.81;
        s.down_axis = ANI_AXIS_Y;
        s.cel_shading = 0;
        s.skybox = keep("");
        s.physics_backend = keep("physics.custom");
        s.interpolation = keep("interpolation.linear");
        view.ambient = {0.2, 0.2, 0.2};
        view.render_output = keep("");
    }

    // A model with every property at its default.
    ani_model_desc default_model(const std::string &name, const std::string &mesh) {
        ani_model_desc m{};
        m.struct_size = sizeof m;
        m.name = keep(name);
        m.mesh = keep(mesh);
        m.parent = -1;
        m.kd = {0.7, 0.7, 0.7};
        m.ks = {0.3, 0.3, 0.3};
        m.shininess = 25.0;
        m.texture = m.collision_sound = m.moving_sound = keep("");
        m.refractive_index = 1.0;
        m.mass = 1.0;
        m.restitution = 1.0; // ABI 1.3: elastic, frictionless, turned by keys only
        m.rest[0] = m.rest[4] = m.rest[8] = 1.0; // ABI 1.7: no rest shape, no joint
        return m;
    }

    // Points the view at the vectors; call once they are complete.
    void finish() {
        for (size_t k = 0; k < keyframes.size(); ++k) {
            keyframes[k].states = states[k].data();
            keyframes[k].keyed = keyed[k].data();
        }
        view.struct_size = sizeof view;
        view.models = models.data();
        view.model_count = static_cast<uint32_t>(models.size());
        view.keyframes = keyframes.data();
        view.keyframe_count = static_cast<uint32_t>(keyframes.size());
        view.params = params.data();
        view.param_count = static_cast<uint32_t>(params.size());
        view.lights = lights.data();
        view.light_count = static_cast<uint32_t>(lights.size());
    }
};

} // namespace ani

#endif // ANIMATOR_SDK_DOCUMENT_BUILDER_HPP
