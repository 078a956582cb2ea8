#include "case_report.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "figure.h"
#include "scene_ini.h"
#include "table.h"

sim_status vfy_write_case_tables(const vfy_options *o, const char *name, const vfy_table *table,
                                  const char *comment, const char *title, const char *notes,
                                  const vfy_table *second, const char *suffix,
                                  const char *title2, const char *notes2, char *msg,
                                  size_t msglen)
{
    char path[1024], tmp[1100], name2[200];
    snprintf(name2, sizeof name2, "%s%s", name, suffix ? suffix : "");
    if (vfy_table_write_csv(table, vfy_report_path(o, name, ".csv", path, sizeof path),
                            comment) != 0
        || (second
            && vfy_table_write_csv(second, vfy_report_path(o, name2, ".csv", path, sizeof path),
                                   comment) != 0))
        return vfy_io_error(path, msg, msglen);
    FILE *f = vfy_file_begin(vfy_report_path(o, name, ".md", path, sizeof path), tmp,
                             sizeof tmp);
    if (f == NULL)
        return vfy_io_error(path, msg, msglen);
    vfy_table_print_markdown(table, f, title, notes);
    if (second) {
        fputc('\n', f);
        vfy_table_print_markdown(second, f, title2, notes2);
    }
    if (vfy_file_commit(f, tmp, path, 1) != 0)
        return vfy_io_error(path, msg, msglen);
    return SIM_OK;
}

sim_status vfy_write_rows_so_far(const vfy_options *o, const char *name, const vfy_table *table,
                                 const sim_scene *scene, char *msg, size_t msglen)
{
    char path[1024];
    /* the scene's path, and room for the version, the numbers and the words */
    const size_t len = strlen(vfy_display_path(scene->file)) + strlen(GDSMC_VERSION) + 256;
    char *comment = malloc(len);
    if (comment == NULL) {
        snprintf(msg, msglen, "out of memory");
        return SIM_ENOMEM;
    }
    size_t used = strlen(vfy_run_comment(scene, comment, len));
    snprintf(comment + used, len - used, "\nin progress: %zu finished rows so far",
             vfy_table_rows(table));
    const int rc = vfy_table_write_csv(table, vfy_report_path(o, name, ".csv", path, sizeof path),
                                       comment);
    free(comment);
    return rc != 0 ? vfy_io_error(path, msg, msglen) : SIM_OK;
}

const char *vfy_display_path(const char *path)
{
    const size_t n = strlen(GDSMC_SOURCE_DIR);
    return strncmp(path, GDSMC_SOURCE_DIR, n) == 0 && path[n] == '/' ? path + n + 1 : path;
}

const char *vfy_run_comment(const sim_scene *s, char *buf, size_t len)
{
    snprintf(buf, len, "gdsmc %s verify: scene %s, seed %llu, N = %zu ensembles, %zu outputs on "
             "[0, %g]", GDSMC_VERSION, vfy_display_path(s->file), (unsigned long long)s->seed,
             s->particles.ensembles, s->outputs, s->t_end);
    return buf;
}


sim_status vfy_io_error(const char *path, char *msg, size_t msglen)
{
    snprintf(msg, msglen, "%s: cannot write: %s", path, strerror(errno));
    return SIM_EIO;
}

sim_status vfy_report_file_open(vfy_report_file *rf, const vfy_options *o, const char *file,
                                char *msg, size_t msglen)
{
    snprintf(rf->path, sizeof rf->path, "%s/%s", o->out_dir, file);
    rf->f = vfy_file_begin(rf->path, rf->tmp, sizeof rf->tmp);
    return rf->f != NULL ? SIM_OK : vfy_io_error(rf->path, msg, msglen);
}

sim_status vfy_report_file_close(vfy_report_file *rf, char *msg, size_t msglen)
{
    const int ok = !ferror(rf->f);
    if (vfy_file_commit(rf->f, rf->tmp, rf->path, ok) != 0 || !ok)
        return vfy_io_error(rf->path, msg, msglen);
    return SIM_OK;
}


void vfy_result_column(const sim_ensemble_result *r, int k, double *mean, double *ci)
{
    for (size_t m = 0; m < r->outputs; m++) {
        mean[m] = sim_result_mean(r, m, k);
        if (ci)
            ci[m] = sim_result_ci(r, m, k);
    }
}


