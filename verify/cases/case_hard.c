/* The hard suite (issue #5 item 1): cases chosen to break a careless solver,
 * each with checks that can fail.  Suite `hard` (the sizes below marked
 * "paper"); every case is also in the quick suite at small sizes (CI, also
 * under ASan+UBSan).  Scenes: verify/cases/scenes/hard-*.ini, and paper A's and B's
 * own scenes where a case reuses their gases.
 *
 * hard-dissipation  very strong dissipation: white-noise heated hard spheres
 *     at alpha = 0.05 and 0.1 (exact jump scheme), steady state.  Steady a2
 *     against the Sonine estimate (C.10); mu4 = 5 mu2, paper C's exact
 *     steady relation (Eq. 23); the exact steady energy balance (below);
 *     majorant violations 0; no NaN.
 * hard-nongaussian  paper C's non-Gaussian thermostat F = m g v/|v|, singular
 *     at v = 0, at alpha = 0.05 and 0.1 (time-step scheme): a2 negative near
 *     (C.76); mu4 = 2 mu2 <c^3>/<c> (Eq. 44); the population near v = 0
 *     depleted (paper C §4.3: f(0) about 0, far below the first Sonine
 *     1 + 15 a2/8); total momentum kept to round-off (Eq. 62); no NaN.
 * hard-tails  paper A Ex 7: hard spheres, alpha = 0.1, beta = 30, gamma = 16,
 *     heated from T0 = 1 to about 3, so U_max grows while the tail fills
 *     (overpopulated, f ~ exp(-A c^{3/2})): majorant violations 0; the
 *     exact energy balance; a2 against (C.10); the tail beyond c = 3 at least
 *     as populated as the first Sonine approximation says.
 * hard-tiny  n = 2, 3, 4 particles: paper A Ex 3's gas (T and T_raw z-tested
 *     against the exact finite-n expectations), paper B Ex 2's (T and u
 *     against theirs), paper A Ex 5's hard spheres (majorant violations);
 *     in paper A's gases the bulk velocity is exactly Gaussian with variance
 *     (T0 + 2 beta t)/n per component (collisions conserve it, heating adds
 *     independent increments), chi^2-tested at every time.
 * hard-long-run  10^9 events per system (10^7 at quick sizes): Maxwell
 *     molecules without heating, alpha just below 1 (k t_end = 4), every
 *     event a collision; and elastic hard spheres, 2x10^8 collisions (about
 *     10^9 candidate events): momentum conserved to round-off;
 *     T(t) = T(0) e^{-kt} within the noise of the inelastic losses
 *     (Maxwell), or T conserved to round-off (elastic); T finite and in its
 *     physical range; no NaN.
 * hard-stiff  paper B's closures (B.21, B.22) with K = 100 and 1e-4, and
 *     (B.13) with Kn = 100 and 1e-4, through CVODE (BDF, Adams, and Adams
 *     with a step budget too small, a real failure): success
 *     with the result at the steady state found independently (Brent) or on
 *     the closed form, or a failure with a clear message; never garbage.
 * hard-extreme  extreme but legal parameters: restitution 1e-3 and exactly
 *     1, rate 1e6, T0 = 1e-8 and 1e8 (Maxwell molecules, exact finite-n
 *     expectations; and hard spheres from T0 = 1e-8 and 1e8 to the steady
 *     state of the first-Sonine closure).
 *
 * The exact steady energy balance (docs/theory.md §11.3: dT/dt = 2 beta - gamma (1 -
 * alpha^2)/24 ∫∫ B1 |g|^2 f f, B1 = 4 pi C |g|).  For the n-particle jump
 * process with X = Σ|v_i - V|^2: white noise adds 6 beta (n - 1) to dE X/dt,
 * and an unordered pair collides at rate 4 pi gamma C |g|/n losing
 * (1 - alpha^2)/4 |g|^2 on average, so in the steady state
 *     2 beta = gamma pi C (1 - alpha^2) <|g|^3> / 6
 * at every n, <.> over the pairs of one system and time.  Pair sampling gives
 * <|g|^3> = 8 mu2 v0^3 / (pi (1 - alpha^2)) (paper C Eq. 65, mu2 reduced by
 * v0 = sqrt(2T/m)); the product of the time averages of mu2 and T^{3/2}
 * differs from the average of the product by O(1/n), which the tolerance
 * allows (3/n).
 */
#include "case_hard.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "background.h"
#include "case_report.h"
#include "cases.h"
#include "driver.h"
#include "heated.h"
#include "metrics.h"
#include "references.h"
#include "scene_refs.h"
#include "steady.h"
#include "tolerances.h"

#define TIGHT_STEPS 20        /* hard-stiff: a step budget per output interval too small */
#define TIGHT_STEPS_TEXT "20"

/* ------------------------------------------------ summaries and pure checks */

/* x into *max, NaN winning (a NaN must make the check fail, not vanish). */
/* x into *max, NaN winning (a NaN must make the check fail, not vanish). */
static void nan_max(double *max, double x)
{
    if (!(x <= *max))
        *max = x;
}

static void nan_min(double *min, double x)
{
    if (!(x >= *min))
        *min = x;
}

void vfy_hard_summarize(const sim_ensemble_result *res, double mass, vfy_hard_summary *s)
{
    memset(s, 0, sizeof *s);
    s->ensembles = res->ensembles;
    s->n = res->n;
    s->candidates = res->counts.candidates;
    s->collisions = res->counts.collisions;
    s->violations = res->counts.violations;
    const size_t M = res->outputs, total = M * res->observables + res->nsteady;
    const double *arrays[3] = {res->mean, res->var, res->ci};
    for (size_t a = 0; a < 3; a++)
        for (size_t i = 0; i < total; i++) {
            s->values++;
            if (!isfinite(arrays[a][i]) && s->nonfinite++ == 0)
                s->first_nonfinite = a * total + i;
        }
    const double N = (double)res->ensembles;
    s->T_first = M ? sim_result_mean(res, 0, SIM_OBS_T) : NAN;
    s->T_last = M ? sim_result_mean(res, M - 1, SIM_OBS_T) : NAN;
    s->T_min = s->T_max = s->T_first;
    for (size_t m = 0; m < M; m++) {
        for (int k = SIM_OBS_UX; k <= SIM_OBS_UZ; k++) {
            double mean = sim_result_mean(res, m, k), var = sim_result_var(res, m, k);
            nan_max(&s->momentum, sqrt(N * (var + mean * mean)));
        }
        double mean = sim_result_mean(res, m, SIM_OBS_T_RAW);
        double var = sim_result_var(res, m, SIM_OBS_T_RAW);
        nan_max(&s->speed, sqrt(3.0 * sqrt(N * (var + mean * mean)) / mass));
        nan_min(&s->T_min, sim_result_mean(res, m, SIM_OBS_T));
        nan_max(&s->T_max, sim_result_mean(res, m, SIM_OBS_T));
    }
}

double vfy_hard_momentum_bound(const vfy_hard_summary *s, double updates)
{
    const double u = 0.5 * DBL_EPSILON;
    return VFY_TOL_HARD_ROUNDING_SIGMAS * u * s->speed * (sqrt(2.0 * updates) / (double)s->n + 2.0);
}

double vfy_hard_energy_bound(const vfy_hard_summary *s, double collisions)
{
    const double u = 0.5 * DBL_EPSILON, n = (double)s->n;
    return VFY_TOL_HARD_ROUNDING_SIGMAS * u * (8.0 * sqrt(collisions) / n + 2.0 * sqrt(n));
}

/* "<label> <what>" in buf (a check's name; checks.h keeps 95 characters). */
static const char *check_name(char *buf, size_t len, const char *label, const char *what)
{
    if (snprintf(buf, len, "%s %s", label, what) >= (int)len)
        buf[len - 1] = '\0';   /* truncated, as the report would */
    return buf;
}

vfy_verdict vfy_hard_check_finite(vfy_report *r, const char *label, const vfy_hard_summary *s)
{
    char name[128];
    check_name(name, sizeof name, label, "no NaN or infinity");
    if (s->nonfinite == 0)
        return vfy_check_true(r, name, s->values > 0,
                              "all %zu values finite (means, variances and half-widths over "
                              "%zu ensembles)", s->values, s->ensembles);
    return vfy_check_true(r, name, 0, "%zu of %zu values NaN or infinite (the first at index "
                          "%zu)", s->nonfinite, s->values, s->first_nonfinite);
}

vfy_verdict vfy_hard_check_violations(vfy_report *r, const char *label,
                                      const vfy_hard_summary *s)
{
    char name[128];
    return vfy_check_true(r, check_name(name, sizeof name, label, "majorant violations"),
                          s->violations == 0,
                          "%llu in %llu candidate events (expected 0; %llu accepted)",
                          (unsigned long long)s->violations,
                          (unsigned long long)s->candidates,
                          (unsigned long long)s->collisions);
}

vfy_verdict vfy_hard_check_momentum(vfy_report *r, const char *label, const vfy_hard_summary *s,
                                    double updates)
{
    char name[128];
    const double bound = vfy_hard_momentum_bound(s, updates);
    return vfy_check_true(r, check_name(name, sizeof name, label, "momentum kept to round-off"),
                          s->momentum <= bound,
                          "max |V_k| over ensembles and times %.3g (allowed %.3g: 6 sigma of "
                          "rounding after %.3g updates per system, r.m.s. speed %.3g)",
                          s->momentum, bound, updates, s->speed);
}

