/* The deterministic references that apply to a scene (docs/theory.md §11-§16), on the
 * scene's output-time grid.  One place decides which reference fits which
 * scene; `gdsmc reference` and the verify cases both use it.
 *
 * Paper A scenes (binary collisions, optional white-noise heating, unit mass,
 * initial Maxwellian at rest):
 *   maxwell kernel:      T_exact (A.13), and the exact expectations of the
 *                        n-particle estimators, T_finite_n and T_raw_finite_n
 *                        (reference/heated.h; i.i.d. initial state only)
 *   hard-spheres kernel: T_maxwell_closure, T_sonine_closure (docs/theory.md §11.4)
 *
 * Paper B scenes (a background, binary collisions optional, no other effect,
 * i.i.d. initial state: Maxwellian, two Maxwellians or shell):
 *   maxwell kernels:      T_exact, ux_exact, uy_exact, uz_exact (B.14-B.17),
 *                         T_finite_n (exact E T_n, reference/background.h)
 *   hard-spheres kernels: T_le, ux_le, uy_le, uz_le (B.21) and T_grad,
 *                         ux_grad, uy_grad, uz_grad (B.22), with CVODE
 *
 * Paper E scenes (homogeneous shear of hard spheres from a Maxwellian at rest,
 * model ihs or ehs, nothing else):
 *   T_bgk, Pxx_bgk, Pyy_bgk, Pzz_bgk, Pxy_bgk (per unit density), s0_bgk (the
 *   local-equilibrium collision counter, times beta for ehs): the BGK model's
 *   second-moment system with CVODE (reference/bgk.h)
 */
#ifndef GDSMC_VFY_SCENE_REFS_H
#define GDSMC_VFY_SCENE_REFS_H

#include <stddef.h>

#include "error.h"
#include "background.h"
#include "bgk.h"
#include "heated.h"
#include "scene.h"

/* The reference columns of a scene, as many as apply: column j is
 * cols[j][0 .. outputs-1], named names[j]. */
typedef struct vfy_refs {
    size_t outputs;
    size_t count, capacity;
    char (*names)[32];
    double **cols;
} vfy_refs;

/* Compute the references for scene (n taken from the scene).  Returns
 * SIM_EUNSUPPORTED naming the key at fault when none applies, SIM_EINVAL if a
 * CVODE integration failed (message says why), SIM_ENOMEM. */
sim_status vfy_scene_references(const sim_scene *scene, vfy_refs *refs, sim_error *err);

/* Column of a reference by name (refs->outputs values), or NULL. */
const double *vfy_refs_column(const vfy_refs *refs, const char *name);

/* Whether refs has the column `name`. */
int vfy_refs_has(const vfy_refs *refs, const char *name);

void vfy_refs_free(vfy_refs *refs);

/* The paper A parameters of a scene (no checks). */
ref_heated_params vfy_heated_params(const sim_scene *scene);

/* The paper B parameters of a scene (no checks): u0 and T0 are the initial
 * distribution's mean velocity and temperature (for two Maxwellians, the
 * mixture's, which includes the spread of the two drifts); rho = 1 and
 * C2 = rate x constant of [collisions] (0 without collisions). */
ref_background_params vfy_background_params(const sim_scene *scene);

/* The paper E BGK parameters of a shear scene (no checks). */
ref_bgk_params vfy_bgk_params(const sim_scene *scene);

#endif
