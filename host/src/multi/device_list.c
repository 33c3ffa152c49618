/* Device lists: each entry an index or a name, or a class of devices. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "multi/device_list.h"

#define MAX_LISTED 64

/* Appends "; the devices are: [0] name (CPU), ..." to err's message. */
static int refuse(vct_error *err, const vct_device_info *all, int n, const char *fmt,
                  const char *what) {
    char list[1024] = "";
    size_t used = 0;
    for (int i = 0; i < n && used < sizeof list; ++i)
        used += (size_t)snprintf(list + used, sizeof list - used, "%s[%d] %s (%s)", i ? ", " : "",
                                 all[i].index, all[i].name, all[i].is_gpu ? "GPU" : "CPU");
    char head[256];
    snprintf(head, sizeof head, fmt, what);
    return vct_fail(err, VCT_ERR_INPUT, "devices: %s; the devices are: %s", head,
                    n ? list : "none");
}

static int add(int *indices, int count, int max, int index, const vct_device_info *all, int n,
               vct_error *err) {
    for (int i = 0; i < count; ++i)
        if (indices[i] == index) {
            char what[32];
            snprintf(what, sizeof what, "%d", index);
            refuse(err, all, n, "device %s is named twice", what);
            return -1;
        }
    if (count >= max) {
        vct_fail(err, VCT_ERR_INPUT, "devices: at most %d devices in one group", max);
        return -1;
    }
    indices[count] = index;
    return count + 1;
}

int vct_device_list_parse(const char *list, int *indices, int max, vct_error *err) {
    vct_device_info all[MAX_LISTED];
    const int n = vct_list_devices(all, MAX_LISTED, err);
    if (n < 0)
        return -1;
    if (!list || !*list)
        list = getenv("VCT_DEVICE");
    if (!list || !*list) {
        cl_platform_id platform;
        cl_device_id device;
        const int pick = vct_device_pick(NULL, &platform, &device, err);
        return pick < 0 ? -1 : add(indices, 0, max, pick, all, n, err);
    }
    const int every = strcasecmp(list, "all") == 0, gpus = strcasecmp(list, "gpu") == 0,
              cpus = strcasecmp(list, "cpu") == 0;
    int count = 0;
    if (every || gpus || cpus) {
        for (int i = 0; i < n && count >= 0; ++i)
            if (every || (gpus && all[i].is_gpu) || (cpus && !all[i].is_gpu))
                count = add(indices, count, max, i, all, n, err);
        if (count == 0)
            return refuse(err, all, n, "no device is a %s",
                          gpus   ? "GPU"
                          : cpus ? "CPU"
                                 : "device"),
                   -1;
        return count;
    }
    char copy[1024];
    snprintf(copy, sizeof copy, "%s", list);
    char *save = NULL;
    for (char *item = strtok_r(copy, ",", &save); item && count >= 0;
         item = strtok_r(NULL, ",", &save)) {
        while (*item == ' ')
            ++item;
        cl_platform_id platform;
        cl_device_id device;
        vct_error quiet = {0};
        const int pick = vct_device_pick(item, &platform, &device, &quiet);
        if (pick < 0)
            return refuse(err, all, n, "no device \"%s\"", item), -1;
        count = add(indices, count, max, pick, all, n, err);
    }
    if (count == 0)
        return refuse(err, all, n, "the list \"%s\" names no device", list), -1;
    return count;
}
