/* Kernel sources: found on disk (next to the binary, installed, or in the
 * source tree) or in the copies embedded at build time. #include "x" lines are
 * expanded here with #line markers, so a build log names the original file. */
#define _GNU_SOURCE /* dladdr */
#include <dlfcn.h>
#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "runtime/runtime.h"

char *vct_read_file(const char *path, size_t *size) {
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *buf = NULL;
    long n = -1;
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0)
        buf = malloc((size_t)n + 1);
    if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    if (buf) {
        buf[n] = '\0';
        if (size)
            *size = (size_t)n;
    }
    return buf;
}

typedef struct vct_embedded_kernel {
    const char *name;
    const unsigned char *data;
    size_t size;
} vct_embedded_kernel;

extern const vct_embedded_kernel vct_embedded_kernels[];
extern const int vct_embedded_kernel_count;

typedef struct text {
    char *data;
    size_t len, cap;
} text;

static int text_append(text *t, const char *s, size_t n) {
    if (t->len + n + 1 > t->cap) {
        size_t cap = (t->cap ? t->cap * 2 : 4096);
        while (cap < t->len + n + 1)
            cap *= 2;
        char *d = realloc(t->data, cap);
        if (!d)
            return 0;
        t->data = d;
        t->cap = cap;
    }
    memcpy(t->data + t->len, s, n);
    t->len += n;
    t->data[t->len] = '\0';
    return 1;
}

static int dir_has_kernels(const char *dir) {
    char probe[PATH_MAX + 64];
    snprintf(probe, sizeof probe, "%s/vct_types.h", dir);
    return access(probe, R_OK) == 0;
}

/* The first directory that holds the kernels, or "" to use the embedded
 * copies: resolved once per process. */
static char kernel_dir_path[PATH_MAX + 32];

static void resolve_kernel_dir(void) {
    char *dir = kernel_dir_path;
    const char *env = getenv("VCT_KERNEL_DIR");
    if (env && *env && dir_has_kernels(env)) {
        snprintf(dir, sizeof kernel_dir_path, "%s", env);
        return;
    }
    /* Beside the library (an installed libvct.so finds ../share/vct/kernels),
     * then beside the program, then where the library was installed. */
    char bases[2][PATH_MAX];
    int base_count = 0;
    Dl_info self;
    if (dladdr((void *)&resolve_kernel_dir, &self) && self.dli_fname &&
        realpath(self.dli_fname, bases[base_count]))
        ++base_count;
    ssize_t n = readlink("/proc/self/exe", bases[base_count], sizeof bases[0] - 1);
    if (n > 0) {
        bases[base_count][n] = '\0';
        ++base_count;
    }
    const char *rel[] = {"kernels", "../kernels", "../share/vct/kernels"};
    for (int b = 0; b < base_count; ++b) {
        char *slash = strrchr(bases[b], '/');
        if (slash)
            *slash = '\0';
        for (size_t i = 0; i < sizeof rel / sizeof rel[0]; ++i) {
            char cand[PATH_MAX + 32];
            snprintf(cand, sizeof cand, "%s/%s", bases[b], rel[i]);
            if (dir_has_kernels(cand)) {
                if (!realpath(cand, dir))
                    snprintf(dir, sizeof kernel_dir_path, "%s", cand);
                return;
            }
        }
    }
#ifdef VCT_INSTALL_KERNEL_DIR
    if (dir_has_kernels(VCT_INSTALL_KERNEL_DIR)) {
        snprintf(dir, sizeof kernel_dir_path, "%s", VCT_INSTALL_KERNEL_DIR);
        return;
    }
#endif
    dir[0] = '\0';
}

static const char *kernel_dir(void) {
    static pthread_once_t once = PTHREAD_ONCE_INIT;
    pthread_once(&once, resolve_kernel_dir);
    return kernel_dir_path;
}

const char *vct_kernel_source_dir(void) {
    return *kernel_dir() ? kernel_dir() : "(embedded)";
}

static char *load_one(const char *name, vct_error *err) {
    const char *dir = kernel_dir();
    if (*dir) {
        char path[PATH_MAX + 256];
        snprintf(path, sizeof path, "%s/%s", dir, name);
        char *s = vct_read_file(path, NULL);
        if (s)
            return s;
    }
    for (int i = 0; i < vct_embedded_kernel_count; ++i) {
        if (strcmp(vct_embedded_kernels[i].name, name) == 0) {
            char *s = malloc(vct_embedded_kernels[i].size + 1);
            if (!s)
                break;
            memcpy(s, vct_embedded_kernels[i].data, vct_embedded_kernels[i].size);
            s[vct_embedded_kernels[i].size] = '\0';
            return s;
        }
    }
    vct_fail(err, VCT_ERR_IO,
             "kernels: source \"%s\" not found in %s nor embedded: reinstall vct or set "
             "VCT_KERNEL_DIR",
             name, *dir ? dir : "(no kernel directory)");
    return NULL;
}

