/* protocol (gdsmc verify --suite protocol): a conformance case for the
 * mechanics of a solver's adapter (docs/solver-protocol.md), in seconds, on
 * paper A Example 3's gas at n = 8 (verify/cases/scenes/protocol.ini):
 *   - the time grid and the T and T_raw columns: z-tests against the exact
 *     finite-n expectations (docs/theory.md §11.2) at every output time;
 *   - the variance columns: at t = 0 the initial Maxwellian fixes the
 *     variance of T, T_raw and ux over the ensembles exactly (below);
 *   - the steady section: steady T is the time average of the T column over
 *     t >= steady.from (§10.1), and the speed histogram integrates to the
 *     fraction of speeds below c_max (§10.4).
 * A wrong sample variance (the standard deviation, the variance of the sum, a
 * population divisor at small N ...), a shifted grid, a steady window other
 * than the scene's or an unnormalised histogram each fails a check here.
 *
 * At t = 0 the n velocities are i.i.d. Maxwellian at T0 (mass m), so
 *   T_raw = (T0/3n) chi^2_{3n},  T = (T0/3n) chi^2_{3(n-1)},  ux ~ N(0, T0/(m n)):
 * variances 2 T0^2/(3n), 2 T0^2 (n-1)/(3 n^2) and T0/(m n), excess kurtoses 4/n,
 * 4/(n-1) and 0.  The sample variance s^2 of N such estimates has standard
 * error sigma^2 sqrt(2/(N-1) + kurtosis/N).  *
 * The cases are data (verify/cases/scenes/protocol.case, docs/adding-a-case.md);
 * this file holds the metrics, guards, rules and hooks they name, listed
 * in vfy_protocol_named at its end.
 */
#include <math.h>
#include <string.h>

#include "driver.h"
#include "named.h"
#include "observe.h"
#include "scene.h"
#include "steady.h"
#include "tolerances.h"

enum { VAR_REPORTED, VAR_EXACT, VAR_ALLOWED };

/* The sample variance at t = 0 of observable m->a, its exact value, or
 * VFY_TOL_ZMAX standard errors of the sample variance (m->x: VAR_...). */
static double initial_variance(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    const sim_scene *s = &row->solver, *ref = &row->scene;   /* the exact values: the scene's */
    const sim_ensemble_result *res = &row->res;
    const double n = (double)ref->particles.n, N = (double)res->ensembles;
    const double T0 = ref->particles.maxwellian.temperature, m0 = sim_scene_grain_mass(ref);
    const int k = sim_observable_find(s, m->a, strlen(m->a));
    if (k < 0 || res->outputs == 0 || N < 2)
        return NAN;
    double exact, kurtosis;
    if (strcmp(m->a, "T_raw") == 0)
        exact = 2.0 * T0 * T0 / (3.0 * n), kurtosis = 4.0 / n;
    else if (strcmp(m->a, "T") == 0)
        exact = 2.0 * T0 * T0 * (n - 1.0) / (3.0 * n * n), kurtosis = 4.0 / (n - 1.0);
    else
        exact = T0 / (m0 * n), kurtosis = 0.0;
    switch ((int)m->x) {
    case VAR_REPORTED:   /* the result's population variance, back to the sample's */
        return res->var[(size_t)k] * N / (N - 1.0);
    case VAR_EXACT:
        return exact;
    default:
        return VFY_TOL_ZMAX * exact * sqrt(2.0 / (N - 1.0) + kurtosis / N);
    }
}

/* |steady T - the time average of the T column over t >= steady.from|,
 * relative to it. */
static double steady_gap(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    (void)m;
    const sim_scene *s = &row->solver;
    const sim_ensemble_result *res = &row->res;
    const long j = sim_steady_find(s, "T");
    const int k = sim_observable_find(s, "T", 1);
    double sum = 0.0;
    size_t count = 0;
    for (size_t t = 0; t < res->outputs && j >= 0 && k >= 0; t++)
        if (res->t[t] >= s->steady.from * (1.0 - 1e-12)) {
            sum += res->mean[t * res->observables + (size_t)k];
            count++;
        }
    if (count == 0 || j < 0)
        return NAN;
    const double average = sum / (double)count;
    return fabs(res->steady_mean[j] - average) / average;
}

/* The speed histogram's integral: sum_k f_k times its shell's volume. */
static double histogram_integral(const vfy_case_run *run, const vfy_row *row,
                                 const vfy_metric *m)
{
    (void)run;
    (void)m;
    const sim_scene *s = &row->solver;
    if (s->steady.bins == 0 || row->res.nsteady < SIM_STEADY_BIN0 + s->steady.bins)
        return NAN;
    double integral = 0.0;
    for (size_t k = 0; k < s->steady.bins; k++) {
        const double lo = sim_steady_bin_lower(s, k), hi = sim_steady_bin_lower(s, k + 1);
        integral += row->res.steady_mean[SIM_STEADY_BIN0 + k] * 4.0 * M_PI / 3.0
                    * (hi * hi * hi - lo * lo * lo);
    }
    return integral;
}

/* The functions this file's case files name (named.h, registry.c). */
const vfy_named_fn vfy_protocol_named[] = {
    VFY_NAMED_METRIC_X("initial_variance_reported", initial_variance, VAR_REPORTED),
    VFY_NAMED_METRIC_X("initial_variance_exact", initial_variance, VAR_EXACT),
    VFY_NAMED_METRIC_X("initial_variance_allowed", initial_variance, VAR_ALLOWED),
    VFY_NAMED_METRIC("steady_gap", steady_gap),
    VFY_NAMED_METRIC("histogram_integral", histogram_integral),
    VFY_NAMED_END};
