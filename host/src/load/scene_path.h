/* Files a scene names, found beside the scene file. */
#ifndef VCT_SCENE_PATH_H
#define VCT_SCENE_PATH_H

#include <stdio.h>
#include <string.h>

/* `rel` as the scene file `model` names it: as given when absolute, else in
 * the scene file's folder. */
static inline void vct_path_beside(const char *model, const char *rel, char *out, size_t size) {
    const char *slash = strrchr(model, '/');
    const int dir_len = rel[0] == '/' || !slash ? 0 : (int)(slash - model + 1);
    snprintf(out, size, "%.*s%s", dir_len, model, rel);
}

#endif
