/* gdsmc bench: throughput of the engine against a bare floor loop measured
 * in the same run (issue 4, docs/bench.md).
 *
 * Cases, each on one core (one ensemble at a time) unless said otherwise:
 *   floor     the engine's hard-sphere kernel without its bookkeeping: the
 *             same index stream, two-stage acceptance test, unit vector and
 *             collision arithmetic (and the same running velocity bound),
 *             but no waiting times or Poisson counts, rates, counters or
 *             output times; run for as many accepted collisions as the
 *             engine's row beside it, on the same initial state
 *   hs-relax  the engine on elastic hard spheres in one homogeneous cell,
 *             relaxing from two counter-streaming Maxwellians, n = 1e3 ...
 *   floor-maxwell  the engine's Maxwell kernel without its bookkeeping
 *             (pair, unit vector, collision rule), n = 1024
 *   grw-ex3, brs-ex2  paper A Ex 3 (Maxwell molecules, white-noise heating,
 *             81 output times) and paper B Ex 2 (Maxwell kernels with a
 *             background, 513 output times) at n = 1024 as their scenes run
 *             them, and -bare: the same without heating and without output
 *             times between start and end
 *   brs-ex4   paper B Ex 4 (hard spheres, Algorithm 2 with its background)
 *   ms-timestep-white, ms-timestep-gaussian  the time-step scheme on paper
 *             C's gas (h = 0.05, Strang, pairs accepted by |g|) with white
 *             noise and with the keep-T Gaussian thermostat, n = 2e5
 *   hcs-jump  the exact jump scheme with the keep-T Gaussian thermostat (the
 *             homogeneous cooling state in scaled variables), n = 2e5
 * The rows with a `-bare` partner and the n = 2e5 rows carry a breakdown in
 * ns per collision (ns_events, ns_flows, ns_observation: breakdown_rows).
 *   grw-ex3-ensembles  paper A Ex 3 with N = 10 000 ensembles (fewer for
 *             short runs) on 1 and on 2 OpenMP threads: wall time and the
 *             speed-up
 * Rates are events (accepted collisions for the floors, hs-relax and the
 * rows with a breakdown, candidate events for brs-ex4) per CPU second of the thread that
 * ran them, or per wall second for the ensemble rows; floor_ratio = a row's
 * rate / the floor's rate at the same n (the paper scenes: the floor at
 * n = 1000).  Every figure is one measurement on a machine that may be
 * shared: the floor beside each row is measured in the same process, minutes
 * apart at most.
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
    const char *scene_dir;  /* where grw-ex3.ini, brs-ex4.ini, ms-white-noise.ini are */
    FILE *progress;         /* progress lines, or NULL */
} vfy_bench_options;

/* The columns of the bench table, in order. */
#define VFY_BENCH_COLUMNS                                                                     \
    "case", "n", "threads", "events", "cpu_s", "wall_s", "events_per_s", "ns_per_event",    \
        "floor_ratio", "acceptance", "speedup", "bytes_per_particle", "peak_rss_mb",          \
        "ns_events", "ns_flows", "ns_observation"

/* Run every case into table (initialised here with VFY_BENCH_COLUMNS; free
 * it with vfy_table_free).  Returns SIM_OK, or an error with msg. */
sim_status vfy_bench_run(const vfy_bench_options *o, vfy_table *table, char *msg,
                         size_t msglen);

#endif
