#include "bench.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "collide.h"
#include "engine.h"
#include "particles.h"
#include "rng.h"
#include "scene_ini.h"

static double thread_cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double peak_rss_mb(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return (double)ru.ru_maxrss / 1024.0;   /* ru_maxrss is in KiB on Linux */
}

/* Elastic hard spheres in one cell from two counter-streaming Maxwellians
 * (drifts -+2 along x, T = 1), C = 1/(4 pi): about 1.7 n accepted collisions
 * per unit time; t_end is set for `collisions` of them. */
static sim_scene hs_relax_scene(size_t n, double collisions)
{
    sim_scene s;
    sim_scene_defaults(&s);
    snprintf(s.title, sizeof s.title, "hs-relax: elastic hard spheres, two beams");
    s.t_end = collisions / (1.7 * (double)n);
    s.outputs = 2;
    s.seed = 1994;
    s.particles.n = n;
    s.particles.initial = SIM_INITIAL_TWO_MAXWELLIANS;
    s.particles.fraction = 0.5;
    s.particles.first = (sim_maxwellian){1.0, {-2.0, 0.0, 0.0}, 1.0};
    s.particles.second = (sim_maxwellian){1.0, {2.0, 0.0, 0.0}, 1.0};
    s.collisions.present = 1;
    s.collisions.kernel = SIM_KERNEL_HARD_SPHERES;
    s.collisions.exponent = 1.0;
    s.collisions.constant = 1.0 / (4.0 * M_PI);
    s.collisions.restitution = 1.0;
    return s;
}

typedef struct bench_row {
    double events, accepted, cpu, bytes_per_particle;
} bench_row;

/* Run `runs` ensembles of the scene one after another on this thread. */
static sim_status run_engine(const sim_scene *s, size_t runs, bench_row *row, sim_error *err)
{
    sim_engine *e = NULL;
    sim_workspace *ws = NULL;
    double *obs = malloc(s->outputs * SIM_OBS_COUNT * sizeof *obs);
    sim_status status = obs ? sim_engine_create(s, &e, err)
                            : sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    if (status == SIM_OK)
        status = sim_workspace_create(e, &ws, err);
    if (status == SIM_OK) {
        sim_counts counts = {0};
        double start = thread_cpu_seconds();
        for (size_t k = 0; k < runs; k++)
            sim_engine_run(e, ws, k, obs, &counts);
        row->cpu = thread_cpu_seconds() - start;
        row->events = (double)counts.candidates;
        row->accepted = (double)(counts.collisions + counts.background);
        row->bytes_per_particle = sizeof(double[3]) + (s->heating.present ? sizeof(double) : 0);
    }
    sim_workspace_free(ws);
    sim_engine_free(e);
    free(obs);
    return status;
}

/* The floor: `candidates` draws of the bare hard-sphere kernel on the same
 * initial state, U_max = 2 max |v_i - mean| fixed. */
static sim_status run_floor(const sim_scene *s, double candidates, bench_row *row,
                            sim_error *err)
{
    sim_particles p;
    sim_status status = sim_particles_alloc(&p, s->particles.n, 0, err);
    gsl_rng *rng = sim_rng_alloc();
    if (status != SIM_OK || rng == NULL) {
        sim_particles_free(&p);
        if (rng)
            gsl_rng_free(rng);
        return status != SIM_OK ? status : sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    }
    sim_rng_set_stream(rng, s->seed, 0);
    sim_particles_sample(&p, s, rng);
    const size_t n = p.n;
    double r = 0.0;
    for (size_t i = 0; i < n; i++)
        r = fmax(r, sim_norm3(p.v[i]));   /* the beams' mean is 0 */
    const double umax = 2.0 * r;
    const uint64_t draws = (uint64_t)candidates;
    uint64_t accepted = 0;
    double start = thread_cpu_seconds();
    for (uint64_t k = 0; k < draws; k++) {
        size_t i = (size_t)sim_rng_index(rng, n);
        size_t j = (size_t)sim_rng_index(rng, n - 1);
        j += (j >= i);
        double *vi = p.v[i], *vj = p.v[j];
        double g[3] = {vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]};
        double gnorm = sim_norm3(g);
        if (sim_rng_uniform(rng) * umax >= gnorm)
            continue;
        double e[3];
        sim_rng_unit_sphere(rng, e);
        sim_collide_inelastic(vi, vj, 1.0, gnorm, e);
        accepted++;
    }
    row->cpu = thread_cpu_seconds() - start;
    row->events = (double)accepted;
    row->accepted = (double)accepted;
    row->bytes_per_particle = sizeof(double[3]);
    sim_particles_free(&p);
    gsl_rng_free(rng);
    return SIM_OK;
}

