/* Unit tests of the Sonine-approximation formulas of paper C (sonine.h).
 * Every known answer names its source: a docs/theory.md section (§13), "(N)"
 * = paper C's Eq. (N), "Table 1" = paper C's Table 1. */
#include "test_reference_util.h"

#include <string.h>

#include "sonine.h"
#include "transport.h"

static const double PI = 3.14159265358979323846;

/* Equal when both are NaN, or within rtol/atol. */
static void assert_same(double actual, double expected, double rtol, double atol)
{
    if (isnan(expected))
        assert_true(isnan(actual));
    else
        assert_close(actual, expected, rtol, atol);
}

/* |x - printed| <= half a unit of the last printed digit (digits after the point). */
#define assert_printed(x, printed, digits) \
    assert_close((x), (printed), 0.0, 0.5 * pow(10.0, -(digits)) + 1e-12)

/* -------------------------------------------------------------- beta_n */

static void test_beta(void **state)
{
    (void)state;
    /* (A.7) against the integrals done by hand: in d = 3, ∫ dr Θ(c·r)(c·r)^n =
     * 2 pi ∫_0^1 x^n dx = 2 pi/(n+1); in d = 2, ∫_{-pi/2}^{pi/2} cos^n t dt. */
    for (int n = 0; n <= 5; n++)
        assert_close(ref_sonine_beta(n, 3.0), 2.0 * PI / (n + 1), 1e-14, 0);
    assert_close(ref_sonine_beta(1.0, 3.0), PI, 1e-15, 0); /* docs/theory.md §13.1: beta_1 = pi */
    assert_close(ref_sonine_beta(3.0, 3.0), PI / 2.0, 1e-15, 0);
    assert_close(ref_sonine_beta(0.0, 2.0), PI, 1e-15, 0);
    assert_close(ref_sonine_beta(1.0, 2.0), 2.0, 1e-15, 0);
    assert_close(ref_sonine_beta(2.0, 2.0), PI / 2.0, 1e-15, 0);
    assert_close(ref_sonine_beta(3.0, 2.0), 4.0 / 3.0, 1e-15, 0);
    /* beta_0 is the area of a half unit sphere: 2 pi^2/2 in d = 4. */
    assert_close(ref_sonine_beta(0.0, 4.0), PI * PI, 1e-14, 0);
    /* (A.5) = (65): beta_3 (1 - a^2)/4 = pi (1 - a^2)/8 at d = 3. */
    assert_close(ref_sonine_beta(3.0, 3.0) / 4.0, PI / 8.0, 1e-15, 0);
}

/* ------------------------------------------------- collisional moments */

static void test_mu2_0(void **state)
{
    (void)state;
    for (double a = 0.0; a <= 1.0; a += 0.0625) {
        /* docs/theory.md §13.1: the general-d (27) is sqrt(2 pi)(1 - a^2) at d = 3. */
        assert_close(ref_sonine_mu2_0(a, 3.0), sqrt(2.0 * PI) * (1.0 - a * a), 1e-14, 1e-300);
        /* d = 2: pi^(1/2)/(sqrt 2 Gamma(1)) = sqrt(pi/2). */
        assert_close(ref_sonine_mu2_0(a, 2.0), sqrt(PI / 2.0) * (1.0 - a * a), 1e-14, 1e-300);
        /* d = 4: pi^(3/2)/(sqrt 2 Gamma(2)). */
        assert_close(ref_sonine_mu2_0(a, 4.0), pow(PI, 1.5) / sqrt(2.0) * (1.0 - a * a), 1e-14,
                     1e-300);
    }
    assert_close(ref_sonine_mu2_0(1.0, 3.0), 0.0, 0, 0);
    /* (28) */
    assert_close(ref_sonine_mu2_1(0.385, 2.5), 3.0 / 16.0 * ref_sonine_mu2_0(0.385, 2.5), 1e-15, 0);
}

