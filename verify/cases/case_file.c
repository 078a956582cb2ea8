/* Case files -> vfy_case_desc (case_file.h), with inih.
 *
 * Design.  Each section kind has a table of its keys (name, type, the
 * member's offset in the record the section fills); one function applies a
 * key of any table.  Records that repeat (metrics, checks, figures, ...)
 * are allocated one by one while the file is read, so that a pointer into
 * one stays valid, and copied into the description's arrays at the end.
 *
 * As in scene_ini.c, inih reads through our own reader, which hands it one
 * line per call and counts them, so that the handler knows the line of its
 * key.  The reader also tells the handler whether the line continues the
 * previous value (an indented line after a key) and whether a section
 * header came since its last call (each [check] and [figure] header starts a
 * record of its own, though inih passes the same section name).  It also
 * reads an "[include NAME]" line's file in its place (a stack of sources),
 * and notes where each line it hands on came from (origins), so that every
 * message names the file, included or not, and its line.
 *
 * Every allocation is recorded in the file's block list and freed with it.
 */
#include "case_file.h"

#include <ctype.h>
#include <errno.h>
#include <ini.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "figure.h"
#include "text.h"

#define MAX_FILE_BYTES (1u << 20)
#define MAX_INCLUDE_DEPTH 8

struct vfy_case_file {
    vfy_case c;
    vfy_case_desc d;
    void **blocks;   /* everything c and d point into */
    size_t nblocks, capblocks;
};

/* ------------------------------------------------------------ memory */

/* A zeroed block of size bytes owned by f, or NULL when out of memory. */
static void *own(vfy_case_file *f, size_t size)
{
    if (f->nblocks == f->capblocks) {
        size_t cap = f->capblocks ? 2 * f->capblocks : 64;
        void **grown = realloc(f->blocks, cap * sizeof *grown);
        if (grown == NULL)
            return NULL;
        f->blocks = grown;
        f->capblocks = cap;
    }
    void *p = calloc(1, size ? size : 1);
    if (p != NULL)
        f->blocks[f->nblocks++] = p;
    return p;
}

static char *own_strndup(vfy_case_file *f, const char *s, size_t n)
{
    char *p = own(f, n + 1);
    if (p != NULL)
        memcpy(p, s, n);
    return p;
}

void vfy_case_file_free(vfy_case_file *f)
{
    if (f == NULL)
        return;
    for (size_t i = 0; i < f->nblocks; i++)
        free(f->blocks[i]);
    free(f->blocks);
    free(f);
}

const vfy_case *vfy_case_file_case(const vfy_case_file *f) { return &f->c; }

/* A growing list of pointers, each with where it came from (an index of
 * parse_ctx.origins). */
typedef struct ptr_list {
    void **v;
    int *lines;
    size_t n, cap;
} ptr_list;

static int list_push(ptr_list *l, void *p, int line)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 8;
        void **v = realloc(l->v, cap * sizeof *v);
        if (v == NULL)
            return -1;
        l->v = v;
        int *lines = realloc(l->lines, cap * sizeof *lines);
        if (lines == NULL)
            return -1;
        l->lines = lines;
        l->cap = cap;
    }
    l->v[l->n] = p;
    l->lines[l->n++] = line;
    return 0;
}

static void list_free(ptr_list *l)
{
    free(l->v);
    free(l->lines);
    memset(l, 0, sizeof *l);
}

/* ------------------------------------------------------------ keys */

typedef enum key_type {
    K_TEXT,      /* const char *: text, may continue on indented lines */
    K_NUMBER,    /* double: a number or a tolerance by name */
    K_COUNT,     /* size_t */
    K_BOOL,      /* int: true or false */
    K_WORDS,     /* const char *const *: words separated by spaces */
    K_LIST,      /* const char *const *: one item per occurrence of the key */
    K_FN,        /* a function pointer of kind fn */
    K_BATCHES,   /* vfy_batches: COUNT STRIDE */
    K_DIFFERS,   /* const char * of the record's vfy_difference */
    K_KIND,      /* vfy_figure_kind: curves, points, row curves or row points */
    K_CURVE,     /* a vfy_figure_curve appended to the list: LABEL=FUNCTION, one
                    per occurrence (ref_curve: a reference) */
} key_type;

typedef struct key_spec {
    const char *key;
    key_type type;
    size_t offset;
    vfy_fn_kind fn;
} key_spec;

#define CASE_KEY(K, T, MEMBER) {K, T, offsetof(vfy_case_file, MEMBER), 0}
static const key_spec case_keys[] = {
    CASE_KEY("suite", K_TEXT, c.suite),
    CASE_KEY("summary", K_TEXT, c.summary),
    CASE_KEY("quick", K_BOOL, c.quick),
    CASE_KEY("scene", K_TEXT, d.scene),
    CASE_KEY("paper", K_TEXT, d.paper),
    CASE_KEY("needs", K_WORDS, d.needs),
    CASE_KEY("needs_why", K_TEXT, d.needs_why),
    CASE_KEY("label", K_TEXT, d.label),
    CASE_KEY("variant", K_LIST, d.variants),
    CASE_KEY("batches", K_BATCHES, d.batches),
    CASE_KEY("row_progress", K_TEXT, d.row_progress),
    CASE_KEY("derived", K_TEXT, d.derived),
    CASE_KEY("require", K_TEXT, d.require),
    CASE_KEY("require_why", K_TEXT, d.require_why),
    CASE_KEY("jump_rows", K_BOOL, d.jump_rows),
    {"adjust", K_FN, offsetof(vfy_case_file, d.adjust), VFY_FN_ADJUST},
    CASE_KEY("values", K_WORDS, d.values),
    CASE_KEY("observes", K_TEXT, d.observes),
    CASE_KEY("no_simulation", K_BOOL, d.no_simulation),
    CASE_KEY("case_progress", K_TEXT, d.case_progress),
    CASE_KEY("columns", K_TEXT, d.columns),
    CASE_KEY("title", K_TEXT, d.title),
    CASE_KEY("notes", K_TEXT, d.notes),
    {"after_rows", K_FN, offsetof(vfy_case_file, d.after_rows), VFY_FN_HOOK},
    CASE_KEY("must_fail", K_TEXT, d.must_fail),
    CASE_KEY("power_keys", K_TEXT, d.power_keys),
    {NULL, 0, 0, 0}};

