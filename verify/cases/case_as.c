/* Paper E (Astillero and Santos 2005): uniform shear flow of inelastic hard
 * spheres (IHS) and of frictional elastic hard spheres (EHS), homogeneous, with
 * the BGK model beside them (docs/theory.md §15, issue 16).
 *
 * Every row is one steady state of verify/cases/scenes/as.ini at one restitution
 * coefficient alpha, model and initial shear rate a tau0: N independent
 * ensembles of n particles sheared from local equilibrium until steady.from,
 * then each averages the reduced stresses, a* = a tau_eta(T), a2 and a3 over
 * the output times (sim/steady.h); the half-widths come from the spread of the
 * N ensembles, with Student's t.  The rows come in the order alpha, model
 * (ihs, ehs), a tau0 (4, 0.1), so that a row's partners come before it: the
 * same alpha and model at a tau0 = 4 (the steady state must not depend on the
 * initial shear rate), and the IHS row of the same alpha and a tau0 (E's
 * comparison of the two models).
 *
 * Cases: as-steady (E Figs. 14-16), as-transient (E Figs. 5-13 against s) and
 * as-distribution (E Figs. 13, 17-18: the steady shell ratios and marginals).
  *
 * The cases are data (verify/cases/scenes/as-*.case, docs/adding-a-case.md);
 * this file holds the metrics, guards, rules and hooks they name, listed
 * in vfy_as_named at its end.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "driver.h"
#include "figure.h"
#include "metrics.h"
#include "named.h"
#include "references.h"
#include "scene_refs.h"
#include "steady.h"
#include "tolerances.h"

/* ------------------------------------------------------------- metrics */

/* Which EHS rows the model comparison judges: x > 0, alpha >= x (agree);
 * x < 0, alpha <= -x (differ).  None at quick sizes, whose half-widths
 * (n = 2000, N = 4) are wider than the differences judged. */
static double as_judged(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const double alpha = vfy_values_get(&row->values, "alpha");
    if (vfy_values_get(&row->values, "is_ehs") != 1.0 || run->o->size == VFY_QUICK)
        return 0.0;
    return m->x > 0 ? alpha >= m->x - 1e-12 : alpha <= -m->x + 1e-12;
}

/* T/T0 of the steady state. */
static double as_T_ratio(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    const double T0 = row->solver.particles.maxwellian.temperature;
    return vfy_values_get(&row->values, m->a) / T0;
}

/* 100 R_l (P(C_{l+1}) - P(C_l)) for shell x = l of E Eq. (3.15) (C = 0, 1, 2):
 * the percentage of particles in it, from R_l (or its half-width). */
static double as_shell_percent(const vfy_case_run *run, const vfy_row *row,
                               const vfy_metric *m)
{
    (void)run;
    const double P1 = erf(1.0) - 2.0 * exp(-1.0) / sqrt(M_PI);
    const double P2 = erf(2.0) - 4.0 * exp(-4.0) / sqrt(M_PI);
    return 100.0 * vfy_values_get(&row->values, m->a) * (m->x == 0 ? P1 : P2 - P1);
}

/* The steady energy balance (docs/theory.md §15.2): the shear's work on the
 * gas, (2/3) a* (-Pxy/nT) in units of 1/tau_eta, against what it loses,
 * zeta tau_eta = 1.016 (5/12)(1 - alpha^2) beta_c <V12^3>/<V12^3>_0 for IHS
 * (the collisions lose (1 - alpha^2)|g|^3/8 per pair and unit rate, exactly)
 * and 1.016 (5/12)(1 - alpha^2) for EHS (the drag zeta0/2 on V).  It holds
 * for every distribution, so no model enters.  a* is the solver's times
 * a_case/a_solver (1 unless --perturb moves the shear rate: a solver that
 * reads a right and shears at another rate), alpha and beta_c the case's.
 * 100 (work/loss - 1); x = 1: its half-width, the relative Student's
 * half-widths summed (a* and -Pxy/nT share the ensembles' T). */
static double as_balance(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    const vfy_values *v = &row->values;
    const double alpha = row->scene.collisions.restitution;
    const int ihs = vfy_values_get(v, "is_ehs") != 1.0;
    const double a_star = vfy_values_get(v, "a_star") * row->scene.shear.rate
                          / row->solver.shear.rate;
    const double pxy = vfy_values_get(v, "Pxy_reduced"), v12 = vfy_values_get(v, "v12_ratio");
    if (m->x == 1.0)
        return 100.0 * (vfy_values_get(v, "a_star_ci_t") / fabs(vfy_values_get(v, "a_star"))
                        + vfy_values_get(v, "Pxy_reduced_ci_t") / fabs(pxy)
                        + (ihs ? vfy_values_get(v, "v12_ratio_ci_t") / fabs(v12) : 0.0));
    const double loss = 1.016 * 5.0 / 12.0 * (1.0 - alpha * alpha)
                        * (ihs ? sim_scene_collision_rate_factor(&row->scene) * v12 : 1.0);
    return 100.0 * (2.0 / 3.0 * a_star * pxy / loss - 1.0);
}

/* 1 + x a2 (E §V A: <V12^3>/<V12^3>_0 about 1 + 0.27 a2). */
static double as_v12_sonine(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    return 1.0 + m->x * vfy_values_get(&row->values, m->a);
}

/* ================================================================ as-transient */

/* Series of a row into a fresh array of its M outputs (NULL when absent or
 * out of memory); ci too when ci != NULL. */
static double *asx_series(const vfy_row *row, const char *name, double **ci)
{
    const size_t M = row->res.outputs;
    double *mean = malloc(2 * M * sizeof *mean);
    if (mean == NULL || vfy_row_series(row, name, mean, mean + M) != 0) {
        free(mean);
        return NULL;
    }
    if (ci != NULL)
        *ci = mean + M;
    return mean;
}

/* The first output index with t >= steady.from. */
static size_t asx_steady_first(const vfy_row *row)
{
    size_t m = 0;
    while (m + 1 < row->res.outputs && row->res.t[m] < row->solver.steady.from)
        m++;
    return m;
}

/* E Fig. 6: the collisions per particle over their local-equilibrium count
 * (the collision rate over its local equilibrium value, <|V12|>/<|V12|>_0).
 * x = 0: ds/ds0 over the steady window; x = 1: its half-width from s's at the
 * window's ends (an upper bound: they are correlated); x = 2: E Fig. 6's own
 * ratio s/s0 at the last output; x = 3: that ratio plus its half-width (s's
 * at the last output over s0: s0 follows the simulated T, whose relative
 * half-width is a tenth of s's), the bound judged below 1. */
static double asx_collision_ratio(const vfy_case_run *run, const vfy_row *row,
                                  const vfy_metric *m)
{
    (void)run;
    double *sci = NULL, *s = asx_series(row, "s", &sci), *s0 = asx_series(row, "s0", NULL);
    double r = NAN;
    if (s != NULL && s0 != NULL) {
        const size_t a = asx_steady_first(row), b = row->res.outputs - 1;
        const double ds0 = s0[b] - s0[a];
        r = m->x == 0   ? (s[b] - s[a]) / ds0
            : m->x == 1 ? hypot(sci[a], sci[b]) / ds0
            : m->x == 2 ? s[b] / s0[b]
                        : (s[b] + sci[b]) / s0[b];
    }
    free(s);
    free(s0);
    return r;
}

/* The duration of the transient in collisions per particle: s at the last
 * output where a* = a tau_eta(T) is more than x percent from its steady value
 * (the row's steady average). */
static double asx_s_relax(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    double *s = asx_series(row, "s", NULL), *a = asx_series(row, "a_star", NULL);
    const double as = vfy_values_get(&row->values, "a_star");
    double r = NAN;
    if (s != NULL && a != NULL && isfinite(as)) {
        r = 0.0;
        for (size_t k = 0; k < row->res.outputs; k++)
            if (fabs(a[k] / as - 1.0) > 0.01 * m->x)
                r = s[k];
    }
    free(s);
    free(a);
    return r;
}

/* eta*(a*) of a curve at a*, by linear interpolation over its points with
 * s >= 2 (E Fig. 10's window, where the memory of the start is lost); NAN
 * outside their range. */