vfy_verdict vfy_hard_check_energy(vfy_report *r, const char *label, const vfy_hard_summary *s,
                                  double collisions)
{
    char name[128];
    const double bound = vfy_hard_energy_bound(s, collisions);
    double dev = 0.0;
    nan_max(&dev, fabs(s->T_last / s->T_first - 1.0));
    nan_max(&dev, fabs(s->T_min / s->T_first - 1.0));
    nan_max(&dev, fabs(s->T_max / s->T_first - 1.0));
    return vfy_check_true(r, check_name(name, sizeof name, label, "energy kept to round-off"),
                          dev <= bound,
                          "max |T(t)/T(0) - 1| %.3g (allowed %.3g: 6 sigma of rounding after "
                          "%.3g collisions per system)", dev, bound, collisions);
}

vfy_verdict vfy_hard_check_cooling_range(vfy_report *r, const char *label,
                                         const vfy_hard_summary *s)
{
    char name[128];
    const int ok = isfinite(s->T_min) && isfinite(s->T_max) && s->T_min > 0.0
                   && s->T_max <= s->T_first * (1.0 + VFY_TOL_HARD_COOLING_RTOL);
    return vfy_check_true(r, check_name(name, sizeof name, label, "T in its physical range"),
                          ok, "T between %.6g and %.6g, T(0) = %.6g (allowed (0, T(0)]: no "
                          "heating)", s->T_min, s->T_max, s->T_first);
}

vfy_verdict vfy_hard_check_ode(vfy_report *r, const char *name, const vfy_hard_ode *run)
{
    if (run->status != REF_OK) {
        const char *m = run->msg ? run->msg : "";
        if (m[0] == '\0')
            return vfy_check_true(r, name, 0, "CVODE failed (%s) without a message",
                                  ref_strerror(run->status));
        if (run->must_succeed)
            return vfy_check_true(r, name, 0, "failed (%s) where it must succeed: %s",
                                  ref_strerror(run->status), m);
        return vfy_check_true(r, name, 1, "failed cleanly (%s): %s", ref_strerror(run->status),
                              m);
    }
    if (run->T == NULL || run->nt == 0)
        return vfy_check_true(r, name, 0, "success reported with no solution");
    size_t garbage = 0, first = 0;
    double dev_exact = 0.0, dev_steady = 0.0;
    for (size_t m = 0; m < run->nt; m++) {
        int bad = !isfinite(run->T[m]) || !(run->T[m] > 0.0);
        if (run->u)
            for (int k = 0; k < 3; k++)
                bad |= !isfinite(run->u[3 * m + k]);
        if (bad && garbage++ == 0)
            first = m;
        if (run->T_exact)
            nan_max(&dev_exact, fabs(run->T[m] / run->T_exact[m] - 1.0));
    }
    if (garbage)
        return vfy_check_true(r, name, 0, "success reported, but %zu of %zu outputs are not "
                              "finite or T <= 0 (first at output %zu: T = %g)", garbage,
                              run->nt, first, run->T[first]);
    const double T_end = run->T[run->nt - 1];
    if (!isnan(run->T_steady))
        dev_steady = fabs(T_end / run->T_steady - 1.0);
    const int ok = dev_exact <= run->rtol && dev_steady <= run->rtol;
    char exact[96] = "";
    if (run->T_exact)
        snprintf(exact, sizeof exact, ", max rel. dev from the closed form %.2g", dev_exact);
    return vfy_check_true(r, name, ok,
                          "succeeded: T(t_end) = %.10g, steady %.10g (rel. dev %.2g)%s "
                          "(allowed %.0e)", T_end, run->T_steady, dev_steady, exact, run->rtol);
}

/* ---------------------------------------------------------------- helpers */

/* |value/expected - 1| <= rtol, as vfy_check_relative, with the deviation
 * and the tolerance to three digits (these tolerances are a fraction of a
 * percent); NaN fails. */
static vfy_verdict check_rel(vfy_report *r, const char *name, double value, double expected,
                             double rtol)
{
    const double dev = value / expected - 1.0;
    return vfy_check_true(r, name, fabs(dev) <= rtol,
                          "%.6g vs %.6g (%+.3g%%, allowed ±%.3g%%)", value, expected,
                          100.0 * dev, 100.0 * rtol);
}

/* Probability of c >= c0 under the Maxwellian phi = pi^{-3/2} e^{-c^2} and
 * its first-Sonine correction: ∫_{c >= c0} phi (1 + a2 S2(c^2)) d^3c with
 * S2(x) = x^2/2 - 5x/2 + 15/8 (d = 3).  J_m = ∫_{c0}^inf c^m e^{-c^2} dc by
 * J_m = c0^{m-1} e^{-c0^2}/2 + (m-1) J_{m-2}/2, J_0 = sqrt(pi) erfc(c0)/2,
 * and ∫ phi c^{2k} d^3c over the tail = (4/sqrt(pi)) J_{2k+2}. */
static double tail_probability(double c0, double a2)
{
    double J[7];
    const double e = exp(-c0 * c0);
    J[0] = 0.5 * sqrt(M_PI) * erfc(c0);
    for (int m = 2; m <= 6; m += 2)
        J[m] = 0.5 * pow(c0, m - 1) * e + 0.5 * (m - 1) * J[m - 2];
    const double I0 = 4.0 / sqrt(M_PI) * J[2], I1 = 4.0 / sqrt(M_PI) * J[4];
    const double I2 = 4.0 / sqrt(M_PI) * J[6];
    return I0 + a2 * (0.5 * I2 - 2.5 * I1 + 15.0 / 8.0 * I0);
}

/* The steady histogram's probability of the shells k >= k0 (steady.h: f_k is
 * the fraction in shell k over its volume), with a confidence half-width
 * from the shells' own (added in quadrature). */
static double shells_probability(const sim_scene *s, const sim_ensemble_result *res, size_t k0,
                                 size_t k1, double *ci)
{
    const double delta = s->steady.c_max / (double)s->steady.bins;
    double p = 0.0, var = 0.0;
    for (size_t k = k0; k < k1; k++) {
        const double kb = (double)k;
        const double vol = 4.0 * M_PI / 3.0 * delta * delta * delta
                           * (3.0 * kb * kb + 3.0 * kb + 1.0);   /* ((k+1)^3 - k^3) */
        const double f = sim_result_steady_mean(res, SIM_STEADY_BIN0 + k);
        const double fc = sim_result_steady_ci(res, SIM_STEADY_BIN0 + k);
        p += f * vol;
        var += fc * vol * fc * vol;
    }
    *ci = sqrt(var);
    return p;
}

/* z-test of the ensemble mean of x_k^2 (k = ux, uy, uz) at every output time
 * against sigma2[m] for a centred Gaussian: (1/N) Σ_j x_j^2 = var + mean^2
 * (population variance) has expectation sigma2 and standard deviation
 * sigma2 sqrt(2/N). */
static vfy_verdict check_gaussian_momentum(vfy_report *r, const char *name,
                                           const sim_ensemble_result *res,
                                           const double *sigma2, double *max_z)
{
    const size_t M = res->outputs, N = res->ensembles;
    double *mean = malloc(3 * M * sizeof *mean), *ci = malloc(3 * M * sizeof *ci);
    double *exact = malloc(3 * M * sizeof *exact);
    vfy_verdict v = VFY_FAIL;
    if (mean && ci && exact) {
        for (size_t m = 0; m < M; m++)
            for (int k = 0; k < 3; k++) {
                const int obs = SIM_OBS_UX + k;
                const double mu = sim_result_mean(res, m, obs);
                mean[3 * m + k] = sim_result_var(res, m, obs) + mu * mu;
                exact[3 * m + k] = sigma2[m];
                ci[3 * m + k] = SIM_LAMBDA_P * sigma2[m] * sqrt(2.0 / (double)N);
            }
        v = vfy_check_zscore(r, name, mean, ci, exact, 3 * M, VFY_TOL_ZMAX, max_z);
    } else {
        v = vfy_check_true(r, name, 0, "out of memory");
    }
    free(mean);
    free(ci);
    free(exact);
    return v;
}

/* A message as one CSV and Markdown cell: no ',', '|' or line breaks. */
static const char *csv_safe(char *text)
{
    for (char *p = text; *p; p++)
        if (*p == ',' || *p == '|' || *p == '\n' || *p == '\r')
            *p = *p == ',' ? ';' : *p == '|' ? '/' : ' ';
    return text;
}

/* ------------------------------------------------ rules, metrics and hooks */

/* The checks on a row's summary (above) as a rule: the check's name is the
 * row's label, the pure check adds what it judges; x selects it, and value
 * names the updates (momentum) or collisions (energy) per system. */
