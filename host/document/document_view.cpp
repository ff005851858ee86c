#include "document/document_view.hpp"

#include <cmath>

namespace animator {

ani_vec3 to_ani(const glm::dvec3 &v) { return ani_vec3{v.x, v.y, v.z}; }
glm::dvec3 from_ani(const ani_vec3 &v) { return glm::dvec3(v.x, v.y, v.z); }

namespace {

ani_model_state to_ani(const ModelState &s) {
    return ani_model_state{animator::to_ani(s.center), animator::to_ani(s.angles),
                           animator::to_ani(s.scale), animator::to_ani(s.turn)};
}

ModelState from_ani(const ani_model_state &s) {
    return ModelState{animator::from_ani(s.center), animator::from_ani(s.angles),
                      animator::from_ani(s.scale), animator::from_ani(s.turn)};
}

ani_camera_state to_ani(const CameraState &c) {
    return ani_camera_state{animator::to_ani(c.position),
                            ani_quat{c.rotation.w, c.rotation.x, c.rotation.y, c.rotation.z},
                            c.fov_degrees};
}

CameraState from_ani(const ani_camera_state &c) {
    return CameraState{animator::from_ani(c.position),
                       glm::dquat(c.rotation.w, c.rotation.x, c.rotation.y, c.rotation.z),
                       c.fov_degrees};
}

std::string str(const char *s) { return s ? std::string(s) : std::string(); }

} // namespace

DocumentView::DocumentView(const Document &doc) {
    models_.reserve(doc.models().size());
    for (const Model &m : doc.models()) {
        ani_model_desc d{};
        d.struct_size = sizeof d;
        d.name = m.name.c_str();
        d.mesh = m.mesh.c_str();
        d.parent = m.parent;
        d.kd = to_ani(m.material.kd);
        d.ks = to_ani(m.material.ks);
        d.shininess = m.material.shininess;
        d.texture = m.texture.c_str();
        d.tint = m.tint;
        d.reflectivity = m.reflectivity;
        d.transparency = m.transparency;
        d.refractive_index = m.refractive_index;
        d.dynamics = m.dynamics ? 1 : 0;
        d.gravity = m.gravity ? 1 : 0;
        d.mass = m.mass;
        d.initial_velocity = to_ani(m.initial_velocity);
        d.restitution = m.restitution;
        d.friction = m.friction;
        d.rotates = m.rotates ? 1 : 0;
        d.angular_velocity = to_ani(m.angular_velocity);
        d.collision_sound = m.collision_sound.c_str();
        d.moving_sound = m.moving_sound.c_str();
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) d.rest[3 * c + r] = m.rest[c][r];
        d.has_joint = m.joint ? 1 : 0;
        if (m.joint) {
            d.joint_min = to_ani(m.joint->min);
            d.joint_max = to_ani(m.joint->max);
        }
        models_.push_back(d);
    }
    states_.reserve(doc.keyframes().size());
    keyed_.reserve(doc.keyframes().size());
    keyframes_.reserve(doc.keyframes().size());
    for (const Keyframe &k : doc.keyframes()) {
        ani::HugeVector<ani_model_state> states;
        std::vector<int32_t> keyed;
        states.reserve(k.states.size());
        keyed.reserve(k.states.size());
        for (const auto &s : k.states) {
            states.push_back(to_ani(s.value_or(ModelState{})));
            keyed.push_back(s ? 1 : 0);
        }
        states_.push_back(std::move(states));
        keyed_.push_back(std::move(keyed));
    }
    for (size_t i = 0; i < doc.keyframes().size(); ++i) {
        const Keyframe &k = doc.keyframes()[i];
        ani_keyframe_view kv{};
        kv.struct_size = sizeof kv;
        kv.time_ms = k.time_ms;
        kv.states = states_[i].data();
        kv.keyed = keyed_[i].data();
        kv.camera = to_ani(k.camera.value_or(CameraState{}));
        kv.camera_keyed = k.camera ? 1 : 0;
        keyframes_.push_back(kv);
    }
    const Settings &s = doc.settings();
    for (const auto &[plugin, values] : s.params)
        for (const auto &[param, value] : values) {
            ani_param_setting p{};
            p.plugin_id = plugin.c_str();
            p.param_id = param.c_str();
            for (size_t c = 0; c < 4; ++c) p.value.value[c] = value[c];
            params_.push_back(p);
        }
    view_.struct_size = sizeof view_;
    view_.models = models_.data();
    view_.model_count = static_cast<uint32_t>(models_.size());
    view_.keyframes = keyframes_.data();
    view_.keyframe_count = static_cast<uint32_t>(keyframes_.size());
    view_.settings.struct_size = sizeof view_.settings;
    view_.settings.max_time_ms = s.max_time_ms;
    view_.settings.gravity = s.gravity;
    view_.settings.down_axis = static_cast<int32_t>(s.down_axis);
    view_.settings.cel_shading = s.cel_shading ? 1 : 0;
    view_.settings.skybox = s.skybox.c_str();
    view_.settings.physics_backend = s.physics_backend.c_str();
    view_.settings.interpolation = s.interpolation.c_str();
    view_.params = params_.data();
    view_.param_count = static_cast<uint32_t>(params_.size());
    for (const Light &l : s.lights)
        lights_.push_back(ani_light{l.name.c_str(), to_ani(l.position), to_ani(l.colour), to_ani(l.falloff)});
    view_.lights = lights_.data();
    view_.light_count = static_cast<uint32_t>(lights_.size());
    view_.ambient = to_ani(s.ambient);
    view_.render_output = s.render_output.c_str();
    view_.render_width = s.render_width;
    view_.render_height = s.render_height;
}

