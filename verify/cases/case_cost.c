/* The accuracy-cost report (docs/theory.md §1.4; work-precision: error against CPU time
 * across (n, N, dt), and which n and N reach a given error fastest).
 *
 * cost-grw-ex3, cost-brs-ex2: the scenes of paper A Ex 3 (grw-ex3.ini) and
 * paper B Ex 2 (brs-ex2.ini), both Maxwell kernels, over a grid of n x N.
 * The error is the papers' (docs/theory.md §1.4): Err = max over the output times t_m of
 * |F(t_m) - eta1(t_m)| / F(t_m), with paper A's uncentred T_raw against
 * (A.13) and paper B's centred T against (B.15).  With E xi^(n)(t) the exact
 * expectation of the n-particle estimator (reference/heated.h,
 * reference/background.h) the error splits exactly at every output time,
 *   eta1 - F = (eta1 - E xi^(n)) + (E xi^(n) - F) = statistical + systematic,
 * and each grid point reports
 *   Err_sys  = max_m |E xi^(n) - F| / F   exact, no noise (O(1/n));
 *   Err_stat = max_m |eta1 - E xi^(n)| / F   measured (O(1/sqrt(n N)));
 *   Conf     = max_m c / F, c = 3.2 sqrt(Var/N), its 99.9% scale;
 * so that |Err - Err_sys| <= Err_stat <= ... and Err <= Err_sys + Err_stat.
 * Model for the whole grid and beyond it: Err ≈ sqrt(Err_sys^2 + (k Conf)^2),
 * with Err_sys exact at every n, Conf^2 N = A/n + B/n^2 (weighted least
 * squares; B carries T_raw's bulk-velocity term, of order 1/n^2 in the
 * variance) and k = the geometric mean of Err_stat / Conf over the grid (the
 * typical largest |z| over the output times, over lambda_p).  The plain sum
 * Err_sys + k Conf was tried too: it is an upper bound, but it overestimated
 * the paper-size grid of cost-grw-ex3 by up to a factor 2 where both parts
 * are comparable, the quadrature sum by at most 1.4 either way.  CPU seconds:
 * cpu = kappa n N (the work of these Maxwell scenes is proportional to n N).
 *
 * cost-split-ex5: the hard-sphere gas of paper A Ex 5 (split-ex5.ini), the
 * time-averaged steady temperature T̄ (steady.h) with the exact jump scheme
 * over n x N and with the time-step scheme (docs/theory.md §8.5) over h, Euler and
 * Strang.  No exact solution: the reference T̄_inf comes from the jump rows,
 * T̄_jump(n) = T̄_inf + b/n (weighted least squares, its chi^2 judged; T̄_inf
 * is compared with the first-Sonine closure's steady state).  A row's error
 *   T̄ - T̄_inf = (T̄ - E T̄) + (E T̄(h) - E T̄(jump)) + (E T̄(jump) - T̄_inf)
 *              = statistical + splitting + systematic,
 * with systematic = b/n, splitting = c1 h^p + c2 h^(p+1) (p = 1 Euler, 2
 * Strang; weighted least squares of the time-step rows' difference from
 * T̄_inf + b/n, chi^2 judged) and the statistical part the residual.  Model:
 * Err ≈ sqrt((|b/n| + |split|)^2 + (k Conf)^2), k = sqrt(2/pi)/lambda_p
 * (E|Z| of one Gaussian number: right when either part dominates); no credit
 * is taken for the two biases' opposite signs.  CPU seconds: kappa n N (jump), n N (a + g/h) (time step:
 * collisions, and one Gaussian kick per particle and step).
 *
 * Every row's CPU time is res.cpu_seconds of that very run.  Targets 1e-2,
 * 1e-3, 1e-4: the cheapest measured grid point with Err <= target, and the
 * cheapest point the model predicts (n = powers of 2 up to 2^24, N among the
 * grid's, h halvings of the grid's largest), marked as a prediction.
  *
 * The cases are data (verify/cases/scenes/cost-*.case, docs/adding-a-case.md);
 * this file holds the metrics, guards, rules and hooks they name, listed
 * in vfy_cost_named at its end.
 */
#include "case_cost.h"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fit.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "case_report.h"
#include "cases.h"
#include "driver.h"
#include "named.h"
#include "figure.h"
#include "heated.h"
#include "metrics.h"
#include "references.h"
#include "scene_ini.h"
#include "scene_refs.h"
#include "steady.h"
#include "table.h"
#include "tolerances.h"

#define PRED_N_MAX ((size_t)1 << 24)
#define PRED_H_HALVINGS 12
#define VFY_COST_TARGETS_TITLE "Cheapest grid point per target, and the model's prediction"

/* ------------------------------------------------------------ shared pieces */

size_t vfy_cost_cheapest(const double *err, const double *cost, size_t count, double target)
{
    size_t best = count;
    for (size_t i = 0; i < count; i++) {
        if (!(err[i] <= target) || cost[i] != cost[i])
            continue;
        if (best == count || cost[i] < cost[best]
            || (cost[i] == cost[best] && err[i] < err[best]))   /* a tie: the smaller Err */
            best = i;
    }
    return best;
}

int vfy_cost_lsq2(size_t count, const double *x1, const double *x2, const double *y,
                  const double *w, double c[2], double *chi2)
{
    double s11 = 0, s12 = 0, s22 = 0, s1y = 0, s2y = 0;
    if (count < 2)
        return -1;
    for (size_t i = 0; i < count; i++) {
        s11 += w[i] * x1[i] * x1[i];
        s12 += w[i] * x1[i] * x2[i];
        s22 += w[i] * x2[i] * x2[i];
        s1y += w[i] * x1[i] * y[i];
        s2y += w[i] * x2[i] * y[i];
    }
    double det = s11 * s22 - s12 * s12;
    if (!(fabs(det) > 1e-12 * s11 * s22))   /* also NaN */
        return -1;
    c[0] = (s1y * s22 - s2y * s12) / det;
    c[1] = (s11 * s2y - s12 * s1y) / det;
    if (chi2) {
        *chi2 = 0.0;
        for (size_t i = 0; i < count; i++) {
            double e = y[i] - c[0] * x1[i] - c[1] * x2[i];
            *chi2 += w[i] * e * e;
        }
    }
    return 0;
}

vfy_verdict vfy_cost_check_stat_scaling(vfy_report *r, const char *name, const double *conf1,
                                        const double *conf2, size_t count, size_t N1, size_t N2,
                                        int nested, double zmax, double *ratio)
{
    double s = 0.0;
    for (size_t i = 0; i < count; i++)
        s += log(conf1[i] / conf2[i]);
    double R = count ? exp(s / (double)count) / sqrt((double)N2 / (double)N1) : NAN;
    const double inv = 1.0 / (double)N1 + (nested ? -1.0 : 1.0) / (double)N2;
    double sd = sqrt((2.0 + VFY_COST_KURTOSIS) / 4.0 * inv / (double)count);
    if (ratio)
        *ratio = R;
    /* vfy_check_range fails NaN too (N2 <= N1 gives a NaN sd) */
    return vfy_check_range(r, name, N2 > N1 ? R : NAN, 1.0 - zmax * sd, 1.0 + zmax * sd);
}

