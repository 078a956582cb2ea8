/* Figures with gnuplot (README.md, "What comes out"), when it is installed. */
#ifndef GDSMC_VFY_FIGURE_H
#define GDSMC_VFY_FIGURE_H

#include <stddef.h>

#include "cases.h"

/* What every figure's error bars and confidence bands are, the text their
 * legends end with: the half-width ci = SIM_LAMBDA_P = 3.2 standard errors
 * (sim/ensemble.h; docs/verdicts.md), two-sided p = 0.999 for many
 * ensembles but less for few (the checks then use Student's t), so the
 * legend says the standard errors, not a probability. */
#define VFY_CI_LEGEND "± 3.2 standard errors"

/* The colours a series or curve may name (vfy_points.lc, vfy_xy_curve.lc),
 * 1 to VFY_FIGURE_COLOURS: blue, vermilion, reddish purple, orange, sky
 * blue, bluish green, black, grey (Okabe and Ito's colour-blind safe set
 * without its yellow, in an order whose first colours differ from gnuplot's
 * first linetypes, purple and green, which draw the references). */
#define VFY_FIGURE_COLOURS 8

/* Run `gnuplot script_path` (the script names its own PNG output).  Returns
 * 1 if gnuplot ran and succeeded, 0 if gnuplot is not installed or this
 * process writes no files (vfy_writes_files), -1 if it failed. */
int vfy_gnuplot(const char *script_path);

/* out_dir/<name>-curves.csv (t, the reference columns, then mean and ci of
 * each row; n[i] = 0 marks the O(1/n) extrapolation) and out_dir/<name>.gp
 * drawing each row's confidence band and its mean (a colour per row) beside
 * the references (black, each its dash type) (one panel per row,
 * 2 x 2 for up to four rows and two columns beyond, or all in one), rendered
 * to <name>.png when gnuplot is installed.  mean and ci are rows x M.  Each row is labelled labels[i],
 * or "n = N" when labels is NULL, then ": mean " VFY_CI_LEGEND.  The y axis is labelled
 * ylabel, or the quantity when ylabel is NULL.  Returns 0 or -1 (errno). */
int vfy_write_curves(const vfy_options *o, const char *name, const char *title,
                     const char *comment,
                     const double *t, size_t M, size_t nref, const char *const *ref_names,
                     const double *const *refs, size_t rows, const size_t *n,
                     const char *const *labels, const double *mean, const double *ci,
                     const char *quantity, const char *ylabel, double x_from,
                     int one_panel_per_row);

/* Points against a parameter with error bars, beside theory curves (paper C's
 * figures of a2 against alpha, G(c) against c). */
typedef struct vfy_points {
    const char *name, *title, *xlabel, *ylabel;
    int logy, logx;   /* log scales */
    size_t npoints;
    const double *x;
    size_t nseries;
    const char *const *series;
    const double *const *y, *const *ci;   /* [series][point]; a point whose y is not
                                             finite is an empty cell, not drawn */
    const char *bars;                     /* what the error bars are, each series'
                                             legend ends with it: NULL for
                                             VFY_CI_LEGEND, "" for none (ci all 0) */
    const int *pt, *lc;                   /* [series]: its point type and colour
                                             (1..VFY_FIGURE_COLOURS), or NULL: pt 5 + 2j
                                             and gnuplot's next linetype */
    size_t nfine;
    const double *xfine;
    size_t ncurves;
    const char *const *curves;
    const double *const *yfine;           /* [curve][fine point] */
    const char *comment;                  /* provenance, the files' first lines */
    const char *key_inside;               /* where a key inside the plot goes, in
                                             gnuplot's words ("bottom left"); NULL:
                                             top right */
} vfy_points;

/* <name>-points.csv (x, each series and its confidence half-width),
 * <name>-theory.csv (the curves on their fine grid) and <name>.gp (each
 * series with error bars, its legend "SERIES " VFY_CI_LEGEND; a key of more
 * than 6 series and curves beside the plot), rendered to <name>.png when
 * gnuplot is installed.  Returns 0 or -1 (errno). */
int vfy_write_points(const vfy_options *o, const vfy_points *f);

/* Curves whose abscissa differs from curve to curve (paper E's quantities
 * against the collisions per particle s), in up to VFY_XY_PANELS panels, one
 * quantity each. */
