/* Result files of the solver protocol, version 1 (docs/solver-protocol.md):
 * what an external solver writes for one scene, and what `gdsmc run
 * --result FILE` writes so that the built-in engine can stand behind the
 * protocol too.
 *
 *   # gdsmc-result 1
 *   # solver = NAME VERSION
 *   # n = 64
 *   # ensembles = 10000
 *   # cpu_seconds = 12.3          (optional)
 *   # events = 10079770           (optional)
 *   # violations = 0              (optional)
 *   t,T,T_var,T_raw,T_raw_var,...
 *   one row per output time
 *   # steady                      (scenes with [steady] only)
 *   name,mean,var
 *   one row per steady quantity
 *
 * NAME_var is the sample variance (divisor N - 1) of the N per-ensemble
 * estimates, numbers with 17 significant digits.
 */
#ifndef GDSMC_VFY_RESULT_H
#define GDSMC_VFY_RESULT_H

#include <stdio.h>

#include "ensemble.h"

#define VFY_RESULT_VERSION 1

/* Write res, a simulation by `solver` (free text, one line), as a
 * version 1 result file: every base observable at every output time, the
 * steady quantities when the scene has them, and the run's counts and CPU
 * seconds.  The engine's population variances become sample variances
 * (times N/(N - 1); 0 for N = 1).  Returns 0, or -1 when f reports an
 * error. */
int vfy_result_write(FILE *f, const char *solver, const sim_ensemble_result *res);

#endif
