/* The collision rules of docs/theory.md §3.1 (paper A Eq. (3)) and §3.4 (paper B Eq. (2)),
 * and the background partner samplers of paper B's Algorithm 2. */
#include "test_util.h"

#include "background_partner.h"
#include "collide.h"
#include "rng.h"

static void random_vector(gsl_rng *r, double scale, double x[3])
{
    for (int k = 0; k < 3; k++)
        x[k] = scale * (2.0 * sim_rng_uniform(r) - 1.0);
}

/* Momentum v + w is conserved to round-off and the energy changes by exactly
 * -(1 - alpha^2)/4 (1 - mu) |g|^2, mu = (g.e)/|g| (docs/theory.md §3.1). */
static void test_conservation_and_energy_loss(void **state)
{
    (void)state;
    gsl_rng *r = sim_rng_alloc();
    sim_rng_set_stream(r, 2385, 1);
    const double alphas[] = {0.3817, 0.5, 0.9, 1.0, 1e-3};
    for (size_t a = 0; a < sizeof alphas / sizeof *alphas; a++) {
        for (int trial = 0; trial < 2000; trial++) {
            double v[3], w[3], e[3];
            random_vector(r, 3.7, v);
            random_vector(r, 2.1, w);
            sim_rng_unit_sphere(r, e);
            double g[3] = {v[0] - w[0], v[1] - w[1], v[2] - w[2]};
            double gnorm = sim_norm3(g);
            double mu = (g[0] * e[0] + g[1] * e[1] + g[2] * e[2]) / gnorm;
            double p0[3] = {v[0] + w[0], v[1] + w[1], v[2] + w[2]};
            double e0 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + w[0] * w[0] + w[1] * w[1]
                        + w[2] * w[2];

            sim_collide_inelastic(v, w, alphas[a], gnorm, e);

            for (int k = 0; k < 3; k++)
                assert_close(v[k] + w[k], p0[k], 0.0, 1e-14 * (fabs(p0[k]) + gnorm));
            double e1 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + w[0] * w[0] + w[1] * w[1]
                        + w[2] * w[2];
            double expected = -(1.0 - alphas[a] * alphas[a]) / 4.0 * (1.0 - mu) * gnorm * gnorm;
            assert_close(e1 - e0, expected, 0.0, 1e-13 * e0);
        }
    }
    gsl_rng_free(r);
}

/* The post-collision relative velocity is (1-alpha)/2 g + (1+alpha)/2 |g| e:
 * with alpha = 1 its length is |g| (elastic), with alpha -> 0 the normal part
 * of the relative motion is only halved. */
static void test_relative_velocity(void **state)
{
    (void)state;
    double v[3] = {1.25, -0.5, 2.0}, w[3] = {-0.75, 0.3, 0.1}, e[3] = {0.6, 0.0, 0.8};
    double g[3] = {v[0] - w[0], v[1] - w[1], v[2] - w[2]};
    double gnorm = sim_norm3(g), alpha = 0.37;
    sim_collide_inelastic(v, w, alpha, gnorm, e);
    for (int k = 0; k < 3; k++)
        assert_close(v[k] - w[k], 0.5 * (1 - alpha) * g[k] + 0.5 * (1 + alpha) * gnorm * e[k],
                     0.0, 1e-15 * gnorm);
}

/* Paper B Eq. (2): with the partner's w' = (1-a) v + a w - (1-a)|g| e, the pair
 * conserves m v + m_B w and m|v|^2 + m_B|w|^2 (a = m_B/(m + m_B)). */
static void test_elastic_background_rule(void **state)
{
    (void)state;
    gsl_rng *r = sim_rng_alloc();
    sim_rng_set_stream(r, 2385, 2);
    const double masses[][2] = {{1.0, 1.0}, {1.0, 0.125}, {5.0, 3.0}, {1.0, 1e-6}};
    for (size_t c = 0; c < sizeof masses / sizeof *masses; c++) {
        double m = masses[c][0], mb = masses[c][1], a = mb / (m + mb);
        for (int trial = 0; trial < 2000; trial++) {
            double v[3], w[3], e[3], v0[3], w1[3];
            random_vector(r, 3.7, v);
            random_vector(r, 2.1, w);
            sim_rng_unit_sphere(r, e);
            double g[3] = {v[0] - w[0], v[1] - w[1], v[2] - w[2]}, gnorm = sim_norm3(g);
            for (int k = 0; k < 3; k++) {
                v0[k] = v[k];
                w1[k] = (1.0 - a) * v[k] + a * w[k] - (1.0 - a) * gnorm * e[k];
            }
            sim_collide_elastic(v, w, a, gnorm, e);
            double e0 = 0.0, e1 = 0.0, scale = gnorm + sim_norm3(v0) + sim_norm3(w);
            for (int k = 0; k < 3; k++) {
                assert_close(m * v[k] + mb * w1[k], m * v0[k] + mb * w[k], 0.0,
                             1e-14 * (m + mb) * scale);
                e0 += m * v0[k] * v0[k] + mb * w[k] * w[k];
                e1 += m * v[k] * v[k] + mb * w1[k] * w1[k];
            }
            assert_close(e1, e0, 1e-13, 0.0);
        }
    }
    gsl_rng_free(r);
}

