// Free motion after a model's last keyframe (seed, "Motion after the Final Keyframe"), as closed
// forms: the four cases of Dynamics x Gravity.
#pragma once

#include <animator/physics.h>

namespace physics_custom {

// The acceleration of gravity: `gravity` m/s^2 toward -down_axis.
ani_vec3 gravity_vector(double gravity, int down_axis);

// The free segment of a model from time t0 with state `start` (center and velocity at t0):
//  Dynamics off, Gravity off: it stays where it is (REST).
//  Dynamics off, Gravity on:  it falls, center[down] -= G tau^2 / 2, from rest.
//  Dynamics on,  Gravity off: constant velocity, the velocity it had at t0.
//  Dynamics on,  Gravity on:  projectile, that velocity plus gravity.
// A model with Dynamics off carries no velocity out of its keyframes: it stops or drops.
ani_motion_segment free_segment(uint32_t model, const ani_model_desc &desc, const ani_body_state &start,
                                double t0, double t1, const ani_vec3 &gravity);

// center(t) and velocity(t) of a segment (FREE or REST) at time t.
ani_vec3 segment_position(const ani_motion_segment &s, double t);
ani_vec3 segment_velocity(const ani_motion_segment &s, double t);

} // namespace physics_custom
