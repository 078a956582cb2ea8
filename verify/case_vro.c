/* vro-grw-ex3: variance-reduced observation on paper A Ex 3 (issue 4).
 *
 * The jump scheme applies the white-noise heating lazily: at an output time
 * every particle still owes a Brownian increment N(0, 2 beta (t - stamp_i))
 * per component.  scene.observation = sampled draws them and observes the
 * brought system (paper A); conditional records T, T_raw, u and P as their
 * exact expectations over those increments (sim/observe.h,
 * sim_observe_pending) and then brings the particles as before, so both modes
 * follow the same trajectories for the same seed and differ only by the noise
 * of the increments at the output times (Rao-Blackwell: the variance can
 * only drop, the mean is unchanged).
 *
 * Each row runs the scene both ways at one n and reports the variance
 * reduction factor Var_sampled / Var_conditional of T_raw and T (mean and
 * smallest over the output times t > 0).  Checks: the conditional means agree
 * with the exact expectations of the n-particle estimators (reference/heated.h)
 * within |z| <= 4.5 at every output time; the two modes agree with each other
 * (the same bound, with the sampled mode's half-width); the factor exceeds 1.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "case_report.h"
#include "cases.h"
#include "scene_ini.h"
#include "scene_refs.h"
#include "table.h"

#define ZMAX 4.5

/* Variance ratio of observable k, sampled over conditional, over m >= 1. */
static void variance_ratio(const sim_ensemble_result *s, const sim_ensemble_result *c, int k,
                           double *mean_ratio, double *min_ratio)
{
    double sum = 0.0, lo = INFINITY;
    for (size_t m = 1; m < s->outputs; m++) {
        double ratio = s->var[m * SIM_OBS_COUNT + (size_t)k] / c->var[m * SIM_OBS_COUNT + (size_t)k];
        sum += ratio;
        lo = fmin(lo, ratio);
    }
    *mean_ratio = sum / (double)(s->outputs - 1);
    *min_ratio = lo;
}