/* z-score of a sample mean against mu (sample variance). */
typedef struct moment {
    double n, sum, sum2;
} moment;

static void moment_add(moment *m, double x)
{
    m->n += 1.0;
    m->sum += x;
    m->sum2 += x * x;
}

static double moment_z(const moment *m, double mu)
{
    double mean = m->sum / m->n, var = m->sum2 / m->n - mean * mean;
    return (mean - mu) / sqrt(var / m->n);
}

#define NSAMPLES 400000
#define ZMAX 4.5

/* Partners from f^B: mean u_B, per-component variance sigma^2; from p2 ∝
 * |w - u_B| f^B: s = |w - u_B|/b with s^2 ~ Gamma(2, 1) (E s^2 = 2,
 * E s^4 = 6), E s = Gamma(5/2)/Gamma(2) = 3 sqrt(pi)/4, isotropic.  A
 * chi-square over 20 equiprobable bins of F(s) = 1 - (1 + s^2) e^{-s^2}
 * tests the whole density.  The same tests reject the Maxwellian partner as
 * a p2 sample (the wrong-answer check). */
static void test_background_partners(void **state)
{
    (void)state;
    gsl_rng *r = sim_rng_alloc();
    sim_rng_set_stream(r, 2385, 3);
    const double u_B[3] = {0.3, -1.0, 2.0}, T_B = 1.7, m_B = 0.4;
    const double sigma = sqrt(T_B / m_B), b = sqrt(2.0 * T_B / m_B);

    moment mw[3] = {{0}}, mw2 = {0}, s1 = {0}, s2 = {0}, s4 = {0}, dir[3] = {{0}};
    moment wrong_s1 = {0}, wrong_s2 = {0};
    double bins[20] = {0}, wrong_bins[20] = {0};
    for (int i = 0; i < NSAMPLES; i++) {
        double w[3];
        sim_background_partner(u_B, sigma, r, w);
        double d[3] = {w[0] - u_B[0], w[1] - u_B[1], w[2] - u_B[2]}, s = sim_norm3(d) / b;
        for (int k = 0; k < 3; k++)
            moment_add(&mw[k], w[k]);
        moment_add(&mw2, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        moment_add(&wrong_s1, s);
        moment_add(&wrong_s2, s * s);
        wrong_bins[(int)fmin(19.0, 20.0 * (1.0 - (1.0 + s * s) * exp(-s * s)))] += 1.0;

        double speed = sim_background_flux_partner(u_B, b, r, w);
        double e[3] = {w[0] - u_B[0], w[1] - u_B[1], w[2] - u_B[2]};
        assert_close(sim_norm3(e), speed, 1e-14, 0.0);
        s = speed / b;
        moment_add(&s1, s);
        moment_add(&s2, s * s);
        moment_add(&s4, s * s * s * s);
        for (int k = 0; k < 3; k++)
            moment_add(&dir[k], e[k] / speed);
        bins[(int)fmin(19.0, 20.0 * (1.0 - (1.0 + s * s) * exp(-s * s)))] += 1.0;
    }
    for (int k = 0; k < 3; k++) {
        assert_true(fabs(moment_z(&mw[k], u_B[k])) < ZMAX);
        assert_true(fabs(moment_z(&dir[k], 0.0)) < ZMAX);
    }
    assert_true(fabs(moment_z(&mw2, 3.0 * sigma * sigma)) < ZMAX);
    assert_true(fabs(moment_z(&s1, 0.75 * sqrt(M_PI))) < ZMAX);
    assert_true(fabs(moment_z(&s2, 2.0)) < ZMAX);
    assert_true(fabs(moment_z(&s4, 6.0)) < ZMAX);
    double chi2 = 0.0, wrong_chi2 = 0.0, expected = NSAMPLES / 20.0;
    for (int i = 0; i < 20; i++) {
        chi2 += (bins[i] - expected) * (bins[i] - expected) / expected;
        wrong_chi2 += (wrong_bins[i] - expected) * (wrong_bins[i] - expected) / expected;
    }
    print_message("p2 speed chi^2 = %.1f (19 dof), Maxwellian partner as p2: %.1f\n", chi2,
                  wrong_chi2);
    assert_true(chi2 < 43.8);   /* 0.999 quantile of chi^2 with 19 degrees of freedom */
    /* the Maxwellian's speeds are not p2's: every test above rejects them */
    assert_true(wrong_chi2 > 43.8);
    assert_true(fabs(moment_z(&wrong_s1, 0.75 * sqrt(M_PI))) > ZMAX);
    assert_true(fabs(moment_z(&wrong_s2, 2.0)) > ZMAX);
    gsl_rng_free(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_conservation_and_energy_loss),
        cmocka_unit_test(test_relative_velocity),
        cmocka_unit_test(test_elastic_background_rule),
        cmocka_unit_test(test_background_partners),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
