/* Checkpoints of finished simulations, so that an interrupted verify run
 * loses nothing (issue 5: nothing lost).
 *
 * Every simulation a verify case finishes is saved at once in
 * DIR/<key>.ckpt (written to a temporary file, then renamed), where key is a
 * 64-bit FNV-1a hash of the gdsmc version, the executable's bytes (another
 * build may draw other numbers for the same scene) and every field of the
 * simulated scene that changes its numbers (seed, n, N, outputs, physics; not
 * the file name, title or key provenance).  `gdsmc verify --resume` loads a matching
 * checkpoint instead of simulating again: the statistics, counters and the
 * recorded CPU and wall times come back exactly (doubles are stored as C99
 * hexadecimal floats), so the tables written from them are byte-identical to
 * an uninterrupted run's.  A checkpoint of another scene or version, or one
 * that is damaged, is never used: that simulation is simply run again.
 */
#ifndef GDSMC_VFY_CHECKPOINT_H
#define GDSMC_VFY_CHECKPOINT_H

#include <stddef.h>
#include <stdint.h>

#include "ensemble.h"
#include "error.h"
#include "scene.h"

/* The key of scene s (see above), for this executable. */
uint64_t vfy_checkpoint_key(const sim_scene *s);

/* The key of scene s for the executable whose identity is `build`. */
uint64_t vfy_checkpoint_key_for(const sim_scene *s, uint64_t build);

/* This executable's identity: a hash of its bytes, 0 if they cannot be read. */
uint64_t vfy_build_identity(void);

/* FNV-1a: h updated with len bytes of data; start from VFY_HASH_START. */
#define VFY_HASH_START UINT64_C(0xcbf29ce484222325)
uint64_t vfy_hash(uint64_t h, const void *data, size_t len);

/* Save res, the result of simulating s, as dir/<key>.ckpt (dir is created
 * if missing); label names the run for readers.  SIM_EIO with msg
 * "PATH: cannot write: ..." on failure. */
sim_status vfy_checkpoint_save(const char *dir, const char *label, const sim_scene *s,
                               const sim_ensemble_result *res, char *msg, size_t msglen);

/* Load the checkpoint of s from dir into *res (free it with
 * sim_ensemble_result_free).  Returns 1 when loaded, 0 when there is none
 * that matches s completely (res is then empty). */
int vfy_checkpoint_load(const char *dir, const sim_scene *s, sim_ensemble_result *res);

#endif