static void add_row(vfy_table *t, const char *name, size_t n, const bench_row *row,
                    double floor_rate, double acceptance)
{
    double rate = row->events / row->cpu;
    vfy_table_cell(t, "%s", name);
    vfy_table_cell(t, "%zu", n);
    vfy_table_cell(t, "%.0f", row->events);
    vfy_table_cell(t, "%.3f", row->cpu);
    vfy_table_cell(t, "%.4g", rate);
    vfy_table_cell(t, "%.1f", 1e9 / rate);
    vfy_table_number(t, floor_rate > 0, "%.3f", rate / floor_rate);
    vfy_table_cell(t, "%.3f", acceptance);
    vfy_table_cell(t, "%.0f", row->bytes_per_particle);
    vfy_table_cell(t, "%.1f", peak_rss_mb());
}

static void say(const vfy_bench_options *o, const char *name, size_t n, const bench_row *row)
{
    if (o->progress) {
        fprintf(o->progress, "   %-8s n = %-9zu %.4g events/s (%.1f s CPU)\n", name, n,
                row->events / row->cpu, row->cpu);
        fflush(o->progress);
    }
}

/* A paper scene from the scene directory, n particles, run for about
 * o->seconds: the number of ensembles is found from a first short run. */
static sim_status paper_rows(const vfy_bench_options *o, const char *name, size_t n,
                             double floor_rate, vfy_table *t, char *msg, size_t msglen)
{
    char path[1024];
    sim_scene s;
    snprintf(path, sizeof path, "%s/%s.ini", o->scene_dir, name);
    sim_status status = vfy_scene_load(path, NULL, 0, &s, msg, msglen);
    if (status != SIM_OK)
        return status;
    s.particles.n = n;
    sim_error err = {{0}, {0}};
    bench_row row = {0};
    status = run_engine(&s, 1, &row, &err);
    if (status == SIM_OK) {
        double runs = ceil(o->seconds / fmax(row.cpu, 1e-6));
        status = run_engine(&s, (size_t)fmin(fmax(runs, 1.0), 1e6), &row, &err);
    }
    if (status != SIM_OK) {
        vfy_scene_format_error(&s, &err, msg, msglen);
        return status;
    }
    say(o, name, n, &row);
    add_row(t, name, n, &row, floor_rate, row.accepted / row.events);
    return SIM_OK;
}

sim_status vfy_bench_run(const vfy_bench_options *o, vfy_table *t, char *msg, size_t msglen)
{
    static const char *const cols[] = {VFY_BENCH_COLUMNS};
    vfy_table_init(t, sizeof cols / sizeof *cols, cols);
    sim_error err = {{0}, {0}};
    double floor_rate_1024 = 0.0;
    for (size_t n = 1000; n <= o->max_n; n *= 10) {
        /* hs-relax: enough collisions for o->seconds at ~3e6/s, at least 2 per particle */
        sim_scene s = hs_relax_scene(n, fmax(2.0 * (double)n, 3e6 * o->seconds));
        bench_row engine_row = {0}, floor_row = {0};
        sim_status status = run_engine(&s, 1, &engine_row, &err);
        if (status == SIM_OK)
            status = run_floor(&s, engine_row.events, &floor_row, &err);
        if (status != SIM_OK) {
            snprintf(msg, msglen, "hs-relax n = %zu: %s", n, err.msg);
            return status;
        }
        double floor_rate = floor_row.events / floor_row.cpu;
        if (n == 1000)
            floor_rate_1024 = floor_rate;
        const double candidates = engine_row.events;
        say(o, "floor", n, &floor_row);
        add_row(t, "floor", n, &floor_row, floor_rate, floor_row.accepted / candidates);
        engine_row.events = engine_row.accepted;   /* the rate of accepted collisions */
        say(o, "hs-relax", n, &engine_row);
        add_row(t, "hs-relax", n, &engine_row, floor_rate, engine_row.accepted / candidates);
    }
    /* The paper scenes at n = 1024; their floor_ratio is against the floor
     * at n = 1000 (same cache regime). */
    sim_status status = paper_rows(o, "grw-ex3", 1024, floor_rate_1024, t, msg, msglen);
    if (status == SIM_OK)
        status = paper_rows(o, "brs-ex4", 1024, floor_rate_1024, t, msg, msglen);
    return status;
}
