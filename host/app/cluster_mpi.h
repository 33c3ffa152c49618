/* What the MPI side of vct render shares between its files. */
#ifndef VCT_APP_CLUSTER_MPI_H
#define VCT_APP_CLUSTER_MPI_H

#include <stdint.h>

#include "vct/vct.h"

/* 1 when MPI lets rank 0 serve the others from a second thread. */
int cli_cluster_threads(void);
/* Prints `what: err` naming this rank and its host, then ends the whole
 * job (a rank that stops would leave the others waiting). */
void cli_cluster_fail(const char *what, const vct_error *err) __attribute__((noreturn));
/* Bytes this rank handed to MPI to send, for --stats. */
void cli_cluster_count_sent(uint64_t bytes);
uint64_t cli_cluster_sent(void);

#endif