enum { HARD_FINITE, HARD_VIOLATIONS, HARD_MOMENTUM, HARD_ENERGY, HARD_COOLING };
static vfy_verdict hard_rule(vfy_report *r, const char *name, vfy_case_run *run, vfy_row *row,
                             const vfy_check_spec *c)
{
    if (vfy_external(run->o)) {   /* what the protocol already decides, or left out */
        const char *why = NULL;
        if (c->x == HARD_FINITE)
            why = "the result reader refuses NaN and infinity in what a solver reports";
        else if (c->x == HARD_VIOLATIONS && (row->res.missing & SIM_MISSING_VIOLATIONS))
            why = "violations not reported by the solver";
        else if (c->x != HARD_VIOLATIONS && isnan(sim_result_mean(&row->res, 0, SIM_OBS_T)))
            why = "T not reported by the solver";
        if (why != NULL) {
            vfy_skip(r, name, why);
            return VFY_SKIP;
        }
    }
    vfy_hard_summary sum;
    vfy_hard_summarize(&row->res, 1.0, &sum);
    const double count = c->value ? vfy_values_get(&row->values, c->value) : 0.0;
    switch ((int)c->x) {
    case HARD_VIOLATIONS:
        return vfy_hard_check_violations(r, name, &sum);
    case HARD_MOMENTUM:
        return vfy_hard_check_momentum(r, name, &sum, count);
    case HARD_ENERGY:
        return vfy_hard_check_energy(r, name, &sum, count);
    case HARD_COOLING:
        return vfy_hard_check_cooling_range(r, name, &sum);
    default:
        return vfy_hard_check_finite(r, name, &sum);
    }
}
#define HARD_CHECK(LABEL, WHICH, COUNT) {.name = LABEL, .rule = hard_rule, .x = WHICH, .value = COUNT}
/* The round-off bounds model this engine's own arithmetic (verify/cases/case_hard.h). */
#define HARD_ROUNDOFF_CHECK(LABEL, WHICH, COUNT)                                    \
    {.name = LABEL, .rule = hard_rule, .x = WHICH, .value = COUNT,                  \
     .builtin_only = "its round-off bound models this engine's own arithmetic"}

/* check_rel of value against expected (or x) within tol + value plus. */
static vfy_verdict hard_rule_rel(vfy_report *r, const char *name, vfy_case_run *run,
                                 vfy_row *row, const vfy_check_spec *c)
{
    (void)run;
    const vfy_values *v = &row->values;
    return check_rel(r, name, vfy_values_get(v, c->value),
                     c->expected ? vfy_values_get(v, c->expected) : c->x,
                     c->tol + (c->plus ? vfy_values_get(v, c->plus) : 0.0));
}

/* value >= value expected (a lower bound the row measured). */
static vfy_verdict hard_rule_at_least(vfy_report *r, const char *name, vfy_case_run *run,
                                      vfy_row *row, const vfy_check_spec *c)
{
    (void)run;
    return vfy_check_range(r, name, vfy_values_get(&row->values, c->value),
                           vfy_values_get(&row->values, c->expected), INFINITY);
}

/* 0 <= value <= tol + value plus. */
static vfy_verdict hard_rule_at_most(vfy_report *r, const char *name, vfy_case_run *run,
                                     vfy_row *row, const vfy_check_spec *c)
{
    (void)run;
    return vfy_check_range(r, name, vfy_values_get(&row->values, c->value), 0.0,
                           c->tol + vfy_values_get(&row->values, c->plus));
}

/* Paper A's gases: the bulk velocity is exactly N(0, (T0 + 2 beta t)/n) per
 * component (check_gaussian_momentum); its max |z| becomes value out. */
static vfy_verdict hard_rule_gaussian_V(vfy_report *r, const char *name, vfy_case_run *run,
                                        vfy_row *row, const vfy_check_spec *c)
{
    (void)run;
    const size_t M = row->res.outputs;
    const ref_heated_params p = vfy_heated_params(&row->scene);
    double *sigma2 = malloc(M * sizeof *sigma2), z = NAN;
    if (sigma2 == NULL)
        return vfy_check_true(r, name, 0, "out of memory");
    for (size_t m = 0; m < M; m++)
        sigma2[m] = (p.T0 + 2.0 * p.beta * row->res.t[m]) / (double)row->res.n;
    vfy_verdict v = check_gaussian_momentum(r, name, &row->res, sigma2, &z);
    vfy_values_set(&row->values, c->out, z);
    free(sigma2);
    return v;
}

/* Paper B: E u_n(t) = u(t) exactly for every n (background.h): the three
 * components at every output time in one z-test; max |z| into value out. */
static vfy_verdict hard_rule_u_exact(vfy_report *r, const char *name, vfy_case_run *run,
                                     vfy_row *row, const vfy_check_spec *c)
{
    (void)run;
    static const char *const obs[] = {"ux", "uy", "uz"}, *const ref[] = {"ux_exact", "uy_exact",
                                                                       "uz_exact"};
    const size_t M = row->res.outputs;
    double *buf = malloc(9 * M * sizeof *buf), z = NAN;
    vfy_verdict v;
    if (buf == NULL)
        return vfy_check_true(r, name, 0, "out of memory");
    double *mean = buf, *ci = buf + 3 * M, *exact = buf + 6 * M;
    int ok = 1;
    for (int k = 0; k < 3; k++)
        ok &= vfy_row_series(row, obs[k], mean + k * M, ci + k * M) == 0
              && vfy_row_series(row, ref[k], exact + k * M, NULL) == 0;
    if (ok)
        v = vfy_check_zscore(r, name, mean, ci, exact, 3 * M,
                             vfy_zmax_ensembles(VFY_TOL_ZMAX, row->res.ensembles), &z);
    else
        v = vfy_check_true(r, name, 0, "no u or u_exact series in this row");
    vfy_values_set(&row->values, c->out, z);
    free(buf);
    return v;
}

/* Guards on the row's gas: Maxwell molecules (exponent 0) or hard spheres;
 * with or without a background; with series a. */
static int is_maxwell(const vfy_row *row) { return row->scene.collisions.exponent == 0.0; }
static vfy_guard_result only_maxwell(const vfy_case_run *run, const vfy_row *row,
                                     const vfy_guard *g)
{
    (void)run;
    double *buf = g->a ? malloc(row->res.outputs * sizeof *buf) : NULL;
    int has = g->a == NULL || (buf && vfy_row_series(row, g->a, buf, NULL) == 0);
    free(buf);
    return is_maxwell(row) && has ? VFY_JUDGE : VFY_OMIT;
}
static vfy_guard_result only_hard_spheres(const vfy_case_run *run, const vfy_row *row,
                                          const vfy_guard *g)
{
    (void)run;
    (void)g;
    return is_maxwell(row) ? VFY_OMIT : VFY_JUDGE;
}
static vfy_guard_result only_with_series(const vfy_case_run *run, const vfy_row *row,
                                         const vfy_guard *g)
{
    (void)run;
    double *buf = malloc(row->res.outputs * sizeof *buf);
    int has = buf && vfy_row_series(row, g->a, buf, NULL) == 0;
    free(buf);
    return has ? VFY_JUDGE : VFY_OMIT;
}
static vfy_guard_result only_background(const vfy_case_run *run, const vfy_row *row,
                                        const vfy_guard *g)
{
    (void)run;
    return row->scene.background.present == (g->x != 0.0) ? VFY_JUDGE : VFY_OMIT;
}

/* A row's quantities for the metrics (m->x selects one). */
enum { Q_ALPHA, Q_BALANCE, Q_BALANCE_CI, Q_BALANCE_TOL, Q_GAP_CI, Q_P_TAIL, Q_P_TAIL_CI,
       Q_P_TAIL_SONINE, Q_P_TAIL_MAXWELL, Q_TAIL_RATIO, Q_TAIL_LOWER, Q_DELTA, Q_RATIO0,
       Q_RATIO0_CI, Q_UPDATES, Q_MAX_V, Q_V_BOUND, Q_ENERGY_BOUND, Q_T_END_OVER_T0,
       Q_VIOLATIONS_HS, Q_PER_SYSTEM, Q_T_END, Q_K_T_END, Q_F_SONINE, Q_T_FINAL, Q_T_FINAL_CI,
       Q_T_REF, Q_SONINE_TOL };

/* The steady tail beyond TAIL_C (hard-tails): the histogram's probability
 * and half-width, the first Sonine approximation's with a2 of (C.10) and the
 * Maxwellian's, over the same shells. */
static double tail_quantity(const vfy_row *row, int which)
{
    const sim_scene *s = &row->solver;
    if (s->steady.bins == 0)
        return NAN;
    const double delta = s->steady.c_max / (double)s->steady.bins;
    const size_t k0 = (size_t)ceil(VFY_TOL_HARD_TAIL_C / delta - 1e-9);
    const double a2 = vfy_values_get(&row->values, "a2_C10");
    double ci, p = shells_probability(s, &row->res, k0, s->steady.bins, &ci);
    const double sonine = tail_probability((double)k0 * delta, a2)
                          - tail_probability(s->steady.c_max, a2);
    switch (which) {
    case Q_P_TAIL:
        return p;
    case Q_P_TAIL_CI:
        return ci;
    case Q_P_TAIL_SONINE:
        return sonine;
    case Q_P_TAIL_MAXWELL:
        return tail_probability((double)k0 * delta, 0.0) - tail_probability(s->steady.c_max, 0.0);
    case Q_TAIL_RATIO:
        return p / sonine;
    default:
        return 1.0 - ci / sonine;
    }
}

/* Near v = 0 (hard-nongaussian): f/phi averaged over the lowest shell, and
 * its half-width. */
static double rest_quantity(const vfy_row *row, int which)
{
    const sim_scene *s = &row->solver;
    const double delta = s->steady.c_max / (double)s->steady.bins;
    double p_ci, p0 = shells_probability(s, &row->res, 0, 1, &p_ci);
    const double phi0 = 1.0 - tail_probability(delta, 0.0);
    return which == Q_DELTA ? delta : which == Q_RATIO0 ? p0 / phi0 : p_ci / phi0;
}

