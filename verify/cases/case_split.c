/* The splitting error of the time-step scheme (docs/theory.md §8.5), measured against
 * the exact jump scheme on the white-noise heated hard-sphere gas of paper A
 * Ex 5 (split-ex5, verify/cases/scenes/split-ex5.ini) and on the same hard spheres
 * with the Gaussian thermostat (split-gaussian, split-gaussian.ini: the jump
 * scheme runs it exactly, engine.c run_jump_linear).
 *
 * One run with the jump scheme (no splitting: its only errors are the O(1/n)
 * bias and noise, which every row shares) of the scene as the references see
 * it (--set), then the time-step scheme of the solver's scene (--set and
 * --solver-set: a deliberately wrong solver changes only these rows) with
 * h = dt, dt/2, ... for Euler (collide h, then free flight h: first order)
 * and Strang (free flight h/2, collide h, free flight h/2: second order)
 * splitting, all with the same n, N and seed.  For each row, the difference
 * from the jump run of
 *   - T̄ and ā2, each ensemble's time average over the output times
 *     t >= steady.from (steady.h), with the confidence half-width of a
 *     difference of two independent runs, sqrt(c_1^2 + c_2^2);
 *   - T(t) in the max norm over the output times (the transient included).
 * CF = difference at 2h / difference at h: about 2 for Euler, 4 for Strang.
 * Common random numbers across schemes are impossible (the schemes consume
 * random numbers differently), so a halving is judged only when both
 * differences stand VFY_TOL_SPLIT_CLEAN_RATIO times above their half-widths;
 * otherwise it is skipped with the reason.  Each row's CPU time, candidates and collisions
 * give the cost; the notes compare what each scheme pays for a given error.
  *
 * The cases are data (verify/cases/scenes/split-*.case, docs/adding-a-case.md);
 * this file holds the metrics, guards, rules and hooks they name, listed
 * in vfy_split_named at its end.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "case_report.h"
#include "driver.h"
#include "figure.h"
#include "named.h"
#include "tolerances.h"

typedef struct split_row {
    double h, dT, dT_ci, cpu;
    sim_counts counts;
} split_row;

/* The time-step scheme's cost model: CPU seconds = alpha x candidates +
 * beta x normal variates (the collision stages and the white-noise flights),
 * least squares over all time-step rows; beta = 0 if the fit makes it
 * negative (noise). */
typedef struct split_cost {
    double alpha, beta;   /* seconds per candidate, per normal variate */
} split_cost;

static split_cost split_cost_fit(const split_row *rows, size_t count)
{
    double scc = 0, scn = 0, snn = 0, scy = 0, sny = 0;
    for (size_t k = 0; k < count; k++) {
        double c = (double)rows[k].counts.candidates, n = (double)rows[k].counts.normals;
        scc += c * c;
        scn += c * n;
        snn += n * n;
        scy += c * rows[k].cpu;
        sny += n * rows[k].cpu;
    }
    split_cost m;
    /* without white noise every row draws the same normals (its initial
     * state's): no flights to fit */
    const int flights = rows[0].counts.normals != rows[count - 1].counts.normals;
    double det = flights ? scc * snn - scn * scn : 0.0;
    m.alpha = (scy * snn - sny * scn) / det;
    m.beta = (scc * sny - scn * scy) / det;
    if (!flights || !(m.beta >= 0.0) || !(m.alpha > 0.0)) {
        m.beta = 0.0;
        m.alpha = scy / scc;
    }
    return m;
}

/* CPU seconds of a splitting at step h: the candidates of its smallest step
 * (they no longer depend on h there) and its flights scaled to h. */
static double split_cost_at(const split_cost *m, const split_row *rows, size_t count,
                            double h, double initial_normals)
{
    const split_row *q = &rows[count - 1];
    double normals = initial_normals
                     + ((double)q->counts.normals - initial_normals) * q->h / h;
    return m->alpha * (double)q->counts.candidates + m->beta * normals;
}

/* The step at which the splitting's T error is eps: from the last judged
 * row, err(h) = err_k (h/h_k)^order. */
static double split_step_for(const split_row *rows, size_t count, double order, double eps)
{
    for (size_t k = count; k-- > 0;)
        if (fabs(rows[k].dT) > VFY_TOL_SPLIT_CLEAN_RATIO * rows[k].dT_ci)
            return rows[k].h * pow(eps / fabs(rows[k].dT), 1.0 / order);
    return NAN;
}

/* The figure: |difference in T̄| against h, log-log, with error bars, beside
 * slope 1 and slope 2 through each splitting's largest step (figure.h). */