static double asx_eta_at(const double *s, const double *a, const double *eta, size_t M,
                         double at)
{
    for (size_t k = 1; k < M; k++) {
        if (s[k - 1] < 2.0)
            continue;
        const double lo = fmin(a[k - 1], a[k]), hi = fmax(a[k - 1], a[k]);
        if (at >= lo && at <= hi && hi > lo)
            return eta[k - 1] + (eta[k] - eta[k - 1]) * (at - a[k - 1]) / (a[k] - a[k - 1]);
    }
    return NAN;
}

/* The BGK model's a*(t) and eta*(t) of a row from its reference series:
 * a* = a tau_eta(T_bgk) (the row's own a* scaled by sqrt(T/T_bgk)), eta* =
 * (-Pxy_bgk/T_bgk)/a*.  Fills a and eta (M each); 0, or -1 without them. */
static int asx_bgk_eta(const vfy_row *row, double *a, double *eta)
{
    const size_t M = row->res.outputs;
    double *T = asx_series(row, "T_bgk", NULL), *P = asx_series(row, "Pxy_bgk", NULL);
    double *Td = asx_series(row, "T", NULL), *ad = asx_series(row, "a_star", NULL);
    const int ok = T && P && Td && ad;
    for (size_t k = 0; ok && k < M; k++) {
        a[k] = ad[k] * sqrt(Td[k] / T[k]);
        eta[k] = -P[k] / T[k] / a[k];
    }
    free(T), free(P), free(Td), free(ad);
    return ok ? 0 : -1;
}

/* E Fig. 10 (alpha = 0.5): eta*(a*) of IHS, EHS and BGK coincide for 0.2 < a*
 * < 1.6.  Over this row's outputs with s in [2, 50] and a* in (0.2, 1.6), the
 * relative difference from the other curve at the same a*, averaged in the a*
 * bins (0.2, 0.4), (0.4, 0.8), (0.8, 1.6), in percent: with a = NULL the
 * largest |average|, with a = "0", "1" or "2" that bin's signed average (NAN
 * where it holds fewer than 3 outputs); x = 2, an EHS row against its IHS
 * partner; x = 3, an IHS row against the BGK model; x = 4, an EHS row against
 * the BGK model.  NAN for the other rows, and at quick sizes. */
static double asx_eta_collapse(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const int bgk = m->x >= 3;
    if (vfy_values_get(&row->values, "is_ehs") != (m->x == 3 ? 0.0 : 1.0)
        || run->o->size == VFY_QUICK)
        return NAN;   /* quick sizes: a bin's average is +-5%, as wide as the bound */
    const vfy_row *other = bgk ? row : vfy_row_partner(run, row, "ihs");
    if (other == NULL)
        return NAN;
    const size_t M = row->res.outputs, Mo = other->res.outputs;
    double *s = asx_series(row, "s", NULL), *a = asx_series(row, "a_star", NULL);
    double *eta = asx_series(row, "eta_star", NULL), *so = asx_series(other, "s", NULL);
    double *ao = malloc(2 * Mo * sizeof *ao), *etao = ao ? ao + Mo : NULL;
    double worst = NAN;
    int ok = s && a && eta && so && ao;
    if (ok && bgk)
        ok = asx_bgk_eta(row, ao, etao) == 0;
    else if (ok) {
        double *x = asx_series(other, "a_star", NULL), *y = asx_series(other, "eta_star", NULL);
        ok = x && y;
        if (ok) {
            memcpy(ao, x, Mo * sizeof *ao);
            memcpy(etao, y, Mo * sizeof *ao);
        }
        free(x), free(y);
    }
    /* the mean of eta* over eta*_o, less 1, in each a* bin (0.2, 0.4, 0.8, 1.6): the noise of
     * single outputs averages out (at quick sizes one output's eta* is +-10%) */
    static const double edges[] = {0.2, 0.4, 0.8, 1.6};
    double sum[3] = {0, 0, 0};
    size_t count[3] = {0, 0, 0};
    for (size_t k = 0; ok && k < M; k++) {
        if (s[k] < 2.0 || s[k] > 50.0 || a[k] <= 0.2 || a[k] >= 1.6)
            continue;
        const double e = asx_eta_at(bgk ? s : so, ao, etao, Mo, a[k]);
        const size_t b = a[k] < edges[1] ? 0 : a[k] < edges[2] ? 1 : 2;
        if (isfinite(e)) {
            sum[b] += eta[k] / e - 1.0;
            count[b]++;
        }
    }
    const int only = m->a != NULL ? atoi(m->a) : -1;
    for (int b = 0; b < 3; b++)
        if (count[b] >= VFY_TOL_AS_ETA_BIN_OUTPUTS && (only < 0 || only == b)) {
            const double d = 100.0 * sum[b] / (double)count[b];
            worst = only >= 0 ? d : isnan(worst) ? fabs(d) : fmax(worst, fabs(d));
        }
    free(s), free(a), free(eta), free(so), free(ao);
    return worst;
}

/* E Figs. 7-8 plot T/T0 against s, and the BGK model's against its own
 * local-equilibrium count s0 (s'/beta and s0'/beta for EHS): the largest
 * |T(s)/T_bgk(s) - 1| over the row's outputs, in percent, with T_bgk(s) the
 * BGK temperature at s0_bgk = s (linear interpolation; outputs beyond the
 * BGK run's last s0 are left out); x = 1: the s where it is largest. */
static double asx_bgk_T_dev(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    const size_t M = row->res.outputs;
    double *T = asx_series(row, "T", NULL), *Tb = asx_series(row, "T_bgk", NULL);
    double *s = asx_series(row, "s", NULL), *sb = asx_series(row, "s0_bgk", NULL);
    double worst = NAN, at = NAN;
    for (size_t k = 1, j = 1; T && Tb && s && sb && k < M; k++) {
        while (j + 1 < M && sb[j] < s[k])
            j++;
        if (s[k] > sb[M - 1])
            break;
        const double w = (s[k] - sb[j - 1]) / (sb[j] - sb[j - 1]);
        const double d = 100.0 * fabs(T[k] / (Tb[j - 1] + w * (Tb[j] - Tb[j - 1])) - 1.0);
        if (isnan(worst) || d > worst)
            worst = d, at = s[k];
    }
    free(T), free(Tb), free(s), free(sb);
    return m->x == 1 ? at : worst;
}

/* E Fig. 5: s'/beta of an EHS row against its IHS partner's s at the last
 * output, 100 (s'/(beta s) - 1). */
static double asx_s_models(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)m;
    const vfy_row *ihs = vfy_row_partner(run, row, "ihs");
    if (ihs == NULL)
        return NAN;
    double *se = asx_series(row, "s", NULL), *si = asx_series(ihs, "s", NULL);
    double r = NAN;
    if (se && si && row->res.outputs == ihs->res.outputs) {
        const size_t b = row->res.outputs - 1;
        r = 100.0 * (se[b] / sim_scene_collision_rate_factor(&row->solver) / si[b] - 1.0);
    }
    free(se), free(si);
    return r;
}

/* The figures' curves, as many as the rows make: each curve allocated (it
 * stays where it is while more are added), its label, and the arrays the
 * curves point into, freed together.  `failed`: memory ran out, and a curve
 * or an array was left out. */
typedef struct asx_plot {
    vfy_xy_curve **curves;
    char **labels;   /* each curve's, allocated */
    double **own;
    size_t ncurves, nown;
    int failed;
    /* paper E's transient figures (asx_by_alpha): a grid column per alpha,
     * titled; then a curve's colour is its model's and its dash its a tau0's */
    size_t ncolumns;
    double *alphas;
    char **titles;
} asx_plot;

/* Array a, owned by the plot from now on (NULL stays NULL: a series the row
 * lacks). */
static double *asx_own(asx_plot *pl, double *a)
{
    double **grown = a != NULL ? realloc(pl->own, (pl->nown + 1) * sizeof *grown) : NULL;
    if (a != NULL && grown == NULL) {
        free(a);
        pl->failed = 1;
        return NULL;
    }
    if (a != NULL) {
        pl->own = grown;
        pl->own[pl->nown++] = a;
    }
    return a;
}

/* A new curve of `count` points labelled `label` (allocated; the plot owns
 * it), or NULL when out of memory. */
static vfy_xy_curve *asx_new_curve(asx_plot *pl, char *label, size_t count, int reference)
{
    vfy_xy_curve **curves = realloc(pl->curves, (pl->ncurves + 1) * sizeof *curves);
    if (curves != NULL)
        pl->curves = curves;
    char **labels = curves ? realloc(pl->labels, (pl->ncurves + 1) * sizeof *labels) : NULL;
    if (labels != NULL)
        pl->labels = labels;
    vfy_xy_curve *c = labels && label ? calloc(1, sizeof *c) : NULL;
    if (c == NULL) {
        free(label);
        pl->failed = 1;
        return NULL;
    }
    c->label = label;
    c->count = count;
    c->reference = reference;
    pl->curves[pl->ncurves] = c;
    pl->labels[pl->ncurves++] = label;
    return c;
}

