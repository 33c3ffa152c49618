/* Untrusted scene files: every file in tests/load/inputs/ is loaded as
 * `vct render` would. Files named refuse_* must fail with a message that
 * names the file; files named load_* must load and validate. The folder
 * keeps what the fuzzer (tools/fuzz.sh) found, once fixed, beside
 * hand-written bad input: malformed JSON, bad base64 (on which assimp 5.2
 * leaks), an index out of range, a NaN vertex, a truncated binary glTF and a
 * negative emissive strength. An OBJ's material file (.mtl) is read with
 * it, not alone. A refusal with a NAME.expect file beside it
 * must also say what that file's first line says. */
#include <dirent.h>
#include <stdio.h>
#include <string.h>

#include "check.h"

int main(void) {
    const char *src = getenv("VCT_SOURCE_DIR");
    char dir[1024];
    snprintf(dir, sizeof dir, "%s/tests/load/inputs", src ? src : ".");
    DIR *d = opendir(dir);
    CHECK(d != NULL, "cannot open %s", dir);
    int refused = 0, loaded = 0;
    for (struct dirent *e; d && (e = readdir(d)) != NULL;) {
        const int refuse = strncmp(e->d_name, "refuse_", 7) == 0;
        const char *dot = strrchr(e->d_name, '.');
        if ((!refuse && strncmp(e->d_name, "load_", 5) != 0) ||
            (dot && (!strcmp(dot, ".expect") || !strcmp(dot, ".mtl"))))
            continue;
        char path[2048];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        vct_error err = {0};
        vct_scene *s = vct_scene_load(path, &err);
        if (refuse) {
            CHECK(!s && err.status != VCT_OK && strstr(err.message, e->d_name),
                  "%s: %s (a refusal must name the file)", e->d_name, s ? "loaded" : err.message);
            char expect_path[2100], expect[256] = "";
            snprintf(expect_path, sizeof expect_path, "%s.expect", path);
            FILE *f = fopen(expect_path, "r");
            if (f) {
                if (fgets(expect, sizeof expect, f))
                    expect[strcspn(expect, "\n")] = '\0';
                fclose(f);
                CHECK(strstr(err.message, expect) != NULL, "%s: the refusal should say \"%s\": %s",
                      e->d_name, expect, err.message);
            }
            printf("refused %-40s %s\n", e->d_name, err.message);
            ++refused;
        } else {
            CHECK(s != NULL, "%s: %s", e->d_name, err.message);
            ++loaded;
        }
        vct_scene_release(s);
    }
    if (d)
        closedir(d);
    CHECK(refused >= 6 && loaded >= 1, "%d refused, %d loaded: inputs missing", refused, loaded);
    return check_exit("test_scene_inputs");
}
