/* Verification cases as data, and the one driver that runs them (docs/adding-a-case.md).
 *
 * A case description (vfy_case_desc, filled from a case file by
 * case_file.h, or in C by a test) names its scene, the rows (a sweep over
 * scene keys), the references it needs, per-row metrics, checks with guards,
 * the table's columns, a figure and its notes.  The driver owns everything
 * else: the row loop, each row's scenes (the sweep's settings first, then
 * --set, then --solver-set, so that the sweep never overrides what the user
 * fixed), simulation with progress, checkpoints and --resume
 * (vfy_simulate), the rows-so-far file after every row, the cost values,
 * the tables and the figure.  Bespoke cross-row analysis (a fit over the
 * rows, a second table) is a hook run after the rows, never a case body.
 *
 * Everything a description refers to is a value by name:
 *   - the row's own: n, N (ensembles), M (outputs), index, each sweep key's
 *     name, the value references it names (references.h), the result's
 *     steady averages by name with _ci ("a2", "a2_ci"), paper columns (a value printed by the paper for this row), the
 *     metrics and the values checks define, and the cost values cpu_s, wall_s,
 *     events, ns_per_event, collisions, background, violations, normals;
 *   - the case's: wall_total (all rows), outputs, rows, N (the first row's
 *     ensembles), N_dof = N - 1 and t_quantile (Student's t for N_dof, the
 *     half-widths _ci_t), and what hooks set;
 *   - a scene key by its name, "particles.n", "scene.splitting" (a word key
 *     is text): the row's solver scene, the first row's at the case's level;
 *     and "scene.step" (the time step the scheme takes) and
 *     "scene.output_interval".
 * Series (one value per output time) are the result's observables by their
 * column names ("T", "T_raw", "ux", ...) and the scene's references by name
 * ("T_exact", ...; scene_refs.h).
 *
 * Text (check names, skip reasons, the title, notes, progress labels) are
 * templates: "{name}" expands to a value (an integer prints as one, anything
 * else with %g) or "{name:%.3g}" with a printf format; the strings {case},
 * {size} ("quick" or "paper"), {paper} (the description's paper label) and
 * {comment} (the provenance line) are always there, and {label} and
 * {scene} (the stem of its scene file) in a row;
 * "{at_quick:TEXT}" is TEXT at quick sizes and nothing at paper sizes,
 * "{at_paper:TEXT}" the converse; "{if:NAME=WORD:TEXT}" is TEXT when
 * NAME's text or number is WORD ("{if:scene.splitting=strang:Strang}");
 * "{at_engine:TEXT}" is TEXT when the
 * built-in engine simulated (how it did), "{at_solver:TEXT}" when an
 * external solver did; a hook's case texts (vfy_run_set_text) by name;
 * a value an external solver did not report prints "(not reported)".
 * "{{" is a brace.
 */
#ifndef GDSMC_VFY_DRIVER_H
#define GDSMC_VFY_DRIVER_H

#include <stddef.h>

#include "cases.h"
#include "ensemble.h"
#include "figure.h"
#include "scene.h"
#include "scene_refs.h"
#include "table.h"
#include "text.h"

/* ------------------------------------------------------------ values */

typedef struct vfy_values {
    size_t count, capacity;
    char **names;   /* each allocated: a name of any length */
    double *v;
} vfy_values;

/* Set (or replace) a value; returns 0, or -1 when out of memory. */
int vfy_values_set(vfy_values *vals, const char *name, double v);
/* The value, or NAN when absent (so that a missing value fails every
 * comparison and prints as an empty cell). */
double vfy_values_get(const vfy_values *vals, const char *name);
int vfy_values_has(const vfy_values *vals, const char *name);
void vfy_values_free(vfy_values *vals);

/* ------------------------------------------------------------ rows */

typedef struct vfy_case_run vfy_case_run;

/* One row: its scenes, the references of `scene` and the simulation of
 * `solver`, and its values.  The texts are allocated (vfy_row_free frees
 * them): as long as the description makes them. */
