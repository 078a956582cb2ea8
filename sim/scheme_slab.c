/* The Lees-Edwards slab (slab.h; paper E §IV A, docs/theory.md §6.3): the
 * time-step scheme with positions, and the engine's scheme object for it. */
#include "slab.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "collide.h"
#include "observe.h"
#include "rng.h"
#include "scheme.h"

typedef void slab_stage(const sim_slab_params *p, sim_slab *s, sim_run *run, double h);

#define SLAB_STAGES 4

struct sim_slab_params {
    const sim_scene *scene;   /* the engine's copy (outlives the params) */
    double rate;          /* a */
    double length;        /* L */
    size_t layers;        /* M */
    double width;         /* dy = L/M */
    const sim_event *events;  /* the engine's (outlive the params), each with a layer stage */
    size_t nevents;
    const sim_flow *flows;    /* ... each with a layer step (the EHS drag) */
    size_t nflows;
    double mass;
    slab_stage *stages[SLAB_STAGES];
};

struct sim_slab {
    double (*v2)[3];   /* the counting sort's second buffers, swapped with the system's */
    double *y2;
    uint32_t *layer;   /* each particle's layer after streaming */
    size_t *start;     /* [M + 1]: layer I is [start[I], start[I + 1]) of the arrays */
    double (*u)[3];    /* [M] the layer velocities u_I */
    double *theta;     /* [M] T_I/m */
    double *radius;    /* [M] R_I = max |v_i - u_I| over the layer */
    double *pxy;       /* [M] Σ C_x C_y over the layer (observation) */
    sim_particles peculiar;   /* C_i = v_i - u_I, for the observers */
};

/* The layer of position y in [-L/2, L/2): floor((y + L/2)/dy), kept within
 * the slab against round-off. */
static inline uint32_t layer_of(const sim_slab_params *p, double y)
{
    const double x = (y + 0.5 * p->length) / p->width;
    const size_t I = x > 0.0 ? (size_t)x : 0;
    return (uint32_t)(I < p->layers ? I : p->layers - 1);
}

/* --------------------------------------------------------------- stages */

/* Streaming with the Lees-Edwards wrap (E Eqs. 4.10-4.11) by the velocity
 * vy: k = floor((y + L/2)/L) crossings upwards (negative: downwards),
 * y <- y - kL, v_x <- v_x - k aL. */
static inline void stream_one(const sim_slab_params *p, sim_slab *s, sim_run *run, size_t i,
                              double vy, double h)
{
    const double L = p->length;
    double y = run->p.y[i] + vy * h;
    const double k = floor((y + 0.5 * L) / L);
    y -= k * L;
    run->p.v[i][0] -= k * p->rate * L;
    run->p.y[i] = y;
    s->layer[i] = layer_of(p, y);
}

static void stage_stream(const sim_slab_params *p, sim_slab *s, sim_run *run, double h)
{
    for (size_t i = 0; i < run->p.n; i++)
        stream_one(p, s, run, i, run->p.v[i][1], h);
}

/* With flows (the EHS drag, E Eq. 4.12): each flow's layer step with the
 * fields at the start of the step, then the streaming by the velocity before
 * them (E Eq. 4.10), kept in the sort's second buffer of positions (free
 * until the sort). */
static void stage_flows_stream(const sim_slab_params *p, sim_slab *s, sim_run *run, double h)
{
    const double N = (double)run->p.n, M = (double)p->layers;
    for (size_t i = 0; i < run->p.n; i++)
        s->y2[i] = run->p.v[i][1];
    for (size_t I = 0; I < p->layers; I++) {
        const size_t lo = s->start[I], hi = s->start[I + 1];
        const double density = (double)(hi - lo) * M / N;   /* n_I/n */
        for (size_t k = 0; k < p->nflows; k++)
            p->flows[k].type->step_layer(&p->flows[k], run->p.v + lo, hi - lo, s->u[I],
                                         s->theta[I], density, h);
    }
    for (size_t i = 0; i < run->p.n; i++)
        stream_one(p, s, run, i, s->y2[i], h);
}