sim_status vfy_case_vro(const vfy_case *c, const vfy_options *o, vfy_report *r, char *msg,
                        size_t msglen)
{
    sim_scene scene, solver;
    sim_status status = vfy_load_scene_stem("grw-ex3", o, &scene, &solver, msg, msglen);
    if (status != SIM_OK)
        return status;
    static const char *const needs[] = {"T_finite_n", "T_raw_finite_n"};
    if ((status = vfy_require_references(&scene, needs, 2, VFY_NEEDS_MAXWELL, msg, msglen))
        != SIM_OK)
        return status;
    const size_t rows = o->size == VFY_PAPER ? 3 : 2, M = scene.outputs;
    if (o->size == VFY_QUICK)
        scene.particles.ensembles = solver.particles.ensembles = 2000;

    static const char *const cols[] = {"n", "N", "var_ratio_T_raw", "var_ratio_T_raw_min",
                                       "var_ratio_T", "var_ratio_T_min", "z_T_raw", "z_T",
                                       "z_modes", "cpu_s_sampled", "cpu_s_conditional"};
    vfy_table table;
    vfy_table_init(&table, sizeof cols / sizeof *cols, cols);
    double *buf = malloc(6 * M * sizeof *buf);
    if (buf == NULL) {
        vfy_table_free(&table);
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    double *finite = buf, *finite_raw = buf + M, *mean = buf + 2 * M, *ci = buf + 3 * M;
    double *mean_s = buf + 4 * M, *ci_s = buf + 5 * M;
    char name[160], comment[600];
    double ratio_raw_all = INFINITY;
    vfy_run_comment(&solver, comment, sizeof comment);

    for (size_t i = 0; i < rows && status == SIM_OK; i++) {
        const size_t n = (size_t)64 << (2 * i);
        scene.particles.n = solver.particles.n = n;
        vfy_refs refs;
        sim_error err;
        if ((status = vfy_scene_references(&scene, &refs, &err)) != SIM_OK) {
            vfy_scene_format_error(&scene, &err, msg, msglen);
            break;
        }
        vfy_refs_column(&refs, "T_finite_n", finite);
        vfy_refs_column(&refs, "T_raw_finite_n", finite_raw);
        vfy_refs_free(&refs);

        sim_ensemble_result res[2];   /* sampled, conditional: the same seed */
        memset(res, 0, sizeof res);
        char label[96];
        for (int mode = 0; mode < 2 && status == SIM_OK; mode++) {
            solver.observation = mode ? SIM_OBSERVE_CONDITIONAL : SIM_OBSERVE_SAMPLED;
            snprintf(label, sizeof label, "%s n=%zu %s", c->name, n,
                     mode ? "conditional" : "sampled");
            status = vfy_simulate(&solver, o, label, &res[mode], msg, msglen);
        }
        if (status == SIM_OK) {
            double raw_mean, raw_min, T_mean, T_min, z_raw, z_T, z_modes = 0.0, dz;
            variance_ratio(&res[0], &res[1], SIM_OBS_T_RAW, &raw_mean, &raw_min);
            variance_ratio(&res[0], &res[1], SIM_OBS_T, &T_mean, &T_min);
            ratio_raw_all = fmin(ratio_raw_all, raw_mean);
            vfy_result_column(&res[1], SIM_OBS_T_RAW, mean, ci);
            vfy_check_zscore(r, vfy_name(name, sizeof name, "%s n=%zu conditional T_raw vs exact "
                                         "finite-n expectation", c->name, n),
                             mean, ci, finite_raw, M, ZMAX, &z_raw);
            vfy_result_column(&res[0], SIM_OBS_T_RAW, mean_s, ci_s);
            vfy_check_zscore(r, vfy_name(name, sizeof name, "%s n=%zu sampled vs conditional "
                                         "T_raw", c->name, n),
                             mean_s, ci_s, mean, M, ZMAX, &dz);
            z_modes = fmax(z_modes, dz);
            vfy_result_column(&res[1], SIM_OBS_T, mean, ci);
            vfy_check_zscore(r, vfy_name(name, sizeof name, "%s n=%zu conditional T vs exact "
                                         "finite-n expectation", c->name, n),
                             mean, ci, finite, M, ZMAX, &z_T);
            vfy_result_column(&res[0], SIM_OBS_T, mean_s, ci_s);
            vfy_check_zscore(r, vfy_name(name, sizeof name, "%s n=%zu sampled vs conditional T",
                                         c->name, n),
                             mean_s, ci_s, mean, M, ZMAX, &dz);
            z_modes = fmax(z_modes, dz);
            /* Var_sampled = Var_conditional + E Var(increments): a factor at or
             * below 1 means the expectation was not taken. */
            vfy_check_range(r, vfy_name(name, sizeof name, "%s n=%zu variance reduction of "
                                        "T_raw (mean over t)", c->name, n),
                            raw_mean, 1.0 + 1e-9, INFINITY);
            vfy_table_cell(&table, "%zu", n);
            vfy_table_cell(&table, "%zu", res[0].ensembles);
            vfy_table_cell(&table, "%.3f", raw_mean);
            vfy_table_cell(&table, "%.3f", raw_min);
            vfy_table_cell(&table, "%.3f", T_mean);
            vfy_table_cell(&table, "%.3f", T_min);
            vfy_table_cell(&table, "%.2f", z_raw);
            vfy_table_cell(&table, "%.2f", z_T);
            vfy_table_cell(&table, "%.2f", z_modes);
            vfy_table_cell(&table, "%.2f", res[0].cpu_seconds);
            vfy_table_cell(&table, "%.2f", res[1].cpu_seconds);
            if (o->progress)
                fprintf(o->progress, "   %s n=%zu: variance reduction T_raw %.3f (min %.3f), "
                        "T %.3f (min %.3f)\n", c->name, n, raw_mean, raw_min, T_mean, T_min);
            status = vfy_write_rows_so_far(o, c->name, &table, &solver, msg, msglen);
        }
        sim_ensemble_result_free(&res[0]);
        sim_ensemble_result_free(&res[1]);
    }
    if (status == SIM_OK) {
        char title[160], notes[1800];
        snprintf(title, sizeof title, "%s: variance-reduced observation, paper A Ex 3 (%s sizes)",
                 c->name, o->size == VFY_PAPER ? "paper" : "quick");
        snprintf(notes, sizeof notes,
                 "%s.\n\nThe same scene and seed observed two ways at every output time: "
                 "sampled (each particle's pending Brownian increment of the white-noise "
                 "heating is drawn, paper A) and conditional (T, T_raw, u, P are their exact "
                 "expectations over those increments, sim_observe_pending; the particles are "
                 "then brought as before, so the trajectories are identical). var_ratio_X = "
                 "Var_sampled / Var_conditional of X, the mean over the output times t > 0 and "
                 "the smallest (_min): the variance reduction factor, i.e. how many times "
                 "fewer ensembles the conditional estimator needs for the same confidence "
                 "half-width. z_T_raw, z_T: max |z| of the conditional means against the exact "
                 "expectations of the n-particle estimators; z_modes: max |z| between the two "
                 "modes. Smallest mean factor for T_raw over the rows: %.3f.",
                 comment, ratio_raw_all);
        status = vfy_write_case_tables(o, c->name, &table, comment, title, notes, msg, msglen);
    }
    vfy_table_free(&table);
    free(buf);
    return status;
}
