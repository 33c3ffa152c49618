/* Program builds: compiled once per (source, device, driver, options) and
 * kept in an on-disk binary cache so that a warm start never recompiles. */
#include <errno.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "program/arg_check.h"
#include "runtime/runtime.h"

static uint64_t fnv1a(uint64_t h, const void *data, size_t n) {
    const unsigned char *p = data;
    for (size_t i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

static uint64_t hash_str(uint64_t h, const char *s) {
    return fnv1a(h, s, strlen(s) + 1);
}

/* Resolved once per process (the environment is read then), so that
 * contexts on several threads share one answer. */
static char cache_dir[1024];

static void resolve_cache_dir(void) {
    char *dir = cache_dir;
    const char *env = getenv("VCT_CACHE_DIR");
    if (env && *env) {
        snprintf(dir, sizeof cache_dir, "%s", env);
    } else {
        const char *xdg = getenv("XDG_CACHE_HOME");
        const char *home = getenv("HOME");
        if (xdg && *xdg)
            snprintf(dir, sizeof cache_dir, "%s/vct", xdg);
        else if (home && *home)
            snprintf(dir, sizeof cache_dir, "%s/.cache/vct", home);
        else
            snprintf(dir, sizeof cache_dir, "/tmp/vct-cache");
    }
}

const char *vct_cache_dir(void) {
    static pthread_once_t once = PTHREAD_ONCE_INIT;
    pthread_once(&once, resolve_cache_dir);
    return cache_dir;
}

static void mkdirs(const char *path) {
    char tmp[1024];
    snprintf(tmp, sizeof tmp, "%s", path);
    for (char *p = tmp + 1; *p; ++p) {
        if (*p == '/') {
            *p = '\0';
            mkdir(tmp, 0755);
            *p = '/';
        }
    }
    mkdir(tmp, 0755);
}

static void cache_key(const vct_context *ctx, const char *source, const char *options,
                      char out[40]) {
    uint64_t a = 0xcbf29ce484222325ull, b = 0x84222325cbf29ce4ull;
    const char *parts[] = {source,           options,           ctx->info.name, ctx->info.version,
                           ctx->info.driver, ctx->info.platform};
    for (size_t i = 0; i < sizeof parts / sizeof parts[0]; ++i) {
        a = hash_str(a, parts[i]);
        b = hash_str(b ^ (i + 1) * 0x9e3779b97f4a7c15ull, parts[i]);
    }
    snprintf(out, 40, "%016llx%016llx", (unsigned long long)a, (unsigned long long)b);
}

static cl_program load_cached(vct_context *ctx, const char *path) {
    size_t size = 0;
    unsigned char *bin = (unsigned char *)vct_read_file(path, &size);
    if (!bin || size == 0) {
        free(bin);
        return NULL;
    }
    const unsigned char *bins[1] = {bin};
    cl_int status = CL_SUCCESS, rc = CL_SUCCESS;
    cl_program p =
        clCreateProgramWithBinary(ctx->context, 1, &ctx->device, &size, bins, &status, &rc);
    free(bin);
    if (rc != CL_SUCCESS || status != CL_SUCCESS)
        return NULL;
    if (clBuildProgram(p, 1, &ctx->device, NULL, NULL, NULL) != CL_SUCCESS) {
        clReleaseProgram(p);
        return NULL; /* stale or foreign binary: rebuild from source */
    }
    return p;
}

/* 1 where the environment variable `name` is "0": a kernel variant the
 * device would get is turned off (tests build both). */
static int turned_off(const char *name) {
    const char *env = getenv(name);
    return env && strcmp(env, "0") == 0;
}

/* fma in hardware, not in software: kernels may then fuse what they would
 * otherwise leave as a product and a sum (kernels/README.md, -D options).
 * VCT_FAST_FMA=0 builds the other variant. */
static int device_has_fast_fma(cl_device_id device) {
    if (turned_off("VCT_FAST_FMA"))
        return 0;
    cl_device_fp_config fp = 0;
    if (clGetDeviceInfo(device, CL_DEVICE_SINGLE_FP_CONFIG, sizeof fp, &fp, NULL) != CL_SUCCESS)
        return 0;
    return (fp & CL_FP_FMA) && !(fp & CL_FP_SOFT_FLOAT);
}

/* Rays traced in packets (kernels/accel/ray_packet.h) on CPU devices, whose
 * wide vector units take a packet's rays at once; VCT_PACKETS=0 builds the
 * other variant. The hits are the same either way. */
static int device_wants_packets(cl_device_id device) {
    if (turned_off("VCT_PACKETS"))
        return 0;
    cl_device_type type = 0;
    if (clGetDeviceInfo(device, CL_DEVICE_TYPE, sizeof type, &type, NULL) != CL_SUCCESS)
        return 0;
    return (type & CL_DEVICE_TYPE_CPU) != 0;
}

static void store_cached(cl_program p, const char *path) {
    size_t size = 0;
    if (clGetProgramInfo(p, CL_PROGRAM_BINARY_SIZES, sizeof size, &size, NULL) != CL_SUCCESS ||
        size == 0)
        return;
    unsigned char *bin = malloc(size);
    if (!bin)
        return;
    unsigned char *bins[1] = {bin};
    if (clGetProgramInfo(p, CL_PROGRAM_BINARIES, sizeof bins, bins, NULL) == CL_SUCCESS) {
        mkdirs(vct_cache_dir());
        /* a name of this process and this call: contexts on several threads
         * may write the same program at once (devices of one kind share it) */
        static atomic_uint writes;
        char tmp[1300];
        snprintf(tmp, sizeof tmp, "%s.%d.%u.tmp", path, (int)getpid(),
                 atomic_fetch_add(&writes, 1u));
        FILE *f = fopen(tmp, "wb");
        if (f) {
            int ok = fwrite(bin, 1, size, f) == size;
            ok = (fclose(f) == 0) && ok;
            if (!ok || rename(tmp, path) != 0)
                remove(tmp);
        }
    }
    free(bin);
}

static int build_from_source(vct_context *ctx, const char *file, const char *source,
                             const char *options, cl_program *out, vct_error *err) {
    cl_int rc = CL_SUCCESS;
    cl_program p = clCreateProgramWithSource(ctx->context, 1, &source, NULL, &rc);
    if (rc != CL_SUCCESS)
        return vct_cl_check(err, rc, file, "clCreateProgramWithSource");
    rc = clBuildProgram(p, 1, &ctx->device, options, NULL, NULL);
    if (rc != CL_SUCCESS) {
        size_t log_size = 0;
        clGetProgramBuildInfo(p, ctx->device, CL_PROGRAM_BUILD_LOG, 0, NULL, &log_size);
        char *log = malloc(log_size + 1);
        if (log) {
            clGetProgramBuildInfo(p, ctx->device, CL_PROGRAM_BUILD_LOG, log_size, log, NULL);
            log[log_size] = '\0';
            char *located = vct_kernel_log_locate(log, source);
            if (located) {
                free(log);
                log = located;
                log_size = strlen(log);
            }
        }
        if (log && ctx->log) {
            char *message = malloc(log_size + 256 + strlen(options));
            if (message) {
                sprintf(message, "build log for %s (options: %s):\n%s", file, options, log);
                ctx->log(ctx->log_user, message);
                free(message);
            }
        }
        clReleaseProgram(p);
        /* the log's start names the first error's file and line */
        vct_fail(err, VCT_ERR_OPENCL, "kernels: building %s failed with %s (%d) on %s:\n%.1500s",
                 file, vct_cl_error_name(rc), (int)rc, ctx->info.name,
                 log ? log : "(no build log)");
        free(log);
        return err->status;
    }
    *out = p;
    return VCT_OK;
}

int vct_program_get(vct_context *ctx, const char *file, const char *options, cl_program *out,
                    vct_error *err) {
    char mem_key[64];
    uint64_t h = hash_str(hash_str(0xcbf29ce484222325ull, file), options ? options : "");
    snprintf(mem_key, sizeof mem_key, "%016llx", (unsigned long long)h);
    for (int i = 0; i < ctx->program_count; ++i) {
        if (strcmp(ctx->programs[i].key, mem_key) == 0) {
            *out = ctx->programs[i].program;
            return VCT_OK;
        }
    }
    if (ctx->program_count >= VCT_MAX_PROGRAMS)
        return vct_fail(err, VCT_ERR_MEMORY,
                        "kernels: %s would be the %dth program variant of one context, more than "
                        "it holds: release the context and create another",
                        file, VCT_MAX_PROGRAMS + 1);

    char full_options[1024];
    snprintf(full_options, sizeof full_options, "-cl-std=CL1.2%s%s%s %s",
             device_has_fast_fma(ctx->device) ? " -DVCT_FAST_FMA" : "",
             device_wants_packets(ctx->device) ? " -DVCT_PACKETS" : "",
             vct_args_checked() ? " -cl-kernel-arg-info" : "", options ? options : "");
    char *source = vct_kernel_source_expand(file, err);
    if (!source)
        return err->status;
    double t0 = vct_now_ms();
    char key[40], path[1200];
    cache_key(ctx, source, full_options, key);
    snprintf(path, sizeof path, "%s/%s.bin", vct_cache_dir(), key);
    const char *no_cache = getenv("VCT_NO_CACHE");
    cl_program p = (no_cache && *no_cache == '1') ? NULL : load_cached(ctx, path);
    int rc = VCT_OK;
    if (p) {
        ctx->cache_hits++;
    } else {
        if (ctx->log) {
            char message[1536];
            snprintf(message, sizeof message,
                     "compiling kernels/%s for %s (once; then cached in %s)", file, ctx->info.name,
                     vct_cache_dir());
            ctx->log(ctx->log_user, message);
        }
        rc = build_from_source(ctx, file, source, full_options, &p, err);
        if (rc == VCT_OK) {
            ctx->cache_misses++;
            store_cached(p, path);
        }
    }
    ctx->build_ms += vct_now_ms() - t0;
    free(source);
    if (rc != VCT_OK)
        return rc;
    snprintf(ctx->programs[ctx->program_count].key, sizeof ctx->programs[0].key, "%s", mem_key);
    ctx->programs[ctx->program_count++].program = p;
    *out = p;
    return VCT_OK;
}

cl_kernel vct_kernel_create(vct_context *ctx, cl_program program, const char *name,
                            vct_error *err) {
    cl_int rc = CL_SUCCESS;
    cl_kernel k = clCreateKernel(program, name, &rc);
    if (rc != CL_SUCCESS) {
        vct_cl_check(err, rc, name, "clCreateKernel");
        return NULL;
    }
    (void)ctx;
    return k;
}

void vct_context_set_log(vct_context *ctx, vct_log_fn log, void *user) {
    ctx->log = log;
    ctx->log_user = user;
}

void vct_context_program_stats(const vct_context *ctx, vct_program_stats *stats) {
    stats->compiled = ctx->cache_misses;
    stats->cached = ctx->cache_hits;
    stats->ms = ctx->build_ms;
}

void vct_context_transfer_stats(const vct_context *ctx, vct_transfer_stats *stats) {
    *stats = ctx->transfers;
}
