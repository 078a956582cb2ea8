#include "figure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "table.h"
#include "text.h"

enum { PATH_LEN = 1024, TMP_LEN = 1100 };   /* a report file's path, and its .tmp */
enum { POINTS_KEY_INSIDE = 6 };   /* the most entries a points figure's key has on the plot */

/* Colour k of VFY_FIGURE_COLOURS (figure.h), 1-based. */
static const char *palette(int k)
{
    static const char *const colour[VFY_FIGURE_COLOURS] = {
        "#0072b2", "#d55e00", "#cc79a7", "#e69f00", "#56b4e9", "#009e73", "#000000", "#999999"};
    return colour[(size_t)(k > 0 ? k - 1 : 0) % VFY_FIGURE_COLOURS];
}

int vfy_gnuplot(const char *script_path)
{
    if (!vfy_writes_files())   /* another process (MPI rank 0) draws it */
        return 0;
    if (system("command -v gnuplot >/dev/null 2>&1") != 0)
        return 0;
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "gnuplot '%s' 2>/dev/null", script_path);
    int status = system(cmd);
    return status == 0 ? 1 : -1;
}

/* Report file `name` `suffix` of o (its path into path), begun as
 * vfy_file_begin does, the provenance comment lines first. */

/* s as the inside of a gnuplot single-quoted string ('' is a quote), in one
 * of four rotating buffers (a script line names up to four texts), each
 * grown to the text's length; "" when out of memory. */
static const char *gp_text(const char *s)
{
    static char *ring[4];
    static size_t cap[4];
    static unsigned next;
    const unsigned r = next++ % 4;
    const size_t need = 2 * strlen(s) + 1;   /* every character doubled, at most */
    if (need > cap[r]) {
        char *grown = realloc(ring[r], need);
        if (grown == NULL)
            return "";
        ring[r] = grown;
        cap[r] = need;
    }
    char *out = ring[r];
    size_t k = 0;
    for (; *s; s++) {
        if (*s == '\'')
            out[k++] = '\'';
        out[k++] = *s;
    }
    out[k] = '\0';
    return out;
}

static FILE *begin_file(const vfy_options *o, const char *name, const char *suffix,
                        const char *comment, char *path, size_t pathlen, char *tmp,
                        size_t tmplen)
{
    FILE *f = vfy_file_begin(vfy_report_path(o, name, suffix, path, pathlen), tmp, tmplen);
    if (f != NULL)
        vfy_write_comment(f, comment);
    return f;
}

/* Begin the gnuplot script `name`.gp of o (its path into gp[PATH_LEN]): the
 * provenance comment, "# HEADING: gnuplot PATH", and a width x height PNG
 * terminal writing `name`.png, reading comma-separated data.  gp and tmp
 * hold PATH_LEN and TMP_LEN characters. */
static FILE *begin_script(const vfy_options *o, const char *name, const char *comment,
                          const char *heading, int width, int height, char *gp, char *tmp)
{
    char png[PATH_LEN];
    FILE *f = begin_file(o, name, ".gp", comment, gp, PATH_LEN, tmp, TMP_LEN);
    if (f != NULL)
        fprintf(f, "# %s: gnuplot %s\nset terminal pngcairo size %d,%d font ',10'\n"
                   "set termoption noenhanced\nset output '%s'\nset datafile separator ','\n",
                heading, gp, width, height, vfy_report_path(o, name, ".png", png, sizeof png));
    return f;
}

/* Commit the gnuplot script begun as tmp to gp and render it (a failure of
 * gnuplot itself is only noted). */
static int finish_script(const vfy_options *o, FILE *f, const char *tmp, const char *gp)
{
    if (vfy_file_commit(f, tmp, gp, 1) != 0)
        return -1;
    if (vfy_gnuplot(gp) < 0 && o->progress)
        fprintf(o->progress, "   note: gnuplot failed on %s\n", gp);
    return 0;
}

/* The header line of a points or theory file: x, then each name (and, with
 * ci, its "NAME_ci"), each a CSV field (quoted where a label has a comma). */
static void csv_header(FILE *out, const char *x, const char *const *names, size_t count, int ci)
{
    vfy_csv_field(out, x);
    for (size_t j = 0; j < count; j++) {
        fputc(',', out);
        vfy_csv_field(out, names[j]);
        if (ci) {
            char *name_ci = vfy_aprintf("%s_ci", names[j]);
            fputc(',', out);
            vfy_csv_field(out, name_ci != NULL ? name_ci : "");
            free(name_ci);
        }
    }
    fputc('\n', out);
}

