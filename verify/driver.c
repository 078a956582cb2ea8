#include "driver.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "case_report.h"
#include "figure.h"
#include "metrics.h"
#include "observe.h"
#include "references.h"
#include "solver.h"
#include "scene_ini.h"
#include "steady.h"
#include "verdicts.h"

/* ------------------------------------------------------------ values */

static long values_find(const vfy_values *vals, const char *name)
{
    for (size_t i = 0; i < vals->count; i++)
        if (strcmp(vals->names[i], name) == 0)
            return (long)i;
    return -1;
}

int vfy_values_set(vfy_values *vals, const char *name, double v)
{
    long at = values_find(vals, name);
    if (at < 0) {
        if (vals->count == vals->capacity) {
            size_t cap = vals->capacity ? 2 * vals->capacity : 32;
            char(*names)[32] = realloc(vals->names, cap * sizeof *names);
            if (names == NULL)
                return -1;
            vals->names = names;
            double *grown = realloc(vals->v, cap * sizeof *grown);
            if (grown == NULL)
                return -1;
            vals->v = grown;
            vals->capacity = cap;
        }
        at = (long)vals->count++;
        snprintf(vals->names[at], sizeof vals->names[at], "%s", name);
    }
    vals->v[at] = v;
    return 0;
}

double vfy_values_get(const vfy_values *vals, const char *name)
{
    long at = values_find(vals, name);
    return at < 0 ? NAN : vals->v[at];
}

int vfy_values_has(const vfy_values *vals, const char *name) { return values_find(vals, name) >= 0; }

void vfy_values_free(vfy_values *vals)
{
    free(vals->names);
    free(vals->v);
    memset(vals, 0, sizeof *vals);
}

/* ------------------------------------------------------------ rows */

/* The variant index of name "X@VARIANT" in the description (0 without '@'),
 * or -1. */
static long variant_index(const vfy_case_desc *d, const char *variant)
{
    if (variant == NULL || variant[0] == '\0')
        return 0;
    for (long k = 0; d->variants && d->variants[k]; k++) {
        size_t n = strcspn(d->variants[k], ":");
        if (strlen(variant) == n && strncmp(d->variants[k], variant, n) == 0)
            return k;
    }
    return -1;
}

const sim_ensemble_result *vfy_row_result(const vfy_case_run *run, const vfy_row *row,
                                          const char *variant)
{
    long k = variant_index(run->d, variant);
    return k < 0 ? NULL : k == 0 ? &row->res : &row->more[k - 1];
}

size_t vfy_variant_count(const vfy_case_desc *d)
{
    size_t count = 0;
    while (d->variants && d->variants[count])
        count++;
    return count ? count : 1;
}

/* Variant k of d ("NAME: SET;SET"): its name into name ("" for a case
 * without variants); returns its settings, or NULL. */
static const char *variant_parts(const vfy_case_desc *d, size_t k, char *name, size_t len)
{
    name[0] = '\0';
    if (d->variants == NULL || d->variants[0] == NULL)
        return NULL;
    const char *text = d->variants[k], *colon = strchr(text, ':');
    snprintf(name, len, "%.*s", (int)strcspn(text, ":"), text);
    return colon ? colon + 1 : NULL;
}

/* "NAME@*": the mean over the variants of observable NAME. */
static int variants_mean(const vfy_row *row, const char *name, size_t len, double *mean,
                         double *ci)
{
    const size_t B = vfy_variant_count(row->run->d), M = row->res.outputs;
    char one[64];
    double *m1 = malloc(2 * M * sizeof *m1);
    if (m1 == NULL)
        return -1;
    memset(mean, 0, M * sizeof *mean);
    if (ci != NULL)
        memset(ci, 0, M * sizeof *ci);
    int rc = 0;
    for (size_t k = 0; k < B && rc == 0; k++) {
        const char *v = row->run->d->variants ? row->run->d->variants[k] : "";
        snprintf(one, sizeof one, "%.*s%s%.*s", (int)len, name, k ? "@" : "",
                 k ? (int)strcspn(v, ":") : 0, v);
        rc = vfy_row_series(row, one, m1, m1 + M);
        for (size_t m = 0; m < M && rc == 0; m++) {
            mean[m] += m1[m];
            if (ci != NULL)
                ci[m] += m1[M + m] * m1[M + m];
        }
    }
    for (size_t m = 0; m < M; m++) {
        mean[m] /= (double)B;
        if (ci != NULL)
            ci[m] = sqrt(ci[m]) / (double)B;
    }
    free(m1);
    return rc;
}

int vfy_row_series(const vfy_row *row, const char *name, double *mean, double *ci)
{
    const char *at = strchr(name, '@');
    size_t len = at ? (size_t)(at - name) : strlen(name);
    if (at != NULL && strcmp(at, "@*") == 0)
        return variants_mean(row, name, len, mean, ci);
    const sim_ensemble_result *res = &row->res;
    if (at != NULL) {
        res = vfy_row_result(row->run, row, at + 1);
        if (res == NULL)
            return -1;
    }
    const int k = sim_observable_find(&row->solver, name, len);
    if (k >= 0 && (size_t)k < res->observables) {
        vfy_result_column(res, k, mean, ci);
        return 0;
    }
    const double *ref = vfy_refs_column(&row->refs, name);
    if (ref == NULL)
        return -1;
    memcpy(mean, ref, row->res.outputs * sizeof *mean);
    if (ci != NULL)
        memset(ci, 0, row->res.outputs * sizeof *ci);
    return 0;
}

const vfy_row *vfy_row_previous(const vfy_case_run *run, const vfy_row *row)
{
    return row->index > 0 ? &run->rows[row->index - 1] : NULL;
}

sim_status vfy_adjust_jump_rows(const vfy_row *row, sim_scene *solver, char *msg,
                                size_t msglen)
{
    (void)msg;
    (void)msglen;
    const char *scheme = vfy_row_text(row, "scheme");
    if (scheme != NULL && strcmp(scheme, "jump") == 0) {
        *solver = row->scene;
        solver->scheme = SIM_SCHEME_JUMP;
        solver->splitting = SIM_SPLIT_EULER;
    }
    return SIM_OK;
}

/* ------------------------------------------------------------ templates */

static const char *run_string(const vfy_case_run *run, const char *name)
{
    if (strcmp(name, "case") == 0)
        return run->c->name;
    if (strcmp(name, "size") == 0)
        return run->o->size == VFY_PAPER ? "paper" : "quick";
    if (strcmp(name, "paper") == 0)
        return run->d->paper ? run->d->paper : "";
    if (strcmp(name, "comment") == 0)
        return run->comment;
    for (size_t i = 0; i < run->ntexts; i++)
        if (strcmp(run->text_names[i], name) == 0)
            return run->texts[i];
    return NULL;
}

int vfy_run_set_text(vfy_case_run *run, const char *name, const char *text)
{
    size_t i = 0;
    while (i < run->ntexts && strcmp(run->text_names[i], name) != 0)
        i++;
    if (i == sizeof run->texts / sizeof *run->texts)
        return -1;
    snprintf(run->text_names[i], sizeof run->text_names[i], "%s", name);
    snprintf(run->texts[i], sizeof run->texts[i], "%s", text);
    run->ntexts += i == run->ntexts;
    return 0;
}

static const char *row_string(const vfy_row *row, const char *name)
{
    if (row != NULL && strcmp(name, "label") == 0)
        return row->label;
    if (row != NULL && strcmp(name, "scene") == 0)
        return row->stem;
    return vfy_row_text(row, name);
}

static double lookup(const vfy_case_run *run, const vfy_row *row, const char *name)
{
    if (row != NULL && vfy_values_has(&row->values, name))
        return vfy_values_get(&row->values, name);
    return vfy_values_get(&run->values, name);
}