#define MAX_INCLUDES 64

static int expand(text *out, const char *name, const char **seen, int *seen_n, int depth,
                  vct_error *err) {
    for (int i = 0; i < *seen_n; ++i)
        if (strcmp(seen[i], name) == 0)
            return 1; /* each header once: they are include-guarded anyway */
    if (depth > 8 || *seen_n >= MAX_INCLUDES) {
        vct_fail(err, VCT_ERR_INPUT,
                 "kernels: %s is nested more than 8 includes deep or is the %dth header of one "
                 "program (more than %d)",
                 name, *seen_n + 1, MAX_INCLUDES);
        return 0;
    }
    char *src = load_one(name, err);
    if (!src)
        return 0;
    seen[(*seen_n)++] = strdup(name);
    char marker[256];
    int line = 1;
    snprintf(marker, sizeof marker, "#line 1 \"%s\"\n", name);
    int ok = text_append(out, marker, strlen(marker));
    for (const char *p = src; ok && *p;) {
        const char *eol = strchr(p, '\n');
        size_t len = eol ? (size_t)(eol - p + 1) : strlen(p);
        const char *q = p;
        while (*q == ' ' || *q == '\t')
            ++q;
        char inc[128];
        if (sscanf(q, "#include \"%127[^\"]\"", inc) == 1) {
            ok = expand(out, inc, seen, seen_n, depth + 1, err);
            snprintf(marker, sizeof marker, "\n#line %d \"%s\"\n", line + 1, name);
            ok = ok && text_append(out, marker, strlen(marker));
        } else {
            ok = text_append(out, p, len);
        }
        p += len;
        ++line;
    }
    free(src);
    return ok;
}

char *vct_kernel_source_expand(const char *file, vct_error *err) {
    text out = {0};
    const char *seen[MAX_INCLUDES];
    int seen_n = 0;
    int ok = expand(&out, file, seen, &seen_n, 0, err);
    for (int i = 0; i < seen_n; ++i)
        free((void *)seen[i]);
    if (!ok) {
        free(out.data);
        if (err && err->status == VCT_OK)
            vct_fail(err, VCT_ERR_MEMORY, "kernels: out of host memory expanding %s", file);
        return NULL;
    }
    return out.data;
}

/* The file and line of an expanded source's line `line` (1-based): the last
 * #line marker before it, counted on from there ("?" without one). */
static void expanded_origin(const char *source, long line, char *file, size_t cap, long *origin) {
    snprintf(file, cap, "?");
    *origin = 0;
    long at = 1;
    for (const char *p = source; *p && at <= line; ++at) {
        long n;
        char name[256];
        if (sscanf(p, "#line %ld \"%255[^\"]\"", &n, name) == 2) {
            snprintf(file, cap, "%s", name);
            *origin = n - 1; /* the marker's next line is n */
        } else {
            ++*origin;
        }
        const char *eol = strchr(p, '\n');
        if (!eol)
            break;
        p = eol + 1;
    }
}

char *vct_kernel_log_locate(const char *log, const char *source) {
    text out = {0};
    int ok = 1;
    for (const char *p = log; ok && *p;) {
        /* "<name>:LINE:" names a line of the expanded source, but for the
         * compiler's own pseudo-files ("<built-in>", "<command line>") */
        const int pseudo = strncmp(p, "<built-in>", 10) == 0 ||
                           strncmp(p, "<command line>", 14) == 0 ||
                           strncmp(p, "<scratch space>", 15) == 0;
        const char *close = *p == '<' && !pseudo ? strchr(p, '>') : NULL;
        char *end = NULL;
        const long line = close && close[1] == ':' && close[2] >= '0' && close[2] <= '9' &&
                                  !memchr(p, '\n', (size_t)(close - p))
                              ? strtol(close + 2, &end, 10)
                              : 0;
        if (line > 0 && *end == ':') {
            char file[256], located[320];
            long origin;
            expanded_origin(source, line, file, sizeof file, &origin);
            snprintf(located, sizeof located, "%s:%ld", file, origin);
            ok = text_append(&out, located, strlen(located));
            p = end;
        } else {
            ok = text_append(&out, p, 1);
            ++p;
        }
    }
    if (!ok || !out.data) {
        free(out.data);
        return NULL;
    }
    return out.data;
}
