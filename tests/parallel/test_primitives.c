/* Scan, compaction, radix sort and segmented sum against plain-C references,
 * for edge sizes and adversarial inputs. */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "runtime/runtime.h"

static const uint32_t all_sizes[] = {0, 1, 2, 255, 256, 257, (1u << 20) + 3, 1u << 24};
static uint32_t sizes[8];
static size_t NSIZES;

/* VCT_TEST_MAX_N trims the sizes (used where a slow kernel shape is checked). */
static void pick_sizes(void) {
    const char *max_env = getenv("VCT_TEST_MAX_N");
    uint64_t max = max_env ? strtoull(max_env, NULL, 10) : UINT32_MAX;
    for (size_t i = 0; i < sizeof all_sizes / sizeof all_sizes[0]; ++i)
        if (all_sizes[i] <= max)
            sizes[NSIZES++] = all_sizes[i];
}

enum pattern { RANDOM, ALL_EQUAL, SORTED, REVERSED, PATTERNS };
static const char *pattern_name[] = {"random", "all-equal", "sorted", "reversed"};

static void fill(uint32_t *v, uint32_t n, enum pattern p, uint32_t mask, uint64_t *seed) {
    for (uint32_t i = 0; i < n; ++i) {
        switch (p) {
        case RANDOM:
            v[i] = (uint32_t)check_rand(seed) & mask;
            break;
        case ALL_EQUAL:
            v[i] = 7u & mask;
            break;
        case SORTED:
            v[i] = (uint32_t)((uint64_t)i * mask / (n ? n : 1));
            break;
        default:
            v[i] = (uint32_t)((uint64_t)(n - 1 - i) * mask / (n ? n : 1));
            break;
        }
    }
}

static cl_mem upload(vct_context *ctx, const void *data, size_t bytes) {
    vct_error err = {0};
    cl_mem m = vct_buffer_create(ctx, "test", "input", bytes, CL_MEM_READ_WRITE, NULL, &err);
    REQUIRE_OK(m ? VCT_OK : err.status, err);
    REQUIRE_OK(vct_buffer_write(ctx, "test", m, 0, bytes, data, &err), err);
    return m;
}

static void test_scan(vct_context *ctx) {
    uint64_t seed = 1;
    for (size_t s = 0; s < NSIZES; ++s) {
        uint32_t n = sizes[s];
        uint32_t *in = malloc((n + 1) * 4ull), *out = malloc((n + 1) * 4ull);
        for (int p = 0; p < PATTERNS; ++p) {
            fill(in, n, (enum pattern)p, 0xff, &seed);
            for (int inclusive = 0; inclusive < 2; ++inclusive) {
                vct_error err = {0};
                cl_mem a = upload(ctx, in, n * 4ull + 4);
                cl_mem b = vct_buffer_create(ctx, "test", "out", n * 4ull + 4, CL_MEM_READ_WRITE,
                                             NULL, &err);
                uint64_t total = 0;
                REQUIRE_OK(vct_scan_u32(ctx, a, b, n, inclusive, &total, &err), err);
                REQUIRE_OK(vct_buffer_read(ctx, "test", b, 0, n * 4ull, out, &err), err);
                uint64_t run = 0;
                uint32_t bad = 0, first_bad = 0;
                for (uint32_t i = 0; i < n; ++i) {
                    uint64_t expect = inclusive ? run + in[i] : run;
                    run += in[i];
                    if (out[i] != (uint32_t)expect && bad++ == 0)
                        first_bad = i;
                }
                CHECK(bad == 0, "scan n=%u %s inclusive=%d: %u wrong, first at %u", n,
                      pattern_name[p], inclusive, bad, first_bad);
                CHECK(total == run, "scan n=%u total %llu expected %llu", n,
                      (unsigned long long)total, (unsigned long long)run);
                vct_buffer_release(ctx, a);
                vct_buffer_release(ctx, b);
            }
        }
        free(in);
        free(out);
    }
}

static void test_scan_large_in_place(vct_context *ctx) {
    const uint32_t n = (1u << 26) + 5;
    uint32_t *in = malloc(n * 4ull), *out = malloc(n * 4ull);
    uint64_t seed = 99;
    fill(in, n, RANDOM, 0x3f, &seed);
    vct_error err = {0};
    cl_mem a = upload(ctx, in, n * 4ull);
    uint64_t total = 0;
    REQUIRE_OK(vct_scan_u32(ctx, a, a, n, 0, &total, &err), err);
    REQUIRE_OK(vct_buffer_read(ctx, "test", a, 0, n * 4ull, out, &err), err);
    uint64_t run = 0;
    uint32_t bad = 0;
    for (uint32_t i = 0; i < n; ++i) {
        bad += out[i] != (uint32_t)run;
        run += in[i];
    }
    CHECK(bad == 0 && total == run, "in-place scan of 2^26+5: %u wrong", bad);
    vct_buffer_release(ctx, a);
    free(in);
    free(out);
}

