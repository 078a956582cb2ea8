/* Paper D (Montanero, Santos and Garzó 2007): the modified thermal
 * conductivity kappa' and the first-order distribution of inelastic hard
 * spheres from the homogeneous heat-flux force (docs/theory.md §7, §14, issue 15).
 *
 * Every row is one steady state of verify/cases/scenes/msg.ini at one restitution
 * coefficient alpha and force strength eps* (time-step scheme, the force and
 * its projection of sim/effect_heat_flux.c): N independent ensembles of n
 * particles relax until steady.from, then each averages q_x, kappa'/kappa0 and
 * the Sonine coefficients b'_k (both estimators, D Eqs. 3.10, 3.12) over the
 * output times (sim/steady.h); the half-widths come from the spread of the N
 * ensembles, with Student's t.
 *
 * Every response is taken per unit of the force the case asked for: a
 * solver's value (its own q_x over its own eps) times eps_solver/eps_case, so
 * that a solver whose force is wrong (the sign, a factor) fails.  The
 * linear-response limit: kappa' and b'_k are even in eps (the reflection
 * x -> -x maps eps to -eps), so the hook extrapolates the two strengths
 * eps1 < eps2 at the same alpha in eps^2:
 *     x(0) = (eps2^2 x(eps1) - eps1^2 x(eps2)) / (eps2^2 - eps1^2).
 *
 * Cases:
 *   msg-kappa: D Figs. 1, 3: kappa'/kappa0 against alpha beside the first
 *     Sonine and the modified first Sonine approximations; eps* = 0.05 at
 *     alpha = 0.3 and 1, and the eps* -> 0 extrapolation, judged at alpha = 1
 *     against the exact elastic value 1.025218 (reference/transport.h);
 *   msg-sonine: D Figs. 2, 4: b'_1, b'_2, b'_3 from both estimators;
 *   msg-distribution: D Figs. 5-7: phi(c_x^2) and its truncations, beta_1/b'_1,
 *     the part of the heat flux carried by c_x^2 <= 6 (87% at alpha = 1, 66% at
 *     alpha = 0.3).
 * The three cases run the same scenes, so they share their checkpoints.
  *
 * The cases are data (verify/cases/scenes/msg-*.case, docs/adding-a-case.md);
 * this file holds the metrics, guards, rules and hooks they name, listed
 * in vfy_msg_named at its end.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case_report.h"
#include "driver.h"
#include "figure.h"
#include "metrics.h"
#include "named.h"
#include "references.h"
#include "steady.h"
#include "tolerances.h"

/* ------------------------------------------------------------- metrics */

/* Value a, reduced by the simulated eps* = lambda0 eps (docs/theory.md
 * §10.5), per unit of the case's: a eps*_solver/eps*_case (x = 1: its
 * absolute value, for a half-width).  A solver's force or collision rate off
 * (lambda0 = 1/(sqrt 2 pi n sigma^2), n sigma^2 = 4 gamma C) shows here, not
 * cancelled by its own reduction. */
static double msg_per_case_force(const vfy_case_run *run, const vfy_row *row,
                                 const vfy_metric *m)
{
    (void)run;
    const double f = row->solver.heat_flux.strength / row->scene.heat_flux.strength
                     * (sim_scene_mean_free_path(&row->solver)
                        / sim_scene_mean_free_path(&row->scene));
    return vfy_values_get(&row->values, m->a) * (m->x == 1.0 ? fabs(f) : f);
}

/* (b - a)/c: how many half-widths c value a lies below value b. */
static double msg_half_widths_below(const vfy_case_run *run, const vfy_row *row,
                                    const vfy_metric *m)
{
    (void)run;
    char ci[40];
    snprintf(ci, sizeof ci, "%s_ci_t", m->a);
    return (vfy_values_get(&row->values, m->b) - vfy_values_get(&row->values, m->a))
           / vfy_values_get(&row->values, ci);
}

/* How many half-widths more than required kappa' lies below the first
 * Sonine value: below_sonine less VFY_TOL_MSG_BELOW_SONINE_PAPER (5,
 * "dramatically") or, at quick sizes, VFY_TOL_MSG_BELOW_SONINE_QUICK (1;
 * tolerances.h says why). */