static void test_mu4_0_table1(void **state)
{
    (void)state;
    /* docs/theory.md §13.1 and Table 1: mu4^(0) = 10.925, 9.812, 7.797, 4.638 at
     * alpha = 0.2 ... 0.8. */
    const double alpha[] = {0.2, 0.4, 0.6, 0.8}, table[] = {10.925, 9.812, 7.797, 4.638};
    for (int i = 0; i < 4; i++)
        assert_printed(ref_sonine_mu4_0(alpha[i], 3.0), table[i], 3);
    /* (29) at d = 3: (9/2 + a^2) sqrt(2 pi)(1 - a^2). */
    for (double a = 0.0; a <= 1.0; a += 0.0625)
        assert_close(ref_sonine_mu4_0(a, 3.0), (4.5 + a * a) * sqrt(2 * PI) * (1 - a * a), 1e-14,
                     1e-300);
    /* d = 2: (7/2 + a^2) sqrt(pi/2)(1 - a^2). */
    assert_close(ref_sonine_mu4_0(0.385, 2.0),
                 (3.5 + 0.385 * 0.385) * sqrt(PI / 2) * (1 - 0.385 * 0.385), 1e-14, 0);
}

static void test_mu4_1(void **state)
{
    (void)state;
    /* (30) at d = 3, written as printed: [(3/32)(69 + 10a^2) + 2/(1-a)] sqrt(2 pi)(1-a^2). */
    for (double a = 0.0; a < 1.0; a += 0.0625)
        assert_close(ref_sonine_mu4_1(a, 3.0),
                     (3.0 / 32.0 * (69.0 + 10.0 * a * a) + 2.0 / (1.0 - a)) * sqrt(2 * PI)
                         * (1 - a * a),
                     1e-14, 0);
    /* General d as printed, d = 2 and 4.5. */
    const double ds[] = {2.0, 4.5};
    for (int i = 0; i < 2; i++) {
        double d = ds[i], a = 0.385;
        assert_close(ref_sonine_mu4_1(a, d),
                     (3.0 / 32.0 * (10 * d + 39 + 10 * a * a) + (d - 1) / (1 - a))
                         * ref_sonine_mu2_0(a, d),
                     1e-14, 0);
    }
    /* alpha = 1: the limit 2(d-1) pi^((d-1)/2)/(sqrt 2 Gamma(d/2)) = 4 sqrt(2 pi) at d = 3,
     * approached continuously. */
    assert_close(ref_sonine_mu4_1(1.0, 3.0), 4.0 * sqrt(2.0 * PI), 1e-14, 0);
    assert_close(ref_sonine_mu4_1(1.0 - 1e-9, 3.0), ref_sonine_mu4_1(1.0, 3.0), 1e-8, 0);
}

static void test_mu_expansions(void **state)
{
    (void)state;
    /* (26) at a high-entropy a2. */
    double a = 0.385, d = 3.0, a2 = 0.0731;
    assert_close(ref_sonine_mu2(a, d, a2),
                 ref_sonine_mu2_0(a, d) * (1.0 + 3.0 / 16.0 * a2), 1e-15, 0);
    assert_close(ref_sonine_mu4(a, d, a2), ref_sonine_mu4_0(a, d) + ref_sonine_mu4_1(a, d) * a2,
                 1e-15, 0);
    assert_close(ref_sonine_mu2(a, d, 0.0), ref_sonine_mu2_0(a, d), 0, 0);
    /* (72), (73): slopes 21/20 and 13/15, d = 3 only. */
    assert_close(ref_sonine_mu2_nongaussian_fit(a, 3.0, a2),
                 ref_sonine_mu2_0(a, 3.0) + 1.05 * ref_sonine_mu2_1(a, 3.0) * a2, 1e-15, 0);
    assert_close(ref_sonine_mu4_nongaussian_fit(a, 3.0, a2),
                 ref_sonine_mu4_0(a, 3.0) + 13.0 / 15.0 * ref_sonine_mu4_1(a, 3.0) * a2, 1e-15,
                 0);
    assert_true(isnan(ref_sonine_mu2_nongaussian_fit(a, 2.0, a2)));
    assert_true(isnan(ref_sonine_mu4_nongaussian_fit(a, 2.0, a2)));
    /* (48), (49) at d = 3: <c> = 2/sqrt(pi), <c^3> = 4/sqrt(pi) for the Maxwellian
     * (Gamma(2)/Gamma(3/2), Gamma(3)/Gamma(3/2)); d = 2: sqrt(pi)/2, 3 sqrt(pi)/4. */
    assert_close(ref_sonine_mean_c(3.0, 0.0), 2.0 / sqrt(PI), 1e-15, 0);
    assert_close(ref_sonine_mean_c3(3.0, 0.0), 4.0 / sqrt(PI), 1e-15, 0);
    assert_close(ref_sonine_mean_c(2.0, a2), sqrt(PI) / 2.0 * (1.0 - a2 / 8.0), 1e-15, 0);
    assert_close(ref_sonine_mean_c3(2.0, a2), 0.75 * sqrt(PI) * (1.0 + 3.0 * a2 / 8.0), 1e-15, 0);
}

