/* animator plugin SDK: file formats (ANI_KIND_FILE_FORMAT).
 *
 * A file format probes a file, reads it into a document view and writes a document view. A
 * reader reports errors with the file, the line and what was expected, in the status message:
 * "scene.ani:12: expected a number after 'mass', got 'heavy'".
 */
#ifndef ANIMATOR_SDK_FILE_FORMAT_H
#define ANIMATOR_SDK_FILE_FORMAT_H

#include "animator/document.h"
#include "animator/instance.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum ani_format_flags {
    ANI_FORMAT_CAN_READ = 1 << 0,
    ANI_FORMAT_CAN_WRITE = 1 << 1
} ani_format_flags;

typedef struct ani_file_format_api {
    uint32_t struct_size;
    ani_instance_api instance;
    uint32_t flags;                  /* ani_format_flags */
    const char *const *extensions;   /* without the dot, lower case: "ani" */
    uint32_t extension_count;

    /* [thread: any] How sure the plugin is that it reads this file, 0 (not at all) to 100,
     * from its path and its first bytes. */
    int32_t (*probe)(void *instance, const char *path, const unsigned char *head,
                     size_t head_size);

    /* Reads `path`. On success *document stays valid until release(instance, *document). */
    ani_status_code (*read)(void *instance, const char *path, const ani_document_view **document,
                            ani_status *status);
    void (*release)(void *instance, const ani_document_view *document);

    /* Writes `document` to `path`. A failed write leaves any previous file at `path` intact. */
    ani_status_code (*write)(void *instance, const char *path, const ani_document_view *document,
                             ani_status *status);
} ani_file_format_api;

#ifdef __cplusplus
}
#endif

#endif /* ANIMATOR_SDK_FILE_FORMAT_H */
