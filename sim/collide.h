/* The inelastic binary collision rule (docs/theory.md §3.1, paper A Eq. (3)).
 *
 *   v' = (v+w)/2 + (1-alpha)/4 g + (1+alpha)/4 |g| e
 *   w' = (v+w)/2 - (1-alpha)/4 g - (1+alpha)/4 |g| e,   g = v - w, e on S^2.
 *
 * Momentum is conserved exactly (up to round-off); the energy changes by
 * -(1-alpha^2)/4 (1 - mu) |g|^2 with mu = (g.e)/|g|.  Paper B's binary rule is
 * the same with alpha = e (docs/theory.md §3.1).  Below it, the elastic rule of a grain
 * with a background partner (paper B).
 */
#ifndef GDSMC_SIM_COLLIDE_H
#define GDSMC_SIM_COLLIDE_H

#include <math.h>

/* Collide velocities v and w (3-vectors, updated in place) with restitution
 * alpha and unit vector e; gnorm = |v - w| (computed by the caller, who needs
 * it for the acceptance test anyway). */
static inline void sim_collide_inelastic(double v[3], double w[3], double alpha,
                                         double gnorm, const double e[3])
{
    const double a = 0.25 * (1.0 - alpha), b = 0.25 * (1.0 + alpha) * gnorm;
    for (int k = 0; k < 3; k++) {
        double centre = 0.5 * (v[k] + w[k]);
        double half = a * (v[k] - w[k]) + b * e[k];
        v[k] = centre + half;
        w[k] = centre - half;
    }
}

/* The contact rule of paper C (docs/theory.md §3.2): inelastic hard spheres meeting along
 * the unit vector s with gs = (v - w).s > 0,
 *   v' = v - (1+alpha)/2 gs s,   w' = w + (1+alpha)/2 gs s.
 * With s drawn with density proportional to Θ(g.s)(g.s) on S^2 this is paper
 * A's rule (above) with e uniform: g' = (1-alpha)/2 g + (1+alpha)/2 |g| e,
 * e = g - 2 (g.s) s / |g| being uniform (docs/theory.md §3.2). */
static inline void sim_collide_contact(double v[3], double w[3], double alpha, double gs,
                                       const double s[3])
{
    const double a = 0.5 * (1.0 + alpha) * gs;
    for (int k = 0; k < 3; k++) {
        v[k] -= a * s[k];
        w[k] += a * s[k];
    }
}

/* Elastic collision of a grain v with a background partner w (docs/theory.md §3.4, paper B
 * Eq. (2)): v' = (1 - a) v + a w + a |v - w| e, with the mass ratio
 * a = m_B / (m + m_B).  The partner's post-collision velocity, which the fixed
 * background never keeps, is w' = (1 - a) v + a w - (1 - a) |v - w| e. */
static inline void sim_collide_elastic(double v[3], const double w[3], double mass_ratio,
                                       double gnorm, const double e[3])
{
    const double a = mass_ratio, b = mass_ratio * gnorm;
    for (int k = 0; k < 3; k++)
        v[k] = (1.0 - a) * v[k] + a * w[k] + b * e[k];
}

static inline double sim_norm3(const double x[3])
{
    return sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}

#endif
