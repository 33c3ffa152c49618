/* OBJ files checked before assimp parses them (obj_check.c). */
#ifndef VCT_OBJ_CHECK_H
#define VCT_OBJ_CHECK_H

#include "runtime/runtime.h"

/* Refuses an .obj whose geometry lines hold bytes no number can; nothing
 * for other formats. */
int vct_obj_precheck(const char *path, vct_error *err);

#endif