int vfy_write_points(const vfy_options *o, const vfy_points *f)
{
    char points[PATH_LEN], theory[PATH_LEN], gp[PATH_LEN], tmp[TMP_LEN], file[256];
    snprintf(file, sizeof file, "%s-points", f->name);
    FILE *out = begin_file(o, file, ".csv", f->comment, points, sizeof points, tmp, sizeof tmp);
    if (out == NULL)
        return -1;
    csv_header(out, f->xlabel, f->series, f->nseries, 1);
    for (size_t i = 0; i < f->npoints; i++) {
        fprintf(out, "%.10g", f->x[i]);
        for (size_t j = 0; j < f->nseries; j++)
            if (isfinite(f->y[j][i]))
                fprintf(out, ",%.10g,%.6g", f->y[j][i], f->ci[j][i]);
            else
                fputs(",,", out);   /* not in this series (another group's point) */
        fputc('\n', out);
    }
    if (vfy_file_commit(out, tmp, points, 1) != 0)
        return -1;
    snprintf(file, sizeof file, "%s-theory", f->name);
    out = begin_file(o, file, ".csv", f->comment, theory, sizeof theory, tmp, sizeof tmp);
    if (out == NULL)
        return -1;
    csv_header(out, f->xlabel, f->curves, f->ncurves, 0);
    for (size_t i = 0; i < f->nfine; i++) {
        fprintf(out, "%.10g", f->xfine[i]);
        for (size_t j = 0; j < f->ncurves; j++)
            fprintf(out, ",%.10g", f->yfine[j][i]);
        fputc('\n', out);
    }
    if (vfy_file_commit(out, tmp, theory, 1) != 0)
        return -1;

    /* a key of more than POINTS_KEY_INSIDE entries beside the plot, not on it */
    const int outside = f->nseries + f->ncurves > POINTS_KEY_INSIDE;
    out = begin_script(o, f->name, f->comment, f->title, outside ? 1200 : 900, 650, gp, tmp);
    if (out == NULL)
        return -1;
    /* offsets: no point on the frame, its error bar hidden in the axis */
    fprintf(out, "set title '%s'\nset xlabel '%s'\nset ylabel '%s'\nset key %s\n"
                 "set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05\n%s"
                 "plot",
            gp_text(f->title), gp_text(f->xlabel), gp_text(f->ylabel),
            outside ? "outside right top" : f->key_inside ? f->key_inside : "top right",
            /* '%g': gnuplot's own format prints 100.0000000 on a log axis of
               many decades */
            f->logx && f->logy ? "set logscale xy\nset format xy '%g'\n"
            : f->logy          ? "set logscale y\nset format y '%g'\n"
            : f->logx          ? "set logscale x\nset format x '%g'\n"
                               : "");
    for (size_t j = 0; j < f->ncurves; j++)
        fprintf(out, "%s '%s' skip 1 using 1:%zu with lines lw 2 dt %zu title '%s'",
                j ? "," : "", theory, j + 2, j + 1, gp_text(f->curves[j]));
    const char *bars = f->bars != NULL ? f->bars : VFY_CI_LEGEND;
    for (size_t j = 0; j < f->nseries; j++) {
        fprintf(out, "%s '%s' skip 1 using 1:%zu:%zu with yerrorbars pt %d",
                f->ncurves || j ? "," : "", points, 2 + 2 * j, 3 + 2 * j,
                f->pt != NULL ? f->pt[j] : 5 + 2 * (int)j);
        /* the project's colours, not gnuplot's (its third and fifth are light
           blue and yellow) */
        fprintf(out, " lc rgb '%s'", palette(f->lc != NULL ? f->lc[j] : 1 + (int)j));
        fprintf(out, " title '%s%s%s'", gp_text(f->series[j]), *bars ? " " : "", gp_text(bars));
    }
    fputc('\n', out);
    return finish_script(o, out, tmp, gp);
}


/* A grid's column k of f (a title for the data's comments). */
static const char *xy_column_title(const vfy_xy_figure *f, size_t k)
{
    return f->ncolumns > 1 && f->column_title != NULL && f->column_title[k] != NULL
               ? f->column_title[k]
               : "";
}