static double msg_below_margin(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)m;
    return vfy_values_get(&row->values, "below_sonine")
           - (run->o->size == VFY_QUICK ? VFY_TOL_MSG_BELOW_SONINE_QUICK
                                        : VFY_TOL_MSG_BELOW_SONINE_PAPER);
}

/* |a - b| over the quadrature sum of their half-widths a_ci_t, b_ci_t. */
static double msg_z_pair(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    char ca[40], cb[40];
    snprintf(ca, sizeof ca, "%s_ci_t", m->a);
    snprintf(cb, sizeof cb, "%s_ci_t", m->b);
    return vfy_z_pair(vfy_values_get(&row->values, m->a), vfy_values_get(&row->values, ca),
                      vfy_values_get(&row->values, m->b), vfy_values_get(&row->values, cb));
}

/* 100 (collisions / expected - 1) over the run: the thermostat holds T = T0
 * at every step, so the N systems collide at the rate of (2.2a) summed over
 * pairs, N (n - 1)/2 4 pi gamma beta_c C <|g|>, with <|g|> = 4 sqrt(T0/(pi m))
 * for a Maxwellian (docs/theory.md §2.2) times 1 - a2/16 + ... (first Sonine).
 * The case's scene sets the expectation, the solver's count is what it did;
 * NAN for a solver that does not count its collisions. */
static double msg_collision_rate(const vfy_case_run *run, const vfy_row *row,
                                 const vfy_metric *m)
{
    (void)run;
    (void)m;
    const sim_scene *s = &row->scene;
    const double n = (double)s->particles.n, N = (double)s->particles.ensembles;
    const double T0 = s->particles.maxwellian.temperature;
    const double g = 4.0 * sqrt(T0 / (M_PI * sim_scene_grain_mass(s)));
    const double expected = N * (n - 1.0) / 2.0 * 4.0 * M_PI * s->collisions.rate
                            * sim_scene_collision_rate_factor(s) * s->collisions.constant * g
                            * s->t_end;
    return 100.0 * (vfy_values_get(&row->values, "collisions") / expected - 1.0);
}

/* max over k = 2, 3 of (|b'_k| + x b'_k's half-width)/b'_1: with x = -1 the
 * smallest, with x = 0 the measured size. */
static double msg_higher_over_b1(const vfy_case_run *run, const vfy_row *row,
                                 const vfy_metric *m)
{
    (void)run;
    const vfy_values *v = &row->values;
    const double b1 = fabs(vfy_values_get(v, "b1c"));
    return fmax(fabs(vfy_values_get(v, "b2c")) + m->x * vfy_values_get(v, "b2c_ci_t"),
                fabs(vfy_values_get(v, "b3c")) + m->x * vfy_values_get(v, "b3c_ci_t"))
           / b1;
}

/* The part of b'_1 (hence of the heat flux) carried by c_x^2 <= 6:
 * 1 - outer/b1_x, with the half-width of the ratio from both (independent
 * particles: the outer part and the inner part). */
static double msg_inner_fraction(const vfy_case_run *run, const vfy_row *row,
                                 const vfy_metric *m)
{
    (void)run;
    const double o = vfy_values_get(&row->values, "outerc");
    const double b = vfy_values_get(&row->values, "b1xc");
    if (m->x == 0.0)
        return 1.0 - o / b;
    const double so = vfy_values_get(&row->values, "outerc_ci_t");
    const double sb = vfy_values_get(&row->values, "b1xc_ci_t");
    return fabs(o / b) * sqrt((so / o) * (so / o) + (sb / b) * (sb / b));
}

/* ------------------------------------------------ eps -> 0 (the hook) */

/* The row at alpha with strength eps (in the case's values), or NULL. */
static const vfy_row *find_row(const vfy_case_run *run, double alpha, double eps)
{
    for (size_t i = 0; i < run->nrows; i++) {
        const vfy_row *row = &run->rows[i];
        if (fabs(vfy_values_get(&row->values, "alpha") - alpha) < 1e-9
            && fabs(vfy_values_get(&row->values, "eps_star") - eps) < 1e-12)
            return row;
    }
    return NULL;
}

/* The linear response of value q at alpha from the rows at eps1 and eps2
 * (the header comment); sets *ci from the rows' q_ci_t.  NAN without both. */