const char *vfy_expand(char *buf, size_t len, const char *tmpl, const vfy_case_run *run,
                       const vfy_row *row)
{
    size_t used = 0;
    buf[0] = '\0';
    for (const char *p = tmpl; *p && used + 1 < len;) {
        const char *close = p[0] == '{' && p[1] != '{' ? strchr(p, '}') : NULL;
        if (close == NULL) {
            p += p[0] == '{' && p[1] == '{';   /* "{{" is one brace */
            buf[used++] = *p++;
            buf[used] = '\0';
            continue;
        }
        int at_quick = strncmp(p + 1, "at_quick:", 9) == 0;
        int at_engine = strncmp(p + 1, "at_engine:", 10) == 0;
        if (at_quick || strncmp(p + 1, "at_paper:", 9) == 0) {   /* text at one size */
            if (at_quick == (run->o->size == VFY_QUICK)) {
                int w = snprintf(buf + used, len - used, "%.*s", (int)(close - p - 10), p + 10);
                used = w < 0 ? used : used + (size_t)w < len ? used + (size_t)w : len - 1;
            }
            p = close + 1;
            continue;
        }
        if (at_engine || strncmp(p + 1, "at_solver:", 10) == 0) {   /* text for one solver */
            if (at_engine != vfy_external(run->o)) {
                int w = snprintf(buf + used, len - used, "%.*s", (int)(close - p - 11), p + 11);
                used = w < 0 ? used : used + (size_t)w < len ? used + (size_t)w : len - 1;
            }
            p = close + 1;
            continue;
        }
        char name[64], fmt[16] = "";
        size_t n = (size_t)(close - p - 1);
        snprintf(name, sizeof name, "%.*s", (int)(n < sizeof name ? n : sizeof name - 1), p + 1);
        char *colon = strchr(name, ':');
        if (colon != NULL) {
            snprintf(fmt, sizeof fmt, "%s", colon + 1);
            *colon = '\0';
        }
        const char *s = row_string(row, name);
        if (s == NULL)
            s = run_string(run, name);
        double v = lookup(run, row, name);
        int w;
        if (s != NULL)
            w = snprintf(buf + used, len - used, "%s", s);
        else if (isnan(v) && vfy_external(run->o))   /* the solver did not report it */
            w = snprintf(buf + used, len - used, "(not reported)");
        else if (fmt[0])
            w = snprintf(buf + used, len - used, fmt, v);
        else if (v == floor(v) && fabs(v) < 1e15)
            w = snprintf(buf + used, len - used, "%.0f", v);
        else
            w = snprintf(buf + used, len - used, "%g", v);
        used = w < 0 ? used : used + (size_t)w < len ? used + (size_t)w : len - 1;
        p = close + 1;
    }
    return buf;
}

/* ------------------------------------------------------------ rules */

static double expected_of(const vfy_case_run *run, const vfy_row *row, const vfy_check_spec *c)
{
    return c->expected ? lookup(run, row, c->expected) : c->x;
}

/* check(value, expected, tol): the relative and absolute rules. */
static vfy_verdict compare(vfy_report *r, const char *name, const vfy_case_run *run,
                           const vfy_row *row, const vfy_check_spec *c,
                           vfy_verdict (*check)(vfy_report *, const char *, double, double, double))
{
    return check(r, name, lookup(run, row, c->value), expected_of(run, row, c), c->tol);
}

vfy_verdict vfy_rule_relative(vfy_report *r, const char *name, vfy_case_run *run, vfy_row *row,
                              const vfy_check_spec *c)
{
    return compare(r, name, run, row, c, vfy_check_relative);
}

vfy_verdict vfy_rule_range(vfy_report *r, const char *name, vfy_case_run *run, vfy_row *row,
                           const vfy_check_spec *c)
{
    return vfy_check_range(r, name, lookup(run, row, c->value), c->lo, c->hi);
}

vfy_verdict vfy_rule_absolute(vfy_report *r, const char *name, vfy_case_run *run, vfy_row *row,
                              const vfy_check_spec *c)
{
    const double expected = expected_of(run, row, c);
    double allowed = c->tol;
    if (c->rtol != 0.0)
        allowed += c->rtol * fabs(expected);
    if (c->plus != NULL)
        allowed += lookup(run, row, c->plus);
    if (c->plus_quick != NULL && run->o->size == VFY_QUICK)
        allowed += lookup(run, row, c->plus_quick);
    return vfy_check_absolute(r, name, lookup(run, row, c->value), expected, allowed);
}

vfy_verdict vfy_rule_count(vfy_report *r, const char *name, vfy_case_run *run, vfy_row *row,
                           const vfy_check_spec *c)
{
    return vfy_check_count(r, name, (uint64_t)lookup(run, row, c->value),
                           (uint64_t)expected_of(run, row, c));
}

vfy_verdict vfy_rule_violations(vfy_report *r, const char *name, vfy_case_run *run,
                                vfy_row *row, const vfy_check_spec *c)
{
    const double allowed = row ? lookup(run, row, "violations_allowed") : 0.0;
    if (!(allowed > 0.0))   /* none declared: exactly zero, as the engine's */
        return vfy_rule_count(r, name, run, row, c);
    const double v = lookup(run, row, c->value);
    return vfy_check_true(r, name, v <= allowed, "%.0f (allowed at most %.0f, declared by the "
                          "solver's '# violations_allowed')", v, allowed);
}

/* Series value against series expected (pair: a second simulation, whose
 * half-widths join value's in quadrature). */
static vfy_verdict zscore_rule(vfy_report *r, const char *name, vfy_row *row,
                               const vfy_check_spec *c, int pair)
{
    size_t M = row->res.outputs;
    double *buf = malloc(4 * M * sizeof *buf), z = INFINITY;
    vfy_verdict v = VFY_FAIL;
    if (buf == NULL || vfy_row_series(row, c->value, buf, buf + M) != 0
        || vfy_row_series(row, c->expected, buf + 2 * M, pair ? buf + 3 * M : NULL) != 0) {
        vfy_check_true(r, name, 0, "no series %s or %s in this row", c->value, c->expected);
    } else {
        for (size_t m = 0; pair && m < M; m++)
            buf[M + m] = hypot(buf[M + m], buf[3 * M + m]);
        v = vfy_check_zscore(r, name, buf + c->from, buf + M + c->from, buf + 2 * M + c->from,
                             M - c->from, c->tol, &z);
    }
    if (c->out != NULL && !(vfy_values_get(&row->values, c->out) >= z))
        vfy_values_set(&row->values, c->out, z);
    free(buf);
    return v;
}

vfy_verdict vfy_rule_zscore(vfy_report *r, const char *name, vfy_case_run *run, vfy_row *row,
                            const vfy_check_spec *c)
{
    (void)run;
    return zscore_rule(r, name, row, c, 0);
}

vfy_verdict vfy_rule_zscore_pair(vfy_report *r, const char *name, vfy_case_run *run,
                                 vfy_row *row, const vfy_check_spec *c)
{
    (void)run;
    return zscore_rule(r, name, row, c, 1);
}

vfy_verdict vfy_rule_printed(vfy_report *r, const char *name, vfy_case_run *run, vfy_row *row,
                             const vfy_check_spec *c)
{
    return vfy_check_printed(r, name, lookup(run, row, c->value),
                             c->plus ? lookup(run, row, c->plus) : 0.0,
                             expected_of(run, row, c), (int)c->tol);
}

/* ------------------------------------------------------------ guards */

vfy_guard_result vfy_guard_at_most(const vfy_case_run *run, const vfy_row *row, const vfy_guard *g)
{
    return lookup(run, row, g->a) <= g->x ? VFY_JUDGE : VFY_GUARD_SKIP;
}

vfy_guard_result vfy_guard_only_at_most(const vfy_case_run *run, const vfy_row *row,
                                        const vfy_guard *g)
{
    return lookup(run, row, g->a) <= g->x ? VFY_JUDGE : VFY_OMIT;
}

vfy_guard_result vfy_guard_at_least(const vfy_case_run *run, const vfy_row *row, const vfy_guard *g)
{
    return lookup(run, row, g->a) >= g->x ? VFY_JUDGE : VFY_GUARD_SKIP;
}

vfy_guard_result vfy_guard_only_at_least(const vfy_case_run *run, const vfy_row *row,
                                         const vfy_guard *g)
{
    return lookup(run, row, g->a) >= g->x ? VFY_JUDGE : VFY_OMIT;
}

vfy_guard_result vfy_guard_unless(const vfy_case_run *run, const vfy_row *row, const vfy_guard *g)
{
    return lookup(run, row, g->a) > 0.0 ? VFY_GUARD_SKIP : VFY_JUDGE;
}

vfy_guard_result vfy_guard_only_unless(const vfy_case_run *run, const vfy_row *row,
                                       const vfy_guard *g)
{
    return lookup(run, row, g->a) > 0.0 ? VFY_OMIT : VFY_JUDGE;
}

