/* Thermostats (docs/theory.md §4): the three of paper C, each its own type.
 *
 * White noise (paper A Eq. (18), paper C Eq. (8)): between collisions each
 * velocity performs Brownian motion,
 *     v(t + dt) = v(t) + sqrt(2 beta dt) xi,   xi standard normal in R^3,
 * exact for any dt, so the jump scheme applies it lazily (`advance`) and the
 * time-step scheme adds it to every particle (`step`, paper C Eqs. (59)-(60)
 * with xi0^2 = 2 beta).
 *
 * Gaussian (paper C Eq. (12), F = m zeta v): v -> v e^{zeta h} (Eq. (61)),
 * exact for any h.  With keep_temperature, zeta is chosen at every step so
 * that the centred temperature returns to particles.temperature:
 * v -> V + (v - V) sqrt(T0/T), the homogeneous cooling state in scaled
 * variables.  A projection, not a flow: both halves of a Strang step rescale,
 * so Strang and Euler coincide for it.
 *
 * Non-Gaussian (paper C Eq. (14), F = m g v/|v|): v_i -> v_i + g h (v̂_i - k)
 * with k = (1/n) Σ v̂_j (Eq. (62)), so the total momentum is kept to round-off.
 * It couples the particles (through k), so it has only `step`.
 *
 * The Gaussian thermostats are linear maps (sim_linear_map): the engine keeps
 * one global factor instead of stepping every particle.  The jump scheme runs
 * white noise, the Gaussian thermostat exactly (a fixed zeta: candidates at a
 * rate growing as e^{lambda zeta t}; keep_temperature: the rescaling after
 * each collision, the h -> 0 limit of rescaling after every step); the
 * constructor refuses the non-Gaussian thermostat there, naming heating.type.
 */
#include <math.h>
#include <stdlib.h>

#include "effect.h"
#include "rng.h"
#include "run.h"

typedef struct heating_params {
    double strength;   /* beta, zeta or g */
    double target;     /* keep_temperature: T0/m */
} heating_params;

/* ------------------------------------------------------------ white noise */

static void white_noise_advance(const sim_flow *e, double v[3], double dt, gsl_rng *rng)
{
    const heating_params *p = e->params;
    double xi[3], s = sqrt(2.0 * p->strength * dt);
    sim_rng_normal3(rng, xi);
    v[0] += s * xi[0];
    v[1] += s * xi[1];
    v[2] += s * xi[2];
}

static void white_noise_step(const sim_flow *e, sim_run *run, double h)
{
    const heating_params *p = e->params;
    const double s = sqrt(2.0 * p->strength * h);
    const size_t n = run->p.n;
    gsl_rng *rng = run->rng;
    for (size_t i = 0; i < n; i++) {
        double xi[3], *v = run->p.v[i];
        sim_rng_normal3(rng, xi);
        v[0] += s * xi[0];
        v[1] += s * xi[1];
        v[2] += s * xi[2];
        sim_run_cover(run, v);
    }
}

/* Each component moves by N(0, 2 beta dt), so the distance moved is
 * sigma chi_3, sigma = sqrt(2 beta dt); 7 sigma is exceeded with probability
 * P(chi_3 > 7) = 1.3e-10.  A radius, not a per-component bound: the
 * hard-sphere majorant (effect_collisions.c) needs |v_i - c| <= R for each
 * drawn particle, and at 4 sigma (P(chi_3 > 4) = 1.1e-3) particles of a gas
 * much colder than the heating outran the bound. */
static double white_noise_reach(const sim_flow *e, double dt)
{
    const heating_params *p = e->params;
    return 7.0 * sqrt(2.0 * p->strength * dt);
}

/* The increment over dt is N(0, 2 beta dt) per component. */
static double white_noise_spread(const sim_flow *e)
{
    const heating_params *p = e->params;
    return 2.0 * p->strength;
}

static const sim_flow_type white_noise_type = {
    .name = "heating",
    .advance = white_noise_advance,
    .step = white_noise_step,
    .reach = white_noise_reach,
    .spread = white_noise_spread,
};

/* --------------------------------------------------------------- Gaussian */

static void gaussian_step(const sim_flow *e, sim_run *run, double h)
{
    const heating_params *p = e->params;
    const double f = exp(p->strength * h);
    const size_t n = run->p.n;
    for (size_t i = 0; i < n; i++) {
        double *v = run->p.v[i];
        v[0] *= f;
        v[1] *= f;
        v[2] *= f;
        sim_run_cover(run, v);
    }
}

/* v -> e^{zeta h} v about the origin. */
static double gaussian_factor(const sim_flow *e, const sim_run *run, double h)
{
    (void)run;
    const heating_params *p = e->params;
    return exp(p->strength * h);
}

static double gaussian_rate(const sim_flow *e)
{
    const heating_params *p = e->params;
    return p->strength;
}

