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
 *   # violations_allowed = 40     (optional: the solver's declared bound)
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
#include "observe.h"
#include "scene.h"

#define VFY_RESULT_VERSION 1

/* What a result file reported beyond the required n and ensembles. */
typedef struct vfy_result_info {
    char solver[256];                /* the "# solver = " line, or "" */
    char substituted[256];           /* "# substituted = ": the algorithm keys (docs/scenes.md)
                                        the solver replaced by its own, ", "-separated, or "" */
    int has_cpu, has_events, has_violations;
    double violations_allowed;       /* "# violations_allowed = K": the most majorant
                                        violations the solver's algorithm declares it lets
                                        through (a bound raised after each step), else 0 */
    unsigned char reported[SIM_OBS_MAX];  /* observable k had a column */
    size_t steady_reported;          /* steady quantities the file gave */
} vfy_result_info;

/* Write res, a simulation by `solver` (free text, one line), as a
 * version 1 result file: every base observable at every output time, the
 * steady quantities the scene has and the run measured (a NaN, mu2 without
 * steady.pairs, is left out), and the run's counts and CPU
 * seconds.  The engine's population variances become sample variances
 * (times N/(N - 1); 0 for N = 1).  Returns 0, or -1 when f reports an
 * error. */
int vfy_result_write(FILE *f, const char *solver, const sim_scene *scene,
                     const sim_ensemble_result *res);

/* Read the result file at path for scene (its output times, n, N and steady
 * quantities) into res: the means as reported, the variances as the
 * engine's population variances (times (N - 1)/N) and the confidence
 * half-widths 3.2 sqrt(var/N) from them; an observable or steady quantity the
 * file does not report is NaN (info says which were).  Refuses, with SIM_EIO
 * for a file that cannot be read and SIM_EINVAL otherwise, a message naming
 * the file, line and column, and res freed: an empty file; a first line
 * other than "# gdsmc-result 1"; n or ensembles missing or unlike the
 * scene's; a header without t first, with an unknown or repeated
 * observable, or a NAME without NAME_var after it; a row with another
 * number of fields, a field that is not a number, NaN, an infinity, a
 * negative variance, or a t unlike the scene's output time (relative 1e-9);
 * too few or too many rows; an unknown or repeated steady quantity;
 * anything after the rows but the steady section. */
sim_status vfy_result_read(const char *path, const sim_scene *scene, sim_ensemble_result *res,
                           vfy_result_info *info, char *msg, size_t msglen);

/* A result for scene that reports nothing: the scene's output times, every
 * mean, variance and half-width NaN, events and violations missing (what a
 * refused scene leaves for the checks).  SIM_OK or SIM_ENOMEM (res freed). */
sim_status vfy_result_blank(const sim_scene *scene, sim_ensemble_result *res);

/* The same from text in memory (len bytes, NUL bytes refused); name stands
 * for the file in messages (tests and the fuzzer). */
sim_status vfy_result_parse(const char *text, size_t len, const char *name,
                            const sim_scene *scene, sim_ensemble_result *res,
                            vfy_result_info *info, char *msg, size_t msglen);

#endif