vfy_guard_result vfy_guard_after_first(const vfy_case_run *run, const vfy_row *row,
                                       const vfy_guard *g)
{
    (void)run;
    (void)g;
    return row->index > 0 ? VFY_JUDGE : VFY_OMIT;
}

vfy_guard_result vfy_guard_clean_pair(const vfy_case_run *run, const vfy_row *row,
                                      const vfy_guard *g)
{
    const vfy_row *prev = vfy_row_previous(run, row);
    if (prev == NULL)
        return VFY_OMIT;
    int clean = vfy_values_get(&row->values, g->a) > g->x * vfy_values_get(&row->values, g->b)
                && vfy_values_get(&prev->values, g->a)
                       > g->x * vfy_values_get(&prev->values, g->b);
    return clean ? VFY_JUDGE : VFY_GUARD_SKIP;
}

/* ------------------------------------------------------------ sweep */

/* The i-th space-separated word of list into buf (empty if there is none). */
static void nth_word(const char *list, size_t i, char *buf, size_t len)
{
    buf[0] = '\0';
    for (const char *p = list; *p;) {
        while (isspace((unsigned char)*p))
            p++;
        size_t n = strcspn(p, " \t\n");
        if (n == 0)
            break;
        if (i-- == 0) {
            snprintf(buf, len, "%.*s", (int)n, p);
            return;
        }
        p += n;
    }
}

static size_t word_count(const char *list)
{
    size_t count = 0;
    char word[64];
    while (nth_word(list, count, word, sizeof word), word[0])
        count++;
    return count;
}

size_t vfy_sweep_rows(const vfy_sweep *s)
{
    if (s->rows != NULL) {
        size_t rows = 0;
        while (s->rows[rows])
            rows++;
        return rows;
    }
    size_t rows = s->keys[0] ? 1 : 0;
    for (size_t k = 0; k < VFY_SWEEP_KEYS && s->keys[k]; k++) {
        size_t n = word_count(s->values[k]);
        rows = s->grid ? rows * n : (k == 0 || n < rows ? n : rows);
    }
    return rows;
}

void vfy_sweep_value(const vfy_sweep *s, size_t i, size_t k, char *buf, size_t len)
{
    size_t at = i;
    if (s->grid) {
        size_t inner = 1;
        for (size_t j = k + 1; j < VFY_SWEEP_KEYS && s->keys[j]; j++)
            inner *= word_count(s->values[j]);
        at = (i / inner) % word_count(s->values[k]);
    }
    nth_word(s->values[k], at, buf, len);
}

static const char *sweep_name(const vfy_sweep *s, size_t k)
{
    if (s->names[k])
        return s->names[k];
    const char *dot = strrchr(s->keys[k], '.');
    return dot ? dot + 1 : s->keys[k];
}

/* ------------------------------------------------------------ one row */

/* A "$NAME=VALUE" setting (n characters at p): a value of the row, a number
 * if VALUE is one, else a text. */
static void row_setting(vfy_row *row, const char *p, size_t n)
{
    char name[24], value[VFY_ROW_TEXT_LEN], *end;
    size_t eq = strcspn(p, "=");
    if (eq >= n)
        return;
    snprintf(name, sizeof name, "%.*s", (int)(eq - 1), p + 1);
    snprintf(value, sizeof value, "%.*s", (int)(n - eq - 1), p + eq + 1);
    double v = strtod(value, &end);
    if (end != value && *end == '\0')
        vfy_values_set(&row->values, name, v);
    else
        vfy_row_set_text(row, name, value);
}

int vfy_row_set_text(vfy_row *row, const char *name, const char *text)
{
    size_t i = 0;
    while (i < row->ntexts && strcmp(row->text_names[i], name) != 0)
        i++;
    if (i == VFY_ROW_TEXTS)
        return -1;
    snprintf(row->text_names[i], sizeof row->text_names[i], "%s", name);
    snprintf(row->texts[i], sizeof row->texts[i], "%s", text);
    row->ntexts += i == row->ntexts;
    return 0;
}

const char *vfy_row_text(const vfy_row *row, const char *name)
{
    for (size_t i = 0; row != NULL && i < row->ntexts; i++)
        if (strcmp(row->text_names[i], name) == 0)
            return row->texts[i];
    return NULL;
}

/* Up to `max` settings of "SET;SET;..." into storage and sets; a "scene=STEM"
 * setting goes to stem instead, a "$NAME=VALUE" one to the row.  Returns the
 * new count. */
static size_t split_sets(const char *list, char (*storage)[160], const char **sets,
                         size_t count, size_t max, char *stem, size_t stemlen, vfy_row *row)
{
    for (const char *p = list; p && *p && count < max;) {
        while (isspace((unsigned char)*p))
            p++;
        size_t n = strcspn(p, ";");
        if (n > 0 && strncmp(p, "scene=", 6) == 0)
            snprintf(stem, stemlen, "%.*s", (int)(n - 6), p + 6);
        else if (n > 0 && p[0] == '$')
            row_setting(row, p, n);
        else if (n > 0) {
            snprintf(storage[count], sizeof storage[count], "%.*s", (int)n, p);
            sets[count] = storage[count];
            count++;
        }
        p += n + (p[n] == ';');
    }
    return count;
}

/* The description's `observes` as the solver scene's observe_only mask: only
 * what the case reads is computed.  A name that is no base observable is an
 * error in the description. */
static sim_status observe_only(const char *names, sim_scene *solver, char *msg, size_t msglen)
{
    uint32_t only = 0;
    for (const char *p = names + strspn(names, " "); *p; p += strspn(p, " ")) {
        const size_t len = strcspn(p, " ");
        const int k = sim_observable_find(solver, p, len);
        if (k < 0 || k >= SIM_OBS_BASE) {
            snprintf(msg, msglen, "the case's observes names \"%.*s\", which is not one of "
                     "the observables T .. a3", (int)len, p);
            return SIM_EINVAL;
        }
        only |= SIM_OBS_BIT(k);
        p += len;
    }
    solver->observe_only = only;
    return SIM_OK;
}

/* Load row i's scenes: the sweep's settings, `extra` (a variant's, or
 * NULL), derived ones, then --set, then --solver-set. */
static sim_status row_scenes(vfy_case_run *run, const vfy_sweep *s, vfy_row *row,
                             const char *extra, char *msg, size_t msglen)
{
    enum { MAX = VFY_SWEEP_KEYS + 32 };
    char storage[MAX][160], stem[sizeof row->stem];
    const char *sets[MAX];
    snprintf(stem, sizeof stem, "%s", run->d->scene ? run->d->scene : run->c->name);
    size_t nsets = split_sets(s->sets, storage, sets, 0, MAX, stem, sizeof stem, row);
    if (s->rows != NULL) {
        const char *text = s->rows[row->index], *colon = strchr(text, ':');
        size_t n = colon ? (size_t)(colon - text) : 0;
        snprintf(row->label, sizeof row->label, "%.*s", (int)n, text);
        nsets = split_sets(colon ? colon + 1 : text, storage, sets, nsets, MAX, stem,
                           sizeof stem, row);
    }
    for (size_t k = 0; k < VFY_SWEEP_KEYS && s->keys[k] && nsets < MAX; k++) {
        char value[64];
        vfy_sweep_value(s, row->index, k, value, sizeof value);
        snprintf(storage[nsets], sizeof storage[nsets], "%s=%s", s->keys[k], value);
        sets[nsets] = storage[nsets];
        nsets++;
        vfy_values_set(&row->values, sweep_name(s, k), strtod(value, NULL));
    }
    nsets = split_sets(extra, storage, sets, nsets, MAX, stem, sizeof stem, row);
    snprintf(row->stem, sizeof row->stem, "%s", stem);
    sim_status status = vfy_load_scene_sets(stem, run->o, sets, nsets, &row->scene,
                                            &row->solver, msg, msglen);
    char derived[512];
    if (status == SIM_OK && run->d->derive
        && run->d->derive(row, derived, sizeof derived)[0]) {
        nsets = split_sets(derived, storage, sets, nsets, MAX, stem, sizeof stem, row);
        status = vfy_load_scene_sets(stem, run->o, sets, nsets, &row->scene, &row->solver, msg,
                                     msglen);
    }
    if (status == SIM_OK && run->d->adjust)
        status = run->d->adjust(row, &row->solver, msg, msglen);
    if (status == SIM_OK && run->d->observes)
        status = observe_only(run->d->observes, &row->solver, msg, msglen);
    return status;
}

