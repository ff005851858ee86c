/* animator plugin SDK: the core of the C ABI between the host and a plugin library.
 *
 * A plugin library exports exactly one symbol, `animator_plugin_entry` (ANI_ENTRY_SYMBOL), of
 * type ani_plugin_entry. Through it the host asks for the library's plugins (a factory), each
 * described by an ani_plugin_descriptor whose `api` points at the interface of its kind
 * (physics.h, interpolator.h, shading.h, file_format.h).
 *
 * Rules of the boundary (docs/sdk.md):
 *  - Pure C. No exceptions, no C++ types, no memory freed on the other side.
 *  - Every struct that may grow starts with `struct_size`; fields are only ever appended, and
 *    the reader of a struct uses only the fields that fit in the size it was given.
 *  - Every fallible call returns an ani_status_code and fills an ani_status with a message.
 *  - Threads: unless a function says otherwise, the host calls a plugin instance from one
 *    thread at a time (not necessarily always the same thread). [thread: any] marks functions
 *    the host may call concurrently.
 */
#ifndef ANIMATOR_SDK_PLUGIN_H
#define ANIMATOR_SDK_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ABI version. A plugin built against another major version, or a newer minor version than
 * the host's, is refused. Minor versions only append fields and functions. */
#define ANI_ABI_MAJOR 1
#define ANI_ABI_MINOR 11

#define ANI_ENTRY_SYMBOL "animator_plugin_entry"

#if defined(_WIN32)
#define ANI_EXPORT __declspec(dllexport)
#else
#define ANI_EXPORT __attribute__((visibility("default")))
#endif

/* ---- status ---------------------------------------------------------------------------- */

typedef enum ani_status_code {
    ANI_OK = 0,
    ANI_ERR_FAILED = 1,                 /* any other failure; the message says what */
    ANI_ERR_INVALID_ARGUMENT = 2,       /* a value out of range, a null pointer, a NaN */
    ANI_ERR_IO = 3,                     /* a file could not be opened, read or written */
    ANI_ERR_PARSE = 4,                  /* a file's content is not what was expected */
    ANI_ERR_UNSUPPORTED = 5,            /* the plugin cannot do this (e.g. write a format) */
    ANI_ERR_OUT_OF_MEMORY = 6,
    ANI_ERR_VERSION = 7,                /* a struct or file version the plugin does not know */
    ANI_ERR_CANCELLED = 8,              /* the host asked to stop (bake progress) */
    ANI_ERR_MISSING_HOST_FEATURE = 9,   /* the host lacks an extension the plugin needs */
    ANI_ERR_UNKNOWN_PARAM = 10          /* no parameter with that id */
} ani_status_code;

#define ANI_STATUS_MESSAGE_SIZE 1024

/* Filled by the callee; owned by the caller. `message` is always NUL-terminated. */
typedef struct ani_status {
    int32_t code; /* ani_status_code */
    char message[ANI_STATUS_MESSAGE_SIZE];
} ani_status;

/* ---- versions and kinds ---------------------------------------------------------------- */

typedef struct ani_version {
    uint32_t major;
    uint32_t minor;
    uint32_t patch;
} ani_version;

typedef enum ani_plugin_kind {
    ANI_KIND_PHYSICS = 1,      /* physics.h */
    ANI_KIND_INTERPOLATOR = 2, /* interpolator.h */
    ANI_KIND_SHADING = 3,      /* shading.h */
    ANI_KIND_FILE_FORMAT = 4   /* file_format.h */
} ani_plugin_kind;

/* ---- host services --------------------------------------------------------------------- */

typedef enum ani_log_level {
    ANI_LOG_DEBUG = 0,
    ANI_LOG_INFO = 1,
    ANI_LOG_WARNING = 2,
    ANI_LOG_ERROR = 3
} ani_log_level;

typedef struct ani_host ani_host;

/* Handed to the plugin library by init(); valid until deinit(). */
struct ani_host {
    uint32_t struct_size;
    ani_version abi; /* the host's ABI version */
    const char *host_name;
    ani_version host_version;
    void *host_data; /* the host's own; plugins pass the ani_host back, never touch this */