typedef struct vfy_row {
    const vfy_case_run *run;    /* the run it belongs to */
    size_t index;
    char *label;                /* {label}: an explicit row's label, or "" (NULL before
                                   the row's scenes are loaded) */
    char *stem;                 /* {scene}: the stem of the row's scene file (likewise) */
    size_t ntexts;              /* text values a sweep ("$scheme=euler") or a rule gave */
    char **text_names, **texts; /* ntexts each */
    sim_scene scene;            /* what the references describe */
    sim_scene solver;           /* what was simulated (--solver-set added) */
    vfy_refs refs;              /* the scene's references (empty if the case names none) */
    sim_ensemble_result res;    /* the first variant's result (or the only one) */
    sim_ensemble_result *more;  /* the other variants' results, in order */
    vfy_values values;
    char refused[280];          /* why an external solver refused the row (or a
                                   variant of it, named first), or "" */
} vfy_row;

/* The series `name` of a row (an observable of the result, or a reference):
 * mean[m] and ci[m] (ci may be NULL; a reference has ci = 0) for the
 * row's M outputs; "NAME@VARIANT" is the observable of a variant's result,
 * "NAME@*" its mean over all the variants (independent batches: ci =
 * sqrt(sum of ci^2) / variants).  Returns 0, or -1 when the row has no such
 * series. */
int vfy_row_series(const vfy_row *row, const char *name, double *mean, double *ci);

/* The result of the variant named `variant` (NULL or "": the first). */
const sim_ensemble_result *vfy_row_result(const vfy_case_run *run, const vfy_row *row,
                                          const char *variant);

/* The row's text value `name` ("$name=..." in its sweep), or NULL. */
const char *vfy_row_text(const vfy_row *row, const char *name);

/* Set (or replace) the row's text `name` (a rule may: a solver's message);
 * returns 0, or -1 when out of memory. */
int vfy_row_set_text(vfy_row *row, const char *name, const char *text);

/* Free what a row owns: its values, texts, label and stem, its references
 * and its results (zeroed members are fine). */
void vfy_row_free(vfy_row *row);

/* Value `name` as templates, checks and metrics see it: the row's own (row
 * may be NULL), else a scene key of the row's scene (the first row's at the
 * case's level), else the case's; NAN when none. */
double vfy_value(const vfy_case_run *run, const vfy_row *row, const char *name);

/* The row before this one, or NULL for the first. */
const vfy_row *vfy_row_previous(const vfy_case_run *run, const vfy_row *row);

/* A row's partner (vfy_case_desc.partners), the row a metric compares it
 * with: for a row whose values satisfy `when`, the first earlier row whose
 * values named in `match` equal this row's and whose values satisfy `has`.
 * A condition is space-separated "NAME=NUMBER" or "NAME!=NUMBER" words (a
 * value the row lacks is NaN, unequal to every number); NULL holds always.
 * as-steady: {"rate", "a_tau0!=4", "alpha is_ehs", "a_tau0=4 is_jump!=1"},
 * a row at a tau0 = 0.1 against the same gas at 4. */
typedef struct vfy_partner {
    const char *name, *when, *match, *has;
} vfy_partner;

/* Row's partner `name` of its case, or NULL: none declared by that name, or
 * none found for this row. */
const vfy_row *vfy_row_partner(const vfy_case_run *run, const vfy_row *row, const char *name);

/* ------------------------------------------------------------ description */

/* A per-row metric: defines value `name` from the row (pure functions in
 * stats.h do the arithmetic; these adapters name their operands). */
typedef struct vfy_metric vfy_metric;
typedef double vfy_metric_func(const vfy_case_run *run, const vfy_row *row, const vfy_metric *m);
typedef vfy_metric_func *vfy_metric_fn;
struct vfy_metric {
    const char *name;
    vfy_metric_fn fn;
    const char *a, *b;   /* operands: series or value names */
    double x;            /* a parameter, as the function documents */
};

