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
 * this file holds the metrics, guards, rules and curves they name, listed
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

/* ------------------------------------------------------------ over the rows */

/* The time-step rows (every row after the jump row, Euler's `levels` then
 * Strang's) as split_rows, in *rows (the caller frees it); returns levels,
 * or 0 (none, or out of memory). */
static size_t split_rows(const vfy_case_run *run, split_row **rows)
{
    const size_t levels = (run->nrows - 1) / 2;
    *rows = levels ? calloc(2 * levels, sizeof **rows) : NULL;
    if (*rows == NULL)
        return 0;
    for (size_t k = 0; k < 2 * levels; k++) {
        const vfy_row *q = &run->rows[1 + k];
        (*rows)[k] = (split_row){vfy_values_get(&q->values, "h"),
                                 vfy_values_get(&q->values, "dT"),
                                 vfy_values_get(&q->values, "dT_ci"),
                                 vfy_values_get(&q->values, "cpu_s"), q->res.counts};
    }
    return levels;
}

/* Whether m->a names Strang ("strang"), else Euler ("euler"). */
static int is_strang(const vfy_metric *m) { return strcmp(m->a, "strang") == 0; }

/* How many halvings of T the splitting m->a could judge: both differences
 * VFY_TOL_SPLIT_CLEAN_RATIO times above their half-widths (a case metric). */
static double split_judged(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)row;
    size_t judged = 0;
    for (size_t i = 1; i < run->nrows; i++) {
        const vfy_row *q = &run->rows[i];
        judged += strcmp(vfy_row_text(q, "scheme"), m->a) == 0
                  && !isnan(vfy_values_get(&q->values, "h_prev"))
                  && clean_halving(q, "dT_abs", "dT_ci");
    }
    return (double)judged;
}

/* What a given accuracy costs (case metrics for the notes and the progress
 * line): the cost model's ns per candidate (x = 0) and per normal variate
 * (x = 1); for a target error x of T̄ (relative to the jump row's T̄), the
 * step splitting m->a needs (split_step, from its error at its smallest
 * resolved step and its order) and the CPU seconds at that step
 * (split_cpu), beside the jump scheme, which has no splitting error at any
 * cost. */
enum { COST_STEP, COST_CPU };
static double split_cost_value(const vfy_case_run *run, const vfy_metric *m, int which)
{
    split_row *rows;
    const size_t levels = split_rows(run, &rows);
    if (levels == 0)
        return NAN;
    const split_cost model = split_cost_fit(rows, 2 * levels);
    const sim_scene *s = &run->rows[run->nrows - 1].solver;
    const double initial = 3.0 * (double)s->particles.n * (double)s->particles.ensembles;
    const double eps = m->x * vfy_values_get(&run->rows[0].values, "T");
    const int strang = is_strang(m);
    const split_row *own = rows + (strang ? levels : 0);
    const double h = split_step_for(own, levels, strang ? 2.0 : 1.0, eps);
    const double v = which == COST_STEP ? h : split_cost_at(&model, own, levels, h, initial);
    free(rows);
    return v;
}

static double split_step(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)row;
    return split_cost_value(run, m, COST_STEP);
}

static double split_cpu(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)row;
    return split_cost_value(run, m, COST_CPU);
}

static double split_cost_model(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m)
{
    (void)row;
    split_row *rows;
    const size_t levels = split_rows(run, &rows);
    if (levels == 0)
        return NAN;
    const split_cost model = split_cost_fit(rows, 2 * levels);
    free(rows);
    return 1e9 * (m->x == 1.0 ? model.beta : model.alpha);
}

/* The figure's curves (split-case.inc): |difference in T̄| of a splitting
 * against h with its half-widths, or the slope 1 (Euler's) or 2 (Strang's)
 * through its largest step. */
enum { CURVE_EULER, CURVE_STRANG, CURVE_SLOPE_1, CURVE_SLOPE_2 };
static int split_curve(const vfy_case_run *run, double which, vfy_curve *out)
{
    split_row *rows;
    const size_t levels = split_rows(run, &rows);
    const int data = which == CURVE_EULER || which == CURVE_STRANG;
    if (levels == 0 || vfy_curve_alloc(out, levels, data) != 0) {
        free(rows);
        return -1;
    }
    const split_row *own = rows + (which == CURVE_STRANG || which == CURVE_SLOPE_2 ? levels : 0);
    const double h0 = rows[0].h, d0 = fabs(own[0].dT);
    for (size_t k = 0; k < levels; k++) {
        const double r = rows[k].h / h0;
        out->x[k] = rows[k].h;
        out->y[0][k] = data ? fabs(own[k].dT) : which == CURVE_SLOPE_1 ? d0 * r : d0 * r * r;
        if (data)
            out->ci[0][k] = own[k].dT_ci;
    }
    free(rows);
    return 0;
}

static int split_curve_fn(const vfy_case_run *run, const vfy_row *row, double x, vfy_curve *out)
{
    (void)row;
    return split_curve(run, x, out);
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
    VFY_NAMED_METRIC("split_judged", split_judged),
    VFY_NAMED_METRIC("split_step", split_step),
    VFY_NAMED_METRIC("split_cpu", split_cpu),
    VFY_NAMED_METRIC_X("split_ns_per_candidate", split_cost_model, 0),
    VFY_NAMED_METRIC_X("split_ns_per_normal", split_cost_model, 1),
    VFY_NAMED_CURVE_X("split_curve_euler", split_curve_fn, CURVE_EULER),
    VFY_NAMED_CURVE_X("split_curve_strang", split_curve_fn, CURVE_STRANG),
    VFY_NAMED_CURVE_X("split_curve_slope_1", split_curve_fn, CURVE_SLOPE_1),
    VFY_NAMED_CURVE_X("split_curve_slope_2", split_curve_fn, CURVE_SLOPE_2),
    VFY_NAMED_END};