/* ------------------------------------------------------ a2 estimates */

typedef double (*a2_fn)(double alpha, double d);

static void test_a2_d3_forms(void **state)
{
    (void)state;
    /* docs/theory.md §13.3: the general-d forms at d = 3 equal the d = 3 forms written out. */
    for (double a = 0.0; a <= 1.0; a += 0.03125) {
        double n = 16 * (1 - a) * (1 - 2 * a * a), c = (1 - a) * a * a;
        assert_close(ref_sonine_a2_white_noise(a, 3.0), n / (241 - 177 * a + 30 * c), 1e-14,
                     1e-17);
        assert_close(ref_sonine_a2_white_noise_ratio(a, 3.0),
                     n / 4 / (61 - 45 * a + 6 * c), 1e-14, 1e-17);
        assert_close(ref_sonine_a2_gaussian(a, 3.0), n / (81 - 17 * a + 30 * c), 1e-14, 1e-17);
        assert_close(ref_sonine_a2_gaussian_alt(a, 3.0), n / (97 - 33 * a - 2 * c), 1e-14,
                     1e-17);
        assert_close(ref_sonine_a2_nongaussian(a, 3.0),
                     -16 * (1 - a) * (1 + 2 * a * a) / (183 - 119 * a + 30 * c), 1e-14, 1e-17);
    }
    /* Hand-evaluated points (d = 3). */
    assert_close(ref_sonine_a2_gaussian_alt(0.4, 3.0), 6.528 / 83.608, 1e-14, 0);
    assert_close(ref_sonine_a2_gaussian(0.2, 3.0), 11.776 / 78.56, 1e-14, 0);
    assert_close(ref_sonine_a2_nongaussian(0.5, 3.0), -12.0 / 127.25, 1e-14, 0);
    assert_close(ref_sonine_a2_nongaussian_fit(0.5, 3.0), -180.0 / 1443.25, 1e-14, 0);
    /* d = 2, alpha = 0.5: (32) 1/(19 + 28 - 1.5*13 + 0.75) = 1/28.25. */
    assert_close(ref_sonine_a2_white_noise_ratio(0.5, 2.0), 1.0 / 28.25, 1e-14, 0);
}

/* mu2^(0,1), mu4^(0,1) at (a, d). */
typedef struct mus {
    double m20, m21, m40, m41;
} mus;

static mus mu_at(double a, double d)
{
    mus m = {ref_sonine_mu2_0(a, d), ref_sonine_mu2_1(a, d), ref_sonine_mu4_0(a, d),
             ref_sonine_mu4_1(a, d)};
    return m;
}

static void test_a2_mu_routes(void **state)
{
    (void)state;
    /* Each closed form is the linearisation the paper states, in general d: the
     * closed forms and the moment coefficients (27)-(30) are independent code. */
    const double ds[] = {2.0, 3.0, 4.5, 7.0};
    for (int i = 0; i < 4; i++) {
        double d = ds[i];
        for (double a = 0.015625; a < 1.0; a += 0.0625) {
            mus m = mu_at(a, d);
            double num = m.m40 - (d + 2) * m.m20;
            /* (31) = (10) */
            assert_close(ref_sonine_a2_white_noise(a, d), -num / (m.m41 - (d + 2) * m.m21),
                         1e-12, 1e-15);
            /* (32) */
            assert_close(ref_sonine_a2_white_noise_ratio(a, d),
                         -num / (m.m41 - m.m21 * m.m40 / m.m20), 1e-12, 1e-15);
            /* (39) = (5) */
            assert_close(ref_sonine_a2_gaussian(a, d),
                         -num / (m.m41 - (d + 2) * (m.m21 + m.m20)), 1e-12, 1e-15);
            /* (40) */
            assert_close(ref_sonine_a2_gaussian_alt(a, d),
                         -num / (m.m41 - m.m40 - (d + 2) * m.m21), 1e-12, 1e-15);
            /* (50): (44) with (26), (48), (49) linearised in a2. */
            double a2 = ref_sonine_a2_nongaussian(a, d);
            double lhs = ref_sonine_mu4(a, d, a2);
            double rhs = 2.0 * ref_sonine_mu2_0(a, d) * ref_sonine_mean_c3(d, 0.0)
                         / ref_sonine_mean_c(d, 0.0)
                         * (1.0 + a2 * (3.0 / 16.0 + 3.0 / 8.0 + 1.0 / 8.0));
            assert_close(lhs, rhs, 1e-12, 1e-14);
        }
    }
    /* (76) from (44) with (72)-(75) linearised, d = 3.  Only <c^3>/<c> = 2 at a2 = 0
     * enters; (75) as printed has 2 sqrt(2)/sqrt(pi) where (49) gives 4/sqrt(pi), and
     * only the latter reproduces (76). */
    for (double a = 0.0; a < 1.0; a += 0.0625) {
        mus m = mu_at(a, 3.0);
        double k = 23.0 / 20.0 * 3.0 / 8.0 + 3.0 / 2.0 / 8.0;
        double a2 = -(m.m40 - 4 * m.m20) / (13.0 / 15.0 * m.m41 - 4 * (1.05 * m.m21 + k * m.m20));
        assert_close(ref_sonine_a2_nongaussian_fit(a, 3.0), a2, 1e-12, 1e-15);
    }
}