/* The cost values of result res, each name followed by suffix ("" or
 * "@VARIANT"), and for the first variant the steady averages by name. */
static void row_cost_values(vfy_row *row, const sim_ensemble_result *res, const char *suffix)
{
    static const char *const names[] = {"N", "M", "cpu_s", "wall_s", "events", "ns_per_event",
                                        "collisions", "background", "violations", "normals"};
    /* what an external solver did not report is NaN (and its checks SKIP) */
    const double events = res->missing & SIM_MISSING_EVENTS ? NAN
                                                            : (double)res->counts.candidates;
    const int counted = !(res->missing & SIM_MISSING_COLLISIONS);
    const double v[] = {(double)res->ensembles, (double)res->outputs, res->cpu_seconds,
                        res->wall_seconds, events,
                        events > 0 || isnan(events) ? 1e9 * res->cpu_seconds / events : 0.0,
                        counted ? (double)res->counts.collisions : NAN,
                        counted ? (double)res->counts.background : NAN,
                        res->missing & SIM_MISSING_VIOLATIONS ? NAN
                                                              : (double)res->counts.violations,
                        counted ? (double)res->counts.normals : NAN};
    for (size_t k = 0; k < sizeof names / sizeof *names; k++) {
        char name[48];
        snprintf(name, sizeof name, "%s%s", names[k], suffix);
        vfy_values_set(&row->values, name, v[k]);
    }
    for (size_t k = 0; suffix[0] == '\0' && k < res->nsteady; k++) {
        char name[32], ci[40];
        if (!sim_steady_scalar(&row->solver, k))
            continue;
        sim_steady_name(&row->solver, k, name, sizeof name);
        snprintf(ci, sizeof ci, "%s_ci", name);
        vfy_values_set(&row->values, name, res->steady_mean[k]);
        vfy_values_set(&row->values, ci, res->steady_ci[k]);
    }
}

/* A row's label template: the description's, or "{case} n={n}". */
static const char *row_label_template(const vfy_case_desc *d)
{
    return d->label ? d->label : "{case} n={n}";
}

/* Simulate each variant of the row (or its one solver scene). */
static sim_status row_simulate(vfy_case_run *run, const vfy_sweep *s, vfy_row *row, char *msg,
                               size_t msglen)
{
    const vfy_case_desc *d = run->d;
    const size_t nvariants = vfy_variant_count(d);
    if (nvariants > 1 && (row->more = calloc(nvariants - 1, sizeof *row->more)) == NULL) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    sim_status status = SIM_OK;
    for (size_t k = 0; k < nvariants && status == SIM_OK; k++) {
        char variant[64], suffix[68] = "", label[160];
        const char *sets = variant_parts(d, k, variant, sizeof variant);
        if (variant[0]) {
            if (k > 0)
                snprintf(suffix, sizeof suffix, "@%s", variant);
            if ((status = row_scenes(run, s, row, sets, msg, msglen)) != SIM_OK)
                break;
        }
        vfy_expand(label, sizeof label, row_label_template(d), run, row);
        if (variant[0])
            snprintf(label + strlen(label), sizeof label - strlen(label), " %s", variant);
        sim_ensemble_result *res = k == 0 ? &row->res : &row->more[k - 1];
        status = vfy_simulate(&row->solver, run->o, label, res, msg, msglen);
        if (status == SIM_EUNSUPPORTED && vfy_external(run->o)) {   /* an answer, not an error */
            if (row->refused[0] == '\0')
                snprintf(row->refused, sizeof row->refused, "%s%s%s", variant,
                         variant[0] ? ": " : "", msg);
            status = SIM_OK;
        }
        if (status == SIM_OK)
            row_cost_values(row, res, suffix);
        if (status == SIM_OK && k == 0)   /* a solver's declared bound (0: the engine's) */
            vfy_values_set(&row->values, "violations_allowed",
                           vfy_external(run->o) && run->o->solver
                               ? run->o->solver->violations_allowed
                               : 0.0);
    }
    return status;
}

/* The first row of the run an external solver refused, or NULL. */
static const vfy_row *run_refused(const vfy_case_run *run)
{
    for (size_t i = 0; i < run->nrows; i++)
        if (run->rows[i].refused[0] != '\0')
            return &run->rows[i];
    return NULL;
}

/* Why a check of the whole case is not judged when row `no` was refused. */
static const char *needs_refused_row(const vfy_case_run *run, const vfy_row *no, char *buf,
                                     size_t len)
{
    char label[160];
    snprintf(buf, len, "needs a row the solver refused (%s: %s)",
             vfy_expand(label, sizeof label, row_label_template(run->d), run, no), no->refused);
    return buf;
}

/* Whether row's result lacks something (an external solver's NaN or a
 * count it did not report). */
static int row_incomplete(const vfy_row *row)
{
    const sim_ensemble_result *res = &row->res;
    int gap = res->missing != 0;
    for (size_t i = 0; i < res->outputs * res->observables + res->nsteady && !gap; i++)
        gap = isnan(res->mean[i]);
    return gap;
}

/* Whether some row's result lacks something. */
static int run_incomplete(const vfy_case_run *run)
{
    for (size_t i = 0; i < run->nrows; i++)
        if (row_incomplete(&run->rows[i]))
            return 1;
    return 0;
}

/* Whether operand `name` of a check on an incomplete row is missing (NaN
 * somewhere): a quantity the solver did not report, or one made from it.
 * The paper's own numbers are not the solver's. */
static int operand_missing(const vfy_case_run *run, const vfy_row *row, const char *name)
{
    if (name == NULL)
        return 0;
    for (const vfy_paper_column *p = run->d->paper_columns; p && p->name; p++)
        if (strcmp(p->name, name) == 0)
            return 0;
    const size_t M = row->res.outputs;
    double *series = malloc((M ? M : 1) * sizeof *series);
    int missing = 0;
    if (series != NULL && vfy_row_series(row, name, series, NULL) == 0) {
        for (size_t m = 0; m < M; m++)
            missing |= isnan(series[m]);
    } else if (series != NULL) {
        missing = isnan(lookup(run, row, name));
    }
    free(series);
    return missing;
}

/* Whether name is a quantity a result file reports itself (an observable,
 * of a variant too, a steady quantity or a count), not one made from them. */
static int reported_quantity(const vfy_row *row, const char *name)
{
    const size_t len = strcspn(name, "@");
    if ((row != NULL && sim_observable_find(&row->solver, name, len) >= 0) || strcmp(name, "violations") == 0
        || strcmp(name, "events") == 0)
        return 1;
    return row != NULL && sim_steady_find(&row->solver, name) >= 0;
}

/* The checks of a row, or of the case (row NULL: no guards).  On an
 * external solver's incomplete result, a NaN any rule meets is a SKIP. */