vfy_verdict vfy_cost_check_model(vfy_report *r, const char *name, const double *err,
                                 const double *model, size_t count, double factor,
                                 double *worst)
{
    double w = 1.0, wl = 0.0;
    for (size_t i = 0; i < count; i++) {
        double l = fabs(log(err[i] / model[i]));
        if (!(l <= wl)) {   /* NaN becomes the worst, and stays */
            wl = l;
            w = err[i] / model[i];
            if (isnan(l))
                break;
        }
    }
    if (worst)
        *worst = w;
    return vfy_check_range(r, name, w, 1.0 / factor, factor);
}

vfy_verdict vfy_cost_check_chi2(vfy_report *r, const char *name, double chi2, size_t dof)
{
    if (dof < 1) {
        vfy_skip(r, name, "no degrees of freedom left (as many rows as fitted parameters)");
        return VFY_SKIP;
    }
    return vfy_check_range(r, name, chi2, 0.0, gsl_cdf_chisq_Qinv(VFY_TOL_COST_CHI2_P, (double)dof));
}

/* ------------------------------------------------------------ helpers */

/* Conf from the fitted variance model, Conf^2 N = A/n + B/n^2. */
static double conf_model(const double AB[2], double n, double N)
{
    return sqrt((AB[0] / n + AB[1] / (n * n)) / N);
}

/* Fit Conf^2 N = A/n + B/n^2 to the points (relative least squares); keep
 * B = 0 if the fit would make the variance negative at the smallest n.
 * Returns 0, or -1 when out of memory. */
static int fit_conf(size_t count, const double *n, const double *N, const double *conf,
                    double AB[2])
{
    double *buf = calloc(4 * (count ? count : 1), sizeof *buf);
    if (buf == NULL)
        return -1;
    double *x1 = buf, *x2 = x1 + count, *y = x2 + count, *w = y + count;
    double n_min = INFINITY;
    for (size_t i = 0; i < count; i++) {
        x1[i] = 1.0 / n[i];
        x2[i] = 1.0 / (n[i] * n[i]);
        y[i] = conf[i] * conf[i] * N[i];
        w[i] = 1.0 / (y[i] * y[i]);
        n_min = fmin(n_min, n[i]);
    }
    if (vfy_cost_lsq2(count, x1, x2, y, w, AB, NULL) != 0 || !(AB[0] > 0.0)
        || !(AB[0] + AB[1] / n_min > 0.0)) {
        double s = 0.0;   /* A alone: the mean of y n, relative weights */
        for (size_t i = 0; i < count; i++)
            s += y[i] * n[i];
        AB[0] = s / (double)count;
        AB[1] = 0.0;
    }
    free(buf);
    return 0;
}

/* The targets table's cells for one point, or empty cells. */
static void target_cells(vfy_table *t, int present, const char *scheme, size_t n, size_t N,
                         double h, double err, double cpu)
{
    if (scheme)
        vfy_table_cell(t, "%s", present ? scheme : "");
    vfy_table_number(t, present, "%.0f", (double)n);
    vfy_table_number(t, present, "%.0f", (double)N);
    if (scheme)
        vfy_table_number(t, present && h > 0.0, "%g", h);
    vfy_table_number(t, present, "%.2e", err);
    vfy_table_number(t, present, "%.3g", cpu);
}

/* ------------------------------------------------ Maxwell kernels: n x N */

/* max_m |E xi^(n) - F| / F of the scene at n particles (exact, references):
 * the systematic part of Err, beyond the grid for the predictions. */
static sim_status exact_sys(const char *exact_name, const char *finite_name,
                            const sim_scene *scene, size_t n, double *sys, char *msg,
                            size_t msglen)
{
    sim_scene s = *scene;
    vfy_refs refs;
    sim_error err;
    s.particles.n = n;
    sim_status status = vfy_scene_references(&s, &refs, &err);
    if (status != SIM_OK) {
        vfy_scene_format_error(&s, &err, msg, msglen);
        return status;
    }
    const double *exact = vfy_refs_column(&refs, exact_name);
    const double *finite = vfy_refs_column(&refs, finite_name);
    if (exact == NULL || finite == NULL) {
        snprintf(msg, msglen, "%s: no %s and %s references for this scene", s.file, exact_name,
                 finite_name);
        status = SIM_EINVAL;
    } else
        *sys = vfy_max_rel_err(finite, exact, refs.outputs);
    vfy_refs_free(&refs);
    return status;
}

/* The grid's distinct values of `name` (n, the slowest, or N), in order: an
 * array the caller frees (NULL when out of memory), *count of them. */
static double *grid_axis(const vfy_case_run *run, const char *name, size_t *count)
{
    double *axis = malloc((run->nrows ? run->nrows : 1) * sizeof *axis);
    *count = 0;
    for (size_t i = 0; axis != NULL && i < run->nrows; i++) {
        const double v = vfy_values_get(&run->rows[i].values, name);
        size_t k = 0;
        while (k < *count && axis[k] != v)
            k++;
        if (k == *count)
            axis[(*count)++] = v;
    }
    return axis;
}

/* One target's words of the notes' summary ("1e-02: n = ..."). */
static void summary_target(vfy_text *summary, size_t t, double target, int measured,
                           int predicted, double n, double N, double cpu)
{
    const char *sep = t ? "; " : "";
    if (measured)
        vfy_text_printf(summary, "%s%.0e: n = %.0f, N = %.0f (%.3g CPU s)", sep, target, n, N,
                        cpu);
    else if (predicted)
        vfy_text_printf(summary, "%s%.0e: not in the grid; predicted n = %.0f, N = %.0f "
                        "(%.3g CPU s)", sep, target, n, N, cpu);
    else
        vfy_text_printf(summary, "%s%.0e: not in the grid nor below n = 2^24", sep, target);
}

/* The Maxwell grid of grid_model: its axes, its points as arrays in row
 * order, and the model's predictions. */
enum { G_N, G_NN, G_ERR, G_SYS, G_STAT, G_CONF, G_CPU, G_MODEL, G_CONF_FIT, G_ARRAYS };
typedef struct grid {
    size_t P, nn, nN;
    double *ns, *Ns;           /* the distinct n (slowest) and N, in order */
    double *g[G_ARRAYS];       /* P each, one allocation (g[0]) */
    double violations;         /* NaN where a solver did not report them */
    double AB[2], k, kappa, lo, hi, cpu_dev;
    size_t np;                 /* predictions: n = n_min 2^j up to 2^24, N among the grid's */
    double *pn, *pN, *perr, *pcost;   /* np each, one allocation (pn) */
} grid;

static void grid_free(grid *gr)
{
    free(gr->ns);
    free(gr->Ns);
    free(gr->g[0]);
    free(gr->pn);
    *gr = (grid){0};
}

/* The targets table: the cheapest measured point and the model's
 * prediction per target, the figure's predictions and the summary line of
 * the notes. */
