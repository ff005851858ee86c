/* animator plugin SDK: the part every kind's interface starts with.
 *
 * A plugin's interface (`api` in its descriptor) begins with an ani_instance_api: the host
 * creates instances of the plugin, sets their parameters and destroys them. Parameter values
 * handed to set_param have already been checked by the host against the plugin's
 * ani_param_descriptor (range, finiteness, enum index); a plugin may still refuse a value.
 */
#ifndef ANIMATOR_SDK_INSTANCE_H
#define ANIMATOR_SDK_INSTANCE_H

#include "animator/plugin.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ani_instance_api {
    uint32_t struct_size;
    /* Returns a new instance with every parameter at its default, or NULL with a status. */
    void *(*create)(const ani_host *host, ani_status *status);
    void (*destroy)(void *instance);
    ani_status_code (*get_param)(void *instance, const char *param_id, ani_param_value *value,
                                 ani_status *status);
    ani_status_code (*set_param)(void *instance, const char *param_id,
                                 const ani_param_value *value, ani_status *status);
} ani_instance_api;

#ifdef __cplusplus
}
#endif

#endif /* ANIMATOR_SDK_INSTANCE_H */
