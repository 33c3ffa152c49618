/* vct: which declarations the shared library exports. Everything else in
 * libvct.so is hidden (the build compiles with hidden visibility). */
#ifndef VCT_API_EXPORT_H
#define VCT_API_EXPORT_H

#if defined(__GNUC__) || defined(__clang__)
#define VCT_API __attribute__((visibility("default")))
#else
#define VCT_API
#endif

#endif