static void test_scan_overflow(vct_context *ctx) {
    const uint32_t n = (1u << 20) + 1;
    uint32_t *in = malloc(n * 4ull);
    for (uint32_t i = 0; i < n; ++i)
        in[i] = 1u << 12; /* total 2^32 + 2^12: one past what 32 bits hold */
    vct_error err = {0};
    cl_mem a = upload(ctx, in, n * 4ull);
    uint64_t total = 0;
    int rc = vct_scan_u32(ctx, a, a, n, 0, &total, &err);
    CHECK(rc == VCT_ERR_OVERFLOW, "overflowing scan returned %d (%s)", rc, err.message);
    CHECK(total == (uint64_t)n << 12, "overflow total %llu", (unsigned long long)total);
    CHECK(strstr(err.message, "exceeds 32 bits") != NULL, "message: %s", err.message);
    vct_buffer_release(ctx, a);
    free(in);
}

static void test_compact(vct_context *ctx) {
    uint64_t seed = 5;
    for (size_t s = 0; s < NSIZES - 1; ++s) {
        uint32_t n = sizes[s];
        uint32_t *in = malloc(n * 4ull + 4), *flags = malloc(n * 4ull + 4),
                 *out = malloc(n * 4ull + 4);
        for (int mode = 0; mode < 3; ++mode) {
            for (uint32_t i = 0; i < n; ++i) {
                in[i] = (uint32_t)check_rand(&seed);
                flags[i] = mode == 0 ? (uint32_t)(check_rand(&seed) % 3) * 0x10001u
                                     : (mode == 1 ? 0u : 0xffffffffu);
            }
            vct_error err = {0};
            cl_mem a = upload(ctx, in, n * 4ull + 4), f = upload(ctx, flags, n * 4ull + 4);
            cl_mem o =
                vct_buffer_create(ctx, "test", "out", n * 4ull + 4, CL_MEM_READ_WRITE, NULL, &err);
            uint32_t count = 0;
            REQUIRE_OK(vct_compact_u32(ctx, a, f, o, n, &count, &err), err);
            REQUIRE_OK(vct_buffer_read(ctx, "test", o, 0, count * 4ull, out, &err), err);
            uint32_t k = 0, bad = 0;
            for (uint32_t i = 0; i < n; ++i)
                if (flags[i])
                    bad += (k < count && out[k] != in[i]), ++k;
            CHECK(k == count && bad == 0, "compact n=%u mode %d: count %u vs %u, %u wrong", n, mode,
                  count, k, bad);
            vct_buffer_release(ctx, a);
            vct_buffer_release(ctx, f);
            vct_buffer_release(ctx, o);
        }
        free(in);
        free(flags);
        free(out);
    }
}

/* A stable sort's output, checked exactly in O(n): keys non-decreasing, values
 * (the input indices) a permutation whose original keys match, and equal keys
 * keeping their input order. */
static uint32_t count_sort_errors(const uint64_t *orig, const uint64_t *keys,
                                  const uint32_t *values, uint32_t n, uint32_t *first) {
    uint8_t *seen = calloc(n + 1, 1);
    uint32_t bad = 0;
    for (uint32_t i = 0; i < n; ++i) {
        int ok = values[i] < n && !seen[values[i]] && orig[values[i]] == keys[i];
        if (ok)
            seen[values[i]] = 1;
        if (i > 0)
            ok = ok &&
                 (keys[i - 1] < keys[i] || (keys[i - 1] == keys[i] && values[i - 1] < values[i]));
        if (!ok && bad++ == 0)
            *first = i;
    }
    free(seen);
    return bad;
}

static void test_sort(vct_context *ctx, int key64) {
    uint64_t seed = 11;
    for (size_t s = 0; s < NSIZES; ++s) {
        uint32_t n = sizes[s];
        if (key64 && n > (1u << 22))
            continue;
        for (int p = 0; p < PATTERNS; ++p) {
            for (int narrow = 0; narrow < 2; ++narrow) {
                /* narrow: keys below 2^13 sorted on 13 bits, as the grid does. */
                int bits = narrow ? 13 : (key64 ? 64 : 32);
                uint32_t *k32 = malloc(n * 4ull + 4);
                uint64_t *k64 = malloc(n * 8ull + 8);
                uint32_t *val = malloc(n * 4ull + 4);
                uint64_t *orig = malloc(n * 8ull + 8), *got = malloc(n * 8ull + 8);
                fill(k32, n, (enum pattern)p, narrow ? 0x1fff : 0xffffffffu, &seed);
                for (uint32_t i = 0; i < n; ++i) {
                    k64[i] =
                        narrow ? k32[i] : ((uint64_t)k32[i] << 32 | (uint32_t)check_rand(&seed));
                    if (p == SORTED || p == REVERSED)
                        k64[i] = narrow ? k32[i] : (uint64_t)k32[i] << 32;
                    val[i] = i;
                    orig[i] = key64 ? k64[i] : k32[i];
                }
                vct_error err = {0};
                cl_mem kb =
                    upload(ctx, key64 ? (void *)k64 : (void *)k32, n * (key64 ? 8ull : 4ull) + 8);
                cl_mem vb = upload(ctx, val, n * 4ull + 4);
                if (key64)
                    REQUIRE_OK(vct_sort_pairs_u64(ctx, kb, vb, n, bits, &err), err);
                else
                    REQUIRE_OK(vct_sort_pairs_u32(ctx, kb, vb, n, bits, &err), err);
                REQUIRE_OK(vct_buffer_read(ctx, "test", kb, 0, n * (key64 ? 8ull : 4ull),
                                           key64 ? (void *)k64 : (void *)k32, &err),
                           err);
                REQUIRE_OK(vct_buffer_read(ctx, "test", vb, 0, n * 4ull, val, &err), err);
                for (uint32_t i = 0; i < n; ++i)
                    got[i] = key64 ? k64[i] : k32[i];
                uint32_t first = 0;
                uint32_t bad = count_sort_errors(orig, got, val, n, &first);
                CHECK(bad == 0, "sort%s n=%u %s bits=%d: %u wrong, first at %u",
                      key64 ? "64" : "32", n, pattern_name[p], bits, bad, first);
                vct_buffer_release(ctx, kb);
                vct_buffer_release(ctx, vb);
                free(k32);
                free(k64);
                free(val);
                free(orig);
                free(got);
            }
        }
    }
}

