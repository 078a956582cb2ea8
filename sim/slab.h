/* The Lees-Edwards slab: uniform shear flow as a laboratory makes it (paper E
 * §IV A, Eqs. 4.2-4.13; docs/theory.md §6.3; issue 17).  Internal to sim/.
 *
 * The gas fills -L/2 < y < L/2 (L = shear.length), split into M = shear.layers
 * layers of width dy = L/M; each particle has a position y beside its velocity
 * (particles.h).  A step of h is an ordered list of stages, chosen when the
 * engine is built:
 *
 *   1. stream    y <- y + v_y h; a particle leaving through the top re-enters at
 *                the bottom with v_x - aL, through the bottom at the top with
 *                v_x + aL (E Eq. 4.11, any number of crossings).  Each flow
 *                (the EHS drag, collisions.model = ehs) first takes its layer
 *                step with the fields of the particle's layer at the start of
 *                the step (effect_drag.c: v <- u_I + (v - u_I) e^{-zeta_I h/2},
 *                zeta_I = zeta0(T_I) n_I/n, E Eq. 4.12); the streaming uses
 *                v_y from before it (E Eq. 4.10).
 *   2. sort      a counting sort of the particles by layer, so that each layer
 *                is a contiguous range of the arrays.
 *   3. fields    per layer: N_I, u_I, T_I (peculiar to u_I) and the bound
 *                R_I = max |v_i - u_I|, so w_I = 2 R_I bounds the layer's relative
 *                speeds exactly (E's w_I is an estimate ∝ sqrt(T_I)).
 *   4. collide   per layer, each event process's layer stage (the collisions'
 *                in effect_collisions.c): candidates at the rate
 *                kappa P_I w_I, P_I = N_I (N_I - 1) (the layer's ordered pairs;
 *                shear.candidates = paper: N_I^2 as E Eq. 4.13 prints, a +1/N_I
 *                bias), kappa = 2 pi gamma C beta M/N: each unordered pair of the
 *                layer collides at 4 pi gamma C beta |g| M/N, the homogeneous
 *                hard-sphere rate at the layer's density n_I = n N_I M/N (E Eq.
 *                4.13 with 1/lambda0 = 4 sqrt(2) pi gamma C).  A candidate is a
 *                uniform pair i != j of the layer, accepted with |g|/w_I, and
 *                collides by paper A's rule with e uniform (equal in distribution
 *                to the contact rule, docs/theory.md §3.2); alpha = 1 for EHS.
 *                The candidates are a Poisson process in each step (exponential
 *                waiting times; Bird's remainder carried from step to step biases
 *                the rate by O(1/N_I) as N_I changes); when a collision grows R_I
 *                the rest of the step runs at the new rate.
 *
 * Observation (E Eqs. 4.3-4.9): the base set with T and P taken against each
 * particle's layer velocity u_I, T = (1/N) Σ N_I T_I and P = (1/M) Σ P_I (never
 * against the global mean, which would add a term of order a^2 <y^2>), u and
 * T_raw of the raw velocities; the shear set of observe.h from the same
 * peculiar velocities; then (observe.h's slab columns)
 *   ux_centre, ux_top  the mean u_x of the particles in the layers whose centres
 *                      lie within 2 dy of y = 0, and in the top three layers, in
 *                      units of U/2 = aL/2 (E Fig. 3; a linear profile gives 0 and
 *                      1 - 3/M)
 *   n_centre, n_top    their densities over n (E Fig. 3)
 *   T_centre, T_top    their temperatures over T (E Fig. 3)
 *   ux_slope           the least-squares slope of u_I,x against the layer centres,
 *                      over a (1 for the linear profile u_x = a y); the three u_x
 *                      columns are NaN at a = 0
 * and the profiles n_I/n, u_I,x, T_I/T and P_I,xy/(n T) (E Fig. 2), I = 0 .. M-1
 * from the bottom.  An empty layer has u_I = 0 and T_I = 0.  T_I divides by N_I
 * as E Eq. (4.6) does, so its expectation in equilibrium is T (1 - 1/N_I).
 */
#ifndef GDSMC_SIM_SLAB_H
#define GDSMC_SIM_SLAB_H

#include <stddef.h>
#include <stdint.h>

#include <gsl/gsl_rng.h>

#include "error.h"
#include "rng.h"
#include "run.h"
#include "scene.h"

typedef struct sim_slab_params sim_slab_params;
typedef struct sim_slab sim_slab;

/* Refuse, naming the key, what the slab cannot simulate: scheme = jump
 * (shear.boundary), a kernel other than hard spheres, [heating],
 * [background], [heat-flux], splitting = strang. */
sim_status sim_slab_accept(const sim_scene *scene, sim_error *err);

/* The slab of a scene with [shear] boundary = lees-edwards, running the
 * effects' per-layer forms (effect.h: each event's stages->layer, each flow's
 * step_layer; refused, naming shear.boundary, when one has none).  scene,
 * events and flows must outlive the params. */
sim_status sim_slab_params_create(const sim_scene *scene, const sim_event *events,
                                  size_t nevents, const sim_flow *flows, size_t nflows,
                                  sim_slab_params **params, sim_error *err);
void sim_slab_params_free(sim_slab_params *params);

/* Bytes per particle and per layer the slab adds to a workspace. */
size_t sim_slab_bytes(const sim_slab_params *params, size_t n);

/* Per-thread state for n particles; gives p positions. */
sim_status sim_slab_create(const sim_slab_params *params, sim_particles *p, sim_slab **slab,
                           sim_error *err);
void sim_slab_free(sim_slab *slab);

/* After the initial state is drawn: sort it into layers and take the fields. */
void sim_slab_start(const sim_slab_params *params, sim_slab *slab, sim_run *run);

/* One step of h: the stages in order (the header comment). */
void sim_slab_step(const sim_slab_params *params, sim_slab *slab, sim_run *run, double h);

/* Output m: fill the scene's whole row (the header comment); prev is the row
 * of output m - 1 or NULL, rng the observers' stream (may be NULL without
 * shear.pairs).  Leaves the peculiar velocities in sim_slab_peculiar. */
void sim_slab_observe(const sim_slab_params *params, sim_slab *slab, const sim_run *run,
                      size_t m, const double *prev, gsl_rng *rng, double *row);

/* The peculiar velocities v_i - u_I of the last observation, in the order of
 * the sorted system (for the steady observers, steady.h). */
const sim_particles *sim_slab_peculiar(const sim_slab *slab);

#endif