/* Panel p's y axis label. */
static const char *axis_label(const vfy_xy_figure *f, size_t p)
{
    return f->yaxis[p] != NULL ? f->yaxis[p] : f->ylabel[p];
}

/* How an xy script reads a cell of <name>-curves.csv: an empty one (a y the
 * curve has no value for, such as an empty histogram bin) is a gap that
 * breaks the curve's line. Read as a column gnuplot would skip the row and
 * draw the line across; read as a string it is undefined there. */
#define XY_CELL "cell(k) = strlen(strcol(k)) ? real(strcol(k)) : NaN\n"

/* <name>-curves.csv of vfy_write_xy, its path into data. */
static int xy_data(const vfy_options *o, const vfy_xy_figure *f, char *data)
{
    char tmp[TMP_LEN], file[256];
    snprintf(file, sizeof file, "%s-curves", f->name);
    FILE *out = begin_file(o, file, ".csv", f->comment, data, PATH_LEN, tmp, sizeof tmp);
    if (out == NULL)
        return -1;
    fprintf(out, "# %s: one block per curve (gnuplot index)\n# %s", f->name, f->xlabel);
    for (size_t p = 0; p < f->npanels; p++)
        fprintf(out, ",%s,%s_ci", f->ylabel[p], f->ylabel[p]);
    fputc('\n', out);
    for (size_t j = 0; j < f->ncurves; j++) {
        const vfy_xy_curve *c = &f->curves[j];
        const char *column = f->ncolumns > 1 ? xy_column_title(f, c->column) : "";
        fprintf(out, "%s# %s%s%s\n", j ? "\n\n" : "", column, *column ? ": " : "", c->label);
        for (size_t i = 0; i < c->count; i++) {
            if (!isfinite(c->x[i]))
                continue;
            fprintf(out, "%.8g", c->x[i]);
            for (size_t p = 0; p < f->npanels; p++) {
                const double y = c->y[p] ? c->y[p][i] : NAN, ci = c->ci[p] ? c->ci[p][i] : 0.0;
                if (isfinite(y))
                    fprintf(out, ",%.8g,%.4g", y, ci);
                else
                    fputs(",,", out);
            }
            fputc('\n', out);
        }
    }
    return vfy_file_commit(out, tmp, data, 1);
}

/* Whether curve c has a gap, a y it has no value for between two it has
 * (in any of the figure's panels). */
static int xy_has_gap(const vfy_xy_figure *f, const vfy_xy_curve *c)
{
    for (size_t p = 0; p < f->npanels; p++) {
        int seen = 0, missing = 0;
        for (size_t i = 0; c->y[p] != NULL && i < c->count; i++) {
            if (!isfinite(c->x[i]))
                continue;
            if (!isfinite(c->y[p][i]))
                missing = seen;
            else if (missing)
                return 1;
            else
                seen = 1;
        }
    }
    return 0;
}

/* XY_CELL, where one of f's curves has a gap. */
static void xy_cell(FILE *out, const vfy_xy_figure *f)
{
    for (size_t j = 0; j < f->ncurves; j++)
        if (xy_has_gap(f, &f->curves[j])) {
            fputs(XY_CELL, out);
            return;
        }
}

/* Curve j's style: "with lines lw .. dt .. lc .. title '..'" (notitle
 * unless titled); a curve with gaps also marks its points, so that a value
 * between two gaps (a lone histogram bin) is seen. */
static void xy_style(FILE *out, const vfy_xy_figure *f, size_t j, int titled)
{
    const vfy_xy_curve *c = &f->curves[j];
    const int dt = c->dt > 0 ? c->dt : c->reference ? 2 : 1;
    fprintf(out, "with %s lw %s dt %d ", xy_has_gap(f, c) ? "linespoints pt 7 ps 0.3" : "lines",
            c->reference ? "2" : "1.5", dt);
    if (c->lc > 0)
        fprintf(out, "lc rgb '%s'", palette(c->lc));
    else
        fprintf(out, "lc %zu", 1 + j % 8);
    if (titled)
        fprintf(out, " title '%s'", gp_text(c->label));
    else
        fputs(" notitle", out);
}

/* Curve j of f in panel p: " 'data' index j using 1:COL with lines ...",
 * its columns read through cell() (XY_CELL) where it has gaps. */
