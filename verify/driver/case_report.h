/* Report pieces of the driver (README.md, "What comes out"): the provenance comment, the case's
 * tables, the rows so far, result columns. */
#ifndef GDSMC_VFY_CASE_REPORT_H
#define GDSMC_VFY_CASE_REPORT_H

#include <stddef.h>

#include "cases.h"
#include "ensemble.h"
#include "scene_refs.h"
#include "table.h"

/* "gdsmc VERSION verify: scene FILE, seed S, N = ..., M outputs on [0, t_end]". */
const char *vfy_run_comment(const sim_scene *s, char *buf, size_t len);

/* A scene file's path as provenance shows it: relative to the source tree
 * when it lies in it (so that reports do not name the machine that ran
 * them), else as given. */
const char *vfy_display_path(const char *path);

/* A case's table as out_dir/<name>.csv (comment first) and out_dir/<name>.md
 * (title, notes), and a second table (or NULL) after the first in the
 * Markdown file (title2, notes2) and as out_dir/<name><suffix>.csv; SIM_EIO
 * with "PATH: cannot write: ..." on failure. */
sim_status vfy_write_case_tables(const vfy_options *o, const char *name, const vfy_table *table,
                                  const char *comment, const char *title, const char *notes,
                                  const vfy_table *second, const char *suffix,
                                  const char *title2, const char *notes2, char *msg,
                                  size_t msglen);

/* After each finished row: the rows so far as out_dir/<name>.csv, its
 * comment saying that the case is still running, so that an interrupted run
 * leaves what it finished on disk (vfy_write_case_tables replaces it at the
 * end).  scene gives the comment's provenance (vfy_run_comment). */
sim_status vfy_write_rows_so_far(const vfy_options *o, const char *name, const vfy_table *table,
                                 const sim_scene *scene, char *msg, size_t msglen);

/* msg = "PATH: cannot write: strerror(errno)"; returns SIM_EIO. */
sim_status vfy_io_error(const char *path, char *msg, size_t msglen);

/* A file of the report directory being written: out_dir/<file> through
 * vfy_file_begin's FILE.tmp, renamed into place by vfy_report_file_close. */
typedef struct vfy_report_file {
    FILE *f;
    char path[1100], tmp[1200];
} vfy_report_file;

/* Open o->out_dir/<file> for writing: SIM_OK, or SIM_EIO with msg. */
sim_status vfy_report_file_open(vfy_report_file *rf, const vfy_options *o, const char *file,
                                char *msg, size_t msglen);

/* Close it and put it in place (removed if a write failed): SIM_OK, or
 * SIM_EIO with msg. */
sim_status vfy_report_file_close(vfy_report_file *rf, char *msg, size_t msglen);

/* Observable k of every output time: mean[m] and (if ci != NULL) ci[m]. */
void vfy_result_column(const sim_ensemble_result *r, int k, double *mean, double *ci);

#endif
