/* The a2 estimates of paper C (docs/theory.md §13); see sonine_a2.h for the
 * contract.  Equation numbers "(N)" are paper C's. */
#include "sonine_a2.h"

#include <math.h>

static int alpha_ok(double alpha) { return alpha >= 0.0 && alpha <= 1.0; }

static int d_ok(double d) { return d >= REF_SONINE_D_MIN && d <= REF_SONINE_D_MAX; }

static int ok(double alpha, double d) { return alpha_ok(alpha) && d_ok(d); }

/* Every a2 estimate below has the shape (1 - a) num / den; NaN unless valid,
 * and +0 exactly at a = 1 (the product would give -0 for num < 0). */
static double a2_form(int valid, double a, double num, double den)
{
    if (!valid)
        return NAN;
    return a == 1.0 ? 0.0 : (1.0 - a) * num / den;
}

/* Eq. (10).  The denominator is positive for a in [0, 1] and d >= 2 (at d = 1,
 * a = 1 it vanishes with the numerator); the same holds for the other forms. */
double ref_sonine_a2_white_noise(double alpha, double d)
{
    const double a = alpha;
    return a2_form(ok(alpha, d), a, 16.0 * (1.0 - 2.0 * a * a),
                   73.0 + 56.0 * d - 3.0 * a * (35.0 + 8.0 * d) + 30.0 * (1.0 - a) * a * a);
}

/* Eq. (32). */
double ref_sonine_a2_white_noise_ratio(double alpha, double d)
{
    const double a = alpha;
    return a2_form(ok(alpha, d), a, 4.0 * (1.0 - 2.0 * a * a),
                   19.0 + 14.0 * d - 3.0 * a * (9.0 + 2.0 * d) + 6.0 * (1.0 - a) * a * a);
}

/* Eq. (5). */
double ref_sonine_a2_gaussian(double alpha, double d)
{
    const double a = alpha;
    return a2_form(ok(alpha, d), a, 16.0 * (1.0 - 2.0 * a * a),
                   9.0 + 24.0 * d - a * (41.0 - 8.0 * d) + 30.0 * (1.0 - a) * a * a);
}

/* Eq. (40). */
double ref_sonine_a2_gaussian_alt(double alpha, double d)
{
    const double a = alpha;
    return a2_form(ok(alpha, d), a, 16.0 * (1.0 - 2.0 * a * a),
                   25.0 + 24.0 * d - a * (57.0 - 8.0 * d) - 2.0 * (1.0 - a) * a * a);
}

/* Eq. (50). */
double ref_sonine_a2_nongaussian(double alpha, double d)
{
    const double a = alpha;
    return a2_form(ok(alpha, d), a, -16.0 * (1.0 + 2.0 * a * a),
                   63.0 + 40.0 * d - a * (95.0 + 8.0 * d) + 30.0 * (1.0 - a) * a * a);
}

/* Eq. (76), d = 3 only. */
double ref_sonine_a2_nongaussian_fit(double alpha, double d)
{
    const double a = alpha;
    return a2_form(alpha_ok(alpha) && d == 3.0, a, -240.0 * (1.0 + 2.0 * a * a),
                   1957.0 - 1125.0 * a + 390.0 * (1.0 - a) * a * a);
}