static void xy_plot_curve(FILE *out, const vfy_xy_figure *f, const char *data, size_t j,
                          size_t p, int titled)
{
    const vfy_xy_curve *c = &f->curves[j];
    const int gaps = xy_has_gap(f, c);
    const size_t y = 2 + 2 * p, ci = 3 + 2 * p;
    if (c->band && c->ci[p] != NULL) {   /* the band first, under its curve */
        if (gaps)
            fprintf(out, " '%s' index %zu using 1:(cell(%zu)-cell(%zu)):(cell(%zu)+cell(%zu)) ",
                    data, j, y, ci, y, ci);
        else
            fprintf(out, " '%s' index %zu using 1:($%zu-$%zu):($%zu+$%zu) ", data, j, y, ci, y,
                    ci);
        fputs("with filledcurves fs transparent solid 0.25 noborder ", out);
        if (c->lc > 0)
            fprintf(out, "lc rgb '%s' notitle,", palette(c->lc));
        else
            fprintf(out, "lc %zu notitle,", 1 + j % 8);
    }
    fprintf(out, gaps ? " '%s' index %zu using 1:(cell(%zu)) " : " '%s' index %zu using 1:%zu ",
            data, j, y);
    xy_style(out, f, j, titled);
}

/* The smallest and largest finite y of panel p over every curve (lo > hi:
 * none). */
static void xy_panel_range(const vfy_xy_figure *f, size_t p, double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (size_t j = 0; j < f->ncurves; j++) {
        const vfy_xy_curve *c = &f->curves[j];
        for (size_t i = 0; c->y[p] != NULL && i < c->count; i++)
            if (isfinite(c->x[i]) && isfinite(c->y[p][i]) && (!f->logy || c->y[p][i] > 0.0)) {
                *lo = fmin(*lo, c->y[p][i]);
                *hi = fmax(*hi, c->y[p][i]);
            }
    }
}

/* The grid's place on the page (screen coordinates): the panels between
 * GRID_LEFT and GRID_RIGHT, GRID_BOTTOM and GRID_TOP, GRID_DX and GRID_DY
 * apart; the key in a strip of its own below them, up to GRID_KEY. */
#define GRID_LEFT 0.065
#define GRID_RIGHT 0.985
#define GRID_BOTTOM 0.1
#define GRID_TOP 0.915
#define GRID_DX 0.035
#define GRID_DY 0.065
#define GRID_KEY 0.04

/* Panel (p, k) of the grid: its place, title and axis labels. */
static void xy_grid_panel(FILE *out, const vfy_xy_figure *f, size_t p, size_t k)
{
    const double w = (GRID_RIGHT - GRID_LEFT - (double)(f->ncolumns - 1) * GRID_DX)
                     / (double)f->ncolumns;
    const double h = (GRID_TOP - GRID_BOTTOM - (double)(f->npanels - 1) * GRID_DY)
                     / (double)f->npanels;
    const double left = GRID_LEFT + (double)k * (w + GRID_DX);
    const double top = GRID_TOP - (double)p * (h + GRID_DY);
    fprintf(out, "set lmargin at screen %.4f\nset rmargin at screen %.4f\n"
                 "set tmargin at screen %.4f\nset bmargin at screen %.4f\n",
            left, left + w, top, top - h);
    fprintf(out, "set title '%s'\nset xlabel '%s'\nset ylabel '%s'\n",
            p == 0 ? gp_text(xy_column_title(f, k)) : "",
            p + 1 == f->npanels ? gp_text(f->xlabel) : "", k == 0 ? gp_text(axis_label(f, p)) : "");
}

/* The grid of vfy_write_xy (f->ncolumns > 1), then its key: the first
 * panel's curves, drawn once across the page below the panels. */
