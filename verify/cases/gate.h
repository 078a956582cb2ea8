/* The gate measured (docs/verdicts.md): how often a correct solver fails by
 * chance (--seeds), whether each case catches the errors it declares
 * (--must-fail), and the smallest relative error each case detects, beside
 * what it costs (--power).
 *
 * All three run the selected cases again and again through vfy_run with
 * changed options: seeds derived from each scene's (vfy_options.seed_run)
 * and perturbations of the solver's scene (vfy_options.perturbs).  A case's
 * declared perturbations are its description's must_fail (driver.h).
 */
#ifndef GDSMC_VFY_GATE_H
#define GDSMC_VFY_GATE_H

#include <stddef.h>

#include "cases.h"
#include "error.h"

/* --seeds K: runs k = 0 .. K-1 of the selection (k = 0 with the scenes' own
 * seeds), each into out_dir/seeds/seed-KK, then out_dir/seeds.csv (per
 * check: runs judged, failed, skipped, differs) and out_dir/seeds.md (the
 * runs that passed whole, and every check that failed in one).  *clean
 * receives the runs without a failure and *flaky the checks that failed in
 * more than one run.  Returns SIM_OK or the first run's error (bad input,
 * I/O, a stop). */
sim_status vfy_seeds(const char *suite, const char *cases, const vfy_options *o, size_t K,
                     size_t *clean, size_t *flaky, char *msg, size_t msglen);

/* --must-fail: each selected case under each of its must_fail perturbations
 * (the scenes' own seeds), into out_dir/must-fail; prints CAUGHT or MISSED a
 * line each to `out`.  *missed receives the perturbations no check caught.
 * A must_fail that names a key the case's scene lacks is an error
 * (SIM_EINVAL, msg naming the case and the key). */
sim_status vfy_must_fail(const char *suite, const char *cases, const vfy_options *o, FILE *out,
                         size_t *missed, char *msg, size_t msglen);

/* --power: for each selected case and each key of its must_fail, the
 * relative errors 0.5%, 1%, 2%, 5%, 10%, 20%, 50% in the must_fail's direction
 * in turn, each under seeds 0, 1, 2 (vfy_derived_seed), until one is caught
 * by every seed: that error is the case's power for the key.  Writes
 * out_dir/power.csv, power.md and power.png (the smallest error detected
 * against the case's CPU seconds); the runs go to out_dir/power. */
sim_status vfy_power(const char *suite, const char *cases, const vfy_options *o, char *msg,
                     size_t msglen);

/* The i-th "KEY=FACTOR" word of a case's must_fail (space-separated) into
 * buf; returns 0, or -1 when there is none. */
int vfy_must_fail_at(const char *must_fail, size_t i, char *buf, size_t len);

#endif