static void test_segmented_sum(vct_context *ctx) {
    uint64_t seed = 17;
    for (size_t s = 0; s < NSIZES - 1; ++s) {
        uint32_t n = sizes[s];
        uint32_t *keys = malloc(n * 4ull + 4), *out_keys = malloc(n * 4ull + 4);
        float *vals = malloc(n * 16ull + 16), *sums = malloc(n * 16ull + 16),
              *ref = malloc(n * 16ull + 16);
        uint32_t key = 0;
        for (uint32_t i = 0; i < n; ++i) {
            if (check_rand(&seed) % 5 == 0)
                key += 1 + (uint32_t)(check_rand(&seed) % 3);
            keys[i] = key;
            for (int c = 0; c < 4; ++c)
                vals[i * 4 + c] = check_randf(&seed) * 2.0f - 0.5f;
        }
        uint32_t runs_ref = 0;
        for (uint32_t i = 0; i < n; ++i) {
            if (i == 0 || keys[i] != keys[i - 1]) {
                out_keys[runs_ref] = keys[i];
                for (int c = 0; c < 4; ++c)
                    ref[runs_ref * 4 + c] = 0.0f;
                ++runs_ref;
            }
            for (int c = 0; c < 4; ++c)
                ref[(runs_ref - 1) * 4 + c] += vals[i * 4 + c];
        }
        vct_error err = {0};
        cl_mem kb = upload(ctx, keys, n * 4ull + 4), vb = upload(ctx, vals, n * 16ull + 16);
        cl_mem ok =
            vct_buffer_create(ctx, "test", "keys", n * 4ull + 4, CL_MEM_READ_WRITE, NULL, &err);
        cl_mem os =
            vct_buffer_create(ctx, "test", "sums", n * 16ull + 16, CL_MEM_READ_WRITE, NULL, &err);
        uint32_t runs = 0;
        REQUIRE_OK(vct_segmented_sum_f4(ctx, kb, vb, n, ok, os, &runs, &err), err);
        CHECK(runs == runs_ref, "segmented n=%u: %u runs, expected %u", n, runs, runs_ref);
        uint32_t *got_keys = malloc(runs * 4ull + 4);
        REQUIRE_OK(vct_buffer_read(ctx, "test", ok, 0, runs * 4ull, got_keys, &err), err);
        REQUIRE_OK(vct_buffer_read(ctx, "test", os, 0, runs * 16ull, sums, &err), err);
        uint32_t bad = 0;
        for (uint32_t r = 0; r < runs && r < runs_ref; ++r) {
            bad += got_keys[r] != out_keys[r];
            bad += memcmp(&sums[r * 4], &ref[r * 4], 16) != 0; /* bit-exact: same order */
        }
        CHECK(bad == 0, "segmented n=%u: %u runs differ", n, bad);
        vct_buffer_release(ctx, kb);
        vct_buffer_release(ctx, vb);
        vct_buffer_release(ctx, ok);
        vct_buffer_release(ctx, os);
        free(keys);
        free(out_keys);
        free(vals);
        free(sums);
        free(ref);
        free(got_keys);
    }
}

int main(void) {
    pick_sizes();
    vct_context *ctx = check_context();
    printf("device: %s (work-group %zu, radix bits %d)\n", vct_context_device(ctx)->name,
           ctx->scan_group_size, ctx->radix_bits);
    test_scan(ctx);
    if (sizes[NSIZES - 1] >= (1u << 24))
        test_scan_large_in_place(ctx);
    test_scan_overflow(ctx);
    test_compact(ctx);
    test_sort(ctx, 0);
    test_sort(ctx, 1);
    test_segmented_sum(ctx);
    vct_context_release(ctx);
    return check_exit("test_primitives");
}