static void run_checks(vfy_case_run *run, vfy_row *row, const vfy_check_spec *checks,
                       vfy_report *r)
{
    const int incomplete =
        vfy_external(run->o) && (row != NULL ? row_incomplete(row) : run_incomplete(run));
    const char *const was = r->missing;
    char label[160] = "", refused[480] = "";
    const vfy_row *no = row != NULL ? (row->refused[0] ? row : NULL) : run_refused(run);
    if (no != NULL && row != NULL)
        snprintf(refused, sizeof refused, "solver refused: %s", row->refused);
    else if (no != NULL)   /* a case check: it may need the refused row */
        needs_refused_row(run, no, refused, sizeof refused);
    if (incomplete)
        r->missing = refused[0] ? refused : "needs quantities the solver did not report";
    if (row != NULL)
        vfy_expand(label, sizeof label, row_label_template(run->d), run, row);
    r->row = row != NULL ? label : "";
    for (const vfy_check_spec *c = checks; c && c->name; c++) {
        vfy_guard_result g = c->guard.fn && row ? c->guard.fn(run, row, &c->guard) : VFY_JUDGE;
        if (g == VFY_OMIT)
            continue;
        char name[160], why[320], differs[400];
        vfy_expand(name, sizeof name, c->name, run, row);
        r->check_id = c->name;
        if (c->builtin_only && vfy_external(run->o)) {
            snprintf(why, sizeof why, "built-in engine only: %s", c->builtin_only);
            vfy_skip(r, name, why);
            continue;
        }
        if (row != NULL && no != NULL) {   /* nothing of the row to judge */
            vfy_skip(r, name, refused);
            continue;
        }
        const char *gone = NULL;   /* an operand an external solver did not report */
        if (row != NULL && incomplete)
            gone = operand_missing(run, row, c->value)      ? c->value
                   : operand_missing(run, row, c->expected) ? c->expected
                                                            : NULL;
        if (row == NULL && incomplete)   /* case checks */
            gone = c->value && isnan(lookup(run, NULL, c->value))          ? c->value
                   : c->expected && isnan(lookup(run, NULL, c->expected)) ? c->expected
                                                                          : NULL;
        if (gone != NULL) {
            if (no != NULL)
                snprintf(why, sizeof why, "%s: %s", gone, refused);
            else if (reported_quantity(row, gone))
                snprintf(why, sizeof why, "%s not reported by the solver", gone);
            else
                snprintf(why, sizeof why, "%s needs quantities the solver did not report", gone);
            vfy_skip(r, name, why);
            continue;
        }
        if (g == VFY_GUARD_SKIP) {
            vfy_skip(r, name, vfy_expand(why, sizeof why, c->guard.reason, run, row));
            continue;
        }
        if (c->differs != NULL) {   /* the judging check by its name after the row's label */
            const char *by = c->differs->judged_by, *prefix = row_label_template(run->d);
            char judge[200];
            if (strncmp(by, prefix, strlen(prefix)) == 0 && by[strlen(prefix)] == ' ')
                by += strlen(prefix) + 1;
            snprintf(differs, sizeof differs, "%s; judged by \"%s\" (docs/differences.md)",
                     c->differs->paper, vfy_expand(judge, sizeof judge, by, run, row));
            r->differs = differs;
        }
        c->rule(r, name, run, row, c);
        r->differs = NULL;
    }
    r->missing = was;
    r->check_id = NULL;
    r->row = NULL;
}

int vfy_parse_columns(const char *spec, vfy_column **cols, size_t *ncols, char **text,
                      char *msg, size_t msglen)
{
    *cols = NULL;
    *ncols = 0;
    size_t words = 0;
    for (const char *p = spec; *p; p++)
        words += !isspace((unsigned char)*p) && (p == spec || isspace((unsigned char)p[-1]));
    *text = malloc(strlen(spec) + 1);
    *cols = calloc(words ? words : 1, sizeof **cols);
    if (*text == NULL || *cols == NULL) {
        snprintf(msg, msglen, "out of memory");
        return -1;
    }
    strcpy(*text, spec);
    char *save = NULL;
    for (char *w = strtok_r(*text, " \t\n", &save); w; w = strtok_r(NULL, " \t\n", &save)) {
        vfy_column *col = &(*cols)[(*ncols)++];
        char *format = strchr(w, ':'), *value = strchr(w, '=');
        if (format == NULL || format == w || format[1] != '%' || (value && value > format)
            || value == w || (value && value + 1 == format)) {
            snprintf(msg, msglen, "column '%s' is not HEADER[=VALUE]:FORMAT", w);
            return -1;
        }
        *format++ = '\0';
        if (value != NULL)
            *value++ = '\0';
        *col = (vfy_column){w, value, format};
    }
    return 0;
}

static int row_cells(vfy_case_run *run, const vfy_row *row)
{
    int rc = 0;
    for (const vfy_column *col = run->columns; col < run->columns + run->ncols; col++) {
        const char *name = col->value ? col->value : col->header;
        if (strcmp(col->format, "%s") == 0) {
            const char *text = row_string(row, name);
            rc |= vfy_table_cell(&run->table, "%s", text ? text : "");
        } else {
            double v = lookup(run, row, name);
            rc |= vfy_table_number(&run->table, !isnan(v), col->format, v);
        }
    }
    return rc;
}

/* Simulate row i and derive its values, checks and cells. */
static sim_status run_row(vfy_case_run *run, const vfy_sweep *s, vfy_row *row, vfy_report *r,
                          char *msg, size_t msglen)
{
    const vfy_case_desc *d = run->d;
    sim_status status = row_scenes(run, s, row, NULL, msg, msglen);
    if (status != SIM_OK)
        return status;
    if (row->index == 0 && d->needs) {
        size_t count = 0;
        while (d->needs[count])
            count++;
        status = vfy_require_references(&row->scene, d->needs, count, d->needs_why, msg, msglen);
        if (status != SIM_OK)
            return status;
    }
    vfy_values_set(&row->values, "index", (double)row->index);
    vfy_values_set(&row->values, "n", (double)row->solver.particles.n);
    if (d->needs || (d->figures[0].kind == VFY_FIGURE_CURVES && d->figures[0].refs[0])) {
        sim_error err;
        if ((status = vfy_scene_references(&row->scene, &row->refs, &err)) != SIM_OK) {
            vfy_scene_format_error(&row->scene, &err, msg, msglen);
            return status;
        }
    }
    for (const char *const *v = d->values; v && *v; v++)
        vfy_values_set(&row->values, *v, vfy_reference_value(*v, &row->scene));
    if (!d->no_simulation && (status = row_simulate(run, s, row, msg, msglen)) != SIM_OK)
        return status;
    if (row->refused[0] != '\0')
        r->refused++;
    for (const vfy_paper_column *p = d->paper_columns; p && p->name; p++)
        vfy_values_set(&row->values, p->name, row->index < p->count ? p->v[row->index] : NAN);
    for (const vfy_metric *m = d->metrics; m && m->name; m++)
        vfy_values_set(&row->values, m->name, m->fn(run, row, m));
    run_checks(run, row, d->checks, r);
    if (row_cells(run, row) != 0) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    if (d->row_progress && run->o->progress && row->refused[0] == '\0') {
        char line[512];
        fprintf(run->o->progress, "   %s\n", vfy_expand(line, sizeof line, d->row_progress, run,
                                                         row));
    }
    return vfy_write_rows_so_far(run->o, run->c->name, &run->table, &row->solver, msg, msglen);
}

/* ------------------------------------------------------------ figure */

/* "LABEL=name" or "name": the label into label, returns the name. */
static const char *label_and_name(const char *spec, char *label, size_t len)
{
    const char *eq = strchr(spec, '=');
    snprintf(label, len, "%.*s", (int)(eq ? (size_t)(eq - spec) : strlen(spec)), spec);
    return eq ? eq + 1 : spec;
}

/* VFY_FIGURE_POINTS (driver.h). */
static int write_points(vfy_case_run *run, const vfy_figure_spec *f)
{
    enum { FINE = 81 };
    size_t nseries = 0, ncurves = 0, np = 0;
    while (nseries < 4 && f->series[nseries])
        nseries++;
    while (ncurves < 4 && f->refs[ncurves])
        ncurves++;
    double *buf = malloc(((1 + 2 * nseries) * run->nrows + (1 + ncurves) * FINE) * sizeof *buf);
    if (buf == NULL)
        return -1;
    double *x = buf, *y = x + run->nrows, *ci = y + nseries * run->nrows;
    double *xfine = ci + nseries * run->nrows, *yfine = xfine + FINE;
    char labels[8][64], cinames[4][48];
    const char *slabels[4], *clabels[4];
    const double *ys[4], *cis[4], *yfs[4];
    for (size_t i = 0; i < run->nrows; i++) {
        const vfy_row *row = &run->rows[i];
        int finite = 1;
        for (size_t j = 0; j < nseries; j++) {
            const char *name = label_and_name(f->series[j], labels[j], sizeof labels[j]);
            snprintf(cinames[j], sizeof cinames[j], "%s_ci", name);
            y[j * run->nrows + np] = lookup(run, row, name);
            ci[j * run->nrows + np] = lookup(run, row, cinames[j]);
            finite &= isfinite(y[j * run->nrows + np]);
        }
        x[np] = lookup(run, row, f->x);
        np += (size_t)finite;
    }
    sim_scene at = run->rows[run->nrows - 1].scene;
    for (size_t k = 0; k < FINE; k++) {
        xfine[k] = f->x_lo + (f->x_hi - f->x_lo) * (double)k / (FINE - 1);
        at.collisions.restitution = xfine[k];
        for (size_t j = 0; j < ncurves; j++)
            yfine[j * FINE + k] = vfy_reference_value(
                label_and_name(f->refs[j], labels[4 + j], sizeof labels[4 + j]), &at);
    }
    for (size_t j = 0; j < 4; j++) {
        slabels[j] = labels[j];
        clabels[j] = labels[4 + j];
        ys[j] = y + j * run->nrows;
        cis[j] = ci + j * run->nrows;
        yfs[j] = yfine + j * FINE;
    }
    char name[160], title[256];
    snprintf(name, sizeof name, "%s%s", run->c->name, f->suffix ? f->suffix : "");
    vfy_expand(title, sizeof title, f->title, run, NULL);
    const vfy_points points = {.name = name, .title = title, .xlabel = f->xlabel,
                               .ylabel = f->ylabel, .npoints = np, .x = x, .nseries = nseries,
                               .series = slabels, .y = ys, .ci = cis,
                               .nfine = ncurves ? FINE : 0, .xfine = xfine,
                               .ncurves = ncurves, .curves = clabels, .yfine = yfs,
                               .comment = run->comment};
    int rc = np > 0 ? vfy_write_points(run->o, &points) : 0;
    free(buf);
    return rc;
}

