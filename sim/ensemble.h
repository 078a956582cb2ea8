/* N independent ensembles and their statistics (docs/theory.md §1.3).
 *
 * Ensembles run in parallel with OpenMP.  Ensemble j always uses random
 * stream (seed, j), and the sums are formed in fixed blocks of ensembles
 * merged in index order, so every number is the same for any thread count.
 * Built with GDSMC_MPI and run under mpiexec, the blocks are shared out
 * across the MPI ranks too, with the same numbers on every rank as on one
 * process (ensemble.c explains how).
 * For each output time m and observable k:
 *   mean  eta1 = (1/N) Σ_j xi_j
 *   var   eta2 - eta1^2 (population variance, computed stably: Welford within
 *         a block, Chan et al. to merge blocks)
 *   ci    c = lambda_p sqrt(var / N), lambda_p = 3.2 (p = 0.999): the
 *         confidence half-width of paper A Eq. (25).
 * The steady-state time averages (steady.h) get the same statistics over the
 * ensembles: each ensemble's time average is one independent sample, so their
 * confidence half-width is honest however correlated the samples in time.
 */
#ifndef GDSMC_SIM_ENSEMBLE_H
#define GDSMC_SIM_ENSEMBLE_H

#include <stddef.h>

#include "engine.h"

#define SIM_LAMBDA_P 3.2

#define SIM_MISSING_EVENTS 1u
#define SIM_MISSING_VIOLATIONS 2u
#define SIM_MISSING_COLLISIONS 4u   /* and the background and normals counts */

typedef struct sim_ensemble_result {
    size_t outputs;      /* rows */
    size_t ensembles;    /* N */
    size_t n;            /* particles per ensemble */
    double *t;           /* [outputs] output times */
    size_t observables;  /* per output row (sim_engine_observables) */
    double *mean;        /* [outputs * observables], observable k of row m at m * observables + k */
    double *var;         /* [outputs * observables] */
    double *ci;          /* [outputs * observables] */
    size_t nsteady;      /* steady-state quantities (0 without [steady]) */
    double *steady_mean; /* [nsteady], pointing into mean/var/ci after the rows */
    double *steady_var;
    double *steady_ci;
    sim_counts counts;   /* summed over ensembles */
    unsigned missing;    /* counts a result from elsewhere (an external solver) lacks:
                            SIM_MISSING_EVENTS, SIM_MISSING_VIOLATIONS,
                            SIM_MISSING_COLLISIONS; 0 from the engine */
    double cpu_seconds;  /* process CPU time, all threads (and MPI ranks) */
    double wall_seconds; /* with MPI, the slowest rank's */
    int threads;         /* OpenMP threads used (summed over MPI ranks) */
} sim_ensemble_result;

/* Called after each finished block of ensembles, from one thread at a time. */
typedef void (*sim_progress_fn)(size_t done, size_t total, void *ctx);

/* Run the scene's N ensembles.  With GDSMC_MPI, once MPI is initialised, a
 * collective call: every rank of MPI_COMM_WORLD makes it with the same scene,
 * from the thread that initialised MPI, outside OpenMP parallel regions, and
 * all get the same result and status.  res is filled (free with
 * sim_ensemble_result_free, also after a failure).  progress may be NULL.
 * Refuses, before allocating anything, a run whose particles (n per thread;
 * with MPI, the threads of all ranks on this machine) and statistics would not fit in the machine's memory: SIM_ENOMEM naming
 * particles.n with the estimate.  Returns SIM_ECANCELED when a stop was
 * requested (checked before every ensemble); res is then incomplete. */
sim_status sim_ensemble_run(const sim_engine *engine, sim_progress_fn progress, void *ctx,
                            sim_ensemble_result *res, sim_error *err);

void sim_ensemble_result_free(sim_ensemble_result *res);

/* Ask running and later calls of sim_ensemble_run to stop (SIGINT, SIGTERM):
 * async-signal-safe, it only sets a flag.  sim_ensemble_clear_stop resets it. */
void sim_ensemble_request_stop(void);
void sim_ensemble_clear_stop(void);
int sim_ensemble_stop_requested(void);

/* Bytes that sim_ensemble_run would hold at once for engine's scene on
 * `threads` threads: each thread's workspace (n particles) and the
 * statistics of every output.  The memory check above uses it. */
double sim_ensemble_memory_estimate(const sim_engine *engine, int threads);

/* Accessors: observable k at output m. */
static inline double sim_result_mean(const sim_ensemble_result *r, size_t m, int k)
{
    return r->mean[m * r->observables + (size_t)k];
}
static inline double sim_result_ci(const sim_ensemble_result *r, size_t m, int k)
{
    return r->ci[m * r->observables + (size_t)k];
}

static inline double sim_result_var(const sim_ensemble_result *r, size_t m, int k)
{
    return r->var[m * r->observables + (size_t)k];
}

static inline double sim_result_steady_mean(const sim_ensemble_result *r, size_t k)
{
    return r->steady_mean[k];
}
static inline double sim_result_steady_ci(const sim_ensemble_result *r, size_t k)
{
    return r->steady_ci[k];
}

#endif
