/* --summary FILE.json: the peaks of every output without the time history (simulate_me.h). */
#ifndef FMI2SIM_SUMMARY_H
#define FMI2SIM_SUMMARY_H

#include <stddef.h>
#include "simulate_me.h"

/* 0 on success; -1 with a one-line reason in err. */
int summary_write_json(const char *path, const sim_summary *sum, const sim_stats *st, char *err, size_t n);

void summary_free(sim_summary *sum);

#endif
