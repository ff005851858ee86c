#include "document/document.hpp"

#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace animator {

namespace {

bool finite(const glm::dvec3 &v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool in_unit(double x) { return x >= 0.0 && x <= 1.0; }
// A colour: finite and >= 0 (above 1 is brighter than white, as the CS488 course allowed).
bool colour(const glm::dvec3 &v) { return finite(v) && v.x >= 0.0 && v.y >= 0.0 && v.z >= 0.0; }

template <class... Parts> std::string concat(const Parts &...parts) {
    std::ostringstream out;
    (out << ... << parts);
    return out.str();
}

} // namespace

bool Model::operator==(const Model &o) const {
    return name == o.name && mesh == o.mesh && parent == o.parent && material == o.material &&
           texture == o.texture && tint == o.tint && reflectivity == o.reflectivity &&
           transparency == o.transparency && refractive_index == o.refractive_index &&
           dynamics == o.dynamics && gravity == o.gravity && mass == o.mass &&
           initial_velocity == o.initial_velocity && restitution == o.restitution &&
           friction == o.friction && rotates == o.rotates &&
           angular_velocity == o.angular_velocity && collision_sound == o.collision_sound &&
           moving_sound == o.moving_sound && rest == o.rest && joint == o.joint;
}

double wrap_degrees(double degrees) {
    double wrapped = std::fmod(degrees, 360.0);
    if (wrapped < 0.0) wrapped += 360.0;
    return wrapped >= 360.0 ? 0.0 : wrapped; // fmod of a tiny negative can round up to 360
}

std::string check_model(const Model &m) {
    if (m.name.empty()) return "a model needs a name";
    if (!colour(m.material.kd) || !colour(m.material.ks))
        return concat("model '", m.name, "': kd and ks must be colours with finite components >= 0");
    if (!std::isfinite(m.material.shininess) || m.material.shininess < 0.0)
        return concat("model '", m.name, "': shininess must be a finite number >= 0");
    if (!in_unit(m.tint)) return concat("model '", m.name, "': tint must be in [0, 1]");
    if (!in_unit(m.reflectivity))
        return concat("model '", m.name, "': reflectivity must be in [0, 1]");
    if (!in_unit(m.transparency))
        return concat("model '", m.name, "': transparency must be in [0, 1]");
    if (!std::isfinite(m.refractive_index) || m.refractive_index <= 0.0)
        return concat("model '", m.name, "': refractive index must be a finite number > 0");
    if (!std::isfinite(m.mass) || m.mass <= 0.0)
        return concat("model '", m.name, "': mass must be a finite number > 0");
    if (!finite(m.initial_velocity))
        return concat("model '", m.name, "': velocity must be finite");
    if (!in_unit(m.restitution))
        return concat("model '", m.name, "': restitution must be in [0, 1]");
    if (!std::isfinite(m.friction) || m.friction < 0.0)
        return concat("model '", m.name, "': friction must be a finite number >= 0");
    if (!finite(m.angular_velocity))
        return concat("model '", m.name, "': angular velocity must be finite");
    for (int c = 0; c < 3; ++c)
        if (!finite(m.rest[c])) return concat("model '", m.name, "': its rest shape must be finite");
    if (!(glm::determinant(m.rest) > 1e-12))
        return concat("model '", m.name, "': its rest shape must keep volume > 0 (no mirror, no flattening)");
    if (m.joint) {
        const JointRange &j = *m.joint;
        if (!finite(j.min) || !finite(j.max))
            return concat("model '", m.name, "': its joint range must be finite");
        for (int a = 0; a < 3; ++a)
            if (!(j.min[a] <= j.max[a]))
                return concat("model '", m.name, "': its joint's ", "xyz"[a], " range must have min <= max");
    }
    return "";
}

std::string check_state(const ModelState &s) {
    if (!finite(s.center)) return "center must be finite";
    for (int i = 0; i < 3; ++i)
        if (!(s.angles[i] >= 0.0 && s.angles[i] < 360.0)) return "angles must be in [0, 360)";
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(s.scale[i]) || s.scale[i] <= 0.0) return "scale must be finite and > 0";
    if (!finite(s.turn)) return "rotation direction must be finite";
    return "";
}

std::string check_camera(const CameraState &c) {
    if (!finite(c.position)) return "camera position must be finite";
    const double n = glm::length(c.rotation);
    if (!std::isfinite(n) || std::abs(n - 1.0) > 1e-6) return "camera rotation must be a unit quaternion";
    if (!(c.fov_degrees > 0.0 && c.fov_degrees < 180.0)) return "camera fov must be in (0, 180) degrees";
    return "";
}

