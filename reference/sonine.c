/* Sonine-approximation formulas (SPEC §5, paper C Appendix). */
#include "sonine.h"

#include <math.h>

/* Paper C Eq. (C.10), white-noise thermostat, general dimension d:
 * a2 = 16(1-a)(1-2a^2) / (73 + 56d - 3a(35 + 8d) + 30(1-a)a^2).
 * The denominator is positive for a in [0, 1] and d >= 2 (at d = 1, a = 1 it
 * vanishes with the numerator), so those are the accepted ranges. */
double ref_sonine_a2_white_noise(double alpha, double d)
{
    if (!(alpha >= 0.0 && alpha <= 1.0) || !(d >= 2.0 && isfinite(d)))
        return NAN;
    double a = alpha;
    return 16.0 * (1.0 - a) * (1.0 - 2.0 * a * a)
           / (73.0 + 56.0 * d - 3.0 * a * (35.0 + 8.0 * d) + 30.0 * (1.0 - a) * a * a);
}
