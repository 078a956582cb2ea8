#include "driver.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "case_report.h"
#include "figure.h"
#include "observe.h"
#include "references.h"
#include "scene_ini.h"
#include "solver.h"
#include "stats.h"
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
            char **names = realloc(vals->names, cap * sizeof *names);
            if (names == NULL)
                return -1;
            vals->names = names;
            double *grown = realloc(vals->v, cap * sizeof *grown);
            if (grown == NULL)
                return -1;
            vals->v = grown;
            vals->capacity = cap;
        }
        char *copy = vfy_strdup(name);
        if (copy == NULL)
            return -1;
        at = (long)vals->count++;
        vals->names[at] = copy;
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
    for (size_t i = 0; i < vals->count; i++)
        free(vals->names[i]);
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
    char buf[48];
    const char *text;
    for (size_t k = 0; (text = vfy_variant_text(d, k, buf, sizeof buf)) != NULL; k++) {
        size_t n = strcspn(text, ":");
        if (strlen(variant) == n && strncmp(text, variant, n) == 0)
            return (long)k;
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
    if (d->batches.count > 0)
        return d->batches.count;
    while (d->variants && d->variants[count])
        count++;
    return count ? count : 1;
}

const char *vfy_variant_text(const vfy_case_desc *d, size_t k, char *buf, size_t len)
{
    if (d->batches.count > 0) {
        if (k >= d->batches.count)
            return NULL;
        snprintf(buf, len, "b%zu: $batch=%zu", k + 1, k);
        return buf;
    }
    if (d->variants == NULL)
        return NULL;
    for (size_t i = 0; i < k; i++)
        if (d->variants[i] == NULL)
            return NULL;
    return d->variants[k];
}

/* Variant k of d ("NAME: SET;SET"): its name, *len characters at *name (0
 * for a case without variants); returns its settings, or NULL.  buf holds
 * a batch's text. */
static const char *variant_parts(const vfy_case_desc *d, size_t k, const char **name, int *len,
                                 char *buf, size_t buflen)
{
    *name = "";
    *len = 0;
    const char *text = vfy_variant_text(d, k, buf, buflen);
    if (text == NULL)
        return NULL;
    const char *colon = strchr(text, ':');
    *name = text;
    *len = (int)strcspn(text, ":");
    return colon ? colon + 1 : NULL;
}

