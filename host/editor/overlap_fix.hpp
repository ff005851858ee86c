// Models the physics backend found overlapping (Timeline::overlaps(): each pair once, with the
// backend's normal and depth), as the editor shows them, and its one-click fix: lift one model
// of the pair out of the other the shortest way, as one undoable edit.
#pragma once

#include "assets/mesh.hpp"
#include "document/edits.hpp"

#include <animator/physics.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace animator {

// Which model moves, and how: `moved` is the root of the jointed model (the scene root's child
// it hangs under, whose key is in world coordinates), so the whole jointed model moves as one.
struct LiftOut {
    int moved = -1;                // the model whose key changes
    int other = -1;                // the model it is lifted out of
    std::int64_t keyframe_ms = 0;  // its key at or before the overlap (at t = 0: its placement)
    glm::dvec3 offset{0.0};        // added to that key's center
    std::string label;             // "lift 'cube' out of 'floor'"
};

// Of the pair, the model that physics moves (Dynamics or Gravity) is lifted out of the other;
// of two such or none, the one with a key at the overlap's time (the key that put it there),
// else the smaller (bounding sphere). The offset is the backend's depth along
// its normal: the shortest way out it measured. Nullopt (with the reason) when no model can move
// (a pair with no direction: two spheres with one center).
std::optional<LiftOut> plan_lift_out(const Document &doc, const std::vector<std::shared_ptr<const Mesh>> &meshes,
                                     const ani_overlap &overlap, std::string *why = nullptr);

// The edit that does it.
std::unique_ptr<Edit> lift_out_edit(const LiftOut &lift);

// "'cube' and 'floor' overlap by 0.5 m at 0 s".
std::string describe_overlap(const Document &doc, const ani_overlap &overlap);

// Every model named in an overlap, for the view to flag.
std::set<int> overlapping_models(const std::vector<ani_overlap> &overlaps, std::size_t model_count);

} // namespace animator
