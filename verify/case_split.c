/* The splitting error of the time-step scheme (SPEC §10), measured against
 * the exact jump scheme on the white-noise heated hard-sphere gas of paper A
 * Ex 5 (verify/scenes/split-ex5.ini).
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
 * differences stand CLEAN_RATIO times above their half-widths; otherwise it
 * is skipped with the reason.  Each row's CPU time, candidates and collisions
 * give the cost; the notes compare what each scheme pays for a given error.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "case_report.h"
#include "cases.h"
#include "figure.h"
#include "steady.h"
#include "table.h"

#define SPLIT_LEVELS_MAX 6
#define CLEAN_RATIO 3.0       /* a difference counts when above 3 x its half-width */
#define EULER_CF_LO 1.6
#define EULER_CF_HI 2.5
#define STRANG_CF_LO 3.2
#define STRANG_CF_HI 5.0
#define MIN_HALVINGS 3
#define A2_ASYMPTOTIC 0.25    /* a2's CF is judged where |da2| <= 0.25 |a2| at the larger h */

typedef struct split_row {
    sim_splitting split;
    double h;
    double T, T_ci, a2, a2_ci;     /* time averages */
    double dT, dT_ci, da2, da2_ci; /* minus the jump run's */
    double dTmax, dTmax_noise;     /* max over t of |T(t) - T_jump(t)|, and of its ci */
    double cpu, wall;
    sim_counts counts;
} split_row;

/* Run the scene; fill the row's time averages and cost; keep T(t) in Tt. */
static sim_status split_run(const sim_scene *s, const vfy_options *o, const char *label,
                            split_row *row, double *Tt, double *Tt_ci, char *msg,
                            size_t msglen)
{
    sim_ensemble_result res;
    sim_status status = vfy_simulate(s, o, label, &res, msg, msglen);
    if (status == SIM_OK) {
        row->T = sim_result_steady_mean(&res, SIM_STEADY_T);
        row->T_ci = sim_result_steady_ci(&res, SIM_STEADY_T);
        row->a2 = sim_result_steady_mean(&res, SIM_STEADY_A2);
        row->a2_ci = sim_result_steady_ci(&res, SIM_STEADY_A2);
        vfy_result_column(&res, SIM_OBS_T, Tt, Tt_ci);
        row->cpu = res.cpu_seconds;
        row->wall = res.wall_seconds;
        row->counts = res.counts;
        if (o->progress)
            fprintf(o->progress, "   %s: T = %.6f ± %.6f, a2 = %.5f ± %.5f (%.1f s)\n", label,
                    row->T, row->T_ci, row->a2, row->a2_ci, res.wall_seconds);
    }
    sim_ensemble_result_free(&res);
    return status;
}

/* Judge the halvings of one splitting: CF of |dT| (and of |da2| where it is
 * resolved) between consecutive rows.  Returns the number of judged
 * halvings of T. */
