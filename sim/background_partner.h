/* Partners drawn from the fixed Maxwellian background of paper B (docs/theory.md §5.2),
 * shared by effect_background.c and its tests. */
#ifndef GDSMC_SIM_BACKGROUND_PARTNER_H
#define GDSMC_SIM_BACKGROUND_PARTNER_H

#include <math.h>

#include "rng.h"

/* w ~ f^B / rho_B: u_B + sigma xi, sigma = sqrt(T_B / m_B). */
static inline void sim_background_partner(const double u_B[3], double sigma, gsl_rng *rng,
                                          double w[3])
{
    double xi[3];
    sim_rng_normal3(rng, xi);
    for (int k = 0; k < 3; k++)
        w[k] = u_B[k] + sigma * xi[k];
}

/* w ~ p2 ∝ |w - u_B| f^B(w) (Algorithm 2's second mixture part): the speed
 * s = |w - u_B| / b has density ∝ s^3 e^{-s^2}, i.e. s^2 ~ Gamma(2, 1) =
 * -ln(U1 U2), b = sqrt(2 T_B / m_B); the direction is uniform.  Returns
 * |w - u_B|. */
static inline double sim_background_flux_partner(const double u_B[3], double b, gsl_rng *rng,
                                                 double w[3])
{
    double dir[3];
    double speed = b * sqrt(-log(sim_rng_uniform_pos(rng) * sim_rng_uniform_pos(rng)));
    sim_rng_unit_sphere(rng, dir);
    for (int k = 0; k < 3; k++)
        w[k] = u_B[k] + speed * dir[k];
    return speed;
}

#endif
