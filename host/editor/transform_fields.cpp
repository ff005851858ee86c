#include "editor/transform_fields.hpp"

namespace animator {

TransformValues transform_values(const ModelState &s) { return {s.center, s.angles, s.scale}; }

std::array<bool, 3> transform_mixed(const std::vector<ModelState> &states) {
    std::array<bool, 3> mixed{false, false, false};
    if (states.empty()) return mixed;
    const TransformValues first = transform_values(states.front());
    for (const ModelState &s : states) {
        const TransformValues v = transform_values(s);
        for (int row = 0; row < 3; ++row)
            if (v.row(row) != first.row(row)) mixed[static_cast<size_t>(row)] = true;
    }
    return mixed;
}

ModelState with_edited_components(const ModelState &s, const TransformValues &shown, const TransformValues &edited) {
    ModelState out = s;
    for (int i = 0; i < 3; ++i) {
        if (edited.position[i] != shown.position[i]) out.center[i] = edited.position[i];
        if (edited.scale[i] != shown.scale[i]) out.scale[i] = edited.scale[i];
        if (edited.rotation[i] != shown.rotation[i]) {
            out.angles[i] = wrap_degrees(edited.rotation[i]);
            out.turn[i] = edited.rotation[i] > shown.rotation[i] ? -1.0 : 1.0; // the seed's ccw is -1
        }
    }
    return out;
}

} // namespace animator