/* A counting sort by layer into the second buffers, which become the system's. */
static void stage_sort(const sim_slab_params *p, sim_slab *s, sim_run *run, double h)
{
    (void)h;
    const size_t n = run->p.n, M = p->layers;
    size_t *start = s->start;
    memset(start, 0, (M + 1) * sizeof *start);
    for (size_t i = 0; i < n; i++)
        start[s->layer[i] + 1]++;
    for (size_t I = 0; I < M; I++)
        start[I + 1] += start[I];
    /* scatter, using start[I] as the next free place of layer I */
    for (size_t i = 0; i < n; i++) {
        const size_t to = start[s->layer[i]]++;
        memcpy(s->v2[to], run->p.v[i], sizeof s->v2[to]);
        s->y2[to] = run->p.y[i];
    }
    for (size_t I = M; I > 0; I--)   /* start[I] now ends layer I: shift back */
        start[I] = start[I - 1];
    start[0] = 0;
    double(*v)[3] = run->p.v, *y = run->p.y;
    run->p.v = s->v2;
    run->p.y = s->y2;
    s->v2 = v;
    s->y2 = y;
}

/* u_I, T_I/m and R_I of every layer of the sorted system. */
static void stage_fields(const sim_slab_params *p, sim_slab *s, sim_run *run, double h)
{
    (void)h;
    for (size_t I = 0; I < p->layers; I++) {
        const size_t lo = s->start[I], hi = s->start[I + 1];
        double u[3] = {0, 0, 0}, c2 = 0.0, r2 = 0.0;
        for (size_t i = lo; i < hi; i++)
            for (int c = 0; c < 3; c++)
                u[c] += run->p.v[i][c];
        for (int c = 0; c < 3 && hi > lo; c++)
            u[c] /= (double)(hi - lo);
        for (size_t i = lo; i < hi; i++) {
            const double *v = run->p.v[i];
            const double d[3] = {v[0] - u[0], v[1] - u[1], v[2] - u[2]};
            const double x = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            c2 += x;
            r2 = x > r2 ? x : r2;
        }
        memcpy(s->u[I], u, sizeof u);
        s->theta[I] = hi > lo ? c2 / (3.0 * (double)(hi - lo)) : 0.0;
        s->radius[I] = sqrt(r2);
    }
}

/* Each layer's candidates for h (slab.h, stage 4): every event process's
 * layer stage (effect.h, sim_event_stages.layer), which grows R_I. */
static void stage_collide(const sim_slab_params *p, sim_slab *s, sim_run *run, double h)
{
    for (size_t I = 0; I < p->layers; I++) {
        const size_t lo = s->start[I], count = s->start[I + 1] - lo;
        if (count < 2 || !(s->radius[I] > 0.0))
            continue;
        for (size_t k = 0; k < p->nevents; k++)
            p->events[k].type->stages->layer(&p->events[k], run, lo, count, s->u[I],
                                             &s->radius[I], h);
    }
}

/* ---------------------------------------------------------------- build */

sim_status sim_slab_accept(const sim_scene *scene, sim_error *err)
{
    if (scene->scheme != SIM_SCHEME_TIMESTEP)
        return sim_error_set(err, SIM_EUNSUPPORTED, "shear.boundary",
                             "lees-edwards needs scheme = timestep (the jump scheme keeps no "
                             "positions)");
    if (!scene->collisions.present || scene->collisions.exponent != 1.0)
        return sim_error_set(err, SIM_EUNSUPPORTED, "shear.boundary",
                             "lees-edwards simulates hard spheres ([collisions] kernel = "
                             "hard-spheres)");
    if (scene->heating.present || scene->background.present || scene->heat_flux.present)
        return sim_error_set(err, SIM_EUNSUPPORTED, "shear.boundary",
                             "lees-edwards takes collisions and their drag only (no [heating], "
                             "[background] or [heat-flux])");
    if (scene->splitting == SIM_SPLIT_STRANG)   /* it was accepted and not applied */
        return sim_error_set(err, SIM_EUNSUPPORTED, "scene.splitting",
                             "lees-edwards steps in one order, streaming then collisions "
                             "(docs/theory.md §6.3): strang is not implemented");
    return SIM_OK;
}