Document document_from_view(const ani_document_view &view) {
    Document doc;
    if (view.keyframe_count == 0 || view.keyframes[0].time_ms != 0)
        throw DocumentError("an animation needs a keyframe at t = 0");

    Settings settings;
    settings.max_time_ms = view.settings.max_time_ms;
    settings.gravity = view.settings.gravity;
    if (view.settings.down_axis < 0 || view.settings.down_axis > 2)
        throw DocumentError("down axis must be x, y or z");
    settings.down_axis = static_cast<Axis>(view.settings.down_axis);
    settings.cel_shading = view.settings.cel_shading != 0;
    settings.skybox = str(view.settings.skybox);
    settings.physics_backend = str(view.settings.physics_backend);
    settings.interpolation = str(view.settings.interpolation);
    for (uint32_t i = 0; i < view.param_count; ++i) {
        const ani_param_setting &p = view.params[i];
        if (!p.plugin_id || !p.param_id) throw DocumentError("a parameter needs a plugin and an id");
        ParamValue &value = settings.params[p.plugin_id][p.param_id];
        for (size_t c = 0; c < 4; ++c) value[c] = p.value.value[c];
    }
    if (ANI_DOCUMENT_VIEW_HAS_LIGHTS(&view)) {
        if (view.light_count > Settings::kMaxLights) // before copying: the count may be anything
            throw DocumentError("a scene has at most " + std::to_string(Settings::kMaxLights) + " lights, this one " +
                                std::to_string(view.light_count));
        for (uint32_t i = 0; i < view.light_count; ++i) {
            const ani_light &l = view.lights[i];
            settings.lights.push_back(Light{str(l.name), from_ani(l.position), from_ani(l.colour), from_ani(l.falloff)});
        }
        settings.ambient = from_ani(view.ambient);
        settings.render_output = str(view.render_output);
        settings.render_width = view.render_width;
        settings.render_height = view.render_height;
    }
    doc.set_settings(settings);

    for (uint32_t i = 0; i < view.model_count; ++i) {
        const ani_model_desc &d = view.models[i];
        Model m;
        m.name = str(d.name);
        m.mesh = str(d.mesh);
        m.parent = d.parent;
        m.material.kd = from_ani(d.kd);
        m.material.ks = from_ani(d.ks);
        m.material.shininess = d.shininess;
        m.texture = str(d.texture);
        m.tint = d.tint;
        m.reflectivity = d.reflectivity;
        m.transparency = d.transparency;
        m.refractive_index = d.refractive_index;
        m.dynamics = d.dynamics != 0;
        m.gravity = d.gravity != 0;
        m.mass = d.mass;
        m.initial_velocity = from_ani(d.initial_velocity);
        if (ANI_MODEL_DESC_HAS_BODY(&d)) {
            m.restitution = d.restitution;
            m.friction = d.friction;
            m.rotates = d.rotates != 0;
            m.angular_velocity = from_ani(d.angular_velocity);
        }
        m.collision_sound = str(d.collision_sound);
        m.moving_sound = str(d.moving_sound);
        if (ANI_MODEL_DESC_HAS_SHAPE(&d)) {
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 3; ++r) m.rest[c][r] = d.rest[3 * c + r];
            if (d.has_joint) m.joint = JointRange{from_ani(d.joint_min), from_ani(d.joint_max)};
        }
        doc.add_model(m, from_ani(view.keyframes[0].states[i]));
    }

    const ani_keyframe_view &first = view.keyframes[0];
    for (uint32_t m = 0; m < view.model_count; ++m)
        if (!first.keyed[m]) throw DocumentError("the keyframe at t = 0 must key model '" + doc.models()[m].name + "'");
    if (!first.camera_keyed) throw DocumentError("the keyframe at t = 0 must key the camera");
    doc.set_camera(0, from_ani(first.camera));
    for (uint32_t k = 1; k < view.keyframe_count; ++k) {
        const ani_keyframe_view &kv = view.keyframes[k];
        if (kv.time_ms <= view.keyframes[k - 1].time_ms)
            throw DocumentError("keyframe times must increase: " + std::to_string(kv.time_ms) +
                                " ms comes after " + std::to_string(view.keyframes[k - 1].time_ms) +
                                " ms");
        Keyframe keyframe;
        keyframe.time_ms = kv.time_ms;
        if (kv.camera_keyed) keyframe.camera = from_ani(kv.camera);
        for (uint32_t m = 0; m < view.model_count; ++m)
            keyframe.states.push_back(kv.keyed[m] ? std::optional<ModelState>(from_ani(kv.states[m])) : std::nullopt);
        doc.insert_keyframe(keyframe);
    }
    return doc;
}

} // namespace animator