/* Whether every row has the last row's output times. */
static int rows_share_grid(const vfy_case_run *run)
{
    const sim_ensemble_result *last = &run->rows[run->nrows - 1].res;
    for (size_t i = 0; i < run->nrows; i++) {
        const sim_ensemble_result *r = &run->rows[i].res;
        if (r->outputs != last->outputs)
            return 0;
        for (size_t m = 0; m < r->outputs; m++)
            if (r->t[m] != last->t[m])
                return 0;
    }
    return 1;
}

/* A curves figure over rows with output times of their own (as-transient's
 * t_end and outputs differ by row): each row a curve on its own times, with
 * its references dashed, as an xy figure (one gnuplot index block a curve),
 * t on a log axis (the rows' spans differ) and y too when it is positive and
 * spans two decades or more. */
static int write_curves_by_row(vfy_case_run *run, const vfy_figure_spec *f, const char *name,
                               const char *title, const char *quantity)
{
    size_t nref = 0, total = 0;
    while (nref < 4 && f->refs[nref])
        nref++;
    for (size_t i = 0; i < run->nrows; i++)
        total += run->rows[i].res.outputs;
    const size_t ncurves = run->nrows * (1 + nref);
    vfy_xy_curve *curves = calloc(ncurves, sizeof *curves);
    char (*labels)[160] = calloc(ncurves, sizeof *labels);
    double *buf = malloc((2 + nref) * total * sizeof *buf);
    int rc = -1;
    if (curves != NULL && labels != NULL && buf != NULL) {
        double *at = buf;
        size_t c = 0;
        for (size_t i = 0; i < run->nrows; i++) {
            const vfy_row *row = &run->rows[i];
            const size_t M = row->res.outputs;
            char label[96];
            vfy_expand(label, sizeof label, row_label_template(run->d), run, row);
            for (size_t j = 0; j <= nref; j++, c++) {
                double *mean = at, *ci = j == 0 ? at + M : NULL;
                at += j == 0 ? 2 * M : M;
                if (vfy_row_series(row, j == 0 ? f->quantity : f->refs[j - 1], mean, ci) != 0)
                    for (size_t m = 0; m < M; m++)   /* no such series: no points */
                        mean[m] = NAN;
                snprintf(labels[c], sizeof labels[c], "%s%s%s", label, j ? ": " : "",
                         j ? f->refs[j - 1] : "");
                curves[c] = (vfy_xy_curve){.label = labels[c], .reference = j > 0, .count = M,
                                           .x = row->res.t, .y = {mean}, .ci = {ci}};
            }
        }
        int positive = 1;
        double lo = INFINITY, hi = 0.0;
        for (size_t k = 0; k < c; k++)
            for (size_t m = 0; m < curves[k].count; m++) {
                const double y = curves[k].y[0][m];
                if (isnan(y))
                    continue;   /* left out of the figure */
                positive &= y > 0.0;
                lo = fmin(lo, y);
                hi = fmax(hi, y);
            }
        const vfy_xy_figure xy = {.name = name, .title = title, .xlabel = "t",
                                  .comment = run->comment, .logx = 1,
                                  .logy = positive && hi >= 100.0 * lo, .npanels = 1,
                                  .ylabel = {quantity}, .ncurves = ncurves, .curves = curves};
        rc = vfy_write_xy(run->o, &xy);
    }
    free(curves);
    free(labels);
    free(buf);
    return rc;
}

static int write_figure(vfy_case_run *run, const vfy_figure_spec *f, const char *title)
{
    if (f->kind == VFY_FIGURE_POINTS)
        return write_points(run, f);
    const vfy_row *last = &run->rows[run->nrows - 1];
    char name[160], quantity[64];   /* "T@*" is drawn as T */
    snprintf(name, sizeof name, "%s%s", run->c->name, f->suffix ? f->suffix : "");
    snprintf(quantity, sizeof quantity, "%.*s",
             (int)(strstr(f->quantity, "@*") ? strcspn(f->quantity, "@") : strlen(f->quantity)),
             f->quantity);
    if (!rows_share_grid(run))
        return write_curves_by_row(run, f, name, title, quantity);
    const int extra = f->extrapolated && run->extra_mean != NULL;
    size_t M = last->res.outputs, rows = run->nrows + (size_t)extra, nref = 0;
    double *buf = malloc((2 * rows + 4) * M * sizeof *buf);
    size_t *n = malloc(rows * sizeof *n);
    int rc = -1;
    if (buf != NULL && n != NULL) {
        const char *names[4];
        const double *refs[4];
        double *mean = buf, *ci = buf + rows * M, *ref = buf + 2 * rows * M;
        for (; nref < 4 && f->refs[nref]; nref++) {
            vfy_row_series(last, f->refs[nref], ref + nref * M, NULL);
            names[nref] = f->refs[nref];
            refs[nref] = ref + nref * M;
        }
        for (size_t i = 0; i < run->nrows; i++) {
            n[i] = run->rows[i].solver.particles.n;
            vfy_row_series(&run->rows[i], f->quantity, mean + i * M, ci + i * M);
        }
        if (extra) {   /* n = 0 marks the extrapolation */
            n[rows - 1] = 0;
            memcpy(mean + (rows - 1) * M, run->extra_mean, M * sizeof *mean);
            memcpy(ci + (rows - 1) * M, run->extra_ci, M * sizeof *ci);
        }
        rc = vfy_write_curves(run->o, name, title, run->comment, last->res.t, M, nref,
                              names, refs, rows, n, NULL, mean, ci, quantity, f->x_from,
                              f->panel_per_row);
    }
    free(buf);
    free(n);
    return rc;
}

/* ------------------------------------------------------------ provenance */

typedef void (*row_field_fn)(const vfy_row *row, char *buf, size_t len);

static void field_scene(const vfy_row *row, char *buf, size_t len)
{
    snprintf(buf, len, "%s", vfy_display_path(row->solver.file));
}
static void field_seed(const vfy_row *row, char *buf, size_t len)
{
    snprintf(buf, len, "%llu", (unsigned long long)row->solver.seed);
}
static void field_n(const vfy_row *row, char *buf, size_t len)
{
    snprintf(buf, len, "%zu", row->solver.particles.n);
}
static void field_ensembles(const vfy_row *row, char *buf, size_t len)
{
    snprintf(buf, len, "%zu", row->solver.particles.ensembles);
}
static void field_outputs(const vfy_row *row, char *buf, size_t len)
{
    snprintf(buf, len, "%zu outputs on [0, %g]", row->solver.outputs, row->solver.t_end);
}

/* Append "LABEL v" when every row has the same value, else "LABEL v1, v2,
 * ... (by row)", each followed by unit. */
static void append_field(const vfy_case_run *run, char *buf, size_t len, const char *label,
                         row_field_fn field, const char *unit)
{
    char first[256], v[256];
    field(&run->rows[0], first, sizeof first);
    int same = 1;
    for (size_t i = 1; i < run->nrows && same; i++) {
        field(&run->rows[i], v, sizeof v);
        same = strcmp(v, first) == 0;
    }
    size_t used = strlen(buf);
    used += (size_t)snprintf(buf + used, used < len ? len - used : 0, "%s%s", label, first);
    for (size_t i = 1; i < run->nrows && !same && used < len; i++) {
        field(&run->rows[i], v, sizeof v);
        used += (size_t)snprintf(buf + used, len - used, ", %s", v);
    }
    if (used < len)
        snprintf(buf + used, len - used, "%s%s", unit, same ? "" : " (by row)");
}