/* A guard decides whether a check is judged on this row: VFY_JUDGE, a SKIP
 * with the guard's reason, or VFY_OMIT (the check does not exist here, e.g.
 * a ratio to the previous row on the first row).  A case check's guard gets
 * row NULL: only the value guards and paper_sizes take one (case_file.c
 * refuses the others there). */
typedef enum vfy_guard_result { VFY_JUDGE, VFY_GUARD_SKIP, VFY_OMIT } vfy_guard_result;
typedef struct vfy_guard vfy_guard;
typedef vfy_guard_result vfy_guard_func(const vfy_case_run *run, const vfy_row *row,
                                        const vfy_guard *g);
typedef vfy_guard_func *vfy_guard_fn;
struct vfy_guard {
    vfy_guard_fn fn;     /* NULL: always judged */
    const char *a, *b;
    double x;
    const char *reason;  /* template of the SKIP's reason */
};

/* A known difference from a paper (docs/differences.md): a paper
 * comparison that fails because the paper is off, as an independent route
 * in this project shows.  Its FAIL is recorded as DIFFERS (never exit 1),
 * and the solver is judged by the check named `judged_by` instead, which
 * must be a check of the same description (its name template) without a
 * difference of its own (tests/test_verify_cases.c holds every description
 * to this). */
typedef struct vfy_difference {
    const char *paper;      /* what the paper prints or says, and where */
    const char *evidence;   /* what shows it off: the route, the run, the number */
    const char *judged_by;  /* the check that judges the solver instead */
} vfy_difference;

/* A check: a rule (checks.h) applied to named values. */
typedef struct vfy_check_spec vfy_check_spec;
typedef vfy_verdict vfy_rule_func(vfy_report *r, const char *name, vfy_case_run *run,
                                  vfy_row *row, const vfy_check_spec *c);
typedef vfy_rule_func *vfy_rule_fn;
struct vfy_check_spec {
    const char *name;          /* template */
    vfy_rule_fn rule;
    const char *value;         /* the value (or series) judged */
    const char *expected;      /* the value (or series) it is judged against, or NULL */
    double x;                  /* the expected constant when expected is NULL */
    double tol, lo, hi;        /* as the rule documents */
    double rtol;               /* vfy_rule_absolute: tol + rtol |expected| ... */
    const char *plus;          /* ... + this value ... */
    const char *plus_quick;    /* ... + this value at quick sizes (its half-width, say) */
    size_t from;               /* series rules: the first output judged */
    const char *out;           /* a value the rule defines (e.g. its max |z|), or NULL */
    vfy_guard guard;
    const char *builtin_only;  /* judged only for the built-in engine, and why: the check
                                  models its own arithmetic or random streams (an
                                  external solver's run is a SKIP saying so), or NULL */
    const vfy_difference *differs;  /* a paper comparison's known difference, or NULL */
};

/* A table column: header, the value it prints (NULL: the header's name) and
 * its printf format for a double; a NaN or missing value is an empty cell.
 * Format "%s" prints the row's text value of that name.  A description
 * lists its columns as one string of words HEADER[=VALUE]:FORMAT
 * ("n:%.0f Emax:%.3e candidates=events:%.0f"), parsed by vfy_parse_columns. */
typedef struct vfy_column {
    const char *header, *value, *format;
} vfy_column;

/* The columns of spec into *cols (count of them in *ncols; the strings
 * point into *text; free both).  Returns 0, or -1 with msg naming the word
 * that is not HEADER[=VALUE]:FORMAT (or out of memory). */
int vfy_parse_columns(const char *spec, vfy_column **cols, size_t *ncols, char **text,
                      char *msg, size_t msglen);

/* The cost columns most tables end with. */
#define VFY_COST_COLUMNS "cpu_s:%.2f wall_s:%.2f events:%.0f ns_per_event:%.1f"

/* A value the paper prints for each row (NAN where it prints none). */
typedef struct vfy_paper_column {
    const char *name;
    size_t count;
    const double *v;
} vfy_paper_column;

