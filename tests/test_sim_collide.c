/* The collision rule of SPEC §3 (paper A Eq. (3)). */
#include "test_util.h"

#include "collide.h"
#include "rng.h"

static void random_vector(gsl_rng *r, double scale, double x[3])
{
    for (int k = 0; k < 3; k++)
        x[k] = scale * (2.0 * sim_rng_uniform(r) - 1.0);
}

/* Momentum v + w is conserved to round-off and the energy changes by exactly
 * -(1 - alpha^2)/4 (1 - mu) |g|^2, mu = (g.e)/|g| (SPEC §3). */
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_conservation_and_energy_loss),
        cmocka_unit_test(test_relative_velocity),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