static void test_a2_sign_and_limits(void **state)
{
    (void)state;
    const a2_fn changing[] = {ref_sonine_a2_white_noise, ref_sonine_a2_white_noise_ratio,
                              ref_sonine_a2_gaussian, ref_sonine_a2_gaussian_alt};
    for (double d = 2.0; d <= 4.0; d += 1.0) {
        for (int i = 0; i < 4; i++) {
            /* docs/theory.md §13.3: sign change at alpha = 1/sqrt(2) for (10), (32), (5), (40). */
            assert_close(changing[i](1.0 / sqrt(2.0), d), 0.0, 0, 1e-16);
            assert_true(changing[i](0.70, d) > 0.0);
            assert_true(changing[i](0.72, d) < 0.0);
            assert_true(changing[i](0.0, d) > 0.0);
            /* Elastic limit: a2 = 0, and +0 (printed "0", not "-0"). */
            assert_close(changing[i](1.0, d), 0.0, 0, 0);
            assert_false(signbit(changing[i](1.0, d)));
        }
        /* (50) stays negative (paper C §2.3); zero at alpha = 1. */
        for (double a = 0.0; a < 1.0; a += 0.03125)
            assert_true(ref_sonine_a2_nongaussian(a, d) < 0.0);
        assert_close(ref_sonine_a2_nongaussian(1.0, d), 0.0, 0, 0);
        assert_false(signbit(ref_sonine_a2_nongaussian(1.0, d)));
    }
    for (double a = 0.0; a < 1.0; a += 0.03125)
        assert_true(ref_sonine_a2_nongaussian_fit(a, 3.0) < 0.0);
    assert_close(ref_sonine_a2_nongaussian_fit(1.0, 3.0), 0.0, 0, 0);
    assert_false(signbit(ref_sonine_a2_nongaussian_fit(1.0, 3.0)));
    /* (76) is d = 3 only. */
    assert_true(isnan(ref_sonine_a2_nongaussian_fit(0.5, 2.0)));
    assert_true(isnan(ref_sonine_a2_nongaussian_fit(0.5, 3.5)));

    /* Paper C after (32): (10) and (32) differ by less than about 0.001 (d = 3). */
    for (double a = 0.0; a <= 1.0; a += 0.001)
        assert_close(ref_sonine_a2_white_noise_ratio(a, 3.0), ref_sonine_a2_white_noise(a, 3.0),
                     0, 0.001);
    /* Paper C after (40): in 0 < alpha < 0.3, (5) exceeds (40) by 12%-20% (d = 3) and
     * 18%-28% (d = 2); the ends of the interval, rounded to whole percent. */
    assert_close(round(100 * (ref_sonine_a2_gaussian(0.0, 3) / ref_sonine_a2_gaussian_alt(0.0, 3) - 1)),
                 20, 0, 0);
    assert_close(round(100 * (ref_sonine_a2_gaussian(0.3, 3) / ref_sonine_a2_gaussian_alt(0.3, 3) - 1)),
                 12, 0, 0);
    assert_close(round(100 * (ref_sonine_a2_gaussian(0.0, 2) / ref_sonine_a2_gaussian_alt(0.0, 2) - 1)),
                 28, 0, 0);
    assert_close(round(100 * (ref_sonine_a2_gaussian(0.3, 2) / ref_sonine_a2_gaussian_alt(0.3, 2) - 1)),
                 18, 0, 0);
}

