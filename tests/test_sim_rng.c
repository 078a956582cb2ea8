/* Random streams and samplers: z-tests with fixed seeds (bound 4 sigma, so a
 * wrong sampler fails and a right one passes for these seeds). */
#include "test_util.h"

#include <stdint.h>
#include <string.h>

#include "collide.h"
#include "rng.h"

#define SAMPLES 400000
#define ZMAX 4.0

/* |sample mean - expected| <= ZMAX standard errors. */
static void assert_mean_z(double sum, double expected, double variance, double count)
{
    double z = (sum / count - expected) / sqrt(variance / count);
    if (fabs(z) > ZMAX) {
        print_error("sample mean %.10g, expected %.10g, z = %.3f\n", sum / count, expected, z);
        fail();
    }
}

static gsl_rng *stream(uint64_t seed, uint64_t id)
{
    gsl_rng *r = sim_rng_alloc();
    assert_non_null(r);
    sim_rng_set_stream(r, seed, id);
    return r;
}

static void test_uniform(void **state)
{
    (void)state;
    gsl_rng *r = stream(2385, 0);
    double s1 = 0, s2 = 0, lo = 1, hi = 0;
    for (int i = 0; i < SAMPLES; i++) {
        double u = sim_rng_uniform_pos(r);
        s1 += u;
        s2 += u * u;
        lo = fmin(lo, u);
        hi = fmax(hi, u);
    }
    assert_true(lo > 0.0 && hi < 1.0);
    assert_mean_z(s1, 0.5, 1.0 / 12.0, SAMPLES);
    assert_mean_z(s2, 1.0 / 3.0, 1.0 / 5.0 - 1.0 / 9.0, SAMPLES);
    gsl_rng_free(r);
}

/* Standard normal: E x = 0, E x^2 = 1 (Var x^2 = 2), E x^4 = 3 (Var 96). */
static void test_normal(void **state)
{
    (void)state;
    gsl_rng *r = stream(2385, 1);
    double s1 = 0, s2 = 0, s4 = 0;
    for (int i = 0; i < SAMPLES / 3; i++) {
        double xi[3];
        sim_rng_normal3(r, xi);
        for (int k = 0; k < 3; k++) {
            s1 += xi[k];
            s2 += xi[k] * xi[k];
            s4 += xi[k] * xi[k] * xi[k] * xi[k];
        }
    }
    double count = 3.0 * (SAMPLES / 3);
    assert_mean_z(s1, 0.0, 1.0, count);
    assert_mean_z(s2, 1.0, 2.0, count);
    assert_mean_z(s4, 3.0, 96.0, count);
    assert_int_equal(sim_rng_state_of(r)->normals, (uint64_t)count);
    gsl_rng_free(r);
}

/* Uniform on S^2: |e| = 1, E e = 0, E e_k^2 = 1/3 (Var 4/45), E e_z^4 = 1/5. */
static void test_unit_sphere(void **state)
{
    (void)state;
    gsl_rng *r = stream(2385, 2);
    double s1[3] = {0}, s2[3] = {0}, s4 = 0, sxy = 0;
    for (int i = 0; i < SAMPLES; i++) {
        double e[3];
        sim_rng_unit_sphere(r, e);
        assert_close(sim_norm3(e), 1.0, 1e-15, 0.0);
        for (int k = 0; k < 3; k++) {
            s1[k] += e[k];
            s2[k] += e[k] * e[k];
        }
        s4 += e[2] * e[2] * e[2] * e[2];
        sxy += e[0] * e[1];
    }
    for (int k = 0; k < 3; k++) {
        assert_mean_z(s1[k], 0.0, 1.0 / 3.0, SAMPLES);
        assert_mean_z(s2[k], 1.0 / 3.0, 1.0 / 5.0 - 1.0 / 9.0, SAMPLES);
    }
    assert_mean_z(sxy, 0.0, 1.0 / 15.0, SAMPLES);
    assert_mean_z(s4, 1.0 / 5.0, 1.0 / 7.0 - 1.0 / 25.0, SAMPLES);
    gsl_rng_free(r);
}

/* sim_rng_index(n) is uniform on 0..n-1: chi-square with 6 degrees of freedom
 * below 22.46 (p = 0.001) for n = 7. */
static void test_index(void **state)
{
    (void)state;
    gsl_rng *r = stream(2385, 3);
    double count[7] = {0};
    for (int i = 0; i < SAMPLES; i++) {
        uint64_t k = sim_rng_index(r, 7);
        assert_true(k < 7);
        count[k] += 1.0;
    }
    double chi2 = 0.0, expected = SAMPLES / 7.0;
    for (int k = 0; k < 7; k++)
        chi2 += (count[k] - expected) * (count[k] - expected) / expected;
    assert_true(chi2 < 22.46);
    gsl_rng_free(r);
}

/* A stream is fixed by (seed, id); other ids and seeds give other numbers. */
static void test_streams(void **state)
{
    (void)state;
    gsl_rng *a = stream(77, 5), *b = stream(77, 5), *c = stream(77, 6), *d = stream(78, 5);
    int same_c = 0, same_d = 0;
    for (int i = 0; i < 1000; i++) {
        uint64_t x = sim_rng_u64(a);
        assert_int_equal(x, sim_rng_u64(b));
        same_c += x == sim_rng_u64(c);
        same_d += x == sim_rng_u64(d);
    }
    assert_int_equal(same_c, 0);
    assert_int_equal(same_d, 0);
    /* restarting a stream replays it */
    sim_rng_set_stream(a, 77, 5);
    sim_rng_set_stream(b, 77, 5);
    assert_int_equal(gsl_rng_get(a), sim_rng_u64(b));
    gsl_rng_free(a);
    gsl_rng_free(b);
    gsl_rng_free(c);
    gsl_rng_free(d);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_uniform),     cmocka_unit_test(test_normal),
        cmocka_unit_test(test_unit_sphere), cmocka_unit_test(test_index),
        cmocka_unit_test(test_streams),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
