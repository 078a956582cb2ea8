/* An independent solver behind gdsmc's solver protocol (docs/solver-protocol.md):
 * inelastic hard spheres with the Gaussian thermostat, by paper C's time-step
 * scheme (docs/theory.md §8.5), on gdsmc_protocol.h.
 *
 *   hard_spheres_gaussian SCENE.ini RESULT.csv [--restitution-factor F]
 *                         [--declare-substitutions]
 *
 * Each ensemble is n particles of one Maxwellian (zero_momentum: its sample
 * mean moved to the drift).  The interval between output times is cut into
 * the fewest equal steps h <= dt; a step is (Euler) collide for h, then the
 * thermostat for h, or (Strang) thermostat h/2, collide h, thermostat h/2.
 *
 * Collisions (Bird's no-time-counter scheme with a majorant, paper C section 3):
 * candidates come at the rate (1/2) n omega_max = 8 pi gamma C beta (n - 1) U_max
 * (so (1/2) n omega_max h per stage, the fraction left over carried to the
 * next), each an ordered pair i != j with s uniform on the sphere, accepted
 * with probability Theta(g.s) (g.s)/U_max, g = v_i - v_j, and then collided
 * by the contact rule v_i -= (1 + alpha)/2 (g.s) s, v_j += (1 + alpha)/2 (g.s) s.
 * Each unordered pair thus collides at the rate 4 pi gamma C beta |g|/n.  U_max =
 * 2R with R >= |v_k - V| for every particle (V the bulk velocity, which the
 * collisions keep): R is the largest distance at the start of the stage and
 * grows with every collided velocity, so g.s <= |g| <= U_max always holds;
 * the time left in the stage is then spent at the new rate.  An accepted
 * pair with g.s > U_max would be a majorant violation (counted; none occur).
 *
 * The Gaussian thermostat (paper C Eq. (61)): v -> e^{zeta h} v with zeta =
 * heating.strength, or with keep_temperature the peculiar velocities rescaled
 * so that T = particles.temperature after every (half) step.  Without
 * [heating] the gas cools freely.
 *
 * collisions.rule = relative-speed (the engine's other acceptance rule, equal
 * in distribution) is an algorithm choice: this solver uses the contact rule
 * for it; --declare-substitutions says so in the result ("# substituted =
 * collisions.rule"; newer gdsmc only).  Every other scene it cannot do is
 * refused (exit status 3, the reason as the last line of standard error):
 * the jump scheme, other kernels, white-noise or non-Gaussian heating, a
 * host medium, shear, the heat-flux force, other initial states, ...
 *
 * --restitution-factor F is a deliberate error: the collisions use F alpha
 * (the steady quantities still use the scene's alpha).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gdsmc_protocol.h"

typedef struct params {
    size_t n, N, outputs;
    unsigned long long seed;
    double mass, T0, u0[3];
    int zero_momentum, strang;
    double dt;
    double alpha, rate_per_umax;   /* candidates per unit time and unit U_max */
    enum { NONE, FIXED_ZETA, KEEP_T } thermostat;
    double zeta;
} params;

