#include "ensemble.h"

#include <math.h>
#include <omp.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#ifdef GDSMC_MPI
#include <mpi.h>
#endif

/* Running mean and sum of squared deviations of one block of ensembles. */
typedef struct block_stats {
    double count;
    double *mean;  /* [outputs * observables + nsteady] */
    double *m2;
} block_stats;

/* Set from a signal handler: only a volatile sig_atomic_t may be (C11 7.14.1.1). */
static volatile sig_atomic_t stop_requested;

void sim_ensemble_request_stop(void) { stop_requested = 1; }
void sim_ensemble_clear_stop(void) { stop_requested = 0; }
int sim_ensemble_stop_requested(void) { return stop_requested != 0; }

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

/* ---- Where the blocks run: one process, or the ranks of MPI (GDSMC_MPI) ----
 *
 * Every number must be the same whatever the numbers of processes and threads
 * (docs/theory.md §8.6, reproducibility): ensemble j always uses random stream (seed, j)
 * and belongs to block j / block_size(N), and every process merges the
 * blocks' sums in block order.  With MPI, rank r of `size` computes the
 * blocks b = r, r + size, r + 2 size, ..., each with its OpenMP threads; then
 * every block's Welford sums are copied bit for bit from the rank that
 * computed them to all the others (MPI_Bcast: no arithmetic on the way), so
 * every rank merges the same bits in the same order as one process does.
 *
 * sim_ensemble_run is then collective over MPI_COMM_WORLD: every rank calls it
 * with the same scene, from the thread that initialised MPI (verify/cli/main.c
 * asks for MPI_THREAD_FUNNELED), never inside an OpenMP parallel region.
 * Without GDSMC_MPI, and before MPI_Init or after MPI_Finalize (the unit
 * tests), the process is rank 0 of 1 and the functions below do nothing.
 * MPI's own errors are fatal (MPI_ERRORS_ARE_FATAL, its default): the MPI
 * runtime, not this code, ends the job. */
typedef struct ranks {
    int rank, size;
} ranks;

static ranks ranks_get(void)
{
    ranks rk = {0, 1};
#ifdef GDSMC_MPI
    int started = 0, finished = 0;
    MPI_Initialized(&started);
    MPI_Finalized(&finished);
    if (started && !finished) {
        MPI_Comm_rank(MPI_COMM_WORLD, &rk.rank);
        MPI_Comm_size(MPI_COMM_WORLD, &rk.size);
    }
#endif
    return rk;
}

/* This rank's blocks are ranks_block(rk, i) for i < ranks_nblocks(rk, nblocks). */
static size_t ranks_nblocks(ranks rk, size_t nblocks)
{
    const size_t r = (size_t)rk.rank, size = (size_t)rk.size;
    return nblocks > r ? (nblocks - r + size - 1) / size : 0;
}

static size_t ranks_block(ranks rk, size_t i) { return (size_t)rk.rank + i * (size_t)rk.size; }

/* The ensembles in this rank's blocks. */
static size_t ranks_ensembles(ranks rk, size_t N, size_t bsize, size_t nblocks)
{
    size_t mine = 0;
    for (size_t i = 0; i < ranks_nblocks(rk, nblocks); i++) {
        const size_t first = ranks_block(rk, i) * bsize;
        mine += (N - first < bsize ? N - first : bsize);
    }
    return mine;
}

#ifdef GDSMC_MPI
/* MPI counts are int: long arrays go in pieces. */
#define RANKS_CHUNK ((size_t)1 << 27)

static void bcast_doubles(double *x, size_t len, int root)
{
    for (size_t at = 0; at < len; at += RANKS_CHUNK) {
        const size_t k = len - at < RANKS_CHUNK ? len - at : RANKS_CHUNK;
        MPI_Bcast(x + at, (int)k, MPI_DOUBLE, root, MPI_COMM_WORLD);
    }
}
#endif

/* Make every rank go on with the same verdict: the status and message (err,
 * which may be NULL) of the lowest-numbered rank that failed, else SIM_OK;
 * *stopped (a stop request cut a block here) becomes 1 on every rank if it is
 * 1 on any, and *done (ensembles finished here) the sum over the ranks.
 * sim_ensemble_run calls it after its set-up (so that no rank simulates a run
 * another has refused) and, when that succeeded, after its ensembles: every
 * rank makes the same calls in the same order on every path. */
