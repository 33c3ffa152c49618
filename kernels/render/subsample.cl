/* Adaptive subsampling (seed 001): the image is covered by squares whose
 * corners are traced pixels. A square is packed as y0 << 16 | x0 and has a
 * size s; its corners are (x0, y0) and (x0 + s, y0 + s), clamped to the
 * image. Level by level: sub_fill fills every square whose four corner keys
 * agree with the bilinear interpolation of its corner radiances and flags
 * the others; the host compacts the flagged squares, sub_points lists the
 * five pixels that split each (edge midpoints and centre), which are traced,
 * and sub_split makes the four half-size squares of the next level. At size
 * 2 the five pixels are the last untraced ones of the square. */
#pragma OPENCL FP_CONTRACT OFF /* the interpolation as written, on every device */

inline uint2 square_of(uint packed) {
    return (uint2)(packed & 0xFFFFu, packed >> 16);
}

inline uint pack_square(uint x, uint y) {
    return y << 16 | x;
}

/* guard: per pixel, the projected size of the smallest object whose screen
 * box covers it (0xFFFF: none). A square that such an object touches is split
 * whatever its corners say while the object is less than twice the square's
 * size (an object that wide can still fall between the corners), so at the
 * last level every pixel near it is traced. */
/* With contrast > 0 the square's centre has been traced too (sub_centres):
 * it must share the corners' key and lie within the contrast of their
 * bilinear interpolation, which catches a peak (a light close to a wall)
 * whose corners are alike by symmetry. The centre keeps its traced value. */
__kernel void sub_fill(__global const uint *squares, uint n, uint size, uint width, uint height,
                       __global const uint *keys, __global const ushort *guard, float contrast,
                       __global float4 *image, __global uint *refine) {
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const uint2 q = square_of(squares[i]);
    if (q.x >= width || q.y >= height) { /* past the image's edge */
        refine[i] = 0u;
        return;
    }
    const uint x1 = min(q.x + size, width - 1u), y1 = min(q.y + size, height - 1u);
    const uint k00 = keys[q.y * width + q.x], k10 = keys[q.y * width + x1],
               k01 = keys[y1 * width + q.x], k11 = keys[y1 * width + x1];
    int small = 0;
    for (uint y = q.y; y <= y1 && !small; ++y)
        for (uint x = q.x; x <= x1 && !small; ++x)
            small = guard[y * width + x] < 2u * size;
    const float4 c00 = image[q.y * width + q.x], c10 = image[q.y * width + x1],
                 c01 = image[y1 * width + q.x], c11 = image[y1 * width + x1];
    /* With contrast > 0, corners whose radiance spreads by more than that
     * share of their mean also disagree (soft shadows, falloff). */
    const float4 lo = fmin(fmin(c00, c10), fmin(c01, c11)),
                 hi = fmax(fmax(c00, c10), fmax(c01, c11));
    const float4 mean = 0.25f * (c00 + c10 + c01 + c11);
    const float3 allowed = contrast * fmax(mean.xyz, (float3)(1e-6f));
    int flat = !(contrast > 0.0f) || all((hi - lo).xyz <= allowed);
    const uint xm = min(q.x + size / 2u, width - 1u), ym = min(q.y + size / 2u, height - 1u);
    const int centred = contrast > 0.0f && size > 2u;
    if (centred && flat) {
        const float fx = x1 > q.x ? (float)(xm - q.x) / (float)(x1 - q.x) : 0.0f;
        const float fy = y1 > q.y ? (float)(ym - q.y) / (float)(y1 - q.y) : 0.0f;
        const float4 top = c00 + (c10 - c00) * fx, bottom = c01 + (c11 - c01) * fx;
        const float4 predicted = top + (bottom - top) * fy;
        flat = keys[ym * width + xm] == k00 &&
               all(fabs(image[ym * width + xm].xyz - predicted.xyz) <= allowed);
    }
    const int agree = !small && flat && k00 == k10 && k00 == k01 && k00 == k11;
    refine[i] = (uint)(!agree && size > 1u);
    if (!agree)
        return;
    const float dx = (float)(x1 - q.x), dy = (float)(y1 - q.y);
    for (uint y = q.y; y <= y1; ++y)
        for (uint x = q.x; x <= x1; ++x) {
            if (((x == q.x || x == x1) && (y == q.y || y == y1)) || (centred && x == xm && y == ym))
                continue; /* the traced corners (and centre) stay as they are */
            const float fx = dx > 0.0f ? (float)(x - q.x) / dx : 0.0f;
            const float fy = dy > 0.0f ? (float)(y - q.y) / dy : 0.0f;
            const float4 top = c00 + (c10 - c00) * fx, bottom = c01 + (c11 - c01) * fx;
            image[y * width + x] = top + (bottom - top) * fy;
        }
}

