#include "editor/model_fields.hpp"

#include <string>
#include <type_traits>
#include <vector>

namespace animator {

namespace {

// Calls f with a reference to `field` in model m (the same member of any model).
template <class M, class F> auto with_field(ModelField field, M &m, F &&f) {
    switch (field) {
    case ModelField::Dynamics: return f(m.dynamics);
    case ModelField::Gravity: return f(m.gravity);
    case ModelField::Mass: return f(m.mass);
    case ModelField::Velocity: return f(m.initial_velocity);
    case ModelField::Kd: return f(m.material.kd);
    case ModelField::Ks: return f(m.material.ks);
    case ModelField::Texture: return f(m.texture);
    case ModelField::Tint: return f(m.tint);
    case ModelField::Shininess: return f(m.material.shininess);
    case ModelField::Reflectivity: return f(m.reflectivity);
    case ModelField::Transparency: return f(m.transparency);
    case ModelField::RefractiveIndex: return f(m.refractive_index);
    case ModelField::CollisionSound: return f(m.collision_sound);
    case ModelField::MovingSound: return f(m.moving_sound);
    case ModelField::Restitution: return f(m.restitution);
    case ModelField::Friction: return f(m.friction);
    case ModelField::Rotates: return f(m.rotates);
    case ModelField::AngularVelocity: return f(m.angular_velocity);
    }
    throw DocumentError("unknown model field " + std::to_string(static_cast<int>(field)));
}

const Model &model_at(const Document &doc, int index) {
    if (index < 0 || index >= static_cast<int>(doc.models().size()))
        throw DocumentError("no model " + std::to_string(index));
    return doc.models()[static_cast<size_t>(index)];
}

} // namespace

void copy_field(ModelField field, const Model &from, Model &to) {
    with_field(field, to, [&](auto &target) {
        with_field(field, from, [&](const auto &source) {
            if constexpr (std::is_same_v<std::decay_t<decltype(target)>, std::decay_t<decltype(source)>>) target = source;
        });
    });
}

bool same_field(ModelField field, const Model &a, const Model &b) {
    Model copy = b;
    copy_field(field, a, copy);
    return copy == b;
}

bool field_mixed(const Document &doc, const std::set<int> &models, ModelField field) {
    if (models.empty()) return false;
    const Model &first = model_at(doc, *models.begin());
    for (int m : models)
        if (!same_field(field, first, model_at(doc, m))) return true;
    return false;
}

std::unique_ptr<Edit> field_edit(const Document &doc, const std::set<int> &models, ModelField field, const Model &from) {
    std::vector<std::unique_ptr<Edit>> edits;
    for (int m : models) {
        Model after = model_at(doc, m);
        if (same_field(field, from, after)) continue;
        copy_field(field, from, after);
        edits.push_back(std::make_unique<SetModelEdit>(m, after));
    }
    if (edits.empty()) return nullptr;
    if (edits.size() == 1) return std::move(edits.front());
    const std::string label = "change " + std::to_string(edits.size()) + " models";
    return std::make_unique<CompositeEdit>(label, std::move(edits));
}

std::string trim_name(const std::string &name) {
    const auto first = name.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return "";
    const auto last = name.find_last_not_of(" \t\r\n");
    return name.substr(first, last - first + 1);
}

std::string check_rename(const Document &doc, int index, const std::string &name) {
    const Model &m = model_at(doc, index);
    if (name.empty()) return "a model needs a name: '" + m.name + "' keeps its own";
    const int other = doc.find_model(name);
    if (other >= 0 && other != index)
        return "cannot rename '" + m.name + "' to '" + name + "': another model is named so (names are unique)";
    return "";
}

} // namespace animator
