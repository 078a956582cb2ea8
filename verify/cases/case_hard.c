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
  *
 * The cases are data (verify/cases/scenes/hard-*.case, docs/adding-a-case.md);
 * this file holds the metrics, guards, rules and hooks they name, listed
 * in vfy_hard_named at its end.
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
#include "named.h"
#include "heated.h"
#include "metrics.h"
#include "references.h"
#include "scene_refs.h"
#include "steady.h"
#include "tolerances.h"

#define TIGHT_STEPS 20        /* hard-stiff: a step budget per output interval too small */

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

/* ----------------------------------------------------------- hard-long-run */

/* Elastic hard spheres: collisions per candidate event, about 1/4 to 1/5
 * for n = 1000 (the majorant's acceptance); the row runs E/5 collisions. */
#define HS_COLLISIONS_PER_EVENT 0.2

/* E candidate events per system ($events: 10^9 paper, 10^7 quick): the
 * row's t_end (x = 0) and restitution coefficient (x = 1; NaN for hard
 * spheres, which keep theirs), metrics the case's derived settings name
 * (driver.h), evaluated before the run.  Maxwell: E events in t_end, alpha
 * with k t_end = 4.  Elastic hard spheres: the gas stays Maxwellian at T0,
 * n(n-1)/2 pairs at the rate 4 pi gamma C <|g|>/n, <|g|> = 4 sqrt(T0/(pi
 * m)): prefactor 4 sqrt(T0/pi) collisions per unit time, E/5 of them. */
static double long_run_setting(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    const sim_scene *s = &row->scene;
    const double E = vfy_values_get(&row->values, "events");
    const double prefactor = 2.0 * M_PI * s->collisions.rate * s->collisions.constant
                             * ((double)s->particles.n - 1.0);
    const double T0 = s->particles.maxwellian.temperature;
    if (s->collisions.kernel == SIM_KERNEL_HARD_SPHERES)
        return m->x == 0 ? HS_COLLISIONS_PER_EVENT * E / (prefactor * 4.0 * sqrt(T0 / M_PI))
                         : NAN;
    const double t_end = E / prefactor;
    const double one_minus_a2 = 4.0 / (s->collisions.rate * M_PI * s->collisions.constant
                                       * t_end);
    return m->x == 0 ? t_end : sqrt(1.0 - one_minus_a2);
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

/* -------------------------------------------------------------- hard-stiff */

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

/* The functions this file's case files name (named.h, registry.c). */
const vfy_named_fn vfy_hard_named[] = {
    VFY_NAMED_RULE_X("hard_check_finite", hard_rule, HARD_FINITE),
    VFY_NAMED_RULE_X("hard_check_violations", hard_rule, HARD_VIOLATIONS),
    VFY_NAMED_RULE_X("hard_check_momentum", hard_rule, HARD_MOMENTUM),
    VFY_NAMED_RULE_X("hard_check_energy", hard_rule, HARD_ENERGY),
    VFY_NAMED_RULE_X("hard_check_cooling", hard_rule, HARD_COOLING),
    VFY_NAMED_RULE("hard_rule_rel", hard_rule_rel),
    VFY_NAMED_RULE("hard_rule_at_least", hard_rule_at_least),
    VFY_NAMED_RULE("hard_rule_at_most", hard_rule_at_most),
    VFY_NAMED_RULE("hard_rule_gaussian_V", hard_rule_gaussian_V),
    VFY_NAMED_RULE("hard_rule_u_exact", hard_rule_u_exact),
    VFY_NAMED_GUARD("only_maxwell", only_maxwell),
    VFY_NAMED_GUARD("only_hard_spheres", only_hard_spheres),
    VFY_NAMED_GUARD("only_with_series", only_with_series),
    VFY_NAMED_GUARD("only_background", only_background),
    VFY_NAMED_METRIC_X("hard_alpha", hard_metric, Q_ALPHA),
    VFY_NAMED_METRIC_X("hard_balance", hard_metric, Q_BALANCE),
    VFY_NAMED_METRIC_X("hard_balance_ci", hard_metric, Q_BALANCE_CI),
    VFY_NAMED_METRIC_X("hard_balance_tol", hard_metric, Q_BALANCE_TOL),
    VFY_NAMED_METRIC_X("hard_gap_ci", hard_metric, Q_GAP_CI),
    VFY_NAMED_METRIC_X("hard_p_tail", hard_metric, Q_P_TAIL),
    VFY_NAMED_METRIC_X("hard_p_tail_ci", hard_metric, Q_P_TAIL_CI),
    VFY_NAMED_METRIC_X("hard_p_tail_sonine", hard_metric, Q_P_TAIL_SONINE),
    VFY_NAMED_METRIC_X("hard_p_tail_maxwell", hard_metric, Q_P_TAIL_MAXWELL),
    VFY_NAMED_METRIC_X("hard_tail_ratio", hard_metric, Q_TAIL_RATIO),
    VFY_NAMED_METRIC_X("hard_tail_lower", hard_metric, Q_TAIL_LOWER),
    VFY_NAMED_METRIC_X("hard_delta", hard_metric, Q_DELTA),
    VFY_NAMED_METRIC_X("hard_ratio0", hard_metric, Q_RATIO0),
    VFY_NAMED_METRIC_X("hard_ratio0_ci", hard_metric, Q_RATIO0_CI),
    VFY_NAMED_METRIC_X("hard_updates", hard_metric, Q_UPDATES),
    VFY_NAMED_METRIC_X("hard_max_v", hard_metric, Q_MAX_V),
    VFY_NAMED_METRIC_X("hard_v_bound", hard_metric, Q_V_BOUND),
    VFY_NAMED_METRIC_X("hard_energy_bound", hard_metric, Q_ENERGY_BOUND),
    VFY_NAMED_METRIC_X("hard_t_end_over_t0", hard_metric, Q_T_END_OVER_T0),
    VFY_NAMED_METRIC_X("hard_violations_hs", hard_metric, Q_VIOLATIONS_HS),
    VFY_NAMED_METRIC_X("hard_per_system", hard_metric, Q_PER_SYSTEM),
    VFY_NAMED_METRIC_X("hard_t_end", hard_metric, Q_T_END),
    VFY_NAMED_METRIC_X("hard_k_t_end", hard_metric, Q_K_T_END),
    VFY_NAMED_METRIC_X("hard_f_sonine", hard_metric, Q_F_SONINE),
    VFY_NAMED_METRIC_X("hard_t_final", hard_metric, Q_T_FINAL),
    VFY_NAMED_METRIC_X("hard_t_final_ci", hard_metric, Q_T_FINAL_CI),
    VFY_NAMED_METRIC_X("hard_t_ref", hard_metric, Q_T_REF),
    VFY_NAMED_METRIC_X("hard_sonine_tol", hard_metric, Q_SONINE_TOL),
    VFY_NAMED_METRIC_X("long_run_t_end", long_run_setting, 0),
    VFY_NAMED_METRIC_X("long_run_restitution", long_run_setting, 1),
    VFY_NAMED_RULE("long_run_rule_decay", long_run_rule_decay),
    VFY_NAMED_RULE("stiff_rule", stiff_rule),
    VFY_NAMED_END};