static void grid_targets(vfy_case_run *run, const grid *gr, vfy_wp_prediction *pred,
                         vfy_text *summary)
{
    static const char *const tcols[] = {
        "target", "grid", "n", "N", "Err", "cpu_s", "predicted_n", "predicted_N",
        "predicted_Err", "predicted_cpu_s"};
    vfy_table *tg = &run->second;
    vfy_table_init(tg, sizeof tcols / sizeof *tcols, tcols);
    const size_t P = gr->P, np = gr->np;
    const double *gn = gr->g[G_N], *gN = gr->g[G_NN], *err = gr->g[G_ERR], *cpu = gr->g[G_CPU];
    for (size_t t = 0; t < VFY_WP_TARGETS; t++) {
        const double target = vfy_wp_targets[t];
        size_t i = vfy_cost_cheapest(err, cpu, P, target);
        size_t j = vfy_cost_cheapest(gr->perr, gr->pcost, np, target);
        if (j < np) {
            pred->cpu[pred->count] = gr->pcost[j];
            pred->err[pred->count] = gr->perr[j];
            pred->label[pred->count++] = vfy_aprintf("%.0e: n=%.0f N=%.0f", target, gr->pn[j],
                                                     gr->pN[j]);
        }
        vfy_table_cell(tg, "%.0e", target);
        vfy_table_cell(tg, "%s", i < P ? "reached" : "not reached in the grid");
        target_cells(tg, i < P, NULL, i < P ? (size_t)gn[i] : 0, i < P ? (size_t)gN[i] : 0, 0.0,
                     i < P ? err[i] : NAN, i < P ? cpu[i] : NAN);
        target_cells(tg, j < np, NULL, j < np ? (size_t)gr->pn[j] : 0,
                     j < np ? (size_t)gr->pN[j] : 0, 0.0, j < np ? gr->perr[j] : NAN,
                     j < np ? gr->pcost[j] : NAN);
        if (i < P)
            summary_target(summary, t, target, 1, 0, gn[i], gN[i], cpu[i]);
        else
            summary_target(summary, t, target, 0, j < np, j < np ? gr->pn[j] : 0.0,
                           j < np ? gr->pN[j] : 0.0, j < np ? gr->pcost[j] : 0.0);
    }
}

/* The grid's points from the rows, with its axes; SIM_EINVAL when it is not
 * every n with every N. */
static sim_status grid_load(const vfy_case_run *run, grid *gr, char *msg, size_t msglen)
{
    const size_t P = gr->P = run->nrows;
    gr->ns = grid_axis(run, "n", &gr->nn);
    gr->Ns = grid_axis(run, "N", &gr->nN);
    gr->g[0] = calloc(G_ARRAYS * (P ? P : 1), sizeof *gr->g[0]);
    if (gr->ns == NULL || gr->Ns == NULL || gr->g[0] == NULL) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    if (gr->nn * gr->nN != P) {
        snprintf(msg, msglen, "%s: grid of %zu points is not %zu x %zu (every n with every N)",
                 run->c->name, P, gr->nn, gr->nN);
        return SIM_EINVAL;
    }
    for (size_t k = 1; k < G_ARRAYS; k++)
        gr->g[k] = gr->g[0] + k * P;
    static const char *const names[] = {"n", "N", "Err", "Err_sys", "Err_stat", "Conf",
                                        "cpu_s"};
    for (size_t i = 0; i < P; i++) {
        for (size_t k = 0; k < sizeof names / sizeof *names; k++)
            gr->g[k][i] = vfy_values_get(&run->rows[i].values, names[k]);
        gr->violations += vfy_values_get(&run->rows[i].values, "violations");
    }
    return SIM_OK;
}

/* The model over the grid (grid_model) into gr and the rows' values:
 * Conf_fit, k, Err_model, kappa and how far the CPU times stray from it. */
static int grid_fit(vfy_case_run *run, grid *gr)
{
    double **g = gr->g, lk = 0.0, work = 0.0, cpu_sum = 0.0;
    const size_t P = gr->P;
    if (fit_conf(P, g[G_N], g[G_NN], g[G_CONF], gr->AB) != 0)
        return -1;
    for (size_t i = 0; i < P; i++) {
        g[G_CONF_FIT][i] = conf_model(gr->AB, g[G_N][i], g[G_NN][i]);
        lk += log(g[G_STAT][i] / g[G_CONF_FIT][i]);
        work += g[G_N][i] * g[G_NN][i];
        cpu_sum += g[G_CPU][i];
    }
    const double k = gr->k = exp(lk / (double)P), kappa = gr->kappa = cpu_sum / work;
    gr->cpu_dev = 0.0;
    gr->lo = INFINITY;
    gr->hi = 0.0;
    for (size_t i = 0; i < P; i++) {
        const double model = hypot(g[G_SYS][i], k * g[G_CONF_FIT][i]);
        g[G_MODEL][i] = model;
        vfy_values_set(&run->rows[i].values, "Err_model", model);
        vfy_values_set(&run->rows[i].values, "Err_over_model", g[G_ERR][i] / model);
        gr->lo = fmin(gr->lo, g[G_ERR][i] / model);
        gr->hi = fmax(gr->hi, g[G_ERR][i] / model);
        if (g[G_CPU][i] >= 1.0)   /* shorter runs are dominated by start-up */
            gr->cpu_dev = fmax(gr->cpu_dev,
                               fabs(g[G_CPU][i] / (kappa * g[G_N][i] * g[G_NN][i]) - 1.0));
    }
    return 0;
}

/* Checks: the 1/sqrt(N) law of the statistical part, pooled over n for each
 * step of N; the model against the grid; no violations.  0, or -1 when out
 * of memory. */
static int grid_checks(vfy_case_run *run, const grid *gr, vfy_report *r)
{
    const size_t P = gr->P, nn = gr->nn, nN = gr->nN;
    double *const *g = gr->g;
    double *buf = malloc(2 * (P + nn) * sizeof *buf);
    if (buf == NULL)
        return -1;
    double *c1 = buf, *c2 = c1 + nn, *dom_err = c2 + nn, *dom_model = dom_err + P, ratio, worst;
    char *name;
    for (size_t b = 1; b < nN; b++) {
        for (size_t a = 0; a < nn; a++) {
            c1[a] = g[G_CONF][a * nN + b - 1];
            c2[a] = g[G_CONF][a * nN + b];
        }
        name = vfy_aprintf("%s Conf(N=%.0f)/Conf(N=%.0f) over sqrt(%.0f/%.0f), pooled over n",
                           run->c->name, gr->Ns[b - 1], gr->Ns[b], gr->Ns[b], gr->Ns[b - 1]);
        vfy_cost_check_stat_scaling(r, name ? name : run->c->name, c1, c2, nn,
                                    (size_t)gr->Ns[b - 1], (size_t)gr->Ns[b],
                                    !vfy_external(run->o), VFY_TOL_COST_Z, &ratio);
        free(name);
    }
    /* Judged where one part dominates (by VFY_TOL_COST_DOMINANCE): where the two are
     * comparable, noise of the opposite sign can cancel the bias and Err
     * fall far below either, which no smooth model follows. */
    size_t ndom = 0;
    for (size_t i = 0; i < P; i++) {
        double a = g[G_SYS][i], b2 = gr->k * g[G_CONF_FIT][i];
        if (fmax(a, b2) >= VFY_TOL_COST_DOMINANCE * fmin(a, b2)) {
            dom_err[ndom] = g[G_ERR][i];
            dom_model[ndom++] = g[G_MODEL][i];
        }
    }
    name = vfy_aprintf("%s Err/model where one part dominates (%zu of %zu points)",
                       run->c->name, ndom, P);
    if (ndom > 0)
        vfy_cost_check_model(r, name ? name : run->c->name, dom_err, dom_model, ndom,
                             VFY_TOL_COST_MODEL_FACTOR, &worst);
    else
        vfy_skip(r, name ? name : run->c->name, "no grid point where one part dominates");
    free(name);
    name = vfy_aprintf("%s majorant violations (all points)", run->c->name);
    vfy_check_zero(r, name ? name : run->c->name, gr->violations);
    free(name);
    free(buf);
    return 0;
}