/* The plot's columns: the rows' alphas in the order they come, each a
 * column of the grid titled "alpha = A" (E draws each alpha apart). */
static void asx_by_alpha(asx_plot *pl, const vfy_case_run *run)
{
    for (size_t i = 0; i < run->nrows && !pl->failed; i++) {
        const double alpha = vfy_values_get(&run->rows[i].values, "alpha");
        size_t k = 0;
        while (k < pl->ncolumns && pl->alphas[k] != alpha)
            k++;
        if (k < pl->ncolumns)
            continue;
        double *a = realloc(pl->alphas, (k + 1) * sizeof *a);
        pl->alphas = a ? a : pl->alphas;
        char **t = a ? realloc(pl->titles, (k + 1) * sizeof *t) : NULL;
        pl->titles = t ? t : pl->titles;
        char *title = t ? vfy_aprintf("alpha = %g", alpha) : NULL;
        if (title == NULL) {
            pl->failed = 1;
            return;
        }
        pl->alphas[k] = alpha;
        pl->titles[pl->ncolumns++] = title;
    }
}

/* A new curve of `count` points labelled from the row, or NULL when out of
 * memory.  In a plot by alpha (asx_by_alpha) the label leaves alpha to the
 * column's title, the colour is the model's (IHS blue, EHS vermilion, a
 * reference black) and the dash the a tau0's (4 solid, 0.1 dash-dot; a
 * reference dashed, dotted). */
static vfy_xy_curve *asx_curve(asx_plot *pl, const vfy_row *row, const char *what,
                               size_t count, int reference)
{
    const char *model = vfy_row_text(row, "model");
    const double alpha = vfy_values_get(&row->values, "alpha");
    const double rate = vfy_values_get(&row->values, "a_tau0");
    if (pl->ncolumns == 0)
        return asx_new_curve(pl, vfy_aprintf("%s%s alpha=%.1f a_tau0=%g", what,
                                             model ? model : "", alpha, rate),
                             count, reference);
    const int ehs = vfy_values_get(&row->values, "is_ehs") == 1.0, hot = rate == 4.0;
    vfy_xy_curve *c = asx_new_curve(pl, reference ? vfy_aprintf("%sa_tau0=%g", what, rate)
                                                  : vfy_aprintf("%s a_tau0=%g",
                                                                ehs ? "EHS" : "IHS", rate),
                                    count, reference);
    if (c == NULL)
        return NULL;
    c->lc = reference ? 7 : ehs ? 2 : 1;
    c->dt = reference ? (hot ? 2 : 3) : (hot ? 1 : 4);
    while (c->column < pl->ncolumns && pl->alphas[c->column] != alpha)
        c->column++;
    return c;
}

/* Label curve k of the plot `label` instead (allocated; NULL: out of memory,
 * the old label stays). */
static void asx_relabel(asx_plot *pl, size_t k, char *label)
{
    if (label == NULL) {
        pl->failed = 1;
        return;
    }
    free(pl->labels[k]);
    pl->labels[k] = label;
    pl->curves[k]->label = label;
}

/* Figure f with the plot's curves (f's ncurves and curves set here);
 * vfy_write_xy's 0 or -1. */
static int asx_write(const vfy_options *o, vfy_xy_figure *f, asx_plot *pl)
{
    vfy_xy_curve *flat = malloc((pl->ncurves ? pl->ncurves : 1) * sizeof *flat);
    if (flat == NULL) {
        pl->failed = 1;
        return 0;   /* reported as out of memory (asx_plot_free) */
    }
    for (size_t k = 0; k < pl->ncurves; k++)
        flat[k] = *pl->curves[k];
    f->ncurves = pl->ncurves;
    f->curves = flat;
    const int rc = vfy_write_xy(o, f);
    free(flat);
    return rc;
}

/* Free the plot; returns whether memory ran out while it was drawn. */
static int asx_plot_free(asx_plot *pl)
{
    for (size_t i = 0; i < pl->nown; i++)
        free(pl->own[i]);
    for (size_t k = 0; k < pl->ncurves; k++) {
        free(pl->labels[k]);
        free(pl->curves[k]);
    }
    for (size_t k = 0; k < pl->ncolumns; k++)
        free(pl->titles[k]);
    free(pl->titles);
    free(pl->alphas);
    free(pl->own);
    free(pl->labels);
    free(pl->curves);
    const int failed = pl->failed;
    memset(pl, 0, sizeof *pl);
    return failed;
}

/* Paper E's transient figure f, named "<case>-SUFFIX", from the plot's curves:
 * a grid with a column per alpha where asx_by_alpha found more than one.
 * Frees the plot (*nomem set when memory ran out); vfy_write_xy's 0 or -1. */
static int asx_transient_write(const vfy_case_run *run, const char *suffix, vfy_xy_figure *f,
                               asx_plot *pl, int *nomem)
{
    char name[96];
    snprintf(name, sizeof name, "%s-%s", run->c->name, suffix);
    f->name = name;
    f->comment = run->comment;
    f->ncolumns = pl->ncolumns > 1 ? pl->ncolumns : 0;
    f->column_title = (const char *const *)pl->titles;
    const int rc = asx_write(run->o, f, pl);
    *nomem |= asx_plot_free(pl);
    return rc;
}

/* A DSMC curve of the row: x series scaled by 1/x_scale, the panels' series
 * times their signs (the series' half-widths beside them). */
static void asx_dsmc(asx_plot *pl, const vfy_row *row, const char *x, double x_scale,
                     const char *const *y, const double *sign, size_t npanels)
{
    const size_t M = row->res.outputs;
    double *xs = asx_own(pl, asx_series(row, x, NULL));
    vfy_xy_curve *c = xs ? asx_curve(pl, row, "", M, 0) : NULL;
    if (c == NULL)
        return;
    for (size_t k = 0; k < M; k++)
        xs[k] /= x_scale;
    c->x = xs;
    for (size_t p = 0; p < npanels; p++) {
        double *ci = NULL, *ys = y[p] ? asx_own(pl, asx_series(row, y[p], &ci)) : NULL;
        for (size_t k = 0; ys && k < M; k++) {
            ys[k] *= sign[p];
            ci[k] = fabs(ci[k]);
        }
        c->y[p] = ys;
        c->ci[p] = ci;
    }
}

/* The BGK curve of the row (reference/bgk.h, the row's T_bgk ... s0_bgk):
 * against s0 (x_s0) or t, the panels kind[p]: 'T' T/T0, 'P' -Pxy/p, 'N'
 * (Pxx - Pyy)/p, 'S' s0/beta. */
static void asx_bgk(asx_plot *pl, const vfy_row *row, int x_s0, const char *kind,
                    size_t npanels)
{
    const size_t M = row->res.outputs;
    double *T = asx_own(pl, asx_series(row, "T_bgk", NULL));
    double *Pxx = asx_own(pl, asx_series(row, "Pxx_bgk", NULL));
    double *Pyy = asx_own(pl, asx_series(row, "Pyy_bgk", NULL));
    double *Pxy = asx_own(pl, asx_series(row, "Pxy_bgk", NULL));
    double *s0 = asx_own(pl, asx_series(row, "s0_bgk", NULL));
    double *out = asx_own(pl, malloc((1 + npanels) * M * sizeof *out));
    vfy_xy_curve *c = T && Pxx && Pyy && Pxy && s0 && out ? asx_curve(pl, row, "BGK ", M, 1)
                                                          : NULL;
    if (c == NULL)
        return;
    const double T0 = row->solver.particles.maxwellian.temperature;
    const double beta = sim_scene_collision_rate_factor(&row->solver);
    for (size_t k = 0; k < M; k++) {
        out[k] = x_s0 ? s0[k] / beta : row->res.t[k];
        for (size_t p = 0; p < npanels; p++)
            out[(1 + p) * M + k] = kind[p] == 'T'   ? T[k] / T0
                                   : kind[p] == 'P' ? -Pxy[k] / T[k]
                                   : kind[p] == 'N' ? (Pxx[k] - Pyy[k]) / T[k]
                                                    : s0[k] / beta;
    }
    c->x = out;
    for (size_t p = 0; p < npanels; p++)
        c->y[p] = out + (1 + p) * M;
}