static int split_figure(const vfy_options *o, const char *name, const char *comment,
                        const split_row *rows, size_t levels)
{
    double *buf = malloc(7 * levels * sizeof *buf);
    if (buf == NULL)
        return -1;
    double *h = buf, *e = buf + levels, *ec = e + levels, *s = ec + levels, *sc = s + levels;
    double *one = sc + levels, *two = one + levels;
    const double h0 = rows[0].h, e0 = fabs(rows[0].dT), s0 = fabs(rows[levels].dT);
    for (size_t k = 0; k < levels; k++) {
        h[k] = rows[k].h;
        e[k] = fabs(rows[k].dT);
        ec[k] = rows[k].dT_ci;
        s[k] = fabs(rows[levels + k].dT);
        sc[k] = rows[levels + k].dT_ci;
        one[k] = e0 * (h[k] / h0);
        two[k] = s0 * (h[k] / h0) * (h[k] / h0);
    }
    char title[200];
    snprintf(title, sizeof title, "%s: |time-step - jump| in the time-averaged T", name);
    const char *series[] = {"Euler |dT|", "Strang |dT|"}, *curves[] = {"slope 1", "slope 2"};
    const double *ys[] = {e, s}, *cs[] = {ec, sc}, *yf[] = {one, two};
    const vfy_points fig = {.name = name, .title = title, .xlabel = "h",
                            .ylabel = "|difference in T|", .logy = 1, .logx = 1,
                            .npoints = levels, .x = h, .nseries = 2, .series = series, .y = ys,
                            .ci = cs, .nfine = levels, .xfine = h, .ncurves = 2,
                            .curves = curves, .yfine = yf, .comment = comment};
    int rc = vfy_write_points(o, &fig);
    free(buf);
    return rc;
}

/* ------------------------------------------------------------ the rows */

/* Against the jump row (the first): value a minus the jump row's. */
static double minus_jump(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    return row->index ? vfy_values_get(&row->values, m->a)
                            - vfy_values_get(&run->rows[0].values, m->a)
                      : NAN;
}

/* The half-width of that difference of independent runs, sqrt(c1^2 + c2^2). */
static double hypot_jump(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    return row->index ? hypot(vfy_values_get(&row->values, m->a),
                              vfy_values_get(&run->rows[0].values, m->a))
                      : NAN;
}

/* max over t > 0 of |T(t) - T_jump(t)| (x = 0), or of its half-width (x = 1). */
static double max_diff_jump(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const size_t M = row->res.outputs;
    double *buf = malloc(4 * M * sizeof *buf), worst = row->index ? 0.0 : NAN;
    if (buf == NULL)
        return NAN;
    vfy_row_series(row, m->a, buf, buf + M);
    vfy_row_series(&run->rows[0], m->a, buf + 2 * M, buf + 3 * M);
    for (size_t t = 1; row->index && t < M; t++)
        worst = fmax(worst, m->x ? hypot(buf[M + t], buf[3 * M + t])
                                 : fabs(buf[t] - buf[2 * M + t]));
    free(buf);
    return worst;
}

/* |value a| */
static double magnitude(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    return fabs(vfy_values_get(&row->values, m->a));
}

/* The previous row's value a, if it has the same splitting (else NAN). */
static double previous_same(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    const vfy_row *p = vfy_row_previous(run, row);
    return p && row->index > 1 && strcmp(vfy_row_text(p, "scheme"), vfy_row_text(row, "scheme")) == 0
               ? vfy_values_get(&p->values, m->a)
               : NAN;
}

/* CF = |d| at 2h / |d| at h within one splitting. */
static double cf_same(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    return previous_same(run, row, m) / vfy_values_get(&row->values, m->a);
}

/* CPU time per accepted collision, everything included. */
static double ns_per_collision(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)run;
    (void)m;
    double c = vfy_values_get(&row->values, "collisions");
    return c > 0 ? 1e9 * vfy_values_get(&row->values, "cpu_s") / c : 0.0;
}

/* A halving is judged only where both differences stand CLEAN_RATIO times
 * above their half-widths: value a (|d|) and its half-width b, this row's
 * and the previous one's ("_prev"); omitted where there is no halving. */
static int clean_halving(const vfy_row *row, const char *d, const char *ci)
{
    char prev_d[32], prev_ci[32];
    snprintf(prev_d, sizeof prev_d, "%s_prev", d);
    snprintf(prev_ci, sizeof prev_ci, "%s_prev", ci);
    const vfy_values *v = &row->values;
    return vfy_values_get(v, prev_d) > VFY_TOL_SPLIT_CLEAN_RATIO * vfy_values_get(v, prev_ci)
           && vfy_values_get(v, d) > VFY_TOL_SPLIT_CLEAN_RATIO * vfy_values_get(v, ci);
}

static vfy_guard_result halving_clean(const vfy_case_run *run, const vfy_row *row,
                                      const vfy_guard *g)
{
    (void)run;
    if (isnan(vfy_values_get(&row->values, "h_prev")))
        return VFY_OMIT;
    return clean_halving(row, g->a, g->b) ? VFY_JUDGE : VFY_GUARD_SKIP;
}