static const sim_linear_map gaussian_map = {.factor = gaussian_factor, .rate = gaussian_rate};

static const sim_flow_type gaussian_type = {
    .name = "heating",
    .step = gaussian_step,
    .linear = &gaussian_map,
};

/* Rescale the peculiar velocities so that T/m = target (h does not enter). */
static void keep_temperature_step(const sim_flow *e, sim_run *run, double h)
{
    (void)h;
    const heating_params *p = e->params;
    const size_t n = run->p.n;
    double V[3] = {0, 0, 0}, c2 = 0.0;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            V[k] += run->p.v[i][k];
    for (int k = 0; k < 3; k++)
        V[k] /= (double)n;
    for (size_t i = 0; i < n; i++) {
        const double *v = run->p.v[i];
        double c[3] = {v[0] - V[0], v[1] - V[1], v[2] - V[2]};
        c2 += c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    }
    if (!(c2 > 0.0))   /* every velocity equal: nothing to rescale */
        return;
    const double f = sqrt(3.0 * (double)n * p->target / c2);
    for (size_t i = 0; i < n; i++) {
        double *v = run->p.v[i];
        for (int k = 0; k < 3; k++)
            v[k] = V[k] + f * (v[k] - V[k]);
        sim_run_cover(run, v);
    }
}

/* The factor that brings T/m of the velocities o + scale f (w - o) to the
 * target, o the bulk velocity, from the sums of the stored w (h does not
 * enter): f = sqrt(target / (scale^2 theta_w)), theta_w = T_w/m. */
static double keep_temperature_factor(const sim_flow *e, const sim_run *run, double h)
{
    (void)h;
    const heating_params *p = e->params;
    const sim_sums *s = &run->sums;
    const double n = (double)run->p.n;
    const double c2 = s->vv[0] + s->vv[1] + s->vv[2]
                      - (s->v[0] * s->v[0] + s->v[1] * s->v[1] + s->v[2] * s->v[2]) / n;
    if (!(c2 > 0.0))   /* every velocity equal: nothing to rescale */
        return 1.0;
    return sqrt(3.0 * n * p->target / c2) / run->scale;
}

static const sim_linear_map keep_temperature_map = {
    .factor = keep_temperature_factor,
    .centred = 1,
    .reads_sums = 1,
};

static const sim_flow_type keep_temperature_type = {
    .name = "heating",
    .step = keep_temperature_step,
    .linear = &keep_temperature_map,
};

/* ----------------------------------------------------------- non-Gaussian */

static void non_gaussian_step(const sim_flow *e, sim_run *run, double h)
{
    const heating_params *p = e->params;
    const size_t n = run->p.n;
    const double gh = p->strength * h;
    double k[3] = {0, 0, 0};
    for (size_t i = 0; i < n; i++) {
        const double *v = run->p.v[i];
        double norm = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (norm > 0.0)   /* v = 0 has probability 0; its direction counts as 0 */
            for (int c = 0; c < 3; c++)
                k[c] += v[c] / norm;
    }
    for (int c = 0; c < 3; c++)
        k[c] /= (double)n;
    for (size_t i = 0; i < n; i++) {
        double *v = run->p.v[i];
        double norm = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        double inv = norm > 0.0 ? 1.0 / norm : 0.0;
        for (int c = 0; c < 3; c++)
            v[c] += gh * (v[c] * inv - k[c]);
        sim_run_cover(run, v);
    }
}

static const sim_flow_type non_gaussian_type = {
    .name = "heating",
    .step = non_gaussian_step,
};

/* ------------------------------------------------------------ constructor */

sim_status sim_effect_heating(const sim_scene *scene, sim_flow *effect, sim_error *err)
{
    const sim_flow_type *type = &white_noise_type;
    switch (scene->heating.type) {
    case SIM_HEATING_WHITE_NOISE:
        type = &white_noise_type;
        break;
    case SIM_HEATING_GAUSSIAN:
        type = scene->heating.keep_temperature ? &keep_temperature_type : &gaussian_type;
        break;
    case SIM_HEATING_NON_GAUSSIAN:
        type = &non_gaussian_type;
        break;
    }
    /* the jump scheme: a lazy flow (white noise) or a linear map kept global
     * (scheme_jump.c, run_jump_linear) */
    if (scene->scheme == SIM_SCHEME_JUMP && type->advance == NULL && type->linear == NULL)
        return sim_error_set(err, SIM_EUNSUPPORTED, "heating.type",
                             "non-gaussian heating needs scene.scheme = timestep (the jump "
                             "scheme supports white-noise and gaussian)");
    heating_params *p = malloc(sizeof *p);
    if (p == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    p->strength = scene->heating.strength;
    p->target = scene->particles.maxwellian.temperature / sim_scene_grain_mass(scene);
    *effect = (sim_flow){.type = type, .params = p};
    return SIM_OK;
}
