/* A device list as users write it ("0,2", "all", "gpu", "cpu", names) read
 * into device indices. */
#ifndef VCT_MULTI_DEVICE_LIST_H
#define VCT_MULTI_DEVICE_LIST_H

#include "runtime/runtime.h"

/* Fills indices (at most max) and returns their count, or -1 with err
 * naming the devices there are. */
int vct_device_list_parse(const char *list, int *indices, int max, vct_error *err);

#endif
