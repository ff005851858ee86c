/* animator plugin SDK: physics backends (ANI_KIND_PHYSICS).
 *
 * A backend bakes a scene: given the models, their meshes, which spans of time each one is
 * driven by its keyframes, and the state of every model at t_begin, it reports the motion of
 * every model from t_begin to t_end as segments, and every collision as an event. The host owns
 * the canonical scene and caches what the backend reports, so a backend can be swapped at run
 * time by destroying one instance and creating another.
 *
 * Between events a segment is a closed form: center(t) = p0 + v0 (t - t0) + a (t - t0)^2 / 2.
 * An analytic backend reports one segment per free flight; a stepping backend one per step,
 * or one per stretch of steps that lie on the same parabola.
 * Times here are in seconds.
 */
#ifndef ANIMATOR_SDK_PHYSICS_H
#define ANIMATOR_SDK_PHYSICS_H

#include "animator/document.h"
#include "animator/instance.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ANI_NO_MODEL 0xffffffffu

/* A triangle mesh in the model's own coordinates (before its keyframed transform). */
typedef struct ani_mesh_view {
    uint32_t struct_size;
    const double *positions;    /* 3 per vertex */
    uint32_t vertex_count;
    const uint32_t *triangles;  /* 3 vertex indices per triangle, counter-clockwise outward */
    uint32_t triangle_count;
    ani_vec3 bound_center;      /* the seed's bounding sphere: mean of the vertices */
    double bound_radius;        /* largest distance from bound_center to a vertex */
    int32_t is_sphere;          /* 1 when the mesh is a sphere of bound_radius (closed forms) */
} ani_mesh_view;

typedef struct ani_time_span {
    double begin, end; /* seconds, begin <= end */
} ani_time_span;

/* How a model moves at a given time. */
typedef enum ani_motion_kind {
    ANI_MOTION_KEYED = 1, /* driven by its keyframes (the host's interpolation) */
    ANI_MOTION_FREE = 2,  /* free flight: the closed form of the segment */
    ANI_MOTION_REST = 3,  /* not moving (a = v0 = 0) */
    /* Since ABI 1.8: carried by another model (ani_carried_segment says by which and where);
     * the motion segment's p0, v0 and a are 0 and unused. A host gives a backend a model carried
     * at t_begin as ANI_MOTION_FREE, with its velocity then and start_turning set. */
    ANI_MOTION_CARRIED = 4
} ani_motion_kind;

typedef struct ani_body_state {
    int32_t motion;   /* ani_motion_kind at t_begin */
    ani_vec3 center;
    ani_vec3 velocity;
} ani_body_state;

typedef struct ani_physics_model {
    uint32_t struct_size;
    const ani_model_desc *desc;  /* dynamics, gravity, mass, ... */
    const ani_mesh_view *mesh;
    /* Models with the same group move as one jointed model and never collide with each other
     * (the index of the scene root's child they hang under). */
    uint32_t group;
    const ani_time_span *keyed_spans; /* spans driven by keyframes, sorted, disjoint */
    uint32_t keyed_span_count;
    ani_body_state start;             /* the state at t_begin */
    /* Since ABI 1.1: the times of the model's own keys, sorted (a keyed model released from its
     * keys at a contact takes them up again at the next one). */
    const double *key_times;
    uint32_t key_count;
    /* Since ABI 1.3: when start_turning is 1, the backend turned the model in an earlier bake
     * (a rotation segment covers t_begin) and this is its world orientation and angular velocity
     * (radians per second, world axes) at t_begin; when 0, its keys turn it at t_begin (and a
     * model whose desc->rotates is on starts turning with desc->angular_velocity at t = 0). */
    ani_quat start_orientation;
    ani_vec3 start_angular_velocity;
    int32_t start_turning;
} ani_physics_model;

/* Whether a physics model carries the start orientation of ABI 1.3. */
#define ANI_PHYSICS_MODEL_HAS_TURNING(m)                                                        \
    ((m)->struct_size >= offsetof(ani_physics_model, start_turning) + sizeof(int32_t))

typedef struct ani_physics_scene {
    uint32_t struct_size;
    const ani_physics_model *models;
    uint32_t model_count;
    double gravity;     /* m/s^2 along -down_axis */
    int32_t down_axis;  /* ani_axis */

    /* [thread: any] The keyframed state (and center velocity) of a model at time t in
     * seconds, for keyed models and for rotation/scale of every model. */
    void *host_context;
    ani_status_code (*evaluate_keyed)(void *host_context, uint32_t model, double t,
                                      ani_model_state *state, ani_vec3 *velocity);
} ani_physics_scene;

typedef struct ani_motion_segment {
    uint32_t model;
    int32_t motion;   /* ani_motion_kind */
    double t0, t1;    /* seconds */
    ani_vec3 p0, v0, a;
} ani_motion_segment;