/* a2's CF is judged only where its difference at the larger step is small
 * against a2 itself (at larger h it saturates): the saturated halvings are
 * skipped with one reason (x = 1), the others judged when clean (x = 0). */
static int a2_saturated(const vfy_case_run *run, const vfy_row *row)
{
    return vfy_values_get(&row->values, "da2_abs_prev")
           > VFY_TOL_SPLIT_A2_ASYMPTOTIC * fabs(vfy_values_get(&run->rows[0].values, "a2"));
}

static vfy_guard_result a2_halving(const vfy_case_run *run, const vfy_row *row,
                                   const vfy_guard *g)
{
    if (isnan(vfy_values_get(&row->values, "h_prev")) || a2_saturated(run, row) != (g->x == 1))
        return VFY_OMIT;
    return g->x == 1 || !clean_halving(row, g->a, g->b) ? VFY_GUARD_SKIP : VFY_JUDGE;
}

/* CF within the splitting's order band: [1.6, 2.5] for Euler (first order),
 * [3.2, 5] for Strang (second). */
static vfy_verdict cf_in_band(vfy_report *r, const char *name, vfy_case_run *run, vfy_row *row,
                              const vfy_check_spec *c)
{
    (void)run;
    const int strang = strcmp(vfy_row_text(row, "scheme"), "strang") == 0;
    return vfy_check_range(r, name, vfy_values_get(&row->values, c->value),
                           strang ? VFY_TOL_SPLIT_STRANG_CF_LO : VFY_TOL_SPLIT_EULER_CF_LO,
                           strang ? VFY_TOL_SPLIT_STRANG_CF_HI : VFY_TOL_SPLIT_EULER_CF_HI);
}

static double jump_value(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)row;
    return vfy_values_get(&run->rows[0].values, m->a);
}

/* What a given accuracy costs (the notes and a progress line): for a target
 * error eps of T̄ (relative to T̄), the step each splitting needs (from its
 * error at its smallest resolved step and its order) and the CPU time at that
 * step, beside the jump scheme, which has no splitting error at any cost. */
#define SPLIT_COST_TEXT \
    " {cost_alpha:%.1f} ns per candidate, {cost_beta:%.1f} ns per normal variate (least " \
    "squares over the time-step rows); relative error 1e-02: Euler h = {he0:%.3g} ({ce0:%.0f} " \
    "CPU s), Strang h = {hs0:%.3g} ({cs0:%.0f} CPU s), jump {jump_cpu:%.0f} CPU s; relative " \
    "error 1e-03: Euler h = {he1:%.3g} ({ce1:%.0f} CPU s), Strang h = {hs1:%.3g} ({cs1:%.0f} " \
    "CPU s), jump {jump_cpu:%.0f} CPU s; relative error 1e-04: Euler h = {he2:%.3g} ({ce2:%.0f} " \
    "CPU s), Strang h = {hs2:%.3g} ({cs2:%.0f} CPU s), jump {jump_cpu:%.0f} CPU s"

static void split_cost_values(vfy_case_run *run, const split_row *rows, size_t levels)
{
    static const double targets[] = {1e-2, 1e-3, 1e-4};
    const split_cost model = split_cost_fit(rows, 2 * levels);
    const sim_scene *s = &run->rows[run->nrows - 1].solver;
    const double initial = 3.0 * (double)s->particles.n * (double)s->particles.ensembles;
    const double T_jump = vfy_values_get(&run->rows[0].values, "T");
    vfy_values *v = &run->values;
    vfy_values_set(v, "cost_alpha", 1e9 * model.alpha);
    vfy_values_set(v, "cost_beta", 1e9 * model.beta);
    vfy_values_set(v, "jump_cpu", vfy_values_get(&run->rows[0].values, "cpu_s"));
    for (size_t i = 0; i < 3; i++) {
        const double eps = targets[i] * T_jump;
        const double he = split_step_for(rows, levels, 1.0, eps);
        const double hs = split_step_for(rows + levels, levels, 2.0, eps);
        char name[8];
        const double cells[4] = {he, split_cost_at(&model, rows, levels, he, initial), hs,
                                 split_cost_at(&model, rows + levels, levels, hs, initial)};
        for (int c = 0; c < 4; c++) {
            snprintf(name, sizeof name, "%s%zu", (const char *[]){"he", "ce", "hs", "cs"}[c], i);
            vfy_values_set(v, name, cells[c]);
        }
    }
}

/* After the rows: how many halvings of T each splitting could judge (at
 * least min_halvings[0] for Euler, [1] for Strang at paper sizes), the cost
 * of a given accuracy, the notes' values and the figure. */
