#include "gate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "case_report.h"
#include "checks.h"
#include "driver.h"
#include "figure.h"
#include "suites.h"
#include "table.h"
#include "text.h"
#include "verdicts.h"

int vfy_must_fail_at(const char *must_fail, size_t i, char *buf, size_t len)
{
    const char *p = must_fail ? must_fail : "";
    for (size_t k = 0;; k++) {
        p += strspn(p, " ");
        if (*p == '\0')
            return -1;
        const size_t n = strcspn(p, " ");
        if (k == i) {
            snprintf(buf, len, "%.*s", (int)n, p);
            return 0;
        }
        p += n;
    }
}

/* One run of the selection with options o (no verdict lines, no progress):
 * its report in *r (free it). */
static sim_status run_once(const char *suite, const char *cases, const vfy_options *o,
                           vfy_report *r, char *msg, size_t msglen)
{
    vfy_report_init(r, NULL);
    return vfy_run(suite, cases, o, r, msg, msglen);
}

/* A copy of o writing to dir (its own checkpoints and finished list). */
typedef struct run_options {
    vfy_options o;
    char dir[1200], checkpoints[1220];
    vfy_finished finished;
} run_options;

static void run_options_init(run_options *ro, const vfy_options *o, const char *dir)
{
    memset(ro, 0, sizeof *ro);
    ro->o = *o;
    snprintf(ro->dir, sizeof ro->dir, "%s", dir);
    snprintf(ro->checkpoints, sizeof ro->checkpoints, "%s/.checkpoint", dir);
    ro->o.out_dir = ro->dir;
    ro->o.checkpoint_dir = ro->checkpoints;
    ro->o.finished = &ro->finished;
    ro->o.progress = NULL;
}

static double seconds_since(const struct timespec *t0)
{
    struct timespec t1;
    clock_gettime(CLOCK_MONOTONIC, &t1);
    return (double)(t1.tv_sec - t0->tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0->tv_nsec);
}

/* ------------------------------------------------------------ --seeds */

/* A check's verdicts over the runs, by its case, id (the name before a row
 * fills it in: a name may carry a measured value) and row; its name as the
 * first run printed it. */
typedef struct seed_tally {
    char *group, *id, *row, *name;   /* allocated, as long as the check's */
    size_t n[VFY_VERDICTS];
    char *first_fail;   /* the detail of its first FAIL (allocated), or NULL */
    size_t first_run;
} seed_tally;

static void tally_strings_free(seed_tally *e)
{
    free(e->group);
    free(e->id);
    free(e->row);
    free(e->name);
    free(e->first_fail);
}

static void tally_free(seed_tally *t, size_t count)
{
    for (size_t i = 0; i < count; i++)
        tally_strings_free(&t[i]);
    free(t);
}

static seed_tally *tally_find(seed_tally **t, size_t *count, size_t *cap, const vfy_check *c)
{
    const char *id = c->id[0] ? c->id : c->name;
    for (size_t i = 0; i < *count; i++)
        if (strcmp((*t)[i].group, c->group) == 0 && strcmp((*t)[i].id, id) == 0
            && strcmp((*t)[i].row, c->row) == 0)
            return &(*t)[i];
    if (*count == *cap) {
        size_t grown = *cap ? 2 * *cap : 256;
        seed_tally *g = realloc(*t, grown * sizeof *g);
        if (g == NULL)
            return NULL;
        *t = g;
        *cap = grown;
    }
    seed_tally *e = &(*t)[*count];
    *e = (seed_tally){.group = vfy_strdup(c->group), .id = vfy_strdup(id),
                      .row = vfy_strdup(c->row), .name = vfy_strdup(c->name)};
    if (e->group == NULL || e->id == NULL || e->row == NULL || e->name == NULL) {
        tally_strings_free(e);
        return NULL;
    }
    (*count)++;
    return e;
}

