/* animator plugin SDK: keyframe interpolators (ANI_KIND_INTERPOLATOR).
 *
 * An interpolator evaluates one keyed channel (a model's center, angles or scale, or the
 * camera's position or rotation) at a time. Keys are given in time order; times in seconds.
 */
#ifndef ANIMATOR_SDK_INTERPOLATOR_H
#define ANIMATOR_SDK_INTERPOLATOR_H

#include "animator/document.h"
#include "animator/instance.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum ani_channel_kind {
    ANI_CHANNEL_POSITION = 1,        /* value[0..2]: a model's center */
    ANI_CHANNEL_ANGLES = 2,          /* value[0..2]: degrees in [0, 360); turn[] gives direction */
    ANI_CHANNEL_SCALE = 3,           /* value[0..2] */
    ANI_CHANNEL_CAMERA_POSITION = 4, /* value[0..2] */
    ANI_CHANNEL_CAMERA_ROTATION = 5  /* value[0..3]: unit quaternion w, x, y, z */
} ani_channel_kind;

typedef struct ani_key {
    double time;     /* seconds */
    double value[4];
    /* ANGLES: the direction the user turned towards this key, per axis: < 0 counter-clockwise,
     * > 0 clockwise, 0 the shorter way (the seed's `ccw`). Unused by other channels. */
    double turn[4];
} ani_key;

typedef struct ani_channel {
    uint32_t struct_size;
    int32_t kind;        /* ani_channel_kind */
    const ani_key *keys; /* strictly increasing times, at least one */
    uint32_t key_count;
    double initial_rate[4]; /* the derivative at the first key (a model's initial velocity) */
} ani_channel;

typedef struct ani_interpolator_api {
    uint32_t struct_size;
    ani_instance_api instance;
    /* Which channel kinds this interpolator handles: bit (1 << kind). */
    uint32_t channel_mask;
    /* [thread: any] Evaluates the channel at `count` times given in increasing order, writing
     * 4 values and 4 rates (derivatives per second) per time. Times before the first key give
     * the first key; times after the last give the last key's value (free motion after the last
     * keyframe is the physics backend's). */
    ani_status_code (*evaluate)(void *instance, const ani_channel *channel, const double *times,
                                uint32_t count, double *values, double *rates,
                                ani_status *status);
} ani_interpolator_api;

#ifdef __cplusplus
}
#endif

#endif /* ANIMATOR_SDK_INTERPOLATOR_H */
