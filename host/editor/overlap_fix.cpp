#include "editor/overlap_fix.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace animator {

namespace {

std::string number(double x) {
    std::ostringstream out;
    out << std::setprecision(3) << (std::abs(x) < 1e-12 ? 0.0 : x);
    return out.str();
}

int group_root(const Document &doc, int m) {
    const auto &models = doc.models();
    for (int guard = 0; guard < static_cast<int>(models.size()) && models[static_cast<size_t>(m)].parent >= 0; ++guard)
        m = models[static_cast<size_t>(m)].parent;
    return m;
}

bool moved_by_physics(const Model &m) { return m.dynamics || m.gravity; }

// The model's latest key at or before t (its placement at t = 0 always is one).
const Keyframe *key_before(const Document &doc, int model, double t) {
    const auto t_ms = static_cast<std::int64_t>(std::floor(t * 1000.0 + 1e-6));
    const Keyframe *found = nullptr;
    for (const Keyframe *k : doc.keys_of(model))
        if (k->time_ms <= t_ms) found = k;
    return found;
}

// The size of a model's bounding sphere at its key (0 for an empty).
double size_of(const Document &doc, const std::vector<std::shared_ptr<const Mesh>> &meshes, int model, double t) {
    const auto m = static_cast<size_t>(model);
    if (m >= meshes.size() || !meshes[m]) return 0.0;
    double scale = 1.0;
    if (const Keyframe *k = key_before(doc, model, t))
        if (const auto &s = k->states[m]) scale = std::max({std::abs(s->scale.x), std::abs(s->scale.y), std::abs(s->scale.z)});
    return meshes[m]->bound_radius * scale;
}

} // namespace

std::optional<LiftOut> plan_lift_out(const Document &doc, const std::vector<std::shared_ptr<const Mesh>> &meshes,
                                     const ani_overlap &overlap, std::string *why) {
    auto fail = [&](const std::string &reason) -> std::optional<LiftOut> {
        if (why) *why = reason;
        return std::nullopt;
    };
    const auto count = doc.models().size();
    if (overlap.a >= count || overlap.b >= count || overlap.a == overlap.b) return fail("no such models");
    const int a = static_cast<int>(overlap.a), b = static_cast<int>(overlap.b);
    const glm::dvec3 normal(overlap.normal.x, overlap.normal.y, overlap.normal.z);
    if (!(glm::length(normal) > 0.5) || !(overlap.depth > 0.0) || !std::isfinite(overlap.depth))
        return fail(describe_overlap(doc, overlap) + " with no way out to lift along (one center)");
    const Model &ma = doc.models()[overlap.a], &mb = doc.models()[overlap.b];
    // A key at the overlap's time put that model there (a drag that keys a model into another).
    auto keyed_then = [&](int m) {
        const Keyframe *k = key_before(doc, group_root(doc, m), overlap.t);
        return k && overlap.t > 0.0 && std::abs(static_cast<double>(k->time_ms) / 1000.0 - overlap.t) < 0.0015;
    };
    bool move_a = true;
    if (moved_by_physics(ma) != moved_by_physics(mb))
        move_a = moved_by_physics(ma);
    else if (keyed_then(a) != keyed_then(b))
        move_a = keyed_then(a);
    else
        move_a = size_of(doc, meshes, a, overlap.t) <= size_of(doc, meshes, b, overlap.t);

    LiftOut lift;
    lift.moved = group_root(doc, move_a ? a : b);
    lift.other = move_a ? b : a;
    const Keyframe *key = key_before(doc, lift.moved, overlap.t);
    if (!key) return fail("'" + doc.models()[static_cast<size_t>(lift.moved)].name + "' has no key to move");
    lift.keyframe_ms = key->time_ms;
    // The normal points from b towards a: a goes along it, b against it.
    lift.offset = (move_a ? 1.0 : -1.0) * overlap.depth * glm::normalize(normal);
    lift.label = "lift '" + doc.models()[static_cast<size_t>(lift.moved)].name + "' out of '" +
                 doc.models()[static_cast<size_t>(lift.other)].name + "'";
    return lift;
}

std::unique_ptr<Edit> lift_out_edit(const LiftOut &lift) {
    return std::make_unique<MoveKeyEdit>(lift.label, lift.keyframe_ms, lift.moved, lift.offset);
}

std::string describe_overlap(const Document &doc, const ani_overlap &overlap) {
    auto name = [&](uint32_t m) { return m < doc.models().size() ? doc.models()[m].name : "?"; };
    return "'" + name(overlap.a) + "' and '" + name(overlap.b) + "' overlap by " + number(overlap.depth) +
           " m at " + number(overlap.t) + " s";
}

std::set<int> overlapping_models(const std::vector<ani_overlap> &overlaps, std::size_t model_count) {
    std::set<int> out;
    for (const ani_overlap &o : overlaps) {
        if (o.a < model_count) out.insert(static_cast<int>(o.a));
        if (o.b < model_count) out.insert(static_cast<int>(o.b));
    }
    return out;
}

} // namespace animator