static void test_table1_expansions(void **state)
{
    (void)state;
    /* Table 1's simulated mu4 (direct) against (26) at each thermostat's a2: the
     * white-noise theory is within 0.13%, Gaussian (40) within 1%, the non-Gaussian
     * fit (73) at (76) within 0.71%; (5) misses by 2.1% at alpha = 0.2 and (50) by
     * 2.3%-3.5% (paper C §4: (40) is the better Gaussian estimate, (50) is poor). */
    const double alpha[] = {0.2, 0.4, 0.6, 0.8};
    const double wn[] = {12.157, 10.602, 8.036, 4.499}, ga[] = {13.881, 11.494, 8.213, 4.414},
                 ng[] = {8.744, 7.631, 5.811, 3.335};
    for (int i = 0; i < 4; i++) {
        double a = alpha[i];
        assert_close(ref_sonine_mu4(a, 3, ref_sonine_a2_white_noise(a, 3)), wn[i], 0.002, 0);
        assert_close(ref_sonine_mu4(a, 3, ref_sonine_a2_gaussian_alt(a, 3)), ga[i], 0.01, 0);
        assert_close(ref_sonine_mu4_nongaussian_fit(a, 3, ref_sonine_a2_nongaussian_fit(a, 3)),
                     ng[i], 0.01, 0);
        assert_false(fabs(ref_sonine_mu4(a, 3, ref_sonine_a2_nongaussian(a, 3)) / ng[i] - 1)
                     < 0.02);
    }
    assert_false(fabs(ref_sonine_mu4(0.2, 3, ref_sonine_a2_gaussian(0.2, 3)) / ga[0] - 1) < 0.02);
}

/* ------------------------------------------------------ tail amplitudes */

static void test_tails(void **state)
{
    (void)state;
    /* docs/theory.md §13.4 / paper C §4.1: white noise A ≈ 1.99 (alpha = 0.4), 2.11 (0.5). */
    assert_printed(ref_sonine_tail_A_white_noise(0.4, 3.0), 1.99, 2);
    assert_printed(ref_sonine_tail_A_white_noise(0.5, 3.0), 2.11, 2);
    /* docs/theory.md §13.4 / paper C §4.2: Gaussian A ≈ 3.82 (alpha = 0.2), 4.41 (0.4). */
    assert_printed(ref_sonine_tail_A_gaussian(0.2, 3.0), 3.82, 2);
    assert_printed(ref_sonine_tail_A_gaussian(0.4, 3.0), 4.41, 2);
    /* The documented choice: mu2^(0) alone would miss the Gaussian digits (3.92, 4.48),
     * and so would (5)'s a2 at alpha = 0.2 (3.81). */
    double g0 = ref_sonine_tail_A_gaussian_mu2(ref_sonine_mu2_0(0.2, 3.0), 3.0);
    assert_close(g0, 3.0 * PI / (sqrt(2 * PI) * 0.96), 1e-14, 0);
    assert_false(fabs(g0 - 3.82) <= 0.005);
    assert_false(fabs(ref_sonine_tail_A_gaussian_mu2(
                          ref_sonine_mu2(0.2, 3.0, ref_sonine_a2_gaussian(0.2, 3.0)), 3.0)
                      - 3.82)
                 <= 0.005);
    /* (36), (42) as written, d = 3, mu2 = 2.385 (beta_1 = pi). */
    assert_close(ref_sonine_tail_A_white_noise_mu2(2.385, 3.0),
                 2.0 / 3.0 * sqrt(6.0 * PI / 2.385), 1e-15, 0);
    assert_close(ref_sonine_tail_A_gaussian_mu2(2.385, 3.0), 3.0 * PI / 2.385, 1e-15, 0);
    /* d = 2 (beta_1 = 2): A = (2/3) sqrt(8/mu2), A = 4/mu2. */
    assert_close(ref_sonine_tail_A_white_noise_mu2(2.385, 2.0), 2.0 / 3.0 * sqrt(8.0 / 2.385),
                 1e-15, 0);
    assert_close(ref_sonine_tail_A_gaussian_mu2(2.385, 2.0), 4.0 / 2.385, 1e-15, 0);
    /* The paper's route: A from the simulated mu2.  White noise, Table 1 at alpha = 0.4:
     * mu4 = 10.600 by (23), so mu2 = 10.600/5; A = 1.99 as printed. */
    assert_printed(ref_sonine_tail_A_white_noise_mu2(10.600 / 5.0, 3.0), 1.99, 2);
    /* (52) at a2 = 0: A' = sqrt(2)/(1 - alpha^2) at d = 3, as paper C states. */
    for (double a = 0.0; a < 1.0; a += 0.0625)
        assert_close(ref_sonine_tail_Aprime_nongaussian(a, 3.0), sqrt(2.0) / (1 - a * a), 1e-14,
                     0);
    /* The fitted A ≈ 1.48 (0.3), 1.51 (0.4) lies below the loss-only A' (gamma > 0). */
    assert_true(ref_sonine_tail_Aprime_nongaussian(0.3, 3.0) > 1.48);
    assert_true(ref_sonine_tail_Aprime_nongaussian(0.4, 3.0) > 1.51);
    /* alpha = 1: mu2 = 0, the amplitudes diverge. */
    assert_true(isinf(ref_sonine_tail_A_white_noise(1.0, 3.0)));
    assert_true(isinf(ref_sonine_tail_A_gaussian(1.0, 2.0)));
    assert_true(isinf(ref_sonine_tail_Aprime_nongaussian(1.0, 3.0)));
    assert_true(isinf(ref_sonine_tail_A_gaussian_mu2(0.0, 3.0)));
    /* White noise: A (1 - alpha)^(1/2) tends to a constant as alpha -> 1 (paper C §2.1). */
    double r1 = ref_sonine_tail_A_white_noise(1 - 1e-6, 3) * sqrt(1e-6);
    double r2 = ref_sonine_tail_A_white_noise(1 - 1e-8, 3) * sqrt(1e-8);
    assert_close(r1, r2, 1e-5, 0);
    assert_close(r2, 2.0 / 3.0 * sqrt(6.0 * PI / (2.0 * sqrt(2.0 * PI))), 1e-6, 0);
}