static void xy_grid(FILE *out, const vfy_xy_figure *f, const char *data)
{
    xy_cell(out, f);
    fprintf(out, "set datafile missing ''\nset multiplot title '%s'\n%s%s"
                 "set key off\nset grid\n",
            gp_text(f->title), f->logx ? "set logscale x\n" : "",
            f->logy ? "set logscale y\nset format y '%g'\n" : "");
    for (size_t p = 0; p < f->npanels; p++) {
        double lo, hi;
        xy_panel_range(f, p, &lo, &hi);
        const double pad = f->logy ? 0.0 : 0.05 * (hi - lo);
        if (lo < hi)   /* the panels of a row on one scale */
            fprintf(out, "set yrange [%.6g:%.6g]\n", f->logy ? lo / 1.2 : lo - pad,
                    f->logy ? hi * 1.2 : hi + pad);
        else
            fputs("set autoscale y\n", out);
        for (size_t k = 0; k < f->ncolumns; k++) {
            xy_grid_panel(out, f, p, k);
            fputs("plot", out);
            int first = 1;
            for (size_t j = 0; j < f->ncurves; j++) {
                if (f->curves[j].y[p] == NULL || f->curves[j].column != k)
                    continue;
                fputs(first ? "" : ",", out);
                xy_plot_curve(out, f, data, j, p, 0);
                first = 0;
            }
            fputs(first ? " NaN notitle\n" : "\n", out);   /* an empty panel keeps its place */
        }
    }
    fprintf(out, "set lmargin at screen %g\nset rmargin at screen %g\nset bmargin at screen 0\n"
                 "set tmargin at screen %g\nunset title\nunset xlabel\nunset ylabel\n"
                 "unset border\nunset tics\nunset grid\nunset logscale\nset xrange [0:1]\n"
                 "set yrange [0:1]\nset key on center center horizontal samplen 4\nplot",
            GRID_LEFT, GRID_RIGHT, GRID_KEY);
    int first = 1;
    for (size_t j = 0; j < f->ncurves; j++) {
        if (f->curves[j].y[0] == NULL || f->curves[j].column != 0)
            continue;
        fputs(first ? " NaN " : ", NaN ", out);
        xy_style(out, f, j, 1);
        first = 0;
    }
    fputs(first ? " NaN notitle\n" : "\n", out);
}

int vfy_write_xy(const vfy_options *o, const vfy_xy_figure *f)
{
    char data[PATH_LEN], gp[PATH_LEN], tmp[TMP_LEN];
    if (xy_data(o, f, data) != 0)
        return -1;
    const int grid = f->ncolumns > 1;
    FILE *out = begin_script(o, f->name, f->comment, f->title,
                             grid ? 360 * (int)f->ncolumns + 140 : 1000,
                             grid ? 300 * (int)f->npanels + 120 : 330 * (int)f->npanels + 60,
                             gp, tmp);
    if (out == NULL)
        return -1;
    if (grid) {
        xy_grid(out, f, data);
        fputs("unset multiplot\n", out);
        return finish_script(o, out, tmp, gp);
    }
    /* offsets: a reference line at the data's extreme is not drawn on the border */
    xy_cell(out, f);
    fprintf(out, "set datafile missing ''\nset multiplot layout %zu,1 title '%s'\n%s%s"
                 "set key outside right top\nset grid\nset offsets 0, 0, graph 0.05, graph 0.05\n",
            f->npanels, gp_text(f->title), f->logx ? "set logscale x\n" : "",
            f->logy ? "set logscale y\nset format y '%g'\n" : "");
    for (size_t p = 0; p < f->npanels; p++) {
        fprintf(out, "set xlabel '%s'\nset ylabel '%s'\nplot", gp_text(f->xlabel),
                gp_text(axis_label(f, p)));
        int first = 1;
        for (size_t j = 0; j < f->ncurves; j++) {
            if (f->curves[j].y[p] == NULL)
                continue;
            fputs(first ? "" : ",", out);
            xy_plot_curve(out, f, data, j, p, 1);
            first = 0;
        }
        fputc('\n', out);
    }
    fputs("unset multiplot\n", out);
    return finish_script(o, out, tmp, gp);
}

const double vfy_wp_targets[VFY_WP_TARGETS] = {1e-2, 1e-3, 1e-4};

void vfy_wp_prediction_free(vfy_wp_prediction *pred)
{
    for (size_t k = 0; k < pred->count; k++)
        free(pred->label[k]);
    *pred = (vfy_wp_prediction){0};
}