typedef struct ani_collision_event {
    double t;         /* seconds, the time of first contact */
    uint32_t a, b;    /* the two models (b may be ANI_NO_MODEL for a world boundary) */
    ani_vec3 normal;  /* unit normal of the face hit, pointing from b towards a */
    ani_vec3 point;   /* contact point */
    double speed;     /* approach speed along the normal, >= 0 */
} ani_collision_event;

/* Since ABI 1.1: a model's orientation over [t0, t1] when the backend turns it (rigid-body
 * rotation, such as Bullet's "rotate on contact"); where no rotation segment covers a time,
 * the model's keys turn it. q(t) is q0 followed by a turn of |w| (t - t0) radians about the
 * world axis w / |w| (w = 0: q0 throughout). */
typedef struct ani_rotation_segment {
    uint32_t model;
    double t0, t1; /* seconds */
    ani_quat q0;   /* unit; world orientation of the model at t0 */
    ani_vec3 w;    /* angular velocity, radians per second, world frame */
} ani_rotation_segment;

/* Since ABI 1.4: a model's orientation over [t0, t1] when the backend turns it as a rigid body
 * without torque, in closed form: for a body whose principal moments are not all equal (a box, a
 * cylinder) its angular velocity changes as it turns, and a body whose centre of mass is not its
 * origin turns about that point, `pivot`. The principal frame's world orientation at t0 is
 * q0 * principal; its orientation at t is that of the closed form in animator/free_rotation.hpp,
 * ani::FreeRotation(moments, q0 * principal, w0, t0).evaluate(t, ...), and the model's, R(t), is
 * that times conjugate(principal). While such a segment covers t, the model's motion segment gives
 * where its pivot is, c(t), and the model's origin is c(t) - R(t) pivot (its velocity
 * v(t) - w(t) x R(t) pivot). The segments of one model, of both kinds, are in time order. */
typedef struct ani_free_rotation_segment {
    uint32_t model;
    double t0, t1;      /* seconds */
    ani_quat q0;        /* unit; world orientation of the model at t0 */
    ani_vec3 w0;        /* angular velocity at t0, radians per second, world frame */
    ani_vec3 moments;   /* principal moments of inertia, ascending, > 0 (kg m^2) */
    ani_quat principal; /* unit; the principal axes in the model's own frame (model <- principal) */
    ani_vec3 pivot;     /* the point it turns about (its centre of mass) in the model's own frame
                         * as its keys scale it (S p for a point p of its mesh); 0: its origin */
} ani_free_rotation_segment;

/* Since ABI 1.5: a model's orientation over [t0, t1] while its angular velocity changes at a
 * constant rate (a ball skidding on a face, or rolling down a slope, turned by friction):
 * w(t) = w0 + alpha (t - t0), world axes, and the orientation q(t) that solves
 * dq/dt = (w(t) / 2) q from q0 at t0. When w0 and alpha are parallel (or either is 0) that is a
 * turn about their fixed axis by |w0| tau + |alpha| tau^2 / 2 (signed along it), tau = t - t0;
 * otherwise animator/free_rotation.hpp's ani::spun_up evaluates it (the host uses that). */
typedef struct ani_spin_up_segment {
    uint32_t model;
    double t0, t1; /* seconds */
    ani_quat q0;   /* unit; world orientation of the model at t0 */
    ani_vec3 w0;   /* angular velocity at t0, radians per second, world frame */
    ani_vec3 alpha; /* angular acceleration, radians per second squared, world frame */
} ani_spin_up_segment;

/* Since ABI 1.6: a model's orientation over [t0, t1] while it turns about a fixed line under
 * gravity (a box tipping over the edge it stands on): the angle psi of its centre of mass about
 * that line obeys the pendulum psi'' = -omega2 sin psi, from angle0 and rate0 at t0, in the closed
 * form of animator/pendulum.hpp (ani::Pendulum(omega2, angle0, rate0, t0)), and the model's
 * orientation at t is q(t) = turn(axis, psi(t) - angle0) q0; its angular velocity psi'(t) axis. The model turns about
 * `pivot`, a point of the line, in its own frame as scaled; while such a segment covers t, the
 * model's motion segment gives where that point is (it stands still: v0 = a = 0) and its origin is
 * there minus R(t) pivot, as for a free-rotation segment. */
typedef struct ani_hinge_segment {
    uint32_t model;
    double t0, t1;  /* seconds */
    ani_quat q0;    /* unit; world orientation of the model at t0 */
    ani_vec3 axis;  /* unit, world: the direction of the line it turns about */
    double angle0;  /* psi at t0, radians (0: its centre of mass straight below the line) */
    double rate0;   /* psi' at t0, rad/s, right-handed about axis */
    double omega2;  /* > 0, 1/s^2: m g r / I about the line, g across it, r its centre's distance */
    ani_vec3 pivot; /* the point of the line it turns about, in the model's own frame as scaled */
} ani_hinge_segment;