static size_t split_judge(vfy_report *r, const char *case_name, const char *split_name,
                          const split_row *rows, size_t count, double a2_ref, double lo,
                          double hi, double *cf, double *cf_a2)
{
    size_t judged = 0;
    char name[160], why[240];
    for (size_t k = 0; k < count; k++) {
        cf[k] = cf_a2[k] = NAN;
        if (k == 0)
            continue;
        const split_row *p = &rows[k - 1], *q = &rows[k];
        cf[k] = fabs(p->dT) / fabs(q->dT);
        cf_a2[k] = fabs(p->da2) / fabs(q->da2);
        vfy_name(name, sizeof name, "%s %s h=%g->%g CF of the T difference", case_name,
                 split_name, p->h, q->h);
        if (fabs(p->dT) > CLEAN_RATIO * p->dT_ci && fabs(q->dT) > CLEAN_RATIO * q->dT_ci) {
            vfy_check_range(r, name, cf[k], lo, hi);
            judged++;
        } else {
            snprintf(why, sizeof why, "difference %.3g ± %.3g at h = %g not %g times its "
                     "half-width: CF %.3g not judged", fabs(q->dT), q->dT_ci, q->h,
                     CLEAN_RATIO, cf[k]);
            vfy_skip(r, name, why);
        }
        vfy_name(name, sizeof name, "%s %s h=%g->%g CF of the a2 difference", case_name,
                 split_name, p->h, q->h);
        if (fabs(p->da2) > A2_ASYMPTOTIC * fabs(a2_ref)) {
            snprintf(why, sizeof why, "difference %.3g at h = %g is not small against a2 = "
                     "%.3g itself (it saturates: a large kick makes f Maxwellian): CF %.3g "
                     "not judged", fabs(p->da2), p->h, a2_ref, cf_a2[k]);
            vfy_skip(r, name, why);
        } else if (fabs(p->da2) > CLEAN_RATIO * p->da2_ci
                   && fabs(q->da2) > CLEAN_RATIO * q->da2_ci)
            vfy_check_range(r, name, cf_a2[k], lo, hi);
        else {
            snprintf(why, sizeof why, "difference %.3g ± %.3g at h = %g not %g times its "
                     "half-width: CF %.3g not judged", fabs(q->da2), q->da2_ci, q->h,
                     CLEAN_RATIO, cf_a2[k]);
            vfy_skip(r, name, why);
        }
    }
    return judged;
}

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
    double det = scc * snn - scn * scn;
    m.alpha = (scy * snn - sny * scn) / det;
    m.beta = (scc * sny - scn * scy) / det;
    if (!(m.beta >= 0.0) || !(m.alpha > 0.0)) {
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
        if (fabs(rows[k].dT) > CLEAN_RATIO * rows[k].dT_ci)
            return rows[k].h * pow(eps / fabs(rows[k].dT), 1.0 / order);
    return NAN;
}

/* The figure: |difference in T̄| against h, log-log, with error bars. */
static int split_figure(const vfy_options *o, const char *name, const char *comment,
                        const split_row *rows, size_t levels)
{
    char data[1024], gp[1024], png[1024], tmp[1100], file[200];
    snprintf(file, sizeof file, "%s-points", name);
    FILE *f = vfy_file_begin(vfy_report_path(o, file, ".csv", data, sizeof data), tmp,
                             sizeof tmp);
    if (f == NULL)
        return -1;
    vfy_write_comment(f, comment);
    fprintf(f, "h,euler_dT,euler_dT_ci,strang_dT,strang_dT_ci\n");
    for (size_t k = 0; k < levels; k++)
        fprintf(f, "%.10g,%.6g,%.4g,%.6g,%.4g\n", rows[k].h, fabs(rows[k].dT), rows[k].dT_ci,
                fabs(rows[levels + k].dT), rows[levels + k].dT_ci);
    if (vfy_file_commit(f, tmp, data, 1) != 0)
        return -1;
    f = vfy_file_begin(vfy_report_path(o, name, ".gp", gp, sizeof gp), tmp, sizeof tmp);
    if (f == NULL)
        return -1;
    vfy_write_comment(f, comment);
    const double h0 = rows[0].h, e0 = fabs(rows[0].dT), s0 = fabs(rows[levels].dT);
    fprintf(f, "# %s: gnuplot %s\nset terminal pngcairo size 900,650 font ',10'\n"
               "set termoption noenhanced\nset output '%s'\nset datafile separator ','\n"
               "set title '%s: |time-step - jump| in the time-averaged T'\n"
               "set xlabel 'h'\nset ylabel '|difference in T|'\nset logscale xy\n"
               "set key top left\n"
               "plot '%s' skip 1 using 1:2:3 with yerrorbars pt 5 title 'Euler ± c',"
               " '%s' skip 1 using 1:4:5 with yerrorbars pt 7 title 'Strang ± c',"
               " %.6g*(x/%.6g) with lines dt 2 title 'slope 1',"
               " %.6g*(x/%.6g)**2 with lines dt 3 title 'slope 2'\n",
            name, gp, vfy_report_path(o, name, ".png", png, sizeof png), name, data, data, e0,
            h0, s0, h0);
    if (vfy_file_commit(f, tmp, gp, 1) != 0)
        return -1;
    if (vfy_gnuplot(gp) < 0 && o->progress)
        fprintf(o->progress, "   note: gnuplot failed on %s\n", gp);
    return 0;
}