static double extrapolate(const vfy_case_run *run, double alpha, double eps1, double eps2,
                          const char *q, double *ci)
{
    const vfy_row *r1 = find_row(run, alpha, eps1), *r2 = find_row(run, alpha, eps2);
    *ci = NAN;
    if (r1 == NULL || r2 == NULL)
        return NAN;
    char qci[40];
    snprintf(qci, sizeof qci, "%s_ci_t", q);
    const double e1 = eps1 * eps1, e2 = eps2 * eps2;
    const double s1 = vfy_values_get(&r1->values, qci), s2 = vfy_values_get(&r2->values, qci);
    *ci = sqrt(e2 * e2 * s1 * s1 + e1 * e1 * s2 * s2) / (e2 - e1);
    return (e2 * vfy_values_get(&r1->values, q) - e1 * vfy_values_get(&r2->values, q))
           / (e2 - e1);
}

/* The quantities extrapolated, the exact elastic reference of each. */
static const struct {
    const char *value, *name, *exact;
} linear[] = {
    {"kappa", "kappa", "kappa_elastic_exact"}, {"b1c", "b1", "b1_elastic_exact"},
    {"b2c", "b2", "b2_elastic_exact"},         {"b3c", "b3", "b3_elastic_exact"},
    {"a2", "a2", NULL}};

/* After the rows: at alpha = 1 and 0.3, each quantity at both strengths and
 * extrapolated ("kappa_lin_1", "kappa_lin_1_ci", ... for the case checks),
 * as the second table. */
static sim_status msg_linear(vfy_case_run *run, vfy_report *r, char *msg, size_t msglen)
{
    (void)r;
    static const char *const cols[] = {"alpha", "quantity", "eps_0.025", "ci_0.025", "eps_0.05",
                                       "ci_0.05", "linear", "linear_ci", "exact"};
    static const double alphas[] = {1.0, 0.3};
    const double e1 = 0.025, e2 = 0.05;
    vfy_table *t = &run->second;
    vfy_table_init(t, sizeof cols / sizeof *cols, cols);
    for (size_t a = 0; a < 2; a++) {
        const vfy_row *r1 = find_row(run, alphas[a], e1), *r2 = find_row(run, alphas[a], e2);
        if (r1 == NULL || r2 == NULL)
            continue;
        for (size_t q = 0; q < sizeof linear / sizeof *linear; q++) {
            char qci[40], name[48], name_ci[56];
            snprintf(qci, sizeof qci, "%s_ci_t", linear[q].value);
            double ci, x = extrapolate(run, alphas[a], e1, e2, linear[q].value, &ci);
            const double exact = linear[q].exact && alphas[a] == 1.0
                                     ? vfy_reference_value(linear[q].exact, &r1->scene)
                                     : NAN;
            snprintf(name, sizeof name, "%s_lin_%s", linear[q].name, a == 0 ? "1" : "03");
            snprintf(name_ci, sizeof name_ci, "%s_ci", name);
            vfy_values_set(&run->values, name, x);
            vfy_values_set(&run->values, name_ci, ci);
            if (a == 0 && linear[q].exact)
                vfy_values_set(&run->values, linear[q].exact, exact);
            vfy_table_cell(t, "%.1f", alphas[a]);
            vfy_table_cell(t, "%s", linear[q].name);
            vfy_table_number(t, 1, "%.5f", vfy_values_get(&r1->values, linear[q].value));
            vfy_table_number(t, vfy_values_has(&r1->values, qci), "%.5f",
                             vfy_values_get(&r1->values, qci));
            vfy_table_number(t, 1, "%.5f", vfy_values_get(&r2->values, linear[q].value));
            vfy_table_number(t, vfy_values_has(&r2->values, qci), "%.5f",
                             vfy_values_get(&r2->values, qci));
            vfy_table_number(t, 1, "%.5f", x);
            vfy_table_number(t, isfinite(ci), "%.5f", ci);
            vfy_table_number(t, isfinite(exact), "%.6f", exact);
        }
    }
    run->second_suffix = "-linear";
    run->second_title = "The linear-response limit: eps* = 0.025, 0.05 and extrapolated in "
                        "eps*^2";
    if (vfy_run_second_notes(run, "%s",
             "kappa = kappa'/kappa0, b1..b3 = b'_k (D Eq. 3.10), each per unit of the case's "
             "force with its Student half-width; linear = the eps* -> 0 limit through both "
             "strengths in eps*^2 (they are even in eps*); exact = the linearised elastic "
             "Boltzmann equation solved by a converged Sonine expansion (gdsmc sonine: "
             "*_elastic_exact). a2, even in eps* too, shows the departure from linear response "
             "(its limit is the HCS a2: 0 at alpha = 1).") != 0) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    return SIM_OK;
}

