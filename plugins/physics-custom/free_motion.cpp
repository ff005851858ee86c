#include "free_motion.hpp"

namespace physics_custom {

ani_vec3 gravity_vector(double gravity, int down_axis) {
    ani_vec3 g{0.0, 0.0, 0.0};
    double *axis[3] = {&g.x, &g.y, &g.z};
    *axis[down_axis >= 0 && down_axis <= 2 ? down_axis : 1] = -gravity;
    return g;
}

ani_motion_segment free_segment(uint32_t model, const ani_model_desc &desc, const ani_body_state &start,
                                double t0, double t1, const ani_vec3 &gravity) {
    ani_motion_segment s{};
    s.model = model;
    s.t0 = t0;
    s.t1 = t1;
    s.p0 = start.center;
    const bool dynamics = desc.dynamics != 0, falls = desc.gravity != 0;
    // Dynamics off: the model keeps no velocity of its own; with Gravity it drops from rest,
    // except that a fall already under way (a resumed bake) goes on.
    const bool carries_velocity = dynamics || (falls && start.motion == ANI_MOTION_FREE);
    s.v0 = carries_velocity ? start.velocity : ani_vec3{0.0, 0.0, 0.0};
    s.a = falls ? gravity : ani_vec3{0.0, 0.0, 0.0};
    const bool moves = falls || s.v0.x != 0.0 || s.v0.y != 0.0 || s.v0.z != 0.0;
    s.motion = moves ? ANI_MOTION_FREE : ANI_MOTION_REST;
    return s;
}

ani_vec3 segment_position(const ani_motion_segment &s, double t) {
    const double tau = t - s.t0;
    return ani_vec3{s.p0.x + s.v0.x * tau + 0.5 * s.a.x * tau * tau,
                    s.p0.y + s.v0.y * tau + 0.5 * s.a.y * tau * tau,
                    s.p0.z + s.v0.z * tau + 0.5 * s.a.z * tau * tau};
}

ani_vec3 segment_velocity(const ani_motion_segment &s, double t) {
    const double tau = t - s.t0;
    return ani_vec3{s.v0.x + s.a.x * tau, s.v0.y + s.a.y * tau, s.v0.z + s.a.z * tau};
}

} // namespace physics_custom