#define PARTNER_KEY(K) {#K, K_TEXT, offsetof(vfy_partner, K), 0}
static const key_spec partner_keys[] = {PARTNER_KEY(when), PARTNER_KEY(match),
                                        PARTNER_KEY(has), {NULL, 0, 0, 0}};

static const key_spec metric_keys[] = {
    {"fn", K_FN, offsetof(vfy_metric, fn), VFY_FN_METRIC},
    {"a", K_TEXT, offsetof(vfy_metric, a), 0},
    {"b", K_TEXT, offsetof(vfy_metric, b), 0},
    {"x", K_NUMBER, offsetof(vfy_metric, x), 0},
    {NULL, 0, 0, 0}};

#define CHECK_KEY(K, T, MEMBER) {K, T, offsetof(vfy_check_spec, MEMBER), 0}
static const key_spec check_keys[] = {
    CHECK_KEY("name", K_TEXT, name),
    {"rule", K_FN, offsetof(vfy_check_spec, rule), VFY_FN_RULE},
    CHECK_KEY("value", K_TEXT, value),
    CHECK_KEY("expected", K_TEXT, expected),
    CHECK_KEY("x", K_NUMBER, x),
    CHECK_KEY("tol", K_NUMBER, tol),
    CHECK_KEY("lo", K_NUMBER, lo),
    CHECK_KEY("hi", K_NUMBER, hi),
    CHECK_KEY("rtol", K_NUMBER, rtol),
    CHECK_KEY("plus", K_TEXT, plus),
    CHECK_KEY("plus_quick", K_TEXT, plus_quick),
    CHECK_KEY("from", K_COUNT, from),
    CHECK_KEY("out", K_TEXT, out),
    CHECK_KEY("builtin_only", K_TEXT, builtin_only),
    {"guard", K_FN, offsetof(vfy_check_spec, guard.fn), VFY_FN_GUARD},
    CHECK_KEY("guard_a", K_TEXT, guard.a),
    CHECK_KEY("guard_b", K_TEXT, guard.b),
    CHECK_KEY("guard_x", K_NUMBER, guard.x),
    CHECK_KEY("guard_reason", K_TEXT, guard.reason),
    {"differs_paper", K_DIFFERS, offsetof(vfy_difference, paper), 0},
    {"differs_evidence", K_DIFFERS, offsetof(vfy_difference, evidence), 0},
    {"differs_judged_by", K_DIFFERS, offsetof(vfy_difference, judged_by), 0},
    {NULL, 0, 0, 0}};

#define FIGURE_KEY(K, T, MEMBER) {K, T, offsetof(vfy_figure_spec, MEMBER), 0}
static const key_spec figure_keys[] = {
    FIGURE_KEY("kind", K_KIND, kind),
    FIGURE_KEY("suffix", K_TEXT, suffix),
    FIGURE_KEY("quantity", K_TEXT, quantity),
    FIGURE_KEY("ref", K_LIST, refs),
    FIGURE_KEY("x_from", K_NUMBER, x_from),
    FIGURE_KEY("panel_per_row", K_BOOL, panel_per_row),
    FIGURE_KEY("extrapolated", K_BOOL, extrapolated),
    FIGURE_KEY("x", K_TEXT, x),
    FIGURE_KEY("series", K_LIST, series),
    FIGURE_KEY("x_lo", K_NUMBER, x_lo),
    FIGURE_KEY("x_hi", K_NUMBER, x_hi),
    FIGURE_KEY("group_by", K_TEXT, group_by),
    FIGURE_KEY("group", K_LIST, groups),
    FIGURE_KEY("title", K_TEXT, title),
    FIGURE_KEY("xlabel", K_TEXT, xlabel),
    FIGURE_KEY("ylabel", K_TEXT, ylabel),
    FIGURE_KEY("curve", K_CURVE, curves),
    FIGURE_KEY("ref_curve", K_CURVE, curves),
    FIGURE_KEY("panel", K_LIST, panels),
    FIGURE_KEY("only", K_TEXT, only),
    FIGURE_KEY("row_label", K_TEXT, row_label),
    FIGURE_KEY("each_row", K_BOOL, each_row),
    FIGURE_KEY("band", K_BOOL, band),
    FIGURE_KEY("logx", K_BOOL, logx),
    FIGURE_KEY("logy", K_BOOL, logy),
    FIGURE_KEY("key_inside", K_TEXT, key_inside),
    {NULL, 0, 0, 0}};

/* ------------------------------------------------------------ the parse */

typedef enum sec_kind {
    SEC_NONE, SEC_CASE, SEC_PAPER_ROWS, SEC_QUICK_ROWS, SEC_PAPER_COLUMNS, SEC_PARTNER,
    SEC_METRIC, SEC_CASE_METRIC, SEC_CHECK, SEC_CASE_CHECK, SEC_FIGURE
} sec_kind;

/* The items of one K_LIST or K_WORDS member, set at the end. */
typedef struct list_field {
    const char *const **field;
    const char **items;
    size_t n, cap;
} list_field;

static int item_push(list_field *l, const char *item)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 8;
        const char **grown = realloc(l->items, cap * sizeof *grown);
        if (grown == NULL)
            return -1;
        l->items = grown;
        l->cap = cap;
    }
    l->items[l->n++] = item;
    return 0;
}

/* What a rows section builds. */
typedef struct sweep_builder {
    ptr_list keys;   /* vfy_sweep_key */
} sweep_builder;

/* A text being read: the case file, or a file it includes. */
typedef struct source {
    char *text;              /* owned (an included file's), or NULL */
    const char *pos;         /* the reader's place in it */
    const char *name;        /* its file name, as messages say it */
    int line;                /* its lines read so far */
} source;

/* Where a line handed to inih came from. */
typedef struct origin {
    const char *file;
    int line;
} origin;

