/* The hard suite (issue #5 item 1): cases chosen to break a careless solver,
 * each with checks that can fail.  Suite `hard` (the sizes below marked
 * "paper"); every case is also in the quick suite at small sizes (CI, also
 * under ASan+UBSan).  Scenes: verify/scenes/hard-*.ini, and paper A's and B's
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
 * The exact steady energy balance (SPEC §3: dT/dt = 2 beta - gamma (1 -
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
#include "engine.h"
#include "heated.h"
#include "scene_ini.h"
#include "scene_refs.h"
#include "sonine.h"
#include "steady.h"
#include "table.h"

#define ZMAX 4.5              /* max |z| over the output times (as case_grw.c, case_brs.c) */
#define A2_WHITE_TOL 0.006    /* |a2 - (C.10)|, white noise (as case_ms.c) */
#define A2_NG_RTOL 0.25       /* non-Gaussian a2 within 25% of (C.76) (as case_ms.c) */
#define MU4_GAP_RTOL 0.002    /* direct and indirect mu4 within 0.2% (as case_ms.c) */
#define BALANCE_BIAS 3.0      /* the energy balance's O(1/n) allowance: 3/n */
#define DEPLETED 0.5          /* non-Gaussian f/phi in the lowest shell at most this */
#define TAIL_C 3.0            /* hard-tails: the tail is c >= TAIL_C */
#define ODE_RTOL 1e-6         /* CVODE (rtol 1e-10) against a closed form or a steady state */
#define TIGHT_STEPS 20        /* hard-stiff: a step budget per output interval too small */
#define TIGHT_STEPS_TEXT "20"
#define SONINE_MODEL_RTOL 0.002   /* first-Sonine closure error (as case_grw.c) */
#define FINITE_N_BIAS 2.0     /* hard spheres, centred T: O(1/n) allowance 2/n */

/* ------------------------------------------------ summaries and pure checks */

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
    const size_t M = res->outputs, total = M * SIM_OBS_COUNT + res->nsteady;
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
            double mean = sim_result_mean(res, m, k), var = res->var[m * SIM_OBS_COUNT + k];
            nan_max(&s->momentum, sqrt(N * (var + mean * mean)));
        }
        double mean = sim_result_mean(res, m, SIM_OBS_T_RAW);
        double var = res->var[m * SIM_OBS_COUNT + SIM_OBS_T_RAW];
        nan_max(&s->speed, sqrt(3.0 * sqrt(N * (var + mean * mean)) / mass));
        nan_min(&s->T_min, sim_result_mean(res, m, SIM_OBS_T));
        nan_max(&s->T_max, sim_result_mean(res, m, SIM_OBS_T));
    }
}

double vfy_hard_momentum_bound(const vfy_hard_summary *s, double updates)
{
    const double u = 0.5 * DBL_EPSILON;
    return 6.0 * u * s->speed * (sqrt(2.0 * updates) / (double)s->n + 2.0);
}