/* One row of the case's table; CF cells (NaN: not known yet, or the first
 * step) are empty. */
static void split_table_row(vfy_table *t, const split_row *q, int is_jump, int strang,
                            double cf, double cf_a2)
{
    const double coll = (double)q->counts.collisions;
    vfy_table_cell(t, "%s", is_jump ? "jump" : strang ? "strang" : "euler");
    vfy_table_number(t, !is_jump, "%g", q->h);
    vfy_table_cell(t, "%.6f", q->T);
    vfy_table_cell(t, "%.6f", q->T_ci);
    vfy_table_number(t, !is_jump, "%+.3e", q->dT);
    vfy_table_number(t, !is_jump, "%.2e", q->dT_ci);
    vfy_table_number(t, !is_jump && !isnan(cf), "%.2f", cf);
    vfy_table_number(t, !is_jump, "%.3e", q->dTmax);
    vfy_table_number(t, !is_jump, "%.2e", q->dTmax_noise);
    vfy_table_cell(t, "%.5f", q->a2);
    vfy_table_cell(t, "%.5f", q->a2_ci);
    vfy_table_number(t, !is_jump, "%+.3e", q->da2);
    vfy_table_number(t, !is_jump, "%.2e", q->da2_ci);
    vfy_table_number(t, !is_jump && !isnan(cf_a2), "%.2f", cf_a2);
    vfy_table_cell(t, "%.2f", q->cpu);
    vfy_table_cell(t, "%.2f", q->wall);
    vfy_table_cell(t, "%llu", (unsigned long long)q->counts.candidates);
    vfy_table_cell(t, "%llu", (unsigned long long)q->counts.collisions);
    vfy_table_cell(t, "%llu", (unsigned long long)q->counts.normals);
    vfy_table_cell(t, "%.1f", coll > 0 ? 1e9 * q->cpu / coll : 0.0);
}

