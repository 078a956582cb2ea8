#include "ensemble.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Running mean and sum of squared deviations of one block of ensembles. */
typedef struct block_stats {
    double count;
    double *mean;  /* [outputs * SIM_OBS_COUNT] */
    double *m2;
} block_stats;

static double now(clockid_t clock)
{
    struct timespec ts;
    clock_gettime(clock, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Ensembles per block: a function of N only (never of the thread count), so
 * that the order of every floating-point sum is fixed; small enough that the
 * blocks keep both cores busy. */
static size_t block_size(size_t ensembles)
{
    size_t b = ensembles / 64;
    return b < 1 ? 1 : b > 32 ? 32 : b;
}

static void welford_add(block_stats *b, const double *x, size_t len)
{
    b->count += 1.0;
    for (size_t i = 0; i < len; i++) {
        double delta = x[i] - b->mean[i];
        b->mean[i] += delta / b->count;
        b->m2[i] += delta * (x[i] - b->mean[i]);
    }
}

/* Merge b into a (Chan, Golub, LeVeque). */
static void merge(block_stats *a, const block_stats *b, size_t len)
{
    if (b->count == 0.0)
        return;
    double total = a->count + b->count;
    for (size_t i = 0; i < len; i++) {
        double delta = b->mean[i] - a->mean[i];
        a->mean[i] += delta * b->count / total;
        a->m2[i] += b->m2[i] + delta * delta * a->count * b->count / total;
    }
    a->count = total;
}

void sim_ensemble_result_free(sim_ensemble_result *res)
{
    free(res->t);
    free(res->mean);
    free(res->var);
    free(res->ci);
    memset(res, 0, sizeof *res);
}

sim_status sim_ensemble_run(const sim_engine *engine, sim_progress_fn progress, void *ctx,
                            sim_ensemble_result *res, sim_error *err)
{
    const sim_scene *scene = sim_engine_scene(engine);
    const size_t outputs = scene->outputs, N = scene->particles.ensembles;
    /* the rows, then the steady-state time averages of each run */
    const size_t rows_len = outputs * SIM_OBS_COUNT, nsteady = sim_engine_steady_count(engine);
    const size_t len = rows_len + nsteady;
    const size_t bsize = block_size(N), nblocks = (N + bsize - 1) / bsize;

    memset(res, 0, sizeof *res);
    res->outputs = outputs;
    res->ensembles = N;
    res->n = scene->particles.n;
    res->t = malloc(outputs * sizeof *res->t);
    res->mean = calloc(len, sizeof *res->mean);
    res->var = calloc(len, sizeof *res->var);
    res->ci = calloc(len, sizeof *res->ci);
    double *sums = calloc(2 * len * nblocks, sizeof *sums);   /* every block's mean, m2 */
    double *counts = calloc(nblocks, sizeof *counts);
    if (!res->t || !res->mean || !res->var || !res->ci || !sums || !counts) {
        free(sums);
        free(counts);
        return sim_error_set(err, SIM_ENOMEM, "particles.ensembles",
                             "cannot allocate statistics for %zu ensembles x %zu outputs", N,
                             outputs);
    }
    for (size_t m = 0; m < outputs; m++)
        res->t[m] = sim_scene_output_time(scene, m);
    res->nsteady = nsteady;
    res->steady_mean = res->mean + rows_len;
    res->steady_var = res->var + rows_len;
    res->steady_ci = res->ci + rows_len;

    const double cpu0 = now(CLOCK_PROCESS_CPUTIME_ID), wall0 = now(CLOCK_MONOTONIC);
    sim_status status = SIM_OK;
    int failed = 0;   /* set once a thread cannot work; read atomically in the loop */
    sim_counts total_counts = {0};
    size_t done = 0;
    int threads = 1;

#pragma omp parallel
    {
        sim_workspace *ws = NULL;
        sim_error local_err;
        sim_status local = sim_workspace_create(engine, &ws, &local_err);
        double *obs = malloc(len * sizeof *obs);
        if (local == SIM_OK && obs == NULL)
            local = sim_error_set(&local_err, SIM_ENOMEM, "", "out of memory");
        if (local != SIM_OK) {
#pragma omp critical(gdsmc_ensemble_error)
            if (status == SIM_OK) {
                status = local;
                if (err)
                    *err = local_err;
            }
#pragma omp atomic write
            failed = 1;
        }
#pragma omp barrier
        sim_counts my_counts = {0};
#pragma omp single
        threads = omp_get_num_threads();

#pragma omp for schedule(dynamic, 1)
        for (size_t b = 0; b < nblocks; b++) {
            int stop;
#pragma omp atomic read
            stop = failed;
            if (stop)
                continue;
            block_stats st = {0.0, sums + 2 * len * b, sums + 2 * len * b + len};
            for (size_t j = b * bsize; j < (b + 1) * bsize && j < N; j++) {
                sim_engine_run(engine, ws, j, obs, &my_counts);
                welford_add(&st, obs, len);
            }
            counts[b] = st.count;
#pragma omp critical(gdsmc_ensemble_progress)
            {
                done += (size_t)st.count;
                if (progress)
                    progress(done, N, ctx);
            }
        }
#pragma omp critical(gdsmc_ensemble_counts)
        {
            sim_counts_add(&total_counts, &my_counts);
        }
        free(obs);
        sim_workspace_free(ws);
    }

    if (status == SIM_OK) {
        block_stats all = {0.0, res->mean, res->var};   /* var holds m2 until scaled */
        for (size_t b = 0; b < nblocks; b++) {
            block_stats st = {counts[b], sums + 2 * len * b, sums + 2 * len * b + len};
            merge(&all, &st, len);
        }
        for (size_t i = 0; i < len; i++) {
            res->var[i] /= (double)N;
            res->ci[i] = SIM_LAMBDA_P * sqrt(res->var[i] / (double)N);
        }
        res->counts = total_counts;
        res->threads = threads;
    }
    res->cpu_seconds = now(CLOCK_PROCESS_CPUTIME_ID) - cpu0;
    res->wall_seconds = now(CLOCK_MONOTONIC) - wall0;
    free(sums);
    free(counts);
    return status;
}