/* The model's predictions: n = n_min 2^j up to 2^24, N among the grid's. */
static sim_status grid_predict(const vfy_case_run *run, grid *gr, char *msg, size_t msglen)
{
    const char *exact = run->d->needs[0], *finite = run->d->needs[1];
    size_t nvalues = 0;
    for (size_t n = (size_t)gr->ns[0]; n <= PRED_N_MAX; n *= 2)
        nvalues++;
    const size_t max = nvalues * gr->nN;
    if ((gr->pn = malloc(4 * (max ? max : 1) * sizeof *gr->pn)) == NULL) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    gr->pN = gr->pn + max;
    gr->perr = gr->pN + max;
    gr->pcost = gr->perr + max;
    sim_status status = SIM_OK;
    for (size_t n = (size_t)gr->ns[0]; n <= PRED_N_MAX && status == SIM_OK; n *= 2) {
        double s;
        status = exact_sys(exact, finite, &run->rows[0].scene, n, &s, msg, msglen);
        for (size_t b = 0; b < gr->nN && status == SIM_OK; b++, gr->np++) {
            const size_t q = gr->np;
            gr->pn[q] = (double)n;
            gr->pN[q] = gr->Ns[b];
            gr->perr[q] = hypot(s, gr->k * conf_model(gr->AB, gr->pn[q], gr->pN[q]));
            gr->pcost[q] = gr->kappa * gr->pn[q] * gr->pN[q];
        }
    }
    return status;
}

/* The work-precision figure: one curve per N (n grows). */
static int grid_figure(const vfy_case_run *run, const grid *gr, const vfy_wp_prediction *pred)
{
    const size_t P = gr->P, nn = gr->nn, nN = gr->nN;
    vfy_wp_series *series = calloc(nN ? nN : 1, sizeof *series);
    size_t *idx = malloc((P ? P : 1) * sizeof *idx);
    char **titles = calloc(nN + 1, sizeof *titles), **labels = calloc(P + 1, sizeof *labels);
    char *ftitle = vfy_aprintf("%s: Err against CPU time, %s", run->c->name,
                               run->d->checks[0].value);
    int rc = series && idx && titles && labels && ftitle ? 0 : -1;
    for (size_t b = 0; b < nN && rc == 0; b++) {
        rc = (titles[b] = vfy_aprintf("N = %.0f (n grows)", gr->Ns[b])) ? 0 : -1;
        series[b] = (vfy_wp_series){.title = titles[b], .idx = idx + b * nn, .count = nn};
        for (size_t a = 0; a < nn; a++)
            idx[b * nn + a] = a * nN + b;
    }
    for (size_t i = 0; i < P && rc == 0; i++)
        rc = (labels[i] = vfy_aprintf("n=%.0f", gr->g[G_N][i])) ? 0 : -1;
    if (rc == 0)
        rc = vfy_write_work_precision(run->o, run->c->name, ftitle, run->comment,
                                      "Err (relative, max norm over the output times)", series,
                                      nN, gr->g[G_CPU], gr->g[G_ERR], gr->g[G_MODEL],
                                      (const char *const *)labels, pred);
    for (size_t b = 0; titles && b < nN; b++)
        free(titles[b]);
    for (size_t i = 0; labels && i < P; i++)
        free(labels[i]);
    free(series);
    free(idx);
    free(titles);
    free(labels);
    free(ftitle);
    return rc;
}

/* After the grid (vfy_hook_fn): the model Err_model = sqrt(Err_sys^2 + (k
 * Conf_fit)^2) with Conf_fit^2 N = A/n + B/n^2 and k the geometric mean of
 * Err_stat/Conf_fit, cpu = kappa n N; its checks, the targets table and
 * the work-precision figure. */
static sim_status grid_model(vfy_case_run *run, vfy_report *r, char *msg, size_t msglen)
{
    grid gr = {0};
    vfy_wp_prediction pred = {0};
    vfy_text summary = {0};
    sim_status status = grid_load(run, &gr, msg, msglen);
    if (status == SIM_OK && (grid_fit(run, &gr) != 0 || grid_checks(run, &gr, r) != 0)) {
        snprintf(msg, msglen, "out of memory");
        status = SIM_ENOMEM;
    }
    if (status == SIM_OK)
        status = grid_predict(run, &gr, msg, msglen);
    if (status == SIM_OK) {
        grid_targets(run, &gr, &pred, &summary);
        if (run->o->progress)
            fprintf(run->o->progress, "   %s: cheapest per target: %s\n", run->c->name,
                    vfy_text_str(&summary));
        const double v[] = {gr.AB[0], gr.AB[1], gr.k, gr.lo, gr.hi, 1e6 * gr.kappa,
                            100.0 * gr.cpu_dev};
        static const char *const vnames[] = {"A", "B", "k", "ratio_lo", "ratio_hi", "kappa_us",
                                             "cpu_dev_percent"};
        for (size_t i = 0; i < sizeof vnames / sizeof *vnames; i++)
            vfy_values_set(&run->values, vnames[i], v[i]);
        run->second_suffix = "-targets";
        run->second_title = VFY_COST_TARGETS_TITLE;
    }
    if (status == SIM_OK
        && (summary.failed
            || vfy_run_second_notes(run,
             "grid: the cheapest measured point (least cpu_s) with Err <= target, or \"not "
             "reached in the grid\". predicted_*: the cheapest (n, N) by the model above "
             "(a prediction, not a measurement) over n = %.0f 2^j up to 2^24 and N among the "
             "grid's values (%.0f to %.0f). The cost kappa n N is linear in n while Err_sys "
             "falls as 1/n, so at a given n N the model always prefers more particles and "
             "fewer ensembles: the prediction sits at the grid's smallest N, and fewer "
             "ensembles than that would leave Var (and so the confidence interval) poorly "
             "estimated (among powers of two several (n, N) cost the same; the one with the "
             "smaller Err is shown). The model assumes kappa stays constant as n grows beyond the grid "
             "(memory effects are not modelled). Summary: %s.",
             gr.ns[0], gr.Ns[0], gr.Ns[gr.nN - 1], vfy_text_str(&summary)) != 0)) {
        snprintf(msg, msglen, "out of memory");
        status = SIM_ENOMEM;
    }
    if (status == SIM_OK && grid_figure(run, &gr, &pred) != 0)
        status = vfy_io_error(run->c->name, msg, msglen);
    vfy_wp_prediction_free(&pred);
    vfy_text_free(&summary);
    grid_free(&gr);
    return status;
}

