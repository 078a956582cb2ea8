/* Report pieces shared by the verify cases (SPEC §9): the provenance
 * comment, result columns, curves files with gnuplot figures, and the O(1/n)
 * extrapolation. */
#ifndef GDSMC_VFY_CASE_REPORT_H
#define GDSMC_VFY_CASE_REPORT_H

#include <stddef.h>

#include "cases.h"
#include "ensemble.h"
#include "metrics.h"
#include "scene_refs.h"
#include "table.h"

#define VFY_ROWS_MAX 8   /* rows (particle numbers) of one case */

/* One row of a convergence table: the references of `scene` into *refs and
 * the simulation of `solver` into *res, with progress lines labelled
 * "<case> n=<n>".  On failure both are freed and msg says why. */
sim_status vfy_run_row(const vfy_case *c, const vfy_options *o, const sim_scene *scene,
                       const sim_scene *solver, vfy_refs *refs, sim_ensemble_result *res,
                       char *msg, size_t msglen);

/* The cost columns every table ends with: cpu_s, wall_s, events,
 * ns_per_event (CPU nanoseconds per candidate event). */
#define VFY_COST_COLUMNS "cpu_s", "wall_s", "events", "ns_per_event"
void vfy_cost_cells(vfy_table *table, double cpu_seconds, double wall_seconds,
                    double events);

/* "gdsmc VERSION verify: scene FILE, seed S, N = ..., M outputs on [0, t_end]". */
const char *vfy_run_comment(const sim_scene *s, char *buf, size_t len);

/* A scene file's path as provenance shows it: relative to the source tree
 * when it lies in it (so that reports do not name the machine that ran
 * them), else as given. */
const char *vfy_display_path(const char *path);

/* A case's table as out_dir/<name>.csv (comment first) and out_dir/<name>.md
 * (title, notes); SIM_EIO with "PATH: cannot write: ..." on failure. */
sim_status vfy_write_case_tables(const vfy_options *o, const char *name, const vfy_table *table,
                                 const char *comment, const char *title, const char *notes,
                                 char *msg, size_t msglen);
/* The same with a second table after the first in the Markdown file (its
 * title2 and notes2) and in out_dir/<name><suffix>.csv. */
sim_status vfy_write_case_tables2(const vfy_options *o, const char *name, const vfy_table *table,
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

/* Observable k of every output time: mean[m] and (if ci != NULL) ci[m]. */
void vfy_result_column(const sim_ensemble_result *r, int k, double *mean, double *ci);



#endif
