/* gdsmc bench: throughput of the engine against a bare floor loop measured
 * in the same run (issue 4, SPEC §9).
 *
 * Cases, each on one core (one ensemble at a time, no OpenMP):
 *   floor     the minimal hard-sphere kernel: two random indices, |g|, the
 *             acceptance test against a fixed U_max, a unit vector and the
 *             collision arithmetic; no waiting times, majorants or counters
 *   hs-relax  the engine on elastic hard spheres in one homogeneous cell,
 *             relaxing from two counter-streaming Maxwellians
 *   grw-ex3   paper A Ex 3 (Maxwell molecules, white-noise heating)
 *   brs-ex4   paper B Ex 4 (hard spheres, Algorithm 2 with its background)
 * Rates are events (accepted collisions for floor and hs-relax, candidate
 * events for the paper scenes) per CPU second of the thread that ran them;
 * floor_ratio = a row's rate / the floor's rate at the same n.
 */
#ifndef GDSMC_VFY_BENCH_H
#define GDSMC_VFY_BENCH_H

#include <stddef.h>
#include <stdio.h>

#include "error.h"
#include "table.h"

typedef struct vfy_bench_options {
    size_t max_n;           /* largest n of the hs-relax series (1e3 ... 1e7) */
    double seconds;         /* target CPU seconds per row (about) */
    const char *scene_dir;  /* where grw-ex3.ini and brs-ex4.ini are */
    FILE *progress;         /* progress lines, or NULL */
} vfy_bench_options;

/* The columns of the bench table, in order. */
#define VFY_BENCH_COLUMNS                                                                     \
    "case", "n", "events", "cpu_s", "events_per_s", "ns_per_event", "floor_ratio",          \
        "acceptance", "bytes_per_particle", "peak_rss_mb"

/* Run every case into table (initialised here with VFY_BENCH_COLUMNS; free
 * it with vfy_table_free).  Returns SIM_OK, or an error with msg. */
sim_status vfy_bench_run(const vfy_bench_options *o, vfy_table *table, char *msg,
                         size_t msglen);

#endif