int vfy_write_work_precision(const vfy_options *o, const char *name, const char *title,
                             const char *comment, const char *ylabel, const vfy_wp_series *series, size_t nseries,
                             const double *cpu, const double *err, const double *model,
                             const char *const *labels, const vfy_wp_prediction *pred)
{
    char data[PATH_LEN], gp[PATH_LEN], tmp[TMP_LEN], file[200];
    snprintf(file, sizeof file, "%s-points", name);
    FILE *f = begin_file(o, file, ".csv", comment, data, sizeof data, tmp, sizeof tmp);
    if (f == NULL)
        return -1;
    fprintf(f, "# %s: work-precision points, one block per curve (gnuplot index)\n"
               "# cpu_s,Err,Err_model,label\n", name);
    for (size_t s = 0; s < nseries; s++) {
        fprintf(f, "%s# %s\n", s ? "\n\n" : "", series[s].title);
        for (size_t k = 0; k < series[s].count; k++) {
            size_t i = series[s].idx[k];
            fprintf(f, "%.6g,%.6g,%.6g,%s\n", cpu[i], err[i], model[i], labels[i]);
        }
    }
    fprintf(f, "\n\n# the model's cheapest point per target (predictions)\n");
    for (size_t k = 0; k < pred->count; k++)
        fprintf(f, "%.6g,%.6g,%.6g,%s\n", pred->cpu[k], pred->err[k], pred->err[k],
                pred->label[k] ? pred->label[k] : "");
    if (vfy_file_commit(f, tmp, data, 1) != 0)
        return -1;
    f = begin_script(o, name, comment, name, 1100, 750, gp, tmp);
    if (f == NULL)
        return -1;
    fprintf(f, "set title '%s'\nset xlabel 'CPU seconds (all threads)'\n"
               "set ylabel '%s'\nset logscale xy\nset format y '%%.0e'\n"
               /* the key below: its prediction entries are long */
               "set grid\nset key below center maxcols 2 samplen 3\n"
               /* room for the labels of the points at the edges */
               "set offsets graph 0.04, graph 0.12, graph 0.1, graph 0.04\n"
               "set label 1 'dotted: the model' at graph 0.02, graph 0.04\nplot",
            gp_text(title), gp_text(ylabel));
    for (size_t s = 0; s < nseries; s++) {   /* each series its colour of the palette */
        const char *lc = palette(1 + (int)s);
        fprintf(f, "%s '%s' index %zu using 1:2 with linespoints pt 7 ps 1.1 lw 2 lc rgb '%s' "
                   "title '%s', '' index %zu using 1:3 with lines dt 3 lw 2 lc rgb '%s' notitle, "
                   "'' index %zu using 1:2:4 with labels offset 0.6,0.7 font ',7' left "
                   "tc rgb '%s' notitle",
                s ? "," : "", data, s, lc, gp_text(series[s].title), s, lc, s, lc);
    }
    /* each prediction its open marker and its key entry (labels in the plot
     * crossed the series where they crowd) */
    static const int pred_pt[VFY_WP_TARGETS] = {6, 4, 8};
    for (size_t k = 0; k < pred->count; k++)
        fprintf(f, ", '%s' index %zu every ::%zu::%zu using 1:2 with points pt %d ps 2.2 lw 2 "
                   "lc rgb 'black' title 'predicted cheapest (model), %s'",
                data, nseries, k, k, pred_pt[k],
                gp_text(pred->label[k] ? pred->label[k] : ""));
    for (size_t i = 0; i < VFY_WP_TARGETS; i++)
        fprintf(f, ", %g with lines dt 2 lc rgb 'gray50' %s", vfy_wp_targets[i],
                i ? "notitle" : "title 'targets 1e-2, 1e-3, 1e-4'");
    fputc('\n', f);
    return finish_script(o, f, tmp, gp);
}

/* The colours of vfy_write_curves' rows, then the same dashed. */
#define CURVES_COLOURS 6