typedef struct parse_ctx {
    vfy_case_file *f;
    const char *dir;         /* where included files are */
    const vfy_named_fn *const *tables;
    source src[MAX_INCLUDE_DEPTH + 1];   /* src[0] the case file, then its includes */
    int depth;
    char **names;            /* the included files' names (owned), for messages */
    size_t nnames;
    origin *origins;         /* of every line handed to inih, in order */
    size_t norigins, caporigins;
    const char *file;        /* the file and line being parsed (line 0: none) */
    int line;
    int need_header;         /* an included file ended: a header must come first */
    int continued;           /* the line continues the previous value */
    int have_key;            /* a key line came since the last header or blank line */
    unsigned header_seq;     /* section headers read so far */
    int header_origin;       /* the origin of the last one */
    unsigned record_seq;     /* the header the current record belongs to */
    int failed;
    sim_status status;
    char err[600];
    /* the current record */
    sec_kind kind;
    void *record;
    char section[80];
    uint64_t seen;           /* its keys set so far, by their index in the table */
    const char *x_fixed_by;  /* the function that set its x (named.h), or NULL */
    /* the last text value, for its continuation lines */
    const char **last_field;
    char *last_raw;
    /* the records, in order */
    ptr_list partners, metrics, case_metrics, checks, case_checks, figures, paper_columns;
    sweep_builder paper_rows, quick_rows;
    list_field *lists;
    size_t nlists, caplists;
    uint64_t case_keys_seen; /* the [case] keys set so far, in any [case] section */
} parse_ctx;