/* A hook's end: SIM_OK, SIM_ENOMEM when memory ran out for a figure
 * (nomem), or SIM_EIO with msg when a figure could not be written (rc != 0,
 * errno set). */
static sim_status asx_figures_written(const vfy_case_run *run, int rc, int nomem, char *msg,
                                      size_t msglen)
{
    if (nomem) {
        snprintf(msg, msglen, "%s: out of memory for the figures", run->c->name);
        return SIM_ENOMEM;
    }
    if (rc == 0)
        return SIM_OK;
    snprintf(msg, msglen, "%s: cannot write the figures: %s", run->c->name, strerror(errno));
    return SIM_EIO;
}

/* E Figs. 5-6: s/beta and s/s0 against t, one curve per row, BGK's s0/beta
 * beside the IHS rows; vfy_write_xy's 0 or -1, *nomem set when memory ran
 * out. */
static int asx_collisions_figure(const vfy_case_run *run, int *nomem)
{
    asx_plot pl;
    memset(&pl, 0, sizeof pl);
    asx_by_alpha(&pl, run);
    for (size_t i = 0; i < run->nrows; i++) {
        const vfy_row *row = &run->rows[i];
        const double beta = sim_scene_collision_rate_factor(&row->solver);
        const size_t M = row->res.outputs;
        double *sv = asx_own(&pl, asx_series(row, "s", NULL));
        double *s0 = asx_own(&pl, asx_series(row, "s0", NULL));
        double *out = asx_own(&pl, malloc(2 * M * sizeof *out));
        vfy_xy_curve *c = sv && s0 && out ? asx_curve(&pl, row, "", M, 0) : NULL;
        if (c == NULL)
            continue;
        for (size_t k = 0; k < M; k++) {
            out[k] = sv[k] / beta;
            out[M + k] = k ? sv[k] / s0[k] : NAN;
        }
        c->x = row->res.t;
        c->y[0] = out;
        c->y[1] = out + M;
        if (vfy_values_get(&row->values, "is_ehs") == 0.0)
            asx_bgk(&pl, row, 0, "S", 1);
    }
    vfy_xy_figure f = {.title = "paper E Figs. 5-6: collisions per particle s "
                       "(EHS: s'/beta) and s/s0 against t", .xlabel = "t/tau0",
                       .logx = 1, .npanels = 2,
                       .ylabel = {"s, s'/beta", "s/s0"}};
    return asx_transient_write(run, "collisions", &f, &pl, nomem);
}

/* E Figs. 7-8: T/T0, -Pxy/nT, (Pxx - Pyy)/nT against s, one curve per row,
 * BGK beside the IHS rows; vfy_write_xy's 0 or -1, *nomem set when memory
 * ran out. */
static int asx_stress_figure(const vfy_case_run *run, int *nomem)
{
    static const char *const stress[] = {"T_ratio", "Pxy_reduced", "N1"};
    static const double plus[] = {1.0, 1.0, 1.0, 1.0};
    asx_plot pl;
    memset(&pl, 0, sizeof pl);
    asx_by_alpha(&pl, run);
    for (size_t i = 0; i < run->nrows; i++) {
        const vfy_row *row = &run->rows[i];
        asx_dsmc(&pl, row, "s", sim_scene_collision_rate_factor(&row->solver), stress, plus, 3);
        if (vfy_values_get(&row->values, "is_ehs") == 0.0)
            asx_bgk(&pl, row, 1, "TPN", 3);
    }
    vfy_xy_figure f = {.title = "paper E Figs. 7-8: T/T0 and the reduced "
                       "stresses against s (EHS: s'/beta), BGK against s0", .xlabel = "s",
                       .logx = 1, .npanels = 3,
                       .ylabel = {"T/T0", "-Pxy/nT", "(Pxx - Pyy)/nT"}};
    return asx_transient_write(run, "stress", &f, &pl, nomem);
}

/* E Fig. 10: eta* against a* at alpha = 0.5, s in [2, 50], BGK beside the
 * IHS rows; vfy_write_xy's 0 or -1, *nomem set when memory ran out. */
static int asx_viscosity_figure(const vfy_case_run *run, int *nomem)
{
    asx_plot pl;
    memset(&pl, 0, sizeof pl);
    for (size_t i = 0; i < run->nrows; i++) {
        const vfy_row *row = &run->rows[i];
        if (fabs(vfy_values_get(&row->values, "alpha") - 0.5) > 1e-9)
            continue;
        const size_t M = row->res.outputs;
        double *sv = asx_own(&pl, asx_series(row, "s", NULL));
        double *a = asx_own(&pl, asx_series(row, "a_star", NULL));
        double *ci = NULL, *eta = asx_own(&pl, asx_series(row, "eta_star", &ci));
        vfy_xy_curve *c = sv && a && eta ? asx_curve(&pl, row, "", M, 0) : NULL;
        if (c == NULL)
            continue;
        for (size_t k = 0; k < M; k++)
            if (sv[k] < 2.0 || sv[k] > 50.0)
                a[k] = NAN;
        c->x = a;
        c->y[0] = eta;
        c->ci[0] = ci;
        /* styled as the plots by alpha are (asx_curve): IHS blue, EHS vermilion, BGK
         * black; a tau0 = 4 solid (BGK dashed), 0.1 dash-dot (BGK dotted) */
        const int ehs = vfy_values_get(&row->values, "is_ehs") == 1.0;
        const int hot = vfy_values_get(&row->values, "a_tau0") == 4.0;
        c->lc = ehs ? 2 : 1;
        c->dt = hot ? 1 : 4;
        if (!ehs) {
            double *ab = asx_own(&pl, malloc(2 * M * sizeof *ab));
            vfy_xy_curve *b = ab ? asx_curve(&pl, row, "BGK ", M, 1) : NULL;
            if (b != NULL && asx_bgk_eta(row, ab, ab + M) == 0) {
                b->x = ab;
                b->y[0] = ab + M;
                b->lc = 7;
                b->dt = hot ? 2 : 3;
            }
        }
    }
    vfy_xy_figure f = {.title = "paper E Fig. 10: eta* against a* at alpha = "
                       "0.5 (2 <= s <= 50)", .xlabel = "a*",
                       .npanels = 1, .ylabel = {"eta*"}};
    return asx_transient_write(run, "viscosity", &f, &pl, nomem);
}

/* E Figs. 11-12: <V12^3>/<V12^3>_0, a2 and -a3 against s, one curve per
 * row; vfy_write_xy's 0 or -1, *nomem set when memory ran out. */
static int asx_cumulants_figure(const vfy_case_run *run, int *nomem)
{
    static const char *const cumulants[] = {"v12_ratio", "a2", "a3"};
    static const double signs[] = {1.0, 1.0, -1.0};
    asx_plot pl;
    memset(&pl, 0, sizeof pl);
    asx_by_alpha(&pl, run);
    for (size_t i = 0; i < run->nrows; i++)
        asx_dsmc(&pl, &run->rows[i], "s",
                 sim_scene_collision_rate_factor(&run->rows[i].solver), cumulants, signs, 3);
    vfy_xy_figure f = {.title = "paper E Figs. 11-12: <V12^3>/<V12^3>_0, a2 "
                       "and -a3 against s (EHS: s'/beta)", .xlabel = "s",
                       .logx = 1, .npanels = 3,
                       .ylabel = {"<V12^3>/<V12^3>_0", "a2", "-a3"}};
    return asx_transient_write(run, "cumulants", &f, &pl, nomem);
}

/* E Fig. 13: the shell ratios R0..R3 against s, one curve per row at
 * a tau0 = 4; vfy_write_xy's 0 or -1, *nomem set when memory ran out. */
static int asx_shells_figure(const vfy_case_run *run, int *nomem)
{
    static const char *const shells[] = {"R0", "R1", "R2", "R3"};
    static const double plus[] = {1.0, 1.0, 1.0, 1.0};
    asx_plot pl;
    memset(&pl, 0, sizeof pl);
    asx_by_alpha(&pl, run);
    for (size_t i = 0; i < run->nrows; i++) {
        const vfy_row *row = &run->rows[i];
        if (vfy_values_get(&row->values, "a_tau0") == 4.0)
            asx_dsmc(&pl, row, "s", sim_scene_collision_rate_factor(&row->solver), shells,
                     plus, 4);
    }
    vfy_xy_figure f = {.title = "paper E Fig. 13: the shell ratios R0..R3 "
                       "against s at a tau0 = 4 (EHS: s'/beta)", .xlabel = "s",
                       .logx = 1, .npanels = 4,
                       .ylabel = {"R0", "R1", "R2", "R3"}};
    return asx_transient_write(run, "shells", &f, &pl, nomem);
}