static sim_status split_after(vfy_case_run *run, vfy_report *r, const size_t min_halvings[2],
                              char *msg, size_t msglen)
{
    const size_t levels = (run->nrows - 1) / 2;
    split_row *rows = calloc(2 * levels + 1, sizeof *rows);
    if (rows == NULL) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    size_t judged[2] = {0, 0};
    for (size_t k = 0; k < 2 * levels; k++) {
        const vfy_row *q = &run->rows[1 + k];
        rows[k] = (split_row){vfy_values_get(&q->values, "h"), vfy_values_get(&q->values, "dT"),
                              vfy_values_get(&q->values, "dT_ci"),
                              vfy_values_get(&q->values, "cpu_s"), q->res.counts};
        judged[k >= levels] += !isnan(vfy_values_get(&q->values, "h_prev"))
                               && clean_halving(q, "dT_abs", "dT_ci");
    }
    for (int sp = 0; sp < 2; sp++) {
        char name[160];
        snprintf(name, sizeof name, "%s %s halvings judged (difference above %g x its "
                 "half-width)", run->c->name, sp ? "strang" : "euler", VFY_TOL_SPLIT_CLEAN_RATIO);
        if (run->o->size == VFY_PAPER)
            vfy_check_range(r, name, (double)judged[sp], (double)min_halvings[sp], INFINITY);
        else
            vfy_skip(r, name, "quick sizes: the statistical error hides the small steps");
    }
    split_cost_values(run, rows, levels);
    const sim_scene *s = &run->rows[run->nrows - 1].solver;
    const double v[] = {(double)s->particles.n, (double)s->particles.ensembles, s->steady.from,
                        s->t_end, VFY_TOL_SPLIT_EULER_CF_LO, VFY_TOL_SPLIT_EULER_CF_HI,
                        VFY_TOL_SPLIT_STRANG_CF_LO, VFY_TOL_SPLIT_STRANG_CF_HI,
                        VFY_TOL_SPLIT_CLEAN_RATIO};
    static const char *const names[] = {"n", "N", "steady_from", "t_end", "euler_lo",
                                        "euler_hi", "strang_lo", "strang_hi", "clean_ratio"};
    for (size_t i = 0; i < sizeof names / sizeof *names; i++)
        vfy_values_set(&run->values, names[i], v[i]);
    if (run->o->progress) {
        char cost[1400];
        fprintf(run->o->progress, "   %s: cost of a splitting error of T̄ at N = %zu, n = %zu:%s\n",
                run->c->name, s->particles.ensembles, s->particles.n,
                vfy_expand(cost, sizeof cost, SPLIT_COST_TEXT, run, NULL));
    }
    sim_status status = SIM_OK;
    if (split_figure(run->o, run->c->name, run->comment, rows, levels) != 0)
        status = vfy_io_error(run->c->name, msg, msglen);
    free(rows);
    return status;
}

static sim_status split_after_ex5(vfy_case_run *run, vfy_report *r, char *msg, size_t msglen)
{
    static const size_t min_halvings[2] = {VFY_TOL_SPLIT_MIN_HALVINGS,
                                           VFY_TOL_SPLIT_MIN_HALVINGS};
    return split_after(run, r, min_halvings, msg, msglen);
}

/* The Gaussian thermostat's Strang error is small beside its Euler error:
 * at the scene's N it stands clear of the noise for one or two halvings. */
static sim_status split_after_gaussian(vfy_case_run *run, vfy_report *r, char *msg,
                                       size_t msglen)
{
    static const size_t min_halvings[2] = {VFY_TOL_SPLIT_MIN_HALVINGS,
                                           VFY_TOL_SPLIT_GAUSSIAN_STRANG_MIN_HALVINGS};
    return split_after(run, r, min_halvings, msg, msglen);
}

/* The functions this file's case files name (named.h, registry.c). */
const vfy_named_fn vfy_split_named[] = {
    VFY_NAMED_METRIC("minus_jump", minus_jump),
    VFY_NAMED_METRIC("hypot_jump", hypot_jump),
    VFY_NAMED_METRIC("max_diff_jump", max_diff_jump),
    VFY_NAMED_METRIC("magnitude", magnitude),
    VFY_NAMED_METRIC("previous_same", previous_same),
    VFY_NAMED_METRIC("cf_same", cf_same),
    VFY_NAMED_METRIC("ns_per_collision", ns_per_collision),
    VFY_NAMED_GUARD("halving_clean", halving_clean),
    VFY_NAMED_GUARD("a2_halving", a2_halving),
    VFY_NAMED_RULE("cf_in_band", cf_in_band),
    VFY_NAMED_METRIC("jump_value", jump_value),
    VFY_NAMED_HOOK("split_after_ex5", split_after_ex5),
    VFY_NAMED_HOOK("split_after_gaussian", split_after_gaussian),
    VFY_NAMED_END};