int vfy_write_curves(const vfy_options *o, const char *name, const char *title,
                     const char *comment,
                        const double *t, size_t M, size_t nref, const char *const *ref_names,
                        const double *const *refs, size_t rows, const size_t *n,
                        const char *const *labels, const double *mean, const double *ci,
                        const char *quantity, const char *ylabel, double x_from, int one_panel_per_row)
{
    char path[PATH_LEN], tmp[TMP_LEN];
    FILE *f = begin_file(o, name, "-curves.csv", comment, path, sizeof path, tmp, sizeof tmp);
    if (f == NULL)
        return -1;
    fprintf(f, "t");
    for (size_t j = 0; j < nref; j++)
        fprintf(f, ",%s", ref_names[j]);
    for (size_t i = 0; i < rows; i++) {
        if (n[i] == 0)   /* the O(1/n) extrapolation */
            fprintf(f, ",%s_ninf,%s_ninf_ci", quantity, quantity);
        else
            fprintf(f, ",%s_n%zu,%s_n%zu_ci", quantity, n[i], quantity, n[i]);
    }
    fputc('\n', f);
    for (size_t m = 0; m < M; m++) {
        fprintf(f, "%.10g", t[m]);
        for (size_t j = 0; j < nref; j++)
            fprintf(f, ",%.12g", refs[j][m]);
        for (size_t i = 0; i < rows; i++)
            fprintf(f, ",%.12g,%.6g", mean[i * M + m], ci[i * M + m]);
        fputc('\n', f);
    }
    if (vfy_file_commit(f, tmp, path, 1) != 0)
        return -1;

    /* one panel per row: 2 x 2 for up to four rows, two columns of as many
     * lines as the rows need beyond */
    const size_t panels = one_panel_per_row ? rows : 1;
    const size_t lines = panels <= 4 ? 2 : (panels + 1) / 2;
    char gp[PATH_LEN];
    f = begin_script(o, name, comment, title, 1200,
                     !one_panel_per_row ? 700 : panels <= 4 ? 900 : 450 * (int)lines, gp, tmp);
    if (f == NULL)
        return -1;
    /* more rows in one panel than colours: the key beside the plot, its
     * entries the rows' lines (each colour's second round dashed), not
     * their bands */
    const int crowded = !one_panel_per_row && rows > CURVES_COLOURS;
    fprintf(f, "set xrange [%g:*]\nset xlabel 't'\nset ylabel '%s'\nset key %s\n", x_from,
            gp_text(ylabel != NULL ? ylabel : quantity),
            crowded ? "outside right top" : "below");   /* off the curves */
    if (one_panel_per_row)
        fprintf(f, "set multiplot layout %zu,2 title '%s'\n", lines, gp_text(title));
    else
        fprintf(f, "set title '%s'\n", gp_text(title));
    for (size_t p = 0; p < panels; p++) {
        size_t first = one_panel_per_row ? p : 0, last = one_panel_per_row ? p + 1 : rows;
        if (one_panel_per_row)
            fprintf(f, "set title 'n = %zu'\n", n[p]);
        fprintf(f, "plot");
        for (size_t j = 0; j < nref; j++)   /* black, each its dash type */
            fprintf(f, "%s '%s' skip 1 using 1:%zu with lines dt %zu lw 2 lc rgb '%s' "
                       "title '%s'",
                    j ? "," : "", path, 2 + j, 2 + j, palette(7), gp_text(ref_names[j]));
        for (size_t i = first; i < last; i++) {
            size_t col = 2 + nref + 2 * i;
            char *label = labels != NULL ? vfy_aprintf("%s: mean %s", labels[i], VFY_CI_LEGEND)
                          : n[i] == 0 ? vfy_aprintf("n = infinity (O(1/n) extrapolation) %s",
                                                    VFY_CI_LEGEND)
                                      : vfy_aprintf("n = %zu: mean %s", n[i], VFY_CI_LEGEND);
            /* the band, and its mean as a line (a band thinner than a line still shows);
             * six colours, then the lines dashed */
            const char *colour = palette(1 + (int)(i % CURVES_COLOURS));
            const char *text = gp_text(label != NULL ? label : "");
            fprintf(f, "%s '%s' skip 1 using 1:($%zu-$%zu):($%zu+$%zu) with filledcurves "
                       "fs transparent solid 0.25 lc rgb '%s' %s%s%s, '%s' skip 1 using "
                       "1:%zu with lines lw %d dt %zu lc rgb '%s' %s%s%s",
                    nref || i > first ? "," : "", path, col, col + 1, col, col + 1, colour,
                    crowded ? "notitle" : "title '", crowded ? "" : text, crowded ? "" : "'",
                    path, col, crowded ? 2 : 1, 1 + i / CURVES_COLOURS, colour,
                    crowded ? "title '" : "notitle", crowded ? text : "", crowded ? "'" : "");
            free(label);
        }
        fputc('\n', f);
    }
    if (one_panel_per_row)
        fprintf(f, "unset multiplot\n");
    return finish_script(o, f, tmp, gp);
}