/* After the rows: E's figures against s (and t, a*), one curve per row, BGK
 * beside the IHS rows (its T and stresses are the same for EHS; only its
 * clock differs, and E plots s'/beta). */
static sim_status as_transient_after(vfy_case_run *run, vfy_report *r, char *msg,
                                     size_t msglen)
{
    (void)r;
    int nomem = 0;
    int rc = asx_collisions_figure(run, &nomem);
    rc |= asx_stress_figure(run, &nomem);
    rc |= asx_viscosity_figure(run, &nomem);
    rc |= asx_cumulants_figure(run, &nomem);
    rc |= asx_shells_figure(run, &nomem);
    return asx_figures_written(run, rc, nomem, msg, msglen);
}

/* ============================================================= as-distribution */

/* One marginal of a row: its bins' abscissae (centres), widths, means and
 * Student half-widths (_ci_t), in units of sqrt(2T/m). */
typedef struct asd_marginal {
    size_t bins;
    double width;
    const double *mean, *ci;   /* into the result's steady arrays */
    double t_factor;           /* ci -> _ci_t */
    int speed;                 /* F: bins on [0, c_max) */
    const sim_scene *scene;
} asd_marginal;

/* Marginal `name` ("gx", "gy" or "F") of the row; 0, or -1 without its bins. */
static int asd_get(const vfy_row *row, const char *name, asd_marginal *g)
{
    const sim_scene *s = &row->solver;
    char first[16];
    snprintf(first, sizeof first, "%s_0", name);
    const long k0 = sim_steady_find(s, first);
    if (k0 < 0 || row->res.steady_mean == NULL || s->steady.bins == 0)
        return -1;
    g->speed = name[0] == 'F';
    g->bins = g->speed ? s->steady.bins : 2 * s->steady.bins;
    g->width = s->steady.c_max / (double)s->steady.bins;
    g->mean = row->res.steady_mean + k0;
    g->ci = row->res.steady_ci + k0;
    g->t_factor = vfy_student_t(VFY_STUDENT_P, (double)s->particles.ensembles - 1.0)
                  / SIM_LAMBDA_P;
    g->scene = s;
    return 0;
}

static double asd_centre(const asd_marginal *g, size_t k)
{
    return g->speed ? sim_steady_bin_centre(g->scene, k) : sim_steady_marginal_centre(g->scene, k);
}

/* The local equilibrium's bin average over [a, b]: g^(+) = e^{-C^2}/(2 sqrt(pi)),
 * F = 4 C^2 e^{-C^2}/sqrt(pi) (E Eqs. 3.18-3.20 at f* = pi^{-3/2} e^{-C^2}). */
static double asd_maxwell(int speed, double a, double b)
{
    if (speed)
        return (erf(b) - 2.0 * b * exp(-b * b) / sqrt(M_PI) - erf(a)
                + 2.0 * a * exp(-a * a) / sqrt(M_PI)) / (b - a);
    return (erf(b) - erf(a)) / (4.0 * (b - a));
}

/* The BGK model's bin average over [a, b] (3-point Gauss-Legendre; the
 * marginals are smooth on a bin's scale), or NAN. */
