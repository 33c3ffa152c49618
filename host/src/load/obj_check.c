/* OBJ files checked before assimp parses them: assimp 5.2 leaks memory when
 * its OBJ parser gives up (found by tools/fuzz.sh: a face index out of
 * range, bytes no number can hold), and crashes on an MTL file whose
 * statements come before any newmtl, so those are refused here first,
 * naming the file and line. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "load/obj_check.h"
#include "load/scene_path.h"

/* Bytes a geometry line may hold after its keyword: digits, signs, points,
 * exponents, slashes, blanks, and the letters of nan and inf(inity). */
static int geometry_byte(int c) {
    return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' || c == '/' || c == ' ' ||
           c == '\t' || c == '\r' || c == '\n' || c == '\\' || (c && strchr("eEnNaAiIfFtTyY", c));
}

/* Each vertex index of face line `rest` within 1..count (or -count..-1). */
static int face_indices_ok(const char *rest, long count, long *bad) {
    const char *p = rest;
    while (*p) {
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')
            ++p;
        if (!*p)
            break;
        char *end;
        const long i = strtol(p, &end, 10);
        if (end == p || i == 0 || i > count || i < -count) {
            *bad = i;
            return 0;
        }
        p = end;
        while (*p && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n')
            ++p; /* the /vt/vn part */
    }
    return 1;
}

/* 1 if `line` of an MTL file is blank or a comment. */
static int mtl_blank(const char *line) {
    const char *p = line;
    while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')
        ++p;
    return *p == '\0' || *p == '#';
}

/* 1 if `line` is a texture statement (map_*, bump, disp, decal, refl, norm)
 * with nothing after its keyword. */
static int mtl_texture_without_file(const char *line) {
    const char *p = line;
    while (*p == ' ' || *p == '\t')
        ++p;
    const int texture = strncasecmp(p, "map_", 4) == 0 || strncasecmp(p, "bump", 4) == 0 ||
                        strncasecmp(p, "disp", 4) == 0 || strncasecmp(p, "decal", 5) == 0 ||
                        strncasecmp(p, "refl", 4) == 0 || strncasecmp(p, "norm", 4) == 0;
    while (*p && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n')
        ++p;
    while (*p == ' ' || *p == '\t')
        ++p;
    return texture && (*p == '\0' || *p == '\r' || *p == '\n');
}

/* Checks the MTL file `name`, beside the model, if it exists. */
static int mtl_precheck(const char *model, const char *name, vct_error *err) {
    char path[2048];
    vct_path_beside(model, name, path, sizeof path);
    FILE *f = fopen(path, "rb");
    if (!f)
        return VCT_OK;
    char line[8192];
    unsigned number = 0;
    int rc = VCT_OK, material = 0;
    while (rc == VCT_OK && fgets(line, sizeof line, f)) {
        ++number;
        if (mtl_blank(line))
            continue;
        if (strncmp(line, "newmtl", 6) == 0)
            material = 1;
        else if (!material)
            rc = vct_fail(err, VCT_ERR_INPUT,
                          "scene %s: material file %s, line %u: a statement before any newmtl",
                          model, name, number);
        else if (mtl_texture_without_file(line))
            rc = vct_fail(err, VCT_ERR_INPUT,
                          "scene %s: material file %s, line %u: a texture statement without a "
                          "file name",
                          model, name, number);
    }
    fclose(f);
    return rc;
}

int vct_obj_precheck(const char *path, vct_error *err) {
    const char *dot = strrchr(path, '.');
    if (!dot || strcasecmp(dot, ".obj") != 0)
        return VCT_OK;
    FILE *f = fopen(path, "rb");
    if (!f)
        return VCT_OK; /* assimp reports it */
    char line[8192];
    unsigned number = 0;
    long vertices = 0, faces = 0;
    int rc = VCT_OK;
    while (rc == VCT_OK && fgets(line, sizeof line, f)) {
        ++number;
        const size_t len = strlen(line);
        if (len == sizeof line - 1 && line[len - 1] != '\n' && line[0] != '#') {
            rc = vct_fail(err, VCT_ERR_INPUT, "scene %s: line %u is over %zu bytes long", path,
                          number, sizeof line - 2);
            break;
        }
        /* what assimp reads as geometry: f, l and p whatever follows, and v
         * followed by a blank, t, n or p */
        size_t start = 0;
        if (line[0] == 'f' || line[0] == 'l' || line[0] == 'p')
            start = 1;
        else if (line[0] == 'v' && (line[1] == ' ' || line[1] == '\t'))
            start = 1;
        else if (line[0] == 'v' && (line[1] == 't' || line[1] == 'n' || line[1] == 'p'))
            start = 2;
        for (size_t i = start; start && i < len; ++i)
            if (!geometry_byte((unsigned char)line[i])) {
                rc = vct_fail(err, VCT_ERR_INPUT,
                              "scene %s: line %u holds byte 0x%02x where numbers belong", path,
                              number, (unsigned char)line[i]);
                break;
            }
        if (rc != VCT_OK)
            continue;
        long bad = 0;
        if (start == 0 && strncmp(line, "mtllib", 6) == 0 && (line[6] == ' ' || line[6] == '\t')) {
            char *name = line + 7;
            name[strcspn(name, "\r\n")] = '\0';
            while (*name == ' ' || *name == '\t')
                ++name;
            rc = mtl_precheck(path, name, err);
        }
        if (start == 1 && line[0] == 'v')
            ++vertices;
        else if (line[0] == 'v' && strchr(line, '/'))
            rc = vct_fail(err, VCT_ERR_INPUT, "scene %s: line %u: a '/' among coordinates", path,
                          number);
        else if ((line[0] == 'f' || line[0] == 'l' || line[0] == 'p') &&
                 (faces += line[0] == 'f', !face_indices_ok(line + 1, vertices, &bad)))
            rc = vct_fail(err, VCT_ERR_INPUT,
                          "scene %s: line %u: a face uses vertex %ld, but %ld are defined "
                          "before it",
                          path, number, bad, vertices);
    }
    if (rc == VCT_OK && ferror(f))
        rc = vct_fail(err, VCT_ERR_IO, "scene %s: read error", path);
    fclose(f);
    /* assimp reads <name>.mtl where the named one is missing */
    if (rc == VCT_OK) {
        const char *slash = strrchr(path, '/');
        char fallback[1024];
        snprintf(fallback, sizeof fallback, "%.*s.mtl", (int)(dot - (slash ? slash + 1 : path)),
                 slash ? slash + 1 : path);
        rc = mtl_precheck(path, fallback, err);
    }
    /* assimp leaks on an OBJ without geometry too */
    if (rc == VCT_OK && (vertices == 0 || faces == 0))
        rc = vct_fail(err, VCT_ERR_INPUT,
                      "scene %s: no triangles to render (%ld vertices, %ld faces)", path, vertices,
                      faces);
    return rc;
}