static sim_status write_seeds(const vfy_options *o, const seed_tally *t, size_t count, size_t K,
                              size_t clean, const size_t *fails_per_run, char *msg,
                              size_t msglen)
{
    vfy_report_file rf;
    if (vfy_report_file_open(&rf, o, "seeds.csv", msg, msglen) != SIM_OK)
        return SIM_EIO;
    FILE *f = rf.f;
    fprintf(f, "# gdsmc %s verify --seeds %zu at %s sizes: run k uses the seed "
               "vfy_derived_seed(scene seed, k), k = 0 the scene's own\n",
            GDSMC_VERSION, K, o->size == VFY_QUICK ? "quick" : "paper");
    fprintf(f, "# runs without a failure: %zu of %zu\n", clean, K);
    fputs("case,check_id,row,check,runs,passed,failed,skipped,differs\n", f);
    for (size_t i = 0; i < count; i++) {
        size_t runs = t[i].n[0] + t[i].n[1] + t[i].n[2] + t[i].n[3];
        fprintf(f, "%s,", t[i].group);
        vfy_csv_field(f, t[i].id);
        fputc(',', f);
        vfy_csv_field(f, t[i].row);
        fputc(',', f);
        vfy_csv_field(f, t[i].name);
        fprintf(f, ",%zu,%zu,%zu,%zu,%zu\n", runs, t[i].n[VFY_PASS], t[i].n[VFY_FAIL],
                t[i].n[VFY_SKIP], t[i].n[VFY_DIFFERS]);
    }
    if (vfy_report_file_close(&rf, msg, msglen) != SIM_OK
        || vfy_report_file_open(&rf, o, "seeds.md", msg, msglen) != SIM_OK)
        return SIM_EIO;
    f = rf.f;
    fprintf(f, "# False alarms: %zu runs at %s sizes\n\n", K,
            o->size == VFY_QUICK ? "quick" : "paper");
    fprintf(f, "Made by `gdsmc verify --seeds %zu` (gdsmc %s). Run k draws every scene's "
               "random numbers from the seed vfy_derived_seed(seed, k) (k = 0: the scene's "
               "own); the built-in engine is correct, so every FAIL here is a false alarm. "
               "Target (issue 34): no check fails in more than 1 run of 20, and at least 19 "
               "of 20 runs pass whole.\n\n",
            K, GDSMC_VERSION);
    fprintf(f, "Runs without a failure: **%zu of %zu**. Failures per run:", clean, K);
    for (size_t k = 0; k < K; k++)
        fprintf(f, " %zu", fails_per_run[k]);
    fputs(".\n\n", f);
    size_t failing = 0;
    for (size_t i = 0; i < count; i++)
        failing += t[i].n[VFY_FAIL] > 0;
    if (failing == 0) {
        fputs("No check failed in any run.\n", f);
    } else {
        fputs("| case | check | failed | of runs judged | first failure (run: detail) |\n"
              "|---|---|---:|---:|---|\n",
              f);
        for (size_t i = 0; i < count; i++)
            if (t[i].n[VFY_FAIL] > 0)
                fprintf(f, "| %s | %s | %zu | %zu | %zu: %s |\n", t[i].group, t[i].name,
                        t[i].n[VFY_FAIL], t[i].n[VFY_FAIL] + t[i].n[VFY_PASS]
                                              + t[i].n[VFY_DIFFERS],
                        t[i].first_run, t[i].first_fail);
    }
    return vfy_report_file_close(&rf, msg, msglen);
}

sim_status vfy_seeds(const char *suite, const char *cases, const vfy_options *o, size_t K,
                     size_t *clean, size_t *flaky, char *msg, size_t msglen)
{
    seed_tally *t = NULL;
    size_t count = 0, cap = 0;
    size_t *fails_per_run = calloc(K, sizeof *fails_per_run);
    sim_status status = fails_per_run ? SIM_OK : SIM_ENOMEM;
    *clean = *flaky = 0;
    for (size_t k = 0; k < K && status == SIM_OK; k++) {
        char dir[1200];
        snprintf(dir, sizeof dir, "%s/seeds/seed-%02zu", o->out_dir, k);
        run_options ro;
        run_options_init(&ro, o, dir);
        ro.o.seed_run = k;
        struct timespec t0;
        clock_gettime(CLOCK_MONOTONIC, &t0);
        vfy_report r;
        status = run_once(suite, cases, &ro.o, &r, msg, msglen);
        vfy_finished_free(&ro.finished);
        for (size_t i = 0; i < r.count && status == SIM_OK; i++) {
            seed_tally *e = tally_find(&t, &count, &cap, &r.checks[i]);
            if (e == NULL) {
                status = SIM_ENOMEM;
                break;
            }
            e->n[r.checks[i].verdict]++;
            if (r.checks[i].verdict == VFY_FAIL && e->n[VFY_FAIL] == 1) {
                if ((e->first_fail = vfy_strdup(r.checks[i].detail)) == NULL)
                    status = SIM_ENOMEM;
                e->first_run = k;
            }
        }
        if (status == SIM_OK) {
            fails_per_run[k] = r.counts[VFY_FAIL];
            *clean += r.counts[VFY_FAIL] == 0;
            if (o->progress) {
                fprintf(o->progress, "seeds: run %zu of %zu: %zu passed, %zu failed, %zu "
                        "skipped (%.0f s)\n", k + 1, K, r.counts[VFY_PASS], r.counts[VFY_FAIL],
                        r.counts[VFY_SKIP], seconds_since(&t0));
                for (size_t i = 0; i < r.count; i++)
                    if (r.checks[i].verdict == VFY_FAIL)
                        fprintf(o->progress, "   FAIL  %s: %s\n", r.checks[i].name,
                                r.checks[i].detail);
            }
        }
        vfy_report_free(&r);
    }
    if (status == SIM_OK)
        status = write_seeds(o, t, count, K, *clean, fails_per_run, msg, msglen);
    for (size_t i = 0; i < count; i++)
        *flaky += t[i].n[VFY_FAIL] > 1;
    if (status == SIM_ENOMEM)
        snprintf(msg, msglen, "out of memory");
    tally_free(t, count);
    free(fails_per_run);
    return status;
}

