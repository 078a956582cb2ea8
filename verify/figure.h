/* Figures with gnuplot (SPEC §9), when it is installed. */
#ifndef GDSMC_VFY_FIGURE_H
#define GDSMC_VFY_FIGURE_H

#include <stddef.h>

#include "cases.h"

/* Run `gnuplot script_path` (the script names its own PNG output).  Returns
 * 1 if gnuplot ran and succeeded, 0 if gnuplot is not installed or this
 * process writes no files (vfy_writes_files), -1 if it failed. */
int vfy_gnuplot(const char *script_path);

/* Points against a parameter with error bars, beside theory curves (paper C's
 * figures of a2 against alpha, G(c) against c). */
typedef struct vfy_points {
    const char *name, *title, *xlabel, *ylabel;
    int logy;
    size_t npoints;
    const double *x;
    size_t nseries;
    const char *const *series;
    const double *const *y, *const *ci;   /* [series][point] */
    size_t nfine;
    const double *xfine;
    size_t ncurves;
    const char *const *curves;
    const double *const *yfine;           /* [curve][fine point] */
    const char *comment;                  /* provenance, the files' first lines */
} vfy_points;

/* <name>-points.csv (x, each series and its confidence half-width),
 * <name>-theory.csv (the curves on their fine grid) and <name>.gp, rendered
 * to <name>.png when gnuplot is installed.  Returns 0 or -1 (errno). */
int vfy_write_points(const vfy_options *o, const vfy_points *f);

#endif
