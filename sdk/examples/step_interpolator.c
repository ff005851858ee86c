/* A minimal, complete animator plugin in plain C: a "step" interpolator that holds each key's
 * value until the next key (what animators call stepped or constant keys). It is the example of
 * docs/sdk.md, and the tests build and load it.
 *
 * Build:  cc -shared -fPIC -fvisibility=hidden -I<sdk>/include step_interpolator.c \
 *            -Wl,--version-script=<sdk>/plugin.map -o animator-example-step.so
 */
#include "animator/interpolator.h"

#include <stdlib.h>
#include <string.h>

typedef struct step_instance {
    double hold; /* parameter "hold": 1 holds the previous key, 0 jumps to the next key early */
} step_instance;

static const ani_param_descriptor step_params[] = {{
    sizeof(ani_param_descriptor), "hold", "Hold previous key",
    "On: a key's value holds until the next key. Off: it jumps to the next key's value.",
    ANI_PARAM_BOOL, 0.0, 1.0, {{1.0, 0.0, 0.0, 0.0}}, 0.0, NULL, 0,
}};

static void *step_create(const ani_host *host, ani_status *status) {
    step_instance *self = malloc(sizeof *self);
    (void)host;
    if (!self) {
        ani_status_set(status, ANI_ERR_OUT_OF_MEMORY, "out of memory");
        return NULL;
    }
    self->hold = 1.0;
    ani_status_set(status, ANI_OK, "");
    return self;
}

static void step_destroy(void *instance) { free(instance); }

static ani_status_code step_get_param(void *instance, const char *id, ani_param_value *value,
                                      ani_status *status) {
    step_instance *self = instance;
    if (id == NULL || strcmp(id, "hold") != 0)
        return ani_status_set(status, ANI_ERR_UNKNOWN_PARAM, "no such parameter");
    value->value[0] = self->hold;
    value->value[1] = value->value[2] = value->value[3] = 0.0;
    return ani_status_set(status, ANI_OK, "");
}

static ani_status_code step_set_param(void *instance, const char *id,
                                      const ani_param_value *value, ani_status *status) {
    ani_param_value unused;
    if (step_get_param(instance, id, &unused, status) != ANI_OK) return (ani_status_code)status->code;
    ((step_instance *)instance)->hold = value->value[0];
    return ani_status_set(status, ANI_OK, "");
}

static ani_status_code step_evaluate(void *instance, const ani_channel *channel,
                                     const double *times, uint32_t count, double *values,
                                     double *rates, ani_status *status) {
    const step_instance *self = instance;
    uint32_t key = 0;
    if (channel->key_count == 0)
        return ani_status_set(status, ANI_ERR_INVALID_ARGUMENT, "a channel needs a key");
    for (uint32_t i = 0; i < count; ++i) {
        uint32_t pick;
        /* Times come in increasing order, so one sweep over the keys serves them all. */
        while (key + 1 < channel->key_count && channel->keys[key + 1].time <= times[i]) ++key;
        pick = key;
        if (self->hold < 0.5 && key + 1 < channel->key_count && times[i] > channel->keys[key].time)
            pick = key + 1;
        for (int c = 0; c < 4; ++c) {
            values[4 * i + c] = channel->keys[pick].value[c];
            rates[4 * i + c] = 0.0; /* a step never moves between keys */
        }
    }
    return ani_status_set(status, ANI_OK, "");
}

static const ani_interpolator_api step_api = {
    sizeof(ani_interpolator_api),
    {sizeof(ani_instance_api), step_create, step_destroy, step_get_param, step_set_param},
    (1u << ANI_CHANNEL_POSITION) | (1u << ANI_CHANNEL_ANGLES) | (1u << ANI_CHANNEL_SCALE) |
        (1u << ANI_CHANNEL_CAMERA_POSITION) | (1u << ANI_CHANNEL_CAMERA_ROTATION),
    step_evaluate,
};

static const ani_plugin_descriptor step_descriptor = {
    sizeof(ani_plugin_descriptor),
    "interpolator.step",
    ANI_KIND_INTERPOLATOR,
    "Step",
    {1, 0, 0},
    "Holds each key's value until the next key.",
    step_params,
    1,
    &step_api,
};

static ani_status_code step_init(const ani_host *host, ani_status *status) {
    (void)host;
    return ani_status_set(status, ANI_OK, "");
}
static void step_deinit(void) {}
static uint32_t step_count(void) { return 1; }
static const ani_plugin_descriptor *step_get(uint32_t index) {
    return index == 0 ? &step_descriptor : NULL;
}

ANI_DECLARE_ENTRY;
const ani_plugin_entry animator_plugin_entry = {
    sizeof(ani_plugin_entry), {ANI_ABI_MAJOR, ANI_ABI_MINOR, 0},
    step_init, step_deinit, step_count, step_get,
};