/* ------------------------------------------------------------ --must-fail */

/* Run case c with perturbation `perturb` under seed run k into dir: the
 * number of failed checks in *failed, the first failure's line in first. */
static sim_status run_perturbed(const vfy_case *c, const char *suite, const vfy_options *o,
                                const char *perturb, size_t k, const char *dir, size_t *failed,
                                double *cpu_s, char *first, size_t firstlen, char *msg,
                                size_t msglen)
{
    run_options ro;
    run_options_init(&ro, o, dir);
    const char *list[1] = {perturb};
    ro.o.perturbs = perturb ? list : NULL;
    ro.o.nperturbs = perturb ? 1 : 0;
    ro.o.seed_run = k;
    vfy_report r;
    struct timespec c0, c1;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c0);
    sim_status status = run_once(suite, c->name, &ro.o, &r, msg, msglen);
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &c1);
    vfy_finished_free(&ro.finished);
    *failed = r.counts[VFY_FAIL];
    if (cpu_s)
        *cpu_s = (double)(c1.tv_sec - c0.tv_sec) + 1e-9 * (double)(c1.tv_nsec - c0.tv_nsec);
    if (first) {
        first[0] = '\0';
        for (size_t i = 0; i < r.count; i++)
            if (r.checks[i].verdict == VFY_FAIL) {
                snprintf(first, firstlen, "%s: %s", r.checks[i].name, r.checks[i].detail);
                break;
            }
    }
    vfy_report_free(&r);
    if (status != SIM_OK) {
        char why[1024];
        snprintf(why, sizeof why, "%s", msg);
        snprintf(msg, msglen, "%s, must_fail %s: %s", c->name, perturb ? perturb : "(none)",
                 why);
    }
    return status;
}

sim_status vfy_must_fail(const char *suite, const char *cases, const vfy_options *o, FILE *out,
                         size_t *missed, char *msg, size_t msglen)
{
    char dir[1200];
    snprintf(dir, sizeof dir, "%s/must-fail", o->out_dir);
    *missed = 0;
    for (size_t i = 0; i < vfy_case_count(); i++) {
        const vfy_case *c = vfy_case_at(i);
        if (!vfy_case_selected(c, suite, cases))
            continue;
        char perturb[128];
        if (c->desc->no_simulation) {
            fprintf(out, "NONE    %s: simulates nothing (its checks judge the references)\n",
                    c->name);
            continue;
        }
        if (vfy_must_fail_at(c->desc->must_fail, 0, perturb, sizeof perturb) != 0) {
            fprintf(out, "NONE    %s: declares no must_fail\n", c->name);
            (*missed)++;
            continue;
        }
        for (size_t k = 0; vfy_must_fail_at(c->desc->must_fail, k, perturb, sizeof perturb) == 0;
             k++) {
            size_t failed;
            char first[512];
            sim_status status = run_perturbed(c, suite, o, perturb, 0, dir, &failed, NULL, first,
                                              sizeof first, msg, msglen);
            if (status != SIM_OK)
                return status;
            if (failed > 0)
                fprintf(out, "CAUGHT  %s --perturb %s: %zu checks failed, first %s\n", c->name,
                        perturb, failed, first);
            else
                fprintf(out, "MISSED  %s --perturb %s: every check held\n", c->name, perturb);
            fflush(out);
            *missed += failed == 0;
        }
    }
    return SIM_OK;
}

/* ------------------------------------------------------------ --power */

static const double ladder[] = {0.005, 0.01, 0.02, 0.05, 0.10, 0.20, 0.50};
#define LADDER (sizeof ladder / sizeof *ladder)
#define POWER_SEEDS 3