/* ------------------------------------- hard spheres: jump and time step */

/* A row of the grid: the jump scheme at (n, N), or a splitting at step h. */
#define J(n, N) "jump n=" #n " N=" #N ": $scheme=jump;particles.n=" #n ";particles.ensembles=" #N
#define TS(SPLIT, n, N, h)                                                              \
    SPLIT " h=" #h " n=" #n " N=" #N ": scene.splitting=" SPLIT ";scene.dt=" #h           \
          ";particles.n=" #n ";particles.ensembles=" #N ";$scheme=" SPLIT ";$h=" #h
#define E(n, N, h) TS("euler", n, N, h)
#define S(n, N, h) TS("strang", n, N, h)
#undef J
#undef TS
#undef E
#undef S

enum { SCHEME_JUMP, SCHEME_EULER, SCHEME_STRANG };
static const char *const scheme_names[] = {"jump", "euler", "strang"};

/* The splitting model c1 h^p + c2 h^(p+1) (p = 1 Euler, 2 Strang). */
static double split_model(const double c[2], int scheme, double h)
{
    double p = scheme == SCHEME_STRANG ? 2.0 : 1.0;
    return c[0] * pow(h, p) + c[1] * pow(h, p + 1.0);
}

#define SPLIT_TARGET_NOTES                                                             \
    "grid: the cheapest measured row (least cpu_s) whose Err_hi <= target (reached with "  \
    "99.9% confidence: a small Err by itself may be luck, or the O(1/n) and splitting "    \
    "biases cancelling, and the reference's own half-width is {T_inf_rel_ci:%.1e}), or "   \
    "\"not reached in the grid\". predicted_*: the cheapest (scheme, n, N, h) by the "     \
    "model above (a prediction, not a measurement) over n = {n_min:%.0f} 2^j up to 2^24, " \
    "N among the grid's values and h = {h_max:%g} 2^-j (j <= 12). As for the Maxwell "     \
    "cases, cost linear in n N and a bias falling as 1/n favour many particles and few "   \
    "ensembles. The jump scheme has no splitting error; per particle and ensemble it "     \
    "costs {kappa_us:%.3g} us here, the time-step scheme {per_h_max_us:%.3g} us at h = "    \
    "{h_max:%g} and {per_h_min_us:%.3g} us at h = {h_min:%g} (the model a + g/h), so the " \
    "time step pays off only where its step is large enough to be cheaper and small "      \
    "enough for the target. Summary: {summary}."

/* Everything the cost-split hook derives from the rows: P of each array,
 * the doubles in one allocation (n), zeroed. */
typedef struct split_fit {
    size_t P;
    int *scheme;
    double *n, *N, *h, *T, *Tci, *cpu;
    double T_inf, b, cov00, cov01, cov11, T_inf_ci;   /* T̄_jump(n) = T̄_inf + b/n */
    double csplit[2][2];                               /* Euler, Strang */
    int have_split[2];
    double *dsplit, *dsplit_ci;                        /* time-step rows: measured */
    double *err, *err_hi, *model, *fit_mean;
    double AB[2], kappa, ag[2];                        /* Conf model; CPU models */
} split_fit;

/* f's arrays for P rows; 0, or -1 when out of memory (nothing held). */
static int split_fit_alloc(split_fit *f, size_t P)
{
    double **arrays[] = {&f->n,      &f->N,         &f->h,   &f->T,      &f->Tci,
                         &f->cpu,    &f->dsplit,    &f->dsplit_ci,       &f->err,
                         &f->err_hi, &f->model,     &f->fit_mean};
    const size_t count = sizeof arrays / sizeof *arrays, rows = P ? P : 1;
    *f = (split_fit){.P = P};
    f->scheme = calloc(rows, sizeof *f->scheme);
    double *block = calloc(count * rows, sizeof *block);
    if (f->scheme == NULL || block == NULL) {
        free(f->scheme);
        free(block);
        return -1;
    }
    for (size_t k = 0; k < count; k++)
        *arrays[k] = block + k * rows;
    return 0;
}

static void split_fit_free(split_fit *f)
{
    free(f->scheme);
    free(f->n);   /* the block of every double array */
}

/* The reference T̄_inf + b/n from the jump rows (its chi^2 judged) and each
 * splitting's error c1 h^p + c2 h^(p+1) fitted to its rows' difference from
 * it, with the variance of the row and of the reference. */
static sim_status split_fits(vfy_case_run *run, split_fit *f, vfy_report *r, char *msg,
                             size_t msglen)
{
    double *buf = malloc(7 * (f->P ? f->P : 1) * sizeof *buf), chi2_jump;
    if (buf == NULL) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    double *x = buf, *y = x + f->P, *w = y + f->P, *x1 = w + f->P, *x2 = x1 + f->P;
    double *ds = x2 + f->P, *ws = ds + f->P;
    size_t nj = 0;
    char *name;
    for (size_t i = 0; i < f->P; i++) {
        if (f->scheme[i] != SCHEME_JUMP)
            continue;
        double sigma = f->Tci[i] / SIM_LAMBDA_P;
        x[nj] = 1.0 / f->n[i];
        y[nj] = f->T[i];
        w[nj++] = 1.0 / (sigma * sigma);
    }
    if (nj < 2 || gsl_fit_wlinear(x, 1, w, 1, y, 1, nj, &f->T_inf, &f->b, &f->cov00, &f->cov01,
                                  &f->cov11, &chi2_jump) != 0) {
        snprintf(msg, msglen, "%s: the O(1/n) fit needs jump rows at two n at least",
                 run->c->name);
        free(buf);
        return SIM_EINVAL;
    }
    for (size_t k = 0; k < nj; k++)   /* gsl passes over NaN weights: no chi^2 of them */
        if (!isfinite(y[k]) || !isfinite(w[k]))
            chi2_jump = NAN;
    f->T_inf_ci = SIM_LAMBDA_P * sqrt(f->cov00);
    name = vfy_aprintf("%s jump rows: O(1/n) fit chi^2 (%zu rows)", run->c->name, nj);
    vfy_cost_check_chi2(r, name ? name : run->c->name, chi2_jump, nj - 2);
    free(name);
    vfy_values_set(&run->values, "nj", (double)nj);
    vfy_values_set(&run->values, "chi2_jump", chi2_jump);
    for (int sp = 0; sp < 2; sp++) {
        const int scheme = sp ? SCHEME_STRANG : SCHEME_EULER;
        const double p = sp ? 2.0 : 1.0;
        double chi2;
        size_t m = 0;
        for (size_t i = 0; i < f->P; i++) {
            if (f->scheme[i] != scheme)
                continue;
            double sigma = f->Tci[i] / SIM_LAMBDA_P, xn = 1.0 / f->n[i];
            double var = sigma * sigma + f->cov00 + 2.0 * f->cov01 * xn + f->cov11 * xn * xn;
            f->dsplit[i] = f->T[i] - (f->T_inf + f->b * xn);
            f->dsplit_ci[i] = SIM_LAMBDA_P * sqrt(var);
            x1[m] = pow(f->h[i], p);
            x2[m] = pow(f->h[i], p + 1.0);
            ds[m] = f->dsplit[i];
            ws[m++] = 1.0 / var;
        }
        if (m == 0)
            continue;
        name = vfy_aprintf("%s %s: splitting-error fit c1 h^%g + c2 h^%g, chi^2 (%zu rows)",
                           run->c->name, scheme_names[scheme], p, p + 1.0, m);
        if (vfy_cost_lsq2(m, x1, x2, ds, ws, f->csplit[sp], &chi2) != 0) {
            vfy_skip(r, name ? name : run->c->name, "fewer than two distinct steps: no fit");
        } else {
            f->have_split[sp] = 1;
            vfy_cost_check_chi2(r, name ? name : run->c->name, chi2, m - 2);
        }
        free(name);
    }
    free(buf);
    return SIM_OK;
}