#define VFY_XY_PANELS 4
typedef struct vfy_xy_curve {
    const char *label;
    int reference;                    /* drawn dashed (a model), else solid */
    size_t count;                     /* points; one with a non-finite x or y is left out */
    const double *x;
    const double *y[VFY_XY_PANELS];   /* per panel (NULL: not in that panel) */
    const double *ci[VFY_XY_PANELS];  /* half-widths (NULL: none) */
    int lc;                           /* 1..VFY_FIGURE_COLOURS: its colour; 0: gnuplot's
                                         linetype 1 + k % 8 for curve k */
    int dt;                           /* > 0: its dash type (1 solid, 2 dashed, 3
                                         dotted, 4 dash-dot, 5 dash-dot-dot); 0:
                                         solid, a reference dashed */
    size_t column;                    /* a grid's column (vfy_xy_figure.ncolumns) */
    int band;                         /* 1: ci drawn as a shaded band under the curve
                                         (its label says what the band is); 0: ci
                                         only in the CSV */
} vfy_xy_curve;

typedef struct vfy_xy_figure {
    const char *name, *title, *xlabel, *comment;
    int logx, logy;
    size_t npanels;
    const char *ylabel[VFY_XY_PANELS];   /* each panel's quantity: its CSV columns' name
                                            and, unless yaxis names it, its axis label */
    const char *yaxis[VFY_XY_PANELS];    /* an axis label other than the column's name
                                            ("T/T0" for T_ratio), or NULL */
    size_t ncurves;
    const vfy_xy_curve *curves;
    /* 0 or 1: the panels one above the other, each with every curve and its
     * key.  More: a grid of npanels rows and ncolumns columns, the panel of
     * column k drawing the curves whose column is k, under column_title[k];
     * the panels of a row share their y range, and the key is drawn once,
     * below the grid, from the first panel's curves: every column's curves
     * are told apart the same way (their style and label), the columns by
     * their titles. */
    size_t ncolumns;
    const char *const *column_title;
} vfy_xy_figure;

/* <name>-curves.csv (one gnuplot index block per curve: x, then each panel's
 * y and its half-width; in a grid the block's comment names the column's
 * title before the curve's label) and <name>.gp, the panels one above the
 * other (or the grid), rendered to <name>.png when gnuplot is installed.
 * Returns 0 or -1 (errno). */
int vfy_write_xy(const vfy_options *o, const vfy_xy_figure *f);

/* Work-precision figures (docs/theory.md §1.4): Err against CPU seconds. */
#define VFY_WP_TARGETS 3
extern const double vfy_wp_targets[VFY_WP_TARGETS];   /* 1e-2, 1e-3, 1e-4 */

/* One curve: the points idx[0..count-1] of the arrays, in that order. */
typedef struct vfy_wp_series {
    const char *title;
    const size_t *idx;
    size_t count;
} vfy_wp_series;

/* The model's cheapest point per target (a prediction); each label
 * allocated (NULL: out of memory, drawn without one). */
typedef struct vfy_wp_prediction {
    size_t count;
    double cpu[VFY_WP_TARGETS], err[VFY_WP_TARGETS];
    char *label[VFY_WP_TARGETS];
} vfy_wp_prediction;

/* Free the labels of a prediction. */
void vfy_wp_prediction_free(vfy_wp_prediction *pred);

/* out_dir/<name>-points.csv (one gnuplot index block per series: cpu_s,
 * Err, Err_model, label (labels[i] of point i); then the predictions) and
 * out_dir/<name>.gp: Err against CPU seconds, log-log, each series with its
 * model dotted, the targets as grey lines, the predicted cheapest points as
 * open markers (a circle, a square, a triangle) each named in the key, the
 * axes extended to leave room for the points' labels at the edges; rendered
 * to <name>.png when gnuplot is installed.  Both files start with the
 * comment lines (the provenance).  Returns 0 or -1. */
int vfy_write_work_precision(const vfy_options *o, const char *name, const char *title,
                             const char *comment, const char *ylabel, const vfy_wp_series *series, size_t nseries,
                             const double *cpu, const double *err, const double *model,
                             const char *const *labels, const vfy_wp_prediction *pred);

#endif