/* After the rows: the linear-response table and D Fig. 1:
 * kappa'(t)/kappa0 = -(64/(75 sqrt(pi))) <c^2 c_x>(t)/eps* from the rows'
 * q_x(t) at T = T0 (q_x = (m/2) v0^3 <c^2 c_x>), every row in one plot. */
static sim_status msg_kappa_after(vfy_case_run *run, vfy_report *r, char *msg, size_t msglen)
{
    sim_status status = msg_linear(run, r, msg, msglen);
    const size_t M = run->rows[0].res.outputs, rows = run->nrows;
    double *mean = malloc(2 * rows * M * sizeof *mean), *ci = mean + rows * M;
    size_t *n = calloc(rows, sizeof *n);
    char (*label)[48] = calloc(rows, sizeof *label);
    const char **labels = calloc(rows, sizeof *labels);
    if (mean == NULL || n == NULL || label == NULL || labels == NULL) {
        free(mean);
        free(n);
        free(label);
        free(labels);
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    for (size_t i = 0; i < rows && status == SIM_OK; i++) {
        const vfy_row *row = &run->rows[i];
        const sim_scene *s = &row->scene;
        const double m = s->particles.maxwellian.mass, T0 = s->particles.maxwellian.temperature;
        const double v0 = sqrt(2.0 * T0 / m);
        const double f = 2.0 / (m * v0 * v0 * v0) * sim_steady_kappa_per_moment(s);
        n[i] = row->res.n;
        snprintf(label[i], sizeof label[i], "alpha = %.1f, eps* = %g",
                 vfy_values_get(&row->values, "alpha"), vfy_values_get(&row->values, "eps_star"));
        labels[i] = label[i];
        if (vfy_row_series(row, "qx", mean + i * M, ci + i * M) != 0 || row->res.outputs != M)
            status = SIM_EINVAL;
        for (size_t k = 0; k < M; k++) {
            mean[i * M + k] *= f;
            ci[i * M + k] *= fabs(f);
        }
    }
    if (status == SIM_OK) {
        char name[160], title[200];
        snprintf(name, sizeof name, "%s-t", run->c->name);
        snprintf(title, sizeof title, "%s: kappa'(t)/kappa0 (paper D Fig. 1), rows in order",
                 run->c->name);
        if (vfy_write_curves(run->o, name, title, run->comment, run->rows[0].res.t, M, 0, NULL,
                             NULL, rows, n, labels, mean, ci, "kappa'/kappa0", NULL, 0.0, 0) != 0)
            status = vfy_io_error(name, msg, msglen);
    } else if (status == SIM_EINVAL) {
        snprintf(msg, msglen, "%s: the rows have no q_x series", run->c->name);
    }
    free(mean);
    free(n);
    free(label);
    free(labels);
    return status;
}

/* L_k^{(1/2)}(x), k = 1, 2, 3 (D Eq. 4.4). */
static double laguerre_half(int k, double x)
{
    return k == 1 ? 1.5 - x : k == 2 ? 15.0 / 8.0 - 2.5 * x + 0.5 * x * x
                                     : 35.0 / 16.0 - 35.0 / 8.0 * x + 1.75 * x * x - x * x * x / 6.0;
}

/* The phi figures stop at c_x^2 = 9: beyond, e^{c_x^2} g1
 * magnifies the overpopulated tail of the HCS and the noise of a few
 * particles (the case keeps every bin in its steady averages). */
#define MSG_PHI_CX_MAX 3.0

/* The curves of D Figs. 5-7 (msg-distribution's [figure]s), of one row:
 * x = 0, phi(c_x^2) = sqrt(pi) e^{c_x^2} g1/c_x at the bin centres with its
 * half-widths; x = K = 1..3, its truncation phi_K = sum_{k <= K} b'_k
 * L_k^{(1/2)}(c_x^2) (the row's b'_k), both up to MSG_PHI_CX_MAX; x = 4,
 * beta_1/b'_1 at the bins' upper edges (their squares), every bin; x = 5,
 * the first Sonine's there, (8/(3 sqrt(pi))) int_0^c u^2 (3/2 - u^2)^2
 * e^{-u^2} du (midpoint rule, 64 steps a bin). */
enum { MSG_PHI, MSG_BETA1 = 4, MSG_BETA1_SONINE };
static int msg_curve(const vfy_case_run *run, const vfy_row *row, double which, vfy_curve *out)
{
    (void)run;
    const sim_scene *s = &row->solver;
    const size_t bins = s->steady.bins;
    const long g1 = sim_steady_find(s, "g1_0"), b0 = sim_steady_find(s, "beta1_0");
    const double f = row->solver.heat_flux.strength / row->scene.heat_flux.strength;
    size_t shown = 0;
    while (shown < bins && sim_steady_bin_centre(s, shown) <= MSG_PHI_CX_MAX)
        shown++;
    const int phi = which < MSG_BETA1;
    if (g1 < 0 || b0 < 0 || vfy_curve_alloc(out, phi ? shown : bins, which == MSG_PHI) != 0)
        return -1;
    double acc = 0.0, u0 = 0.0;
    for (size_t k = 0; k < out->count; k++) {
        const double c = sim_steady_bin_centre(s, k), c2 = c * c;
        const double edge = sim_steady_bin_lower(s, k + 1);
        out->x[k] = phi ? c2 : edge * edge;
        if (which == MSG_PHI) {
            out->y[0][k] = sqrt(M_PI) * exp(c2) / c * f * row->res.steady_mean[(size_t)g1 + k];
            out->ci[0][k] = sqrt(M_PI) * exp(c2) / c * fabs(f) * row->res.steady_ci[(size_t)g1 + k];
        } else if (phi) {
            static const char *const bn[] = {"b1c", "b2c", "b3c"};
            double sum = 0.0;
            for (int K = 0; K < (int)which; K++)
                sum += vfy_values_get(&row->values, bn[K]) * laguerre_half(K + 1, c2);
            out->y[0][k] = sum;
        } else if (which == MSG_BETA1) {
            out->y[0][k] = f * row->res.steady_mean[(size_t)b0 + k]
                        / vfy_values_get(&row->values, "b1xc");
        } else {
            const double u1 = sqrt(out->x[k]), du = (u1 - u0) / 64.0;
            for (int j = 0; j < 64; j++) {
                const double u = u0 + (j + 0.5) * du, l = 1.5 - u * u;
                acc += u * u * l * l * exp(-u * u) * du;
            }
            out->y[0][k] = 8.0 / (3.0 * sqrt(M_PI)) * acc;
            u0 = u1;
        }
    }
    return 0;
}

/* The functions this file's case files name (named.h, registry.c). */
const vfy_named_fn vfy_msg_named[] = {
    VFY_NAMED_METRIC("msg_per_case_force", msg_per_case_force),
    VFY_NAMED_METRIC("msg_half_widths_below", msg_half_widths_below),
    VFY_NAMED_METRIC("msg_below_margin", msg_below_margin),
    VFY_NAMED_METRIC("msg_z_pair", msg_z_pair),
    VFY_NAMED_METRIC("msg_collision_rate", msg_collision_rate),
    VFY_NAMED_METRIC("msg_higher_over_b1", msg_higher_over_b1),
    VFY_NAMED_METRIC("msg_inner_fraction", msg_inner_fraction),
    VFY_NAMED_HOOK("msg_linear", msg_linear),
    VFY_NAMED_HOOK("msg_kappa_after", msg_kappa_after),
    VFY_NAMED_CURVE_X("msg_curve_phi", msg_curve, MSG_PHI),
    VFY_NAMED_CURVE_X("msg_curve_phi_1", msg_curve, 1),
    VFY_NAMED_CURVE_X("msg_curve_phi_2", msg_curve, 2),
    VFY_NAMED_CURVE_X("msg_curve_phi_3", msg_curve, 3),
    VFY_NAMED_CURVE_X("msg_curve_beta1", msg_curve, MSG_BETA1),
    VFY_NAMED_CURVE_X("msg_curve_beta1_sonine", msg_curve, MSG_BETA1_SONINE),
    VFY_NAMED_END};