std::string check_settings(const Settings &s) {
    if (s.max_time_ms < Settings::kMinMaxTimeMs || s.max_time_ms > Settings::kMaxMaxTimeMs)
        return "max time must be between 1 s and 300000 s";
    if (!std::isfinite(s.gravity)) return "gravity must be finite";
    if (s.down_axis != Axis::X && s.down_axis != Axis::Y && s.down_axis != Axis::Z)
        return "down axis must be x, y or z";
    if (s.physics_backend.empty()) return "a physics backend id is needed";
    if (s.interpolation.empty()) return "an interpolation plugin id is needed";
    for (const auto &[plugin, values] : s.params)
        for (const auto &[param, value] : values) {
            for (double v : value)
                if (!std::isfinite(v))
                    return concat("parameter ", plugin, ".", param, " must be finite");
        }
    if (s.lights.size() > Settings::kMaxLights)
        return concat("a scene has at most ", Settings::kMaxLights, " lights, this one ", s.lights.size());
    for (const Light &l : s.lights) {
        if (!finite(l.position)) return concat("light '", l.name, "': position must be finite");
        if (!colour(l.colour)) return concat("light '", l.name, "': colour must be finite and >= 0");
        if (!colour(l.falloff) || !(l.falloff.x + l.falloff.y + l.falloff.z > 0.0))
            return concat("light '", l.name, "': falloff must be three finite numbers >= 0, not all 0");
    }
    if (!colour(s.ambient)) return "ambient light must be finite and >= 0";
    if (s.render_width < 0 || s.render_height < 0 || s.render_width > 16384 || s.render_height > 16384)
        return "the render size must be 0 (the default) or 1 to 16384 pixels";
    return "";
}

Document::Document() {
    Keyframe initial;
    initial.camera = CameraState{};
    keyframes_.push_back(initial);
}

int Document::find_model(const std::string &name) const {
    const auto it = by_name_.find(name);
    return it == by_name_.end() ? -1 : it->second;
}

int Document::find_keyframe(std::int64_t time_ms) const {
    auto it = std::lower_bound(keyframes_.begin(), keyframes_.end(), time_ms,
                               [](const Keyframe &k, std::int64_t t) { return k.time_ms < t; });
    if (it == keyframes_.end() || it->time_ms != time_ms) return -1;
    return static_cast<int>(it - keyframes_.begin());
}

const Keyframe &Document::keyframe_at(std::int64_t time_ms) const {
    const int i = find_keyframe(time_ms);
    if (i < 0) throw DocumentError(concat("no keyframe at ", time_ms, " ms"));
    return keyframes_[static_cast<size_t>(i)];
}

Keyframe &Document::mutable_keyframe(std::int64_t time_ms) {
    return const_cast<Keyframe &>(keyframe_at(time_ms));
}

void Document::add_model(const Model &model, const ModelState &state) {
    if (auto problem = check_model(model); !problem.empty()) throw DocumentError(problem);
    if (auto problem = check_state(state); !problem.empty())
        throw DocumentError(concat("model '", model.name, "': ", problem));
    if (find_model(model.name) >= 0)
        throw DocumentError(concat("a model named '", model.name, "' already exists"));
    if (model.parent < -1 || model.parent >= static_cast<int>(models_.size()))
        throw DocumentError(concat("model '", model.name, "': parent ", model.parent,
                                   " is not an earlier model"));
    by_name_[model.name] = static_cast<int>(models_.size());
    models_.push_back(model);
    for (auto &k : keyframes_) k.states.push_back(k.time_ms == 0 ? std::optional<ModelState>(state) : std::nullopt);
}

void Document::remove_last_model() {
    if (models_.empty()) throw DocumentError("there is no model to remove");
    by_name_.erase(models_.back().name);
    models_.pop_back();
    for (auto &k : keyframes_) k.states.pop_back();
}

void Document::set_model(int index, const Model &model) {
    if (index < 0 || index >= static_cast<int>(models_.size()))
        throw DocumentError(concat("no model ", index));
    if (auto problem = check_model(model); !problem.empty()) throw DocumentError(problem);
    const int other = find_model(model.name);
    if (other >= 0 && other != index)
        throw DocumentError(concat("a model named '", model.name, "' already exists"));
    if (model.parent < -1 || model.parent >= index)
        throw DocumentError(concat("model '", model.name, "': parent ", model.parent,
                                   " is not an earlier model"));
    by_name_.erase(models_[static_cast<size_t>(index)].name);
    by_name_[model.name] = index;
    models_[static_cast<size_t>(index)] = model;
}