static sim_status ranks_agree(ranks rk, sim_status status, int *stopped, size_t *done,
                              sim_error *err)
{
#ifdef GDSMC_MPI
    if (rk.size > 1) {
        int first[2] = {status != SIM_OK ? rk.rank : rk.size, -*stopped};   /* both MPI_MIN */
        unsigned long long total = *done;
        MPI_Allreduce(MPI_IN_PLACE, first, 2, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
        MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
        *stopped = -first[1];
        *done = (size_t)total;
        if (first[0] < rk.size) {
            struct {
                int status;
                sim_error err;
            } verdict;
            memset(&verdict, 0, sizeof verdict);
            verdict.status = (int)status;
            if (err && rk.rank == first[0])
                verdict.err = *err;
            MPI_Bcast(&verdict, (int)sizeof verdict, MPI_BYTE, first[0], MPI_COMM_WORLD);
            status = (sim_status)verdict.status;
            if (err)
                *err = verdict.err;
        }
    }
#else
    (void)rk, (void)stopped, (void)done, (void)err;
#endif
    return status;
}

/* After a run that succeeded on every rank: each block's sums (2 len doubles
 * at sums + 2 len b) and count copied from the rank that computed it to all,
 * and the event counts and threads summed over the ranks. */
static void ranks_combine(ranks rk, double *sums, double *counts, size_t len, size_t nblocks,
                          sim_counts *total, int *threads)
{
#ifdef GDSMC_MPI
    if (rk.size > 1) {
        for (size_t b = 0; b < nblocks; b++) {
            const int owner = (int)(b % (size_t)rk.size);
            bcast_doubles(sums + 2 * len * b, 2 * len, owner);
            bcast_doubles(counts + b, 1, owner);
        }
        _Static_assert(sizeof(sim_counts) == 5 * sizeof(uint64_t),
                       "ranks_combine sums every field of sim_counts");
        unsigned long long c[5] = {total->candidates, total->collisions, total->background,
                                   total->violations, total->normals};
        MPI_Allreduce(MPI_IN_PLACE, c, 5, MPI_UNSIGNED_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
        total->candidates = c[0];
        total->collisions = c[1];
        total->background = c[2];
        total->violations = c[3];
        total->normals = c[4];
        MPI_Allreduce(MPI_IN_PLACE, threads, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    }
#else
    (void)rk, (void)sums, (void)counts, (void)len, (void)nblocks, (void)total, (void)threads;
#endif
}

/* The memory check's need and threads summed over the ranks that share this
 * machine's memory (MPI_COMM_TYPE_SHARED): all of them are held at once. */
static void ranks_machine_sum(ranks rk, double *need, int *threads)
{
#ifdef GDSMC_MPI
    if (rk.size > 1) {
        MPI_Comm machine;
        MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rk.rank, MPI_INFO_NULL,
                            &machine);
        MPI_Allreduce(MPI_IN_PLACE, need, 1, MPI_DOUBLE, MPI_SUM, machine);
        MPI_Allreduce(MPI_IN_PLACE, threads, 1, MPI_INT, MPI_SUM, machine);
        MPI_Comm_free(&machine);
    }
#else
    (void)rk, (void)need, (void)threads;
#endif
}

/* CPU seconds summed over the ranks, wall seconds their maximum. */
static void ranks_seconds(ranks rk, double *cpu, double *wall)
{
#ifdef GDSMC_MPI
    if (rk.size > 1) {
        MPI_Allreduce(MPI_IN_PLACE, cpu, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
        MPI_Allreduce(MPI_IN_PLACE, wall, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    }
#else
    (void)rk, (void)cpu, (void)wall;
#endif
}

double sim_ensemble_memory_estimate(const sim_engine *engine, int threads)
{
    const sim_scene *scene = sim_engine_scene(engine);
    const double N = (double)scene->particles.ensembles;
    const double len = (double)(scene->outputs * sim_engine_observables(engine)
                               + sim_engine_steady_count(engine));
    const double bsize = (double)block_size(scene->particles.ensembles);
    /* mean, var, ci, the blocks' mean and m2, and one observation per thread */
    const double stats = 8.0 * len * (3.0 + 2.0 * ceil(N / bsize) + threads);
    return (double)threads * (double)sim_engine_workspace_bytes(engine) + stats;
}

/* The machine's physical memory in bytes, or +inf when unknown. */
static double physical_memory(void)
{
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? (double)pages * (double)page : INFINITY;
}

void sim_ensemble_result_free(sim_ensemble_result *res)
{
    free(res->t);
    free(res->mean);
    free(res->var);
    free(res->ci);
    memset(res, 0, sizeof *res);
}

/* This process's blocks of ensembles, on every thread: each block's running
 * mean and m2 into job->sums, its count into job->counts.  A thread that
 * cannot work, or a stop request, sets *failed; the first error is kept. */
typedef struct block_job {
    const sim_engine *engine;
    ranks rk;
    size_t len, N, bsize, my_nblocks, my_ensembles;
    double *sums, *counts;
    sim_progress_fn progress;
    void *ctx;
} block_job;

static void simulate_blocks(const block_job *job, sim_status *status_out, sim_error *err,
                            int *failed_out, size_t *done_out, sim_counts *total_counts,
                            int *threads_out)
{
    const sim_engine *engine = job->engine;
    const size_t len = job->len, N = job->N, bsize = job->bsize;
    const size_t my_nblocks = job->my_nblocks, my_ensembles = job->my_ensembles;
    double *sums = job->sums, *counts = job->counts;
    const sim_progress_fn progress = job->progress;
    void *ctx = job->ctx;
    const ranks rk = job->rk;
    sim_status status = *status_out;
    int failed = 0, threads = 1;
    size_t done = *done_out;

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
        for (size_t i = 0; i < my_nblocks; i++) {
            const size_t b = ranks_block(rk, i);
            int stop;
#pragma omp atomic read
            stop = failed;
            if (stop)
                continue;
            block_stats st = {0.0, sums + 2 * len * b, sums + 2 * len * b + len};
            int cut = 0;
            for (size_t j = b * bsize; j < (b + 1) * bsize && j < N && !cut; j++) {
                if ((cut = stop_requested) != 0)
                    break;
                sim_engine_run(engine, ws, j, obs, &my_counts);
                welford_add(&st, obs, len);
            }
            if (cut) {   /* the block is incomplete: the run's statistics are void */
#pragma omp atomic write
                failed = 1;
                continue;
            }
            counts[b] = st.count;
#pragma omp critical(gdsmc_ensemble_progress)
            {
                done += (size_t)st.count;
                if (progress)   /* this process's fraction, in ensembles of N */
                    progress(my_ensembles == N ? done
                                               : (size_t)((double)done * (double)N
                                                          / (double)my_ensembles),
                             N, ctx);
            }
        }
#pragma omp critical(gdsmc_ensemble_counts)
        {
            sim_counts_add(total_counts, &my_counts);
        }
        free(obs);
        sim_workspace_free(ws);
    }

    *status_out = status;
    *failed_out = failed;
    *done_out = done;
    *threads_out = threads;
}

sim_status sim_ensemble_run(const sim_engine *engine, sim_progress_fn progress, void *ctx,
                            sim_ensemble_result *res, sim_error *err)
{
    const sim_scene *scene = sim_engine_scene(engine);
    const size_t outputs = scene->outputs, N = scene->particles.ensembles;
    /* the rows, then the steady-state time averages of each run */
    const size_t observables = sim_engine_observables(engine);
    const size_t rows_len = outputs * observables, nsteady = sim_engine_steady_count(engine);
    const size_t len = rows_len + nsteady;
    const size_t bsize = block_size(N), nblocks = (N + bsize - 1) / bsize;
    /* this process's share of the blocks (all of them without MPI) */
    const ranks rk = ranks_get();
    const size_t my_nblocks = ranks_nblocks(rk, nblocks),
                 my_ensembles = ranks_ensembles(rk, N, bsize, nblocks);
    int stopped = 0;   /* a stop request cut a block short */
    size_t done = 0;   /* ensembles finished */

    memset(res, 0, sizeof *res);
    int max_threads = omp_get_max_threads();
    double need = sim_ensemble_memory_estimate(engine, max_threads);
    ranks_machine_sum(rk, &need, &max_threads);   /* with MPI, all ranks on this machine */
    const double have = physical_memory();
    if (need > have) {
        sim_status refused = sim_error_set(
            err, SIM_ENOMEM, "particles.n",
            "n = %zu particles per ensemble on %d threads, N = %zu ensembles and %zu outputs "
            "need about %.3g GB at once, more than the %.3g GB of memory this machine has",
            scene->particles.n, max_threads, N, outputs, need / 1e9, have / 1e9);
        return ranks_agree(rk, refused, &stopped, &done, err);
    }
    res->outputs = outputs;
    res->observables = observables;
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
        sim_status refused = sim_error_set(err, SIM_ENOMEM, "particles.ensembles",
                                           "cannot allocate statistics for %zu ensembles x "
                                           "%zu outputs", N, outputs);
        return ranks_agree(rk, refused, &stopped, &done, err);
    }
    sim_status status = ranks_agree(rk, SIM_OK, &stopped, &done, err);   /* refused elsewhere? */
    if (status != SIM_OK) {
        free(sums);
        free(counts);
        return status;
    }
    for (size_t m = 0; m < outputs; m++)
        res->t[m] = sim_scene_output_time(scene, m);
    res->nsteady = nsteady;
    res->steady_mean = res->mean + rows_len;
    res->steady_var = res->var + rows_len;
    res->steady_ci = res->ci + rows_len;

    const double cpu0 = now(CLOCK_PROCESS_CPUTIME_ID), wall0 = now(CLOCK_MONOTONIC);
    int failed = 0;   /* set once a thread cannot work; read atomically in the loop */
    sim_counts total_counts = {0};
    int threads = 1;

    const block_job job = {engine, rk, len, N, bsize, my_nblocks, my_ensembles, sums, counts,
                           progress, ctx};
    simulate_blocks(&job, &status, err, &failed, &done, &total_counts, &threads);

    stopped = failed && status == SIM_OK;
    status = ranks_agree(rk, status, &stopped, &done, err);   /* one verdict on all ranks */
    if (status == SIM_OK && stopped)
        status = sim_error_set(err, SIM_ECANCELED, "", "stopped on request after %zu of %zu "
                               "ensembles", done, N);
    if (status == SIM_OK) {
        ranks_combine(rk, sums, counts, len, nblocks, &total_counts, &threads);
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
    if (status == SIM_OK)
        ranks_seconds(rk, &res->cpu_seconds, &res->wall_seconds);
    free(sums);
    free(counts);
    return status;
}

void sim_counts_add(sim_counts *to, const sim_counts *from)
{
    to->candidates += from->candidates;
    to->collisions += from->collisions;
    to->background += from->background;
    to->violations += from->violations;
    to->normals += from->normals;
}
