// A course puppet's joint range in the editor (docs/manual.md, "Joints"): as the CS488 puppet
// viewer did, a turn of a model with a joint range (Model::joint) stops at the range's ends.
// One rule for every way of turning a model (the mouse's Rotate drags, the gizmo's rings, the
// Transform section's Rotation fields), pure and tested without a window
// (tests/session/joint_clamp_test.cpp).
#pragma once

#include "document/document.hpp"

#include <array>
#include <string>

namespace animator {

// An angle in degrees read signed, in (-180, 180]: 350 reads -10, 180 reads 180.
double signed_degrees(double degrees);

struct JointClamp {
    ModelState state;
    std::array<bool, 3> stopped{false, false, false}; // the angles the range held back
    bool any() const { return stopped[0] || stopped[1] || stopped[2]; }
};

// `to`, a turn of `model` from `from` (the state the turn started from), with each angle held in
// the model's joint range (none: `to` as it is). An angle is read signed; a range whose max - min
// is 360 or more does not clamp. An angle outside its range goes to the end the turn was heading
// for: the max for a turn that increased it (to.turn < 0, the seed's ccw), the min for one that
// decreased it, so a drag carried on past the max stays there even after the angle, read signed,
// has come round past 180 (an angle not turned, or with no direction, goes to the nearer end of
// the signed reading: below the min to the min, above the max to the max); an angle the turn did
// not change is left as it is, inside its range or not. Each angle turned
// records the direction from `from` to where it ends inside the range (`turn`), so the keys
// interpolate through the joint's range and never the other way round; an angle held where it
// was keeps `from`'s angle and turn. Angles stay wrapped in [0, 360).
JointClamp clamp_to_joint(const Model &model, const ModelState &from, const ModelState &to);

// "x -90..45, y 0..0, z 0..0" (the Model panel's "Joint:" line).
std::string joint_range_text(const JointRange &range);

// The status line's note for a turn held back: "'arm' stopped at its joint range (x -30..30)",
// naming the axes stopped; "" when none was.
std::string joint_stop_text(const Model &model, const JointClamp &clamp);

} // namespace animator