/* "NAME@*": the mean over the variants of observable NAME. */
static int variants_mean(const vfy_row *row, const char *name, size_t len, double *mean,
                         double *ci)
{
    const size_t B = vfy_variant_count(row->run->d), M = row->res.outputs;
    double *m1 = malloc(2 * M * sizeof *m1);
    if (m1 == NULL)
        return -1;
    memset(mean, 0, M * sizeof *mean);
    if (ci != NULL)
        memset(ci, 0, M * sizeof *ci);
    int rc = 0;
    for (size_t k = 0; k < B && rc == 0; k++) {
        char buf[48];
        const char *v = vfy_variant_text(row->run->d, k, buf, sizeof buf);
        v = v ? v : "";
        char *one = vfy_aprintf("%.*s%s%.*s", (int)len, name, k ? "@" : "",
                                k ? (int)strcspn(v, ":") : 0, v);
        rc = one != NULL ? vfy_row_series(row, one, m1, m1 + M) : -1;
        free(one);
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

/* Whether the values hold every "NAME=NUMBER" / "NAME!=NUMBER" word of cond
 * (NULL: yes). */
static int values_hold(const vfy_values *v, const char *cond)
{
    for (const char *p = cond; p != NULL && *p != '\0';) {
        p += strspn(p, " ");
        const size_t len = strcspn(p, " ");
        if (len == 0)
            break;
        const char *eq = memchr(p, '=', len);
        if (eq == NULL)
            return 0;
        const int negate = eq > p && eq[-1] == '!';
        char name[64];
        snprintf(name, sizeof name, "%.*s", (int)(eq - p - negate), p);
        const int equal = vfy_values_get(v, name) == strtod(eq + 1, NULL);
        if (equal == negate)
            return 0;
        p += len;
    }
    return 1;
}

/* Whether rows a and b have equal values for every name in the space-
 * separated list (NaN equals nothing). */
static int values_match(const vfy_values *a, const vfy_values *b, const char *names)
{
    for (const char *p = names; p != NULL && *p != '\0';) {
        p += strspn(p, " ");
        const size_t len = strcspn(p, " ");
        if (len == 0)
            break;
        char name[64];
        snprintf(name, sizeof name, "%.*s", (int)len, p);
        if (vfy_values_get(a, name) != vfy_values_get(b, name))
            return 0;
        p += len;
    }
    return 1;
}

const vfy_row *vfy_row_partner(const vfy_case_run *run, const vfy_row *row, const char *name)
{
    const vfy_partner *p = run->d->partners;
    while (p != NULL && p->name != NULL && strcmp(p->name, name) != 0)
        p++;
    if (p == NULL || p->name == NULL || !values_hold(&row->values, p->when))
        return NULL;
    for (size_t i = 0; i < row->index; i++) {
        const vfy_values *w = &run->rows[i].values;
        if (values_hold(w, p->has) && values_match(w, &row->values, p->match))
            return &run->rows[i];
    }
    return NULL;
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
        return run->comment ? run->comment : "";
    for (size_t i = 0; i < run->ntexts; i++)
        if (strcmp(run->text_names[i], name) == 0)
            return run->texts[i];
    return NULL;
}

/* Set text `name` of a list of (names, texts), count of them: replaced, or
 * appended (the arrays grown by one).  Returns 0, or -1 when out of memory
 * (the list unchanged). */
static int set_text(char ***names, char ***texts, size_t *count, const char *name,
                    const char *text)
{
    size_t i = 0;
    while (i < *count && strcmp((*names)[i], name) != 0)
        i++;
    char *copy = vfy_strdup(text);
    if (copy == NULL)
        return -1;
    if (i < *count) {
        free((*texts)[i]);
        (*texts)[i] = copy;
        return 0;
    }
    char *key = vfy_strdup(name);
    char **n = key ? realloc(*names, (i + 1) * sizeof *n) : NULL;
    if (n != NULL)
        *names = n;
    char **t = n ? realloc(*texts, (i + 1) * sizeof *t) : NULL;
    if (t == NULL) {
        free(key);
        free(copy);
        return -1;
    }
    *texts = t;
    (*names)[i] = key;
    (*texts)[i] = copy;
    *count = i + 1;
    return 0;
}

/* Free a list of (names, texts). */
static void free_texts(char ***names, char ***texts, size_t *count)
{
    for (size_t i = 0; i < *count; i++) {
        free((*names)[i]);
        free((*texts)[i]);
    }
    free(*names);
    free(*texts);
    *names = *texts = NULL;
    *count = 0;
}

int vfy_run_set_text(vfy_case_run *run, const char *name, const char *text)
{
    return set_text(&run->text_names, &run->texts, &run->ntexts, name, text);
}

int vfy_run_second_notes(vfy_case_run *run, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    free(run->second_notes);
    run->second_notes = vfy_vaprintf(fmt, ap);
    va_end(ap);
    return run->second_notes != NULL ? 0 : -1;
}

/* The solver scene whose keys a name "SECTION.KEY" reads: the row's, or at
 * the case's level the first row's; NULL before the rows. */
static const sim_scene *keys_scene(const vfy_case_run *run, const vfy_row *row)
{
    if (row != NULL)
        return &row->solver;
    return run->rows != NULL && run->nrows > 0 ? &run->rows[0].solver : NULL;
}

/* Scene key `name` of the row (keys_scene) as a number (1) or a word (2), or
 * 0; besides the keys, "scene.step" (the time step the scheme takes, 0 for
 * the jump scheme) and "scene.output_interval" (t_end/(outputs - 1)). */
static int scene_key(const vfy_case_run *run, const vfy_row *row, const char *name, double *v,
                     const char **word)
{
    const sim_scene *s = strchr(name, '.') ? keys_scene(run, row) : NULL;
    if (s == NULL)
        return 0;
    if (strcmp(name, "scene.step") == 0) {
        *v = vfy_scene_step(s);
        return 1;
    }
    if (strcmp(name, "scene.output_interval") == 0) {
        *v = sim_scene_output_time(s, 1);
        return 1;
    }
    return vfy_scene_key_value(s, name, v, word);
}

static const char *row_string(const vfy_case_run *run, const vfy_row *row, const char *name)
{
    if (row != NULL && strcmp(name, "label") == 0)
        return row->label ? row->label : "";
    if (row != NULL && strcmp(name, "scene") == 0)
        return row->stem ? row->stem : "";
    const char *word;
    double v;
    if (scene_key(run, row, name, &v, &word) == 2)
        return word;
    return vfy_row_text(row, name);
}

static double lookup(const vfy_case_run *run, const vfy_row *row, const char *name)
{
    double v;
    const char *word;
    if (row != NULL && vfy_values_has(&row->values, name))
        return vfy_values_get(&row->values, name);
    if (scene_key(run, row, name, &v, &word) == 1)
        return v;
    return vfy_values_get(&run->values, name);
}

double vfy_value(const vfy_case_run *run, const vfy_row *row, const char *name)
{
    return lookup(run, row, name);
}

/* "{if:NAME=WORD:TEXT}": whether NAME's text (a row's or the case's, a word
 * key's) or number equals WORD. */
static int condition_holds(const vfy_case_run *run, const vfy_row *row, const char *cond,
                           size_t len)
{
    const char *eq = memchr(cond, '=', len);
    if (eq == NULL)
        return 0;
    char *name = vfy_aprintf("%.*s", (int)(eq - cond), cond);
    char *want = vfy_aprintf("%.*s", (int)(cond + len - eq - 1), eq + 1);
    int holds = 0;
    if (name != NULL && want != NULL) {
        const char *text = row_string(run, row, name);
        if (text == NULL)
            text = run_string(run, name);
        char *end;
        const double x = strtod(want, &end);
        holds = text != NULL ? strcmp(text, want) == 0
                             : end != want && *end == '\0' && lookup(run, row, name) == x;
    }
    free(name);
    free(want);
    return holds;
}

/* One "{...}" of a template (p at its '{', close at its '}') onto out. */
static int expand_one(vfy_text *out, const char *p, const char *close,
                      const vfy_case_run *run, const vfy_row *row)
{
    const int at_quick = strncmp(p + 1, "at_quick:", 9) == 0;
    const int at_engine = strncmp(p + 1, "at_engine:", 10) == 0;
    if (at_quick || strncmp(p + 1, "at_paper:", 9) == 0)   /* text at one size */
        return at_quick == (run->o->size == VFY_QUICK)
                   ? vfy_text_append(out, p + 10, (size_t)(close - p - 10))
                   : 0;
    if (at_engine || strncmp(p + 1, "at_solver:", 10) == 0)   /* text for one solver */
        return at_engine != vfy_external(run->o)
                   ? vfy_text_append(out, p + 11, (size_t)(close - p - 11))
                   : 0;
    if (strncmp(p + 1, "if:", 3) == 0) {   /* text on a condition */
        const char *cond = p + 4, *text = memchr(cond, ':', (size_t)(close - cond));
        return text != NULL && condition_holds(run, row, cond, (size_t)(text - cond))
                   ? vfy_text_append(out, text + 1, (size_t)(close - text - 1))
                   : 0;
    }
    const size_t n = (size_t)(close - p - 1);
    const char *colon = memchr(p + 1, ':', n);
    char *name = vfy_aprintf("%.*s", (int)(colon ? (size_t)(colon - p - 1) : n), p + 1);
    char *fmt = colon ? vfy_aprintf("%.*s", (int)(close - colon - 1), colon + 1) : NULL;
    if (name == NULL || (colon != NULL && fmt == NULL)) {
        free(name);
        free(fmt);
        return -1;
    }
    const char *s = row_string(run, row, name);
    if (s == NULL)
        s = run_string(run, name);
    const double v = lookup(run, row, name);
    int rc;
    if (s != NULL)
        rc = vfy_text_append(out, s, strlen(s));
    else if (isnan(v) && vfy_external(run->o))   /* the solver did not report it */
        rc = vfy_text_printf(out, "(not reported)");
    else if (fmt != NULL && fmt[0])
        rc = vfy_text_printf(out, fmt, v);
    else if (v == floor(v) && fabs(v) < 1e15)
        rc = vfy_text_printf(out, "%.0f", v);
    else
        rc = vfy_text_printf(out, "%g", v);
    free(name);
    free(fmt);
    return rc;
}

int vfy_expand_text(vfy_text *out, const char *tmpl, const vfy_case_run *run,
                    const vfy_row *row)
{
    int rc = vfy_text_append(out, "", 0);   /* "" even for an empty template */
    for (const char *p = tmpl; p && *p && rc == 0;) {
        const char *close = p[0] == '{' && p[1] != '{' ? strchr(p, '}') : NULL;
        if (close == NULL) {
            p += p[0] == '{' && p[1] == '{';   /* "{{" is one brace */
            rc = vfy_text_append(out, p++, 1);
            continue;
        }
        rc = expand_one(out, p, close, run, row);
        p = close + 1;
    }
    return rc;
}

char *vfy_expand_alloc(const char *tmpl, const vfy_case_run *run, const vfy_row *row)
{
    vfy_text t = {0};
    vfy_expand_text(&t, tmpl, run, row);
    return vfy_text_take(&t);
}

const char *vfy_expand(char *buf, size_t len, const char *tmpl, const vfy_case_run *run,
                       const vfy_row *row)
{
    vfy_text t = {0};
    vfy_expand_text(&t, tmpl, run, row);
    snprintf(buf, len, "%s", vfy_text_str(&t));
    vfy_text_free(&t);
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
                             M - c->from, vfy_zmax_ensembles(c->tol, row->res.ensembles), &z);
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

vfy_guard_result vfy_guard_paper_sizes(const vfy_case_run *run, const vfy_row *row,
                                       const vfy_guard *g)
{
    (void)row;
    (void)g;
    return run->o->size == VFY_PAPER ? VFY_JUDGE : VFY_GUARD_SKIP;
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

/* The i-th space-separated word of list: its length, and *word its start
 * (0 if there is none). */
static size_t nth_word(const char *list, size_t i, const char **word)
{
    for (const char *p = list; *p;) {
        while (isspace((unsigned char)*p))
            p++;
        size_t n = strcspn(p, " \t\n");
        if (n == 0)
            break;
        if (i-- == 0) {
            *word = p;
            return n;
        }
        p += n;
    }
    *word = list;
    return 0;
}

static size_t word_count(const char *list)
{
    size_t count = 0;
    const char *word;
    while (nth_word(list, count, &word) > 0)
        count++;
    return count;
}

/* Key k's value of row i of the sweep: its length, and *word its start. */
static size_t sweep_word(const vfy_sweep *s, size_t i, size_t k, const char **word)
{
    size_t at = i;
    if (s->grid) {
        size_t inner = 1;
        for (size_t j = k + 1; s->keys[j].key; j++)
            inner *= word_count(s->keys[j].values);
        at = (i / inner) % word_count(s->keys[k].values);
    }
    return nth_word(s->keys[k].values, at, word);
}

size_t vfy_sweep_rows(const vfy_sweep *s)
{
    if (s->rows != NULL) {
        size_t rows = 0;
        while (s->rows[rows])
            rows++;
        return rows;
    }
    size_t rows = s->keys && s->keys[0].key ? 1 : 0;
    for (size_t k = 0; s->keys && s->keys[k].key; k++) {
        size_t n = word_count(s->keys[k].values);
        rows = s->grid ? rows * n : (k == 0 || n < rows ? n : rows);
    }
    return rows;
}

void vfy_sweep_value(const vfy_sweep *s, size_t i, size_t k, char *buf, size_t len)
{
    const char *word;
    const size_t n = sweep_word(s, i, k, &word);
    snprintf(buf, len, "%.*s", (int)n, word);
}

static const char *sweep_name(const vfy_sweep *s, size_t k)
{
    if (s->keys[k].name)
        return s->keys[k].name;
    const char *dot = strrchr(s->keys[k].key, '.');
    return dot ? dot + 1 : s->keys[k].key;
}

/* ------------------------------------------------------------ one row */

/* A "$NAME=VALUE" setting (n characters at p): a value of the row, a number
 * if VALUE is one, else a text.  Returns 0, or -1 when out of memory. */
static int row_setting(vfy_row *row, const char *p, size_t n)
{
    size_t eq = strcspn(p, "=");
    if (eq >= n)
        return 0;
    char *name = vfy_aprintf("%.*s", (int)(eq - 1), p + 1);
    char *value = vfy_aprintf("%.*s", (int)(n - eq - 1), p + eq + 1), *end;
    int rc = -1;
    if (name != NULL && value != NULL) {
        double v = strtod(value, &end);
        rc = end != value && *end == '\0' ? vfy_values_set(&row->values, name, v)
                                          : vfy_row_set_text(row, name, value);
    }
    free(name);
    free(value);
    return rc;
}

int vfy_row_set_text(vfy_row *row, const char *name, const char *text)
{
    return set_text(&row->text_names, &row->texts, &row->ntexts, name, text);
}

const char *vfy_row_text(const vfy_row *row, const char *name)
{
    for (size_t i = 0; row != NULL && i < row->ntexts; i++)
        if (strcmp(row->text_names[i], name) == 0)
            return row->texts[i];
    return NULL;
}

void vfy_row_free(vfy_row *row)
{
    vfy_refs_free(&row->refs);
    sim_ensemble_result_free(&row->res);
    const size_t more = row->run != NULL ? vfy_variant_count(row->run->d) - 1 : 0;
    for (size_t k = 0; row->more && k < more; k++)
        sim_ensemble_result_free(&row->more[k]);
    free(row->more);
    row->more = NULL;
    vfy_values_free(&row->values);
    free_texts(&row->text_names, &row->texts, &row->ntexts);
    free(row->label);
    free(row->stem);
    row->label = row->stem = NULL;
}

/* A row's scene settings, as vfy_load_scene_sets takes them. */
typedef struct set_list {
    char **sets;   /* allocated, count of them */
    size_t count;
} set_list;

/* Append setting `set` (allocated; the list owns it, or frees it when out of
 * memory); 0, or -1. */
static int set_take(set_list *l, char *set)
{
    char **grown = set ? realloc(l->sets, (l->count + 1) * sizeof *grown) : NULL;
    if (grown == NULL) {
        free(set);
        return -1;
    }
    l->sets = grown;
    l->sets[l->count++] = set;
    return 0;
}

static void set_list_free(set_list *l)
{
    for (size_t i = 0; i < l->count; i++)
        free(l->sets[i]);
    free(l->sets);
    *l = (set_list){0};
}

/* The settings of "SET;SET;..." appended to l; a "scene=STEM" setting goes
 * to *stem instead (allocated, replacing it), a "$NAME=VALUE" one to the
 * row.  Returns 0, or -1 when out of memory. */
static int split_sets(const char *list, set_list *l, char **stem, vfy_row *row)
{
    int rc = 0;
    for (const char *p = list; p && *p && rc == 0;) {
        while (isspace((unsigned char)*p))
            p++;
        size_t n = strcspn(p, ";");
        if (n > 0 && strncmp(p, "scene=", 6) == 0) {
            free(*stem);
            rc = (*stem = vfy_aprintf("%.*s", (int)(n - 6), p + 6)) != NULL ? 0 : -1;
        } else if (n > 0 && p[0] == '$') {
            rc = row_setting(row, p, n);
        } else if (n > 0) {
            rc = set_take(l, vfy_aprintf("%.*s", (int)n, p));
        }
        p += n + (p[n] == ';');
    }
    return rc;
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

/* The row metric of d named `name`, or NULL. */
static const vfy_metric *derived_metric(const vfy_case_desc *d, const char *name)
{
    for (const vfy_metric *m = d->metrics; m != NULL && m->name != NULL; m++)
        if (strcmp(m->name, name) == 0)
            return m;
    return NULL;
}

/* A derived setting's value (vfy_case_desc.derived): the row metric named
 * `name`, before the run, else the value reference at the row's scene. */
static double derived_value(const vfy_case_run *run, const vfy_row *row, const char *name)
{
    const vfy_metric *m = derived_metric(run->d, name);
    return m != NULL ? m->fn(run, row, m) : vfy_reference_value(name, &row->scene);
}

/* One word of vfy_case_desc.derived, "KEY=NAME[:FORMAT]", copied into word:
 * split in place into the key (word itself), *name and *format (NULL
 * without one); 0, or -1 when it has no '=' or a format that is not
 * printf's. */
static int derived_split(char *word, char **name, char **format)
{
    char *eq = strchr(word, '=');
    if (eq == NULL)
        return -1;
    *eq = '\0';
    *name = eq + 1;
    char *colon = strchr(*name, ':');
    *format = colon != NULL ? colon + 1 : NULL;
    if (colon != NULL)
        *colon = '\0';
    return colon != NULL && colon[1] != '%' ? -1 : 0;
}

int vfy_derived_check(const vfy_case_desc *d, const char **bad, size_t *badlen)
{
    const char *words = d->derived != NULL ? d->derived : "";
    for (const char *w = words + strspn(words, " "); *w; w += strspn(w, " ")) {
        const size_t len = strcspn(w, " ");
        char word[200], *name, *format;
        snprintf(word, sizeof word, "%.*s", (int)len, w);
        const vfy_reference *ref = NULL;
        const int ok = len < sizeof word && derived_split(word, &name, &format) == 0
                       && vfy_scene_key_class(word) != VFY_KEY_UNKNOWN
                       && (derived_metric(d, name) != NULL
                           || ((ref = vfy_reference_find(name)) != NULL
                               && ref->kind == VFY_REF_VALUE));
        if (!ok) {
            *bad = w;
            *badlen = len;
            return 0;
        }
        w += len;
    }
    return 1;
}

/* The description's settings derived from value references or metrics
 * ("KEY=NAME[:FORMAT] ...", vfy_case_desc.derived) as "KEY=V;" appended to
 * *out, a NaN value's left out; 0, or -1 when out of memory. */
static int referenced_sets(const vfy_case_run *run, const char *words, const vfy_row *row,
                           vfy_text *out)
{
    int rc = 0;
    for (const char *p = words + strspn(words, " "); *p && rc == 0; p += strspn(p, " ")) {
        const size_t len = strcspn(p, " ");
        char *word = vfy_aprintf("%.*s", (int)len, p), *name, *format;
        if (word == NULL)
            rc = -1;
        else if (derived_split(word, &name, &format) == 0) {   /* else refused at load */
            const double v = derived_value(run, row, name);
            if (!isnan(v)) {
                char value[64];
                snprintf(value, sizeof value, format ? format : "%.17g", v);
                rc = vfy_text_printf(out, "%s=%s;", word, value);
            }
        }
        free(word);
        p += len;
    }
    return rc;
}

/* The description's derived settings for the row; NULL when out of memory. */
static char *derived_sets(const vfy_case_run *run, const vfy_row *row)
{
    vfy_text out = {0};
    if (referenced_sets(run, run->d->derived, row, &out) != 0) {
        vfy_text_free(&out);
        return NULL;
    }
    return vfy_text_take(&out);
}

/* The row's settings: the sweep's (its sets, an explicit row's label and
 * settings, each key's value) then `extra`'s; the scene's stem into *stem. */
static int sweep_sets(const vfy_sweep *s, vfy_row *row, const char *extra, set_list *l,
                      char **stem)
{
    int rc = split_sets(s->sets, l, stem, row);
    free(row->label);
    row->label = NULL;
    if (rc == 0 && s->rows != NULL) {
        const char *text = s->rows[row->index], *colon = strchr(text, ':');
        size_t n = colon ? (size_t)(colon - text) : 0;
        rc = (row->label = vfy_aprintf("%.*s", (int)n, text)) != NULL
                 ? split_sets(colon ? colon + 1 : text, l, stem, row)
                 : -1;
    }
    for (size_t k = 0; rc == 0 && s->keys && s->keys[k].key; k++) {
        const char *word;
        const size_t n = sweep_word(s, row->index, k, &word);
        char *value = vfy_aprintf("%.*s", (int)n, word);
        rc = value != NULL ? set_take(l, vfy_aprintf("%s=%s", s->keys[k].key, value)) : -1;
        if (rc == 0)
            rc = vfy_values_set(&row->values, sweep_name(s, k), strtod(value, NULL));
        free(value);
    }
    if (rc == 0 && row->label == NULL)
        rc = (row->label = vfy_strdup("")) != NULL ? 0 : -1;
    return rc == 0 ? split_sets(extra, l, stem, row) : rc;
}

/* The description's requirements on the row's scenes, the references' and
 * the solver's: SIM_OK, or SIM_EINVAL with "FILE: REQUIRE_WHY (needs WORD)"
 * in msg. */
static sim_status row_requirements(const vfy_case_run *run, const vfy_row *row, char *msg,
                                   size_t msglen)
{
    const sim_scene *scenes[] = {&row->scene, &row->solver};
    for (size_t i = 0; i < 2; i++) {
        char unmet[200];
        const int holds = vfy_scene_requires(scenes[i], run->d->require, unmet, sizeof unmet);
        if (holds == 1)
            continue;
        if (holds == 0)
            snprintf(msg, msglen, "%s: %s (needs %s)", scenes[i]->file, run->d->require_why,
                     unmet);
        else
            snprintf(msg, msglen, "case %s: %s", run->c->name, unmet);
        return SIM_EINVAL;
    }
    return SIM_OK;
}

/* Load row i's scenes: the sweep's settings, `extra` (a variant's, or
 * NULL), derived ones, then --set, then --solver-set. */
static sim_status row_scenes(vfy_case_run *run, const vfy_sweep *s, vfy_row *row,
                             const char *extra, char *msg, size_t msglen)
{
    set_list l = {0};
    char *stem = vfy_strdup(run->d->scene ? run->d->scene : run->c->name);
    char *derived = NULL;
    int rc = stem != NULL ? sweep_sets(s, row, extra, &l, &stem) : -1;
    free(row->stem);
    row->stem = rc == 0 ? vfy_strdup(stem) : NULL;
    sim_status status = rc == 0 && row->stem != NULL ? SIM_OK : SIM_ENOMEM;
    if (status == SIM_OK)
        status = vfy_load_scene_sets(stem, run->o, (const char *const *)l.sets, l.count,
                                     &row->scene, &row->solver, msg, msglen);
    if (status == SIM_OK && run->d->derived) {
        derived = derived_sets(run, row);
        if (derived == NULL || split_sets(derived, &l, &stem, row) != 0)
            status = SIM_ENOMEM;
        else if (derived[0])
            status = vfy_load_scene_sets(stem, run->o, (const char *const *)l.sets, l.count,
                                         &row->scene, &row->solver, msg, msglen);
    }
    if (status == SIM_ENOMEM)
        snprintf(msg, msglen, "out of memory");
    if (status == SIM_OK && run->d->batches.count > 0) {
        const double batch = vfy_values_get(&row->values, "batch");
        if (!isnan(batch))
            row->solver.seed = row->scene.seed
                               + run->d->batches.seed_stride * (row->index + 1) + (uint64_t)batch;
    }
    if (status == SIM_OK && run->d->require)
        status = row_requirements(run, row, msg, msglen);
    if (status == SIM_OK && run->d->jump_rows)
        status = vfy_adjust_jump_rows(row, &row->solver, msg, msglen);
    if (status == SIM_OK && run->d->adjust)
        status = run->d->adjust(row, &row->solver, msg, msglen);
    if (status == SIM_OK && run->d->observes)
        status = observe_only(run->d->observes, &row->solver, msg, msglen);
    free(derived);
    free(stem);
    set_list_free(&l);
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
        char *name = vfy_aprintf("%s%s", names[k], suffix);
        if (name != NULL)
            vfy_values_set(&row->values, name, v[k]);
        free(name);
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
        const char *variant;
        char vbuf[48];
        int vlen;
        const char *sets = variant_parts(d, k, &variant, &vlen, vbuf, sizeof vbuf);
        if (vlen > 0 && (status = row_scenes(run, s, row, sets, msg, msglen)) != SIM_OK)
            break;
        vfy_text label = {0};
        vfy_expand_text(&label, row_label_template(d), run, row);
        if (vlen > 0)
            vfy_text_printf(&label, " %.*s", vlen, variant);
        char *suffix = vfy_aprintf("%s%.*s", k > 0 && vlen > 0 ? "@" : "", k > 0 ? vlen : 0,
                                   variant);
        if (label.failed || suffix == NULL) {
            vfy_text_free(&label);
            free(suffix);
            snprintf(msg, msglen, "out of memory");
            return SIM_ENOMEM;
        }
        sim_ensemble_result *res = k == 0 ? &row->res : &row->more[k - 1];
        status = vfy_simulate(&row->solver, run->o, vfy_text_str(&label), res, msg, msglen);
        vfy_text_free(&label);
        if (status == SIM_EUNSUPPORTED && vfy_external(run->o)) {   /* an answer, not an error */
            if (row->refused[0] == '\0')
                snprintf(row->refused, sizeof row->refused, "%.*s%s%s", vlen, variant,
                         vlen > 0 ? ": " : "", msg);
            status = SIM_OK;
        }
        if (status == SIM_OK)
            row_cost_values(row, res, suffix);
        free(suffix);
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

/* Why a check of the whole case is not judged when row `no` was refused
 * (allocated), or NULL when out of memory. */
static char *needs_refused_row(const vfy_case_run *run, const vfy_row *no)
{
    char *label = vfy_expand_alloc(row_label_template(run->d), run, no);
    char *why = label != NULL ? vfy_aprintf("needs a row the solver refused (%s: %s)", label,
                                            no->refused)
                              : NULL;
    free(label);
    return why;
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

/* Record a SKIP with an allocated reason (NULL: out of memory), and free it. */
static void skip_with(vfy_report *r, const char *name, char *why)
{
    vfy_skip(r, name, why != NULL ? why : "out of memory");
    free(why);
}

/* The operand of check c an external solver's incomplete result left NaN
 * (row NULL: a check of the case), or NULL. */
static const char *gone_operand(const vfy_case_run *run, const vfy_row *row,
                                const vfy_check_spec *c)
{
    if (row != NULL)
        return operand_missing(run, row, c->value)      ? c->value
               : operand_missing(run, row, c->expected) ? c->expected
                                                        : NULL;
    return c->value && isnan(lookup(run, NULL, c->value))          ? c->value
           : c->expected && isnan(lookup(run, NULL, c->expected)) ? c->expected
                                                                  : NULL;
}

/* Why check c is not judged for want of operand `gone` (allocated). */
static char *gone_reason(const vfy_row *row, const char *gone, const char *refused)
{
    if (refused != NULL)
        return vfy_aprintf("%s: %s", gone, refused);
    if (reported_quantity(row, gone))
        return vfy_aprintf("%s not reported by the solver", gone);
    return vfy_aprintf("%s needs quantities the solver did not report", gone);
}

/* A known difference as r->differs says it: what the paper prints, and the
 * judging check by its name after the row's label (allocated). */
static char *differs_text(const vfy_case_run *run, const vfy_row *row, const vfy_difference *d)
{
    const char *by = d->judged_by, *prefix = row_label_template(run->d);
    if (strncmp(by, prefix, strlen(prefix)) == 0 && by[strlen(prefix)] == ' ')
        by += strlen(prefix) + 1;
    char *judge = vfy_expand_alloc(by, run, row);
    char *text = judge != NULL ? vfy_aprintf("%s; judged by \"%s\" (docs/differences.md)",
                                             d->paper, judge)
                               : NULL;
    free(judge);
    return text;
}

/* One check of run_checks: its guard, a row the solver refused (no, with
 * the reason `refused`), an operand an incomplete result left out, then
 * its rule. */
static void judge_check(vfy_case_run *run, vfy_row *row, const vfy_check_spec *c,
                        vfy_report *r, const vfy_row *no, const char *refused, int incomplete)
{
    const vfy_guard_result g = c->guard.fn ? c->guard.fn(run, row, &c->guard) : VFY_JUDGE;
    if (g == VFY_OMIT)
        return;
    char *expanded = vfy_expand_alloc(c->name, run, row);
    const char *name = expanded != NULL ? expanded : c->name;   /* no memory: the template */
    const char *gone = NULL;
    r->check_id = c->name;
    if (c->builtin_only && vfy_external(run->o))
        skip_with(r, name, vfy_aprintf("built-in engine only: %s", c->builtin_only));
    else if (row != NULL && no != NULL)   /* nothing of the row to judge */
        vfy_skip(r, name, refused);
    else if (incomplete && (gone = gone_operand(run, row, c)) != NULL)
        skip_with(r, name, gone_reason(row, gone, no != NULL ? refused : NULL));
    else if (g == VFY_GUARD_SKIP)
        skip_with(r, name, vfy_expand_alloc(c->guard.reason, run, row));
    else {
        char *differs = c->differs != NULL ? differs_text(run, row, c->differs) : NULL;
        if (c->differs != NULL)
            r->differs = differs != NULL ? differs : c->differs->paper;
        c->rule(r, name, run, row, c);
        r->differs = NULL;
        free(differs);
    }
    free(expanded);
}

/* The checks of a row, or of the case (row NULL).  On an
 * external solver's incomplete result, a NaN any rule meets is a SKIP. */
static void run_checks(vfy_case_run *run, vfy_row *row, const vfy_check_spec *checks,
                       vfy_report *r)
{
    const int incomplete =
        vfy_external(run->o) && (row != NULL ? row_incomplete(row) : run_incomplete(run));
    const char *const was = r->missing;
    const vfy_row *no = row != NULL ? (row->refused[0] ? row : NULL) : run_refused(run);
    char *refused = no == NULL  ? NULL
                    : row != NULL ? vfy_aprintf("solver refused: %s", row->refused)
                                  : needs_refused_row(run, no);   /* it may need that row */
    const char *why = no == NULL ? "" : refused != NULL ? refused : "out of memory";
    if (incomplete)
        r->missing = why[0] ? why : "needs quantities the solver did not report";
    char *label = row != NULL ? vfy_expand_alloc(row_label_template(run->d), run, row) : NULL;
    r->row = label != NULL ? label : "";
    for (const vfy_check_spec *c = checks; c && c->name; c++)
        judge_check(run, row, c, r, no, why, incomplete);
    r->missing = was;
    r->check_id = NULL;
    r->row = NULL;
    free(label);
    free(refused);
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
            const char *text = row_string(run, row, name);
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
    if (d->needs || (d->figures && d->figures[0].kind == VFY_FIGURE_CURVES
                     && d->figures[0].refs && d->figures[0].refs[0])) {
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
        char *line = vfy_expand_alloc(d->row_progress, run, row);
        fprintf(run->o->progress, "   %s\n", line != NULL ? line : d->row_progress);
        free(line);
    }
    return vfy_write_rows_so_far(run->o, run->c->name, &run->table, &row->solver, msg, msglen);
}

/* ------------------------------------------------------------ figure */

/* "LABEL=name" or "name": the label into *label (allocated; NULL when out
 * of memory), returns the name. */
static const char *label_and_name(const char *spec, char **label)
{
    const char *eq = strchr(spec, '=');
    *label = vfy_aprintf("%.*s", (int)(eq ? (size_t)(eq - spec) : strlen(spec)), spec);
    return eq ? eq + 1 : spec;
}

/* The length of a NULL-terminated list (NULL: 0). */
static size_t list_length(const char *const *list)
{
    size_t n = 0;
    while (list != NULL && list[n] != NULL)
        n++;
    return n;
}

/* Free count allocated strings and their array. */
static void free_strings(char **s, size_t count)
{
    for (size_t i = 0; s != NULL && i < count; i++)
        free(s[i]);
    free(s);
}

/* ------------------------------------------------------------ points figure */

/* A POINTS figure's groups (driver.h, group_by): each one's value and label
 * (allocated; with no group_by one group, value and label NULL). */
typedef struct points_groups {
    size_t count;
    char **value, **label;
} points_groups;

static void points_groups_free(points_groups *g)
{
    free_strings(g->value, g->count);
    free_strings(g->label, g->count);
    *g = (points_groups){0};
}

/* The row's value of group_by as a text (its text, else its number with
 * %g, else ""; of several names, their values joined by a space, "" when
 * one has none), allocated (NULL: out of memory). */
static char *group_value(const vfy_case_run *run, const vfy_row *row, const char *names)
{
    vfy_text out = {0};
    int none = 0;
    for (const char *p = names; *p && !none && !out.failed; p += strspn(p, " ")) {
        const size_t len = strcspn(p, " ");
        char *name = vfy_aprintf("%.*s", (int)len, p);
        const char *text = name ? vfy_row_text(row, name) : NULL;
        const double v = name ? lookup(run, row, name) : NAN;
        const char *sep = p == names ? "" : " ";
        if (name == NULL)
            out.failed = 1;
        else if (text != NULL)
            vfy_text_printf(&out, "%s%s", sep, text);
        else if (!(none = isnan(v)))
            vfy_text_printf(&out, "%s%g", sep, v);
        free(name);
        p += len;
    }
    char *value = vfy_text_take(&out);
    if (value != NULL && none)
        value[0] = '\0';
    return value;
}

/* Add group value (taken: freed on failure) labelled label (likewise). */
static int groups_add(points_groups *g, char *value, char *label)
{
    char **v = realloc(g->value, (g->count + 1) * sizeof *v);
    if (v != NULL)
        g->value = v;
    char **l = v != NULL ? realloc(g->label, (g->count + 1) * sizeof *l) : NULL;
    if (l != NULL)
        g->label = l;
    if (l == NULL || value == NULL || label == NULL) {
        free(value);
        free(label);
        return -1;
    }
    g->value[g->count] = value;
    g->label[g->count++] = label;
    return 0;
}

/* The index of value among the groups, or g->count. */
static size_t group_index(const points_groups *g, const char *value)
{
    size_t k = 0;
    while (k < g->count && strcmp(g->value[k], value) != 0)
        k++;
    return k;
}

/* The groups of figure f: its list, or the rows' values in order.
 * Returns 0, or -1 when out of memory. */
static int points_groups_make(const vfy_case_run *run, const vfy_figure_spec *f,
                              points_groups *g)
{
    *g = (points_groups){0};
    if (f->group_by == NULL)
        return groups_add(g, vfy_strdup(""), vfy_strdup(""));
    for (const char *const *k = f->groups; k != NULL && *k != NULL; k++) {
        char *label = NULL;
        const char *value = label_and_name(*k, &label);
        if (groups_add(g, vfy_strdup(value), label) != 0)
            return -1;
    }
    for (size_t i = 0; f->groups == NULL && i < run->nrows; i++) {
        char *value = group_value(run, &run->rows[i], f->group_by);
        if (value == NULL)
            return -1;
        if (*value == '\0' || group_index(g, value) < g->count)
            free(value);   /* none, or a group already found */
        else if (groups_add(g, value, vfy_strdup(value)) != 0)
            return -1;
    }
    return 0;
}

/* The group of a row (g->count: none of them). */
static size_t points_group_of(const vfy_case_run *run, const vfy_figure_spec *f,
                              const points_groups *g, const vfy_row *row)
{
    if (f->group_by == NULL)
        return 0;
    char *value = group_value(run, row, f->group_by);
    const size_t k = value != NULL ? group_index(g, value) : g->count;
    free(value);
    return k;
}

/* What a POINTS figure is drawn from: nseries quantities (names[j], the
 * values' names, label[j] and cinames[j] their "_ci"), ncurves references
 * (names[nseries + k], labels[nseries + k]), the groups, and the series
 * drawn: quantity j in group g is series j * groups + g, labelled slabel[]. */
typedef struct points_plan {
    size_t nseries, ncurves, nshown;
    const char **names;
    char **labels, **cinames, **slabel;
    int *pt, *lc;   /* per series shown (grouped figures), else NULL */
    points_groups g;
} points_plan;

/* The plan of figure f; returns 0, or -1 when out of memory. */
static int points_plan_make(const vfy_case_run *run, const vfy_figure_spec *f, points_plan *pl)
{
    static const int group_pt[] = {7, 6, 2, 5, 4, 9, 8, 3};   /* filled, open, cross, ... */
    /* the series' colours (figure.h's palette): blue, vermilion, reddish purple,
     * then bluish green before orange, which a fourth series would confuse with
     * the vermilion of the second */
    static const int series_lc[] = {1, 2, 3, 6, 5, 4, 7, 8};
    const size_t nseries = list_length(f->series), ncurves = list_length(f->refs);
    *pl = (points_plan){.nseries = nseries, .ncurves = ncurves};
    pl->names = calloc(nseries + ncurves + 1, sizeof *pl->names);
    pl->labels = calloc(nseries + ncurves + 1, sizeof *pl->labels);
    pl->cinames = calloc(nseries + 1, sizeof *pl->cinames);
    if (pl->names == NULL || pl->labels == NULL || pl->cinames == NULL
        || points_groups_make(run, f, &pl->g) != 0)
        return -1;
    for (size_t j = 0; j < nseries + ncurves; j++) {
        pl->names[j] = label_and_name(j < nseries ? f->series[j] : f->refs[j - nseries],
                                      &pl->labels[j]);
        if (pl->labels[j] == NULL)
            return -1;
        if (j < nseries && (pl->cinames[j] = vfy_aprintf("%s_ci", pl->names[j])) == NULL)
            return -1;
    }
    const size_t G = pl->g.count;
    const int grouped = f->group_by != NULL;
    pl->nshown = nseries * G;
    pl->slabel = calloc(pl->nshown + 1, sizeof *pl->slabel);
    pl->pt = grouped ? calloc(pl->nshown + 1, sizeof *pl->pt) : NULL;
    pl->lc = grouped ? calloc(pl->nshown + 1, sizeof *pl->lc) : NULL;
    if (pl->slabel == NULL || (grouped && (pl->pt == NULL || pl->lc == NULL)))
        return -1;
    for (size_t j = 0; j < nseries; j++)
        for (size_t g = 0; g < G; g++) {
            const size_t k = j * G + g;
            pl->slabel[k] = grouped ? vfy_aprintf("%s (%s)", pl->labels[j], pl->g.label[g])
                                    : vfy_strdup(pl->labels[j]);
            if (pl->slabel[k] == NULL)
                return -1;
            if (grouped) {
                pl->pt[k] = group_pt[g % (sizeof group_pt / sizeof group_pt[0])];
                pl->lc[k] = nseries == 1 ? 1 + (int)g
                                         : series_lc[j % (sizeof series_lc / sizeof *series_lc)];
            }
        }
    return 0;
}

static void points_plan_free(points_plan *pl)
{
    free(pl->names);
    free_strings(pl->labels, pl->nseries + pl->ncurves);
    free_strings(pl->cinames, pl->nseries);
    free_strings(pl->slabel, pl->nshown);
    free(pl->pt);
    free(pl->lc);
    points_groups_free(&pl->g);
}

/* VFY_FIGURE_POINTS (driver.h) by plan pl: buf holds x (a row each), the
 * shown series' y and ci (rows each) and the references on their fine
 * grid; arrays the shown series' y, their ci and the references' rows. */
static int write_points_with(vfy_case_run *run, const vfy_figure_spec *f, const points_plan *pl,
                             double *buf, const double **arrays, const char *name,
                             const char *title)
{
    enum { FINE = 81 };
    const size_t rows = run->nrows, S = pl->nshown, G = pl->g.count;
    size_t np = 0;
    double *x = buf, *y = x + rows, *ci = y + S * rows;
    double *xfine = ci + S * rows, *yfine = xfine + FINE;
    for (size_t i = 0; i < rows; i++) {
        const vfy_row *row = &run->rows[i];
        const size_t group = points_group_of(run, f, &pl->g, row);
        int finite = group < G;
        for (size_t j = 0; j < pl->nseries; j++) {
            const double v = lookup(run, row, pl->names[j]), c = lookup(run, row, pl->cinames[j]);
            for (size_t g = 0; g < G; g++) {
                y[(j * G + g) * rows + np] = g == group ? v : NAN;
                ci[(j * G + g) * rows + np] = g == group ? c : NAN;
            }
            finite &= isfinite(v);
        }
        x[np] = lookup(run, row, f->x);
        np += (size_t)finite;
    }
    sim_scene at = run->rows[rows - 1].scene;
    for (size_t k = 0; k < FINE; k++) {
        xfine[k] = f->x_lo + (f->x_hi - f->x_lo) * (double)k / (FINE - 1);
        at.collisions.restitution = xfine[k];
        for (size_t j = 0; j < pl->ncurves; j++)
            yfine[j * FINE + k] = vfy_reference_value(pl->names[pl->nseries + j], &at);
    }
    for (size_t j = 0; j < S; j++) {
        arrays[j] = y + j * rows;
        arrays[S + j] = ci + j * rows;
    }
    for (size_t j = 0; j < pl->ncurves; j++)
        arrays[2 * S + j] = yfine + j * FINE;
    const vfy_points points = {
        .name = name, .title = title, .xlabel = f->xlabel, .ylabel = f->ylabel, .npoints = np,
        .x = x, .nseries = S, .series = (const char *const *)pl->slabel, .y = arrays,
        .ci = arrays + S, .pt = pl->pt, .lc = pl->lc, .nfine = pl->ncurves ? FINE : 0,
        .xfine = xfine, .ncurves = pl->ncurves,
        .curves = (const char *const *)pl->labels + pl->nseries, .yfine = arrays + 2 * S,
        .comment = run->comment};
    return np > 0 ? vfy_write_points(run->o, &points) : 0;
}

/* VFY_FIGURE_POINTS (driver.h): as many series, references and groups as
 * the description makes. */
static int write_points(vfy_case_run *run, const vfy_figure_spec *f)
{
    enum { FINE = 81 };
    points_plan pl;
    int rc = points_plan_make(run, f, &pl);
    const size_t S = pl.nshown, ncurves = pl.ncurves;
    double *buf = rc == 0 ? malloc(((1 + 2 * S) * run->nrows + (1 + ncurves) * FINE) * sizeof *buf)
                          : NULL;
    const double **arrays = calloc(2 * S + ncurves + 1, sizeof *arrays);
    char *title = vfy_expand_alloc(f->title, run, NULL);
    char *name = vfy_aprintf("%s%s", run->c->name, f->suffix ? f->suffix : "");
    if (rc == 0 && buf && arrays && title && name)
        rc = write_points_with(run, f, &pl, buf, arrays, name, title);
    else
        rc = -1;
    points_plan_free(&pl);
    free(buf);
    free(arrays);
    free(title);
    free(name);
    return rc;
}

/* ------------------------------------------------------------ row figures */

int vfy_curve_alloc_panels(vfy_curve *out, size_t count, size_t p0, size_t p1, int ci)
{
    const size_t per = ci ? 2 : 1;
    *out = (vfy_curve){.count = count};
    out->x = malloc((1 + per * (p1 - p0 + 1)) * (count ? count : 1) * sizeof *out->x);
    if (out->x == NULL)
        return -1;
    for (size_t p = p0; p <= p1; p++) {
        out->y[p] = out->x + (1 + per * (p - p0)) * count;
        out->ci[p] = ci ? out->y[p] + count : NULL;
    }
    return 0;
}

int vfy_curve_alloc(vfy_curve *out, size_t count, int ci)
{
    return vfy_curve_alloc_panels(out, count, 0, 0, ci);
}

/* The curves a ROW_ figure draws, made: n of them, each with its label and
 * whether it is a reference. */
typedef struct row_plot {
    size_t n;
    vfy_curve *c;
    char **labels;
    int *ref;
} row_plot;

/* VFY_FIGURE_ROW_CURVES: the curves as lines, in the figure's panels. */
static int row_xy(vfy_case_run *run, const vfy_figure_spec *f, const char *name,
                  const char *title, const row_plot *pl)
{
    vfy_xy_curve *xy = calloc(pl->n ? pl->n : 1, sizeof *xy);
    if (xy == NULL)
        return -1;
    const size_t P = f->panels ? list_length(f->panels) : 1;
    for (size_t i = 0; i < pl->n; i++) {
        const vfy_curve *c = &pl->c[i];
        xy[i] = (vfy_xy_curve){.label = pl->labels[i], .reference = pl->ref[i],
                               .count = c->count, .x = c->x, .lc = c->lc, .dt = c->dt,
                               .band = !pl->ref[i] && f->band};
        for (size_t p = 0; p < P; p++) {
            xy[i].y[p] = c->y[p];
            xy[i].ci[p] = pl->ref[i] ? NULL : c->ci[p];
        }
    }
    vfy_xy_figure fig = {.name = name, .title = title, .xlabel = f->xlabel,
                         .comment = run->comment, .logx = f->logx, .logy = f->logy,
                         .npanels = P, .ylabel = {f->ylabel}, .ncurves = pl->n, .curves = xy};
    for (size_t p = 0; f->panels && p < P; p++)
        fig.ylabel[p] = f->panels[p];
    const int rc = vfy_write_xy(run->o, &fig);
    free(xy);
    return rc;
}

/* VFY_FIGURE_ROW_POINTS: the data curves as points on their shared x (with
 * no error bars when none has half-widths), the references as lines on
 * theirs (panel 0 each); -1 when they do not share it or out of memory. */
static int row_points(vfy_case_run *run, const vfy_figure_spec *f, const char *name,
                      const char *title, const row_plot *pl)
{
    const size_t n = pl->n;
    const double **arrays = calloc(3 * n + 1, sizeof *arrays);
    const char **names = calloc(2 * n + 1, sizeof *names);
    const vfy_curve *first = NULL, *first_ref = NULL;
    double *zero = NULL;   /* the half-widths of data without them */
    size_t S = 0, R = 0, with_ci = 0;
    int rc = arrays && names && n > 0 ? 0 : -1;
    for (size_t i = 0; i < n && rc == 0; i++) {
        const vfy_curve *c = &pl->c[i], **shared = pl->ref[i] ? &first_ref : &first;
        if (*shared == NULL)
            *shared = c;
        if (c->count != (*shared)->count)
            rc = -1;
        else if (pl->ref[i]) {
            arrays[2 * n + R] = c->y[0];
            names[n + R++] = pl->labels[i];
        } else {
            if (c->ci[0] == NULL && zero == NULL
                && (zero = calloc(c->count + 1, sizeof *zero)) == NULL)
                rc = -1;
            with_ci += c->ci[0] != NULL;
            arrays[S] = c->y[0];
            arrays[n + S] = c->ci[0] ? c->ci[0] : zero;
            names[S++] = pl->labels[i];
        }
    }
    if (rc == 0 && first == NULL)
        rc = -1;   /* every data curve was left out */
    if (rc == 0) {
        const vfy_points points = {
            .name = name, .title = title, .xlabel = f->xlabel, .ylabel = f->ylabel,
            .logx = f->logx, .logy = f->logy, .npoints = first->count, .x = first->x,
            .nseries = S, .series = names, .y = arrays, .ci = arrays + n,
            .bars = with_ci ? NULL : "", .nfine = first_ref ? first_ref->count : 0,
            .xfine = first_ref ? first_ref->x : NULL, .ncurves = R, .curves = names + n,
            .yfine = arrays + 2 * n, .comment = run->comment, .key_inside = f->key_inside};
        rc = vfy_write_points(run->o, &points);
    }
    free(zero);
    free(arrays);
    free(names);
    return rc;
}

/* A ROW_CURVES figure of row series (driver.h, row_label): every row a
 * curve against its series f->x, a panel per item of f->series. */
static int write_series_curves(vfy_case_run *run, const vfy_figure_spec *f, const char *title)
{
    const size_t P = list_length(f->series), rows = run->nrows;
    size_t width = 1, n = 0;
    for (size_t i = 0; i < rows; i++)
        width = run->rows[i].res.outputs > width ? run->rows[i].res.outputs : width;
    const size_t per_row = (2 * P + 2) * width;   /* x and its ci, then each panel's */
    vfy_xy_curve *curves = calloc(rows, sizeof *curves);
    char **labels = calloc(rows + P, sizeof *labels), **axes = labels + rows;
    double *buf = malloc(per_row * rows * sizeof *buf);
    char *name = vfy_aprintf("%s%s", run->c->name, f->suffix ? f->suffix : "");
    const char *series[VFY_XY_PANELS] = {NULL};
    vfy_xy_figure fig = {.name = name, .title = title, .xlabel = f->xlabel,
                         .comment = run->comment, .logx = f->logx, .logy = f->logy,
                         .npanels = P, .curves = curves};
    int rc = curves && labels && buf && name ? 0 : -1;
    for (size_t p = 0; p < P && rc == 0; p++) {   /* "AXIS LABEL=series" */
        series[p] = label_and_name(f->series[p], &axes[p]);
        fig.ylabel[p] = axes[p];
        rc = axes[p] ? 0 : -1;
    }
    for (size_t i = 0; i < rows && rc == 0; i++) {
        const vfy_row *row = &run->rows[i];
        double *x = buf + i * per_row, *y = x + 2 * width;
        if (vfy_row_series(row, f->x, x, x + width) != 0)
            continue;   /* a row without it is left out */
        vfy_xy_curve *c = &curves[n];
        *c = (vfy_xy_curve){.count = row->res.outputs, .x = x, .band = f->band};
        for (size_t p = 0; p < P; p++) {
            double *mean = y + 2 * p * width, *ci = mean + width;
            if (vfy_row_series(row, series[p], mean, ci) != 0)
                continue;   /* a panel without it */
            for (size_t k = 0; k < c->count; k++)
                ci[k] = fabs(ci[k]);
            c->y[p] = mean;
            c->ci[p] = ci;
        }
        rc = (labels[n] = vfy_expand_alloc(f->row_label, run, row)) ? 0 : -1;
        c->label = labels[n++];
    }
    fig.ncurves = n;
    if (rc == 0)
        rc = vfy_write_xy(run->o, &fig);
    free_strings(labels, rows + P);
    free(curves);
    free(buf);
    free(name);
    return rc;
}

/* Whether row is one figure f draws (driver.h, only). */
static int row_shown(const vfy_case_run *run, const vfy_figure_spec *f, const vfy_row *row)
{
    if (f->only == NULL)
        return 1;
    const char *eq = strchr(f->only, '=');
    char *name = vfy_aprintf("%.*s", (int)(eq ? eq - f->only : 0), f->only);
    char *value = name ? group_value(run, row, name) : NULL;
    const int shown = value != NULL && eq != NULL && strcmp(value, eq + 1) == 0;
    free(name);
    free(value);
    return shown;
}

/* Curve k of row (its label the template `label` at the row) into the
 * plot's next place, unless the row has none; 0, or -1 when out of
 * memory. */
static int row_plot_add(row_plot *pl, vfy_case_run *run, const vfy_row *row,
                        const vfy_figure_curve *k, const char *label)
{
    const size_t i = pl->n;
    const int made = k->fn(run, row, k->x, &pl->c[i]);
    if (made == 1)
        return 0;   /* left out */
    pl->n++;
    pl->ref[i] = k->reference;
    return made != 0 || (pl->labels[i] = vfy_expand_alloc(label, run, row)) == NULL ? -1 : 0;
}

/* A ROW_ figure of row (driver.h): its name the case's with the suffix
 * expanded at the row, its title (else the case's) too; with row_label,
 * each data curve once per row of the run that the figure shows, the
 * references of row. */
static int write_row_figure(vfy_case_run *run, const vfy_figure_spec *f, const vfy_row *row,
                            const char *case_title)
{
    size_t data = 0, refs = 0;
    for (const vfy_figure_curve *k = f->curves; k != NULL; k = k->next)
        *(k->reference ? &refs : &data) += 1;
    const size_t cap = (f->row_label ? data * run->nrows : data) + refs;
    row_plot pl = {.c = calloc(cap, sizeof *pl.c), .labels = calloc(cap, sizeof *pl.labels),
                   .ref = calloc(cap, sizeof *pl.ref)};
    char *suffix = vfy_expand_alloc(f->suffix ? f->suffix : "", run, row);
    char *name = suffix ? vfy_aprintf("%s%s", run->c->name, suffix) : NULL;
    char *title = f->title ? vfy_expand_alloc(f->title, run, row) : vfy_strdup(case_title);
    int rc = pl.c && pl.labels && pl.ref && name && title ? 0 : -1;
    for (size_t i = 0; f->row_label && i < run->nrows && rc == 0; i++)   /* over rows */
        for (const vfy_figure_curve *k = f->curves; k != NULL && rc == 0; k = k->next)
            if (!k->reference && row_shown(run, f, &run->rows[i]))
                rc = row_plot_add(&pl, run, &run->rows[i], k, f->row_label);
    for (const vfy_figure_curve *k = f->curves; k != NULL && rc == 0; k = k->next)
        if (k->reference || !f->row_label)
            rc = row_plot_add(&pl, run, row, k, k->label);
    if (rc == 0)
        rc = f->kind == VFY_FIGURE_ROW_CURVES ? row_xy(run, f, name, title, &pl)
                                              : row_points(run, f, name, title, &pl);
    for (size_t i = 0; pl.c != NULL && i < pl.n; i++)
        free(pl.c[i].x);
    free_strings(pl.labels, pl.n);
    free(pl.c);
    free(pl.ref);
    free(suffix);
    free(name);
    free(title);
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
 * spans two decades or more.  labels[] (ncurves) are filled here. */
static int curves_by_row_with(vfy_case_run *run, const vfy_figure_spec *f, const char *name,
                              const char *title, const char *quantity, size_t nref,
                              vfy_xy_curve *curves, char **labels, double *buf)
{
    double *at = buf;
    size_t c = 0;
    for (size_t i = 0; i < run->nrows; i++) {
        const vfy_row *row = &run->rows[i];
        const size_t M = row->res.outputs;
        char *label = vfy_expand_alloc(row_label_template(run->d), run, row);
        for (size_t j = 0; j <= nref; j++, c++) {
            double *mean = at, *ci = j == 0 ? at + M : NULL;
            at += j == 0 ? 2 * M : M;
            if (vfy_row_series(row, j == 0 ? f->quantity : f->refs[j - 1], mean, ci) != 0)
                for (size_t m = 0; m < M; m++)   /* no such series: no points */
                    mean[m] = NAN;
            labels[c] = vfy_aprintf("%s%s%s", label ? label : "", j ? ": " : "",
                                    j ? f->refs[j - 1] : "");
            /* gnuplot's 8 colours in turn, each round of them dashed anew */
            curves[c] = (vfy_xy_curve){.label = labels[c] ? labels[c] : "", .reference = j > 0,
                                       .count = M, .x = row->res.t, .y = {mean}, .ci = {ci},
                                       .dt = j > 0 ? 0 : 1 + (int)(c / 8)};
        }
        free(label);
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
                              .ylabel = {quantity}, .yaxis = {f->ylabel}, .ncurves = c,
                              .curves = curves};
    return vfy_write_xy(run->o, &xy);
}

static int write_curves_by_row(vfy_case_run *run, const vfy_figure_spec *f, const char *name,
                               const char *title, const char *quantity)
{
    const size_t nref = list_length(f->refs);
    size_t total = 0;
    for (size_t i = 0; i < run->nrows; i++)
        total += run->rows[i].res.outputs;
    const size_t ncurves = run->nrows * (1 + nref);
    vfy_xy_curve *curves = calloc(ncurves, sizeof *curves);
    char **labels = calloc(ncurves, sizeof *labels);
    double *buf = malloc((2 + nref) * total * sizeof *buf);
    int rc = -1;
    if (curves != NULL && labels != NULL && buf != NULL)
        rc = curves_by_row_with(run, f, name, title, quantity, nref, curves, labels, buf);
    free(curves);
    free_strings(labels, ncurves);
    free(buf);
    return rc;
}

/* A curves figure over rows that share their output times (vfy_write_curves). */
static int curves_shared(vfy_case_run *run, const vfy_figure_spec *f, const char *name,
                         const char *title, const char *quantity)
{
    const vfy_row *last = &run->rows[run->nrows - 1];
    if (f->extrapolated && run->extra_mean == NULL
        && vfy_run_extrapolate(run, f->quantity, NULL) != 0)
        return -1;
    const int extra = f->extrapolated && run->extra_mean != NULL;
    const size_t M = last->res.outputs, rows = run->nrows + (size_t)extra;
    const size_t nref = list_length(f->refs);
    double *buf = malloc((2 * rows + nref) * M * sizeof *buf);
    size_t *n = malloc(rows * sizeof *n);
    const double **refs = malloc((nref + 1) * sizeof *refs);
    int rc = -1;
    if (buf != NULL && n != NULL && refs != NULL) {
        double *mean = buf, *ci = buf + rows * M, *ref = buf + 2 * rows * M;
        for (size_t j = 0; j < nref; j++) {
            vfy_row_series(last, f->refs[j], ref + j * M, NULL);
            refs[j] = ref + j * M;
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
                              f->refs, refs, rows, n, NULL, mean, ci, quantity, f->ylabel,
                              f->x_from, f->panel_per_row);
    }
    free(buf);
    free(n);
    free(refs);
    return rc;
}

static int write_figure(vfy_case_run *run, const vfy_figure_spec *f, const char *title)
{
    if (f->kind == VFY_FIGURE_POINTS)
        return write_points(run, f);
    if (f->kind == VFY_FIGURE_ROW_CURVES && f->row_label != NULL && f->curves == NULL) {
        char *own = f->title ? vfy_expand_alloc(f->title, run, NULL) : vfy_strdup(title);
        const int rc = own != NULL ? write_series_curves(run, f, own) : -1;
        free(own);
        return rc;
    }
    if (f->kind == VFY_FIGURE_ROW_CURVES || f->kind == VFY_FIGURE_ROW_POINTS) {
        int rc = 0;
        size_t last = run->nrows;   /* the last row shown: none yet */
        for (size_t i = 0; i < run->nrows && rc == 0; i++)
            if (row_shown(run, f, &run->rows[i])) {
                last = i;
                if (f->each_row)   /* each row's figure */
                    rc = write_row_figure(run, f, &run->rows[i], title);
            }
        if (!f->each_row && last < run->nrows && rc == 0)   /* the last shown row's */
            rc = write_row_figure(run, f, &run->rows[last], title);
        return rc;
    }
    char *name = vfy_aprintf("%s%s", run->c->name, f->suffix ? f->suffix : "");
    char *quantity = vfy_aprintf(   /* "T@*" is drawn as T */
        "%.*s", (int)(strstr(f->quantity, "@*") ? strcspn(f->quantity, "@") : strlen(f->quantity)),
        f->quantity);
    char *own = f->title ? vfy_expand_alloc(f->title, run, NULL) : NULL;   /* else the case's */
    int rc = -1;
    if (name != NULL && quantity != NULL && (own != NULL || f->title == NULL))
        rc = rows_share_grid(run) ? curves_shared(run, f, name, own ? own : title, quantity)
                                  : write_curves_by_row(run, f, name, own ? own : title, quantity);
    free(name);
    free(quantity);
    free(own);
    return rc;
}

/* ------------------------------------------------------------ provenance */

/* A row's field of the provenance, allocated (NULL: out of memory). */
typedef char *(*row_field_fn)(const vfy_row *row);

static char *field_scene(const vfy_row *row)
{
    return vfy_strdup(vfy_display_path(row->solver.file));
}
static char *field_seed(const vfy_row *row)
{
    return vfy_aprintf("%llu", (unsigned long long)row->solver.seed);
}
static char *field_n(const vfy_row *row) { return vfy_aprintf("%zu", row->solver.particles.n); }
static char *field_ensembles(const vfy_row *row)
{
    return vfy_aprintf("%zu", row->solver.particles.ensembles);
}
static char *field_outputs(const vfy_row *row)
{
    return vfy_aprintf("%zu outputs on [0, %g]", row->solver.outputs, row->solver.t_end);
}

/* Append "LABEL v" when every row has the same value, else "LABEL v1, v2,
 * ... (by row)", each followed by unit. */
static void append_field(const vfy_case_run *run, vfy_text *t, const char *label,
                         row_field_fn field, const char *unit)
{
    char *first = field(&run->rows[0]);
    int same = 1;
    for (size_t i = 1; i < run->nrows && same; i++) {
        char *v = field(&run->rows[i]);
        same = v != NULL && first != NULL && strcmp(v, first) == 0;
        free(v);
    }
    vfy_text_printf(t, "%s%s", label, first ? first : "");
    for (size_t i = 1; i < run->nrows && !same; i++) {
        char *v = field(&run->rows[i]);
        vfy_text_printf(t, ", %s", v ? v : "");
        free(v);
    }
    vfy_text_printf(t, "%s%s", unit, same ? "" : " (by row)");
    free(first);
}

/* The provenance line of the tables and figures ({comment}): each row's own
 * scene file, seed, n, N and output times, said once where the rows share
 * them.  0, or -1 when out of memory. */
static int run_provenance(vfy_case_run *run)
{
    vfy_text t = {0};
    vfy_text_printf(&t, "gdsmc %s verify: ", GDSMC_VERSION);
    append_field(run, &t, "scene ", field_scene, "");
    append_field(run, &t, ", seed ", field_seed, "");
    append_field(run, &t, ", n = ", field_n, "");
    append_field(run, &t, ", N = ", field_ensembles, " ensembles");
    append_field(run, &t, ", ", field_outputs, "");
    if (vfy_external(run->o))   /* the command, and what the solver said it is */
        vfy_text_printf(&t, "; solver '%s'%s%s%s", run->o->solver->command,
                        run->o->solver->line[0] ? " (" : "", run->o->solver->line,
                        run->o->solver->line[0] ? ")" : "");
    free(run->comment);
    run->comment = vfy_text_take(&t);
    return run->comment != NULL ? 0 : -1;
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
    /* the first row's ensembles, the degrees of freedom and Student's t quantile of
       the half-widths _ci_t (the notes of cases whose rows share N) */
    const double N = (double)run->rows[0].solver.particles.ensembles;
    vfy_values_set(&run->values, "N", N);
    vfy_values_set(&run->values, "N_dof", N - 1.0);
    vfy_values_set(&run->values, "t_quantile",
                   N >= 2.0 ? vfy_student_t(VFY_STUDENT_P, N - 1.0) : NAN);
    if (run_provenance(run) != 0) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    /* the hook's own checks on what an incomplete external result left NaN */
    const vfy_row *no = run_refused(run);
    char *refused = no != NULL ? needs_refused_row(run, no) : NULL;
    if (vfy_external(run->o) && run_incomplete(run))
        r->missing = no == NULL          ? "needs quantities the solver did not report"
                     : refused != NULL ? refused
                                       : "out of memory";
    for (const vfy_metric *m = d->case_metrics; m != NULL && m->name != NULL; m++)
        if (vfy_values_set(&run->values, m->name, m->fn(run, NULL, m)) != 0) {
            free(refused);
            snprintf(msg, msglen, "out of memory");
            return SIM_ENOMEM;
        }
    sim_status status = d->after_rows ? d->after_rows(run, r, msg, msglen) : SIM_OK;
    r->missing = NULL;
    free(refused);
    if (status != SIM_OK)
        return status;
    if (d->case_progress && run->o->progress) {
        char *line = vfy_expand_alloc(d->case_progress, run, NULL);
        fprintf(run->o->progress, "   %s\n", line != NULL ? line : d->case_progress);
        free(line);
    }
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
    char *title = vfy_expand_alloc(d->title, run, NULL);
    char *notes = vfy_expand_alloc(d->notes, run, NULL);
    if (title == NULL || notes == NULL) {
        free(title);
        free(notes);
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    status = vfy_write_case_tables(run->o, run->c->name, &run->table, run->comment, title,
                                    notes, run->second.ncols ? &run->second : NULL,
                                    run->second_suffix, run->second_title, run->second_notes,
                                    msg, msglen);
    free(notes);
    for (const vfy_figure_spec *f = d->figures; f && f->kind != VFY_FIGURE_NONE
                                                && status == SIM_OK;
         f++)
        if (write_figure(run, f, title) != 0)
            status = vfy_io_error(run->c->name, msg, msglen);
    free(title);
    return status;
}

/* ------------------------------------------------------------ dry run */

/* What a check operand `name` is, for the row's solver scene: a quantity
 * the result file reports, or what the case makes from it (--dry-run). */
static const char *base_kind(const vfy_case_run *run, const vfy_row *row, char *base)
{
    const vfy_case_desc *d = run->d;
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

static const char *operand_kind(const vfy_case_run *run, const vfy_row *row, const char *name)
{
    char *base = vfy_aprintf("%.*s", (int)strcspn(name, "@"), name);   /* without @VARIANT */
    const char *kind = base != NULL ? base_kind(run, row, base) : "(out of memory)";
    free(base);
    return kind;
}

/* Add name (without "@VARIANT") to the list `reported` (" a b ") once,
 * when the result file reports it. */
static void note_reported(const vfy_case_run *run, const vfy_row *row, const char *name,
                          vfy_text *reported)
{
    char *word = vfy_aprintf(" %.*s ", (int)strcspn(name, "@"), name);
    if (word != NULL && strncmp(operand_kind(run, row, name), "reported", 8) == 0
        && strstr(vfy_text_str(reported), word) == NULL)   /* one space between */
        vfy_text_printf(reported, "%s", word + (reported->len > 0));
    free(word);
}

/* One check's operands and what each is; the reported ones noted. */
static void dry_check(FILE *out, const vfy_case_run *run, const vfy_row *row,
                      const vfy_check_spec *c, vfy_text *reported)
{
    fprintf(out, "     %s\n", c->name);
    const char *const ops[] = {c->value, c->expected, c->plus, c->plus_quick};
    static const char *const role[] = {"value", "against", "plus", "plus (quick)"};
    for (size_t k = 0; k < sizeof ops / sizeof *ops; k++)
        if (ops[k] != NULL) {
            fprintf(out, "       %-13s %-22s %s\n", role[k], ops[k],
                    operand_kind(run, row, ops[k]));
            note_reported(run, row, ops[k], reported);
        }
    for (const vfy_metric *m = run->d->metrics; m && m->name; m++) {
        if (c->value == NULL || strcmp(m->name, c->value) != 0)
            continue;
        const char *const from[] = {m->a, m->b};   /* a metric's named operands */
        for (size_t k = 0; k < 2; k++)
            if (from[k] != NULL) {
                fprintf(out, "       %-13s %-22s %s\n", "  made from", from[k],
                        operand_kind(run, row, from[k]));
                note_reported(run, row, from[k], reported);
            }
    }
}

/* --dry-run: row i's scene for variant k, written to dir/row-NN[@VARIANT].ini,
 * and its line on out. */
static sim_status dry_row(FILE *out, vfy_case_run *run, const vfy_sweep *s, vfy_row *row,
                          size_t k, const char *dir, char *msg, size_t msglen)
{
    const char *variant;
    char vbuf[48];
    int vlen;
    const char *sets = variant_parts(run->d, k, &variant, &vlen, vbuf, sizeof vbuf);
    sim_status status = row_scenes(run, s, row, sets, msg, msglen);
    if (status != SIM_OK)
        return status;
    vfy_values_set(&row->values, "index", (double)row->index);
    vfy_values_set(&row->values, "n", (double)row->solver.particles.n);
    char *path = vfy_aprintf("%s/row-%02zu%s%.*s.ini", dir, row->index + 1, vlen ? "@" : "",
                             vlen, variant);
    char *label = vfy_expand_alloc(row_label_template(run->d), run, row);
    if (path == NULL || label == NULL) {
        snprintf(msg, msglen, "out of memory");
        status = SIM_ENOMEM;
    } else {
        FILE *f = fopen(path, "w");
        const int written = f != NULL && vfy_scene_write(f, &row->solver) == 0;
        if (f == NULL || fclose(f) != 0 || !written) {
            snprintf(msg, msglen, "%s: cannot write: %s", path, strerror(errno));
            status = SIM_EIO;
        } else {
            fprintf(out, "   row %zu%s%.*s: %s -> %s\n", row->index + 1,
                    vlen ? " variant " : "", vlen, variant, label, path);
        }
    }
    free(path);
    free(label);
    return status;
}

/* --dry-run: what the checks read, and which of it the result reports. */
static void dry_checks(FILE *out, const vfy_case_run *run, const vfy_row *row)
{
    const vfy_case_desc *d = run->d;
    vfy_text reported = {0};
    if (d->checks && d->checks->name) {
        fprintf(out, "   checks of every row (their operands, for the last row's scene):\n");
        for (const vfy_check_spec *k = d->checks; k->name; k++)
            dry_check(out, run, row, k, &reported);
    }
    if (d->case_checks && d->case_checks->name) {
        fprintf(out, "   checks of the case (over its rows):\n");
        for (const vfy_check_spec *k = d->case_checks; k->name; k++)
            dry_check(out, run, row, k, &reported);
    }
    if (d->after_rows)
        fprintf(out, "   and the case's own analysis after the rows (its checks read what the "
                "rows' results report)\n");
    if (reported.len > 0 && reported.s[reported.len - 1] == ' ')
        reported.s[--reported.len] = '\0';
    if (!d->no_simulation)
        fprintf(out, "   the checks read directly: %s (a check whose quantity is not "
                "reported is a SKIP; what the case makes itself comes from the observables "
                "and steady quantities of docs/solver-protocol.md)\n",
                reported.len > 0 ? reported.s + 1 : "nothing the result reports by name");
    vfy_text_free(&reported);
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
    char *dir = vfy_aprintf("%s/%s", o->out_dir, c->name);
    if (row == NULL || dir == NULL || vfy_ensure_dir(dir) != 0) {
        snprintf(msg, msglen, "%s: cannot create: %s", dir ? dir : c->name,
                 dir ? strerror(errno) : "out of memory");
        free(row);
        free(dir);
        return dir ? SIM_EIO : SIM_ENOMEM;
    }
    FILE *out = o->dry_run;
    const size_t nvariants = vfy_variant_count(d);
    fprintf(out, "== %s (%s sizes): %zu rows%s, the scenes in %s/\n", c->name,
            o->size == VFY_QUICK ? "quick" : "paper", rows,
            d->no_simulation ? " (references only: nothing to simulate)" : "", dir);
    sim_status status = SIM_OK;
    run.rows = row;
    for (size_t i = 0; i < rows && status == SIM_OK && !d->no_simulation; i++) {
        if (i > 0)
            vfy_row_free(row);   /* the last row's stays, for the checks */
        *row = (vfy_row){.index = i, .run = &run};
        run.nrows = 1;
        for (size_t k = 0; k < nvariants && status == SIM_OK; k++)
            status = dry_row(out, &run, s, row, k, dir, msg, msglen);
    }
    if (status == SIM_OK)
        dry_checks(out, &run, row);
    vfy_row_free(row);
    free(row);
    free(dir);
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
    for (size_t i = 0; i < run.nrows; i++)
        vfy_row_free(&run.rows[i]);
    vfy_run_free(&run);
    free(run.rows);
    free(headers);
    return status;
}

void vfy_run_free(vfy_case_run *run)
{
    vfy_values_free(&run->values);
    free_texts(&run->text_names, &run->texts, &run->ntexts);
    vfy_table_free(&run->table);
    vfy_table_free(&run->second);
    free(run->comment);
    free(run->second_notes);
    free(run->extra_mean);
    free(run->extra_ci);
    free(run->columns);
    free(run->column_text);
    run->comment = run->second_notes = NULL;
    run->extra_mean = run->extra_ci = NULL;
    run->columns = NULL;
    run->column_text = NULL;
}