/* A description's list of strings, NULL-terminated: VFY_LIST("a", "b"). */
#define VFY_LIST(...) ((const char *const[]){__VA_ARGS__, NULL})

/* One swept key: the scene key, its values ("64 256 1024": one value a row,
 * separated by spaces) and the name of the value in the row (NULL: the
 * key's part after the dot). */
typedef struct vfy_sweep_key {
    const char *key, *values, *name;
} vfy_sweep_key;
/* A sweep's keys, ended by a NULL key: VFY_KEYS({"particles.n", "64 256"}). */
#define VFY_KEYS(...) ((const vfy_sweep_key[]){__VA_ARGS__, {NULL, NULL, NULL}})

/* A sweep: rows of settings.  Each of `keys` takes its value list; the keys
 * are zipped (row i takes the i-th value of each), or with `grid` every
 * combination (the first key slowest).  `sets` holds settings every row
 * takes ("particles.ensembles=2000;scene.t_end=4").  Instead of keys, `rows`
 * may list the rows explicitly, each "LABEL: SET;SET;..." ({label} in
 * templates); in sets and rows, "scene=STEM" takes the row from scene file
 * STEM instead of the description's, and "$NAME=VALUE" gives the row a value
 * NAME that is no scene key (a number, or else a text for templates and
 * "%s" columns).  None of these has a limit of count or length. */
typedef struct vfy_sweep {
    const vfy_sweep_key *keys;   /* terminated by a NULL key; NULL: none */
    int grid;
    const char *sets;
    const char *const *rows;     /* NULL-terminated */
} vfy_sweep;

/* The number of rows of a sweep, and row i's value of key k (in buf, len
 * bytes: truncated to fit). */
size_t vfy_sweep_rows(const vfy_sweep *s);
void vfy_sweep_value(const vfy_sweep *s, size_t i, size_t k, char *buf, size_t len);

typedef enum vfy_figure_kind {
    VFY_FIGURE_NONE,
    VFY_FIGURE_CURVES,   /* a series against t per row, with its confidence band,
                            beside reference lines */
    VFY_FIGURE_POINTS,   /* values against a row value (one point a row), with
                            error bars, beside value references as lines */
    VFY_FIGURE_ROW_CURVES,   /* curves a row makes (vfy_curve_fn), as lines */
    VFY_FIGURE_ROW_POINTS,   /* curves a row makes, the data as points with error
                                bars, the references as lines */
} vfy_figure_kind;

/* A curve a row makes, for a ROW_ figure (paper A's ln f against the speed,
 * paper C's G(c)): count points x, in each panel p its y[p] (NULL: not in
 * that panel) and their half-widths ci[p] (NULL: none), in one allocation
 * at x that the figure frees; its colour and dash (vfy_xy_curve's lc, dt;
 * 0: the figure's default). */
typedef struct vfy_curve {
    size_t count;
    double *x, *y[VFY_XY_PANELS], *ci[VFY_XY_PANELS];
    int lc, dt;
} vfy_curve;

/* Make row's curve into *out; x is the named function's fixed x (named.h),
 * else NaN.  Returns 0; 1 when the row has no such curve (it is left out);
 * -1 when out of memory. */
typedef int (*vfy_curve_fn)(const vfy_case_run *run, const vfy_row *row, double x,
                            vfy_curve *out);

/* Allocate *out (zeroed first) for count points: x, y[0] and, with ci,
 * ci[0]; returns 0, or -1 when out of memory. */
int vfy_curve_alloc(vfy_curve *out, size_t count, int ci);

/* The same for panels p0 .. p1 (p1 < VFY_XY_PANELS): y[p] and ci[p] each. */
int vfy_curve_alloc_panels(vfy_curve *out, size_t count, size_t p0, size_t p1, int ci);

/* One curve of a ROW_ figure, in a list in the order the figure draws them:
 * its label (a template at the row), its function, and whether it is a
 * reference (a model, drawn dashed, without half-widths). */