static double asd_bgk(const vfy_row *row, int which, double a, double b)
{
    static const double node[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
    static const double weight[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    const ref_bgk_params p = vfy_bgk_params(&row->scene);
    double sum = 0.0;
    for (int i = 0; i < 3; i++) {
        double v;
        const double c = 0.5 * (a + b) + 0.5 * (b - a) * node[i];
        if (ref_bgk_steady_marginal(&p, (ref_bgk_marginal)which, c, &v, NULL, 0) != REF_OK)
            return NAN;
        sum += 0.5 * weight[i] * v;
    }
    return sum;
}

static int asd_which(const char *name)
{
    return name[0] == 'F' ? REF_BGK_F_SPEED : name[1] == 'x' ? REF_BGK_GX_PLUS : REF_BGK_GY_PLUS;
}

/* E §V: "the curves obtained from the two values of the shear rate practically
 * coincide" and, at alpha = 0.9, IHS and EHS are "hardly distinguishable":
 * marginal a of the row against its partner b (as_partners), the
 * largest |g - g'| less the joint half-width over the bins with |C| <= 2, in
 * percent of the partner's peak.  NAN without a partner. */
static double asd_partner_dev(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const vfy_row *other = vfy_row_partner(run, row, m->b);
    asd_marginal g, h;
    if (other == NULL || asd_get(row, m->a, &g) != 0 || asd_get(other, m->a, &h) != 0
        || g.bins != h.bins)
        return NAN;
    double peak = 0.0, worst = -INFINITY;
    for (size_t k = 0; k < h.bins; k++)
        peak = fmax(peak, h.mean[k]);
    for (size_t k = 0; k < g.bins; k++) {
        if (fabs(asd_centre(&g, k)) > VFY_TOL_AS_THERMAL_C)
            continue;
        const double joint = hypot(g.ci[k] * g.t_factor, h.ci[k] * h.t_factor);
        worst = fmax(worst, fabs(g.mean[k] - h.mean[k]) - joint);
    }
    return 100.0 * worst / peak;
}

/* E §V: the BGK model "captures well ... the local details of the velocity
 * distribution function": over the bins with |C| <= 2, the L1 distance of
 * marginal a from the BGK model's over its distance from the local
 * equilibrium's.  NAN without the bins or the model. */
static double asd_bgk_ratio(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    asd_marginal g;
    if (asd_get(row, m->a, &g) != 0)
        return NAN;
    double to_bgk = 0.0, to_maxwell = 0.0;
    for (size_t k = 0; k < g.bins; k++) {
        const double c = asd_centre(&g, k), a = c - 0.5 * g.width, b = c + 0.5 * g.width;
        if (fabs(c) > VFY_TOL_AS_THERMAL_C)
            continue;
        to_bgk += fabs(g.mean[k] - asd_bgk(row, asd_which(m->a), a, b));
        to_maxwell += fabs(g.mean[k] - asd_maxwell(g.speed, a, b));
    }
    return to_bgk / to_maxwell;
}

/* E §V's statements about where one distribution is more populated than
 * another.  Metric b is "ALPHA:LO:HI" (the bins whose centres lie in [LO, HI])
 * or "ALPHA:|LO:HI" (|C| in [LO, HI]); the population of marginal a there, in
 * percent of the particles, of this row less that of the other, times the
 * sign E states (positive: as E says): |x| = 2 the IHS partner (EHS rows),
 * |x| = 4 the BGK model (IHS rows), the sign of x E's.  |x| < 10: that
 * difference less its half-width, the sum of the bins' joint half-widths (an
 * upper bound whatever their correlation); |x| > 10 (x = +-12, +-14): the
 * difference itself.  NAN
 * for the rows at another alpha or without that comparison, and at quick
 * sizes (n = 2000, N = 4), whose half-widths are wider than the differences. */
static double asd_region(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const int kind = (int)fabs(m->x) % 10, margin = fabs(m->x) < 10;
    const double sign = m->x < 0 ? -1.0 : 1.0;
    double alpha, lo, hi;
    const char *r = strchr(m->b, ':');
    const int absolute = r != NULL && r[1] == '|';
    if (r == NULL || sscanf(m->b, "%lf", &alpha) != 1
        || sscanf(r + 1 + absolute, "%lf:%lf", &lo, &hi) != 2
        || fabs(vfy_values_get(&row->values, "alpha") - alpha) > 1e-9
        || vfy_values_get(&row->values, "is_ehs") != (kind == 2 ? 1.0 : 0.0)
        || run->o->size == VFY_QUICK)
        return NAN;
    const vfy_row *other = kind == 2 ? vfy_row_partner(run, row, "ihs") : NULL;
    asd_marginal g, h;
    if ((kind == 2 && other == NULL) || asd_get(row, m->a, &g) != 0
        || (other != NULL && asd_get(other, m->a, &h) != 0))
        return NAN;
    double diff = 0.0, half = 0.0;
    for (size_t k = 0; k < g.bins; k++) {
        const double c = asd_centre(&g, k), cc = absolute ? fabs(c) : c;
        if (cc < lo || cc > hi)
            continue;
        const double ref = other != NULL ? h.mean[k]
                                         : asd_bgk(row, asd_which(m->a), c - 0.5 * g.width,
                                                   c + 0.5 * g.width);
        diff += (g.mean[k] - ref) * g.width;
        half += (other != NULL ? hypot(g.ci[k] * g.t_factor, h.ci[k] * h.t_factor)
                               : g.ci[k] * g.t_factor) * g.width;
    }
    return 100.0 * (sign * diff - (margin ? half : 0.0));
}

/* A statement of asd_region with difference d (value a) and margin d - h
 * (value b): judged where the sizes resolve its sign (|d| > h), a SKIP with
 * the reason where they do not, omitted where it does not apply (NAN). */
static vfy_guard_result asd_guard_resolved(const vfy_case_run *run, const vfy_row *row,
                                           const vfy_guard *g)
{
    (void)run;
    const double d = vfy_values_get(&row->values, g->a);
    const double h = d - vfy_values_get(&row->values, g->b);
    return isnan(h) ? VFY_OMIT : fabs(d) > h ? VFY_JUDGE : VFY_GUARD_SKIP;
}

/* ------------------------------------ the marginals' figures (E Figs. 17-18) */

/* BGK and local-equilibrium curves on a fine grid beside the bins. */
enum { ASD_FINE = 121 };

/* A row's marginals (curve functions of as-distribution's [figure]s): x = 0,
 * g_x^(+) and g_y^(+) against the marginal bins' centres in panels 0 and 1;
 * x = 1, F against the speed bins' in panel 2; with their Student
 * half-widths.  A row's colour is the same in every panel: IHS blue, EHS
 * vermilion, at a tau0 = 0.1 their lighter kin (sky blue, orange),
 * dash-dotted: the steady state forgets the initial rate (E), so the two lie
 * on one another.  1 for a row without them. */
static int as_curve_marginals(const vfy_case_run *run, const vfy_row *row, double x,
                              vfy_curve *out)
{
    (void)run;
    asd_marginal gx, gy, F;
    if (asd_get(row, "gx", &gx) != 0 || asd_get(row, "gy", &gy) != 0
        || asd_get(row, "F", &F) != 0)
        return 1;
    const int speed = x == 1.0;
    const asd_marginal *g = speed ? &F : &gx;
    if (vfy_curve_alloc_panels(out, g->bins, speed ? 2 : 0, speed ? 2 : 1, 1) != 0)
        return -1;
    for (size_t k = 0; k < g->bins; k++) {
        out->x[k] = asd_centre(g, k);
        if (speed) {
            out->y[2][k] = F.mean[k];
            out->ci[2][k] = F.ci[k] * F.t_factor;
        } else {
            out->y[0][k] = gx.mean[k];
            out->ci[0][k] = gx.ci[k] * gx.t_factor;
            out->y[1][k] = gy.mean[k];
            out->ci[1][k] = gy.ci[k] * gy.t_factor;
        }
    }
    const int ehs = vfy_values_get(&row->values, "is_ehs") == 1.0;
    const int cold = vfy_values_get(&row->values, "a_tau0") != 4.0;
    out->lc = ehs ? (cold ? 4 : 2) : (cold ? 5 : 1);
    out->dt = cold ? 4 : 1;
    return 0;
}

/* The BGK model's (x = 0, 1; black) and the local equilibrium's (x = 2, 3;
 * grey) marginals at points (not bin averages) at the row's scene: g_x^(+)
 * and g_y^(+) (x even, panels 0 and 1) or F (x odd, panel 2). */
enum { ASD_BGK_G, ASD_BGK_F, ASD_EQ_G, ASD_EQ_F };
static int as_curve_model(const vfy_case_run *run, const vfy_row *row, double x,
                          vfy_curve *out)
{
    (void)run;
    const int which = (int)x, speed = which == ASD_BGK_F || which == ASD_EQ_F;
    const ref_bgk_params p = vfy_bgk_params(&row->scene);
    const double cmax = row->solver.steady.c_max;
    if (vfy_curve_alloc_panels(out, ASD_FINE, speed ? 2 : 0, speed ? 2 : 1, 0) != 0)
        return -1;
    for (size_t k = 0; k < ASD_FINE; k++) {
        const double c = speed ? cmax * (double)k / (ASD_FINE - 1)
                               : -cmax + 2.0 * cmax * (double)k / (ASD_FINE - 1);
        double y[2] = {NAN, NAN};
        out->x[k] = c;
        if (which == ASD_BGK_G) {
            if (ref_bgk_steady_marginal(&p, REF_BGK_GX_PLUS, c, &y[0], NULL, 0) != REF_OK)
                y[0] = NAN;
            if (ref_bgk_steady_marginal(&p, REF_BGK_GY_PLUS, c, &y[1], NULL, 0) != REF_OK)
                y[1] = NAN;
        } else if (which == ASD_BGK_F) {
            if (ref_bgk_steady_marginal(&p, REF_BGK_F_SPEED, c, &y[0], NULL, 0) != REF_OK)
                y[0] = NAN;
        } else if (which == ASD_EQ_G)
            y[0] = y[1] = exp(-c * c) / (2.0 * sqrt(M_PI));
        else
            y[0] = 4.0 * c * c * exp(-c * c) / sqrt(M_PI);
        /* below 1e-6 the simulations hold no particle (10^9 samples at most): the
         * curves stop there, so that E Fig. 18's range shows */
        for (size_t j = 0; j < 2; j++)
            y[j] = y[j] >= 1e-6 ? y[j] : NAN;
        if (speed)
            out->y[2][k] = y[0];
        else
            out->y[0][k] = y[0], out->y[1][k] = y[1];
    }
    out->lc = which == ASD_BGK_G || which == ASD_BGK_F ? 7 : 8;   /* black, grey */
    return 0;
}


/* ============================================================= as-slab */

/* The output closest to time x. */
static size_t asl_output_at(const vfy_row *row, double x)
{
    const double t_end = row->solver.t_end;
    const double k = floor(x / t_end * (double)(row->res.outputs - 1) + 0.5);
    return k <= 0.0 ? 0 : k >= (double)(row->res.outputs - 1) ? row->res.outputs - 1 : (size_t)k;
}

/* The first output where s >= x (s' / beta for EHS), or M when none is. */
static size_t asl_output_at_s(const vfy_row *row, const double *s, double x)
{
    const double beta = sim_scene_collision_rate_factor(&row->solver);
    size_t m = 0;
    while (m < row->res.outputs && s[m] / beta < x)
        m++;
    return m;
}

/* Series a at time x: its mean, or its half-width when b is "ci". */
static double asl_at(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    double *ci = NULL, *v = asx_series(row, m->a, &ci);
    if (v == NULL)
        return NAN;
    const size_t k = asl_output_at(row, m->x);
    const double x = m->b ? ci[k] : v[k];
    free(v);
    return x;
}

/* Series a at the first output with s >= x (E: the profiles are uniform by
 * s = 4): its mean, or its half-width when b is "ci". */
static double asl_at_s(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    double *ci = NULL, *v = asx_series(row, m->a, &ci), *s = asx_series(row, "s", NULL);
    double x = NAN;
    const size_t k = v && s ? asl_output_at_s(row, s, m->x) : row->res.outputs;
    if (k < row->res.outputs)
        x = m->b ? ci[k] : v[k];
    free(v);
    free(s);
    return x;
}

/* Over the outputs with s < 4: the largest (x > 0) or smallest (x < 0) mean of
 * series a, or with b = "s" the s where it is (E Fig. 3: the temperature
 * difference peaks at s about 0.15, the density difference after about one
 * collision per particle). */
static double asl_extreme(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    double *v = asx_series(row, m->a, NULL), *s = asx_series(row, "s", NULL);
    double best = NAN, where = NAN;
    const double beta = sim_scene_collision_rate_factor(&row->solver);
    for (size_t k = 1; v && s && k < row->res.outputs && s[k] / beta < 4.0; k++)
        if (isnan(best) || (m->x > 0 ? v[k] > best : v[k] < best)) {
            best = v[k];
            where = s[k] / beta;
        }
    free(v);
    free(s);
    return m->b ? where : best;
}

/* The top three layers' u_x of the linear profile u_x = a y, in units of U/2:
 * (L/2 - 3 dy/2)/(L/2) = 1 - 3/M. */
static double asl_ux_linear(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    (void)m;
    return 1.0 - 3.0 / (double)row->solver.shear.layers;
}

/* EHS rows: s'/(beta s) at the end against the IHS row before it (E Fig. 1:
 * s'/s about beta = 0.95); x = 1: its half-width from the two s's. */
static double asl_s_ratio(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const vfy_row *ihs = vfy_row_previous(run, row);
    if (vfy_values_get(&row->values, "is_ehs") != 1.0 || ihs == NULL)
        return NAN;
    double *ci = NULL, *s = asx_series(row, "s", &ci), *ci_i = NULL;
    double *si = asx_series(ihs, "s", &ci_i);
    double x = NAN;
    if (s && si) {
        const size_t k = row->res.outputs - 1;
        const double r = s[k] / si[k] / sim_scene_collision_rate_factor(&row->solver);
        x = m->x == 0 ? r : r * hypot(ci[k] / s[k], ci_i[k] / si[k]);
    }
    free(s);
    free(si);
    return x;
}

/* EHS rows: 100 (q - q')/q' against the IHS row before it; with b = "ci",
 * its half-width, 100 sqrt(c^2 + c'^2)/q' from the two rows' Student's t
 * half-widths q_ci_t (independent simulations). */
static double asl_percent_ihs(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const vfy_row *ihs = vfy_row_previous(run, row);
    if (vfy_values_get(&row->values, "is_ehs") != 1.0 || ihs == NULL)
        return NAN;
    const double b = vfy_values_get(&ihs->values, m->a);
    if (m->b != NULL) {
        char ci[48];
        snprintf(ci, sizeof ci, "%s_ci_t", m->a);
        return 100.0 * hypot(vfy_values_get(&row->values, ci), vfy_values_get(&ihs->values, ci))
               / fabs(b);
    }
    return 100.0 * (vfy_values_get(&row->values, m->a) - b) / b;
}

/* Relabel the plot's last curve: "ihs from E Eq. (3.5)" (the initial
 * state) and what follows. */
static void asl_label(asx_plot *pl, const vfy_row *row, const char *what)
{
    const char *model = vfy_row_text(row, "model");
    if (pl->ncurves > 0)
        asx_relabel(pl, pl->ncurves - 1,
                    vfy_aprintf("%s from E Eq. (%g)%s", model ? model : "",
                                vfy_values_get(&row->values, "initial"), what));
}

/* Style the plot's last curve, the row's: a colour per initial state (E Eq.
 * 3.5 blue, 3.6 vermilion; `top`: their lighter kin, sky blue and orange,
 * for the top layers), IHS solid and EHS dashed (the two lie close: E finds
 * them practically identical). */
static void asl_style(asx_plot *pl, const vfy_row *row, int top)
{
    if (pl->ncurves == 0)
        return;
    vfy_xy_curve *c = pl->curves[pl->ncurves - 1];
    const int e35 = vfy_values_get(&row->values, "initial") == 3.5;
    c->lc = top ? (e35 ? 5 : 4) : (e35 ? 1 : 2);
    c->dt = vfy_values_get(&row->values, "is_ehs") == 1.0 ? 2 : 1;
}

/* Write figure f of the plot's curves and free the plot (nomem: memory ran
 * out); vfy_write_xy's 0 or -1. */
static int asl_write(const vfy_case_run *run, vfy_xy_figure *f, asx_plot *pl, int *nomem)
{
    const int rc = asx_write(run->o, f, pl);
    *nomem |= asx_plot_free(pl);
    return rc;
}

/* E Fig. 1: s (EHS: s'/beta) against t, and s'/s. */
static int asl_collisions_figure(const vfy_case_run *run, int *nomem)
{
    asx_plot pl = {0};
    for (size_t i = 0; i < run->nrows; i++) {
        const vfy_row *row = &run->rows[i], *ihs = vfy_row_previous(run, row);
        const double beta = sim_scene_collision_rate_factor(&row->solver);
        const size_t M = row->res.outputs;
        const int ehs = vfy_values_get(&row->values, "is_ehs") == 1.0 && ihs != NULL;
        double *ci = NULL, *s = asx_own(&pl, asx_series(row, "s", &ci));
        double *si = ehs ? asx_own(&pl, asx_series(ihs, "s", NULL)) : NULL;
        double *ratio = ehs ? asx_own(&pl, malloc(M * sizeof *ratio)) : NULL;
        vfy_xy_curve *c = s ? asx_curve(&pl, row, "", M, 0) : NULL;
        if (c == NULL)
            continue;
        asl_label(&pl, row, "");
        asl_style(&pl, row, 0);
        for (size_t k = 0; k < M; k++) {
            s[k] /= beta;
            ci[k] /= beta;
            if (ratio && si)
                ratio[k] = k > 0 && si[k] > 0.0 ? s[k] * beta / si[k] : NAN;
        }
        c->x = row->res.t;
        c->y[0] = s;
        c->ci[0] = ci;
        c->y[1] = si ? ratio : NULL;
    }
    char name[96];
    snprintf(name, sizeof name, "%s-collisions", run->c->name);
    vfy_xy_figure f = {.name = name, .title = "paper E Fig. 1: collisions per particle s (EHS: "
                       "s'/beta) against t, and s'/s", .xlabel = "t/tau0",
                       .comment = run->comment, .npanels = 2,
                       .ylabel = {"s, s'/beta", "s'/s"}};
    return asl_write(run, &f, &pl, nomem);
}

/* E Fig. 2's times t/tau0, each a colour (blue, vermilion, black, orange,
 * sky blue; figure.h) and a dash type (solid, dashed, dotted, ...) */
static const double asl_times[] = {0.13, 0.5, 1.0, 1.5, 2.0};
static const int asl_time_colour[] = {1, 2, 7, 4, 5};
#define ASL_TIMES (sizeof asl_times / sizeof asl_times[0])

/* The row's profiles at E Fig. 2's times, in column `column` of the grid. */
static void asl_profiles(asx_plot *pl, const vfy_row *row, size_t column)
{
    static const int profile[3] = {SIM_PROFILE_UX, SIM_PROFILE_N, SIM_PROFILE_T};
    const size_t L = row->solver.shear.layers, K = row->res.observables;
    const double half_U = 0.5 * row->solver.shear.rate * row->solver.shear.length;
    for (size_t q = 0; q < ASL_TIMES; q++) {
        const size_t m = asl_output_at(row, asl_times[q]);
        double *a = asx_own(pl, malloc(7 * L * sizeof *a));
        vfy_xy_curve *c = a ? asx_new_curve(pl, vfy_aprintf("t/tau0 = %g", asl_times[q]), L, 0)
                            : NULL;
        if (c == NULL)
            continue;
        for (size_t I = 0; I < L; I++) {
            a[I] = ((double)I + 0.5) / (double)L - 0.5;
            for (int p = 0; p < 3; p++) {
                const size_t col = m * K + SIM_OBS_PROFILE + (size_t)profile[p] * L + I;
                const double scale = p == 0 ? half_U : 1.0;
                a[(1 + p) * L + I] = row->res.mean[col] / scale;
                a[(4 + p) * L + I] = row->res.ci[col] / fabs(scale);
            }
        }
        c->x = a;
        for (int p = 0; p < 3; p++) {
            c->y[p] = a + (1 + p) * L;
            c->ci[p] = a + (4 + p) * L;
        }
        c->lc = asl_time_colour[q];
        c->dt = 1 + (int)q;
        c->column = column;
    }
}

/* E Fig. 2: the profiles u_x/(U/2), n_I/n and T_I/T against y/L at five
 * times, a column of panels per row. */
static int asl_profiles_figure(const vfy_case_run *run, int *nomem)
{
    asx_plot pl = {0};
    char **titles = calloc(run->nrows, sizeof *titles);
    for (size_t i = 0; titles != NULL && i < run->nrows; i++) {
        const vfy_row *row = &run->rows[i];
        titles[i] = vfy_aprintf("%s from E Eq. (%g)",
                                vfy_values_get(&row->values, "is_ehs") == 1.0 ? "EHS" : "IHS",
                                vfy_values_get(&row->values, "initial"));
        pl.failed |= titles[i] == NULL;
        asl_profiles(&pl, row, i);
    }
    pl.failed |= titles == NULL;
    char name[96];
    snprintf(name, sizeof name, "%s-profiles", run->c->name);
    vfy_xy_figure f = {.name = name, .title = "paper E Fig. 2: the profiles at t/tau0 = 0.13, "
                       "0.5, 1, 1.5, 2; E Eq. (3.5): uniform, at rest; E Eq. (3.6): a shell with "
                       "density and flow waves", .xlabel = "y/L", .comment = run->comment,
                       .npanels = 3, .ylabel = {"u_x/(U/2) (U = aL)", "n_I/n (n the mean density)",
                                                "T_I/T (T the slab's temperature)"},
                       .ncolumns = titles ? run->nrows : 0,
                       .column_title = (const char *const *)titles};
    const int rc = titles ? asl_write(run, &f, &pl, nomem) : 0;
    if (titles == NULL)
        *nomem |= asx_plot_free(&pl);
    for (size_t i = 0; titles != NULL && i < run->nrows; i++)
        free(titles[i]);
    free(titles);
    return rc;
}

/* E Fig. 3: the four central and the three top layers against s. */
static int asl_layers_figure(const vfy_case_run *run, int *nomem)
{
    static const char *const centre[] = {"ux_centre", "n_centre", "T_centre"};
    static const char *const top[] = {"ux_top", "n_top", "T_top"};
    static const double plus[] = {1.0, 1.0, 1.0};
    asx_plot pl = {0};
    for (size_t i = 0; i < run->nrows; i++) {
        const vfy_row *row = &run->rows[i];
        const double beta = sim_scene_collision_rate_factor(&row->solver);
        asx_dsmc(&pl, row, "s", beta, centre, plus, 3);
        asl_label(&pl, row, " centre");
        asl_style(&pl, row, 0);
        asx_dsmc(&pl, row, "s", beta, top, plus, 3);
        asl_label(&pl, row, " top");
        asl_style(&pl, row, 1);
    }
    char name[96];
    snprintf(name, sizeof name, "%s-layers", run->c->name);
    vfy_xy_figure f = {.name = name, .title = "paper E Fig. 3: u_x/(U/2), n_I/n and T_I/T of the "
                       "central and the top layers against s (EHS: s'/beta)", .xlabel = "s",
                       .comment = run->comment, .logx = 1, .npanels = 3,
                       .ylabel = {"u_x/(U/2) (U = aL)", "n_I/n (n the mean density)",
                                  "T_I/T (T the slab's temperature)"}};
    return asl_write(run, &f, &pl, nomem);
}

/* E Fig. 4: T/T0 and the reduced stresses against s. */
static int asl_stress_figure(const vfy_case_run *run, int *nomem)
{
    static const char *const stress[] = {"T_ratio", "Pxy_reduced", "N1"};
    static const double plus[] = {1.0, 1.0, 1.0};
    asx_plot pl = {0};
    for (size_t i = 0; i < run->nrows; i++) {
        const vfy_row *row = &run->rows[i];
        asx_dsmc(&pl, row, "s", sim_scene_collision_rate_factor(&row->solver), stress, plus, 3);
        asl_label(&pl, row, "");
        asl_style(&pl, row, 0);
    }
    char name[96];
    snprintf(name, sizeof name, "%s-stress", run->c->name);
    vfy_xy_figure f = {.name = name, .title = "paper E Fig. 4: T/T0 and the reduced stresses "
                       "against s (EHS: s'/beta)", .xlabel = "s", .comment = run->comment,
                       .logx = 1, .npanels = 3,
                       .ylabel = {"T/T0 (T0 the initial temperature)", "-Pxy/nT",
                                  "(Pxx - Pyy)/nT"}};
    return asl_write(run, &f, &pl, nomem);
}

/* After the rows: E Figs. 1-4 of the slab. */
static sim_status as_slab_after(vfy_case_run *run, vfy_report *r, char *msg, size_t msglen)
{
    (void)r;
    int nomem = 0, rc = asl_collisions_figure(run, &nomem);
    rc |= asl_profiles_figure(run, &nomem);
    rc |= asl_layers_figure(run, &nomem);
    rc |= asl_stress_figure(run, &nomem);
    return asx_figures_written(run, rc, nomem, msg, msglen);
}

/* ============================================================= as-slab-vs-homogeneous */

/* The s windows of the hydrodynamic regime compared (E Fig. 9: from about one
 * collision per particle the stage is hydrodynamic; after s = 4 the slab's
 * profiles are uniform). */
static const double asv_windows[3] = {10.0, 20.0, 40.0};

/* Series a averaged over the outputs with s in window x (0: [10, 20), 1: [20,
 * 40)); b = "ci": the mean of its half-widths there (an upper bound of the
 * average's, the outputs being positively correlated). */
static double asv_window(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    double *ci = NULL, *v = asx_series(row, m->a, &ci), *s = asx_series(row, "s", NULL);
    double sum = 0.0, count = 0.0;
    const int w = (int)m->x;
    for (size_t k = 0; v && s && k < row->res.outputs; k++)
        if (s[k] >= asv_windows[w] && s[k] < asv_windows[w + 1]) {
            sum += m->b ? ci[k] : v[k];
            count += 1.0;
        }
    free(v);
    free(s);
    return count > 0.0 ? sum / count : NAN;
}

/* |q - q_hom| over the quadrature sum of the half-widths q_ci_t, against the
 * homogeneous (first) row; NAN on it. */
static double asv_z_homogeneous(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    if (row->index == 0)
        return NAN;
    const vfy_row *hom = &run->rows[0];
    char ci[40];
    snprintf(ci, sizeof ci, "%s_ci_t", m->a);
    return vfy_z_pair(vfy_values_get(&row->values, m->a), vfy_values_get(&row->values, ci),
                      vfy_values_get(&hom->values, m->a), vfy_values_get(&hom->values, ci));
}


/* The functions this file's case files name (named.h, registry.c). */
const vfy_named_fn vfy_as_named[] = {
    VFY_NAMED_METRIC("as_judged", as_judged),
    VFY_NAMED_METRIC("as_T_ratio", as_T_ratio),
    VFY_NAMED_METRIC("as_shell_percent", as_shell_percent),
    VFY_NAMED_METRIC("as_balance", as_balance),
    VFY_NAMED_METRIC("as_v12_sonine", as_v12_sonine),
    VFY_NAMED_METRIC("asx_collision_ratio", asx_collision_ratio),
    VFY_NAMED_METRIC("asx_s_relax", asx_s_relax),
    VFY_NAMED_METRIC("asx_eta_collapse", asx_eta_collapse),
    VFY_NAMED_METRIC("asx_bgk_T_dev", asx_bgk_T_dev),
    VFY_NAMED_METRIC("asx_s_models", asx_s_models),
    VFY_NAMED_HOOK("as_transient_after", as_transient_after),
    VFY_NAMED_METRIC("asd_partner_dev", asd_partner_dev),
    VFY_NAMED_METRIC("asd_bgk_ratio", asd_bgk_ratio),
    VFY_NAMED_METRIC("asd_region", asd_region),
    VFY_NAMED_GUARD("asd_guard_resolved", asd_guard_resolved),
    VFY_NAMED_CURVE_X("as_curve_marginals_g", as_curve_marginals, 0),
    VFY_NAMED_CURVE_X("as_curve_marginals_F", as_curve_marginals, 1),
    VFY_NAMED_CURVE_X("as_curve_bgk_g", as_curve_model, ASD_BGK_G),
    VFY_NAMED_CURVE_X("as_curve_bgk_F", as_curve_model, ASD_BGK_F),
    VFY_NAMED_CURVE_X("as_curve_equilibrium_g", as_curve_model, ASD_EQ_G),
    VFY_NAMED_CURVE_X("as_curve_equilibrium_F", as_curve_model, ASD_EQ_F),
    VFY_NAMED_METRIC("asl_at", asl_at),
    VFY_NAMED_METRIC("asl_at_s", asl_at_s),
    VFY_NAMED_METRIC("asl_extreme", asl_extreme),
    VFY_NAMED_METRIC("asl_ux_linear", asl_ux_linear),
    VFY_NAMED_METRIC("asl_s_ratio", asl_s_ratio),
    VFY_NAMED_METRIC("asl_percent_ihs", asl_percent_ihs),
    VFY_NAMED_HOOK("as_slab_after", as_slab_after),
    VFY_NAMED_METRIC("asv_window", asv_window),
    VFY_NAMED_METRIC("asv_z_homogeneous", asv_z_homogeneous),
    VFY_NAMED_END};
