/* animator plugin SDK: a document (an animation) as plain C data.
 *
 * File-format plugins read into and write from this view; physics backends receive the models
 * part of it. All pointers are owned by whoever built the view and stay valid for the call (or,
 * for a view returned by a plugin, until the plugin's matching release function).
 *
 * Units: lengths in scene units (1 unit = 1 metre), times in milliseconds for keyframes and max
 * time, angles in degrees, colours RGB >= 0 (1 is full; the CS488 course allowed brighter).
 */
#ifndef ANIMATOR_SDK_DOCUMENT_H
#define ANIMATOR_SDK_DOCUMENT_H

#include "animator/plugin.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ani_vec3 {
    double x, y, z;
} ani_vec3;

typedef struct ani_quat {
    double w, x, y, z; /* unit quaternion */
} ani_quat;

typedef enum ani_axis { ANI_AXIS_X = 0, ANI_AXIS_Y = 1, ANI_AXIS_Z = 2 } ani_axis;

/* A model: what the seed's Model Interface holds. Empty strings mean "none". */
typedef struct ani_model_desc {
    uint32_t struct_size;
    const char *name;   /* unique in the document */
    const char *mesh;   /* mesh id or path; "" for an empty (a scene-tree node, no geometry) */
    int32_t parent;     /* index of the parent model in the scene tree, -1 for the root */
    ani_vec3 kd;        /* diffuse colour */
    ani_vec3 ks;        /* specular colour */
    double shininess;   /* >= 0 */
    const char *texture;
    double tint;        /* [0, 1] */
    double reflectivity;     /* [0, 1] */
    double transparency;     /* [0, 1] */
    double refractive_index; /* > 0, air 1, water 1.33 */
    int32_t dynamics;   /* 0 or 1 */
    int32_t gravity;    /* 0 or 1 */
    double mass;        /* > 0 */
    ani_vec3 initial_velocity; /* velocity at t = 0 */
    const char *collision_sound;
    const char *moving_sound;
    /* Since ABI 1.3 (read them only when struct_size covers them: ANI_MODEL_DESC_HAS_BODY;
     * otherwise the defaults, the seed's idealised world, apply). A contact uses the lower
     * restitution and the higher friction of its two models (docs/physics.md). */
    double restitution;        /* [0, 1], default 1: elastic */
    double friction;           /* >= 0, default 0: frictionless (Coulomb's mu) */
    int32_t rotates;           /* 0 or 1, default 0: turned only by its keys */
    ani_vec3 angular_velocity; /* at t = 0, radians per second about world axes, default 0 */
    /* Since ABI 1.7 (ANI_MODEL_DESC_HAS_SHAPE; otherwise the identity and no joint). */
    double rest[9];     /* a fixed linear shape under the keyed T R S, column-major 3x3, det > 0:
                         * the mesh is at T R S rest; children hang from T R S. A physics backend
                         * gets the model's mesh already in this shape and may ignore it. */
    int32_t has_joint;  /* 0 or 1: the model is a joint with a range of its own angles */
    ani_vec3 joint_min; /* degrees, read signed in (-180, 180], per own axis X Y Z */
    ani_vec3 joint_max; /* >= joint_min */
} ani_model_desc;

/* Whether a model description carries the rigid-body fields of ABI 1.3. */
#define ANI_MODEL_DESC_HAS_BODY(d)                                                             \
    ((d)->struct_size >= offsetof(ani_model_desc, angular_velocity) + sizeof(ani_vec3))

/* Whether a model description carries the rest shape and joint range of ABI 1.7. */
#define ANI_MODEL_DESC_HAS_SHAPE(d)                                                            \
    ((d)->struct_size >= offsetof(ani_model_desc, joint_max) + sizeof(ani_vec3))

/* One model's state at one keyframe (the seed's NodeState), in its parent's frame (the world for
 * a model under the root): T(center) Rx(angles.x) Ry(angles.y) Rz(angles.z) S(scale). */
typedef struct ani_model_state {
    ani_vec3 center; /* world position of the model's origin */
    ani_vec3 angles; /* degrees in [0, 360) about the model's own X, Y, Z axes */
    ani_vec3 scale;  /* > 0 */
    ani_vec3 turn;   /* rotation direction per axis: the sign of the seed's `ccw`; 0 = shortest */
} ani_model_state;

typedef struct ani_camera_state {
    ani_vec3 position;
    ani_quat rotation; /* camera-to-world rotation; identity looks down -Z with +Y up */
    double fov_degrees; /* vertical field of view, (0, 180) */
} ani_camera_state;

typedef struct ani_keyframe_view {
    uint32_t struct_size;
    int64_t time_ms;               /* >= 0; the first keyframe has time 0 */
    /* A keyframe keys some models and perhaps the camera; the one at t = 0 keys everything. */
    const ani_model_state *states; /* one per model, in model order; meaningful where keyed */
    const int32_t *keyed;          /* one per model: 1 if this keyframe keys that model */
    ani_camera_state camera;       /* meaningful if camera_keyed */
    int32_t camera_keyed;
} ani_keyframe_view;

/* One saved parameter value of a plugin. */
typedef struct ani_param_setting {
    const char *plugin_id;
    const char *param_id;
    ani_param_value value;
} ani_param_setting;

typedef struct ani_settings_view {
    uint32_t struct_size;
    int64_t max_time_ms;  /* [1000, 300000000] */
    double gravity;       /* m/s^2, default 9.81 */
    int32_t down_axis;    /* ani_axis; models fall toward -axis */
    int32_t cel_shading;  /* 0 or 1 */
    const char *skybox;   /* "" for none */
    const char *physics_backend; /* plugin id, e.g. "physics.custom" */
    const char *interpolation;   /* interpolator plugin id, e.g. "interpolation.linear" */
} ani_settings_view;

/* A point light (since ABI 1.7): it reaches a point at distance d as
 * colour / (falloff.x + falloff.y d + falloff.z d^2). */
typedef struct ani_light {
    const char *name;
    ani_vec3 position; /* world */
    ani_vec3 colour;   /* >= 0 */
    ani_vec3 falloff;  /* >= 0, not all 0; {1, 0, 0} for none */
} ani_light;

#define ANI_MAX_LIGHTS 8

typedef struct ani_document_view {
    uint32_t struct_size;
    const ani_model_desc *models;
    uint32_t model_count;
    const ani_keyframe_view *keyframes; /* strictly increasing times, the first at 0 */
    uint32_t keyframe_count;
    ani_settings_view settings;
    const ani_param_setting *params;
    uint32_t param_count;
    /* Since ABI 1.7 (ANI_DOCUMENT_VIEW_HAS_LIGHTS; otherwise none, ambient 0.2, no render). */
    const ani_light *lights;   /* at most ANI_MAX_LIGHTS; none: the renderer's own light */
    uint32_t light_count;
    ani_vec3 ambient;          /* >= 0, default 0.2 0.2 0.2 */
    const char *render_output; /* the still `animator render` writes when not told; "" none */
    int32_t render_width;      /* pixels, 0 for the command's default */
    int32_t render_height;
} ani_document_view;

#define ANI_DOCUMENT_VIEW_HAS_LIGHTS(v)                                                        \
    ((v)->struct_size >= offsetof(ani_document_view, render_height) + sizeof(int32_t))

#ifdef __cplusplus
}
#endif

#endif /* ANIMATOR_SDK_DOCUMENT_H */