typedef struct vfy_figure_curve {
    const char *label;
    vfy_curve_fn fn;
    double x;
    int reference;
    const struct vfy_figure_curve *next;
} vfy_figure_curve;

typedef struct vfy_figure_spec {
    vfy_figure_kind kind;
    const char *suffix;              /* the files are <case><suffix>.csv ... ("" or NULL) */
    /* CURVES */
    const char *quantity;            /* the series drawn for every row */
    const char *const *refs;         /* reference series drawn as lines (POINTS: value
                                        references, "LABEL=name" or "name"); VFY_LIST,
                                        or NULL for none */
    double x_from;                   /* the t axis starts here */
    int panel_per_row;               /* one panel per row (every row), or one plot */
    int extrapolated;                /* draw the n = infinity curve too: the O(1/n)
                                        extrapolation of the quantity over the rows
                                        (vfy_run_extrapolate, unless a hook made one) */
    /* POINTS: x is a row value; each series a value with its "_ci" ("LABEL=name"
       or "name"); a row where one of them is not finite is left out.  The
       references are drawn on 81 points of [x_lo, x_hi], each at a copy of the
       last row's scene whose restitution coefficient is x (every value
       reference is a function of it, references.h). */
    const char *x;
    const char *const *series;       /* VFY_LIST, or NULL for none */
    double x_lo, x_hi;
    /* POINTS: group_by names a row value that splits the rows into groups
       (as-steady's "model": ihs, ehs; of several names, "model a_tau0",
       their values joined by a space: "ihs 4"): each series is drawn once
       per group, "LABEL (GROUP)", with a symbol of its own per group and a colour per
       series (with one series, per group), as columns of its own in the
       points file (empty where a row is in another group).  A row's group is
       its text of that name, or else its number (%g).  `groups` lists them
       in order, "GROUP=value" or "value" (VFY_LIST): a row in none of them is
       left out; NULL: every value the rows have, in the order they come,
       labelled by the value.  NULL group_by: one group, unlabelled. */
    const char *group_by;
    const char *const *groups;
    /* ROW_CURVES, ROW_POINTS: the curves (at least one that is no
       reference; ROW_POINTS: the data curves share their x, and so do the
       references), of the last row, or of each row (each_row: one figure a
       row, suffix a template at the row that tells them apart); with
       row_label (a template at the row), each data curve once per row of
       the run, labelled row_label, the references the figure's row's.  Or
       ROW_CURVES of row series (row_label, no curves): every row one curve,
       labelled row_label, against its series x, one panel per item of
       series ("AXIS LABEL=series", with its half-widths in the CSV); a row
       without series x is left out.  ROW_POINTS draws each curve's panel 0,
       without error bars when no data curve has half-widths.  band: the
       data curves' half-widths drawn as a shaded band (ROW_CURVES; else
       only in the CSV); logx, logy: log axes; key_inside: where the key goes,
       in gnuplot's words (ROW_POINTS; NULL: top right). */
    const vfy_figure_curve *curves;
    const char *const *panels;   /* ROW_CURVES: each panel's y label (VFY_LIST, at most
                                    VFY_XY_PANELS), a curve's y[p] drawn in panel p;
                                    NULL: one panel, ylabel */
    const char *only;            /* "NAME=VALUE": only the rows whose value NAME (as
                                    group_by reads it) is VALUE; NULL: every row */
    const char *row_label;
    int each_row, band, logx, logy;
    const char *key_inside;
    const char *title, *xlabel, *ylabel;   /* title: a template (curves:
                                              NULL, the case's title; ROW_: at
                                              the row); curves: ylabel the y
                                              axis's label (NULL: the
                                              quantity's name), no xlabel */
} vfy_figure_spec;
/* A description's figures, ended by one of kind VFY_FIGURE_NONE:
 * VFY_FIGURES({.kind = VFY_FIGURE_CURVES, ...}, {...}). */