/* Long runs: the Maxwell gas's decay rate k = gamma pi C (1 - alpha^2). */
static double decay_rate(const sim_scene *s)
{
    const double a = s->collisions.restitution;
    return s->collisions.rate * M_PI * s->collisions.constant * (1.0 - a * a);
}

/* The row's final T and its reference (hard-extreme): the exact finite-n
 * expectation (Maxwell), or (1 - 1/n) times the first-Sonine closure from the
 * same T0 (hard spheres), with the closure's tolerance. */
static double final_quantity(const vfy_row *row, int which)
{
    const size_t M = row->res.outputs;
    double *buf = malloc(2 * M * sizeof *buf), v = NAN;
    if (buf == NULL || M == 0) {
        free(buf);
        return NAN;
    }
    vfy_row_series(row, "T", buf, buf + M);
    const double T_end = buf[M - 1], T_ci = buf[2 * M - 1], n = (double)row->res.n;
    double T_ref = NAN;
    if (is_maxwell(row) && vfy_row_series(row, "T_finite_n", buf, NULL) == 0)
        T_ref = buf[M - 1];
    else if (!is_maxwell(row) && vfy_row_series(row, "T_sonine_closure", buf, NULL) == 0)
        T_ref = (1.0 - 1.0 / n) * buf[M - 1];
    free(buf);
    switch (which) {
    case Q_T_FINAL:
        v = T_end;
        break;
    case Q_T_FINAL_CI:
        v = T_ci;
        break;
    case Q_T_REF:
        v = T_ref;
        break;
    default:   /* the closure's tolerance: T_end_ci + (model error + 2/n) T_ref */
        v = T_ci + (VFY_TOL_SONINE_MODEL_RTOL + VFY_TOL_HARD_FINITE_N_BIAS / n) * T_ref;
    }
    return v;
}

static double hard_metric(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    const int which = (int)m->x;
    const vfy_values *v = &row->values;
    vfy_hard_summary sum;
    vfy_hard_summarize(&row->res, 1.0, &sum);
    const double N = (double)row->res.ensembles;
    double ci;
    switch (which) {
    case Q_ALPHA:
        return row->scene.collisions.restitution;
    case Q_BALANCE:
    case Q_BALANCE_CI: {
        const double b = vfy_energy_balance(&row->scene, &row->solver, &row->res, &ci);
        return which == Q_BALANCE ? b : ci;
    }
    case Q_BALANCE_TOL:
        vfy_energy_balance(&row->scene, &row->solver, &row->res, &ci);
        return ci + VFY_TOL_HARD_BALANCE_BIAS / (double)row->res.n;
    case Q_GAP_CI: /* mu4 and the relation named m->a: their relative half-widths */ {
        char name[48];
        snprintf(name, sizeof name, "%s_ci", m->a);
        return vfy_values_get(v, "mu4_ci") / vfy_values_get(v, "mu4")
               + vfy_values_get(v, name) / vfy_values_get(v, m->a);
    }
    case Q_P_TAIL:
    case Q_P_TAIL_CI:
    case Q_P_TAIL_SONINE:
    case Q_P_TAIL_MAXWELL:
    case Q_TAIL_RATIO:
    case Q_TAIL_LOWER:
        return tail_quantity(row, which);
    case Q_DELTA:
    case Q_RATIO0:
    case Q_RATIO0_CI:
        return rest_quantity(row, which);
    case Q_UPDATES: { /* paper C Eq. (62): n per step plus each collision */
        const double h = vfy_scene_step(&row->solver);
        const double steps = h > 0.0 ? row->solver.t_end / h : 0.0;
        return (double)row->res.counts.collisions / N + (double)row->res.n * steps;
    }
    case Q_MAX_V:
        return sum.momentum;
    case Q_V_BOUND:
        return vfy_hard_momentum_bound(&sum, vfy_values_get(v, m->a));
    case Q_ENERGY_BOUND:
        return is_maxwell(row) ? NAN : vfy_hard_energy_bound(&sum, vfy_values_get(v, m->a));
    case Q_T_END_OVER_T0:
        return sum.T_last / sum.T_first;
    case Q_VIOLATIONS_HS:
        return is_maxwell(row) ? NAN : (double)sum.violations;
    case Q_PER_SYSTEM:
        return vfy_values_get(v, m->a) / N;
    case Q_T_END:
        return row->scene.t_end;
    case Q_K_T_END:
        return decay_rate(&row->scene) * row->scene.t_end;
    case Q_F_SONINE:   /* the first Sonine f/phi at c = 0: 1 + a2 S2(0) */
        return 1.0 + 15.0 / 8.0 * vfy_values_get(v, "a2");
    default:
        return final_quantity(row, which);
    }
}
#define HARD_METRIC(NAME, WHICH) {NAME, hard_metric, NULL, NULL, WHICH}

/* What each case needs of its scene (vfy_scene_requires): every hard case
 * paper A's units. */
#define HARD_UNIT_MASS "grain_mass=1"
#define HARD_UNIT_MASS_WHY "the hard cases use unit grain mass (paper A's units)"
#define HARD_REQUIRE(WORDS, WHY)                                                        \
    .require = HARD_UNIT_MASS " " WORDS, .require_why = HARD_UNIT_MASS_WHY "; this one " WHY
#define WHITE_REQUIRE                                                                   \
    HARD_REQUIRE("[heating] heating.type=white-noise [steady] steady.pairs>0",         \
                 "needs white-noise [heating] and [steady] with pairs")

/* The notes' frame: provenance first, wall time last. */
#define HARD_NOTES(TEXT) "{comment}.\n\n" TEXT " Total wall time {wall_total:%.1f} s."
#define HARD_TITLE(WHAT) "{case}: " WHAT " ({size} sizes)"

/* ------------------------------------------- hard-dissipation, hard-tails */

/* 2 beta = the first-Sonine loss at T0, so that the steady T is about T0. */
#define HARD_DERIVED "heating.strength=heating_strength_T0"

static const char *const white_values[] = {"a2_C10", NULL};
#define WHITE_METRICS                                                                  \
    HARD_METRIC("balance", Q_BALANCE), HARD_METRIC("balance_ci", Q_BALANCE_CI),         \
        HARD_METRIC("balance_tol", Q_BALANCE_TOL),                                     \
        {"gap_ci", hard_metric, "mu4_white", NULL, Q_GAP_CI},                          \
        {"beta", vfy_metric_heating_strength, NULL, NULL, 0},                          \
        {"fictitious_fraction", vfy_metric_fictitious_fraction, NULL, NULL, 0}
static const vfy_metric dissipation_metrics[] = {WHITE_METRICS, {NULL, NULL, NULL, NULL, 0}};
static const vfy_metric tails_metrics[] = {
    WHITE_METRICS, HARD_METRIC("P_tail", Q_P_TAIL), HARD_METRIC("P_tail_ci", Q_P_TAIL_CI),
    HARD_METRIC("P_tail_sonine", Q_P_TAIL_SONINE),
    HARD_METRIC("P_tail_maxwell", Q_P_TAIL_MAXWELL), HARD_METRIC("tail_ratio", Q_TAIL_RATIO),
    HARD_METRIC("tail_lower", Q_TAIL_LOWER), {NULL, NULL, NULL, NULL, 0}};

#define WHITE_LABEL "{case} alpha={alpha:%g}"
/* Steady a2 against (C.10), the Sonine estimate's own error plus the
 * half-width; paper C Eq. (23) mu4 = (d + 2) mu2 exactly (direct against
 * indirect); the exact energy balance within half-widths and 3/n. */
#define WHITE_CHECKS                                                                   \
    {.name = WHITE_LABEL " a2 vs Sonine (C.10)", .rule = vfy_rule_absolute, .value = "a2", \
     .expected = "a2_C10", .tol = VFY_TOL_HARD_A2_WHITE, .plus = "a2_ci"},             \
        {.name = WHITE_LABEL " mu4 vs 5 mu2 (C Eq. 23)", .rule = hard_rule_rel,        \
         .value = "mu4", .expected = "mu4_white", .tol = VFY_TOL_MS_MU4_GAP_RTOL,      \
         .plus = "gap_ci"},                                                            \
        {.name = WHITE_LABEL " energy balance 2 beta = loss (exact)", .rule = hard_rule_rel, \
         .value = "balance", .x = 1.0, .plus = "balance_tol"}
#define WHITE_TAIL_CHECKS                                                              \
    HARD_CHECK(WHITE_LABEL, HARD_VIOLATIONS, NULL), HARD_CHECK(WHITE_LABEL, HARD_FINITE, NULL), \
        {.name = NULL}
static const vfy_check_spec dissipation_checks[] = {WHITE_CHECKS, WHITE_TAIL_CHECKS};
/* Paper A Ex 7, docs/theory.md §11.5: the overpopulated tail exp(-A c^{3/2}) is fatter
 * than the first Sonine approximation's Maxwellian times a polynomial, so
 * beyond c = 3 the population must reach at least the latter's (with the
 * reference's a2 of (C.10)), up to its half-width; a Maxwellian tail (0.37
 * of it here) or one cut short by a stale majorant falls below. */