typedef struct power_row {
    char name[32], key[96];
    double must_factor;   /* the must_fail factor, or NaN for a power_keys word */
    double smallest, cpu_s;
    int up;               /* the direction: factors above 1 */
    int must_caught;      /* the must_fail factor caught under seed 0 */
} power_row;

static sim_status write_power(const vfy_options *o, const power_row *rows, size_t count,
                              char *msg, size_t msglen)
{
    vfy_report_file rf;
    if (vfy_report_file_open(&rf, o, "power.csv", msg, msglen) != SIM_OK)
        return SIM_EIO;
    FILE *f = rf.f;
    fprintf(f, "# gdsmc %s verify --power at %s sizes: relative errors %g%% .. %g%% of the "
               "solver's value, each under %d seeds; smallest_detected is the first caught by "
               "every seed (empty: none up to %g%%)\n",
            GDSMC_VERSION, o->size == VFY_QUICK ? "quick" : "paper", 100 * ladder[0],
            100 * ladder[LADDER - 1], POWER_SEEDS, 100 * ladder[LADDER - 1]);
    fputs("case,key,direction,smallest_detected,must_fail_factor,must_fail_caught,cpu_s\n", f);
    for (size_t i = 0; i < count; i++) {
        fprintf(f, "%s,%s,%s,", rows[i].name, rows[i].key, rows[i].up ? "up" : "down");
        if (isfinite(rows[i].smallest))
            fprintf(f, "%g", rows[i].smallest);
        fputc(',', f);
        if (isfinite(rows[i].must_factor))
            fprintf(f, "%g,%d", rows[i].must_factor, rows[i].must_caught);
        else
            fputc(',', f);
        fprintf(f, ",%.2f\n", rows[i].cpu_s);
    }
    if (vfy_report_file_close(&rf, msg, msglen) != SIM_OK
        || vfy_report_file_open(&rf, o, "power.md", msg, msglen) != SIM_OK)
        return SIM_EIO;
    f = rf.f;
    fprintf(f, "# Power: the smallest error each case detects (%s sizes)\n\n"
               "Made by `gdsmc verify --power` (gdsmc %s). For each key a case declares in "
               "its `must_fail` (the errors it must catch) or `power_keys` (measured, not "
               "required), the solver's value of the key is multiplied by 1 ± e for e = "
               "0.5%%, 1%%, 2%%, 5%%, 10%%, 20%%, 50%% in turn (the sign of the declared "
               "factor), each run under %d seeds; the smallest e that makes the case fail under "
               "every seed is its power for the key. CPU s is the unperturbed case's (the "
               "process, every thread).\n\n"
               "| case | key | direction | smallest error detected | must_fail | caught | "
               "CPU s |\n|---|---|---|---:|---:|---|---:|\n",
            o->size == VFY_QUICK ? "quick" : "paper", GDSMC_VERSION, POWER_SEEDS);
    for (size_t i = 0; i < count; i++) {
        fprintf(f, "| %s | %s | %s | ", rows[i].name, rows[i].key, rows[i].up ? "up" : "down");
        if (isfinite(rows[i].smallest))
            fprintf(f, "%g%%", 100 * rows[i].smallest);
        else
            fprintf(f, "none up to %g%%", 100 * ladder[LADDER - 1]);
        if (isfinite(rows[i].must_factor))
            fprintf(f, " | ×%g | %s | %.1f |\n", rows[i].must_factor,
                    rows[i].must_caught ? "yes" : "**no**", rows[i].cpu_s);
        else
            fprintf(f, " | – | – | %.1f |\n", rows[i].cpu_s);
    }
    fputs("\nFigure: power.png, the smallest error detected against the CPU seconds.\n", f);
    if (vfy_report_file_close(&rf, msg, msglen) != SIM_OK)
        return SIM_EIO;

    double *x = malloc((count ? count : 1) * sizeof *x), *y = malloc((count ? count : 1) * sizeof *y),
           *ci = calloc(count ? count : 1, sizeof *ci);
    size_t n = 0;
    for (size_t i = 0; x && y && ci && i < count; i++)
        if (isfinite(rows[i].smallest) && rows[i].cpu_s > 0) {
            x[n] = rows[i].cpu_s;
            y[n++] = rows[i].smallest;
        }
    sim_status status = SIM_OK;
    if (x && y && ci && n > 0) {
        const char *series[] = {"smallest relative error detected"};
        const double *ys[] = {y}, *cis[] = {ci};
        char comment[200];
        snprintf(comment, sizeof comment, "gdsmc %s verify --power", GDSMC_VERSION);
        const vfy_points fig = {.name = "power", .title = "Power of the gate against its cost",
                                .xlabel = "CPU seconds of the case",
                                .ylabel = "smallest relative error detected by 3 of 3 seeds",
                                .logx = 1, .logy = 1, .npoints = n, .x = x, .nseries = 1,
                                .series = series, .y = ys, .ci = cis, .bars = "",
                                .comment = comment};
        if (vfy_write_points(o, &fig) != 0)
            status = vfy_io_error("power", msg, msglen);
    }
    free(x);
    free(y);
    free(ci);
    return status;
}

