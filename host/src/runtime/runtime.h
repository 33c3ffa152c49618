/* Everything a stage needs from the runtime: errors, the context, programs,
 * buffers, stages and launches. */
#ifndef VCT_RUNTIME_RUNTIME_H
#define VCT_RUNTIME_RUNTIME_H

#include "runtime/buffer.h"
#include "runtime/context.h"
#include "runtime/error.h"
#include "program/launch.h"
#include "program/program.h"
#include "runtime/stats.h"

#endif