/* ------------------------------------------------------ the listing */

static void test_all(void **state)
{
    (void)state;
    ref_sonine_value v[REF_SONINE_ALL_COUNT + 1];
    const double a = 0.385, ds[] = {3.0, 2.0};
    for (int k = 0; k < 2; k++) {
        double d = ds[k];
        size_t n = ref_sonine_all(a, d, v, REF_SONINE_ALL_COUNT + 1);
        assert_int_equal(n, REF_SONINE_ALL_COUNT);
        for (size_t i = 0; i < n; i++) {
            assert_non_null(v[i].name);
            assert_non_null(v[i].source);
            assert_true(strlen(v[i].source) > 0);
            for (size_t j = 0; j < i; j++)
                assert_string_not_equal(v[i].name, v[j].name);
        }
        struct {
            const char *name;
            double value;
        } want[] = {
            {"beta_1", ref_sonine_beta(1, d)},
            {"beta_3", ref_sonine_beta(3, d)},
            {"mu2_0", ref_sonine_mu2_0(a, d)},
            {"mu2_1", ref_sonine_mu2_1(a, d)},
            {"mu4_0", ref_sonine_mu4_0(a, d)},
            {"mu4_1", ref_sonine_mu4_1(a, d)},
            {"a2_white_noise", ref_sonine_a2_white_noise(a, d)},
            {"a2_white_noise_ratio", ref_sonine_a2_white_noise_ratio(a, d)},
            {"a2_gaussian", ref_sonine_a2_gaussian(a, d)},
            {"a2_gaussian_alt", ref_sonine_a2_gaussian_alt(a, d)},
            {"a2_nongaussian", ref_sonine_a2_nongaussian(a, d)},
            {"a2_nongaussian_fit", ref_sonine_a2_nongaussian_fit(a, d)},
            {"mu2_white_noise", ref_sonine_mu2(a, d, ref_sonine_a2_white_noise(a, d))},
            {"mu4_white_noise", ref_sonine_mu4(a, d, ref_sonine_a2_white_noise(a, d))},
            {"mu2_gaussian", ref_sonine_mu2(a, d, ref_sonine_a2_gaussian(a, d))},
            {"mu4_gaussian", ref_sonine_mu4(a, d, ref_sonine_a2_gaussian(a, d))},
            {"mu2_gaussian_alt", ref_sonine_mu2(a, d, ref_sonine_a2_gaussian_alt(a, d))},
            {"mu4_gaussian_alt", ref_sonine_mu4(a, d, ref_sonine_a2_gaussian_alt(a, d))},
            {"mu2_nongaussian", ref_sonine_mu2(a, d, ref_sonine_a2_nongaussian(a, d))},
            {"mu4_nongaussian", ref_sonine_mu4(a, d, ref_sonine_a2_nongaussian(a, d))},
            {"mu2_nongaussian_fit",
             ref_sonine_mu2_nongaussian_fit(a, d, ref_sonine_a2_nongaussian_fit(a, d))},
            {"mu4_nongaussian_fit",
             ref_sonine_mu4_nongaussian_fit(a, d, ref_sonine_a2_nongaussian_fit(a, d))},
            {"A_white_noise", ref_sonine_tail_A_white_noise(a, d)},
            {"A_gaussian", ref_sonine_tail_A_gaussian(a, d)},
            {"A_white_noise_mu2_0", ref_sonine_tail_A_white_noise_mu2(ref_sonine_mu2_0(a, d), d)},
            {"A_gaussian_mu2_0", ref_sonine_tail_A_gaussian_mu2(ref_sonine_mu2_0(a, d), d)},
            {"Aprime_nongaussian", ref_sonine_tail_Aprime_nongaussian(a, d)},
            /* paper D (transport.h); the exact elastic values are d = 3 only */
            {"zeta_star", ref_transport_zeta_star(a, d)},
            {"nu_kappa_star", ref_transport_nu_kappa_star(a, d)},
            {"kappa_over_kappa0", ref_transport_kappa_star(a, d)},
            {"kappa_prime_over_kappa0", ref_transport_kappa_prime_star(a, d)},
            {"mu_star", ref_transport_mu_star(a, d)},
            {"zeta_star_modified", ref_transport_zeta_star_modified(a, d)},
            {"nu_kappa_star_modified", ref_transport_nu_kappa_star_modified(a, d)},
            {"kappa_over_kappa0_modified", ref_transport_kappa_star_modified(a, d)},
            {"kappa_prime_over_kappa0_modified", ref_transport_kappa_prime_star_modified(a, d)},
            {"mu_star_modified", ref_transport_mu_star_modified(a, d)},
            {"kappa_elastic_exact", d == 3.0 ? ref_transport_kappa_elastic_exact() : NAN},
            {"b1_elastic_exact", d == 3.0 ? ref_transport_b_elastic_exact(1) : NAN},
            {"b2_elastic_exact", d == 3.0 ? ref_transport_b_elastic_exact(2) : NAN},
            {"b3_elastic_exact", d == 3.0 ? ref_transport_b_elastic_exact(3) : NAN},
        };
        assert_int_equal(sizeof want / sizeof want[0], REF_SONINE_ALL_COUNT);
        for (size_t i = 0; i < sizeof want / sizeof want[0]; i++)
            assert_same(lookup(v, n, want[i].name), want[i].value, 0, 0);
        /* d = 3-only values are NaN at d = 2, the others finite. */
        for (size_t i = 0; i < n; i++) {
            if (d == 2.0 && (strstr(v[i].name, "nongaussian_fit")
                             || strstr(v[i].name, "elastic_exact")))
                assert_true(isnan(v[i].value));
            else
                assert_true(isfinite(v[i].value));
        }
    }
    /* Partial copy: cap values written, the total returned, the rest untouched. */
    ref_sonine_value few[3];
    few[2].name = "untouched";
    assert_int_equal(ref_sonine_all(0.2, 3.0, few, 2), REF_SONINE_ALL_COUNT);
    assert_string_equal(few[0].name, "beta_1");
    assert_string_equal(few[2].name, "untouched");
    assert_int_equal(ref_sonine_all(0.2, 3.0, NULL, 0), REF_SONINE_ALL_COUNT);
    /* docs/theory.md §13.1 check through the listing. */
    ref_sonine_all(0.2, 3.0, v, REF_SONINE_ALL_COUNT);
    assert_printed(lookup(v, REF_SONINE_ALL_COUNT, "mu4_0"), 10.925, 3);
    /* alpha = 1: a2 all zero, tails infinite. */
    ref_sonine_all(1.0, 3.0, v, REF_SONINE_ALL_COUNT);
    for (size_t i = 0; i < REF_SONINE_ALL_COUNT; i++) {
        if (strncmp(v[i].name, "a2_", 3) == 0)
            assert_close(v[i].value, 0.0, 0, 0);
        else if (v[i].name[0] == 'A')
            assert_true(isinf(v[i].value));
    }
}

