/* Steady-state observers (SPEC §5, paper C §3): quantities sampled at the
 * output times t >= steady.from of each ensemble and averaged over those
 * times, so that each ensemble yields one time average and the ensemble layer
 * gives their mean and a confidence half-width from N independent ensembles
 * (ensemble.h).  The scene's [steady] section turns them on.
 *
 * Reduced units: with V the bulk velocity, C = v - V, T the centred
 * temperature and v0 = sqrt(2T/m), c = C/v0 (<c^2> = 3/2).  Per sample:
 *   T                          centred temperature
 *   a2, a3                     as observe.h (SPEC §1)
 *   c1 = <c>, c3 = <c^3>
 *   mu2, mu4                   collisional moments by pair sampling, paper C
 *                              Eqs. (65)-(67): v0^{-p-1} (1/N') Σ' Phi_p(C_i, C_j)
 *                              over N' = steady.pairs random pairs i != j (NaN
 *                              when pairs = 0); alpha = collisions.restitution
 *                              (its default 1 when the scene sets none)
 *   mu4_white                  5 mu2            (exact steady relation, white noise, Eq. (23))
 *   mu4_gaussian               5 (1 + a2) mu2   (Gaussian thermostat, Eq. (38))
 *   mu4_nongaussian            2 mu2 c3/c1      (non-Gaussian thermostat, Eq. (44))
 *   f_0 ... f_{bins-1}         the reduced distribution averaged over the shell
 *                              k Δ <= |c| < (k+1) Δ, Δ = c_max/bins: the fraction of
 *                              particles in it over its volume 4 pi/3 ((k+1)^3 - k^3) Δ^3,
 *                              so that ∫ f d^3c = 1 (paper C's f̃(c); Maxwellian:
 *                              pi^{-3/2} e^{-c^2})
 * The relations are computed per sample so that the difference between a
 * direct mu4 and an indirect one has its own confidence interval.
 *
 * Pair sampling draws from its own random substream (rng.h), so observing
 * never changes the simulated trajectory.
 */
#ifndef GDSMC_SIM_STEADY_H
#define GDSMC_SIM_STEADY_H

#include <stddef.h>

#include <gsl/gsl_rng.h>

#include "particles.h"
#include "scene.h"

typedef enum sim_steady_quantity {
    SIM_STEADY_T, SIM_STEADY_A2, SIM_STEADY_A3, SIM_STEADY_C1, SIM_STEADY_C3,
    SIM_STEADY_MU2, SIM_STEADY_MU4,
    SIM_STEADY_MU4_WHITE, SIM_STEADY_MU4_GAUSSIAN, SIM_STEADY_MU4_NONGAUSSIAN,
    SIM_STEADY_BIN0   /* the first histogram bin; bins follow */
} sim_steady_quantity;

/* Number of steady quantities of the scene: SIM_STEADY_BIN0 + steady.bins, or
 * 0 without a [steady] section. */
size_t sim_steady_count(const sim_scene *scene);

/* Name of quantity k ("T", "a2", ..., "mu4_nongaussian", "f_0", ...), in buf. */
const char *sim_steady_name(size_t k, char *buf, size_t len);

/* The reduced speed at the lower edge and the centre of bin k. */
double sim_steady_bin_lower(const sim_scene *scene, size_t k);
double sim_steady_bin_centre(const sim_scene *scene, size_t k);

/* Add one sample of every quantity of p to sum[sim_steady_count(scene)]
 * (particles of mass `mass`; pair sampling with rng, which may be NULL when
 * steady.pairs = 0).  Allocates nothing. */
void sim_steady_sample(const sim_scene *scene, const sim_particles *p, double mass,
                       gsl_rng *rng, double *sum);

#endif
