/* A tiny valid interpolator plugin, bent in one way per file by the macros each broken plugin
 * defines before including this. The host must refuse each bent one and name the reason. */
#include "animator/interpolator.h"

#ifndef BROKEN_ID
#define BROKEN_ID "interpolator.broken"
#endif
#ifndef BROKEN_ABI_MAJOR
#define BROKEN_ABI_MAJOR ANI_ABI_MAJOR
#endif
#ifndef BROKEN_ABI_MINOR
#define BROKEN_ABI_MINOR ANI_ABI_MINOR
#endif
#ifndef BROKEN_PARAM_MIN
#define BROKEN_PARAM_MIN 0.0
#endif
#ifndef BROKEN_PARAM_MAX
#define BROKEN_PARAM_MAX 1.0
#endif
#ifndef BROKEN_EVALUATE
#define BROKEN_EVALUATE broken_evaluate
#endif
#ifndef BROKEN_INIT_CODE
#define BROKEN_INIT_CODE ANI_OK
#endif
#ifndef BROKEN_KIND
#define BROKEN_KIND ANI_KIND_INTERPOLATOR
#endif

static void *broken_create(const ani_host *host, ani_status *status) {
    static int instance;
    (void)host;
    ani_status_set(status, ANI_OK, "");
    return &instance;
}
static void broken_destroy(void *instance) { (void)instance; }
static ani_status_code broken_get(void *i, const char *id, ani_param_value *v, ani_status *s) {
    (void)i; (void)id; (void)v;
    return ani_status_set(s, ANI_ERR_UNKNOWN_PARAM, "none");
}
static ani_status_code broken_set(void *i, const char *id, const ani_param_value *v, ani_status *s) {
    (void)i; (void)id; (void)v;
    return ani_status_set(s, ANI_ERR_UNKNOWN_PARAM, "none");
}
static ani_status_code __attribute__((unused)) broken_evaluate(void *i, const ani_channel *c, const double *t, uint32_t n,
                                       double *values, double *rates, ani_status *s) {
    (void)i; (void)c; (void)t; (void)n; (void)values; (void)rates;
    return ani_status_set(s, ANI_OK, "");
}

static const ani_param_descriptor broken_params[] = {{
    sizeof(ani_param_descriptor), "amount", "Amount", "", ANI_PARAM_FLOAT,
    BROKEN_PARAM_MIN, BROKEN_PARAM_MAX, {{0.5, 0, 0, 0}}, 0.0, NULL, 0,
}};

static const ani_interpolator_api broken_api = {
    sizeof(ani_interpolator_api),
    {sizeof(ani_instance_api), broken_create, broken_destroy, broken_get, broken_set},
    1u << ANI_CHANNEL_POSITION,
    BROKEN_EVALUATE,
};

static const ani_plugin_descriptor broken_descriptor = {
    sizeof(ani_plugin_descriptor), BROKEN_ID, BROKEN_KIND, "Broken", {1, 0, 0}, "A test plugin.",
    broken_params, 1, &broken_api,
};

static ani_status_code broken_init(const ani_host *host, ani_status *status) {
    (void)host;
    return ani_status_set(status, BROKEN_INIT_CODE, "the test plugin fails on purpose");
}
static void broken_deinit(void) {}
static uint32_t broken_count(void) { return 1; }
static const ani_plugin_descriptor *broken_get_descriptor(uint32_t i) {
    return i == 0 ? &broken_descriptor : NULL;
}

#ifndef BROKEN_NO_ENTRY
ANI_DECLARE_ENTRY;
const ani_plugin_entry animator_plugin_entry = {
    sizeof(ani_plugin_entry), {BROKEN_ABI_MAJOR, BROKEN_ABI_MINOR, 0},
    broken_init, broken_deinit, broken_count, broken_get_descriptor,
};
#else
/* Exports something, but not the entry symbol. */
ANI_EXPORT const ani_plugin_entry animator_plugin_entry_misspelt = {
    sizeof(ani_plugin_entry), {ANI_ABI_MAJOR, ANI_ABI_MINOR, 0},
    broken_init, broken_deinit, broken_count, broken_get_descriptor,
};
#endif