static const vfy_check_spec tails_checks[] = {
    WHITE_CHECKS,
    {.name = WHITE_LABEL " tail P(c >= 3) / first-Sonine value", .rule = hard_rule_at_least,
     .value = "tail_ratio", .expected = "tail_lower"},
    WHITE_TAIL_CHECKS};
#define WHITE_COLUMNS_HEAD                                                                   \
    "alpha:%g n:%.0f N:%.0f beta:%.5g T:%.5f T_ci:%.5f a2:%.5f a2_ci:%.5f a2_C10:%.5f mu2:%.5f " \
    "mu4:%.5f mu4_white:%.5f balance:%.5f balance_tol:%.5f "
#define WHITE_COLUMNS_TAIL "fictitious_fraction:%.3f violations:%.0f " VFY_COST_COLUMNS
static const char dissipation_columns[] = WHITE_COLUMNS_HEAD WHITE_COLUMNS_TAIL;
static const char tails_columns[] = WHITE_COLUMNS_HEAD
    "P_tail:%.4g P_tail_ci:%.2g P_tail_sonine:%.4g P_tail_maxwell:%.4g " WHITE_COLUMNS_TAIL;
#define WHITE_NOTES                                                                    \
    "Steady state of white-noise heated hard spheres, exact jump scheme (time averages " \
    "per ensemble over the output times t >= steady.from; half-widths 3.2 sigma over the " \
    "ensembles). a2_C10: the Sonine estimate (paper C Eq. 10), allowed 0.006 + a2_ci. mu4 " \
    "(pair sampling) against mu4_white = 5 mu2, paper C's exact steady relation (Eq. 23), " \
    "within 0.2% plus half-widths. balance = gamma pi C (1 - alpha^2) <|g|^3>/6 over 2 "  \
    "beta, with <|g|^3> = 8 mu2 v0^3/(pi (1 - alpha^2)): exactly 1 in the steady state of " \
    "the n-particle process, allowed balance_tol = half-widths + 3/n."
#define WHITE_PROGRESS                                                                 \
    WHITE_LABEL ": T = {T:%.5f}, a2 = {a2:%.5f} ± {a2_ci:%.5f} (C.10 {a2_C10:%.5f}), "   \
                "balance {balance:%.5f}"

/* alpha = 0.05, 0.1; quick: n = 4000, N = 16, 20 mean free times of
 * relaxation, 40 samples one mean free time apart, 4000 pairs per sample. */
#define STEADY_QUICK_SETS                                                              \
    "particles.n=4000;particles.ensembles=16;scene.outputs=61;steady.pairs=4000;"       \
    "scene.t_end=30;steady.from=10"
const vfy_case_desc vfy_hard_dissipation = {
    .must_fail = "heating.strength=1.05",
    .power_keys = "collisions.restitution=0.9",
    .paper_rows = {.keys = VFY_KEYS({"collisions.restitution", "0.05 0.1", "alpha"})},
    .quick_rows = {.keys = VFY_KEYS({"collisions.restitution", "0.05 0.1", "alpha"}),
                   .sets = STEADY_QUICK_SETS},
    .label = WHITE_LABEL, .row_progress = WHITE_PROGRESS, .derived = HARD_DERIVED,
    WHITE_REQUIRE, .values = white_values, .metrics = dissipation_metrics,
    .checks = dissipation_checks, .columns = dissipation_columns,
    .title = HARD_TITLE("very strong dissipation, white-noise heated hard spheres"),
    .notes = HARD_NOTES(WHITE_NOTES " beta is set so that the first-Sonine steady T is "
                                    "T0 = 1.")};

/* The scene's own alpha = 0.1, beta = 30; quick: n = 2000, N = 16, 4000
 * pairs (t in [0, 1], samples t >= 0.25). */
const vfy_case_desc vfy_hard_tails = {
    .must_fail = "heating.strength=1.05",
    .paper_rows = {.keys = VFY_KEYS({"collisions.restitution", "0.1", "alpha"})},
    .quick_rows = {.keys = VFY_KEYS({"collisions.restitution", "0.1", "alpha"}),
                   .sets = "particles.n=2000;particles.ensembles=16;steady.pairs=4000"},
    .label = WHITE_LABEL, .row_progress = WHITE_PROGRESS, WHITE_REQUIRE,
    .values = white_values, .metrics = tails_metrics, .checks = tails_checks,
    .columns = tails_columns,
    .title = HARD_TITLE("paper A Ex 7, growing majorant and overpopulated tail"),
    .notes = HARD_NOTES(
        "Paper A Ex 7 (docs/theory.md §11.5): hard spheres, alpha = 0.1, beta = 30, gamma = 16, C = 1/(4 "
        "pi), T0 = 1, heated to T about 3: the majorant U_max grows and the tail fills (f ~ "
        "exp(-A c^{{3/2})). " WHITE_NOTES " P_tail: the steady probability of c >= 3 (reduced "
        "speed) from the shells of the histogram (to c = {steady.c_max:%g}), against the first "
        "Sonine approximation with a2 of (C.10) (P_tail_sonine) and the Maxwellian "
        "(P_tail_maxwell); the tail must reach at least P_tail_sonine - P_tail_ci.")};

/* ------------------------------------------------------- hard-nongaussian */

static const char *const nongaussian_values[] = {"a2_C76", NULL};
static const vfy_metric nongaussian_metrics[] = {
    {"g", vfy_metric_heating_strength, NULL, NULL, 0},
    {"h", vfy_metric_time_step, NULL, NULL, 0},
    {"gap_ci", hard_metric, "mu4_nongaussian", NULL, Q_GAP_CI},
    HARD_METRIC("delta", Q_DELTA), HARD_METRIC("f_over_phi_0", Q_RATIO0),
    HARD_METRIC("f_over_phi_0_ci", Q_RATIO0_CI), HARD_METRIC("updates", Q_UPDATES),
    HARD_METRIC("max_V", Q_MAX_V), {"V_bound", hard_metric, "updates", NULL, Q_V_BOUND},
    HARD_METRIC("f_over_phi_sonine", Q_F_SONINE),
    HARD_METRIC("balance", Q_BALANCE), HARD_METRIC("balance_tol", Q_BALANCE_TOL),
    {NULL, NULL, NULL, NULL, 0}};
/* Paper C Fig. 8: (C.76) is semi-empirical, "fairly good agreement"; Eq.
 * (44), exact in the steady state; near v = 0 (paper C §4.3, Fig. 9):
 * Delta(0) is about -1/a2, "an almost vanishing population of rest
 * particles", while the first Sonine approximation gives f/phi = 1 + 15 a2/8
 * (0.78 here); Eq. (62): the thermostat keeps the total momentum, and so do
 * the collisions. */
static const vfy_check_spec nongaussian_checks[] = {
    {.name = WHITE_LABEL " a2 vs Sonine (C.76)", .rule = hard_rule_rel, .value = "a2",
     .expected = "a2_C76", .tol = VFY_TOL_MS_A2_NG_RTOL},
    {.name = WHITE_LABEL " mu4 vs 2 mu2 <c^3>/<c> (C Eq. 44)", .rule = hard_rule_rel,
     .value = "mu4", .expected = "mu4_nongaussian", .tol = VFY_TOL_MS_MU4_GAP_RTOL,
     .plus = "gap_ci"},
    {.name = WHITE_LABEL " f/phi near v = 0 (depleted, C §4.3)", .rule = hard_rule_at_most,
     .value = "f_over_phi_0", .tol = VFY_TOL_HARD_DEPLETED, .plus = "f_over_phi_0_ci"},
    /* the exact steady energy balance, (2/3) g <|v|> = loss, plus the time step's
     * splitting error */
    {.name = WHITE_LABEL " energy balance (2/3) g <|v|> = loss (exact)", .rule = hard_rule_rel,
     .value = "balance", .x = 1.0, .tol = VFY_TOL_MS_BALANCE_RTOL, .plus = "balance_tol"},
    HARD_ROUNDOFF_CHECK(WHITE_LABEL, HARD_MOMENTUM, "updates"),
    HARD_CHECK(WHITE_LABEL, HARD_VIOLATIONS, NULL), HARD_CHECK(WHITE_LABEL, HARD_FINITE, NULL),
    {.name = NULL}};
static const char nongaussian_columns[] =
    "alpha:%g n:%.0f N:%.0f g:%.5g h:%g T:%.5f a2:%.5f a2_ci:%.5f a2_C76:%.5f mu4:%.5f "
    "mu4_nongaussian:%.5f f_over_phi_0:%.4f f_over_phi_0_ci:%.4f f_over_phi_sonine:%.4f "
    "balance:%.5f balance_tol:%.5f max_V:%.3g V_bound:%.3g violations:%.0f "
    VFY_COST_COLUMNS;
