/* The suites: every verification case in suite order (the case files
 * verify/cases/scenes/NAME.case, case_file.h), the suites, and the runs of a
 * suite.  The top of
 * the verify layer below the command line: cli -> cases -> driver ->
 * protocol -> sim (docs/layout.md). */
#ifndef GDSMC_VFY_SUITES_H
#define GDSMC_VFY_SUITES_H

#include <stddef.h>

#include "cases.h"
#include "checks.h"
#include "error.h"

/* Load the cases listed in DIR/cases.list, in its order, from their case
 * files DIR/NAME.case (case_file.h), replacing any loaded before.  Returns
 * SIM_OK, or an error with msg naming the file, line and key (then no case
 * is loaded).  The functions below see the cases loaded last (none before
 * the first load). */
sim_status vfy_cases_load(const char *dir, char *msg, size_t msglen);
/* Free the loaded cases. */
void vfy_cases_unload(void);

/* Where the case files are: the source tree's verify/cases/scenes. */
const char *vfy_case_dir(void);

size_t vfy_case_count(void);
const vfy_case *vfy_case_at(size_t i);
const vfy_case *vfy_case_find(const char *name);

/* Does every name of the comma-separated `list` name a case?  If not, 0 with
 * the first that does not in unknown. */
int vfy_case_list_check(const char *list, char *unknown, size_t len);

/* Is `name` a suite ("quick", "paper" or a paper's suite such as "grw")? */
int vfy_suite_exists(const char *name);

/* The papers' suites in case order, comma-separated ("grw, brs"), in buf. */
const char *vfy_paper_suites(char *buf, size_t len);

/* Whether case c is selected by suite (NULL: "paper") or, when case_name
 * is not NULL, by that comma-separated list of cases. */
int vfy_case_selected(const vfy_case *c, const char *suite, const char *case_name);

/* Run every case of the suite, or only the cases named in case_name, a
 * comma-separated list (in suite order, at the suite's sizes; the default
 * suite for named cases is "paper").  Stops at the first case that
 * cannot run (returns its error).  Reports go to o->out_dir; with
 * o->dry_run, the scenes and the listing, and r may be NULL. */
sim_status vfy_run(const char *suite, const char *case_name, const vfy_options *o,
                   vfy_report *r, char *msg, size_t msglen);

#endif