#define VFY_FIGURES(...) ((const vfy_figure_spec[]){__VA_ARGS__, {.kind = VFY_FIGURE_NONE}})

/* Change a row's solver scene after it was loaded, for what no setting can
 * say (e.g. simulate the reference scene with another scheme).  Returns
 * SIM_OK or an error with msg. */
typedef sim_status (*vfy_adjust_fn)(const vfy_row *row, sim_scene *solver, char *msg,
                                    size_t msglen);

/* After the rows: cross-row analysis.  May record checks, set case values
 * (run->values) for the notes, set row values (the table is made again
 * after it: a model fitted to every row has its columns), fill a second
 * table (run->second) and write its own files.  Returns SIM_OK or an error
 * with msg. */
typedef sim_status (*vfy_hook_fn)(vfy_case_run *run, vfy_report *r, char *msg, size_t msglen);

/* Seeded batches: count independent runs of each row, the variants "b1" ..
 * "bCOUNT" with $batch = 0 .. count - 1; batch b of row i draws from the
 * solver seed scene seed + seed_stride (i + 1) + b. */
typedef struct vfy_batches {
    size_t count;
    uint64_t seed_stride;
} vfy_batches;

typedef struct vfy_case_desc {
    const char *scene;                  /* scene file stem (NULL: the case's name) */
    const char *paper;                  /* {paper} in templates ("Table 1") */
    vfy_sweep paper_rows, quick_rows;   /* the rows at paper and at quick sizes */
    const char *const *needs;           /* references every row needs (NULL-terminated) */
    const char *needs_why;              /* said when the scene lacks them */
    const char *label;                  /* progress label (NULL: "{case} n={n}";
                                           {variant} names the variant) */
    const char *const *variants;        /* each row simulated once per variant,
                                           "NAME: SET;SET" (NULL-terminated; NULL: once);
                                           the variants after the first have their cost
                                           values as "cpu_s@NAME" ... */
    vfy_batches batches;                /* count > 0: the variants are seeded batches */
    const char *row_progress;           /* printed after each row (a template), or NULL */
    const char *derived;                /* settings derived from value references
                                           (references.h) at the row's scene, or from
                                           the row metrics of that name (evaluated
                                           before the run: one that reads only the
                                           scene and the row's $ values):
                                           "KEY=NAME[:FORMAT] ..." (FORMAT: a printf one,
                                           %.17g when none), applied after the sweep and
                                           before --set and --solver-set, so they never
                                           override what the user fixed; one whose
                                           value is NaN (does not apply) left out; or
                                           NULL */
    const char *require;                /* what the case needs of each row's scenes (both
                                           the references' and the solver's):
                                           vfy_scene_requires words, or NULL */
    const char *require_why;            /* said when one is unmet: "FILE: REQUIRE_WHY" */
    int jump_rows;                      /* rows whose text "scheme" is "jump" simulate
                                           the references' scene with the jump scheme
                                           (vfy_adjust_jump_rows) */
    vfy_adjust_fn adjust;               /* a row's solver scene changed, or NULL */
    const char *const *values;          /* value references (references.h) every row
                                           takes at its scene (NULL-terminated) */
    const char *observes;               /* the base observables the case reads, by
                                           name ("T ux uy uz"): the engine computes
                                           these alone, the others are NaN
                                           (scene.observe_only); NULL: all */
    int no_simulation;                  /* rows evaluate references only */
    const vfy_paper_column *paper_columns;  /* terminated by a NULL name */
    const vfy_partner *partners;        /* the rows metrics compare a row with; terminated
                                           by a NULL name */
    const vfy_metric *metrics;          /* in order; terminated by a NULL name */
    const vfy_check_spec *checks;       /* in order; terminated by a NULL name */
    const vfy_metric *case_metrics;     /* on the case's values, over its rows, before
                                           after_rows (the function's row is NULL);
                                           terminated by a NULL name */
    const char *case_progress;          /* printed after the case's metrics and hook
                                           (a template), or NULL */
    const vfy_check_spec *case_checks;  /* on the case's values, after after_rows (no
                                           row, no guard) */
    const char *columns;                /* "HEADER[=VALUE]:FORMAT ..." (vfy_column) */
    const vfy_figure_spec *figures;     /* VFY_FIGURES, up to the first of kind NONE;
                                           NULL: none */
    const char *title, *notes;          /* templates */
    vfy_hook_fn after_rows;
    const char *must_fail;              /* the errors the case must catch at quick
                                           sizes: "SECTION.KEY=FACTOR ..." (space-
                                           separated), each a relative error of the
                                           solver's value (--perturb); gate.h.  NULL
                                           only with no_simulation */
    const char *power_keys;             /* more "SECTION.KEY=FACTOR" words --power
                                           measures (the direction: FACTOR's side of
                                           1), not required to be caught: the keys a
                                           case is about but too weak to catch at
                                           quick sizes, or NULL */
} vfy_case_desc;

