/* Thermostats (SPEC §2, §3, §5).  White noise (paper A Eq. (18)): between
 * collisions each velocity performs Brownian motion,
 *     v(t + dt) = v(t) + sqrt(2 beta dt) xi,   xi standard normal in R^3,
 * exact for any dt, so the jump scheme applies it lazily.  The Gaussian and
 * non-Gaussian thermostats of paper C come with the time-step scheme. */
#include <math.h>
#include <stdlib.h>

#include "effect.h"
#include "rng.h"

typedef struct white_noise_params {
    double beta;
} white_noise_params;

static void white_noise_advance(const sim_effect *e, double v[3], double dt, gsl_rng *rng)
{
    const white_noise_params *p = e->params;
    double xi[3], s = sqrt(2.0 * p->beta * dt);
    sim_rng_normal3(rng, xi);
    v[0] += s * xi[0];
    v[1] += s * xi[1];
    v[2] += s * xi[2];
}

/* Each component moves by N(0, 2 beta dt); 4 standard deviations. */
static double white_noise_reach(const sim_effect *e, double dt)
{
    const white_noise_params *p = e->params;
    return 4.0 * sqrt(2.0 * p->beta * dt);
}

static const sim_effect_type white_noise_type = {
    .name = "heating",
    .advance = white_noise_advance,
    .reach = white_noise_reach,
};

sim_status sim_effect_heating(const sim_scene *scene, sim_effect *effect, sim_error *err)
{
    if (scene->heating.type != SIM_HEATING_WHITE_NOISE)
        return sim_error_set(err, SIM_EUNSUPPORTED, "heating.type",
                             "%s heating needs the time-step scheme, not implemented yet "
                             "(supported: white-noise)",
                             scene->heating.type == SIM_HEATING_GAUSSIAN ? "gaussian"
                                                                         : "non-gaussian");
    white_noise_params *p = malloc(sizeof *p);
    if (p == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    p->beta = scene->heating.strength;
    *effect = (sim_effect){.type = &white_noise_type, .params = p};
    return SIM_OK;
}