/* Read every key this solver implements and refuse the rest. */
static void read_scene(gp_scene *s, params *p, gp_steady *st, double restitution_factor)
{
    if (gp_present(s, "background"))
        gp_refuse("[background] not supported (this solver: hard spheres, Gaussian thermostat)");
    if (gp_present(s, "shear"))
        gp_refuse("[shear] not supported (this solver: hard spheres, Gaussian thermostat)");
    if (gp_present(s, "heat-flux"))
        gp_refuse("[heat-flux] not supported (this solver: hard spheres, Gaussian thermostat)");
    gp_only(s, "scene.scheme", "timestep");
    p->dt = gp_real(s, "scene.dt");
    p->strang = strcmp(gp_only(s, "scene.splitting", "euler|strang"), "strang") == 0;
    gp_only(s, "scene.step_follows_temperature", "false");
    gp_only(s, "scene.observation", "sampled");
    p->outputs = (size_t)gp_count(s, "scene.outputs");
    p->seed = gp_count(s, "scene.seed");

    p->n = (size_t)gp_count(s, "particles.n");
    p->N = (size_t)gp_count(s, "particles.ensembles");
    gp_only(s, "particles.initial", "maxwellian");
    p->mass = gp_real(s, "particles.mass");
    p->T0 = gp_real(s, "particles.temperature");
    gp_vec3(s, "particles.velocity", p->u0);
    p->zero_momentum = gp_bool(s, "particles.zero_momentum");

    if (!gp_present(s, "collisions"))
        gp_refuse("a scene without [collisions] not supported (this solver: hard spheres)");
    gp_only(s, "collisions.kernel", "hard-spheres");
    gp_only_real(s, "collisions.exponent", 1.0);
    gp_only(s, "collisions.model", "ihs");
    if (strcmp(gp_only(s, "collisions.rule", "contact|relative-speed"), "contact") != 0)
        gp_substitute(s, "collisions.rule");   /* equal in distribution (docs/theory.md §3.2) */
    p->alpha = restitution_factor * gp_real(s, "collisions.restitution");
    p->rate_per_umax = 8.0 * M_PI * gp_real(s, "collisions.rate")
                       * gp_real(s, "collisions.constant") * gp_real(s, "collisions.beta")
                       * (double)(p->n - 1);

    p->thermostat = NONE;
    if (gp_present(s, "heating")) {
        gp_only(s, "heating.type", "gaussian");
        if (gp_bool(s, "heating.keep_temperature"))
            p->thermostat = KEEP_T;
        else {
            p->thermostat = FIXED_ZETA;
            p->zeta = gp_real(s, "heating.strength");
        }
    }
    gp_steady_init(st, s);
    gp_refuse_unread(s);
}

static void bulk_velocity(const double (*v)[3], size_t n, double V[3])
{
    V[0] = V[1] = V[2] = 0.0;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            V[k] += v[i][k];
    for (int k = 0; k < 3; k++)
        V[k] /= (double)n;
}