    /* [thread: any] Writes one line to the host's log, attributed to plugin_id. */
    void (*log)(const ani_host *host, ani_log_level level, const char *plugin_id,
                const char *message);

    /* [thread: any] An optional host feature by id, or NULL when the host lacks it. */
    const void *(*get_extension)(const ani_host *host, const char *extension_id);
};

/* ---- parameters ------------------------------------------------------------------------ */

/* What a parameter means, so the host can draw the right widget and check values. */
typedef enum ani_param_kind {
    ANI_PARAM_FLOAT = 1,  /* value[0], finite, in [min, max] */
    ANI_PARAM_INT = 2,    /* value[0], an integer in [min, max] */
    ANI_PARAM_BOOL = 3,   /* value[0], 0 or 1 */
    ANI_PARAM_ENUM = 4,   /* value[0], an index into enum_labels */
    ANI_PARAM_COLOUR = 5, /* value[0..2] RGB in [0, 1], value[3] alpha in [0, 1] */
    ANI_PARAM_ANGLE = 6,  /* value[0] in degrees, in [min, max] */
    ANI_PARAM_TIME = 7    /* value[0] in seconds, in [min, max] */
} ani_param_kind;

typedef struct ani_param_value {
    double value[4];
} ani_param_value;

typedef struct ani_param_descriptor {
    uint32_t struct_size;
    const char *id;   /* stable, [a-z0-9_.]+, saved in animations */
    const char *name; /* shown to the user */
    const char *description;
    int32_t kind;     /* ani_param_kind */
    double min_value; /* finite; for BOOL 0, for ENUM 0 */
    double max_value; /* finite; for BOOL 1, for ENUM enum_count - 1 */
    ani_param_value default_value;
    double step;      /* UI drag step; 0 lets the host choose */
    const char *const *enum_labels; /* ENUM only: enum_count labels */
    uint32_t enum_count;
} ani_param_descriptor;

/* ---- descriptor and entry -------------------------------------------------------------- */

typedef struct ani_plugin_descriptor {
    uint32_t struct_size;
    const char *id; /* unique, "<kind-ish>.<name>", e.g. "physics.custom"; [a-z0-9_.-]+ */
    int32_t kind;   /* ani_plugin_kind */
    const char *name;
    ani_version version;
    const char *description;
    const ani_param_descriptor *params;
    uint32_t param_count;
    /* The interface of `kind`: const ani_physics_api *, const ani_interpolator_api *,
     * const ani_shading_api * or const ani_file_format_api *. */
    const void *api;
} ani_plugin_descriptor;

typedef struct ani_plugin_entry {
    uint32_t struct_size;
    ani_version abi; /* ANI_ABI_MAJOR, ANI_ABI_MINOR the library was built with */

    /* Called once after loading, before anything else. A failure refuses the library. */
    ani_status_code (*init)(const ani_host *host, ani_status *status);
    /* Called once before the host exits (libraries are never unloaded). */
    void (*deinit)(void);

    /* The factory. */
    uint32_t (*plugin_count)(void);
    const ani_plugin_descriptor *(*plugin_descriptor)(uint32_t index);
} ani_plugin_entry;

/* Every plugin library defines exactly this, and exports nothing else. */
#define ANI_DECLARE_ENTRY ANI_EXPORT extern const ani_plugin_entry animator_plugin_entry

/* A helper for C plugins: fill a status. */
static inline ani_status_code ani_status_set(ani_status *status, ani_status_code code,
                                             const char *message) {
    if (status) {
        size_t i = 0;
        status->code = (int32_t)code;
        if (message) {
            for (; message[i] != '\0' && i + 1 < ANI_STATUS_MESSAGE_SIZE; ++i)
                status->message[i] = message[i];
        }
        status->message[i] = '\0';
    }
    return code;
}

#ifdef __cplusplus
}
#endif

#endif /* ANIMATOR_SDK_PLUGIN_H */