/* ---------------------------------------------------------------- traps */

static void test_trap_bad_input(void **state)
{
    (void)state;
    const a2_fn fns[] = {ref_sonine_a2_white_noise, ref_sonine_a2_white_noise_ratio,
                         ref_sonine_a2_gaussian, ref_sonine_a2_gaussian_alt,
                         ref_sonine_a2_nongaussian, ref_sonine_a2_nongaussian_fit,
                         ref_sonine_mu2_0, ref_sonine_mu2_1, ref_sonine_mu4_0, ref_sonine_mu4_1,
                         ref_sonine_tail_A_white_noise, ref_sonine_tail_A_gaussian,
                         ref_sonine_tail_Aprime_nongaussian};
    const double bad_alpha[] = {-0.1, -1e-300, 1.0000001, 1.2, NAN, INFINITY, -INFINITY};
    const double bad_d[] = {1.0, 1.999, 100.5, 1e300, NAN, INFINITY, -3.0};
    for (size_t f = 0; f < sizeof fns / sizeof fns[0]; f++) {
        assert_false(isnan(fns[f](0.5, 3.0)));
        for (size_t i = 0; i < sizeof bad_alpha / sizeof bad_alpha[0]; i++)
            assert_true(isnan(fns[f](bad_alpha[i], 3.0)));
        for (size_t i = 0; i < sizeof bad_d / sizeof bad_d[0]; i++)
            assert_true(isnan(fns[f](0.5, bad_d[i])));
    }
    /* The accepted ends of the ranges. */
    assert_false(isnan(ref_sonine_mu4_1(0.5, REF_SONINE_D_MIN)));
    assert_false(isnan(ref_sonine_mu4_1(0.5, REF_SONINE_D_MAX)));
    assert_true(isfinite(ref_sonine_tail_A_gaussian(0.5, REF_SONINE_D_MAX)));
    /* Non-finite a2. */
    assert_true(isnan(ref_sonine_mu2(0.5, 3.0, NAN)));
    assert_true(isnan(ref_sonine_mu4(0.5, 3.0, INFINITY)));
    assert_true(isnan(ref_sonine_mu2_nongaussian_fit(0.5, 3.0, NAN)));
    assert_true(isnan(ref_sonine_mu4_nongaussian_fit(0.5, 3.0, -INFINITY)));
    assert_true(isnan(ref_sonine_mean_c(3.0, NAN)));
    assert_true(isnan(ref_sonine_mean_c3(1.5, 0.0)));
    assert_true(isnan(ref_sonine_mu2(1.5, 3.0, 0.0)));
    /* beta_n: n > -1, d in range. */
    assert_true(isnan(ref_sonine_beta(-1.0, 3.0)));
    assert_true(isnan(ref_sonine_beta(NAN, 3.0)));
    assert_true(isnan(ref_sonine_beta(INFINITY, 3.0)));
    assert_true(isnan(ref_sonine_beta(1.0, 1.0)));
    assert_false(isnan(ref_sonine_beta(-0.5, 3.0)));
    /* Tails from mu2: mu2 >= 0 and finite. */
    assert_true(isnan(ref_sonine_tail_A_white_noise_mu2(-0.1, 3.0)));
    assert_true(isnan(ref_sonine_tail_A_gaussian_mu2(NAN, 3.0)));
    assert_true(isnan(ref_sonine_tail_A_gaussian_mu2(INFINITY, 3.0)));
    assert_true(isnan(ref_sonine_tail_A_white_noise_mu2(2.0, 1.0)));
    /* The listing writes nothing and returns 0. */
    ref_sonine_value v[1] = {{"untouched", 1.0, "x"}};
    assert_int_equal(ref_sonine_all(1.2, 3.0, v, 1), 0);
    assert_int_equal(ref_sonine_all(NAN, 3.0, v, 1), 0);
    assert_int_equal(ref_sonine_all(0.5, 1.0, v, 1), 0);
    assert_int_equal(ref_sonine_all(0.5, INFINITY, v, 1), 0);
    assert_string_equal(v[0].name, "untouched");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_beta),
        cmocka_unit_test(test_mu2_0),
        cmocka_unit_test(test_mu4_0_table1),
        cmocka_unit_test(test_mu4_1),
        cmocka_unit_test(test_mu_expansions),
        cmocka_unit_test(test_a2_d3_forms),
        cmocka_unit_test(test_a2_mu_routes),
        cmocka_unit_test(test_a2_sign_and_limits),
        cmocka_unit_test(test_table1_expansions),
        cmocka_unit_test(test_tails),
        cmocka_unit_test(test_all),
        cmocka_unit_test(test_trap_bad_input),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