const vfy_case_desc vfy_hard_nongaussian = {
    .must_fail = "heating.strength=1.05",
    .power_keys = "collisions.restitution=0.9",
    .paper_rows = {.keys = VFY_KEYS({"collisions.restitution", "0.05 0.1", "alpha"})},
    .quick_rows = {.keys = VFY_KEYS({"collisions.restitution", "0.05 0.1", "alpha"}),
                   .sets = STEADY_QUICK_SETS},
    .label = WHITE_LABEL,
    .row_progress = WHITE_LABEL ": a2 = {a2:%.5f} (C.76 {a2_C76:%.5f}), f/phi(c < {delta:%g}) "
                                "= {f_over_phi_0:%.3f}, max |V| {max_V:%.3g}",
    .derived = HARD_DERIVED,
    HARD_REQUIRE("[steady] steady.pairs>0 steady.bins>0 scene.scheme=timestep "
                 "particles.zero_momentum=true",
                 "needs scheme = timestep, zero_momentum and [steady] with pairs and bins"), .values = nongaussian_values,
    .metrics = nongaussian_metrics, .checks = nongaussian_checks,
    .columns = nongaussian_columns,
    .title = HARD_TITLE("paper C's non-Gaussian thermostat near v = 0"),
    .notes = HARD_NOTES(
        "Steady state under F = m g v/|v| (paper C Eq. 14; the time-step scheme with paper "
        "C's momentum-keeping increment w_i = g h (v_i/|v_i| - k), Eq. 62), time averages per "
        "ensemble over t >= steady.from. a2 against the semi-empirical (C.76), allowed 25%. "
        "mu4 (pair sampling) against mu4_nongaussian = 2 mu2 <c^3>/<c>, the exact steady "
        "relation (Eq. 44), within 0.2% plus half-widths. f_over_phi_0: the reduced "
        "distribution over the Maxwellian, averaged over the lowest shell of the histogram, "
        "with its half-width; paper C §4.3: about 0 (an almost vanishing population of rest "
        "particles), while the first Sonine approximation gives 1 + 15 a2/8 "
        "(f_over_phi_sonine); allowed at most 0.5. max_V: an upper bound on |V_k| over "
        "ensembles and times (sqrt(N (var + mean^2))) after zero_momentum, against the "
        "round-off bound V_bound (verify/cases/case_hard.h). balance: the collisional loss over the "
        "thermostat's input (2/3) g <|v|>, 1 in the steady state (exact), judged within "
        "balance_tol (half-widths and 3/n) plus 0.2% for the time step.")};

/* --------------------------------------------------------------- hard-tiny */

/* Three gases (paper A Ex 3, paper B Ex 2, paper A Ex 5) at n = 2, 3, 4,
 * 41 output times, N = 2x10^4 (quick) or 10^6 (paper) ensembles; observed as
 * the papers do (sampled: the distribution of V and every moment are judged,
 * which the scenes' conditional observation does not give). */
#define TINY_ROW(GAS, N)                                                             \
    GAS " n=" #N ": scene=" GAS ";particles.n=" #N ";scene.observation=sampled;$gas=" GAS
#define TINY_GAS(GAS) TINY_ROW(GAS, 2), TINY_ROW(GAS, 3), TINY_ROW(GAS, 4)
static const char *const tiny_rows[] = {TINY_GAS("grw-ex3"), TINY_GAS("brs-ex2"),
                                        TINY_GAS("grw-ex5"), NULL};
static const char *const all_references[] = {NULL};   /* every row's, none required */
#define TINY_LABEL "{case} {gas} n={n}"
static const vfy_check_spec tiny_checks[] = {
    /* the exact expectation of the n-particle T (docs/theory.md §11.2) */
    {.name = TINY_LABEL " T vs exact finite-n expectation", .rule = vfy_rule_zscore,
     .value = "T", .expected = "T_finite_n", .from = 1, .tol = VFY_TOL_ZMAX, .out = "z_T",
     .guard = {only_maxwell, "T_finite_n", NULL, 0, NULL}},
    {.name = TINY_LABEL " T_raw vs exact finite-n expectation", .rule = vfy_rule_zscore,
     .value = "T_raw", .expected = "T_raw_finite_n", .from = 1, .tol = VFY_TOL_ZMAX,
     .out = "z_T_raw", .guard = {only_with_series, "T_raw_finite_n", NULL, 0, NULL}},
    {.name = TINY_LABEL " u vs exact expectation", .rule = hard_rule_u_exact, .out = "z_u",
     .guard = {only_background, NULL, NULL, 1, NULL}},
    {.name = TINY_LABEL " V Gaussian, variance (T0 + 2 beta t)/n",
     .rule = hard_rule_gaussian_V, .out = "z_V2", .guard = {only_background, NULL, NULL, 0, NULL}},
    {.name = TINY_LABEL, .rule = hard_rule, .x = HARD_VIOLATIONS,
     .guard = {only_hard_spheres, NULL, NULL, 0, NULL}},
    HARD_CHECK(TINY_LABEL, HARD_FINITE, NULL),
    {.name = NULL}};
static const vfy_metric tiny_metrics[] = {HARD_METRIC("violations_hs", Q_VIOLATIONS_HS),
                                          {NULL, NULL, NULL, NULL, 0}};
static const char tiny_columns[] =
    "gas:%s n:%.0f N:%.0f z_T:%.2f z_T_raw:%.2f z_u:%.2f z_V2:%.2f "
    "violations=violations_hs:%.0f "
    VFY_COST_COLUMNS;
const vfy_case_desc vfy_hard_tiny = {
    .must_fail = "collisions.constant=1.05",
    .paper_rows = {.rows = tiny_rows, .sets = "particles.ensembles=1000000;scene.outputs=41"},
    .quick_rows = {.rows = tiny_rows, .sets = "particles.ensembles=20000;scene.outputs=41"},
    .label = "{case} {gas} n={n}", .needs = all_references, .require = HARD_UNIT_MASS,
    .require_why = HARD_UNIT_MASS_WHY,
    .metrics = tiny_metrics, .checks = tiny_checks, .columns = tiny_columns,
    .title = HARD_TITLE("tiny systems, n = 2, 3, 4"),
    .notes = HARD_NOTES(
        "Paper A Ex 3's heated Maxwell gas (grw-ex3), paper B Ex 2's Maxwell gas in a host "
        "medium (brs-ex2) and paper A Ex 5's heated hard spheres (grw-ex5), each at n = 2, 3, "
        "4 with 41 output times. z_T, z_T_raw: max |z| over the output times t > 0 of the "
        "ensemble mean against the exact expectation of the n-particle estimator (docs/theory.md §11.2); "
        "z_u: of u against paper B's exact u(t) = E u_n(t). z_V2: the bulk velocity of paper "
        "A's gases is exactly N(0, (T0 + 2 beta t)/n) per component (collisions conserve it, "
        "the heating adds independent Gaussian increments), whatever the kernel: (1/N) Σ_j "
        "V_k^2 against its expectation, standard deviation (T0 + 2 beta t)/n sqrt(2/N). "
        "Allowed |z| <= 4.5.")};

/* ----------------------------------------------------------- hard-long-run */

/* Elastic hard spheres: collisions per candidate event, about 1/4 to 1/5
 * for n = 1000 (the majorant's acceptance); the row runs E/5 collisions. */
#define HS_COLLISIONS_PER_EVENT 0.2

/* E candidate events per system ($events: 10^9 paper, 10^7 quick).  Maxwell:
 * E events in t_end, alpha with k t_end = 4.  Elastic hard spheres: the gas
 * stays Maxwellian at T0, n(n-1)/2 pairs at the rate 4 pi gamma C <|g|>/n,
 * <|g|> = 4 sqrt(T0/(pi m)): prefactor 4 sqrt(T0/pi) collisions per unit
 * time, E/5 of them. */
static const char *long_run_times(const vfy_row *row, char *buf, size_t len)
{
    const sim_scene *s = &row->scene;
    const double E = vfy_values_get(&row->values, "events");
    const double prefactor = 2.0 * M_PI * s->collisions.rate * s->collisions.constant
                             * ((double)s->particles.n - 1.0);
    const double T0 = s->particles.maxwellian.temperature;
    if (s->collisions.kernel == SIM_KERNEL_HARD_SPHERES) {
        snprintf(buf, len, "scene.t_end=%.17g",
                 HS_COLLISIONS_PER_EVENT * E / (prefactor * 4.0 * sqrt(T0 / M_PI)));
    } else {
        const double t_end = E / prefactor;
        const double one_minus_a2 = 4.0 / (s->collisions.rate * M_PI * s->collisions.constant
                                           * t_end);
        snprintf(buf, len, "scene.t_end=%.17g;collisions.restitution=%.17g", t_end,
                 sqrt(1.0 - one_minus_a2));
    }
    return buf;
}

/* Maxwell molecules without heating: E[X(t) | X(0)] = X(0) e^{-kt} exactly,
 * X = Σ|v_i - V|^2 (dE X/dt = -k X: the loss is (1 - alpha^2)/4 |g|^2 at rate
 * 4 pi gamma C/n per pair and Σ_{i<j} |g_ij|^2 = n X), so the ensemble mean
 * of T(t) must be mean T(0) e^{-kt}.  Its noise: the losses are a compound
 * Poisson sum, (1 - alpha^2)/4 (1 - mu) |g|^2 per collision with E[(1 -
 * mu)^2] = 4/3 and E|g|^4 = 60 T^2 (Maxwellian), so after E events X(t)
 * e^{kt}/X(0) - 1 has standard deviation (1 - alpha^2) sqrt(80 E)/(12 n) per
 * system.  max |z| into value out. */