sim_status vfy_case_split(const vfy_case *c, const vfy_options *o, vfy_report *r, char *msg,
                          size_t msglen)
{
    sim_scene scene, solver;
    sim_status status = vfy_load_case_scene(c, o, &scene, &solver, msg, msglen);
    if (status != SIM_OK)
        return status;
    if (!solver.steady.present || solver.scheme != SIM_SCHEME_TIMESTEP) {
        snprintf(msg, msglen, "%s: the splitting case needs [steady] and scheme = timestep",
                 solver.file);
        return SIM_EINVAL;
    }
    const size_t levels = o->size == VFY_PAPER ? 5 : 3;
    if (o->size == VFY_QUICK) {   /* CI: small, so the small steps are skipped as noise */
        sim_scene *both[] = {&scene, &solver};
        for (int i = 0; i < 2; i++) {
            both[i]->particles.n = 200;
            both[i]->particles.ensembles = 60;
            both[i]->t_end = 16.0;
            both[i]->outputs = 11;
        }
    }
    const size_t M = solver.outputs;
    const double h0 = solver.dt;
    double *Tj = malloc(M * sizeof *Tj), *Tj_ci = malloc(M * sizeof *Tj_ci);
    double *Tt = malloc(M * sizeof *Tt), *Tt_ci = malloc(M * sizeof *Tt_ci);
    split_row jump = {0}, rows[2 * SPLIT_LEVELS_MAX];
    memset(rows, 0, sizeof rows);
    static const char *const cols[] = {
        "scheme", "h", "T", "T_ci", "dT", "dT_ci", "CF_T", "dTmax_t", "dTmax_noise", "a2",
        "a2_ci", "da2", "da2_ci", "CF_a2", "cpu_s", "wall_s", "candidates", "collisions",
        "normals", "ns_per_collision"};
    vfy_table table;
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    if (!Tj || !Tj_ci || !Tt || !Tt_ci) {
        snprintf(msg, msglen, "out of memory");
        status = SIM_ENOMEM;
        goto done;
    }

    char label[128], name[160];
    sim_scene s = scene;
    s.scheme = SIM_SCHEME_JUMP;
    s.splitting = SIM_SPLIT_EULER;
    snprintf(label, sizeof label, "%s jump", c->name);
    if ((status = split_run(&s, o, label, &jump, Tj, Tj_ci, msg, msglen)) != SIM_OK)
        goto done;
    vfy_check_count(r, vfy_name(name, sizeof name, "%s jump majorant violations", c->name),
                    jump.counts.violations, 0);
    split_table_row(&table, &jump, 1, 0, NAN, NAN);   /* rows so far, CF at the end */
    if ((status = vfy_write_rows_so_far(o, c->name, &table, &solver, msg, msglen)) != SIM_OK)
        goto done;

    for (size_t sp = 0; sp < 2 && status == SIM_OK; sp++) {
        for (size_t k = 0; k < levels && status == SIM_OK; k++) {
            split_row *row = &rows[sp * levels + k];
            s = solver;
            s.splitting = sp ? SIM_SPLIT_STRANG : SIM_SPLIT_EULER;
            s.dt = h0 / (double)(1u << k);
            row->split = s.splitting;
            row->h = s.dt;
            snprintf(label, sizeof label, "%s %s h=%g", c->name, sp ? "strang" : "euler", s.dt);
            if ((status = split_run(&s, o, label, row, Tt, Tt_ci, msg, msglen)) != SIM_OK)
                break;
            row->dT = row->T - jump.T;
            row->dT_ci = hypot(row->T_ci, jump.T_ci);
            row->da2 = row->a2 - jump.a2;
            row->da2_ci = hypot(row->a2_ci, jump.a2_ci);
            for (size_t m = 1; m < M; m++) {
                row->dTmax = fmax(row->dTmax, fabs(Tt[m] - Tj[m]));
                row->dTmax_noise = fmax(row->dTmax_noise, hypot(Tt_ci[m], Tj_ci[m]));
            }
            vfy_check_count(r, vfy_name(name, sizeof name, "%s %s majorant violations",
                                        c->name, label + strlen(c->name) + 1),
                            row->counts.violations, 0);
            split_table_row(&table, row, 0, (int)sp, NAN, NAN);
            status = vfy_write_rows_so_far(o, c->name, &table, &solver, msg, msglen);
        }
    }
    if (status != SIM_OK)
        goto done;

    double cf[2][SPLIT_LEVELS_MAX], cf_a2[2][SPLIT_LEVELS_MAX];
    size_t judged[2];
    judged[0] = split_judge(r, c->name, "euler", rows, levels, jump.a2, EULER_CF_LO,
                            EULER_CF_HI, cf[0], cf_a2[0]);
    judged[1] = split_judge(r, c->name, "strang", rows + levels, levels, jump.a2, STRANG_CF_LO,
                            STRANG_CF_HI, cf[1], cf_a2[1]);
    for (int sp = 0; sp < 2; sp++) {
        vfy_name(name, sizeof name, "%s %s halvings judged (difference above %g x its "
                 "half-width)", c->name, sp ? "strang" : "euler", CLEAN_RATIO);
        if (o->size == VFY_PAPER)
            vfy_check_range(r, name, (double)judged[sp], MIN_HALVINGS, INFINITY);
        else
            vfy_skip(r, name, "quick sizes: the statistical error hides the small steps");
    }

    /* The table: the jump row, then each splitting's rows. */
    vfy_table_free(&table);
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    split_table_row(&table, &jump, 1, 0, NAN, NAN);
    for (size_t k = 0; k < 2 * levels; k++) {
        const int sp = k >= levels, first = k % levels == 0;   /* no CF at the first step */
        split_table_row(&table, &rows[k], 0, sp, first ? NAN : cf[sp][k % levels],
                        first ? NAN : cf_a2[sp][k % levels]);
    }

    /* What a given accuracy costs: for a target error eps of T̄ (relative to
     * T̄), the step each splitting needs (from its error at its smallest
     * resolved step and its order) and the CPU time at that step (cpu = a +
     * b/h fitted to its rows), beside the jump scheme, which has no
     * splitting error at any cost. */
    char cost[1400] = "", line[300];
    static const double targets[] = {1e-2, 1e-3, 1e-4};
    const split_cost model = split_cost_fit(rows, 2 * levels);
    const double initial = 3.0 * (double)solver.particles.n * (double)solver.particles.ensembles;
    snprintf(cost, sizeof cost, " %.1f ns per candidate, %.1f ns per normal variate (least "
             "squares over the time-step rows);", 1e9 * model.alpha, 1e9 * model.beta);
    for (size_t i = 0; i < 3; i++) {
        const double eps = targets[i] * jump.T;
        const double he = split_step_for(rows, levels, 1.0, eps);
        const double hs = split_step_for(rows + levels, levels, 2.0, eps);
        snprintf(line, sizeof line, "%s relative error %.0e: Euler h = %.3g (%.0f CPU s), "
                 "Strang h = %.3g (%.0f CPU s), jump %.0f CPU s", i ? ";" : "", targets[i], he,
                 split_cost_at(&model, rows, levels, he, initial), hs,
                 split_cost_at(&model, rows + levels, levels, hs, initial), jump.cpu);
        strncat(cost, line, sizeof cost - strlen(cost) - 1);
    }
    if (o->progress)
        fprintf(o->progress, "   %s: cost of a splitting error of T̄ at N = %zu, n = %zu:%s\n",
                c->name, solver.particles.ensembles, solver.particles.n, cost);

    double wall = jump.wall;
    for (size_t k = 0; k < 2 * levels; k++)
        wall += rows[k].wall;
    char comment[600], notes[4000], title[200];
    vfy_run_comment(&solver, comment, sizeof comment);
    snprintf(title, sizeof title, "%s: splitting error of the time-step scheme against the "
             "exact jump scheme, paper A Ex 5's gas (%s sizes)", c->name,
             o->size == VFY_PAPER ? "paper" : "quick");
    snprintf(notes, sizeof notes,
             "%s; n = %zu, N = %zu in every row.\n\nT, a2: each ensemble's time average over "
             "the output times t in [%g, %g] (steady state), T_ci, a2_ci = 3.2 x the standard "
             "error over the N ensembles. dT, da2 = time-step row minus the jump row, with "
             "the half-width of a difference of independent runs, sqrt(c1^2 + c2^2). CF = "
             "|d| at 2h / |d| at h, judged (Euler in [%g, %g], Strang in [%g, %g]) only "
             "where both differences exceed %g times their half-widths, and for a2 only "
             "where its difference at 2h is at most a quarter of a2 itself (at larger h "
             "the Gaussian kicks of one step make f nearly Maxwellian and the difference "
             "saturates at about -a2). dTmax_t = max over "
             "the output times of |T(t) - T_jump(t)| (the transient included), "
             "dTmax_noise its largest half-width. Strang merges the half flights of "
             "adjacent steps (exact for white noise), so it costs what Euler costs. "
             "ns_per_collision = CPU time per accepted collision, everything included "
             "(the time-step rows pay about 4 candidates per jump-scheme candidate for the "
             "contact rule, plus one Gaussian kick per particle and step; normals = "
             "standard normal variates drawn).\n\nCost of a splitting error of T̄ at "
             "these n and N (the step from each splitting's order and its smallest "
             "resolved difference; the CPU time from a cost model fitted to the rows, "
             "with the candidates of the smallest step and the flights scaled to the "
             "step):%s. "
             "Total wall time %.1f s.",
             comment, solver.particles.n, solver.particles.ensembles, solver.steady.from,
             solver.t_end, EULER_CF_LO, EULER_CF_HI, STRANG_CF_LO, STRANG_CF_HI, CLEAN_RATIO,
             cost, wall);
    if ((status = vfy_write_case_tables(o, c->name, &table, comment, title, notes, msg,
                                        msglen)) != SIM_OK)
        goto done;
    if (split_figure(o, c->name, comment, rows, levels) != 0)
        status = vfy_io_error(c->name, msg, msglen);
done:
    vfy_table_free(&table);
    free(Tj);
    free(Tj_ci);
    free(Tt);
    free(Tt_ci);
    return status;
}
