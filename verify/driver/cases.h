/* Verification cases and suites (docs/cases.md).
 *
 * A case runs solver against reference over a sequence of particle numbers,
 * writes reports/<case>.csv, reports/<case>.md and a figure, and records one
 * verdict per check.  Suites: `quick` (CI, minutes on 2 cores: small sizes),
 * `paper` (every case at the papers' sizes), `grw` (paper A's cases at the
 * paper's sizes).
 */
#ifndef GDSMC_VFY_CASES_H
#define GDSMC_VFY_CASES_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "checks.h"
#include "ensemble.h"
#include "error.h"
#include "scene.h"

typedef enum vfy_size { VFY_QUICK, VFY_PAPER } vfy_size;

/* The simulations one `gdsmc verify` has finished, by checkpoint key
 * (checkpoint.h): a row that needs a simulation an earlier row or case of the
 * same invocation ran (the same scene, seed and sizes, so the same numbers
 * bit for bit) takes it from that checkpoint instead of running it again.
 * Free the keys with vfy_finished_free. */
typedef struct vfy_finished {
    uint64_t *keys;
    size_t count, cap;
} vfy_finished;

void vfy_finished_free(vfy_finished *f);

typedef struct vfy_options {
    vfy_size size;
    const char *out_dir;               /* where reports go ("reports") */
    const char *scene_dir;             /* where scene files are ("verify/cases/scenes") */
    const char *const *overrides;      /* --set: change every case (solver and references) */
    size_t noverrides;
    const char *const *solver_overrides; /* --solver-set: change only the simulated scene,
                                            e.g. a deliberately wrong solver */
    size_t nsolver_overrides;
    FILE *progress;                    /* progress lines, or NULL for silence */
    const char *checkpoint_dir;        /* save every finished simulation there
                                          (checkpoint.h), or NULL */
    int resume;                        /* reuse the matching checkpoints */
    vfy_finished *finished;            /* this invocation's finished simulations (with
                                          checkpoint_dir), or NULL: each one runs */
    struct vfy_solver *solver;         /* an external solver (solver.h: --solver), or
                                          NULL for the built-in engine */
    size_t *stop_countdown;            /* if not NULL and > 0: counts finished
                                          simulations down and requests a stop at 0, as
                                          SIGINT would (a test's deterministic interrupt) */
    const char *const *perturbs;       /* --perturb "SECTION.KEY=FACTOR": the solver's
                                          value of KEY multiplied by FACTOR (a relative
                                          error, as a bug makes one) */
    size_t nperturbs;
    uint64_t seed_run;                 /* 0: every scene's own seed; k > 0: the seed
                                          vfy_derived_seed(seed, k) (--seeds) */
    FILE *dry_run;                     /* if not NULL (--dry-run): no simulation; each
                                          row's scene is written under out_dir/CASE/ and
                                          what each check reads is listed here */
} vfy_options;

typedef struct vfy_case vfy_case;

struct vfy_case {
    const char *name;      /* also the scene file's stem and the report's name */
    const char *suite;     /* the paper's suite: "grw" (paper A), "brs" (paper B) */
    const char *summary;   /* one line for --list */
    int quick;             /* part of the quick suite */
    const struct vfy_case_desc *desc;  /* what the driver runs (driver.h) */
};

/* The same for the scene o->scene_dir/<stem>.ini, for a case built on
 * another case's scene (e.g. cost-grw-ex3 on grw-ex3). */
sim_status vfy_load_scene_stem(const char *stem, const vfy_options *o, sim_scene *scene,
                               sim_scene *solver, char *msg, size_t msglen);

/* The same with settings `sets` applied before the options' overrides (a
 * case's sweep: what --set and --solver-set fix, they never change). */
sim_status vfy_load_scene_sets(const char *stem, const vfy_options *o, const char *const *sets,
                               size_t nsets, sim_scene *scene, sim_scene *solver, char *msg,
                               size_t msglen);

/* The seed of run k of --seeds for a scene seeded `seed` (k = 0: seed
 * itself): a splitmix64 mix, so that runs draw unrelated streams. */
uint64_t vfy_derived_seed(uint64_t seed, uint64_t k);

/* Parse a --perturb "SECTION.KEY=FACTOR": the key into key (a number key,
 * vfy_scene_real) and a factor > 0.  Returns SIM_OK, or SIM_EINVAL with a
 * message naming what is wrong. */
sim_status vfy_perturb_parse(const char *text, char *key, size_t keylen, double *factor,
                             char *msg, size_t msglen);

/* Refuse, before any simulation, a scene without the references `names` (a
 * case whose checks need them, given a scene changed by --set): msg gets
 * "FILE: the scene has no <names[0]> ... references (why)". */
sim_status vfy_require_references(const sim_scene *scene, const char *const *names,
                                  size_t count, const char *why, char *msg, size_t msglen);

/* Shared by the cases: build the engine for scene and run its ensembles,
 * with progress lines labelled `label`; with o->checkpoint_dir, save the
 * result there at once, and with o->resume, or when o->finished holds the
 * scene's key, take a matching saved result instead of simulating.  msg gets
 * "FILE:LINE: key: ..." on failure; SIM_ECANCELED when a stop was requested.
 * An external solver's refusal is SIM_EUNSUPPORTED with msg its reason and
 * res a blank result (vfy_result_blank), never saved. */
sim_status vfy_simulate(const sim_scene *scene, const vfy_options *o, const char *label,
                        sim_ensemble_result *res, char *msg, size_t msglen);

/* Whether the simulations come from an external solver (o->solver), which
 * may leave quantities unreported (NaN in the result). */
int vfy_external(const vfy_options *o);

/* The time step the engine uses for scene s, from the scene alone
 * (sim_scene_step): 0 for the jump scheme or a step the engine refuses. */
double vfy_scene_step(const sim_scene *s);

/* out_dir/<name><suffix>, in buf. */
const char *vfy_report_path(const vfy_options *o, const char *name, const char *suffix,
                            char *buf, size_t len);

#endif