sim_status sim_slab_params_create(const sim_scene *scene, const sim_event *events,
                                  size_t nevents, const sim_flow *flows, size_t nflows,
                                  sim_slab_params **params, sim_error *err)
{
    *params = NULL;
    sim_status status = sim_slab_accept(scene, err);
    if (status != SIM_OK)
        return status;
    for (size_t k = 0; k < nevents; k++)
        if (events[k].type->stages == NULL || events[k].type->stages->layer == NULL)
            return sim_error_set(err, SIM_EUNSUPPORTED, "shear.boundary",
                                 "lees-edwards has no per-layer form of the %s",
                                 events[k].type->name);
    for (size_t k = 0; k < nflows; k++)
        if (flows[k].type->step_layer == NULL)
            return sim_error_set(err, SIM_EUNSUPPORTED, "shear.boundary",
                                 "lees-edwards has no per-layer form of the %s",
                                 flows[k].type->name);
    sim_slab_params *p = calloc(1, sizeof *p);
    if (p == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    const double M = (double)scene->shear.layers;
    p->scene = scene;
    p->rate = scene->shear.rate;
    p->length = scene->shear.length;
    p->layers = scene->shear.layers;
    p->width = p->length / M;
    p->events = events;
    p->nevents = nevents;
    p->flows = flows;
    p->nflows = nflows;
    p->mass = sim_scene_grain_mass(scene);
    p->stages[0] = nflows > 0 ? stage_flows_stream : stage_stream;
    p->stages[1] = stage_sort;
    p->stages[2] = stage_fields;
    p->stages[3] = stage_collide;
    *params = p;
    return SIM_OK;
}

void sim_slab_params_free(sim_slab_params *params)
{
    free(params);
}

size_t sim_slab_bytes(const sim_slab_params *params, size_t n)
{
    /* y, the second v and y, the layer index, the peculiar velocities */
    return n * (sizeof(double) + sizeof(double[3]) + sizeof(double) + sizeof(uint32_t)
                + sizeof(double[3]))
           + (params->layers + 1) * sizeof(size_t) + params->layers * 6 * sizeof(double)   /* u, theta, radius, pxy */;
}

sim_status sim_slab_create(const sim_slab_params *params, sim_particles *p, sim_slab **slab,
                           sim_error *err)
{
    *slab = NULL;
    sim_status status = sim_particles_alloc_positions(p, err);
    if (status != SIM_OK)
        return status;
    sim_slab *s = calloc(1, sizeof *s);
    const size_t n = p->n, M = params->layers;
    if (s != NULL) {
        s->v2 = malloc(n * sizeof *s->v2);
        s->y2 = malloc(n * sizeof *s->y2);
        s->layer = malloc(n * sizeof *s->layer);
        s->start = calloc(M + 1, sizeof *s->start);
        s->u = calloc(M, sizeof *s->u);
        s->theta = calloc(M, sizeof *s->theta);
        s->radius = calloc(M, sizeof *s->radius);
        s->pxy = calloc(M, sizeof *s->pxy);
    }
    if (s == NULL || s->v2 == NULL || s->y2 == NULL || s->layer == NULL || s->start == NULL
        || s->u == NULL || s->theta == NULL || s->radius == NULL
        || s->pxy == NULL || sim_particles_alloc(&s->peculiar, n, 0, err) != SIM_OK) {
        sim_slab_free(s);
        return sim_error_set(err, SIM_ENOMEM, "particles.n",
                             "cannot allocate the slab of %zu particles (%zu bytes)", n,
                             sim_slab_bytes(params, n));
    }
    *slab = s;
    return SIM_OK;
}

void sim_slab_free(sim_slab *slab)
{
    if (slab == NULL)
        return;
    free(slab->v2);
    free(slab->y2);
    free(slab->layer);
    free(slab->start);
    free(slab->u);
    free(slab->theta);
    free(slab->radius);
    free(slab->pxy);
    sim_particles_free(&slab->peculiar);
    free(slab);
}

void sim_slab_start(const sim_slab_params *params, sim_slab *slab, sim_run *run)
{
    for (size_t i = 0; i < run->p.n; i++)
        slab->layer[i] = layer_of(params, run->p.y[i]);
    stage_sort(params, slab, run, 0.0);
    stage_fields(params, slab, run, 0.0);
}

void sim_slab_step(const sim_slab_params *params, sim_slab *slab, sim_run *run, double h)
{
    for (int k = 0; k < SLAB_STAGES; k++)
        params->stages[k](params, slab, run, h);
}

/* ---------------------------------------------------------- observation */

const sim_particles *sim_slab_peculiar(const sim_slab *slab)
{
    return &slab->peculiar;
}

/* The particle-weighted mean of u_x and T_I/m over layers [lo, hi), and their
 * share of the particles. */
static void layer_average(const sim_slab *s, size_t lo, size_t hi, double *ux, double *theta,
                          double *share, size_t n)
{
    double count = 0.0, sx = 0.0, st = 0.0;
    for (size_t I = lo; I < hi; I++) {
        const double NI = (double)(s->start[I + 1] - s->start[I]);
        count += NI;
        sx += NI * s->u[I][0];
        st += NI * s->theta[I];
    }
    *ux = count > 0.0 ? sx / count : 0.0;
    *theta = count > 0.0 ? st / count : 0.0;
    *share = count / (double)n;
}

void sim_slab_observe(const sim_slab_params *p, sim_slab *s, const sim_run *run, size_t m,
                      const double *prev, gsl_rng *rng, double *row)
{
    const sim_particles *ps = &run->p;
    const size_t n = ps->n, M = p->layers;
    /* the layers of the system as it is now (the collisions changed T_I, R_I) */
    stage_fields(p, s, (sim_run *)run, 0.0);
    double raw2 = 0.0, mean[3] = {0, 0, 0};
    for (size_t I = 0; I < M; I++) {
        double pxy = 0.0;
        for (size_t i = s->start[I]; i < s->start[I + 1]; i++) {
            const double *v = ps->v[i];
            double *c = s->peculiar.v[i];
            for (int k = 0; k < 3; k++) {
                c[k] = v[k] - s->u[I][k];
                mean[k] += v[k];
            }
            raw2 += v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
            pxy += c[0] * c[1];
        }
        s->pxy[I] = pxy;
    }
    /* T, P, q, a2, a3 against the layers' velocities (E Eqs. 4.6-4.9), then the
     * shear set from the same peculiar velocities (whose mean is 0) */
    sim_observe(&s->peculiar, p->mass, row);
    sim_observe_shear(p->scene, &s->peculiar, p->mass, run->counts.collisions, m, prev, rng,
                      row);
    for (int k = 0; k < 3; k++)
        row[SIM_OBS_UX + k] = mean[k] / (double)n;
    row[SIM_OBS_T_RAW] = p->mass * raw2 / (3.0 * (double)n);

    const double T = row[SIM_OBS_T], theta = T / p->mass, half_U = 0.5 * p->rate * p->length;
    double ux, th, share;
    /* the layers whose centres lie within 2 dy of y = 0: for even M the four central
     * ones, for odd M five */
    const size_t centre_lo = M / 2 >= 2 ? M / 2 - 2 : 0;
    const size_t centre_hi = M / 2 + 2 + M % 2 < M ? M / 2 + 2 + M % 2 : M;
    layer_average(s, centre_lo, centre_hi, &ux, &th, &share, n);
    row[SIM_OBS_UX_CENTRE] = ux / half_U;
    row[SIM_OBS_N_CENTRE] = share * (double)M / (double)(centre_hi - centre_lo);
    row[SIM_OBS_T_CENTRE] = th / theta;
    const size_t top_lo = M >= 3 ? M - 3 : 0;
    layer_average(s, top_lo, M, &ux, &th, &share, n);
    row[SIM_OBS_UX_TOP] = ux / half_U;
    row[SIM_OBS_N_TOP] = share * (double)M / (double)(M - top_lo);
    row[SIM_OBS_T_TOP] = th / theta;

    /* the profiles, and the slope of u_I,x against the layer centres y_I */
    double sy = 0.0, su = 0.0, syy = 0.0, syu = 0.0, filled = 0.0;
    double *profile = row + SIM_OBS_PROFILE;
    for (size_t I = 0; I < M; I++) {
        const double NI = (double)(s->start[I + 1] - s->start[I]);
        const double yI = ((double)I + 0.5) * p->width - 0.5 * p->length;
        profile[SIM_PROFILE_N * M + I] = NI * (double)M / (double)n;
        profile[SIM_PROFILE_UX * M + I] = s->u[I][0];
        profile[SIM_PROFILE_T * M + I] = s->theta[I] / theta;
        /* P_I/n = m (M/N) Σ C_x C_y (E Eq. 4.7 with A dy = N/(n M)) */
        profile[SIM_PROFILE_PXY * M + I] = p->mass * (double)M * s->pxy[I] / ((double)n * T);
        if (NI > 0.0) {
            filled += 1.0;
            sy += yI;
            su += s->u[I][0];
            syy += yI * yI;
            syu += yI * s->u[I][0];
        }
    }
    const double var = syy - sy * sy / filled;
    row[SIM_OBS_UX_SLOPE] = var > 0.0 ? (syu - sy * su / filled) / var / p->rate : NAN;
}

/* ------------------------------------------------------- the scheme object */

static void slab_free_params(void *params)
{
    sim_slab_params_free(params);
}

static sim_status slab_build(sim_engine *e, sim_error *err)
{
    sim_slab_params *params;
    sim_status status = sim_slab_params_create(&e->scene, e->events, e->nevents, e->flows,
                                               e->nflows, &params, err);
    if (status != SIM_OK)
        return status;
    e->scheme_params = params;
    e->free_params = slab_free_params;
    return sim_scene_step(&e->scene, &e->h, &e->steps, err);
}

static size_t slab_bytes(const sim_engine *e, size_t n)
{
    return sim_slab_bytes(e->scheme_params, n);
}

static sim_status slab_create(const sim_engine *e, sim_workspace *ws, sim_error *err)
{
    sim_slab *slab;
    sim_status status = sim_slab_create(e->scheme_params, &ws->run.p, &slab, err);
    ws->scheme_state = status == SIM_OK ? slab : NULL;
    return status;
}

static void slab_free(void *state)
{
    sim_slab_free(state);
}

static void slab_start(const sim_engine *e, sim_workspace *ws)
{
    sim_slab_start(e->scheme_params, ws->scheme_state, &ws->run);
}

/* The time-step scheme's output intervals, each of ws->steps slab steps. */
static void slab_evolve(const sim_engine *e, sim_workspace *ws, double *obs, size_t *samples)
{
    const sim_scene *scene = &e->scene;
    for (size_t m = 1; m < scene->outputs; m++) {
        sim_engine_interval_steps(e, ws, obs, m);
        for (size_t k = 0; k < ws->steps; k++)
            sim_slab_step(e->scheme_params, ws->scheme_state, &ws->run, ws->h);
        sim_engine_observe_output(e, ws, m, sim_scene_output_time(scene, m), obs, samples);
    }
}

/* Against the layers' velocities (slab.h); the steady observers see the
 * peculiar velocities. */
static const sim_particles *slab_observe(const sim_engine *e, sim_workspace *ws, size_t m,
                                         const double *prev, double *row)
{
    sim_slab_observe(e->scheme_params, ws->scheme_state, &ws->run, m, prev, ws->observer_rng,
                     row);
    return sim_slab_peculiar(ws->scheme_state);
}

static const sim_scheme_state slab_state = {slab_bytes, slab_create, slab_free};

/* A shear with the Lees-Edwards boundary, in either scheme (the jump scheme
 * is refused by sim_slab_accept, naming shear.boundary). */
static int slab_claims(const sim_scene *scene)
{
    return scene->shear.present && scene->shear.boundary == SIM_SHEAR_LEES_EDWARDS;
}

const sim_scheme_type sim_scheme_slab = {
    .effect_name = "slab",
    .claims = slab_claims,
    .accept = sim_slab_accept,
    .accept_event = sim_scheme_needs_stages,
    .build = slab_build,
    .state = &slab_state,
    .start = slab_start,
    .evolve = slab_evolve,
    .observe = slab_observe,
};