/* ------------------------------------------------------------ the run */

struct vfy_case_run {
    const vfy_case *c;
    const vfy_case_desc *d;
    const vfy_options *o;
    vfy_row *rows;
    size_t nrows;
    vfy_column *columns;   /* the description's, parsed */
    size_t ncols;
    char *column_text;     /* the strings columns point into */
    vfy_values values;     /* the case's values (wall_total, hooks') */
    size_t ntexts;         /* the case's texts a hook set (vfy_run_set_text) */
    char **text_names, **texts;   /* ntexts each, allocated */
    vfy_table table;
    char *comment;         /* provenance: the version, and each row's scene file, seed,
                              n, N and outputs (once where all rows share them);
                              allocated, NULL before the rows are done ({comment}: "") */
    double *extra_mean, *extra_ci;  /* set by a hook (malloc'd, M each): one more
                                       curve in the figure, the n = infinity
                                       extrapolation */
    vfy_table second;      /* a hook's second table (ncols 0: none), written after the
                              first in the Markdown file and as <case><second_suffix>.csv */
    const char *second_suffix, *second_title;
    char *second_notes;    /* its notes (allocated; vfy_run_second_notes), or NULL */
};

/* Set (or replace) the case's text `name` for templates; returns 0, or -1
 * when out of memory. */
int vfy_run_set_text(vfy_case_run *run, const char *name, const char *text);

/* Set the second table's notes, printf-style; returns 0, or -1 when out of
 * memory (the notes are then empty). */