/* Each row's parts of Err, the model, the residual z-test, and the CPU
 * models: kappa n N (jump rows), n N (a + g/h) (time-step rows).  0, or -1
 * when out of memory. */
static int split_parts(vfy_case_run *run, split_fit *f, vfy_report *r)
{
    double *buf = calloc(5 * (f->P ? f->P : 1), sizeof *buf);
    if (buf == NULL)
        return -1;
    double *conf = buf, *one = conf + f->P, *inv_h = one + f->P, *per = inv_h + f->P;
    double *wc = per + f->P;
    for (size_t i = 0; i < f->P; i++)
        conf[i] = f->Tci[i] / f->T_inf;
    if (fit_conf(f->P, f->n, f->N, conf, f->AB) != 0) {
        free(buf);
        return -1;
    }
    const double k_scalar = sqrt(2.0 / M_PI) / SIM_LAMBDA_P;   /* E|Z| in units of Conf */
    for (size_t i = 0; i < f->P; i++) {
        vfy_row *row = &run->rows[i];
        const int ts = f->scheme[i] != SCHEME_JUMP, sp = f->scheme[i] == SCHEME_STRANG;
        double split_signed = ts && f->have_split[sp]
                                  ? split_model(f->csplit[sp], f->scheme[i], f->h[i]) : 0.0;
        f->fit_mean[i] = f->T_inf + f->b / f->n[i] + split_signed;
        f->err[i] = fabs(f->T[i] - f->T_inf) / f->T_inf;
        /* the reference is itself measured: Err's 99.9% upper bound */
        f->err_hi[i] = f->err[i] + hypot(f->Tci[i], f->T_inf_ci) / f->T_inf;
        const double sys = fabs(f->b / f->n[i]) / f->T_inf, spl = fabs(split_signed) / f->T_inf;
        f->model[i] = hypot(sys + spl, k_scalar * conf_model(f->AB, f->n[i], f->N[i]));
        const double v[] = {f->err[i], f->err_hi[i], sys, ts ? spl : NAN,
                            fabs(f->T[i] - f->fit_mean[i]) / f->T_inf, conf[i],
                            ts ? f->dsplit[i] / f->T_inf : NAN,
                            ts ? f->dsplit_ci[i] / f->T_inf : NAN, f->model[i]};
        static const char *const names[] = {"Err", "Err_hi", "Err_sys", "Err_split",
                                            "Err_stat", "Conf", "split_meas", "split_meas_ci",
                                            "Err_model"};
        for (size_t k = 0; k < sizeof names / sizeof *names; k++)
            vfy_values_set(&row->values, names[k], v[k]);
    }
    double zmax;
    char *name = vfy_aprintf("%s every row vs the fitted model T_inf + b/n + splitting",
                             run->c->name);
    vfy_check_zscore(r, name ? name : run->c->name, f->T, f->Tci, f->fit_mean, f->P,
                     VFY_TOL_COST_Z, &zmax);
    free(name);
    vfy_values_set(&run->values, "zmax", zmax);

    double kappa_num = 0.0, kappa_den = 0.0;
    size_t m = 0;
    f->ag[0] = NAN;
    f->ag[1] = 0.0;
    for (size_t i = 0; i < f->P; i++) {
        if (f->scheme[i] == SCHEME_JUMP) {
            kappa_num += f->cpu[i];
            kappa_den += f->n[i] * f->N[i];
            continue;
        }
        one[m] = 1.0;
        inv_h[m] = 1.0 / f->h[i];
        per[m] = f->cpu[i] / (f->n[i] * f->N[i]);
        wc[m] = 1.0 / (per[m] * per[m]);
        m++;
    }
    if (m > 0 && (vfy_cost_lsq2(m, one, inv_h, per, wc, f->ag, NULL) != 0 || !(f->ag[1] >= 0.0)
                  || !(f->ag[0] > 0.0))) {
        double s = 0.0;
        for (size_t i = 0; i < m; i++)
            s += per[i];
        f->ag[0] = s / (double)m;
        f->ag[1] = 0.0;
    }
    f->kappa = kappa_num / kappa_den;
    free(buf);
    return 0;
}

/* The model's predictions: n = n_min 2^j up to 2^24, N among the grid's,
 * the jump scheme or a splitting at h = h_max 2^-j; count of each array,
 * the doubles in one allocation (err). */
typedef struct split_predictions {
    size_t count;
    double *err, *cost, *n, *N, *h;
    int *scheme;
} split_predictions;

static void split_predictions_free(split_predictions *pr)
{
    free(pr->err);
    free(pr->scheme);
    *pr = (split_predictions){0};
}

/* 0, or -1 when out of memory. */
static int split_predict(const split_fit *f, double n_min, double h_max,
                         split_predictions *pr)
{
    double *Nvals = malloc((f->P ? f->P : 1) * sizeof *Nvals);
    size_t nNv = 0, nvalues = 0;
    for (size_t i = 0; Nvals != NULL && i < f->P; i++) {
        size_t v = 0;
        while (v < nNv && Nvals[v] != f->N[i])
            v++;
        if (v == nNv)
            Nvals[nNv++] = f->N[i];
    }
    for (double n = n_min; n <= (double)PRED_N_MAX; n *= 2.0)
        nvalues++;
    const size_t per_point = 1 + (size_t)(f->have_split[0] + f->have_split[1])
                                     * (PRED_H_HALVINGS + 1);
    const size_t max = nvalues * nNv * per_point + 1;
    *pr = (split_predictions){0};
    pr->err = malloc(5 * max * sizeof *pr->err);
    pr->scheme = malloc(max * sizeof *pr->scheme);
    if (Nvals == NULL || pr->err == NULL || pr->scheme == NULL) {
        free(Nvals);
        split_predictions_free(pr);
        return -1;
    }
    pr->cost = pr->err + max;
    pr->n = pr->cost + max;
    pr->N = pr->n + max;
    pr->h = pr->N + max;
    const double k_scalar = sqrt(2.0 / M_PI) / SIM_LAMBDA_P;
    for (double n = n_min; n <= (double)PRED_N_MAX; n *= 2.0) {
        for (size_t v = 0; v < nNv; v++) {
            const double N = Nvals[v], cstat = k_scalar * conf_model(f->AB, n, N);
            const double sys_n = fabs(f->b / n) / f->T_inf;
            for (int sch = 0; sch < 3; sch++) {
                if (sch > 0 && !f->have_split[sch - 1])
                    continue;
                for (int j = 0; j <= (sch ? PRED_H_HALVINGS : 0); j++) {
                    const size_t q = pr->count++;
                    double h = sch ? h_max / (double)(1u << j) : 0.0;
                    double s = sch ? fabs(split_model(f->csplit[sch - 1], sch, h)) / f->T_inf
                                   : 0.0;
                    pr->n[q] = n;
                    pr->N[q] = N;
                    pr->h[q] = h;
                    pr->scheme[q] = sch;
                    pr->err[q] = hypot(sys_n + s, cstat);
                    pr->cost[q] = n * N * (sch ? f->ag[0] + f->ag[1] / h : f->kappa);
                }
            }
        }
    }
    free(Nvals);
    return 0;
}

