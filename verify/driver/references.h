/* Every reference of the verification cases by name (docs/theory.md §11-§16).
 *
 * A reference is a time series on a scene's output times (closed forms,
 * CVODE closures, exact finite-n expectations: computed together by
 * vfy_scene_references, scene_refs.h, which decides which apply to a
 * scene) or a value at a scene's restitution coefficient (paper C's Sonine
 * estimates and collisional moments, reference/sonine.h).  `gdsmc
 * reference --list` prints this registry; the cases name references here
 * and never call reference/ directly.
 */
#ifndef GDSMC_VFY_REFERENCES_H
#define GDSMC_VFY_REFERENCES_H

#include <stddef.h>

#include "scene.h"

typedef enum vfy_reference_kind { VFY_REF_SERIES, VFY_REF_VALUE } vfy_reference_kind;

typedef struct vfy_reference {
    const char *name;                      /* series come in groups: "T_le ux_le ..." */
    vfy_reference_kind kind;
    const char *what;                      /* the formula and its source, one line */
    double (*value)(const sim_scene *s);   /* VFY_REF_VALUE: at the scene (NAN: n/a) */
} vfy_reference;

size_t vfy_reference_count(void);
const vfy_reference *vfy_reference_at(size_t i);
/* The entry that holds `name` (a group of series holds several). */
const vfy_reference *vfy_reference_find(const char *name);

/* Value reference `name` at scene s; NAN when there is no such value
 * reference or it does not apply. */
double vfy_reference_value(const char *name, const sim_scene *s);

/* Paper C Eqs. (36), (42): the high-energy tail amplitude A of the scene's
 * thermostat (white noise: f ~ exp(-A c^1.5); Gaussian: f ~ exp(-A c)) with
 * the given mu2 (a simulated one, as the paper does); NAN for the others. */
double vfy_reference_tail_A(const sim_scene *s, double mu2);

#endif