int vfy_run_second_notes(vfy_case_run *run, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* Free what a run owns besides its rows array: its values and texts, the
 * provenance, the tables and notes, the extrapolation, the parsed columns
 * (zeroed members are fine). */
void vfy_run_free(vfy_case_run *run);

/* The O(1/n) extrapolation of series `quantity` at every output time
 * (vfy_extrapolate_inverse_n over the rows, sigma = ci / 3.2): sets
 * run->extra_mean and run->extra_ci (the figure's n = infinity curve), and
 * chi2[m] when chi2 is not NULL.  Returns 0, or -1 when out of memory. */
int vfy_run_extrapolate(vfy_case_run *run, const char *quantity, double *chi2);

/* The number of variants of the description (1 without). */
size_t vfy_variant_count(const vfy_case_desc *d);

/* Variant k of the description, "NAME: SET;SET" (its batches' written into
 * buf, "bK: $batch=K-1"), or NULL for a case without variants. */
const char *vfy_variant_text(const vfy_case_desc *d, size_t k, char *buf, size_t len);

/* Whether every word of d->derived is KEY=NAME[:FORMAT]: KEY a scene key,
 * NAME a row metric of d or a value reference (references.h), FORMAT a
 * printf one; else 0, with the first word that is not at *bad (*badlen
 * characters). The case file loader refuses a description this fails. */
int vfy_derived_check(const vfy_case_desc *d, const char **bad, size_t *badlen);

/* Run a case: fill the report; SIM_OK when it ran (whatever the verdicts),
 * or an error with msg (a bad scene, I/O) when it could not. */
sim_status vfy_run_described(const vfy_case *c, const vfy_options *o, vfy_report *r, char *msg,
                             size_t msglen);

/* Expand template `tmpl` for run and row (row may be NULL: case values
 * only): appended to *out (text.h), whatever its length; returns 0, or -1
 * when out of memory. */
int vfy_expand_text(vfy_text *out, const char *tmpl, const vfy_case_run *run,
                    const vfy_row *row);

/* The expansion as a string the caller frees, or NULL when out of memory. */
char *vfy_expand_alloc(const char *tmpl, const vfy_case_run *run, const vfy_row *row);

/* The expansion into buf (len bytes), truncated to fit; returns buf.  For a
 * line whose length the caller bounds; everything a report keeps uses the
 * two above. */
const char *vfy_expand(char *buf, size_t len, const char *tmpl, const vfy_case_run *run,
                       const vfy_row *row);

/* An adjust hook (vfy_adjust_fn): a row whose text "scheme" is "jump"
 * simulates the scene the references describe (no --solver-set) with the
 * exact jump scheme, the reference the time-step rows (the solver under
 * test) are measured against (docs/theory.md §8.5). */
sim_status vfy_adjust_jump_rows(const vfy_row *row, sim_scene *solver, char *msg,
                                size_t msglen);

/* ------------------------------------------------------------ rules */

/* value within tol relative of expected (vfy_check_relative). */
vfy_rule_func vfy_rule_relative;
/* lo <= value <= hi (vfy_check_range). */
vfy_rule_func vfy_rule_range;
/* |value - expected| <= tol + rtol |expected| + plus + (quick sizes only)
 * plus_quick (vfy_check_absolute; the terms not given are left out). */
vfy_rule_func vfy_rule_absolute;
/* value == expected (or x), integers (vfy_check_count). */
vfy_rule_func vfy_rule_count;
/* Majorant violations: value == 0 (vfy_rule_count), or at most the bound an
 * external solver declared in its result ("# violations_allowed = K",
 * docs/solver-protocol.md), the row's value violations_allowed. */
vfy_rule_func vfy_rule_violations;
/* Series value against series expected from output `from` on: max |z| <=
 * tol (vfy_check_zscore); value `out` becomes the largest max |z| of the
 * checks that name it on this row. */
vfy_rule_func vfy_rule_zscore;
/* As vfy_rule_zscore for two independent estimates (two simulations): the
 * half-widths of value and expected in quadrature. */
vfy_rule_func vfy_rule_zscore_pair;

/* value within half a unit of the last of `tol` printed decimals of expected
 * (or x), plus value `plus` (its half-width) when given (vfy_check_printed). */
vfy_rule_func vfy_rule_printed;

/* ------------------------------------------------------------ guards */

/* Judged while value a <= x; else SKIP. */
vfy_guard_func vfy_guard_at_most;
/* Judged while value a <= x; else omitted. */
vfy_guard_func vfy_guard_only_at_most;
/* Judged while value a >= x; else SKIP. */
vfy_guard_func vfy_guard_at_least;
/* Judged while value a >= x; else omitted. */
vfy_guard_func vfy_guard_only_at_least;
/* Judged unless value a is positive (a row marked "$a=1"); then SKIP. */
vfy_guard_func vfy_guard_unless;
/* Judged unless value a is positive; then omitted (another check, with a
 * known difference, judges that row). */
vfy_guard_func vfy_guard_only_unless;
/* Judged at paper sizes; at quick sizes SKIP (what only the papers' sizes
 * resolve). */
vfy_guard_func vfy_guard_paper_sizes;
/* Omitted on the first row (a ratio to the previous row). */
vfy_guard_func vfy_guard_after_first;
/* Omitted on the first row; judged when value a exceeds x times value b on
 * this row and on the previous one ("clean": the error well above the
 * noise); else SKIP. */
vfy_guard_func vfy_guard_clean_pair;

#endif
