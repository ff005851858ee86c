#include "editor/joint_clamp.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace animator {

namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

std::string axis_range(const JointRange &range, int axis) {
    static const char *const kAxes[3] = {"x", "y", "z"};
    return std::string(kAxes[axis]) + " " + number(range.min[axis]) + ".." + number(range.max[axis]);
}

} // namespace

double signed_degrees(double degrees) {
    const double a = wrap_degrees(degrees);
    return a > 180.0 ? a - 360.0 : a;
}

JointClamp clamp_to_joint(const Model &model, const ModelState &from, const ModelState &to) {
    JointClamp out{to, {false, false, false}};
    if (!model.joint) return out;
    const JointRange &range = *model.joint;
    for (int i = 0; i < 3; ++i) {
        const double lo = range.min[i], hi = range.max[i];
        if (!(hi - lo < 360.0)) continue; // a whole turn or more: free
        // An angle this turn did not change is left as it is, even outside its range (a joint
        // under a sheared parent reads other angles than its own: docs/scene-lua.md): a turn about
        // one axis never jumps another.
        if (to.angles[i] == from.angles[i]) continue;
        double a = signed_degrees(to.angles[i]);
        if (a < lo || a > hi) {
            if (to.turn[i] != 0.0) a = to.turn[i] < 0.0 ? hi : lo; // the end it was heading for
            else a = a < lo ? lo : hi;
            out.stopped[static_cast<size_t>(i)] = true;
            out.state.angles[i] = wrap_degrees(a);
        }
        // The way from `from` inside the range (a key's turn: docs/interpolation.md); held where
        // it was, the axis is as it was.
        const double start = signed_degrees(from.angles[i]);
        if (a == start) {
            out.state.angles[i] = from.angles[i];
            out.state.turn[i] = from.turn[i];
        } else {
            out.state.turn[i] = a > start ? -1.0 : 1.0;
        }
    }
    return out;
}

std::string joint_range_text(const JointRange &range) {
    return axis_range(range, 0) + ", " + axis_range(range, 1) + ", " + axis_range(range, 2);
}

std::string joint_stop_text(const Model &model, const JointClamp &clamp) {
    if (!model.joint || !clamp.any()) return "";
    std::string axes;
    for (int i = 0; i < 3; ++i)
        if (clamp.stopped[static_cast<size_t>(i)]) axes += (axes.empty() ? "" : ", ") + axis_range(*model.joint, i);
    return "'" + model.name + "' stopped at its joint range (" + axes + ")";
}

} // namespace animator