/* The targets table (the cheapest measured row whose Err_hi reaches each
 * target, and the model's prediction), the figure's predictions and the
 * summary line. */
static void split_targets(vfy_case_run *run, const split_fit *f, const split_predictions *pr,
                          vfy_wp_prediction *pred, vfy_text *summary)
{
    static const char *const tcols[] = {
        "target", "grid", "scheme", "n", "N", "h", "Err_hi", "cpu_s", "predicted_scheme",
        "predicted_n", "predicted_N", "predicted_h", "predicted_Err", "predicted_cpu_s"};
    vfy_table *tg = &run->second;
    vfy_table_init(tg, sizeof tcols / sizeof *tcols, tcols);
    const size_t P = f->P, np = pr->count;
    for (size_t t = 0; t < VFY_WP_TARGETS; t++) {
        const double target = vfy_wp_targets[t];
        size_t i = vfy_cost_cheapest(f->err_hi, f->cpu, P, target);
        size_t j = vfy_cost_cheapest(pr->err, pr->cost, np, target);
        if (j < np) {
            pred->cpu[pred->count] = pr->cost[j];
            pred->err[pred->count] = pr->err[j];
            if (pr->scheme[j])
                pred->label[pred->count++] = vfy_aprintf("%.0e: %s n=%.0f N=%.0f h=%g", target,
                                                         scheme_names[pr->scheme[j]], pr->n[j],
                                                         pr->N[j], pr->h[j]);
            else
                pred->label[pred->count++] = vfy_aprintf("%.0e: jump n=%.0f N=%.0f", target,
                                                         pr->n[j], pr->N[j]);
        }
        vfy_table_cell(tg, "%.0e", target);
        vfy_table_cell(tg, "%s", i < P ? "reached" : "not reached in the grid");
        target_cells(tg, i < P, i < P ? scheme_names[f->scheme[i]] : "",
                     i < P ? (size_t)f->n[i] : 0, i < P ? (size_t)f->N[i] : 0,
                     i < P && f->scheme[i] ? f->h[i] : 0.0, i < P ? f->err_hi[i] : NAN,
                     i < P ? f->cpu[i] : NAN);
        target_cells(tg, j < np, j < np ? scheme_names[pr->scheme[j]] : "",
                     j < np ? (size_t)pr->n[j] : 0, j < np ? (size_t)pr->N[j] : 0,
                     j < np ? pr->h[j] : 0.0, j < np ? pr->err[j] : NAN,
                     j < np ? pr->cost[j] : NAN);
        char hs[40] = "";   /* ", h = " and one %g */
        if (i < P && f->scheme[i])
            snprintf(hs, sizeof hs, ", h = %g", f->h[i]);
        else if (i == P && j < np && pr->h[j] > 0.0)
            snprintf(hs, sizeof hs, ", h = %g", pr->h[j]);
        const char *sep = t ? "; " : "";
        if (i < P)
            vfy_text_printf(summary, "%s%.0e: %s n = %.0f, N = %.0f%s (%.3g CPU s)", sep, target,
                            scheme_names[f->scheme[i]], f->n[i], f->N[i], hs, f->cpu[i]);
        else if (j < np)
            vfy_text_printf(summary, "%s%.0e: not in the grid; predicted %s n = %.0f, N = "
                            "%.0f%s (%.3g CPU s)", sep, target, scheme_names[pr->scheme[j]],
                            pr->n[j], pr->N[j], hs, pr->cost[j]);
        else
            vfy_text_printf(summary, "%s%.0e: not in the grid nor below n = 2^24", sep,
                            target);
    }
}

/* Whether rows q and i of the fit draw as one curve: jump rows of the same
 * N, or time-step rows of the same splitting, n and N. */
static int same_series(const split_fit *f, size_t q, size_t i)
{
    return (f->scheme[q] == SCHEME_JUMP) == (f->scheme[i] == SCHEME_JUMP) && f->N[q] == f->N[i]
           && (f->scheme[q] == SCHEME_JUMP
               || (f->scheme[q] == f->scheme[i] && f->n[q] == f->n[i]));
}

/* The figure's series, in the order their first rows come: idx holds each
 * series' rows in row order (offsets in series[s].idx), titles their
 * titles, labels each row's label; returns the count of series, or 0 when
 * out of memory. */
static size_t split_series(const split_fit *f, vfy_wp_series *series, size_t *idx,
                           size_t *first, size_t *of, char **titles, char **labels)
{
    size_t nseries = 0;
    for (size_t i = 0; i < f->P; i++) {   /* each row's series, and each series' first row */
        size_t s = 0;
        while (s < nseries && !same_series(f, first[s], i))
            s++;
        if (s == nseries) {
            first[nseries++] = i;
            titles[s] = f->scheme[i] == SCHEME_JUMP
                            ? vfy_aprintf("jump, N = %.0f (n grows)", f->N[i])
                            : vfy_aprintf("%s, n = %.0f, N = %.0f (h shrinks)",
                                          scheme_names[f->scheme[i]], f->n[i], f->N[i]);
            series[s] = (vfy_wp_series){.title = titles[s]};
            if (titles[s] == NULL)
                return 0;
        }
        of[i] = s;
        series[s].count++;
        labels[i] = f->scheme[i] == SCHEME_JUMP ? vfy_aprintf("n=%.0f", f->n[i])
                                                : vfy_aprintf("h=%g", f->h[i]);
        if (labels[i] == NULL)
            return 0;
    }
    size_t at = 0;
    for (size_t s = 0; s < nseries; s++) {
        series[s].idx = idx + at;
        at += series[s].count;
        series[s].count = 0;
    }
    for (size_t i = 0; i < f->P; i++)
        idx[series[of[i]].idx - idx + series[of[i]].count++] = i;
    return nseries;
}

/* The figure: the jump rows by N (n grows), the time-step rows by
 * (splitting, n, N) (h shrinks). */
