/* A template: put an existing solver behind gdsmc's --solver
 * (docs/solver-protocol.md).
 *
 * Copy this file (and gdsmc_protocol.h beside it), then
 *   1. in read_scene(), read every scene key your code handles and turn it
 *      into your code's parameters; refuse the values it cannot do;
 *   2. in my_solver_*(), call your code: one ensemble of n particles from
 *      its initial state, advanced from one output time to the next;
 *   3. build it (cc -O2 my_adapter.c -lm) and run it:
 *        gdsmc verify --suite quick --case CASE --solver './my_adapter {scene} {out}'
 *
 * As it stands the "solver" is a stand-in that never changes the particles:
 * right for a scene with no collisions and no forces (only [scene] and
 * [particles]), and every effect section is refused.  Refusing is always
 * allowed: a scene your code cannot do exits with status 3 and the reason as
 * the last line of standard error (gp_refuse), and gdsmc reports that
 * scene's checks as not judged.  What you never read, gp_refuse_unread()
 * refuses for you ("key X not supported"), so a key added to gdsmc later
 * cannot be silently ignored.
 *
 *   template_adapter SCENE.ini RESULT.csv
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gdsmc_protocol.h"

/* Your code's parameters. */
typedef struct params {
    size_t n, N, outputs;
    unsigned long long seed;
    double mass, T0, u0[3];
    int zero_momentum;
} params;

static void read_scene(gp_scene *s, params *p, gp_steady *st)
{
    /* [scene]: t_end and outputs give the output times (gp_output_time) */
    p->outputs = (size_t)gp_count(s, "scene.outputs");
    p->seed = gp_count(s, "scene.seed");
    /* The scheme and its dt are algorithm choices: a code with its own time
     * stepping may take them over.  This stand-in takes no steps at all. */
    gp_substitute(s, "scene.scheme");
    gp_substitute(s, "scene.dt");
    /* the time-step scheme's own options: refuse what your code cannot follow */
    gp_only(s, "scene.splitting", "euler");
    gp_only(s, "scene.step_follows_temperature", "false");
    /* how output times observe a lazy flow: both have the same expectations */
    gp_only(s, "scene.observation", "sampled|conditional");

    /* [particles] */
    p->n = (size_t)gp_count(s, "particles.n");
    p->N = (size_t)gp_count(s, "particles.ensembles");
    gp_only(s, "particles.initial", "maxwellian");   /* not two-maxwellians, shell */
    p->mass = gp_real(s, "particles.mass");
    p->T0 = gp_real(s, "particles.temperature");
    gp_vec3(s, "particles.velocity", p->u0);
    p->zero_momentum = gp_bool(s, "particles.zero_momentum");

    /* The effects.  Replace a refusal by reading the section's keys when your
     * code does the effect, e.g. for hard-sphere collisions:
     *   gp_only(s, "collisions.kernel", "hard-spheres");
     *   p->alpha = gp_real(s, "collisions.restitution"); ... */
    static const char *const effects[][2] = {
        {"collisions", "binary collisions"}, {"heating", "a thermostat"},
        {"background", "a host medium"},     {"shear", "uniform shear flow"},
        {"heat-flux", "the heat-flux force"}};
    for (size_t k = 0; k < sizeof effects / sizeof effects[0]; k++)
        if (gp_present(s, effects[k][0]))
            gp_refuse("[%s] not supported: this solver does not do %s", effects[k][0],
                      effects[k][1]);

    /* [steady]: the time averages are computed by the helpers (gp_steady_*) */
    gp_steady_init(st, s);

    gp_refuse_unread(s);   /* anything not read above is refused */
}

/* ---- the stand-in for your code: replace these two ---------------------- */

/* Ensemble e's initial state: n velocities of the Maxwellian. */
static void my_solver_start(const params *p, size_t e, double (*v)[3], gp_rng *rng)
{
    gp_rng_seed(rng, p->seed, e);   /* a stream of its own per ensemble */
    const double sigma = sqrt(p->T0 / p->mass);
    double mean[3] = {0, 0, 0};
    for (size_t i = 0; i < p->n; i++)
        for (int k = 0; k < 3; k++) {
            v[i][k] = p->u0[k] + sigma * gp_rng_normal(rng);
            mean[k] += v[i][k] / (double)p->n;
        }
    if (p->zero_momentum)   /* the sample's mean velocity moved to the drift */
        for (size_t i = 0; i < p->n; i++)
            for (int k = 0; k < 3; k++)
                v[i][k] += p->u0[k] - mean[k];
}

/* Advance the ensemble from time t0 to t1. */
static void my_solver_advance(const params *p, double (*v)[3], double t0, double t1,
                              gp_rng *rng)
{
    (void)p, (void)v, (void)t0, (void)t1, (void)rng;   /* ... your code here ... */
}

/* ------------------------------------------------------------------------- */

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: template_adapter SCENE.ini RESULT.csv\n");
        return GP_EXIT_FAILED;
    }
    static gp_scene scene;
    gp_scene_load(&scene, argv[1]);
    params p;
    gp_steady st;
    read_scene(&scene, &p, &st);

    gp_result res;
    gp_result_init(&res, &scene, &st);
    const size_t nsteady = gp_steady_count(&st);
    double (*v)[3] = malloc(p.n * sizeof *v);
    double *steady_sum = malloc((nsteady + 1) * sizeof *steady_sum);
    if (v == NULL || steady_sum == NULL)
        gp_fail("out of memory for %zu particles", p.n);
    const double cpu0 = gp_cpu_seconds();
    for (size_t e = 0; e < p.N; e++) {
        gp_rng rng;
        my_solver_start(&p, e, v, &rng);
        memset(steady_sum, 0, (nsteady + 1) * sizeof *steady_sum);
        size_t samples = 0;
        for (size_t m = 0; m < p.outputs; m++) {
            const double t = gp_output_time(&scene, m);
            if (m > 0)
                my_solver_advance(&p, v, gp_output_time(&scene, m - 1), t, &rng);
            double obs[GP_NOBS];
            gp_observe((const double (*)[3])v, p.n, p.mass, obs);
            gp_result_add(&res, m, obs);
            if (gp_steady_due(&st, t)) {
                gp_steady_sample(&st, (const double (*)[3])v, p.n, p.mass, &rng, steady_sum);
                samples++;
            }
        }
        if (nsteady > 0)
            gp_result_add_steady(&res, steady_sum, samples);
    }
    /* events and violations: give your code's counts, or -1 (not reported) */
    const gp_result_info info = {.solver = "template_adapter (examples/c)",
                                 .cpu_seconds = gp_cpu_seconds() - cpu0, .events = -1,
                                 .violations = -1, .declare_substitutions = 0};
    gp_result_write(&res, &scene, argv[2], &info);
    gp_result_free(&res);
    free(v);
    free(steady_sum);
    return 0;
}