/* The ladder for one key of case c: p->smallest (NaN: none caught). */
static sim_status power_ladder(const vfy_case *c, const char *suite, const vfy_options *o,
                               const char *dir, const char *key, double factor, power_row *p,
                               char *msg, size_t msglen)
{
    sim_status status = SIM_OK;
    p->smallest = NAN;
    for (size_t l = 0; l < LADDER && status == SIM_OK && isnan(p->smallest); l++) {
        char perturb[160];
        snprintf(perturb, sizeof perturb, "%s=%.6g", key,
                 factor < 1.0 ? 1.0 - ladder[l] : 1.0 + ladder[l]);
        size_t seeds = 0, caught = 0;
        for (size_t s = 0; s < POWER_SEEDS && status == SIM_OK; s++) {
            status = run_perturbed(c, suite, o, perturb, s, dir, &caught, NULL, NULL, 0, msg,
                                   msglen);
            if (status != SIM_OK || caught == 0)
                break;
            seeds++;
        }
        if (status == SIM_EINVAL) {   /* out of the key's range: the ladder ends there */
            if (o->progress)
                fprintf(o->progress, "power: %s\n", msg);
            return SIM_OK;
        }
        if (o->progress && status == SIM_OK)
            fprintf(o->progress, "power: %s %s: caught under %zu of %d seeds\n", c->name,
                    perturb, seeds, POWER_SEEDS);
        if (seeds == POWER_SEEDS)
            p->smallest = ladder[l];
    }
    return status;
}

sim_status vfy_power(const char *suite, const char *cases, const vfy_options *o, char *msg,
                     size_t msglen)
{
    char dir[1200];
    snprintf(dir, sizeof dir, "%s/power", o->out_dir);
    power_row *rows = NULL;
    size_t count = 0, cap = 0;
    sim_status status = SIM_OK;
    for (size_t i = 0; i < vfy_case_count() && status == SIM_OK; i++) {
        const vfy_case *c = vfy_case_at(i);
        if (!vfy_case_selected(c, suite, cases) || c->desc->no_simulation)
            continue;
        size_t failed;
        double cpu = 0.0;
        if ((status = run_perturbed(c, suite, o, NULL, 0, dir, &failed, &cpu, NULL, 0, msg,
                                    msglen))
            != SIM_OK)
            break;
        /* the must_fail words, then the power_keys words */
        const char *lists[2] = {c->desc->must_fail, c->desc->power_keys};
        char word[128];
        for (size_t list = 0; list < 2 && status == SIM_OK; list++)
            for (size_t k = 0; vfy_must_fail_at(lists[list], k, word, sizeof word) == 0
                               && status == SIM_OK;
                 k++) {
                if (count == cap) {
                    cap = cap ? 2 * cap : 32;
                    power_row *g = realloc(rows, cap * sizeof *g);
                    if (g == NULL) {
                        status = SIM_ENOMEM;
                        snprintf(msg, msglen, "out of memory");
                        break;
                    }
                    rows = g;
                }
                power_row *p = &rows[count++];
                memset(p, 0, sizeof *p);
                char key[96];
                double factor;
                if ((status = vfy_perturb_parse(word, key, sizeof key, &factor, msg, msglen))
                    != SIM_OK)
                    break;
                snprintf(p->name, sizeof p->name, "%s", c->name);
                snprintf(p->key, sizeof p->key, "%s", key);
                p->must_factor = list == 0 ? factor : NAN;
                p->up = factor > 1.0;
                p->cpu_s = cpu;
                if (list == 0) {
                    size_t caught;
                    status = run_perturbed(c, suite, o, word, 0, dir, &caught, NULL, NULL, 0,
                                           msg, msglen);
                    p->must_caught = caught > 0;
                }
                if (status == SIM_OK)
                    status = power_ladder(c, suite, o, dir, key, factor, p, msg, msglen);
            }
    }
    if (status == SIM_OK)
        status = write_power(o, rows, count, msg, msglen);
    free(rows);
    return status;
}