double vfy_hard_energy_bound(const vfy_hard_summary *s, double collisions)
{
    const double u = 0.5 * DBL_EPSILON, n = (double)s->n;
    return 6.0 * u * (8.0 * sqrt(collisions) / n + 2.0 * sqrt(n));
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
                   && s->T_max <= s->T_first * (1.0 + 1e-12);
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

/* Set by --set or --solver-set (such keys are never changed by a case: a
 * deliberately wrong solver stays wrong). */
static int overridden(const sim_scene *s, const char *key)
{
    return sim_scene_key_line(s, key) < 0;
}

#define SET_UNLESS_OVERRIDDEN(s, key, field, value)                                          \
    do {                                                                                     \
        if (!overridden((s), (key)))                                                         \
            (s)->field = (value);                                                            \
    } while (0)

/* Both scenes: the reference and the solver. */
#define SET_BOTH(scene, solver, key, field, value)                                           \
    do {                                                                                     \
        SET_UNLESS_OVERRIDDEN(scene, key, field, value);                                     \
        SET_UNLESS_OVERRIDDEN(solver, key, field, value);                                    \
    } while (0)

/* Scene `stem` of o->scene_dir with the case's overrides (scene) and the
 * solver overrides too (solver). */
static sim_status hard_load(const vfy_case *c, const vfy_options *o, const char *stem,
                            sim_scene *scene, sim_scene *solver, char *msg, size_t msglen)
{
    vfy_case tmp = *c;
    tmp.name = stem;
    sim_status status = vfy_load_case_scene(&tmp, o, scene, solver, msg, msglen);
    if (status == SIM_OK && sim_scene_grain_mass(scene) != 1.0) {
        snprintf(msg, msglen, "%s: the hard cases use unit grain mass (paper A's units)",
                 scene->file);
        status = SIM_EINVAL;
    }
    return status;
}

/* A case's sizes, set on both scenes unless --set or --solver-set gave
 * them; 0 keeps the scene's value. */
typedef struct hard_sizes {
    size_t n, ensembles, outputs, pairs;
    double t_end, from;
} hard_sizes;

static void apply_sizes(sim_scene *s, const hard_sizes *z)
{
    if (z->n)
        SET_UNLESS_OVERRIDDEN(s, "particles.n", particles.n, z->n);
    if (z->ensembles)
        SET_UNLESS_OVERRIDDEN(s, "particles.ensembles", particles.ensembles, z->ensembles);
    if (z->outputs)
        SET_UNLESS_OVERRIDDEN(s, "scene.outputs", outputs, z->outputs);
    if (z->pairs)
        SET_UNLESS_OVERRIDDEN(s, "steady.pairs", steady.pairs, z->pairs);
    if (z->t_end > 0.0)
        SET_UNLESS_OVERRIDDEN(s, "scene.t_end", t_end, z->t_end);
    if (z->from > 0.0)
        SET_UNLESS_OVERRIDDEN(s, "steady.from", steady.from, z->from);
}

static sim_status hard_simulate(const vfy_case *c, const vfy_options *o, const sim_scene *solver,
                                const char *row, sim_ensemble_result *res, char *msg,
                                size_t msglen)
{
    char label[128];
    snprintf(label, sizeof label, "%s %s", c->name, row);
    sim_status status = vfy_simulate(solver, o, label, res, msg, msglen);
    if (status != SIM_OK)
        sim_ensemble_result_free(res);
    return status;
}

/* Collisional loss rate of T of hard spheres (unit mass), SPEC §3 Ex 5 with
 * the first Sonine factor:
 *   gamma (1 - alpha^2)/24 4 pi C (32/sqrt(pi)) T^{3/2} (1 + 3 a2/16). */
static double hs_loss(const sim_scene *s, double T, double a2)
{
    const double alpha = s->collisions.restitution;
    return s->collisions.rate * (1.0 - alpha * alpha) / 24.0 * 4.0 * M_PI * s->collisions.constant
           * 32.0 / sqrt(M_PI) * pow(T, 1.5) * (1.0 + 3.0 * a2 / 16.0);
}

/* The exact steady energy balance (top of this file): the collisional loss
 * gamma pi C (1 - alpha^2) <|g|^3>/6 of the reference scene, with <|g|^3>
 * from the solver's steady mu2 (reduced with the solver's alpha, which the
 * observer used) and T, over the heating 2 beta; its relative confidence
 * half-width in *rel_ci. */
static double balance_ratio(const sim_scene *scene, const sim_scene *solver,
                            const sim_ensemble_result *res, double *rel_ci)
{
    const double mu2 = sim_result_steady_mean(res, SIM_STEADY_MU2);
    const double T = sim_result_steady_mean(res, SIM_STEADY_T);
    const double a = scene->collisions.restitution, a_obs = solver->collisions.restitution;
    const double g3 = 8.0 * mu2 * pow(2.0 * T, 1.5) / (M_PI * (1.0 - a_obs * a_obs));
    const double loss = scene->collisions.rate * M_PI * scene->collisions.constant
                        * (1.0 - a * a) * g3 / 6.0;
    *rel_ci = sim_result_steady_ci(res, SIM_STEADY_MU2) / mu2
              + 1.5 * sim_result_steady_ci(res, SIM_STEADY_T) / T;
    return loss / (2.0 * scene->heating.strength);
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
                mean[3 * m + k] = res->var[m * SIM_OBS_COUNT + obs] + mu * mu;
                exact[3 * m + k] = sigma2[m];
                ci[3 * m + k] = SIM_LAMBDA_P * sigma2[m] * sqrt(2.0 / (double)N);
            }
        v = vfy_check_zscore(r, name, mean, ci, exact, 3 * M, ZMAX, max_z);
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

static sim_status write_tables(const vfy_case *c, const vfy_options *o, const vfy_table *table,
                               const sim_scene *solver, const char *what, const char *notes,
                               double wall, char *msg, size_t msglen)
{
    char comment[600], title[200], full[4000];
    vfy_run_comment(solver, comment, sizeof comment);
    snprintf(title, sizeof title, "%s: %s (%s sizes)", c->name, what,
             o->size == VFY_PAPER ? "paper" : "quick");
    snprintf(full, sizeof full, "%s.\n\n%s Total wall time %.1f s.", comment, notes, wall);
    return vfy_write_case_tables(o, c->name, table, comment, title, full, msg, msglen);
}

/* ------------------------------------------- hard-dissipation, hard-tails */

/* Steady white-noise rows (hard-dissipation, hard-tails): one row per alpha;
 * beta is set so that the first-Sonine steady T is T0 (unless overridden). */
typedef struct white_row_out {
    double a2, a2_ci, a2_sonine, T, T_ci, mu2, mu4, mu4_white, balance, balance_ci, tail,
        tail_ci, tail_sonine, tail_maxwell;
} white_row_out;

static sim_status white_noise_row(const vfy_case *c, const vfy_options *o, double alpha,
                                  const hard_sizes *quick, int tail, vfy_report *r,
                                  vfy_table *table, double *wall, char *msg, size_t msglen)
{
    sim_scene scene, solver;
    sim_status status = hard_load(c, o, c->name, &scene, &solver, msg, msglen);
    if (status != SIM_OK)
        return status;
    if (!scene.steady.present || scene.steady.pairs == 0 || !scene.heating.present
        || scene.heating.type != SIM_HEATING_WHITE_NOISE) {
        snprintf(msg, msglen, "%s: needs white-noise [heating] and [steady] with pairs",
                 scene.file);
        return SIM_EINVAL;
    }
    if (o->size == VFY_QUICK) {
        apply_sizes(&scene, quick);
        apply_sizes(&solver, quick);
    }
    if (alpha > 0.0)
        SET_BOTH(&scene, &solver, "collisions.restitution", collisions.restitution, alpha);
    alpha = scene.collisions.restitution;
    const double a2_c10 = ref_sonine_a2_white_noise(alpha, 3.0);
    if (!tail) {   /* 2 beta = the first-Sonine loss at T0 */
        const double beta = 0.5 * hs_loss(&scene, scene.particles.maxwellian.temperature, a2_c10);
        SET_BOTH(&scene, &solver, "heating.strength", heating.strength, beta);
    }

    char row[64], label[128], name[160];
    snprintf(row, sizeof row, "alpha=%g", alpha);
    snprintf(label, sizeof label, "%s %s", c->name, row);
    sim_ensemble_result res;
    if ((status = hard_simulate(c, o, &solver, row, &res, msg, msglen)) != SIM_OK)
        return status;
    vfy_hard_summary sum;
    vfy_hard_summarize(&res, 1.0, &sum);

    white_row_out w;
    w.a2 = sim_result_steady_mean(&res, SIM_STEADY_A2);
    w.a2_ci = sim_result_steady_ci(&res, SIM_STEADY_A2);
    w.a2_sonine = a2_c10;
    w.T = sim_result_steady_mean(&res, SIM_STEADY_T);
    w.T_ci = sim_result_steady_ci(&res, SIM_STEADY_T);
    w.mu2 = sim_result_steady_mean(&res, SIM_STEADY_MU2);
    w.mu4 = sim_result_steady_mean(&res, SIM_STEADY_MU4);
    w.mu4_white = sim_result_steady_mean(&res, SIM_STEADY_MU4_WHITE);
    w.balance = balance_ratio(&scene, &solver, &res, &w.balance_ci);

    /* Steady a2 against (C.10): the Sonine estimate's own error, paper C
     * Fig. 1, plus the confidence half-width. */
    vfy_check_absolute(r, check_name(name, sizeof name, label, "a2 vs Sonine (C.10)"), w.a2,
                       a2_c10, A2_WHITE_TOL + w.a2_ci);
    /* Paper C Eq. (23): mu4 = (d + 2) mu2 exactly in the white-noise steady
     * state; direct (pair sampling) against indirect. */
    const double gap_ci = sim_result_steady_ci(&res, SIM_STEADY_MU4) / w.mu4
                          + sim_result_steady_ci(&res, SIM_STEADY_MU4_WHITE) / w.mu4_white;
    check_rel(r, check_name(name, sizeof name, label, "mu4 vs 5 mu2 (C Eq. 23)"), w.mu4,
              w.mu4_white, MU4_GAP_RTOL + gap_ci);
    /* The exact energy balance; the relative tolerance: half-widths and 3/n. */
    const double balance_tol = w.balance_ci + BALANCE_BIAS / (double)res.n;
    check_rel(r, check_name(name, sizeof name, label, "energy balance 2 beta = loss (exact)"),
              w.balance, 1.0, balance_tol);
    w.tail = w.tail_ci = w.tail_sonine = w.tail_maxwell = NAN;
    if (tail && scene.steady.bins > 0) {
        /* Paper A Ex 7, SPEC §3: the overpopulated tail exp(-A c^{3/2}) is
         * fatter than the first Sonine approximation's Maxwellian times a
         * polynomial, so beyond c = 3 the population must reach at least the
         * latter's (with the reference's a2 of (C.10), not the solver's), up
         * to its confidence half-width; a Maxwellian tail (0.37 of it here)
         * or one cut short by a stale majorant falls below. */
        const double delta = solver.steady.c_max / (double)solver.steady.bins;
        const size_t k0 = (size_t)ceil(TAIL_C / delta - 1e-9);
        w.tail = shells_probability(&solver, &res, k0, solver.steady.bins, &w.tail_ci);
        w.tail_maxwell = tail_probability((double)k0 * delta, 0.0)
                         - tail_probability(solver.steady.c_max, 0.0);
        w.tail_sonine = tail_probability((double)k0 * delta, a2_c10)
                        - tail_probability(solver.steady.c_max, a2_c10);
        vfy_check_range(r, check_name(name, sizeof name, label,
                                      "tail P(c >= 3) / first-Sonine value"),
                        w.tail / w.tail_sonine, 1.0 - w.tail_ci / w.tail_sonine, INFINITY);
    }
    vfy_hard_check_violations(r, label, &sum);
    vfy_hard_check_finite(r, label, &sum);

    vfy_table_cell(table, "%g", alpha);
    vfy_table_cell(table, "%zu", res.n);
    vfy_table_cell(table, "%zu", res.ensembles);
    vfy_table_cell(table, "%.5g", scene.heating.strength);
    vfy_table_cell(table, "%.5f", w.T);
    vfy_table_cell(table, "%.5f", w.T_ci);
    vfy_table_cell(table, "%.5f", w.a2);
    vfy_table_cell(table, "%.5f", w.a2_ci);
    vfy_table_cell(table, "%.5f", a2_c10);
    vfy_table_cell(table, "%.5f", w.mu2);
    vfy_table_cell(table, "%.5f", w.mu4);
    vfy_table_cell(table, "%.5f", w.mu4_white);
    vfy_table_cell(table, "%.5f", w.balance);
    vfy_table_cell(table, "%.5f", balance_tol);
    if (tail) {
        vfy_table_number(table, isfinite(w.tail), "%.4g", w.tail);
        vfy_table_number(table, isfinite(w.tail), "%.2g", w.tail_ci);
        vfy_table_number(table, isfinite(w.tail), "%.4g", w.tail_sonine);
        vfy_table_number(table, isfinite(w.tail), "%.4g", w.tail_maxwell);
    }
    vfy_table_cell(table, "%.3f", 1.0 - (double)sum.collisions / (double)sum.candidates);
    vfy_table_cell(table, "%llu", (unsigned long long)sum.violations);
    vfy_cost_cells(table, res.cpu_seconds, res.wall_seconds, (double)res.counts.candidates);
    *wall += res.wall_seconds;
    if (o->progress)
        fprintf(o->progress, "   %s: T = %.5f, a2 = %.5f ± %.5f (C.10 %.5f), balance %.5f\n",
                label, w.T, w.a2, w.a2_ci, a2_c10, w.balance);
    sim_ensemble_result_free(&res);
    return SIM_OK;
}

static const char *const white_cols[] = {
    "alpha", "n", "N", "beta", "T", "T_ci", "a2", "a2_ci", "a2_C10", "mu2", "mu4", "mu4_white",
    "balance", "balance_tol", "fictitious_fraction", "violations", VFY_COST_COLUMNS};
static const char *const tail_cols[] = {
    "alpha", "n", "N", "beta", "T", "T_ci", "a2", "a2_ci", "a2_C10", "mu2", "mu4", "mu4_white",
    "balance", "balance_tol", "P_tail", "P_tail_ci", "P_tail_sonine", "P_tail_maxwell",
    "fictitious_fraction", "violations", VFY_COST_COLUMNS};

static const char white_notes[] =
    "Steady state of white-noise heated hard spheres, exact jump scheme (time averages per "
    "ensemble over the output times t >= steady.from; half-widths 3.2 sigma over the "
    "ensembles). a2_C10: the Sonine estimate (paper C Eq. 10), allowed 0.006 + a2_ci. mu4 "
    "(pair sampling) against mu4_white = 5 mu2, paper C's exact steady relation (Eq. 23), "
    "within 0.2% plus half-widths. balance = gamma pi C (1 - alpha^2) <|g|^3>/6 over 2 beta, "
    "with <|g|^3> = 8 mu2 v0^3/(pi (1 - alpha^2)): exactly 1 in the steady state of the "
    "n-particle process, allowed balance_tol = half-widths + 3/n.";

sim_status vfy_case_hard_dissipation(const vfy_case *c, const vfy_options *o, vfy_report *r,
                                     char *msg, size_t msglen)
{
    static const double alphas[] = {0.05, 0.1};
    /* quick: n = 4000, N = 16, 20 mean free times of relaxation, 40 samples
     * one mean free time apart, 4000 pairs per sample */
    static const hard_sizes quick = {4000, 16, 61, 4000, 30.0, 10.0};
    vfy_table table;
    vfy_table_init(&table, sizeof white_cols / sizeof *white_cols, white_cols);
    double wall = 0.0;
    sim_status status = SIM_OK;
    for (size_t i = 0; i < sizeof alphas / sizeof *alphas && status == SIM_OK; i++)
        status = white_noise_row(c, o, alphas[i], &quick, 0, r, &table, &wall, msg, msglen);
    if (status == SIM_OK) {
        sim_scene scene, solver;
        status = hard_load(c, o, c->name, &scene, &solver, msg, msglen);
        char notes[2000];
        snprintf(notes, sizeof notes, "%s beta is set so that the first-Sonine steady T is "
                 "T0 = 1.", white_notes);
        if (status == SIM_OK)
            status = write_tables(c, o, &table, &solver,
                                  "very strong dissipation, white-noise heated hard spheres",
                                  notes, wall, msg, msglen);
    }
    vfy_table_free(&table);
    return status;
}

sim_status vfy_case_hard_tails(const vfy_case *c, const vfy_options *o, vfy_report *r,
                               char *msg, size_t msglen)
{
    /* quick: n = 2000, N = 16, pairs 4000 (t in [0, 1], samples t >= 0.25) */
    static const hard_sizes quick = {2000, 16, 0, 4000, 0.0, 0.0};
    vfy_table table;
    vfy_table_init(&table, sizeof tail_cols / sizeof *tail_cols, tail_cols);
    double wall = 0.0;
    sim_status status = white_noise_row(c, o, 0.0, &quick, 1, r, &table, &wall, msg, msglen);
    if (status == SIM_OK) {
        sim_scene scene, solver;
        status = hard_load(c, o, c->name, &scene, &solver, msg, msglen);
        char notes[2000];
        snprintf(notes, sizeof notes,
                 "Paper A Ex 7 (SPEC §3): hard spheres, alpha = 0.1, beta = 30, gamma = 16, "
                 "C = 1/(4 pi), T0 = 1, heated to T about 3: the majorant U_max grows and the "
                 "tail fills (f ~ exp(-A c^{3/2})). %s P_tail: the steady probability of "
                 "c >= %g (reduced speed) from the shells of the histogram (to c = %g), "
                 "against the first Sonine approximation with a2 of (C.10) "
                 "(P_tail_sonine) and the Maxwellian (P_tail_maxwell); the tail must reach "
                 "at least P_tail_sonine - P_tail_ci.", white_notes, TAIL_C,
                 solver.steady.c_max);
        if (status == SIM_OK)
            status = write_tables(c, o, &table, &solver, "paper A Ex 7, growing majorant and "
                                  "overpopulated tail", notes, wall, msg, msglen);
    }
    vfy_table_free(&table);
    return status;
}

/* ------------------------------------------------------- hard-nongaussian */

sim_status vfy_case_hard_nongaussian(const vfy_case *c, const vfy_options *o, vfy_report *r,
                                     char *msg, size_t msglen)
{
    static const double alphas[] = {0.05, 0.1};
    static const hard_sizes quick = {4000, 16, 61, 4000, 30.0, 10.0};
    static const char *const cols[] = {
        "alpha", "n", "N", "g", "h", "T", "a2", "a2_ci", "a2_C76", "mu4", "mu4_nongaussian",
        "f_over_phi_0", "f_over_phi_0_ci", "f_over_phi_sonine", "max_V", "V_bound",
        "violations", VFY_COST_COLUMNS};
    vfy_table table;
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    double wall = 0.0;
    sim_status status = SIM_OK;
    sim_scene scene, solver;
    for (size_t i = 0; i < sizeof alphas / sizeof *alphas && status == SIM_OK; i++) {
        if ((status = hard_load(c, o, c->name, &scene, &solver, msg, msglen)) != SIM_OK)
            break;
        if (!scene.steady.present || scene.steady.pairs == 0 || scene.steady.bins == 0
            || scene.scheme != SIM_SCHEME_TIMESTEP || !scene.particles.zero_momentum) {
            snprintf(msg, msglen, "%s: needs scheme = timestep, zero_momentum and [steady] "
                     "with pairs and bins", scene.file);
            status = SIM_EINVAL;
            break;
        }
        if (o->size == VFY_QUICK) {
            apply_sizes(&scene, &quick);
            apply_sizes(&solver, &quick);
        }
        const double alpha = alphas[i];
        SET_BOTH(&scene, &solver, "collisions.restitution", collisions.restitution, alpha);
        /* g so that the steady T is about T0: (2/3) g <|v|> = loss, <|v|> =
         * sqrt(2 T0) (2/sqrt(pi)) (1 - a2/8) (paper C Eq. 48), as case_ms.c */
        const double a2_c76 = ref_sonine_a2_nongaussian_fit(scene.collisions.restitution, 3.0);
        const double T0 = scene.particles.maxwellian.temperature;
        const double g = 1.5 * hs_loss(&scene, T0, a2_c76)
                         / (sqrt(2.0 * T0) * 2.0 / sqrt(M_PI) * (1.0 - a2_c76 / 8.0));
        SET_BOTH(&scene, &solver, "heating.strength", heating.strength, g);

        char row[64], label[128], name[160];
        snprintf(row, sizeof row, "alpha=%g", scene.collisions.restitution);
        snprintf(label, sizeof label, "%s %s", c->name, row);
        sim_ensemble_result res;
        if ((status = hard_simulate(c, o, &solver, row, &res, msg, msglen)) != SIM_OK)
            break;
        vfy_hard_summary sum;
        vfy_hard_summarize(&res, 1.0, &sum);
        const double a2 = sim_result_steady_mean(&res, SIM_STEADY_A2);
        const double mu4 = sim_result_steady_mean(&res, SIM_STEADY_MU4);
        const double mu4_ng = sim_result_steady_mean(&res, SIM_STEADY_MU4_NONGAUSSIAN);
        /* Paper C Fig. 8: (C.76) is semi-empirical, "fairly good agreement". */
        check_rel(r, check_name(name, sizeof name, label, "a2 vs Sonine (C.76)"), a2, a2_c76,
                  A2_NG_RTOL);
        /* Paper C Eq. (44), exact in the steady state. */
        const double gap_ci = sim_result_steady_ci(&res, SIM_STEADY_MU4) / mu4
                              + sim_result_steady_ci(&res, SIM_STEADY_MU4_NONGAUSSIAN) / mu4_ng;
        check_rel(r, check_name(name, sizeof name, label, "mu4 vs 2 mu2 <c^3>/<c> (C Eq. 44)"),
                  mu4, mu4_ng, MU4_GAP_RTOL + gap_ci);
        /* Near v = 0 (paper C §4.3, Fig. 9): Delta(0) is about -1/a2, "an
         * almost vanishing population of rest particles", while the first
         * Sonine approximation gives f/phi = 1 + a2 S2(0) = 1 + 15 a2/8 (0.78
         * here).  f/phi averaged over the lowest shell c < Delta: at most
         * DEPLETED, up to its half-width. */
        const double delta = solver.steady.c_max / (double)solver.steady.bins;
        double p_ci, p0 = shells_probability(&solver, &res, 0, 1, &p_ci);
        const double phi0 = 1.0 - tail_probability(delta, 0.0);
        const double ratio0 = p0 / phi0, ratio0_ci = p_ci / phi0;
        vfy_check_range(r, check_name(name, sizeof name, label,
                                      "f/phi near v = 0 (depleted, C §4.3)"),
                        ratio0, 0.0, DEPLETED + ratio0_ci);
        /* Paper C Eq. (62): the thermostat keeps the total momentum, and so
         * do the collisions: n per step plus each collision. */
        const double h = vfy_scene_step(&solver);
        const double steps = h > 0.0 ? solver.t_end / h : 0.0;
        const double updates = (double)res.counts.collisions / (double)res.ensembles
                               + (double)res.n * steps;
        vfy_hard_check_momentum(r, label, &sum, updates);
        vfy_hard_check_violations(r, label, &sum);
        vfy_hard_check_finite(r, label, &sum);

        vfy_table_cell(&table, "%g", scene.collisions.restitution);
        vfy_table_cell(&table, "%zu", res.n);
        vfy_table_cell(&table, "%zu", res.ensembles);
        vfy_table_cell(&table, "%.5g", solver.heating.strength);
        vfy_table_cell(&table, "%g", h);
        vfy_table_cell(&table, "%.5f", sim_result_steady_mean(&res, SIM_STEADY_T));
        vfy_table_cell(&table, "%.5f", a2);
        vfy_table_cell(&table, "%.5f", sim_result_steady_ci(&res, SIM_STEADY_A2));
        vfy_table_cell(&table, "%.5f", a2_c76);
        vfy_table_cell(&table, "%.5f", mu4);
        vfy_table_cell(&table, "%.5f", mu4_ng);
        vfy_table_cell(&table, "%.4f", ratio0);
        vfy_table_cell(&table, "%.4f", ratio0_ci);
        vfy_table_cell(&table, "%.4f", 1.0 + 15.0 / 8.0 * a2);
        vfy_table_cell(&table, "%.3g", sum.momentum);
        vfy_table_cell(&table, "%.3g", vfy_hard_momentum_bound(&sum, updates));
        vfy_table_cell(&table, "%llu", (unsigned long long)sum.violations);
        vfy_cost_cells(&table, res.cpu_seconds, res.wall_seconds, (double)res.counts.candidates);
        wall += res.wall_seconds;
        if (o->progress)
            fprintf(o->progress, "   %s: a2 = %.5f (C.76 %.5f), f/phi(c < %g) = %.3f, max |V| "
                    "%.3g\n", label, a2, a2_c76, delta, ratio0, sum.momentum);
        sim_ensemble_result_free(&res);
    }
    if (status == SIM_OK)
        status = write_tables(
            c, o, &table, &solver, "paper C's non-Gaussian thermostat near v = 0",
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
            "round-off bound V_bound (verify/case_hard.h).",
            wall, msg, msglen);
    vfy_table_free(&table);
    return status;
}

/* --------------------------------------------------------------- hard-tiny */

sim_status vfy_case_hard_tiny(const vfy_case *c, const vfy_options *o, vfy_report *r,
                              char *msg, size_t msglen)
{
    /* Three gases (paper A Ex 3, paper B Ex 2, paper A Ex 5) at n = 2, 3, 4,
     * 41 output times, N = 2x10^4 (quick) or 10^6 (paper) ensembles. */
    static const char *const stems[] = {"grw-ex3", "brs-ex2", "grw-ex5"};
    static const size_t ns[] = {2, 3, 4};
    const size_t N = o->size == VFY_PAPER ? 1000000 : 20000;
    static const char *const cols[] = {"gas", "n", "N", "z_T", "z_T_raw", "z_u", "z_V2",
                                       "violations", VFY_COST_COLUMNS};
    vfy_table table;
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    double wall = 0.0;
    sim_status status = SIM_OK;
    sim_scene scene, solver;
    double *buf = NULL;
    for (size_t g = 0; g < 3 && status == SIM_OK; g++) {
        for (size_t i = 0; i < 3 && status == SIM_OK; i++) {
            if ((status = hard_load(c, o, stems[g], &scene, &solver, msg, msglen)) != SIM_OK)
                break;
            const hard_sizes sizes = {ns[i], N, 41, 0, 0.0, 0.0};
            apply_sizes(&scene, &sizes);
            apply_sizes(&solver, &sizes);
            const size_t M = scene.outputs;
            free(buf);
            if ((buf = malloc(3 * M * sizeof *buf)) == NULL) {
                snprintf(msg, msglen, "out of memory");
                status = SIM_ENOMEM;
                break;
            }
            double *mean = buf, *ci = buf + M, *exact = buf + 2 * M;
            vfy_refs refs;
            sim_ensemble_result res;
            if ((status = vfy_run_row(c, o, &scene, &solver, &refs, &res, msg, msglen))
                != SIM_OK)
                break;
            char label[128], name[160];
            snprintf(label, sizeof label, "%s %s n=%zu", c->name, stems[g], ns[i]);
            vfy_hard_summary sum;
            vfy_hard_summarize(&res, 1.0, &sum);
            double z_T = NAN, z_raw = NAN, z_u = NAN, z_V = NAN;
            const int hard_spheres = scene.collisions.exponent != 0.0;
            if (!hard_spheres && vfy_refs_column(&refs, "T_finite_n", exact)) {
                /* the exact expectation of the n-particle T (SPEC §10) */
                vfy_result_column(&res, SIM_OBS_T, mean, ci);
                vfy_check_zscore(r, check_name(name, sizeof name, label,
                                               "T vs exact finite-n expectation"),
                                 mean + 1, ci + 1, exact + 1, M - 1, ZMAX, &z_T);
            }
            if (vfy_refs_column(&refs, "T_raw_finite_n", exact)) {
                vfy_result_column(&res, SIM_OBS_T_RAW, mean, ci);
                vfy_check_zscore(r, check_name(name, sizeof name, label,
                                               "T_raw vs exact finite-n expectation"),
                                 mean + 1, ci + 1, exact + 1, M - 1, ZMAX, &z_raw);
            }
            if (scene.background.present) {
                /* paper B: E u_n(t) = u(t) exactly for every n (background.h) */
                double *all_m = malloc(3 * M * sizeof *all_m);
                double *all_c = malloc(3 * M * sizeof *all_c);
                double *all_e = malloc(3 * M * sizeof *all_e);
                static const char *const ref_u[] = {"ux_exact", "uy_exact", "uz_exact"};
                if (all_m && all_c && all_e) {
                    for (int k = 0; k < 3; k++) {
                        vfy_result_column(&res, SIM_OBS_UX + k, mean, ci);
                        vfy_refs_column(&refs, ref_u[k], exact);
                        for (size_t m = 0; m < M; m++) {
                            all_m[k * M + m] = mean[m];
                            all_c[k * M + m] = ci[m];
                            all_e[k * M + m] = exact[m];
                        }
                    }
                    vfy_check_zscore(r, check_name(name, sizeof name, label,
                                                   "u vs exact expectation"),
                                     all_m, all_c, all_e, 3 * M, ZMAX, &z_u);
                } else {
                    vfy_check_true(r, check_name(name, sizeof name, label,
                                                 "u vs exact expectation"), 0, "out of memory");
                }
                free(all_m);
                free(all_c);
                free(all_e);
            } else {
                /* paper A: V ~ N(0, (T0 + 2 beta t)/n) per component, exactly */
                const ref_heated_params p = vfy_heated_params(&scene);
                for (size_t m = 0; m < M; m++)
                    exact[m] = (p.T0 + 2.0 * p.beta * res.t[m]) / (double)ns[i];
                check_gaussian_momentum(r, check_name(name, sizeof name, label,
                                                      "V Gaussian, variance (T0 + 2 beta t)/n"),
                                        &res, exact, &z_V);
            }
            if (hard_spheres)
                vfy_hard_check_violations(r, label, &sum);
            vfy_hard_check_finite(r, label, &sum);

            vfy_table_cell(&table, "%s", stems[g]);
            vfy_table_cell(&table, "%zu", ns[i]);
            vfy_table_cell(&table, "%zu", res.ensembles);
            vfy_table_number(&table, !isnan(z_T), "%.2f", z_T);
            vfy_table_number(&table, !isnan(z_raw), "%.2f", z_raw);
            vfy_table_number(&table, !isnan(z_u), "%.2f", z_u);
            vfy_table_number(&table, !isnan(z_V), "%.2f", z_V);
            vfy_table_number(&table, hard_spheres, "%.0f", (double)sum.violations);
            vfy_cost_cells(&table, res.cpu_seconds, res.wall_seconds,
                           (double)res.counts.candidates);
            wall += res.wall_seconds;
            vfy_refs_free(&refs);
            sim_ensemble_result_free(&res);
        }
    }
    free(buf);
    if (status == SIM_OK)
        status = write_tables(
            c, o, &table, &solver, "tiny systems, n = 2, 3, 4",
            "Paper A Ex 3's heated Maxwell gas (grw-ex3), paper B Ex 2's Maxwell gas in a host "
            "medium (brs-ex2) and paper A Ex 5's heated hard spheres (grw-ex5), each at n = 2, "
            "3, 4 with 41 output times. z_T, z_T_raw: max |z| over the output times t > 0 of the "
            "ensemble mean against the exact expectation of the n-particle estimator (SPEC "
            "§10); z_u: of u against paper B's exact u(t) = E u_n(t). z_V2: the bulk velocity of "
            "paper A's gases is exactly N(0, (T0 + 2 beta t)/n) per component (collisions "
            "conserve it, the heating adds independent Gaussian increments), whatever the "
            "kernel: (1/N) Σ_j V_k^2 against its expectation, standard deviation "
            "(T0 + 2 beta t)/n sqrt(2/N). Allowed |z| <= 4.5.",
            wall, msg, msglen);
    vfy_table_free(&table);
    return status;
}

/* ----------------------------------------------------------- hard-long-run */

/* Elastic hard spheres: collisions per candidate event, about 1/4 to 1/5
 * for n = 1000 (the majorant's acceptance); the row runs E/5 collisions. */
#define HS_COLLISIONS_PER_EVENT 0.2

sim_status vfy_case_hard_long_run(const vfy_case *c, const vfy_options *o, vfy_report *r,
                                  char *msg, size_t msglen)
{
    /* candidate events per system: 10^9 (paper), 10^7 (quick) */
    const double E = o->size == VFY_PAPER ? 1e9 : 1e7;
    static const char *const cols[] = {
        "row", "n", "N", "alpha", "t_end", "events_per_system", "collisions_per_system",
        "k_t_end", "T_end_over_T0", "z_T", "max_V", "V_bound", "energy_bound", "violations",
        VFY_COST_COLUMNS};
    vfy_table table;
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    double wall = 0.0;
    sim_status status = SIM_OK;
    sim_scene scene, solver;
    double *buf = NULL;
    for (int row = 0; row < 2 && status == SIM_OK; row++) {
        if ((status = hard_load(c, o, c->name, &scene, &solver, msg, msglen)) != SIM_OK)
            break;
        if (scene.heating.present || scene.background.present || !scene.collisions.present
            || !scene.particles.zero_momentum) {
            snprintf(msg, msglen, "%s: needs [collisions] only and zero_momentum", scene.file);
            status = SIM_EINVAL;
            break;
        }
        const int hs = row == 1;
        const double T0 = scene.particles.maxwellian.temperature;
        const double n = (double)scene.particles.n;
        const double prefactor = 2.0 * M_PI * scene.collisions.rate * scene.collisions.constant
                                 * (n - 1.0);
        if (hs) {   /* elastic hard spheres: energy conserved exactly */
            SET_BOTH(&scene, &solver, "collisions.kernel", collisions.kernel,
                     SIM_KERNEL_HARD_SPHERES);
            SET_BOTH(&scene, &solver, "collisions.kernel", collisions.exponent, 1.0);
            SET_BOTH(&scene, &solver, "collisions.restitution", collisions.restitution, 1.0);
            /* the elastic gas stays Maxwellian at T0: n(n-1)/2 pairs at the
             * rate 4 pi gamma C <|g|>/n, <|g|> = 4 sqrt(T0/(pi m)), i.e.
             * prefactor 4 sqrt(T0/pi) collisions per unit time */
            const double t_end = HS_COLLISIONS_PER_EVENT * E
                                 / (prefactor * 4.0 * sqrt(T0 / M_PI));
            scene.t_end = solver.t_end = t_end;
        } else {   /* Maxwell: E events in t_end; alpha with k t_end = 4 */
            const double t_end = E / prefactor;
            scene.t_end = solver.t_end = t_end;
            const double one_minus_a2 = 4.0 / (scene.collisions.rate * M_PI
                                               * scene.collisions.constant * t_end);
            SET_BOTH(&scene, &solver, "collisions.restitution", collisions.restitution,
                     sqrt(1.0 - one_minus_a2));
        }
        const size_t M = scene.outputs;
        free(buf);
        if ((buf = malloc(3 * M * sizeof *buf)) == NULL) {
            snprintf(msg, msglen, "out of memory");
            status = SIM_ENOMEM;
            break;
        }
        char rowname[64], label[128], name[160];
        snprintf(rowname, sizeof rowname, "%s", hs ? "elastic-hard-spheres" : "maxwell");
        snprintf(label, sizeof label, "%s %s", c->name, rowname);
        sim_ensemble_result res;
        if ((status = hard_simulate(c, o, &solver, rowname, &res, msg, msglen)) != SIM_OK)
            break;
        vfy_hard_summary sum;
        vfy_hard_summarize(&res, 1.0, &sum);
        const double per_system = (double)res.counts.candidates / (double)res.ensembles;
        const double coll_per_system = (double)res.counts.collisions / (double)res.ensembles;
        const double alpha = scene.collisions.restitution;
        const double k = scene.collisions.rate * M_PI * scene.collisions.constant
                         * (1.0 - alpha * alpha);
        double z = NAN;
        if (!hs) {
            /* Maxwell molecules without heating: E[X(t) | X(0)] = X(0) e^{-kt}
             * exactly, X = Σ|v_i - V|^2 (dE X/dt = -k X: the loss is
             * (1 - alpha^2)/4 |g|^2 at rate 4 pi gamma C/n per pair and
             * Σ_{i<j} |g_ij|^2 = n X), so the ensemble mean of T(t) must be
             * mean T(0) e^{-kt}.  Its noise: the losses are a compound Poisson
             * sum, (1 - alpha^2)/4 (1 - mu) |g|^2 per collision with
             * E[(1 - mu)^2] = 4/3 and E|g|^4 = 60 T^2 (Maxwellian), so after
             * E events X(t) e^{kt}/X(0) - 1 has standard deviation
             * (1 - alpha^2) sqrt(80 E)/(12 n) per system. */
            double *mean = buf, *ci = buf + M, *exact = buf + 2 * M;
            vfy_result_column(&res, SIM_OBS_T, mean, NULL);
            for (size_t m = 0; m < M; m++) {
                const double events = prefactor * res.t[m];
                const double sd = (1.0 - alpha * alpha) * sqrt(80.0 * events) / (12.0 * n);
                exact[m] = mean[0] * exp(-k * res.t[m]);
                ci[m] = SIM_LAMBDA_P * sd * exact[m] / sqrt((double)res.ensembles);
            }
            vfy_check_zscore(r, check_name(name, sizeof name, label,
                                           "T(t) vs T(0) e^{-kt} (exact)"),
                             mean, ci, exact, M, ZMAX, &z);
            vfy_hard_check_cooling_range(r, label, &sum);
        } else {
            vfy_hard_check_energy(r, label, &sum, coll_per_system);
            vfy_hard_check_violations(r, label, &sum);
        }
        vfy_hard_check_momentum(r, label, &sum, coll_per_system);
        vfy_hard_check_finite(r, label, &sum);

        vfy_table_cell(&table, "%s", rowname);
        vfy_table_cell(&table, "%zu", res.n);
        vfy_table_cell(&table, "%zu", res.ensembles);
        vfy_table_cell(&table, "%.9g", alpha);
        vfy_table_cell(&table, "%.6g", scene.t_end);
        vfy_table_cell(&table, "%.4g", per_system);
        vfy_table_cell(&table, "%.4g", coll_per_system);
        vfy_table_cell(&table, "%.4g", k * scene.t_end);
        vfy_table_cell(&table, "%.6g", sum.T_last / sum.T_first);
        vfy_table_number(&table, !hs, "%.2f", z);
        vfy_table_cell(&table, "%.3g", sum.momentum);
        vfy_table_cell(&table, "%.3g", vfy_hard_momentum_bound(&sum, coll_per_system));
        vfy_table_number(&table, hs, "%.3g", vfy_hard_energy_bound(&sum, coll_per_system));
        vfy_table_number(&table, hs, "%.0f", (double)sum.violations);
        vfy_cost_cells(&table, res.cpu_seconds, res.wall_seconds, (double)res.counts.candidates);
        wall += res.wall_seconds;
        if (o->progress)
            fprintf(o->progress, "   %s: %.3g events per system, T(t_end)/T(0) = %.6g, max |V| "
                    "%.3g\n", label, per_system, sum.T_last / sum.T_first, sum.momentum);
        sim_ensemble_result_free(&res);
        if ((status = vfy_write_rows_so_far(o, c->name, &table, &solver, msg, msglen)) != SIM_OK)
            break;
    }
    free(buf);
    if (status == SIM_OK)
        status = write_tables(
            c, o, &table, &solver, "long runs",
            "Each system runs its events in one jump-scheme trajectory, initial momentum removed "
            "(zero_momentum). maxwell: Maxwell molecules, no heating, alpha just below 1 so that "
            "k t_end = 4 (k = gamma pi C (1 - alpha^2)); every candidate is a collision. z_T: max "
            "|z| of the ensemble mean of T(t) against mean T(0) e^{-kt}, exact for Maxwell "
            "molecules without heating, with the standard deviation of the inelastic losses "
            "(1 - alpha^2) sqrt(80 E(t))/(12 n sqrt(N)), E(t) events per system by t. "
            "elastic-hard-spheres: alpha = 1, E/5 collisions per system (about E candidate "
            "events), energy and momentum conserved exactly in real arithmetic, T(t) against "
            "T(0) within energy_bound. max_V: an upper bound on "
            "|V_k| of every system at every output time (sqrt(N (var + mean^2))), against "
            "V_bound = 6 u s (sqrt(2 U)/n + 2), U collisions per system, s the r.m.s. speed "
            "(verify/case_hard.h).",
            wall, msg, msglen);
    vfy_table_free(&table);
    return status;
}

/* -------------------------------------------------------------- hard-stiff */

sim_status vfy_case_hard_stiff(const vfy_case *c, const vfy_options *o, vfy_report *r,
                               char *msg, size_t msglen)
{
    sim_scene scene, solver;
    sim_status status = hard_load(c, o, c->name, &scene, &solver, msg, msglen);
    if (status != SIM_OK)
        return status;
    if (!scene.background.present || scene.background.kernel != SIM_KERNEL_HARD_SPHERES) {
        snprintf(msg, msglen, "%s: needs a hard-sphere [background]", scene.file);
        return SIM_EINVAL;
    }
    static const double Ks[] = {100.0, 1e-4};
    static const char *const cols[] = {"model", "K", "method", "status", "T_end", "T_steady",
                                       "rel_dev", "message"};
    vfy_table table;
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    const size_t M = scene.outputs;
    double *t = malloc(M * sizeof *t), *T = malloc(M * sizeof *T);
    double *u = malloc(3 * M * sizeof *u), *Tx = malloc(M * sizeof *Tx);
    if (!t || !T || !u || !Tx) {
        snprintf(msg, msglen, "out of memory");
        status = SIM_ENOMEM;
    }
    for (size_t m = 0; m < M && status == SIM_OK; m++)
        t[m] = sim_scene_output_time(&scene, m);
    for (int model = 0; model < 3 && status == SIM_OK; model++) {
        for (size_t ik = 0; ik < 2; ik++) {
            for (int method = 0; method < 3; method++) {
                /* K = (rho/rho_B)^2 C2/C1 with rho = 1 (background.h); Kn =
                 * rho C2/(rho_B C1) for Maxwell kernels */
                ref_background_params p = vfy_background_params(&scene);
                p.C2 = Ks[ik] * p.C1 * p.bg_density * p.bg_density / (p.density * p.density);
                /* BDF (the references' default), Adams, and Adams with a step
                 * budget too small for K = 100's stiff transient (a real
                 * failure, which must come back as a clear message) */
                ref_ode_options opt = ref_ode_default_options();
                opt.method = method ? REF_ODE_ADAMS : REF_ODE_BDF;
                if (method == 2)
                    opt.max_steps = TIGHT_STEPS;
                char method_name[32] = "BDF";
                if (method == 1)
                    snprintf(method_name, sizeof method_name, "Adams");
                else if (method == 2)
                    snprintf(method_name, sizeof method_name, "Adams max_steps=%d", TIGHT_STEPS);
                char emsg[400] = "";
                /* BDF and Adams without a budget solve every one of these (they
                 * must); only the budgeted Adams may fail, cleanly */
                vfy_hard_ode run = {.nt = M, .T = T, .u = u, .T_exact = NULL,
                                    .T_steady = NAN, .rtol = ODE_RTOL,
                                    .must_succeed = method < 2};
                const char *model_name = model == 0 ? "LE (B.21)" : model == 1 ? "Grad (B.22)"
                                                                                : "Maxwell (B.13)";
                if (model < 2) {
                    const ref_background_closure cl = model == 0 ? REF_BACKGROUND_LE
                                                                 : REF_BACKGROUND_GRAD;
                    run.status = ref_background_hs(&p, cl, t, M, &opt, u, T, emsg, sizeof emsg);
                    run.T_steady = ref_background_hs_T_steady(&p, cl);
                } else {
                    p.C2 = Ks[ik] * p.C1 * p.bg_density / p.density;
                    run.status = ref_background_maxwell_ode(&p, t, M, &opt, u, T, emsg,
                                                            sizeof emsg);
                    for (size_t m = 0; m < M; m++)
                        Tx[m] = ref_background_maxwell_T(&p, t[m]);
                    run.T_exact = Tx;
                    run.T_steady = ref_background_maxwell_T_steady(&p);
                }
                run.msg = emsg;
                char name[160];
                snprintf(name, sizeof name, "%s %s K=%g %s", c->name, model_name, Ks[ik],
                         method_name);
                vfy_hard_check_ode(r, name, &run);
                const int ok = run.status == REF_OK;
                vfy_table_cell(&table, "%s", model_name);
                vfy_table_cell(&table, "%g", Ks[ik]);
                vfy_table_cell(&table, "%s", method_name);
                vfy_table_cell(&table, "%s", ok ? "ok" : ref_strerror(run.status));
                vfy_table_number(&table, ok, "%.10g", T[M - 1]);
                vfy_table_cell(&table, "%.10g", run.T_steady);
                vfy_table_number(&table, ok, "%.2g", fabs(T[M - 1] / run.T_steady - 1.0));
                vfy_table_cell(&table, "%s", csv_safe(emsg));
            }
        }
    }
    if (status == SIM_OK) {
        char notes[1400];
        snprintf(notes, sizeof notes,
                 "Paper B's hard-sphere closures, local equilibrium (B.21) and Grad (B.22), "
                 "with K = 100 (strongly inelastic, a fast stiff transient) and K = 1e-4 (almost "
                 "no inelastic loss), and the Maxwell-kernel moment equations (B.13) with "
                 "Kn = 100 and 1e-4 against their closed form (B.15), integrated with CVODE "
                 "(rtol 1e-10, atol 1e-12; BDF with Newton, Adams with fixed-point "
                 "iteration, and Adams with at most " TIGHT_STEPS_TEXT " steps per output "
                 "interval) on %zu output times of [0, %g]. T_steady: the closure's steady "
                 "state by GSL's Brent root finder, or (B.18). Verdict: success with every value "
                 "finite, T > 0, T(t_end) within %.0e of T_steady (and the whole trajectory "
                 "within %.0e of the closed form); BDF and Adams must succeed, the budgeted Adams "
                 "may instead fail cleanly with a message; never garbage.", M, scene.t_end, ODE_RTOL, ODE_RTOL);
        status = write_tables(c, o, &table, &scene, "stiff references through CVODE", notes,
                              0.0, msg, msglen);
    }
    free(t);
    free(T);
    free(u);
    free(Tx);
    vfy_table_free(&table);
    return status;
}

/* ------------------------------------------------------------ hard-extreme */

typedef struct extreme_row {
    const char *label;
    const char *stem;     /* the gas */
    double restitution;   /* 0: the scene's */
    double rate;          /* 0: the scene's; t_end and outputs scale to keep the events */
    double T0;            /* 0: the scene's */
    size_t outputs;       /* 0: the case's default */
} extreme_row;

sim_status vfy_case_hard_extreme(const vfy_case *c, const vfy_options *o, vfy_report *r,
                                 char *msg, size_t msglen)
{
    static const extreme_row rows[] = {
        {"alpha=1e-3", "hard-extreme", 1e-3, 0.0, 0.0, 0},
        {"alpha=1", "hard-extreme", 1.0, 0.0, 0.0, 0},
        {"rate=1e6", "hard-extreme", 0.0, 1e6, 0.0, 0},
        {"T0=1e-8", "hard-extreme", 0.0, 0.0, 1e-8, 0},
        {"T0=1e8", "hard-extreme", 0.0, 0.0, 1e8, 0},
        {"hard-spheres T0=1e-8", "grw-ex5", 0.0, 0.0, 1e-8, 601},
        {"hard-spheres T0=1e8", "grw-ex5", 0.0, 0.0, 1e8, 3001},
    };
    static const char *const cols[] = {"row", "n", "N", "t_end", "T_end", "T_end_ci",
                                       "T_end_ref", "z_T", "z_T_raw", "z_V2",
                                       "fictitious_fraction", "violations", VFY_COST_COLUMNS};
    vfy_table table;
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    double wall = 0.0;
    sim_status status = SIM_OK;
    sim_scene scene, solver;
    double *buf = NULL;
    for (size_t i = 0; i < sizeof rows / sizeof *rows && status == SIM_OK; i++) {
        const extreme_row *x = &rows[i];
        if ((status = hard_load(c, o, x->stem, &scene, &solver, msg, msglen)) != SIM_OK)
            break;
        const int hs = scene.collisions.exponent != 0.0;
        /* Maxwell rows: n = 64, N = 4000 (quick) or 40000.  Hard spheres: n =
         * 256, N = 200 or 2000, t in [0, 6] with 601 outputs, 3001 from
         * T0 = 1e8: the majorant is recomputed from the synchronised system at
         * each output time only, and from T0 = 1e8 (U_max about 8e4, while T
         * falls below 10^6 within t = 0.002) the first interval is nearly all
         * fictitious candidates, about 4e7 (n - 1)/255 per unit time. */
        hard_sizes sizes = {64, o->size == VFY_PAPER ? 40000 : 4000, 41, 0, 0.0, 0.0};
        if (hs)
            sizes = (hard_sizes){256, o->size == VFY_PAPER ? 2000 : 200, x->outputs, 0, 6.0,
                                 0.0};
        apply_sizes(&scene, &sizes);
        apply_sizes(&solver, &sizes);
        if (x->restitution > 0.0)
            SET_BOTH(&scene, &solver, "collisions.restitution", collisions.restitution,
                     x->restitution);
        if (x->rate > 0.0) {   /* the same events in t_end scaled by rate0/rate */
            const double scale = scene.collisions.rate / x->rate;
            SET_BOTH(&scene, &solver, "collisions.rate", collisions.rate, x->rate);
            scene.t_end *= scale;
            solver.t_end *= scale;
        }
        if (x->T0 > 0.0)
            SET_BOTH(&scene, &solver, "particles.temperature", particles.maxwellian.temperature,
                     x->T0);
        const size_t M = scene.outputs;
        free(buf);
        if ((buf = malloc(3 * M * sizeof *buf)) == NULL) {
            snprintf(msg, msglen, "out of memory");
            status = SIM_ENOMEM;
            break;
        }
        double *mean = buf, *ci = buf + M, *exact = buf + 2 * M;
        vfy_refs refs;
        sim_ensemble_result res;
        if ((status = vfy_run_row(c, o, &scene, &solver, &refs, &res, msg, msglen)) != SIM_OK)
            break;
        char label[128], name[160];
        snprintf(label, sizeof label, "%s %s", c->name, x->label);
        vfy_hard_summary sum;
        vfy_hard_summarize(&res, 1.0, &sum);
        double z_T = NAN, z_raw = NAN, z_V = NAN, T_ref = NAN;
        vfy_result_column(&res, SIM_OBS_T, mean, ci);
        const double T_end = mean[M - 1], T_end_ci = ci[M - 1];
        if (!hs) {
            vfy_refs_column(&refs, "T_finite_n", exact);
            T_ref = exact[M - 1];
            vfy_check_zscore(r, check_name(name, sizeof name, label,
                                           "T vs exact finite-n expectation"),
                             mean + 1, ci + 1, exact + 1, M - 1, ZMAX, &z_T);
            vfy_result_column(&res, SIM_OBS_T_RAW, mean, ci);
            vfy_refs_column(&refs, "T_raw_finite_n", exact);
            vfy_check_zscore(r, check_name(name, sizeof name, label,
                                           "T_raw vs exact finite-n expectation"),
                             mean + 1, ci + 1, exact + 1, M - 1, ZMAX, &z_raw);
        } else {
            /* From T0 = 1e-8 or 1e8 to the steady state: T(t_end) against
             * the first-Sonine closure (CVODE from the same T0) times the
             * centred estimator's 1 - 1/n, allowed its half-width, the
             * closure's model error and 2/n for the rest of the O(1/n)
             * bias. */
            vfy_refs_column(&refs, "T_sonine_closure", exact);
            const double n = (double)res.n;
            T_ref = (1.0 - 1.0 / n) * exact[M - 1];
            vfy_check_absolute(r, check_name(name, sizeof name, label,
                                             "T(t_end) vs Sonine closure"),
                               T_end, T_ref,
                               T_end_ci + (SONINE_MODEL_RTOL + FINITE_N_BIAS / n) * T_ref);
            vfy_hard_check_violations(r, label, &sum);
        }
        {
            const ref_heated_params p = vfy_heated_params(&scene);
            for (size_t m = 0; m < M; m++)
                exact[m] = (p.T0 + 2.0 * p.beta * res.t[m]) / (double)res.n;
            check_gaussian_momentum(r, check_name(name, sizeof name, label,
                                                  "V Gaussian, variance (T0 + 2 beta t)/n"),
                                    &res, exact, &z_V);
        }
        vfy_hard_check_finite(r, label, &sum);

        vfy_table_cell(&table, "%s", x->label);
        vfy_table_cell(&table, "%zu", res.n);
        vfy_table_cell(&table, "%zu", res.ensembles);
        vfy_table_cell(&table, "%.4g", scene.t_end);
        vfy_table_cell(&table, "%.6g", T_end);
        vfy_table_cell(&table, "%.2g", T_end_ci);
        vfy_table_cell(&table, "%.6g", T_ref);
        vfy_table_number(&table, !hs, "%.2f", z_T);
        vfy_table_number(&table, !hs, "%.2f", z_raw);
        vfy_table_cell(&table, "%.2f", z_V);
        vfy_table_cell(&table, "%.3f", 1.0 - (double)sum.collisions / (double)sum.candidates);
        vfy_table_number(&table, hs, "%.0f", (double)sum.violations);
        vfy_cost_cells(&table, res.cpu_seconds, res.wall_seconds, (double)res.counts.candidates);
        wall += res.wall_seconds;
        vfy_refs_free(&refs);
        sim_ensemble_result_free(&res);
    }
    free(buf);
    if (status == SIM_OK)
        status = write_tables(
            c, o, &table, &solver, "extreme but legal parameters",
            "Maxwell rows: paper A Ex 3's heated gas (hard-extreme.ini) with restitution 1e-3, "
            "restitution exactly 1 (k = 0: T = T0 + 2 beta t), rate gamma = 1e6 (t_end scaled "
            "to keep the events: T falls from 1 to 2 beta/k = 1.1e-5), T0 = 1e-8 and T0 = 1e8; "
            "z_T, z_T_raw: max |z| over the output times against the exact expectations of the "
            "n-particle estimators (SPEC §10). Hard-sphere rows: paper A Ex 5's gas from "
            "T0 = 1e-8 and 1e8 on [0, 6]: T(t_end) against (1 - 1/n) times the first-Sonine "
            "closure (CVODE from the same T0), allowed T_end_ci + (0.002 + 2/n) T_end_ref; "
            "majorant violations 0. z_V2 (every row): the bulk velocity is exactly "
            "N(0, (T0 + 2 beta t)/n) per component.",
            wall, msg, msglen);
    vfy_table_free(&table);
    return status;
}
