// The Model Interface's Transform section (docs/manual.md): Position, Rotation (degrees) and
// Scale of the last selected model at the current time, typed or dragged; a change keys every
// selected model at the current time, each getting only the component changed (the others stay
// its own), as the other fields do (model_fields.hpp). Pure, tested without a window
// (tests/session/gizmo_test.cpp).
#pragma once

#include "document/document.hpp"

#include <array>
#include <vector>

namespace animator {

struct TransformValues {
    glm::dvec3 position{0.0}, rotation{0.0}, scale{1.0};
    glm::dvec3 &row(int i) { return i == 0 ? position : i == 1 ? rotation : scale; }
    const glm::dvec3 &row(int i) const { return i == 0 ? position : i == 1 ? rotation : scale; }
};

TransformValues transform_values(const ModelState &s);

// For each row (position, rotation, scale): true when its values differ among `states`.
std::array<bool, 3> transform_mixed(const std::vector<ModelState> &states);

// `s` with every component that differs between `shown` and `edited` set to `edited`'s. An
// angle is wrapped into [0, 360) and its turn recorded in the direction it was changed (up is
// counter-clockwise: docs/interpolation.md); a scale must stay > 0 (the widget keeps it so).
ModelState with_edited_components(const ModelState &s, const TransformValues &shown, const TransformValues &edited);

} // namespace animator
