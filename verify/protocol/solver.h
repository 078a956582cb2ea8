/* An external solver behind the solver protocol (docs/solver-protocol.md):
 * for one scene, write the resolved scene as canonical INI (scene_ini.h),
 * run the user's command with {scene} and {out} replaced by the two paths,
 * and read the result file it wrote (result.h).
 *
 * The command is split into words as a shell would split a simple command
 * (white space separates words; '...' keeps everything literally; "..." keeps
 * all but \" and \\), but no shell runs: `sh -c '...'` is there for a user
 * who wants one.  {scene} and {out} may stand anywhere inside a word.  The
 * child inherits the environment (OMP_NUM_THREADS and the rest) and the
 * working directory; its standard output goes to a log file beside the
 * result (KEY.log) and its standard error to another (KEY.err), whose last
 * lines a failure quotes (the log's when the error file is empty).
 *
 * A solver that cannot do a scene refuses it: it exits with status
 * VFY_SOLVER_REFUSES and writes the reason as the last line of its standard
 * error (docs/solver-protocol.md); nothing else counts as a refusal.
 */
#ifndef GDSMC_VFY_SOLVER_H
#define GDSMC_VFY_SOLVER_H

#include <stddef.h>

#include "ensemble.h"
#include "result.h"
#include "scene.h"

#define VFY_SOLVER_REFUSES 3   /* the exit status of a refusal */

typedef struct vfy_solver {
    const char *command;   /* "python3 mysolver.py {scene} {out}" */
    double timeout;        /* seconds a run may take (> 0), the child killed after it */
    const char *work_dir;  /* where the scene, result and log files go (created) */
    char line[540];        /* the "# solver = " line of its latest result ("" before one),
                              and "; substituted KEYS" after it when it said so */
    double violations_allowed;  /* its latest result's declared bound (0: none) */
} vfy_solver;

/* Split command into at most max words (in buf, bufsize bytes; words[]
 * point into it); the number of words, or -1 with msg saying why (an
 * unterminated quote, too many or too long words, no words). */
int vfy_solver_split(const char *command, char **words, size_t max, char *buf, size_t bufsize,
                     char *msg, size_t msglen);

/* Whether command splits into words within the limits vfy_solver_run uses
 * and names both {scene} and {out}, each placeholder whole ("{out" is
 * refused); if not, msg says why (before any work: the command line checks
 * it). */
int vfy_solver_command_ok(const char *command, char *msg, size_t msglen);

/* The solver's identity for checkpoints: a hash of the command and of the
 * contents of every file its words name (the program, found on PATH when
 * the first word has no '/', and a script or input it is given), so that a
 * changed solver's results are never resumed as the old one's. */
uint64_t vfy_solver_identity(const char *command);

/* Simulate scene with the solver: res as vfy_result_read fills it, its
 * cpu_seconds the child's (and its children's) CPU time unless the result
 * reports them, its wall_seconds the run's.  label names the run in
 * messages.  SIM_EINVAL with a message naming the command or the file, line
 * and column: the command not found or not executable, a non-zero exit or
 * a signal (its last standard-error lines quoted), the time limit exceeded,
 * a missing, empty or malformed result, a refusal without a reason;
 * SIM_EUNSUPPORTED when the solver refused the scene, msg its reason (the
 * last line of its standard error, at most 239 bytes), res empty;
 * SIM_ECANCELED when a stop was requested (the child killed); SIM_EIO when
 * the files cannot be written. */
sim_status vfy_solver_run(const vfy_solver *solver, const sim_scene *scene, const char *label,
                          sim_ensemble_result *res, vfy_result_info *info, char *msg,
                          size_t msglen);

#endif
