#include "figure.h"

#include <stdio.h>
#include <stdlib.h>
#include <sys/wait.h>

#include "table.h"

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

int vfy_write_points(const vfy_options *o, const vfy_points *f)
{
    char points[1024], theory[1024], gp[1024], png[1024], tmp[1100], file[256];
    snprintf(file, sizeof file, "%s-points", f->name);
    FILE *out = vfy_file_begin(vfy_report_path(o, file, ".csv", points, sizeof points), tmp,
                               sizeof tmp);
    if (out == NULL)
        return -1;
    vfy_write_comment(out, f->comment);
    fprintf(out, "%s", f->xlabel);
    for (size_t j = 0; j < f->nseries; j++)
        fprintf(out, ",%s,%s_ci", f->series[j], f->series[j]);
    fputc('\n', out);
    for (size_t i = 0; i < f->npoints; i++) {
        fprintf(out, "%.10g", f->x[i]);
        for (size_t j = 0; j < f->nseries; j++)
            fprintf(out, ",%.10g,%.6g", f->y[j][i], f->ci[j][i]);
        fputc('\n', out);
    }
    if (vfy_file_commit(out, tmp, points, 1) != 0)
        return -1;
    snprintf(file, sizeof file, "%s-theory", f->name);
    out = vfy_file_begin(vfy_report_path(o, file, ".csv", theory, sizeof theory), tmp,
                         sizeof tmp);
    if (out == NULL)
        return -1;
    vfy_write_comment(out, f->comment);
    fprintf(out, "%s", f->xlabel);
    for (size_t j = 0; j < f->ncurves; j++)
        fprintf(out, ",%s", f->curves[j]);
    fputc('\n', out);
    for (size_t i = 0; i < f->nfine; i++) {
        fprintf(out, "%.10g", f->xfine[i]);
        for (size_t j = 0; j < f->ncurves; j++)
            fprintf(out, ",%.10g", f->yfine[j][i]);
        fputc('\n', out);
    }
    if (vfy_file_commit(out, tmp, theory, 1) != 0)
        return -1;

    out = vfy_file_begin(vfy_report_path(o, f->name, ".gp", gp, sizeof gp), tmp, sizeof tmp);
    if (out == NULL)
        return -1;
    vfy_write_comment(out, f->comment);
    fprintf(out, "# %s: gnuplot %s\nset terminal pngcairo size 900,650 font ',10'\n"
                 "set termoption noenhanced\nset output '%s'\nset datafile separator ','\n"
                 "set title '%s'\nset xlabel '%s'\nset ylabel '%s'\nset key top right\n%s"
                 "plot",
            f->title, gp, vfy_report_path(o, f->name, ".png", png, sizeof png), f->title,
            f->xlabel, f->ylabel, f->logy ? "set logscale y\n" : "");
    for (size_t j = 0; j < f->ncurves; j++)
        fprintf(out, "%s '%s' skip 1 using 1:%zu with lines lw 2 dt %zu title '%s'",
                j ? "," : "", theory, j + 2, j + 1, f->curves[j]);
    for (size_t j = 0; j < f->nseries; j++)
        fprintf(out, "%s '%s' skip 1 using 1:%zu:%zu with yerrorbars pt %zu title '%s ± c'",
                f->ncurves || j ? "," : "", points, 2 + 2 * j, 3 + 2 * j, 5 + 2 * j,
                f->series[j]);
    fputc('\n', out);
    if (vfy_file_commit(out, tmp, gp, 1) != 0)
        return -1;
    if (vfy_gnuplot(gp) < 0 && o->progress)
        fprintf(o->progress, "   note: gnuplot failed on %s\n", gp);
    return 0;
}