static int fail(parse_ctx *c, sim_status st, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static int fail(parse_ctx *c, sim_status st, const char *key, const char *fmt, ...)
{
    if (c->failed)
        return 0;
    c->failed = 1;
    c->status = st;
    char what[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    if (c->line > 0 && key != NULL)
        snprintf(c->err, sizeof c->err, "%s:%d: [%s] %s: %s", c->file, c->line, c->section, key,
                 what);
    else if (c->line > 0)
        snprintf(c->err, sizeof c->err, "%s:%d: %s", c->file, c->line, what);
    else
        snprintf(c->err, sizeof c->err, "%s: %s", c->file, what);
    return 0;
}

static int nomem(parse_ctx *c) { return fail(c, SIM_ENOMEM, NULL, "out of memory"); }

/* Messages from now on name origin k (k < 0: the case file, no line). */
static void at_origin(parse_ctx *c, int k)
{
    c->file = k >= 0 ? c->origins[k].file : c->src[0].name;
    c->line = k >= 0 ? c->origins[k].line : 0;
}

/* value with \n and \\ resolved, owned by the file; NULL after a failure. */
static char *unescape(parse_ctx *c, const char *key, const char *value)
{
    char *out = own(c->f, strlen(value) + 1), *o = out;
    if (out == NULL)
        return nomem(c), NULL;
    for (const char *p = value; *p; p++) {
        if (*p != '\\') {
            *o++ = *p;
            continue;
        }
        if (p[1] == 'n')
            *o++ = '\n';
        else if (p[1] == '\\')
            *o++ = '\\';
        else
            return fail(c, SIM_EINVAL, key, "unknown escape '\\%c' (allowed \\n, \\\\)",
                        p[1] ? p[1] : ' '), NULL;
        p++;
    }
    return out;
}

/* A number; with `named`, a tolerance's name (or minus one) too. */
static int parse_number(parse_ctx *c, const char *key, const char *text, int named, double *v)
{
    const int minus = text[0] == '-';
    if (named && isalpha((unsigned char)text[minus]) && strcmp(text + minus, "nan") != 0
        && strcmp(text + minus, "inf") != 0) {   /* a tolerance, or minus one */
        for (const vfy_tolerance *t = vfy_tolerances; t->name; t++)
            if (strcmp(t->name, text + minus) == 0)
                return *v = minus ? -t->value : t->value, 1;
        return fail(c, SIM_EINVAL, key, "'%s' is no tolerance of tolerances.h", text + minus);
    }
    char *end;
    errno = 0;
    *v = strtod(text, &end);
    if (end == text || *end != '\0' || errno == ERANGE)
        return fail(c, SIM_EINVAL, key, "'%s' is not a number (allowed a decimal number, nan, "
                    "inf%s)", text, named ? " or a tolerance's name" : "");
    return 1;
}

static const vfy_named_fn *find_fn(parse_ctx *c, vfy_fn_kind kind, const char *name)
{
    for (const vfy_named_fn *const *t = c->tables; *t; t++) {
        const vfy_named_fn *e = vfy_named_find(*t, kind, name);
        if (e != NULL)
            return e;
    }
    return NULL;
}

static list_field *list_of(parse_ctx *c, const char *const **field)
{
    for (size_t i = 0; i < c->nlists; i++)
        if (c->lists[i].field == field)
            return &c->lists[i];
    if (c->nlists == c->caplists) {
        size_t cap = c->caplists ? 2 * c->caplists : 16;
        list_field *grown = realloc(c->lists, cap * sizeof *grown);
        if (grown == NULL)
            return NULL;
        c->lists = grown;
        c->caplists = cap;
    }
    list_field *l = &c->lists[c->nlists++];
    memset(l, 0, sizeof *l);
    l->field = field;
    return l;
}

/* Remember a text member's raw value, for its continuation lines. */
static int set_text(parse_ctx *c, const char *key, const char **field, const char *raw)
{
    free(c->last_raw);
    c->last_raw = strdup(raw);
    c->last_field = field;
    if (c->last_raw == NULL)
        return nomem(c);
    const char *text = unescape(c, key, raw);
    if (text == NULL)
        return 0;
    *field = text;
    return 1;
}

static int continue_text(parse_ctx *c, const char *key, const char *raw)
{
    if (c->last_field == NULL)
        return fail(c, SIM_EINVAL, key, "an indented line continues only a text value");
    size_t n = strlen(c->last_raw);
    const int after_break = (n >= 2 && c->last_raw[n - 2] == '\\' && c->last_raw[n - 1] == 'n')
                            || (n >= 1 && c->last_raw[n - 1] == ';');
    char *joined = malloc(n + strlen(raw) + 2);
    if (joined == NULL)
        return nomem(c);
    sprintf(joined, "%s%s%s", c->last_raw, after_break ? "" : " ", raw);
    free(c->last_raw);
    c->last_raw = joined;
    const char *text = unescape(c, key, joined);
    if (text == NULL)
        return 0;
    *c->last_field = text;
    return 1;
}

/* Function e (fixed_x, named.h) sets the record's x: refused when the
 * record has set x itself. */
static int set_fixed_x(parse_ctx *c, const key_spec *table, void *base, const char *key,
                       const vfy_named_fn *e)
{
    size_t k = 0;
    while (table[k].key && strcmp(table[k].key, "x") != 0)
        k++;
    if (table[k].key == NULL || table[k].type != K_NUMBER)
        return fail(c, SIM_EINVAL, key, "'%s' takes no x here", e->name);
    if (k < 64 && (c->seen >> k & 1))
        return fail(c, SIM_EINVAL, key, "'%s' sets x itself", e->name);
    *(double *)((char *)base + table[k].offset) = e->x;
    c->x_fixed_by = e->name;
    return 1;
}

/* A figure's kind by its word. */
static int set_kind(parse_ctx *c, const char *key, vfy_figure_kind *kind, const char *value)
{
    static const struct {
        const char *word;
        vfy_figure_kind kind;
    } kinds[] = {{"curves", VFY_FIGURE_CURVES}, {"points", VFY_FIGURE_POINTS},
                 {"row curves", VFY_FIGURE_ROW_CURVES}, {"row points", VFY_FIGURE_ROW_POINTS}};
    for (size_t i = 0; i < sizeof kinds / sizeof *kinds; i++)
        if (strcmp(value, kinds[i].word) == 0)
            return *kind = kinds[i].kind, 1;
    return fail(c, SIM_EINVAL, key, "'%s' (allowed curves, points, row curves, row points)",
                value);
}

/* "LABEL=FUNCTION" (the label may hold '=': the last one ends it) appended
 * to the figure's list at *list; key ref_curve makes a reference. */
static int add_curve(parse_ctx *c, const char *key, const vfy_figure_curve **list,
                     const char *value)
{
    const char *eq = strrchr(value, '=');
    if (eq == NULL || eq == value || eq[1] == '\0')
        return fail(c, SIM_EINVAL, key, "'%s' (allowed LABEL=FUNCTION)", value);
    const vfy_named_fn *e = find_fn(c, VFY_FN_CURVE, eq + 1);
    if (e == NULL)
        return fail(c, SIM_EINVAL, key, "unknown curve '%s' (named.h, registry.c)", eq + 1);
    vfy_figure_curve *curve = own(c->f, sizeof *curve);
    char *label = own_strndup(c->f, value, (size_t)(eq - value));
    if (curve == NULL || label == NULL)
        return nomem(c);
    *curve = (vfy_figure_curve){.label = label, .fn = e->curve, .x = e->x,
                                .reference = strcmp(key, "ref_curve") == 0};
    while (*list != NULL)
        list = (const vfy_figure_curve **)&(*list)->next;
    *list = curve;
    c->last_field = NULL;
    return 1;
}

static int apply_key(parse_ctx *c, const key_spec *table, void *base, const char *key,
                     const char *value)
{
    size_t k = 0;
    while (table[k].key && strcmp(table[k].key, key) != 0)
        k++;
    const key_spec *s = &table[k];
    if (s->key == NULL) {
        char allowed[600] = "";
        size_t used = 0;
        for (const key_spec *t = table; t->key && used < sizeof allowed; t++)
            used += (size_t)snprintf(allowed + used, sizeof allowed - used, "%s%s",
                                     used ? ", " : "", t->key);
        return fail(c, SIM_EINVAL, key, "unknown key (allowed %s)", allowed);
    }
    if (strcmp(key, "x") == 0 && c->x_fixed_by != NULL)
        return fail(c, SIM_EINVAL, key, "'%s' sets x itself", c->x_fixed_by);
    if (s->type != K_LIST && s->type != K_CURVE) {
        if (k < 64 && (c->seen >> k & 1))
            return fail(c, SIM_EINVAL, key, "set twice in this section");
        c->seen |= k < 64 ? (uint64_t)1 << k : 0;
    }
    char *at = (char *)base + s->offset;
    switch (s->type) {
    case K_TEXT:
        return set_text(c, key, (const char **)at, value);
    case K_DIFFERS: {
        vfy_check_spec *check = base;
        if (check->differs == NULL && (check->differs = own(c->f, sizeof(vfy_difference))) == NULL)
            return nomem(c);
        return set_text(c, key, (const char **)((char *)check->differs + s->offset), value);
    }
    case K_NUMBER:
        return parse_number(c, key, value, 1, (double *)at);
    case K_COUNT: {
        char *end;
        errno = 0;
        unsigned long long v = strtoull(value, &end, 10);
        if (!isdigit((unsigned char)value[0]) || *end != '\0' || errno == ERANGE)
            return fail(c, SIM_EINVAL, key, "'%s' is not a count (allowed 0, 1, 2, ...)", value);
        *(size_t *)at = (size_t)v;
        return 1;
    }
    case K_BOOL:
        if (strcmp(value, "true") != 0 && strcmp(value, "false") != 0)
            return fail(c, SIM_EINVAL, key, "'%s' (allowed true, false)", value);
        *(int *)at = strcmp(value, "true") == 0;
        return 1;
    case K_KIND:
        return set_kind(c, key, (vfy_figure_kind *)at, value);
    case K_CURVE:
        return add_curve(c, key, (const vfy_figure_curve **)at, value);
    case K_BATCHES: {
        vfy_batches *b = (vfy_batches *)at;
        unsigned long long count, stride;
        char extra;
        if (sscanf(value, "%llu %llu %c", &count, &stride, &extra) != 2 || count == 0)
            return fail(c, SIM_EINVAL, key, "'%s' (allowed COUNT STRIDE, COUNT > 0)", value);
        b->count = (size_t)count;
        b->seed_stride = (uint64_t)stride;
        return 1;
    }
    case K_WORDS:
    case K_LIST: {
        list_field *l = list_of(c, (const char *const **)at);
        if (l == NULL)
            return nomem(c);
        if (s->type == K_LIST)   /* the member itself is set at the end (finish) */
            return item_push(l, NULL) == 0 ? set_text(c, key, &l->items[l->n - 1], value)
                                           : nomem(c);
        for (const char *p = value; *p;) {
            size_t n = strcspn(p, " \t");
            char *word = n ? own_strndup(c->f, p, n) : NULL;
            if (n && (word == NULL || item_push(l, word)))
                return nomem(c);
            p += n;
            p += strspn(p, " \t");
        }
        return 1;
    }
    case K_FN: {
        const vfy_named_fn *e = find_fn(c, s->fn, value);
        if (e == NULL)
            return fail(c, SIM_EINVAL, key, "unknown %s '%s' (named.h, registry.c)",
                        vfy_fn_kind_word(s->fn), value);
        if (e->fixed_x && !set_fixed_x(c, table, base, key, e))
            return 0;
        switch (s->fn) {
        case VFY_FN_METRIC: *(vfy_metric_fn *)at = e->metric; break;
        case VFY_FN_RULE: *(vfy_rule_fn *)at = e->rule; break;
        case VFY_FN_GUARD: *(vfy_guard_fn *)at = e->guard; break;
        case VFY_FN_HOOK: *(vfy_hook_fn *)at = e->hook; break;
        case VFY_FN_ADJUST: *(vfy_adjust_fn *)at = e->adjust; break;
        case VFY_FN_CURVE: break;   /* no K_FN key names a curve (K_CURVE) */
        }
        return 1;
    }
    }
    return 1;
}

/* A key of [paper rows] or [quick rows]: grid, sets, row, or a swept scene
 * key "SECTION.KEY" or "SECTION.KEY as NAME". */
static int apply_rows(parse_ctx *c, vfy_sweep *sweep, sweep_builder *b, const char *key,
                      const char *value)
{
    static const key_spec rows_keys[] = {
        {"grid", K_BOOL, offsetof(vfy_sweep, grid), 0},
        {"sets", K_TEXT, offsetof(vfy_sweep, sets), 0},
        {"row", K_LIST, offsetof(vfy_sweep, rows), 0},
        {NULL, 0, 0, 0}};
    if (strchr(key, '.') == NULL)
        return apply_key(c, rows_keys, sweep, key, value);
    vfy_sweep_key *k = own(c->f, sizeof *k);
    if (k == NULL || list_push(&b->keys, k, (int)c->norigins - 1))
        return nomem(c);
    const char *as = strstr(key, " as ");
    k->key = own_strndup(c->f, key, as ? (size_t)(as - key) : strlen(key));
    k->name = as ? own_strndup(c->f, as + 4, strlen(as + 4)) : NULL;
    k->values = own_strndup(c->f, value, strlen(value));
    if (k->key == NULL || (as && k->name == NULL) || k->values == NULL)
        return nomem(c);
    if (strchr(k->key, ' ') || (as && (k->name[0] == '\0' || strchr(k->name, ' '))))
        return fail(c, SIM_EINVAL, key, "a swept key is SECTION.KEY or SECTION.KEY as NAME");
    c->last_field = NULL;
    return 1;
}

static int apply_paper_column(parse_ctx *c, const char *key, const char *value)
{
    for (size_t i = 0; i < c->paper_columns.n; i++)
        if (strcmp(((const vfy_paper_column *)c->paper_columns.v[i])->name, key) == 0)
            return fail(c, SIM_EINVAL, key, "set twice in this section");
    vfy_paper_column *p = own(c->f, sizeof *p);
    size_t words = 0;
    for (const char *q = value; *q; q += strspn(q, " \t"))
        if (*q != ' ' && *q != '\t')
            words++, q += strcspn(q, " \t");
    double *v = own(c->f, (words ? words : 1) * sizeof *v);
    if (p == NULL || v == NULL || (p->name = own_strndup(c->f, key, strlen(key))) == NULL
        || list_push(&c->paper_columns, p, (int)c->norigins - 1))
        return nomem(c);
    p->v = v;
    char word[64];
    for (const char *q = value + strspn(value, " \t"); *q; q += strspn(q, " \t")) {
        size_t n = strcspn(q, " \t");
        snprintf(word, sizeof word, "%.*s", (int)n, q);
        if (!parse_number(c, key, word, 0, &v[p->count++]))
            return 0;
        q += n;
    }
    c->last_field = NULL;
    return 1;
}

/* The section kinds, by their headers. */
static const struct {
    const char *header;
    sec_kind kind;
    int named;      /* the header names the record: "[metric NAME]" */
    size_t size;    /* the record's size (0: the section fills the description) */
} sections[] = {
    {"case", SEC_CASE, 0, 0},
    {"paper rows", SEC_PAPER_ROWS, 0, 0},
    {"quick rows", SEC_QUICK_ROWS, 0, 0},
    {"paper columns", SEC_PAPER_COLUMNS, 0, 0},
    {"partner ", SEC_PARTNER, 1, sizeof(vfy_partner)},
    {"metric ", SEC_METRIC, 1, sizeof(vfy_metric)},
    {"case metric ", SEC_CASE_METRIC, 1, sizeof(vfy_metric)},
    {"check", SEC_CHECK, 0, sizeof(vfy_check_spec)},
    {"case check", SEC_CASE_CHECK, 0, sizeof(vfy_check_spec)},
    {"figure", SEC_FIGURE, 0, sizeof(vfy_figure_spec)},
};

/* The index in sections[] of header `section`, or -1 (an error in c). */
static int find_section(parse_ctx *c, const char *section)
{
    for (size_t i = 0; i < sizeof sections / sizeof *sections; i++) {
        const size_t n = strlen(sections[i].header);
        if (sections[i].named ? strncmp(section, sections[i].header, n) == 0 && section[n] != '\0'
                              : strcmp(section, sections[i].header) == 0)
            return (int)i;
    }
    fail(c, SIM_EINVAL, NULL,
         "[%s]: unknown section (allowed [case], [paper rows], [quick rows], [paper columns], "
         "[partner NAME], [metric NAME], [case metric NAME], [check], [case check], [figure])",
         section);
    return -1;
}

/* The record a section header starts (on the first key after it). */
static int start_record(parse_ctx *c, const char *section)
{
    snprintf(c->section, sizeof c->section, "%s", section);
    c->seen = 0;
    c->x_fixed_by = NULL;
    c->record_seq = c->header_seq;
    const int i = find_section(c, section);
    if (i < 0)
        return 0;
    c->kind = sections[i].kind;
    if (sections[i].size == 0) {
        c->record = NULL;
        return 1;
    }
    const size_t n = strlen(sections[i].header);
    c->record = own(c->f, sections[i].size);
    const char *name = sections[i].named ? own_strndup(c->f, section + n, strlen(section + n))
                                         : "";
    ptr_list *list = c->kind == SEC_PARTNER       ? &c->partners
                     : c->kind == SEC_METRIC      ? &c->metrics
                     : c->kind == SEC_CASE_METRIC ? &c->case_metrics
                     : c->kind == SEC_CHECK       ? &c->checks
                     : c->kind == SEC_CASE_CHECK  ? &c->case_checks
                                                  : &c->figures;
    if (c->record == NULL || name == NULL || list_push(list, c->record, c->header_origin))
        return nomem(c);
    if (c->kind == SEC_PARTNER)
        ((vfy_partner *)c->record)->name = name;
    else if (c->kind == SEC_METRIC || c->kind == SEC_CASE_METRIC)
        ((vfy_metric *)c->record)->name = name;
    return 1;
}

/* A key of [case check]: as [check]'s, but a guard gets no row there
 * (driver.h), so only those that need none. */
static int case_check_key(parse_ctx *c, const char *key, const char *value)
{
    static const char *const case_guards[] = {"at_most", "only_at_most", "at_least",
                                              "only_at_least", "unless", "only_unless",
                                              "paper_sizes"};
    int allowed = strcmp(key, "guard") != 0;
    for (size_t i = 0; i < sizeof case_guards / sizeof *case_guards && !allowed; i++)
        allowed = strcmp(value, case_guards[i]) == 0;
    if (!allowed)
        return fail(c, SIM_EINVAL, key, "'%s' needs a row (allowed here at_most, only_at_most, "
                    "at_least, only_at_least, unless, only_unless, paper_sizes)", value);
    return apply_key(c, check_keys, c->record, key, value);
}

static int handler(void *user, const char *section, const char *name, const char *value)
{
    parse_ctx *c = user;
    if (c->failed)
        return 0;
    if (c->continued)
        return continue_text(c, name, value);
    c->last_field = NULL;
    if (c->record_seq != c->header_seq || strcmp(section, c->section) != 0)
        if (!start_record(c, section))
            return 0;
    switch (c->kind) {
    case SEC_CASE: {   /* its keys once across all its sections (an included file's) */
        c->seen = c->case_keys_seen;
        const int ok = apply_key(c, case_keys, c->f, name, value);
        c->case_keys_seen = c->seen;
        return ok;
    }
    case SEC_PAPER_ROWS: return apply_rows(c, &c->f->d.paper_rows, &c->paper_rows, name, value);
    case SEC_QUICK_ROWS: return apply_rows(c, &c->f->d.quick_rows, &c->quick_rows, name, value);
    case SEC_PAPER_COLUMNS: return apply_paper_column(c, name, value);
    case SEC_PARTNER: return apply_key(c, partner_keys, c->record, name, value);
    case SEC_METRIC:
    case SEC_CASE_METRIC: return apply_key(c, metric_keys, c->record, name, value);
    case SEC_CHECK: return apply_key(c, check_keys, c->record, name, value);
    case SEC_CASE_CHECK: return case_check_key(c, name, value);
    case SEC_FIGURE: return apply_key(c, figure_keys, c->record, name, value);
    case SEC_NONE: break;
    }
    return fail(c, SIM_EINVAL, name, "a key before any section header");
}

/* The text of the file at path (at most MAX_FILE_BYTES, no NUL byte) into
 * *text (the caller frees it); msg names the file and says what is wrong. */
static sim_status read_text(const char *path, char **text, char *msg, size_t msglen)
{
    size_t n;
    char why[256];
    sim_status st = vfy_read_file(path, MAX_FILE_BYTES, text, &n, why, sizeof why);
    if (st == SIM_OK && memchr(*text, '\0', n) != NULL) {
        snprintf(why, sizeof why, "NUL byte (allowed text only)");
        free(*text);
        *text = NULL;
        st = SIM_EINVAL;
    }
    if (st != SIM_OK)
        snprintf(msg, msglen, "%s: %s", path, why);
    return st;
}

/* "[include NAME]" at p (a line's first non-blank character): read
 * DIR/NAME.inc and read on from its first line (case_file.h). */
static int push_include(parse_ctx *c, const char *p, const char *end)
{
    const char *rb = memchr(p, ']', (size_t)(end - p));
    const char *name = p + strlen("[include ");
    const size_t n = rb ? (size_t)(rb - name) : 0;
    if (n == 0 || strspn(name, "abcdefghijklmnopqrstuvwxyz0123456789-") != n)
        return fail(c, SIM_EINVAL, NULL, "[include NAME]: NAME of a-z, 0-9 and -");
    if (c->depth == MAX_INCLUDE_DEPTH)
        return fail(c, SIM_EINVAL, NULL, "[include %.*s]: includes nested deeper than %d",
                    (int)n, name, MAX_INCLUDE_DEPTH);
    char **grown = realloc(c->names, (c->nnames + 1) * sizeof *grown);
    if (grown == NULL)
        return nomem(c);
    c->names = grown;
    char *path = c->names[c->nnames++] = malloc(strlen(c->dir) + n + 8);
    if (path == NULL)
        return nomem(c);
    sprintf(path, "%s/%.*s.inc", c->dir, (int)n, name);
    char *text, msg[sizeof c->err];
    sim_status st = read_text(path, &text, msg, sizeof msg);
    if (st != SIM_OK)
        return fail(c, st, NULL, "[include %.*s]: %s", (int)n, name, msg);
    c->src[++c->depth] = (source){.text = text, .pos = text, .name = path};
    return 1;
}

/* The next line of the innermost text, in line (the included files' ends
 * popped); NULL at the end of the case file. */
static const char *next_line(parse_ctx *c, const char **end)
{
    while (*c->src[c->depth].pos == '\0') {
        if (c->depth == 0)
            return NULL;
        free(c->src[c->depth--].text);
        c->need_header = 1, c->have_key = 0;
    }
    source *s = &c->src[c->depth];
    const char *p = s->pos, *nl = strchr(p, '\n');
    *end = nl ? nl + 1 : p + strlen(p);
    s->pos = *end;
    s->line++;
    c->file = s->name;
    c->line = s->line;
    return p;
}

/* Hand inih one whole line per call (see the top of the file). */
static char *reader(char *buf, int num, void *stream)
{
    parse_ctx *c = stream;
    const char *p = NULL, *end = NULL, *start = NULL;
    while (!c->failed && (p = next_line(c, &end)) != NULL) {
        start = p;
        while (start < end && *start != '\n' && isspace((unsigned char)*start))
            start++;
        if (strncmp(start, "[include ", strlen("[include ")) != 0)
            break;
        push_include(c, start, end);
    }
    if (c->failed || p == NULL)
        return NULL;
    if (c->norigins == c->caporigins) {
        size_t cap = c->caporigins ? 2 * c->caporigins : 256;
        origin *grown = realloc(c->origins, cap * sizeof *grown);
        if (grown == NULL)
            return nomem(c), NULL;
        c->origins = grown;
        c->caporigins = cap;
    }
    c->origins[c->norigins++] = (origin){c->file, c->line};
    const int blank = start == end || *start == '\n';
    const int comment = !blank && (*start == ';' || *start == '#');
    c->continued = !blank && !comment && start > p && c->have_key;
    if (!c->continued)
        p = start;
    if (!blank && !comment && !c->continued) {
        if (*p == '[') {   /* a header, as inih reads it: up to the first ']' */
            const char *rb = memchr(p, ']', (size_t)(end - p));
            char section[80];
            snprintf(section, sizeof section, "%.*s", rb ? (int)(rb - p - 1) : 0, p + 1);
            if (rb && find_section(c, section) < 0)
                return NULL;
            c->header_seq++, c->have_key = 0, c->need_header = 0;
            c->header_origin = (int)c->norigins - 1;
        } else if (c->need_header) {
            fail(c, SIM_EINVAL, NULL, "a key right after an included file: start a section "
                 "first");
            return NULL;
        } else
            c->have_key = 1;
    } else if (blank)
        c->have_key = 0;
    size_t len = (size_t)(end - p);
    if (num < 3 || len > (size_t)num - 1) {
        fail(c, SIM_EINVAL, NULL, "line too long (allowed at most %d characters)", num - 2);
        return NULL;
    }
    memcpy(buf, p, len);
    buf[len] = '\0';
    return buf;
}

/* ------------------------------------------------------------ the end */

/* The records of list as one array of `size`-byte records ending with a
 * zeroed one, owned by the file; NULL when the list is empty. */
static void *records(parse_ctx *c, const ptr_list *list, size_t size)
{
    if (list->n == 0)
        return NULL;
    char *a = own(c->f, (list->n + 1) * size);
    if (a == NULL)
        return nomem(c), NULL;
    for (size_t i = 0; i < list->n; i++)
        memcpy(a + i * size, list->v[i], size);
    return a;
}

static int finish_sweep(parse_ctx *c, vfy_sweep *sweep, const sweep_builder *b)
{
    if (b->keys.n == 0)
        return 1;
    vfy_sweep_key *keys = records(c, &b->keys, sizeof *keys);
    sweep->keys = keys;
    return keys != NULL;
}

/* Whether figure g's keys go together (case_file.h); else a message. */
static int figure_ok(parse_ctx *c, const vfy_figure_spec *g)
{
    if (g->kind == VFY_FIGURE_NONE)
        return fail(c, SIM_EINVAL, NULL, "[figure] needs kind");
    const int by_row = g->kind == VFY_FIGURE_ROW_CURVES || g->kind == VFY_FIGURE_ROW_POINTS;
    int data = 0;
    for (const vfy_figure_curve *k = g->curves; k != NULL; k = k->next)
        data += !k->reference;
    const int of_series = g->row_label != NULL && g->curves == NULL;
    if (of_series && (g->kind != VFY_FIGURE_ROW_CURVES || g->each_row || g->x == NULL
                      || g->series == NULL))
        return fail(c, SIM_EINVAL, NULL, "[figure] of row series (row_label, no curve) is "
                    "of kind row curves and needs x and series, and no each_row");
    if (g->row_label != NULL && g->each_row)
        return fail(c, SIM_EINVAL, NULL, "[figure]: row_label (a curve per row) or each_row "
                    "(a figure per row), not both");
    size_t panels = 0;
    while (g->series != NULL && g->series[panels] != NULL)
        panels++;
    if (of_series && panels > VFY_XY_PANELS)
        return fail(c, SIM_EINVAL, NULL, "[figure] of row series: at most %d series (a "
                    "panel each)", VFY_XY_PANELS);
    size_t npanel = 0;
    while (g->panels != NULL && g->panels[npanel] != NULL)
        npanel++;
    if (npanel > VFY_XY_PANELS || (npanel && g->kind != VFY_FIGURE_ROW_CURVES))
        return fail(c, SIM_EINVAL, NULL, "[figure]: panel (at most %d) is for kind row "
                    "curves", VFY_XY_PANELS);
    if (g->only && (strchr(g->only, '=') == NULL || g->only[0] == '='))
        return fail(c, SIM_EINVAL, NULL, "[figure] only: '%s' (allowed NAME=VALUE)",
                    g->only);
    if (by_row && !of_series && data == 0)
        return fail(c, SIM_EINVAL, NULL, "[figure] of kind row curves or row points needs "
                    "a curve (curve = LABEL=FUNCTION) or, for row curves, row_label, x "
                    "and series");
    if (!by_row && (g->curves || g->row_label || g->each_row || g->band || g->logx
                    || g->logy || g->key_inside || g->only))
        return fail(c, SIM_EINVAL, NULL, "[figure]: curve, ref_curve, row_label, each_row, "
                    "band, logx, logy, key_inside and only are for kinds row curves and "
                    "row points");
    if (g->each_row && (g->suffix == NULL || strchr(g->suffix, '{') == NULL))
        return fail(c, SIM_EINVAL, NULL, "[figure] each_row needs a suffix that tells the "
                    "rows apart (a template: -{alpha})");
    return 1;
}

/* Check the records (their header's line in messages) and set the
 * description's arrays. */
static int finish(parse_ctx *c)
{
    vfy_case_file *f = c->f;
    for (size_t i = 0; i < c->nlists; i++) {
        const list_field *l = &c->lists[i];
        const char **a = own(f, (l->n + 1) * sizeof *a);
        if (a == NULL)
            return nomem(c);
        if (l->n > 0)   /* "needs =": an empty list, no items to copy */
            memcpy(a, l->items, l->n * sizeof *a);
        *l->field = a;
    }
    at_origin(c, -1);
    if (f->c.suite == NULL || f->c.summary == NULL)
        return fail(c, SIM_EINVAL, NULL, "[case] needs suite and summary");
    for (size_t i = 0; i < c->metrics.n + c->case_metrics.n; i++) {
        const int own_rows = i < c->metrics.n;
        const vfy_metric *m = own_rows ? c->metrics.v[i] : c->case_metrics.v[i - c->metrics.n];
        at_origin(c, own_rows ? c->metrics.lines[i] : c->case_metrics.lines[i - c->metrics.n]);
        if (m->fn == NULL)
            return fail(c, SIM_EINVAL, NULL, "[%smetric %s] needs fn", own_rows ? "" : "case ",
                        m->name);
    }
    for (size_t i = 0; i < c->checks.n + c->case_checks.n; i++) {
        const int own_rows = i < c->checks.n;
        const vfy_check_spec *s = own_rows ? c->checks.v[i] : c->case_checks.v[i - c->checks.n];
        at_origin(c, own_rows ? c->checks.lines[i] : c->case_checks.lines[i - c->checks.n]);
        if (s->name == NULL || s->rule == NULL)
            return fail(c, SIM_EINVAL, NULL, "[%scheck] needs name and rule",
                        own_rows ? "" : "case ");
        if (s->differs && (!s->differs->paper || !s->differs->evidence || !s->differs->judged_by))
            return fail(c, SIM_EINVAL, NULL, "[%scheck] %s: a known difference needs "
                        "differs_paper, differs_evidence and differs_judged_by",
                        own_rows ? "" : "case ", s->name);
    }
    for (size_t i = 0; i < c->figures.n; i++) {
        at_origin(c, c->figures.lines[i]);
        if (!figure_ok(c, c->figures.v[i]))
            return 0;
    }
    vfy_case_desc *d = &f->d;
    d->partners = records(c, &c->partners, sizeof *d->partners);
    d->metrics = records(c, &c->metrics, sizeof *d->metrics);
    d->case_metrics = records(c, &c->case_metrics, sizeof *d->case_metrics);
    d->checks = records(c, &c->checks, sizeof *d->checks);
    d->case_checks = records(c, &c->case_checks, sizeof *d->case_checks);
    d->figures = records(c, &c->figures, sizeof *d->figures);
    d->paper_columns = records(c, &c->paper_columns, sizeof *d->paper_columns);
    const char *bad;
    size_t badlen;
    if (!c->failed && !vfy_derived_check(d, &bad, &badlen)) {   /* a name that sets nothing */
        at_origin(c, -1);
        return fail(c, SIM_EINVAL, NULL, "[case] derived: '%.*s' (allowed KEY=NAME[:FORMAT], "
                    "NAME a value reference or a [metric] of the file)", (int)badlen, bad);
    }
    return !c->failed && finish_sweep(c, &d->paper_rows, &c->paper_rows)
           && finish_sweep(c, &d->quick_rows, &c->quick_rows);
}

static void ctx_free(parse_ctx *c)
{
    ptr_list *lists[] = {&c->partners, &c->metrics, &c->case_metrics, &c->checks,
                         &c->case_checks, &c->figures, &c->paper_columns,
                         &c->paper_rows.keys, &c->quick_rows.keys};
    for (size_t i = 0; i < sizeof lists / sizeof *lists; i++)
        list_free(lists[i]);
    for (size_t i = 0; i < c->nlists; i++)
        free(c->lists[i].items);
    free(c->lists);
    free(c->last_raw);
    for (int d = 1; d <= c->depth; d++)
        free(c->src[d].text);
    for (size_t i = 0; i < c->nnames; i++)
        free(c->names[i]);
    free(c->names);
    free(c->origins);
    free((char *)c->dir);
}

sim_status vfy_case_file_parse(const char *text, const char *file, const char *name,
                               const vfy_named_fn *const *tables, vfy_case_file **out,
                               char *msg, size_t msglen)
{
    *out = NULL;
    parse_ctx c = {.file = file, .tables = tables};
    c.src[0] = (source){.pos = text, .name = file};
    const char *slash = strrchr(file, '/');
    c.dir = slash ? strndup(file, (size_t)(slash - file)) : strdup(".");
    c.f = calloc(1, sizeof *c.f);
    if (c.dir == NULL || c.f == NULL
        || (c.f->c.name = own_strndup(c.f, name, strlen(name))) == NULL) {
        vfy_case_file_free(c.f);
        free((char *)c.dir);
        snprintf(msg, msglen, "%s: out of memory", file);
        return SIM_ENOMEM;
    }
    c.f->c.desc = &c.f->d;
    int ret = ini_parse_stream(reader, &c, handler, &c);
    if (ret > 0 && !c.failed) {   /* inih counts the lines it was handed */
        at_origin(&c, ret - 1 < (int)c.norigins ? ret - 1 : -1);
        fail(&c, SIM_EINVAL, NULL, "not a [section] header, a KEY = VALUE line or a comment");
    } else if (ret < 0)
        nomem(&c);
    if (!c.failed)
        finish(&c);
    ctx_free(&c);
    if (c.failed) {
        snprintf(msg, msglen, "%s", c.err);
        vfy_case_file_free(c.f);
        return c.status;
    }
    *out = c.f;
    return SIM_OK;
}

sim_status vfy_case_file_load(const char *path, const char *name,
                              const vfy_named_fn *const *tables, vfy_case_file **out,
                              char *msg, size_t msglen)
{
    *out = NULL;
    char *text;
    sim_status st = read_text(path, &text, msg, msglen);
    if (st == SIM_OK)
        st = vfy_case_file_parse(text, path, name, tables, out, msg, msglen);
    free(text);
    return st;
}