static vfy_verdict long_run_rule_decay(vfy_report *r, const char *name, vfy_case_run *run,
                                       vfy_row *row, const vfy_check_spec *c)
{
    (void)run;
    const sim_ensemble_result *res = &row->res;
    const sim_scene *s = &row->scene;
    const size_t M = res->outputs;
    const double n = (double)s->particles.n, alpha = s->collisions.restitution;
    const double prefactor = 2.0 * M_PI * s->collisions.rate * s->collisions.constant * (n - 1.0);
    double *buf = malloc(3 * M * sizeof *buf), z = NAN;
    if (buf == NULL)
        return vfy_check_true(r, name, 0, "out of memory");
    double *mean = buf, *ci = buf + M, *exact = buf + 2 * M;
    vfy_result_column(res, SIM_OBS_T, mean, NULL);
    for (size_t m = 0; m < M; m++) {
        const double events = prefactor * res->t[m];
        const double sd = (1.0 - alpha * alpha) * sqrt(80.0 * events) / (12.0 * n);
        exact[m] = mean[0] * exp(-decay_rate(s) * res->t[m]);
        ci[m] = SIM_LAMBDA_P * sd * exact[m] / sqrt((double)res->ensembles);
    }
    vfy_verdict v = vfy_check_zscore(r, name, mean, ci, exact, M, VFY_TOL_ZMAX, &z);
    vfy_values_set(&row->values, c->out, z);
    free(buf);
    return v;
}

static const char *const long_run_rows[] = {
    "maxwell: $row=maxwell",
    "elastic-hard-spheres: $row=elastic-hard-spheres;collisions.kernel=hard-spheres;"
    "collisions.restitution=1",
    NULL};
#define LONG_LABEL "{case} {row}"
static const vfy_check_spec long_run_checks[] = {
    {.name = LONG_LABEL " T(t) vs T(0) e^{{-kt} (exact)", .rule = long_run_rule_decay,
     .out = "z_T", .guard = {only_maxwell, NULL, NULL, 0, NULL}},
    {.name = LONG_LABEL, .rule = hard_rule, .x = HARD_COOLING,
     .guard = {only_maxwell, NULL, NULL, 0, NULL}},
    {.name = LONG_LABEL, .rule = hard_rule, .x = HARD_ENERGY,
     .value = "collisions_per_system", .guard = {only_hard_spheres, NULL, NULL, 0, NULL},
     .builtin_only = "its round-off bound models this engine's own arithmetic"},
    {.name = LONG_LABEL, .rule = hard_rule, .x = HARD_VIOLATIONS,
     .guard = {only_hard_spheres, NULL, NULL, 0, NULL}},
    HARD_ROUNDOFF_CHECK(LONG_LABEL, HARD_MOMENTUM, "collisions_per_system"),
    HARD_CHECK(LONG_LABEL, HARD_FINITE, NULL),
    {.name = NULL}};
static const vfy_metric long_run_metrics[] = {
    {"events_per_system", hard_metric, "events", NULL, Q_PER_SYSTEM},
    {"collisions_per_system", hard_metric, "collisions", NULL, Q_PER_SYSTEM},
    HARD_METRIC("alpha", Q_ALPHA), HARD_METRIC("t_end", Q_T_END),
    HARD_METRIC("k_t_end", Q_K_T_END), HARD_METRIC("T_end_over_T0", Q_T_END_OVER_T0),
    HARD_METRIC("max_V", Q_MAX_V),
    {"V_bound", hard_metric, "collisions_per_system", NULL, Q_V_BOUND},
    {"energy_bound", hard_metric, "collisions_per_system", NULL, Q_ENERGY_BOUND},
    HARD_METRIC("violations_hs", Q_VIOLATIONS_HS), {NULL, NULL, NULL, NULL, 0}};
static const char long_run_columns[] =
    "row:%s n:%.0f N:%.0f alpha:%.9g t_end:%.6g events_per_system:%.4g "
    "collisions_per_system:%.4g k_t_end:%.4g T_end_over_T0:%.6g z_T:%.2f max_V:%.3g "
    "V_bound:%.3g energy_bound:%.3g violations=violations_hs:%.0f "
    VFY_COST_COLUMNS;
const vfy_case_desc vfy_hard_long_run = {
    .must_fail = "collisions.constant=1.05",
    .paper_rows = {.rows = long_run_rows, .sets = "$events=1e9"},
    .quick_rows = {.rows = long_run_rows, .sets = "$events=1e7"},
    .label = LONG_LABEL, .derive = long_run_times,
    HARD_REQUIRE("![heating] ![background] [collisions] particles.zero_momentum=true",
                 "needs [collisions] only and zero_momentum"),
    .row_progress = LONG_LABEL ": {events_per_system:%.3g} events per system, T(t_end)/T(0) = "
                               "{T_end_over_T0:%.6g}, max |V| {max_V:%.3g}",
    .metrics = long_run_metrics, .checks = long_run_checks, .columns = long_run_columns,
    .title = HARD_TITLE("long runs"),
    .notes = HARD_NOTES(
        "Each system runs its events in one jump-scheme trajectory, initial momentum removed "
        "(zero_momentum). maxwell: Maxwell molecules, no heating, alpha just below 1 so that "
        "k t_end = 4 (k = gamma pi C (1 - alpha^2)); every candidate is a collision. z_T: max "
        "|z| of the ensemble mean of T(t) against mean T(0) e^{{-kt}, exact for Maxwell "
        "molecules without heating, with the standard deviation of the inelastic losses (1 - "
        "alpha^2) sqrt(80 E(t))/(12 n sqrt(N)), E(t) events per system by t. "
        "elastic-hard-spheres: alpha = 1, E/5 collisions per system (about E candidate "
        "events), energy and momentum conserved exactly in real arithmetic, T(t) against T(0) "
        "within energy_bound. max_V: an upper bound on |V_k| of every system at every output "
        "time (sqrt(N (var + mean^2))), against V_bound = 6 u s (sqrt(2 U)/n + 2), U "
        "collisions per system, s the r.m.s. speed (verify/cases/case_hard.h).")};

/* -------------------------------------------------------------- hard-stiff */

/* Paper B's hard-sphere closures, local equilibrium (B.21) and Grad (B.22),
 * with K = (rho/rho_B)^2 C2/C1 = 100 (a fast stiff transient) and 1e-4, and
 * the Maxwell-kernel moment equations (B.13) with Kn = rho C2/(rho_B C1) =
 * 100 and 1e-4 against their closed form (B.15); BDF (the references'
 * default), Adams, and Adams with a step budget too small for K = 100's
 * transient (a real failure, which must come back as a clear message).
 * BDF and Adams without a budget solve every one of these (they must). */
#define STIFF_METHODS(MODEL, NAME, K)                                                   \
    NAME " K=" #K " BDF: $model=" #MODEL ";$model_name=" NAME ";$K=" #K ";$method=0;"       \
         "$method_name=BDF",                                                            \
        NAME " K=" #K " Adams: $model=" #MODEL ";$model_name=" NAME ";$K=" #K ";$method=1;" \
             "$method_name=Adams",                                                      \
        NAME " K=" #K " Adams max_steps: $model=" #MODEL ";$model_name=" NAME ";$K=" #K   \
             ";$method=2;$method_name=Adams max_steps=" TIGHT_STEPS_TEXT
#define STIFF_MODEL(MODEL, NAME) STIFF_METHODS(MODEL, NAME, 100), STIFF_METHODS(MODEL, NAME, 0.0001)
static const char *const stiff_rows[] = {STIFF_MODEL(0, "LE (B.21)"),
                                         STIFF_MODEL(1, "Grad (B.22)"),
                                         STIFF_MODEL(2, "Maxwell (B.13)"), NULL};

/* One CVODE integration of the row's model (vfy_rule_fn): judged by
 * vfy_hard_check_ode; its status, T at t_end, the steady state and the
 * message become the row's values and texts. */
static vfy_verdict stiff_rule(vfy_report *r, const char *name, vfy_case_run *run, vfy_row *row,
                              const vfy_check_spec *c)
{
    (void)run;
    (void)c;
    const sim_scene *s = &row->scene;
    const size_t M = s->outputs;
    const int model = (int)vfy_values_get(&row->values, "model");
    const int method = (int)vfy_values_get(&row->values, "method");
    const double K = vfy_values_get(&row->values, "K");
    double *buf = malloc(6 * M * sizeof *buf);
    if (buf == NULL)
        return vfy_check_true(r, name, 0, "out of memory");
    double *t = buf, *T = buf + M, *Tx = buf + 2 * M, *u = buf + 3 * M;
    for (size_t m = 0; m < M; m++)
        t[m] = sim_scene_output_time(s, m);
    ref_background_params p = vfy_background_params(s);
    ref_ode_options opt = ref_ode_default_options();
    opt.method = method ? REF_ODE_ADAMS : REF_ODE_BDF;
    if (method == 2)
        opt.max_steps = TIGHT_STEPS;
    char emsg[400] = "";
    vfy_hard_ode ode = {.nt = M, .T = T, .u = u, .T_exact = NULL, .T_steady = NAN,
                        .rtol = VFY_TOL_HARD_ODE_RTOL, .must_succeed = method < 2};
    if (model < 2) {
        const ref_background_closure cl = model == 0 ? REF_BACKGROUND_LE : REF_BACKGROUND_GRAD;
        p.C2 = K * p.C1 * p.bg_density * p.bg_density / (p.density * p.density);
        ode.status = ref_background_hs(&p, cl, t, M, &opt, u, T, emsg, sizeof emsg);
        ode.T_steady = ref_background_hs_T_steady(&p, cl);
    } else {
        p.C2 = K * p.C1 * p.bg_density / p.density;
        ode.status = ref_background_maxwell_ode(&p, t, M, &opt, u, T, emsg, sizeof emsg);
        for (size_t m = 0; m < M; m++)
            Tx[m] = ref_background_maxwell_T(&p, t[m]);
        ode.T_exact = Tx;
        ode.T_steady = ref_background_maxwell_T_steady(&p);
    }
    ode.msg = emsg;
    const vfy_verdict v = vfy_hard_check_ode(r, name, &ode);
    const int ok = ode.status == REF_OK;
    vfy_values_set(&row->values, "T_end", ok ? T[M - 1] : NAN);
    vfy_values_set(&row->values, "T_steady", ode.T_steady);
    vfy_values_set(&row->values, "rel_dev", ok ? fabs(T[M - 1] / ode.T_steady - 1.0) : NAN);
    vfy_row_set_text(row, "status", ok ? "ok" : ref_strerror(ode.status));
    vfy_row_set_text(row, "message", csv_safe(emsg));
    free(buf);
    return v;
}
static const vfy_check_spec stiff_checks[] = {
    {.name = "{case} {model_name} K={K} {method_name}", .rule = stiff_rule}, {.name = NULL}};