void Document::insert_keyframe(const Keyframe &keyframe) {
    if (keyframe.time_ms < 0 || keyframe.time_ms > settings_.max_time_ms)
        throw DocumentError(concat("keyframe time ", keyframe.time_ms, " ms is outside 0 .. ",
                                   settings_.max_time_ms, " ms"));
    if (find_keyframe(keyframe.time_ms) >= 0)
        throw DocumentError(concat("there is already a keyframe at ", keyframe.time_ms, " ms"));
    if (keyframe.states.size() != models_.size())
        throw DocumentError(concat("keyframe at ", keyframe.time_ms, " ms has ",
                                   keyframe.states.size(), " model states for ", models_.size(),
                                   " models"));
    for (size_t i = 0; i < keyframe.states.size(); ++i) {
        if (!keyframe.states[i]) {
            if (keyframe.time_ms == 0)
                throw DocumentError(concat("the keyframe at t = 0 must key model '", models_[i].name, "'"));
            continue;
        }
        if (auto problem = check_state(*keyframe.states[i]); !problem.empty())
            throw DocumentError(concat("keyframe at ", keyframe.time_ms, " ms, model '",
                                       models_[i].name, "': ", problem));
    }
    if (!keyframe.camera && keyframe.time_ms == 0)
        throw DocumentError("the keyframe at t = 0 must key the camera");
    if (keyframe.camera)
        if (auto problem = check_camera(*keyframe.camera); !problem.empty())
            throw DocumentError(concat("keyframe at ", keyframe.time_ms, " ms: ", problem));
    auto at = std::upper_bound(keyframes_.begin(), keyframes_.end(), keyframe.time_ms,
                               [](std::int64_t t, const Keyframe &k) { return t < k.time_ms; });
    keyframes_.insert(at, keyframe);
}

Keyframe Document::delete_keyframe(std::int64_t time_ms) {
    if (time_ms == 0) throw DocumentError("the keyframe at t = 0 cannot be deleted");
    const int i = find_keyframe(time_ms);
    if (i < 0) throw DocumentError(concat("no keyframe at ", time_ms, " ms"));
    Keyframe removed = keyframes_[static_cast<size_t>(i)];
    keyframes_.erase(keyframes_.begin() + i);
    return removed;
}

void Document::set_state(std::int64_t keyframe_ms, int model, const std::optional<ModelState> &state) {
    if (model < 0 || model >= static_cast<int>(models_.size()))
        throw DocumentError(concat("no model ", model));
    const std::string &name = models_[static_cast<size_t>(model)].name;
    if (!state && keyframe_ms == 0)
        throw DocumentError(concat("model '", name, "' cannot be unkeyed at t = 0"));
    if (state)
        if (auto problem = check_state(*state); !problem.empty())
            throw DocumentError(concat("model '", name, "': ", problem));
    mutable_keyframe(keyframe_ms).states[static_cast<size_t>(model)] = state;
}

void Document::set_camera(std::int64_t keyframe_ms, const std::optional<CameraState> &camera) {
    if (!camera && keyframe_ms == 0) throw DocumentError("the camera cannot be unkeyed at t = 0");
    if (camera)
        if (auto problem = check_camera(*camera); !problem.empty()) throw DocumentError(problem);
    mutable_keyframe(keyframe_ms).camera = camera;
}

std::vector<const Keyframe *> Document::keys_of(int model) const {
    std::vector<const Keyframe *> out;
    for (const Keyframe &k : keyframes_)
        if (model < 0 ? k.camera.has_value() : k.states[static_cast<size_t>(model)].has_value())
            out.push_back(&k);
    return out;
}

std::vector<Keyframe> Document::set_settings(const Settings &settings) {
    if (auto problem = check_settings(settings); !problem.empty()) throw DocumentError(problem);
    std::vector<Keyframe> removed;
    // Shortening the animation deletes every keyframe past the new max time (seed, "The
    // Animator Interface"); t = 0 is always kept since max time is at least 1 s.
    while (keyframes_.back().time_ms > settings.max_time_ms) {
        removed.insert(removed.begin(), keyframes_.back());
        keyframes_.pop_back();
    }
    settings_ = settings;
    return removed;
}

} // namespace animator
