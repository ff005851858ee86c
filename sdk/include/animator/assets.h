/* animator plugin SDK: the host extension "animator.assets.v1" (ANI_EXT_ASSETS).
 *
 * Asks the host where an asset named in a document lives, so a reader can report an unknown
 * mesh at the line that names it. Get it with host->get_extension(host, ANI_EXT_ASSETS); a host
 * without asset folders (some tests) returns NULL, and readers then skip the check.
 */
#ifndef ANIMATOR_SDK_ASSETS_H
#define ANIMATOR_SDK_ASSETS_H

#include "animator/plugin.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ANI_EXT_ASSETS "animator.assets.v1"

typedef enum ani_asset_kind {
    ANI_ASSET_MESH = 1,    /* <root>/meshes/<id>.obj, or a path relative to the document */
    ANI_ASSET_TEXTURE = 2, /* <root>/textures/<id>.png or .bmp */
    ANI_ASSET_SKYBOX = 3,  /* <root>/skyboxes/<id>/ with six faces */
    ANI_ASSET_SOUND = 4    /* <root>/sounds/<id>.wav */
} ani_asset_kind;

typedef struct ani_assets_ext {
    uint32_t struct_size;
    /* [thread: any] Resolves asset `id` of `kind` for the document at `relative_to` (may be
     * NULL). Returns 1 and writes the file's path into `out`, or returns 0 and writes where it
     * looked ("looked for assets/meshes/x.obj in: /a, /b") into `out`. */
    int32_t (*resolve)(const ani_host *host, int32_t kind, const char *id, const char *relative_to,
                       char *out, size_t out_size);
} ani_assets_ext;

#ifdef __cplusplus
}
#endif

#endif /* ANIMATOR_SDK_ASSETS_H */