static double distance(const double v[3], const double V[3])
{
    const double d[3] = {v[0] - V[0], v[1] - V[1], v[2] - V[2]};
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* The thermostat for time h. */
static void thermostat(const params *p, double (*v)[3], double h)
{
    const size_t n = p->n;
    if (p->thermostat == FIXED_ZETA) {
        const double f = exp(p->zeta * h);
        for (size_t i = 0; i < n; i++)
            for (int k = 0; k < 3; k++)
                v[i][k] *= f;
    } else if (p->thermostat == KEEP_T) {
        double V[3], c2 = 0.0;
        bulk_velocity((const double (*)[3])v, n, V);
        for (size_t i = 0; i < n; i++) {
            const double d = distance(v[i], V);
            c2 += d * d;
        }
        if (!(c2 > 0.0))
            return;
        const double f = sqrt(3.0 * (double)n * p->T0 / p->mass / c2);
        for (size_t i = 0; i < n; i++)
            for (int k = 0; k < 3; k++)
                v[i][k] = V[k] + f * (v[i][k] - V[k]);
    }
}

typedef struct counts {
    long long candidates, collisions, violations;
} counts;

/* One collision stage of length h; *credit carries the time not yet spent
 * on candidates from one stage to the next. */
static void collide(const params *p, double (*v)[3], double h, double *credit, gp_rng *rng,
                    counts *c)
{
    const size_t n = p->n;
    double V[3], R = 0.0;
    bulk_velocity((const double (*)[3])v, n, V);
    for (size_t i = 0; i < n; i++)
        R = fmax(R, distance(v[i], V));
    double umax = 2.0 * R, per_candidate = 1.0 / (p->rate_per_umax * umax);
    *credit += h;
    while (*credit >= per_candidate) {
        *credit -= per_candidate;
        c->candidates++;
        const size_t i = (size_t)gp_rng_index(rng, n);
        size_t j = (size_t)gp_rng_index(rng, n - 1);
        j += (j >= i);
        double s[3];
        gp_rng_unit_vector(rng, s);
        const double gs = (v[i][0] - v[j][0]) * s[0] + (v[i][1] - v[j][1]) * s[1]
                          + (v[i][2] - v[j][2]) * s[2];
        if (!(gs > 0.0) || gp_rng_uniform(rng) * umax >= gs)
            continue;
        c->collisions++;
        c->violations += gs > umax;
        const double a = 0.5 * (1.0 + p->alpha) * gs;   /* the contact rule */
        for (int k = 0; k < 3; k++) {
            v[i][k] -= a * s[k];
            v[j][k] += a * s[k];
        }
        const double r = fmax(distance(v[i], V), distance(v[j], V));
        if (r > R) {   /* the bound grows: the rest of the stage at the new rate */
            R = r;
            umax = 2.0 * R;
            per_candidate = 1.0 / (p->rate_per_umax * umax);
        }
    }
}

/* One ensemble from its initial state to t_end, observed at every output. */
static void run_ensemble(gp_scene *s, const params *p, const gp_steady *st, size_t e,
                         double (*v)[3], double *steady_sum, gp_result *res, counts *c)
{
    gp_rng rng;
    gp_rng_seed(&rng, p->seed, e);
    const double sigma = sqrt(p->T0 / p->mass);
    for (size_t i = 0; i < p->n; i++)
        for (int k = 0; k < 3; k++)
            v[i][k] = p->u0[k] + sigma * gp_rng_normal(&rng);
    if (p->zero_momentum) {
        double V[3];
        bulk_velocity((const double (*)[3])v, p->n, V);
        for (size_t i = 0; i < p->n; i++)
            for (int k = 0; k < 3; k++)
                v[i][k] += p->u0[k] - V[k];
    }
    const size_t nsteady = gp_steady_count(st);
    memset(steady_sum, 0, (nsteady + 1) * sizeof *steady_sum);
    size_t samples = 0;
    double credit = 0.0;
    for (size_t m = 0; m < p->outputs; m++) {
        const double t = gp_output_time(s, m);
        if (m > 0) {
            const double interval = t - gp_output_time(s, m - 1);
            const double steps = ceil(interval / p->dt * (1.0 - 1e-9));
            const double h = interval / steps;
            for (double k = 0; k < steps; k++) {
                if (p->strang)
                    thermostat(p, v, 0.5 * h);
                collide(p, v, h, &credit, &rng, c);
                thermostat(p, v, p->strang ? 0.5 * h : h);
            }
        }
        double obs[GP_NOBS];
        gp_observe((const double (*)[3])v, p->n, p->mass, obs);
        gp_result_add(res, m, obs);
        if (gp_steady_due(st, t)) {
            gp_steady_sample(st, (const double (*)[3])v, p->n, p->mass, &rng, steady_sum);
            samples++;
        }
    }
    if (nsteady > 0)
        gp_result_add_steady(res, steady_sum, samples);
}

int main(int argc, char **argv)
{
    double factor = 1.0;
    int declare = 0, bad = argc < 3;
    for (int a = 3; a < argc && !bad; a++) {
        if (strcmp(argv[a], "--restitution-factor") == 0 && a + 1 < argc) {
            char *end;
            factor = strtod(argv[++a], &end);
            bad = *end != '\0' || !(factor > 0.0);
        } else if (strcmp(argv[a], "--declare-substitutions") == 0)
            declare = 1;
        else
            bad = 1;
    }
    if (bad) {
        fprintf(stderr, "usage: hard_spheres_gaussian SCENE.ini RESULT.csv "
                        "[--restitution-factor F] [--declare-substitutions]\n");
        return GP_EXIT_FAILED;
    }
    static gp_scene scene;
    gp_scene_load(&scene, argv[1]);
    params p;
    gp_steady st;
    read_scene(&scene, &p, &st, factor);

    gp_result res;
    gp_result_init(&res, &scene, &st);
    double (*v)[3] = malloc(p.n * sizeof *v);
    double *steady_sum = malloc((gp_steady_count(&st) + 1) * sizeof *steady_sum);
    if (v == NULL || steady_sum == NULL)
        gp_fail("out of memory for %zu particles", p.n);
    counts c = {0, 0, 0};
    const double cpu0 = gp_cpu_seconds();
    for (size_t e = 0; e < p.N; e++)
        run_ensemble(&scene, &p, &st, e, v, steady_sum, &res, &c);

    char solver[128];
    snprintf(solver, sizeof solver, "hard_spheres_gaussian (examples/c)%s",
             factor != 1.0 ? ", restitution factor set" : "");
    const gp_result_info info = {.solver = solver, .cpu_seconds = gp_cpu_seconds() - cpu0,
                                 .events = c.candidates, .violations = c.violations,
                                 .declare_substitutions = declare};
    gp_result_write(&res, &scene, argv[2], &info);
    gp_result_free(&res);
    free(v);
    free(steady_sum);
    return 0;
}