/* Since ABI 1.8: a model carried by another over [t0, t1] (a box that stands on a platform whose
 * keys accelerate it, turn it or lift it, and sticks to it): it moves rigidly with model
 * `carrier`. With c(t) where the carrier's origin is and Q(t) its world orientation (without its
 * scale; from its keys, or from the backend's segments where they turn or move it), the model's
 * origin is c(t) + Q(t) offset and its orientation Q(t) relative; its velocity is the carrier's
 * at that point, v_c(t) + w_c(t) x Q(t) offset, and its angular velocity the carrier's. Its scale
 * is its keys'. The model's motion segments over the span say ANI_MOTION_CARRIED, and no rotation
 * segment of it covers the span. Both models have no parent (they are not parts of a jointed
 * model) and the carrier is not the model; the carrier may itself be carried, but not by a chain
 * that comes back to the model. */
typedef struct ani_carried_segment {
    uint32_t model, carrier;
    double t0, t1;     /* seconds */
    ani_vec3 offset;   /* metres: the model's origin in the carrier's frame (turned, not scaled) */
    ani_quat relative; /* unit: the model's orientation in the carrier's frame */
} ani_carried_segment;

/* Since ABI 1.2: two models found overlapping when they start to interact (at the start of a
 * bake, when a model becomes free inside another, or when its keys take it back inside one).
 * The backend treats them as touching (docs/physics.md, "Models that start overlapping") and
 * reports the pair once per bake, however the host slices it. Moving `a` by depth * normal (or
 * `b` by -depth * normal) parts them. */
typedef struct ani_overlap {
    double t;        /* seconds, when found */
    uint32_t a, b;   /* the two models */
    ani_vec3 normal; /* unit, pointing from b towards a (zero when they share a center) */
    double depth;    /* metres, > 0: how far a is into b along the normal */
} ani_overlap;

/* Where a bake reports what it finds; the host copies what it is given. */
typedef struct ani_bake_sink {
    void *context;
    void (*segment)(void *context, const ani_motion_segment *segment);
    void (*event)(void *context, const ani_collision_event *event);
    /* Reports progress in [0, 1]; returns 0 when the host asks the bake to stop, which then
     * returns ANI_ERR_CANCELLED. */
    int32_t (*progress)(void *context, double fraction);
    /* Since ABI 1.1 (a backend built for 1.1 runs only in a host of 1.1 or newer, which always
     * sets this field, possibly to NULL): a count of the backend's work, reported at the end of
     * a bake, such as "pair tests done"; the host adds the counts of its bakes up by name. */
    void (*count)(void *context, const char *name, double value);
    /* Since ABI 1.1 (may be NULL): the rotation segments of models the backend turns, each
     * model's in time order. */
    void (*rotation)(void *context, const ani_rotation_segment *segment);
    /* Since ABI 1.2 (a backend built for 1.2 runs only in a host of 1.2 or newer, which always
     * sets this field, possibly to NULL): each pair found overlapping, when found. */
    void (*overlap)(void *context, const ani_overlap *overlap);
    /* Since ABI 1.4 (a backend built for 1.4 runs only in a host of 1.4 or newer, which always
     * sets this field, possibly to NULL): the free-rotation segments of models the backend turns.
     * The host refuses the bake when one is not finite or its moments are not ascending and
     * positive (FreeRotation::refusal). */
    void (*free_rotation)(void *context, const ani_free_rotation_segment *segment);
    /* Since ABI 1.5 (a backend built for 1.5 runs only in a host of 1.5 or newer, which always
     * sets this field, possibly to NULL): the spin-up segments of models the backend turns, in
     * time order with their other rotation segments. The host refuses one that is not finite. */
    void (*spin_up)(void *context, const ani_spin_up_segment *segment);
    /* Since ABI 1.6 (a backend built for 1.6 runs only in a host of 1.6 or newer, which always
     * sets this field, possibly to NULL): the hinge segments of models the backend tips over, in
     * time order with their other rotation segments. The host refuses one that is not finite,
     * whose axis is not unit or whose omega2 is not positive (ani::Pendulum::refusal). */
    void (*hinge)(void *context, const ani_hinge_segment *segment);
    /* Since ABI 1.8 (a backend built for 1.8 runs only in a host of 1.8 or newer, which always
     * sets this field, possibly to NULL): the carried segments, each model's in time order, each
     * reported with the ANI_MOTION_CARRIED motion segment of the same span. The host refuses the
     * bake when one is not finite, its relative orientation is zero, or a model or carrier is
     * not one it can carry (see ani_carried_segment). */
    void (*carried)(void *context, const ani_carried_segment *segment);
} ani_bake_sink;

typedef struct ani_physics_api {
    uint32_t struct_size;
    ani_instance_api instance;
    /* Bakes [t_begin, t_end] seconds. Every model's motion over the whole span is reported
     * (segments of one model in time order, covering the span); events in time order. Never
     * reports a NaN or an infinity: a scene that would produce one is refused with a status
     * naming the model. */
    ani_status_code (*bake)(void *instance, const ani_physics_scene *scene, double t_begin,
                            double t_end, const ani_bake_sink *sink, ani_status *status);
} ani_physics_api;

#ifdef __cplusplus
}
#endif

#endif /* ANIMATOR_SDK_PHYSICS_H */