/* The centre pixel of square i (clamped to the image), for sub_fill's
 * contrast test; wanted: 0 where it was traced already (at the image's edge
 * a clamped centre can be a corner). */
__kernel void sub_centres(__global const uint *squares, uint n, uint size, uint width, uint height,
                          __global const uint *traced, __global uint *points,
                          __global uint *wanted) {
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const uint2 q = square_of(squares[i]);
    const uint p = min(q.y + size / 2u, height - 1u) * width + min(q.x + size / 2u, width - 1u);
    points[i] = p;
    wanted[i] = traced[p] == 0u;
}

/* The squares being split at this level, marked in a map of the level's
 * cells (width / size + 2 per row) with the level's size. */
__kernel void sub_mark(__global const uint *squares, uint n, uint size, uint width,
                       __global uint *map) {
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const uint2 q = square_of(squares[i]);
    map[(q.y / size) * (width / size + 2u) + q.x / size] = size;
}

/* The five pixels that split square i (clamped to the image): the top and
 * left edges' midpoints, the centre, the right and bottom edges' midpoints.
 * wanted: 0 for a pixel traced already (a contrast centre, a clamped
 * corner) or one a neighbour being split at this level traces (the right
 * and bottom midpoints are its left and top ones), so that no ray is cast
 * twice. */
__kernel void sub_points(__global const uint *squares, uint n, uint size, uint width, uint height,
                         __global const uint *map, __global const uint *traced,
                         __global uint *points, __global uint *wanted) {
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const uint2 q = square_of(squares[i]);
    const uint h = size / 2u;
    const uint xm = min(q.x + h, width - 1u), ym = min(q.y + h, height - 1u);
    const uint x1 = min(q.x + size, width - 1u), y1 = min(q.y + size, height - 1u);
    const uint cols = width / size + 2u, cell = (q.y / size) * cols + q.x / size;
    const int right_split = q.x + size < width && map[cell + 1u] == size;
    const int below_split = q.y + size < height && map[cell + cols] == size;
    const uint p[5] = {q.y * width + xm, ym * width + q.x, ym * width + xm, ym * width + x1,
                       y1 * width + xm};
    const int mine[5] = {1, 1, 1, !right_split && x1 != xm, !below_split && y1 != ym};
    for (int k = 0; k < 5; ++k) {
        points[5 * i + k] = p[k];
        wanted[5 * i + k] = mine[k] && traced[p[k]] == 0u;
    }
}

__kernel void sub_split(__global const uint *squares, uint n, uint size, __global uint *children) {
    const uint i = get_global_id(0);
    if (i >= n)
        return;
    const uint2 q = square_of(squares[i]);
    const uint h = size / 2u;
    children[4 * i] = pack_square(q.x, q.y);
    children[4 * i + 1] = pack_square(q.x + h, q.y);
    children[4 * i + 2] = pack_square(q.x, q.y + h);
    children[4 * i + 3] = pack_square(q.x + h, q.y + h);
}