static const char stiff_columns[] =
    "model=model_name:%s K:%g method=method_name:%s status:%s T_end:%.10g T_steady:%.10g "
    "rel_dev:%.2g message:%s";
const vfy_case_desc vfy_hard_stiff = {
    .paper_rows = {.rows = stiff_rows}, .quick_rows = {.rows = stiff_rows},
    .no_simulation = 1,
    HARD_REQUIRE("[background] background.kernel=hard-spheres", "needs a hard-sphere [background]"),
    .checks = stiff_checks,
    .columns = stiff_columns,
    .title = HARD_TITLE("stiff references through CVODE"),
    .notes = HARD_NOTES(
        "Paper B's hard-sphere closures, local equilibrium (B.21) and Grad (B.22), with K = "
        "100 (strongly inelastic, a fast stiff transient) and K = 1e-4 (almost no inelastic "
        "loss), and the Maxwell-kernel moment equations (B.13) with Kn = 100 and 1e-4 against "
        "their closed form (B.15), integrated with CVODE (rtol 1e-10, atol 1e-12; BDF with "
        "Newton, Adams with fixed-point iteration, and Adams with at most " TIGHT_STEPS_TEXT
        " steps per output interval) on {scene.outputs} output times of [0, {scene.t_end:%g}]. "
        "T_steady: the closure's steady state by GSL's Brent root finder, or (B.18). Verdict: "
        "success with every value finite, T > 0, T(t_end) within 1e-06 of T_steady (and the "
        "whole trajectory within 1e-06 of the closed form); BDF and Adams must succeed, the "
        "budgeted Adams may instead fail cleanly with a message; never garbage.")};

/* ------------------------------------------------------------ hard-extreme */

/* Maxwell rows: paper A Ex 3's heated gas (hard-extreme.ini) at n = 64, N =
 * 4000 (quick) or 40000, 41 outputs.  Hard spheres (paper A Ex 5's gas): n =
 * 256, N = 200 or 2000, t in [0, 6] with 601 outputs, 3001 from T0 = 1e8: the
 * majorant is recomputed from the synchronised system at each output time
 * only, and from T0 = 1e8 (U_max about 8e4, while T falls below 10^6 within
 * t = 0.002) the first interval is nearly all fictitious candidates, about
 * 4e7 (n - 1)/255 per unit time.  The rate = 1e6 row runs the same events as
 * the scene's rate = 4 in t_end scaled by 4/1e6: 8 -> 3.2e-5. */
#define MAXWELL_SIZES(N) "particles.n=64;particles.ensembles=" N ";scene.outputs=41"
#define HS_SIZES(N, M) "particles.n=256;particles.ensembles=" N ";scene.outputs=" M ";scene.t_end=6"
#define EXTREME_ROWS(NM, NH)                                                            \
    {"alpha=1e-3: scene=hard-extreme;collisions.restitution=1e-3;" MAXWELL_SIZES(NM),     \
     "alpha=1: scene=hard-extreme;collisions.restitution=1;" MAXWELL_SIZES(NM),           \
     "rate=1e6: scene=hard-extreme;collisions.rate=1e6;scene.t_end=3.2e-5;"               \
     MAXWELL_SIZES(NM),                                                                  \
     "T0=1e-8: scene=hard-extreme;particles.temperature=1e-8;" MAXWELL_SIZES(NM),         \
     "T0=1e8: scene=hard-extreme;particles.temperature=1e8;" MAXWELL_SIZES(NM),           \
     "hard-spheres T0=1e-8: scene=grw-ex5;particles.temperature=1e-8;" HS_SIZES(NH, "601"), \
     "hard-spheres T0=1e8: scene=grw-ex5;particles.temperature=1e8;" HS_SIZES(NH, "3001"), \
     NULL}
static const char *const extreme_paper[] = EXTREME_ROWS("40000", "2000");
static const char *const extreme_quick[] = EXTREME_ROWS("4000", "200");

static const vfy_metric extreme_metrics[] = {
    HARD_METRIC("t_end", Q_T_END), HARD_METRIC("T_end", Q_T_FINAL),
    HARD_METRIC("T_end_ci", Q_T_FINAL_CI), HARD_METRIC("T_end_ref", Q_T_REF),
    HARD_METRIC("sonine_tol", Q_SONINE_TOL),
    {"fictitious_fraction", vfy_metric_fictitious_fraction, NULL, NULL, 0},
    HARD_METRIC("violations_hs", Q_VIOLATIONS_HS), {NULL, NULL, NULL, NULL, 0}};
#define EXTREME_LABEL "{case} {label}"
/* Hard spheres, from T0 = 1e-8 or 1e8 to the steady state: T(t_end)
 * against the first-Sonine closure (CVODE from the same T0) times the
 * centred estimator's 1 - 1/n, allowed its half-width, the closure's model
 * error and 2/n for the rest of the O(1/n) bias. */
static const vfy_check_spec extreme_checks[] = {
    {.name = EXTREME_LABEL " T vs exact finite-n expectation", .rule = vfy_rule_zscore,
     .value = "T", .expected = "T_finite_n", .from = 1, .tol = VFY_TOL_ZMAX, .out = "z_T",
     .guard = {only_maxwell, NULL, NULL, 0, NULL}},
    {.name = EXTREME_LABEL " T_raw vs exact finite-n expectation", .rule = vfy_rule_zscore,
     .value = "T_raw", .expected = "T_raw_finite_n", .from = 1, .tol = VFY_TOL_ZMAX,
     .out = "z_T_raw", .guard = {only_maxwell, NULL, NULL, 0, NULL}},
    {.name = EXTREME_LABEL " T(t_end) vs Sonine closure", .rule = vfy_rule_absolute,
     .value = "T_end", .expected = "T_end_ref", .plus = "sonine_tol",
     .guard = {only_hard_spheres, NULL, NULL, 0, NULL}},
    {.name = EXTREME_LABEL, .rule = hard_rule, .x = HARD_VIOLATIONS,
     .guard = {only_hard_spheres, NULL, NULL, 0, NULL}},
    {.name = EXTREME_LABEL " V Gaussian, variance (T0 + 2 beta t)/n",
     .rule = hard_rule_gaussian_V, .out = "z_V2"},
    HARD_CHECK(EXTREME_LABEL, HARD_FINITE, NULL),
    {.name = NULL}};
static const char extreme_columns[] =
    "row=label:%s n:%.0f N:%.0f t_end:%.4g T_end:%.6g T_end_ci:%.2g T_end_ref:%.6g "
    "z_T:%.2f z_T_raw:%.2f z_V2:%.2f fictitious_fraction:%.3f "
    "violations=violations_hs:%.0f "
    VFY_COST_COLUMNS;
const vfy_case_desc vfy_hard_extreme = {
    .must_fail = "heating.strength=1.05",
    .paper_rows = {.rows = extreme_paper}, .quick_rows = {.rows = extreme_quick},
    .label = EXTREME_LABEL, .needs = all_references, .require = HARD_UNIT_MASS,
    .require_why = HARD_UNIT_MASS_WHY, .metrics = extreme_metrics, .checks = extreme_checks,
    .columns = extreme_columns, .title = HARD_TITLE("extreme but legal parameters"),
    .notes = HARD_NOTES(
        "Maxwell rows: paper A Ex 3's heated gas (hard-extreme.ini) with restitution 1e-3, "
        "restitution exactly 1 (k = 0: T = T0 + 2 beta t), rate gamma = 1e6 (t_end scaled to "
        "keep the events: T falls from 1 to 2 beta/k = 1.1e-5), T0 = 1e-8 and T0 = 1e8; z_T, "
        "z_T_raw: max |z| over the output times against the exact expectations of the "
        "n-particle estimators (docs/theory.md §11.2). Hard-sphere rows: paper A Ex 5's gas from T0 = "
        "1e-8 and 1e8 on [0, 6]: T(t_end) against (1 - 1/n) times the first-Sonine closure "
        "(CVODE from the same T0), allowed T_end_ci + (0.002 + 2/n) T_end_ref; majorant "
        "violations 0. z_V2 (every row): the bulk velocity is exactly N(0, (T0 + 2 beta t)/n) "
        "per component.")};
