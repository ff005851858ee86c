// The motion of a baked timeline as keys (docs/export.md, "What is exact"): for every model its
// translation, rotation and scale in its parent's frame, and the camera's, over [from, until].
//
// Translation and scale are cubic Hermite keys (motion_keys.hpp): a key at every keyframe and
// every event, each span the closed form's own cubic (free flight's parabola, the interpolators'
// spans), exact to rounding; only a model turned about a point that is not its origin (its
// centre of mass), or carried by another model, is sampled. Rotation is slerped keys: exact for a
// turn at a constant rate about a fixed axis (keys at most 90 degrees apart), sampled within a
// bound for keyed Euler angles, torque-free tumbling, spin-up, hinges and carried models.
#pragma once

#include "export/motion_keys.hpp"
#include "timeline/timeline.hpp"

#include <vector>

namespace animator {

struct NodeKeys {
    std::vector<motion_keys::VecKey> translation, scale;
    std::vector<motion_keys::QuatKey> rotation;
};

struct MotionKeyOptions {
    double from = 0.0, until = 0.0; // seconds, within what the timeline has baked
    // > 0: one key per frame at this rate (LINEAR), as Blender and Maya bake, instead of the
    // exact keys; for clients that read only LINEAR.
    double fps = 0.0;
    double rotation_tolerance = 1e-5; // radians: largest angle a sampled rotation strays
    double position_tolerance = 1e-9; // relative to 1 + |value|: a sampled translation or scale
};

struct MotionKeyStats {
    motion_keys::PieceStats translation, rotation, scale;
};

struct MotionKeys {
    std::vector<NodeKeys> models; // one per model of the document, in its order
    NodeKeys camera;              // its translation and rotation (no scale)
    MotionKeyStats stats;
};

// The keyed orientation of Euler angles in degrees: Rx(x) Ry(y) Rz(z), about the model's own axes
// (docs/ani-format.md).
glm::dquat euler_rotation(const glm::dvec3 &degrees);

MotionKeys motion_keys_of(const Timeline &timeline, const MotionKeyOptions &options);

} // namespace animator
