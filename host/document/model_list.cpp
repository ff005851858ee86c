#include "document/model_list.hpp"

#include <cctype>
#include <cstdio>

namespace animator {

namespace {

// A document with `models` and, per keyframe of `doc` (same times, same cameras), `states`.
Document assemble(const Document &doc, const std::vector<Model> &models,
                  const std::vector<std::vector<std::optional<ModelState>>> &states) {
    Document out;
    out.set_settings(doc.settings());
    const auto &keys = doc.keyframes();
    for (size_t m = 0; m < models.size(); ++m) out.add_model(models[m], *states[0][m]);
    out.set_camera(0, keys[0].camera);
    for (size_t k = 1; k < keys.size(); ++k) {
        Keyframe key;
        key.time_ms = keys[k].time_ms;
        key.camera = keys[k].camera;
        key.states = states[k];
        out.insert_keyframe(key);
    }
    return out;
}

std::vector<std::vector<std::optional<ModelState>>> states_of(const Document &doc) {
    std::vector<std::vector<std::optional<ModelState>>> states;
    for (const Keyframe &k : doc.keyframes()) states.push_back(k.states);
    return states;
}

// "cube.001" -> "cube"; anything else as it is.
std::string stem_of(const std::string &name) {
    const auto dot = name.rfind('.');
    if (dot == std::string::npos || dot == 0 || name.size() - dot != 4) return name;
    for (size_t i = dot + 1; i < name.size(); ++i)
        if (!std::isdigit(static_cast<unsigned char>(name[i]))) return name;
    return name.substr(0, dot);
}

} // namespace

std::set<int> with_descendants(const Document &doc, const std::set<int> &models) {
    std::set<int> out;
    const auto &all = doc.models();
    // Parents come before their children, so one pass in order finds every level.
    for (int m = 0; m < static_cast<int>(all.size()); ++m) {
        const int parent = all[static_cast<size_t>(m)].parent;
        if (models.count(m) || (parent >= 0 && out.count(parent))) out.insert(m);
    }
    return out;
}

Document without_models(const Document &doc, const std::set<int> &removed) {
    if (with_descendants(doc, removed) != removed)
        throw DocumentError("a model under a deleted one would be left without its parent");
    const auto &all = doc.models();
    std::vector<int> new_index(all.size(), -1);
    std::vector<Model> models;
    for (size_t m = 0; m < all.size(); ++m) {
        if (removed.count(static_cast<int>(m))) continue;
        new_index[m] = static_cast<int>(models.size());
        Model model = all[m];
        if (model.parent >= 0) model.parent = new_index[static_cast<size_t>(model.parent)];
        models.push_back(std::move(model));
    }
    auto states = states_of(doc);
    for (auto &row : states) {
        std::vector<std::optional<ModelState>> kept;
        for (size_t m = 0; m < row.size(); ++m)
            if (!removed.count(static_cast<int>(m))) kept.push_back(row[m]);
        row = std::move(kept);
    }
    return assemble(doc, models, states);
}

Document with_copies(const Document &doc, const std::vector<ModelCopy> &copies) {
    std::vector<Model> models = doc.models();
    auto states = states_of(doc);
    std::vector<int> copy_of(models.size(), -1); // original -> its copy's index
    for (const ModelCopy &c : copies) {
        if (c.original < 0 || c.original >= static_cast<int>(doc.models().size()))
            throw DocumentError("no model " + std::to_string(c.original) + " to copy");
        Model model = doc.models()[static_cast<size_t>(c.original)];
        model.name = c.name;
        const bool parent_copied = model.parent >= 0 && copy_of[static_cast<size_t>(model.parent)] >= 0;
        if (parent_copied) model.parent = copy_of[static_cast<size_t>(model.parent)];
        copy_of[static_cast<size_t>(c.original)] = static_cast<int>(models.size());
        models.push_back(std::move(model));
        for (auto &row : states) {
            std::optional<ModelState> s = row[static_cast<size_t>(c.original)];
            if (s) s->center += c.offset;
            row.push_back(s);
        }
    }
    return assemble(doc, models, states); // add_model refuses a taken or empty name
}

std::string unique_model_name(const Document &doc, const std::string &base, const std::set<std::string> &also_taken) {
    const auto taken = [&](const std::string &name) { return doc.find_model(name) >= 0 || also_taken.count(name) > 0; };
    if (!base.empty() && !taken(base)) return base;
    const std::string stem = base.empty() ? "model" : stem_of(base);
    if (base.empty() && !taken(stem)) return stem;
    for (int n = 1;; ++n) {
        char suffix[16];
        std::snprintf(suffix, sizeof suffix, ".%03d", n);
        if (!taken(stem + suffix)) return stem + suffix;
    }
}

void ReplaceDocumentEdit::apply(Document &doc) {
    if (!(doc == before_)) throw DocumentError("the document changed since this edit was made");
    doc = after_;
}

} // namespace animator
