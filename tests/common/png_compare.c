/* png_compare TEST.png REFERENCE.png TOLERANCE: the two images have the same
 * size and no channel differs by more than TOLERANCE (8-bit steps); the
 * reference is not black, so that two empty images cannot agree. */
#include <stdio.h>
#include <stdlib.h>

#include <stb/stb_image.h>

int main(int argc, char **argv) {
    if (argc != 4) {
        fprintf(stderr, "usage: png_compare TEST.png REFERENCE.png TOLERANCE\n");
        return 2;
    }
    int w[2], h[2], n;
    unsigned char *px[2];
    for (int i = 0; i < 2; ++i) {
        px[i] = stbi_load(argv[1 + i], &w[i], &h[i], &n, 3);
        if (!px[i]) {
            fprintf(stderr, "png_compare: cannot read %s: %s\n", argv[1 + i],
                    stbi_failure_reason());
            return 1;
        }
    }
    const int tolerance = atoi(argv[3]);
    if (w[0] != w[1] || h[0] != h[1]) {
        fprintf(stderr, "png_compare: %dx%d against %dx%d\n", w[0], h[0], w[1], h[1]);
        return 1;
    }
    const size_t values = 3 * (size_t)w[0] * h[0];
    int worst = 0, brightest = 0;
    size_t over = 0, differ = 0;
    for (size_t i = 0; i < values; ++i) {
        const int d = abs((int)px[0][i] - (int)px[1][i]);
        worst = d > worst ? d : worst;
        over += d > tolerance;
        differ += d > 0;
        brightest = px[1][i] > brightest ? px[1][i] : brightest;
    }
    printf("png_compare %s: %dx%d, %zu of %zu values differ, largest difference %d (tolerance "
           "%d)\n",
           argv[1], w[0], h[0], differ, values, worst, tolerance);
    stbi_image_free(px[0]);
    stbi_image_free(px[1]);
    if (brightest == 0) {
        fprintf(stderr, "png_compare: the reference is black\n");
        return 1;
    }
    return over ? 1 : 0;
}