/* The provenance line of the tables and figures ({comment}): each row's own
 * scene file, seed, n, N and output times, said once where the rows share
 * them. */
static void run_provenance(vfy_case_run *run)
{
    char *buf = run->comment;
    const size_t len = sizeof run->comment;
    snprintf(buf, len, "gdsmc %s verify: ", GDSMC_VERSION);
    append_field(run, buf, len, "scene ", field_scene, "");
    append_field(run, buf, len, ", seed ", field_seed, "");
    append_field(run, buf, len, ", n = ", field_n, "");
    append_field(run, buf, len, ", N = ", field_ensembles, " ensembles");
    append_field(run, buf, len, ", ", field_outputs, "");
    if (vfy_external(run->o))   /* the command, and what the solver said it is */
        snprintf(buf + strlen(buf), len - strlen(buf), "; solver '%s'%s%s%s",
                 run->o->solver->command, run->o->solver->line[0] ? " (" : "",
                 run->o->solver->line, run->o->solver->line[0] ? ")" : "");
}

/* ------------------------------------------------------------ extrapolation */

int vfy_run_extrapolate(vfy_case_run *run, const char *quantity, double *chi2)
{
    const size_t rows = run->nrows, M = run->rows[0].res.outputs;
    double *buf = malloc((2 * rows * M + 2 * rows) * sizeof *buf);
    size_t *n = malloc(rows * sizeof *n);
    free(run->extra_mean);
    free(run->extra_ci);
    run->extra_mean = malloc(M * sizeof *run->extra_mean);
    run->extra_ci = malloc(M * sizeof *run->extra_ci);
    int rc = buf && n && run->extra_mean && run->extra_ci ? 0 : -1;
    double *mean = buf, *sigma = buf ? buf + rows * M : NULL;
    for (size_t i = 0; i < rows && rc == 0; i++) {
        n[i] = run->rows[i].solver.particles.n;
        rc = vfy_row_series(&run->rows[i], quantity, mean + i * M, sigma + i * M);
        for (size_t m = 0; m < M; m++)
            sigma[i * M + m] /= SIM_LAMBDA_P;
    }
    for (size_t m = 0; m < M && rc == 0; m++) {
        double *mm = sigma + rows * M, *ss = mm + rows, sd, x2;
        for (size_t i = 0; i < rows; i++) {
            mm[i] = mean[i * M + m];
            ss[i] = sigma[i * M + m];
        }
        vfy_extrapolate_inverse_n(rows, n, mm, ss, &run->extra_mean[m], &sd, &x2);
        run->extra_ci[m] = SIM_LAMBDA_P * sd;
        if (chi2 != NULL)
            chi2[m] = x2;
    }
    free(buf);
    free(n);
    return rc;
}

/* ------------------------------------------------------------ the case */

static sim_status finish(vfy_case_run *run, vfy_report *r, char *msg, size_t msglen)
{
    const vfy_case_desc *d = run->d;
    double wall = 0.0;
    for (size_t i = 0; i < run->nrows; i++) {
        wall += run->rows[i].res.wall_seconds;
        for (size_t k = 0; run->rows[i].more && k + 1 < vfy_variant_count(d); k++)
            wall += run->rows[i].more[k].wall_seconds;
    }
    const vfy_row *last = &run->rows[run->nrows - 1];
    vfy_values_set(&run->values, "wall_total", wall);
    vfy_values_set(&run->values, "rows", (double)run->nrows);
    vfy_values_set(&run->values, "outputs", (double)last->res.outputs);
    run_provenance(run);
    /* the hook's own checks on what an incomplete external result left NaN */
    char refused[480];
    const vfy_row *no = run_refused(run);
    if (vfy_external(run->o) && run_incomplete(run))
        r->missing = no != NULL ? needs_refused_row(run, no, refused, sizeof refused)
                                : "needs quantities the solver did not report";
    sim_status status = d->after_rows ? d->after_rows(run, r, msg, msglen) : SIM_OK;
    r->missing = NULL;
    if (status != SIM_OK)
        return status;
    run_checks(run, NULL, d->case_checks, r);
    double cpu = 0.0;
    for (size_t i = 0; i < run->nrows; i++) {
        cpu += run->rows[i].res.cpu_seconds;
        for (size_t k = 0; run->rows[i].more && k + 1 < vfy_variant_count(d); k++)
            cpu += run->rows[i].more[k].cpu_seconds;
    }
    if ((status = vfy_write_verdicts(run->o, run->c->name, r, run->comment, wall, cpu, msg,
                                     msglen))
        != SIM_OK)
        return status;
    const char *const *headers = run->table.cols;   /* the table again, with what the hook set */
    const size_t ncols = run->table.ncols;
    vfy_table_free(&run->table);
    vfy_table_init(&run->table, ncols, headers);
    for (size_t i = 0; i < run->nrows; i++)
        if (row_cells(run, &run->rows[i]) != 0) {
            snprintf(msg, msglen, "out of memory");
            return SIM_ENOMEM;
        }
    size_t notes_len = strlen(d->notes) + 4096;
    char title[256], *notes = malloc(notes_len);
    if (notes == NULL) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    vfy_expand(title, sizeof title, d->title, run, NULL);
    vfy_expand(notes, notes_len, d->notes, run, NULL);
    status = vfy_write_case_tables(run->o, run->c->name, &run->table, run->comment, title,
                                    notes, run->second.ncols ? &run->second : NULL,
                                    run->second_suffix, run->second_title, run->second_notes,
                                    msg, msglen);
    free(notes);
    for (size_t k = 0; k < VFY_FIGURES_MAX && d->figures[k].kind != VFY_FIGURE_NONE
                       && status == SIM_OK;
         k++)
        if (write_figure(run, &d->figures[k], title) != 0)
            status = vfy_io_error(run->c->name, msg, msglen);
    return status;
}

/* ------------------------------------------------------------ dry run */

/* What a check operand `name` is, for the row's solver scene: a quantity
 * the result file reports, or what the case makes from it (--dry-run). */
static const char *operand_kind(const vfy_case_run *run, const vfy_row *row, const char *name)
{
    const vfy_case_desc *d = run->d;
    const size_t len = strcspn(name, "@");
    char base[64];
    snprintf(base, sizeof base, "%.*s", (int)(len < sizeof base ? len : sizeof base - 1), name);
    if (sim_observable_find(&row->solver, base, strlen(base)) >= 0)
        return "reported: an observable, at every output time";
    if (sim_steady_find(&row->solver, base) >= 0)
        return "reported: a steady quantity";
    const size_t blen = strlen(base);
    if (blen > 3 && strcmp(base + blen - 3, "_ci") == 0) {
        base[blen - 3] = '\0';
        if (sim_steady_find(&row->solver, base) >= 0)
            return "reported: a steady quantity's variance (its half-width)";
        base[blen - 3] = '_';
    }
    if (strcmp(base, "violations") == 0 || strcmp(base, "events") == 0)
        return "reported: a count (optional)";
    static const char *const engine_counts[] = {"collisions", "background", "normals"};
    for (size_t k = 0; k < sizeof engine_counts / sizeof *engine_counts; k++)
        if (strcmp(base, engine_counts[k]) == 0)
            return "the built-in engine's count (not in the protocol: SKIP)";
    static const char *const cost[] = {"N", "M", "cpu_s", "wall_s", "ns_per_event", "n",
                                       "index"};
    for (size_t k = 0; k < sizeof cost / sizeof *cost; k++)
        if (strcmp(base, cost[k]) == 0)
            return "the run's size or cost";
    for (const vfy_paper_column *p = d->paper_columns; p && p->name; p++)
        if (strcmp(p->name, base) == 0)
            return "a paper's printed number";
    for (const char *const *v = d->values; v && *v; v++)
        if (strcmp(*v, base) == 0)
            return "a reference value";
    if (vfy_reference_find(base) != NULL)
        return "a reference";
    return "made by the case from the result";   /* a metric, a hook's value */
}