static int split_figure(const vfy_case_run *run, const split_fit *f,
                        const vfy_wp_prediction *pred)
{
    const size_t P = f->P ? f->P : 1;
    vfy_wp_series *series = calloc(P, sizeof *series);
    size_t *idx = malloc(3 * P * sizeof *idx);
    char **titles = calloc(P, sizeof *titles), **labels = calloc(P, sizeof *labels);
    char *ftitle = vfy_aprintf("%s: Err of the time-averaged T against CPU time",
                               run->c->name);
    int rc = -1;
    size_t nseries = 0;
    if (series && idx && titles && labels && ftitle
        && (nseries = split_series(f, series, idx, idx + P, idx + 2 * P, titles, labels)) > 0)
        rc = vfy_write_work_precision(run->o, run->c->name, ftitle, run->comment,
                                      "Err = |T - T_inf| / T_inf (time-averaged T)", series,
                                      nseries, f->cpu, f->err, f->model,
                                      (const char *const *)labels, pred);
    for (size_t i = 0; i < f->P; i++) {
        free(titles ? titles[i] : NULL);
        free(labels ? labels[i] : NULL);
    }
    free(series);
    free(idx);
    free(titles);
    free(labels);
    free(ftitle);
    return rc;
}

/* The rows into the fit's arrays; the violations summed, the candidates and
 * collisions by kind of row (jump, time step), the smallest n and the
 * largest h. */
static void split_load(const vfy_case_run *run, split_fit *f, double *violations,
                       double cand[2], double coll[2], double *n_min, double *h_max)
{
    for (size_t i = 0; i < f->P; i++) {
        const vfy_row *row = &run->rows[i];
        const char *scheme = vfy_row_text(row, "scheme");
        f->scheme[i] = strcmp(scheme, "jump") == 0     ? SCHEME_JUMP
                       : strcmp(scheme, "strang") == 0 ? SCHEME_STRANG
                                                       : SCHEME_EULER;
        f->n[i] = vfy_values_get(&row->values, "n");
        f->N[i] = vfy_values_get(&row->values, "N");
        f->h[i] = vfy_values_get(&row->values, "h");
        f->T[i] = vfy_values_get(&row->values, "T");
        f->Tci[i] = vfy_values_get(&row->values, "T_ci");
        f->cpu[i] = vfy_values_get(&row->values, "cpu_s");
        *violations += vfy_values_get(&row->values, "violations");
        cand[f->scheme[i] != SCHEME_JUMP] += vfy_values_get(&row->values, "events");
        coll[f->scheme[i] != SCHEME_JUMP] += vfy_values_get(&row->values, "collisions");
        *n_min = fmin(*n_min, f->n[i]);
        if (f->scheme[i] != SCHEME_JUMP)
            *h_max = fmax(*h_max, f->h[i]);
    }
}

/* The case values the notes name, and its texts: the summary and the
 * second table's notes.  0, or -1 when out of memory. */
static int split_notes(vfy_case_run *run, const split_fit *f, double T_sonine,
                       const double cand[2], const double coll[2], double n_min, double h_max,
                       const char *summary)
{
    const double H = (double)(1u << PRED_H_HALVINGS);
    const double v[] = {f->T_inf, f->T_inf_ci, f->b, T_sonine, f->csplit[0][0],
                        f->csplit[0][1], f->csplit[1][0], f->csplit[1][1], f->AB[0],
                        f->AB[1], f->T_inf_ci / f->T_inf, 1e6 * f->kappa, 1e6 * f->ag[0],
                        1e6 * f->ag[1], cand[0] / coll[0], cand[1] / coll[1], n_min, h_max,
                        1e6 * (f->ag[0] + f->ag[1] / h_max),
                        1e6 * (f->ag[0] + f->ag[1] * H / h_max), h_max / H,
                        run->rows[0].solver.steady.from, run->rows[0].solver.t_end};
    static const char *const names[] = {
        "T_inf", "T_inf_ci", "b", "T_sonine", "c1_euler", "c2_euler", "c1_strang",
        "c2_strang", "A", "B", "T_inf_rel_ci", "kappa_us", "a_us", "g_us",
        "cand_per_coll_jump", "cand_per_coll_ts", "n_min", "h_max", "per_h_max_us",
        "per_h_min_us", "h_min", "steady_from", "t_end"};
    for (size_t k = 0; k < sizeof names / sizeof *names; k++)
        vfy_values_set(&run->values, names[k], v[k]);
    if (vfy_run_set_text(run, "summary", summary) != 0)
        return -1;
    run->second_suffix = "-targets";
    run->second_title = VFY_COST_TARGETS_TITLE;
    free(run->second_notes);
    run->second_notes = vfy_expand_alloc(SPLIT_TARGET_NOTES, run, NULL);
    return run->second_notes != NULL ? 0 : -1;
}

/* After the rows (vfy_hook_fn): the reference, the fits, each row's parts
 * and model, the CPU models, the targets and the figure. */
static sim_status split_cost_model(vfy_case_run *run, vfy_report *r, char *msg, size_t msglen)
{
    split_fit f;
    split_predictions pr = {0};
    vfy_wp_prediction pred = {0};
    vfy_text summary = {0};
    if (split_fit_alloc(&f, run->nrows) != 0) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    double violations = 0.0;   /* NaN where a solver did not report them */
    double cand[2] = {0, 0}, coll[2] = {0, 0}, n_min = INFINITY, h_max = 0.0;
    split_load(run, &f, &violations, cand, coll, &n_min, &h_max);
    char *name = vfy_aprintf("%s majorant violations (all rows)", run->c->name);
    vfy_check_zero(r, name ? name : run->c->name, violations);
    free(name);
    sim_status status = split_fits(run, &f, r, msg, msglen);
    if (status == SIM_OK) {
        const double T_sonine = vfy_reference_value("T_steady_sonine", &run->rows[0].scene);
        name = vfy_aprintf("%s T_inf (n -> infinity) vs first-Sonine steady T", run->c->name);
        vfy_check_absolute(r, name ? name : run->c->name, f.T_inf, T_sonine,
                           f.T_inf_ci + VFY_TOL_SONINE_MODEL_RTOL * T_sonine);
        free(name);
        if (split_parts(run, &f, r) != 0 || split_predict(&f, n_min, h_max, &pr) != 0)
            status = SIM_ENOMEM;
        if (status == SIM_OK) {
            split_targets(run, &f, &pr, &pred, &summary);
            if (run->o->progress)
                fprintf(run->o->progress, "   %s: T_inf = %.6f ± %.6f (Sonine %.6f); cheapest "
                        "per target: %s\n", run->c->name, f.T_inf, f.T_inf_ci, T_sonine,
                        vfy_text_str(&summary));
            if (summary.failed || split_notes(run, &f, T_sonine, cand, coll, n_min, h_max,
                                              vfy_text_str(&summary)) != 0)
                status = SIM_ENOMEM;
        }
        if (status == SIM_ENOMEM)
            snprintf(msg, msglen, "out of memory");
        else if (split_figure(run, &f, &pred) != 0)
            status = vfy_io_error(run->c->name, msg, msglen);
    }
    vfy_wp_prediction_free(&pred);
    vfy_text_free(&summary);
    split_predictions_free(&pr);
    split_fit_free(&f);
    return status;
}

/* The functions this file's case files name (named.h, registry.c). */
const vfy_named_fn vfy_cost_named[] = {
    VFY_NAMED_HOOK("grid_model", grid_model),
    VFY_NAMED_HOOK("split_cost_model", split_cost_model),
    VFY_NAMED_END};
