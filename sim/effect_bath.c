/* The Langevin bath (docs/theory.md §4.5): viscous friction towards rest and
 * a white noise that balances it at the bath's temperature T_b,
 *     dv = -gamma v dt + sqrt(2 gamma T_b/m) dW,
 * the Ornstein-Uhlenbeck process, whose law over any dt is exact:
 *     v(t + dt) = f v(t) + s xi,  f = e^{-gamma dt},  s = sqrt((T_b/m) (1 - f^2)),
 * xi standard normal in each component.  Without collisions (or with elastic
 * ones, which keep the energy and the momentum) the centred temperature
 * relaxes as T(t) = T_b + (T(0) - T_b) e^{-2 gamma t} and the mean velocity as
 * e^{-gamma t}.  A flow of either scheme: the jump scheme brings particles
 * forward lazily with this exact law (`advance`), the time-step scheme steps
 * every particle with it.
 *
 * The effect added through the registry alone (issue 36): this file, its
 * line in registry.c, and its section's keys in the scene (scene.h,
 * verify/protocol/scene_ini.c, docs/scenes.md).
 */
#include <math.h>
#include <stdlib.h>

#include "effect.h"
#include "rng.h"
#include "run.h"

typedef struct bath_params {
    double friction;   /* gamma */
    double theta;      /* T_b/m */
} bath_params;

/* The law over dt: v <- f v + s xi (the header comment). */
static inline void bath_map(double v[3], double f, double s, gsl_rng *rng)
{
    double xi[3];
    sim_rng_normal3(rng, xi);
    v[0] = f * v[0] + s * xi[0];
    v[1] = f * v[1] + s * xi[1];
    v[2] = f * v[2] + s * xi[2];
}

/* s = sqrt((T_b/m) (1 - e^{-2 gamma dt})), without cancellation at small dt. */
static double bath_spread(const bath_params *p, double dt)
{
    return sqrt(p->theta * -expm1(-2.0 * p->friction * dt));
}

static void bath_advance(const sim_flow *e, double v[3], double dt, gsl_rng *rng)
{
    const bath_params *p = e->params;
    bath_map(v, exp(-p->friction * dt), bath_spread(p, dt), rng);
}

static void bath_step(const sim_flow *e, sim_run *run, double h)
{
    const bath_params *p = e->params;
    const double f = exp(-p->friction * h), s = bath_spread(p, h);
    for (size_t i = 0; i < run->p.n; i++) {
        bath_map(run->p.v[i], f, s, run->rng);
        sim_run_cover(run, run->p.v[i]);
    }
}

/* The noise moves a velocity by s chi_3 (7 s: exceeded with probability
 * 1.3e-10, as white noise's reach); the friction moves it towards rest,
 * which keeps |v - c| for a centre c at rest (the bath's bulk velocity).  A
 * gas that starts with a bulk velocity U adds up to (1 - f) |U| beyond it,
 * which the majorant-violation counter would show. */
static double bath_reach(const sim_flow *e, double dt)
{
    const bath_params *p = e->params;
    return 7.0 * bath_spread(p, dt);
}

static const sim_flow_type bath_type = {
    .name = "bath",
    .advance = bath_advance,
    .step = bath_step,
    .reach = bath_reach,
};

sim_status sim_effect_bath(const sim_scene *scene, sim_flow *effect, sim_error *err)
{
    bath_params *p = malloc(sizeof *p);
    if (p == NULL)
        return sim_error_set(err, SIM_ENOMEM, "", "out of memory");
    p->friction = scene->bath.friction;
    p->theta = scene->bath.temperature / sim_scene_grain_mass(scene);
    *effect = (sim_flow){.type = &bath_type, .params = p};
    return SIM_OK;
}