/* Add name (without "@VARIANT") to the list `reported` (" a b ", cap
 * bytes) once, when the result file reports it. */
static void note_reported(const vfy_case_run *run, const vfy_row *row, const char *name,
                          char *reported, size_t cap)
{
    char word[72];
    snprintf(word, sizeof word, " %.*s ", (int)strcspn(name, "@"), name);
    const size_t used = strlen(reported);
    if (strncmp(operand_kind(run, row, name), "reported", 8) != 0
        || strstr(reported, word) != NULL || used + strlen(word) >= cap)
        return;
    snprintf(reported + used, cap - used, "%s", word + (used > 0));   /* one space between */
}

/* One check's operands and what each is; the reported ones noted. */
static void dry_check(FILE *out, const vfy_case_run *run, const vfy_row *row,
                      const vfy_check_spec *c, char *reported, size_t cap)
{
    fprintf(out, "     %s\n", c->name);
    const char *const ops[] = {c->value, c->expected, c->plus, c->plus_quick};
    static const char *const role[] = {"value", "against", "plus", "plus (quick)"};
    for (size_t k = 0; k < sizeof ops / sizeof *ops; k++)
        if (ops[k] != NULL) {
            fprintf(out, "       %-13s %-22s %s\n", role[k], ops[k],
                    operand_kind(run, row, ops[k]));
            note_reported(run, row, ops[k], reported, cap);
        }
    for (const vfy_metric *m = run->d->metrics; m && m->name; m++) {
        if (c->value == NULL || strcmp(m->name, c->value) != 0)
            continue;
        const char *const from[] = {m->a, m->b};   /* a metric's named operands */
        for (size_t k = 0; k < 2; k++)
            if (from[k] != NULL) {
                fprintf(out, "       %-13s %-22s %s\n", "  made from", from[k],
                        operand_kind(run, row, from[k]));
                note_reported(run, row, from[k], reported, cap);
            }
    }
}

/* --dry-run: each row's scene (and each variant's) as the solver would get
 * it, written to OUT/CASE/row-NN[@VARIANT].ini, and what each check reads;
 * no simulation. */
static sim_status dry_run_case(const vfy_case *c, const vfy_options *o, char *msg,
                               size_t msglen)
{
    const vfy_case_desc *d = c->desc;
    const vfy_sweep *s = o->size == VFY_PAPER ? &d->paper_rows : &d->quick_rows;
    const size_t rows = vfy_sweep_rows(s);
    vfy_case_run run = {.c = c, .d = d, .o = o};
    vfy_row *row = calloc(1, sizeof *row);
    char dir[1100], path[1200], label[160];
    snprintf(dir, sizeof dir, "%s/%s", o->out_dir, c->name);
    if (row == NULL || vfy_ensure_dir(dir) != 0) {
        free(row);
        snprintf(msg, msglen, "%s: cannot create: %s", dir, strerror(errno));
        return SIM_EIO;
    }
    FILE *out = o->dry_run;
    const size_t nvariants = vfy_variant_count(d);
    fprintf(out, "== %s (%s sizes): %zu rows%s, the scenes in %s/\n", c->name,
            o->size == VFY_QUICK ? "quick" : "paper", rows,
            d->no_simulation ? " (references only: nothing to simulate)" : "", dir);
    sim_status status = SIM_OK;
    run.rows = row;
    for (size_t i = 0; i < rows && status == SIM_OK && !d->no_simulation; i++) {
        *row = (vfy_row){.index = i, .run = &run};
        run.nrows = 1;
        for (size_t k = 0; k < nvariants && status == SIM_OK; k++) {
            char variant[64];
            const char *sets = variant_parts(d, k, variant, sizeof variant);
            if ((status = row_scenes(&run, s, row, sets, msg, msglen)) != SIM_OK)
                break;
            vfy_values_set(&row->values, "index", (double)i);
            vfy_values_set(&row->values, "n", (double)row->solver.particles.n);
            snprintf(path, sizeof path, "%s/row-%02zu%s%s.ini", dir, i + 1, variant[0] ? "@" : "",
                     variant);
            FILE *f = fopen(path, "w");
            const int written = f != NULL && vfy_scene_write(f, &row->solver) == 0;
            if (f == NULL || fclose(f) != 0 || !written) {
                snprintf(msg, msglen, "%s: cannot write: %s", path, strerror(errno));
                status = SIM_EIO;
                break;
            }
            fprintf(out, "   row %zu%s%s: %s -> %s\n", i + 1, variant[0] ? " variant " : "",
                    variant, vfy_expand(label, sizeof label, row_label_template(d), &run, row),
                    path);
        }
        if (status == SIM_OK && i + 1 < rows)
            vfy_values_free(&row->values);
    }
    char reported[1024] = "";
    if (status == SIM_OK && d->checks && d->checks->name) {
        fprintf(out, "   checks of every row (their operands, for the last row's scene):\n");
        for (const vfy_check_spec *k = d->checks; k->name; k++)
            dry_check(out, &run, row, k, reported, sizeof reported);
    }
    if (status == SIM_OK && d->case_checks && d->case_checks->name) {
        fprintf(out, "   checks of the case (over its rows):\n");
        for (const vfy_check_spec *k = d->case_checks; k->name; k++)
            dry_check(out, &run, row, k, reported, sizeof reported);
    }
    if (status == SIM_OK && d->after_rows)
        fprintf(out, "   and the case's own analysis after the rows (its checks read what the "
                "rows' results report)\n");
    const size_t rlen = strlen(reported);
    if (rlen > 0 && reported[rlen - 1] == ' ')
        reported[rlen - 1] = '\0';
    if (status == SIM_OK && !d->no_simulation)
        fprintf(out, "   the checks read directly: %s (a check whose quantity is not "
                "reported is a SKIP; what the case makes itself comes from the observables "
                "and steady quantities of docs/solver-protocol.md)\n",
                reported[0] ? reported + 1 : "nothing the result reports by name");
    vfy_values_free(&row->values);
    free(row);
    return status;
}

sim_status vfy_run_described(const vfy_case *c, const vfy_options *o, vfy_report *r, char *msg,
                             size_t msglen)
{
    if (o->dry_run != NULL)
        return dry_run_case(c, o, msg, msglen);
    const vfy_case_desc *d = c->desc;
    const vfy_sweep *s = o->size == VFY_PAPER ? &d->paper_rows : &d->quick_rows;
    vfy_case_run run = {.c = c, .d = d, .o = o};
    size_t rows = vfy_sweep_rows(s);
    char why[200];
    if (vfy_parse_columns(d->columns, &run.columns, &run.ncols, &run.column_text, why,
                          sizeof why) != 0) {
        free(run.columns);
        free(run.column_text);
        snprintf(msg, msglen, "%s: %s", c->name, why);
        return SIM_EINVAL;
    }
    const size_t ncols = run.ncols;
    const char **headers = malloc((ncols + 1) * sizeof *headers);
    run.rows = calloc(rows ? rows : 1, sizeof *run.rows);
    if (headers == NULL || run.rows == NULL) {
        free(headers);
        free(run.rows);
        free(run.columns);
        free(run.column_text);
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    for (size_t k = 0; k < ncols; k++)
        headers[k] = run.columns[k].header;
    vfy_table_init(&run.table, ncols, headers);
    sim_status status = SIM_OK;
    for (size_t i = 0; i < rows && status == SIM_OK; i++) {
        run.rows[i].index = i;
        run.rows[i].run = &run;
        run.nrows = i + 1;
        status = run_row(&run, s, &run.rows[i], r, msg, msglen);
    }
    if (status == SIM_OK && rows > 0)
        status = finish(&run, r, msg, msglen);
    for (size_t i = 0; i < run.nrows; i++) {
        vfy_refs_free(&run.rows[i].refs);
        sim_ensemble_result_free(&run.rows[i].res);
        for (size_t k = 0; run.rows[i].more && d->variants[k + 1]; k++)
            sim_ensemble_result_free(&run.rows[i].more[k]);
        free(run.rows[i].more);
        vfy_values_free(&run.rows[i].values);
    }
    vfy_values_free(&run.values);
    vfy_table_free(&run.table);
    vfy_table_free(&run.second);
    free(run.extra_mean);
    free(run.extra_ci);
    free(run.rows);
    free(run.columns);
    free(run.column_text);
    free(headers);
    return status;
}
