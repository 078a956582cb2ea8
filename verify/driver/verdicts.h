/* The verdicts a run keeps (docs/verdicts.md): one file per case beside its
 * table, and an index of a report directory.
 *
 * out_dir/<case>-verdicts.csv holds every check the case recorded, a row
 * each: check_id (the check's name before a row fills it in), row (the row's
 * label), verdict (PASS, FAIL, SKIP or DIFFERS), value, reference, allowed,
 * name and detail; its comment lines give the provenance (as the case's
 * table), the counts and the case's cost ("# cost: wall_s = W, cpu_s = C":
 * the simulations' seconds, which --resume keeps).
 *
 * out_dir/README.md is made from the verdicts files in out_dir (so a run of
 * some cases keeps the others' lines): per case the counts, the cost and
 * links to its table, verdicts and figures, then every DIFFERS and FAIL with
 * its detail.
 */
#ifndef GDSMC_VFY_VERDICTS_H
#define GDSMC_VFY_VERDICTS_H

#include <stddef.h>
#include <stdio.h>

#include "cases.h"
#include "checks.h"
#include "error.h"

/* Write the checks of group `name` in r as out_dir/<name>-verdicts.csv,
 * its provenance `comment` (vfy_run_comment's lines) first, then the counts
 * and the case's cost.  Returns SIM_OK or SIM_EIO with msg. */
sim_status vfy_write_verdicts(const vfy_options *o, const char *name, const vfy_report *r,
                              const char *comment, double wall_s, double cpu_s, char *msg,
                              size_t msglen);

/* Write out_dir/README.md from the verdicts files there of the ncases
 * cases named in `cases`, in that order (title: "quick sizes" or "paper
 * sizes").  Returns SIM_OK or SIM_EIO with msg. */
sim_status vfy_write_index(const vfy_options *o, const char *title, const char *const *cases,
                           size_t ncases, char *msg, size_t msglen);

#endif
