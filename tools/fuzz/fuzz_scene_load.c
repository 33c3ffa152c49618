/* libFuzzer harness over scene loading and validation: the first byte picks
 * the format (glTF, binary glTF, OBJ with an MTL beside it), the rest is the
 * file. Each input is written to a private directory and loaded through
 * vct_scene_load, as `vct render` would; a scene that loads is freed, one
 * that does not must fail with a message. Built by tools/fuzz.sh. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "vct/vct.h"

static char dir[64];

static int write_file(const char *path, const uint8_t *data, size_t size) {
    FILE *f = fopen(path, "wb");
    if (!f)
        return 0;
    const int ok = fwrite(data, 1, size, f) == size;
    return fclose(f) == 0 && ok;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (!dir[0]) {
        snprintf(dir, sizeof dir, "/tmp/vct-fuzz-XXXXXX");
        if (!mkdtemp(dir))
            abort();
    }
    if (size < 1)
        return 0;
    static const char *const ext[] = {"gltf", "glb", "obj"};
    const int format = data[0] % 3;
    char path[128], mtl[128];
    snprintf(path, sizeof path, "%s/scene.%s", dir, ext[format]);
    snprintf(mtl, sizeof mtl, "%s/scene.mtl", dir);
    size_t body = size - 1;
    const uint8_t *bytes = data + 1;
    if (format == 2) {
        /* OBJ: the bytes after the first NUL (if any) are its MTL file */
        const uint8_t *nul = memchr(bytes, 0, body);
        if (nul) {
            if (!write_file(mtl, nul + 1, (size_t)(bytes + body - nul - 1)))
                abort();
            body = (size_t)(nul - bytes);
        }
    }
    if (!write_file(path, bytes, body))
        abort();
    vct_error err = {0};
    vct_scene *s = vct_scene_load(path, &err);
    if (s)
        vct_scene_release(s);
    else if (!err.message[0])
        abort(); /* a failure must say why */
    unlink(path);
    unlink(mtl);
    return 0;
}
