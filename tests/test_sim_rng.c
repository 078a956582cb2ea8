/* Random streams and samplers: z-tests with fixed seeds (bound 4 sigma, so a
 * wrong sampler fails and a right one passes for these seeds), chi-square
 * tests against their 0.999 quantiles; each kind of test is also shown a
 * wrong sampler (or a wrong expectation) and must fail it. */
#include "test_util.h"

#include <stdint.h>
#include <string.h>

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>

#include "collide.h"
#include "particles.h"
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

/* Pearson's chi-square of counts against equal expectations. */
static double chi2_equal(const double *count, int bins, double total)
{
    double chi2 = 0.0, expected = total / bins;
    for (int k = 0; k < bins; k++)
        chi2 += (count[k] - expected) * (count[k] - expected) / expected;
    return chi2;
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

/* Standard normal: E x = 0, E x^2 = 1 (Var x^2 = 2), E x^4 = 3 (Var 96);
 * the inline ziggurat and GSL's (the initial states) alike. */
static void check_normal3(void (*normal3)(gsl_rng *, double *), uint64_t id)
{
    gsl_rng *r = stream(2385, id);
    double s1 = 0, s2 = 0, s4 = 0;
    for (int i = 0; i < SAMPLES / 3; i++) {
        double xi[3];
        normal3(r, xi);
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

static void test_normal(void **state)
{
    (void)state;
    check_normal3(sim_rng_normal3, 1);
    check_normal3(sim_rng_normal3_gsl, 11);
}

/* The ziggurat's tables close: every layer has the area V of the base strip
 * (rectangle and tail), the top one (x[128] = 0) included. */
static void test_ziggurat_table(void **state)
{
    (void)state;
    gsl_rng *r = stream(1, 1);   /* builds the tables */
    const sim_ziggurat *z = &sim_ziggurat_table;
    const double r_edge = z->r, V = z->w[0] * 0x1p24 * z->f[1];
    for (int i = 1; i < SIM_ZIGGURAT_LAYERS; i++) {
        const double x = z->w[i] * 0x1p24;
        assert_close(x * (z->f[i + 1] - z->f[i]), V, 1e-13, 0.0);
        assert_close(z->f[i], exp(-0.5 * x * x), 1e-15, 0.0);
    }
    assert_close(r_edge, 3.442619855899, 1e-12, 0.0);   /* Marsaglia and Tsang's */
    assert_close(z->w[1] * 0x1p24, r_edge, 1e-15, 0.0);
    /* the base strip: the rectangle under f(r) and the tail beyond r */
    assert_close(V, r_edge * z->f[1] + sqrt(M_PI / 2.0) * erfc(r_edge / M_SQRT2), 1e-14, 0.0);
    assert_true(z->k[SIM_ZIGGURAT_LAYERS - 1] == 0.0 && z->f[SIM_ZIGGURAT_LAYERS] == 1.0);
    gsl_rng_free(r);
}

/* The ziggurat's tail sampler, replaced by a plain exponential beyond r: the
 * wrong sampler its tail test must fail. */
static double normal_wrong_tail(gsl_rng *r)
{
    const double x = sim_rng_normal(r), edge = sim_ziggurat_table.r;
    return fabs(x) > edge ? copysign(edge - log(sim_rng_uniform_pos(r)) / edge, x) : x;
}

static double normal_wide(gsl_rng *r) { return 1.003 * sim_rng_normal(r); }

typedef struct normal_test {
    double chi2;       /* 40 equal-probability bins, 39 dof */
    double z_tail;     /* P(|x| > r), r = 3.4426: the tail sampler's share */
    double z_excess;   /* E(|x| - r | |x| > r) = 0.26516... against its mean */
    double z_pair;     /* E x_k x_k+1 = 0: the two halves of a word */
} normal_test;

#define NORMAL_SAMPLES 8000000

static normal_test test_normals(double (*normal)(gsl_rng *), uint64_t id)
{
    gsl_rng *r = stream(2385, id);
    enum { BINS = 40 };
    double count[BINS] = {0}, tail = 0, excess = 0, excess2 = 0, pair = 0, last = 0;
    const double edge = 3.442619855899;
    for (long i = 0; i < NORMAL_SAMPLES; i++) {
        const double x = normal(r);
        int b = (int)(gsl_cdf_ugaussian_P(x) * BINS);
        count[b < BINS ? b : BINS - 1] += 1.0;
        if (fabs(x) > edge) {
            tail += 1.0;
            excess += fabs(x) - edge;
            excess2 += (fabs(x) - edge) * (fabs(x) - edge);
        }
        pair += x * last;
        last = x;
    }
    gsl_rng_free(r);
    const double p = 2.0 * gsl_cdf_ugaussian_Q(edge), N = NORMAL_SAMPLES;
    /* the excess's exact mean: E(x - r | x > r) = phi(r)/Q(r) - r */
    const double mean = gsl_ran_ugaussian_pdf(edge) / gsl_cdf_ugaussian_Q(edge) - edge;
    const double var = excess2 / tail - (excess / tail) * (excess / tail);
    return (normal_test){chi2_equal(count, BINS, N), (tail - N * p) / sqrt(N * p * (1 - p)),
                         (excess / tail - mean) / sqrt(var / tail), pair / sqrt(N)};
}

/* sim_rng_normal against the normal law: 40 equal-probability bins (0.999
 * quantile of chi-square with 39 dof: 72.05), the tail beyond r (count and
 * mean excess, z within 4) and the two normals of one word uncorrelated.  A
 * width 0.3% too large fails the chi-square; an exponential tail fails the
 * excess. */
static void test_normal_law(void **state)
{
    (void)state;
    const normal_test t = test_normals(sim_rng_normal, 12);
    const normal_test wide = test_normals(normal_wide, 12), tail = test_normals(normal_wrong_tail, 12);
    print_message("normals: chi^2 %.1f, tail z %.2f, excess z %.2f, pair z %.2f; 1.003 wide chi^2 "
                  "%.1f; exponential tail excess z %.2f\n",
                  t.chi2, t.z_tail, t.z_excess, t.z_pair, wide.chi2, tail.z_excess);
    assert_true(t.chi2 < 72.05);
    assert_true(fabs(t.z_tail) < ZMAX && fabs(t.z_excess) < ZMAX && fabs(t.z_pair) < ZMAX);
    assert_true(wide.chi2 > 72.05);
    assert_true(fabs(tail.z_excess) > ZMAX);
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

/* sim_rng_index32 with n = 3 2^30, where Lemire's method rejects a quarter of
 * the words: without the rejection, index = floor(3 x / 4) hits indices
 * 0 mod 3 twice as often as the others (1/2 instead of 1/3), which the
 * chi-square of index mod 3 must show; with it they are uniform.  The spare
 * half is uniform (8 bins) and independent of the index (its mean is the same
 * for even and odd indices). */
static void test_index32(void **state)
{
    (void)state;
    gsl_rng *r = stream(2385, 4);
    const uint32_t n = 3u << 30;
    double mod3[3] = {0}, naive3[3] = {0}, spare_bins[8] = {0}, sum[2] = {0}, cnt[2] = {0};
    for (int i = 0; i < SAMPLES; i++) {
        uint32_t spare, k = sim_rng_index32(r, n, &spare);
        assert_true(k < n);
        mod3[k % 3] += 1.0;
        spare_bins[spare >> 29] += 1.0;
        sum[k & 1] += spare * 0x1p-32;
        cnt[k & 1] += 1.0;
        /* the wrong sampler: the multiply without the rejection */
        uint32_t naive = (uint32_t)(((uint64_t)(uint32_t)sim_rng_u64(r) * n) >> 32);
        naive3[naive % 3] += 1.0;
    }
    double chi2 = chi2_equal(mod3, 3, SAMPLES), wrong = chi2_equal(naive3, 3, SAMPLES);
    print_message("index mod 3: chi^2 = %.2f, without rejection %.0f (2 dof)\n", chi2, wrong);
    assert_true(chi2 < 13.82);    /* 0.999 quantile, 2 degrees of freedom */
    assert_true(wrong > 13.82);
    assert_true(chi2_equal(spare_bins, 8, SAMPLES) < 24.32);   /* 7 dof */
    assert_mean_z(sum[0], 0.5, 1.0 / 12.0, cnt[0]);
    assert_mean_z(sum[1], 0.5, 1.0 / 12.0, cnt[1]);
    /* n = 1 and n = 2^32 - 1 stay in range */
    uint32_t spare;
    assert_int_equal(sim_rng_index32(r, 1, &spare), 0);
    assert_true(sim_rng_index32(r, UINT32_MAX, &spare) < UINT32_MAX);
    gsl_rng_free(r);
}

/* Binomial z-score of `hits` successes in `trials` with probability p. */
static double binomial_z(double hits, double trials, double p)
{
    return (hits - trials * p) / sqrt(trials * p * (1.0 - p));
}

/* sim_rng_accept32 and sim_rng_accept32_ratio succeed with probability x/2^32
 * and num/den: z-tests at p = 0.3172 and at p = 0.731 within one step of the
 * 32-bit grid (u = 5, x = 5.731: only the refinement decides), where the
 * comparison of u alone (u < x) would always succeed; x <= u never
 * succeeds, x >= u + 1 always; den = 0 never. */
static void test_accept32(void **state)
{
    (void)state;
    gsl_rng *r = stream(2385, 5);
    const double p = 0.3172;
    double hits = 0, hits_ratio = 0, tie = 0, tie_ratio = 0;
    for (int i = 0; i < SAMPLES; i++) {
        const uint32_t u = (uint32_t)sim_rng_u64(r), v = (uint32_t)sim_rng_u64(r);
        hits += sim_rng_accept32(r, u, p * 0x1p32);
        hits_ratio += sim_rng_accept32_ratio(r, v, 2.0 * p, 2.0);
        tie += sim_rng_accept32(r, 5, 5.731);
        tie_ratio += sim_rng_accept32_ratio(r, 5, 5.731 * 0x1p-32 * 3.0, 3.0);
    }
    double z[4] = {binomial_z(hits, SAMPLES, p), binomial_z(hits_ratio, SAMPLES, p),
                   binomial_z(tie, SAMPLES, 0.731), binomial_z(tie_ratio, SAMPLES, 0.731)};
    print_message("accept32 z: %.2f %.2f, undecided by 32 bits: %.2f %.2f\n", z[0], z[1], z[2],
                  z[3]);
    for (int k = 0; k < 4; k++)
        assert_true(fabs(z[k]) < ZMAX);
    /* the wrong answer: deciding by u < x alone succeeds every time */
    assert_true(fabs(binomial_z(SAMPLES, SAMPLES, 0.731)) > ZMAX);
    for (int i = 0; i < 1000; i++) {
        assert_false(sim_rng_accept32(r, 7, 7.0));
        assert_true(sim_rng_accept32(r, 7, 8.0));
        assert_false(sim_rng_accept32(r, 0, 0.0));
        assert_true(sim_rng_accept32(r, UINT32_MAX, 0x1p32));
        assert_false(sim_rng_accept32(r, 0, NAN));
        assert_false(sim_rng_accept32_ratio(r, 0, 0.0, 0.0));
        assert_true(sim_rng_accept32_ratio(r, UINT32_MAX, 1.0, 1.0));
    }
    gsl_rng_free(r);
}

/* Marsaglia's directions: e_z uniform on [-1, 1] and the azimuth uniform
 * (chi-square, 20 bins each, 19 dof: 0.999 quantile 43.82); the same tests
 * reject directions that are uniform in the cube's angles (x, y, z uniform
 * on [-1, 1], normalised: not uniform on the sphere). */
static void test_unit_sphere_uniform(void **state)
{
    (void)state;
    gsl_rng *r = stream(2385, 6);
    double z_bins[20] = {0}, phi_bins[20] = {0}, wrong_bins[20] = {0};
    for (int i = 0; i < SAMPLES; i++) {
        double e[3];
        sim_rng_unit_sphere(r, e);
        z_bins[(int)fmin(19.0, 10.0 * (e[2] + 1.0))] += 1.0;
        phi_bins[(int)fmin(19.0, 20.0 * (atan2(e[1], e[0]) + M_PI) / (2.0 * M_PI))] += 1.0;
        double c[3];
        for (int k = 0; k < 3; k++)
            c[k] = 2.0 * sim_rng_uniform(r) - 1.0;
        double norm = sim_norm3(c);
        wrong_bins[(int)fmin(19.0, 10.0 * (c[2] / norm + 1.0))] += 1.0;
    }
    double chi_z = chi2_equal(z_bins, 20, SAMPLES), chi_phi = chi2_equal(phi_bins, 20, SAMPLES);
    double wrong = chi2_equal(wrong_bins, 20, SAMPLES);
    print_message("unit sphere: chi^2 e_z %.1f, azimuth %.1f; cube directions e_z %.0f\n", chi_z,
                  chi_phi, wrong);
    assert_true(chi_z < 43.82);
    assert_true(chi_phi < 43.82);
    assert_true(wrong > 43.82);
    gsl_rng_free(r);
}

/* The index streams of particles.h: sim_pick's entries and sim_batch's are
 * uniform on 0..n-1 and consecutive entries independent (chi-square over the
 * 7 x 7 pairs, 48 dof: 0.999 quantile 84.04), including the entries used to
 * redraw j == i.  The wrong answer: pairs drawn as j uniform over the others
 * (never equal) fail the independence test. */
static void test_index_streams(void **state)
{
    (void)state;
    gsl_rng *r = stream(2385, 7);
    sim_particles p;
    assert_int_equal(sim_particles_alloc(&p, 7, 0, NULL), SIM_OK);
    sim_pick pick;
    sim_batch batch;
    sim_pick_start(&pick, &p, r);
    sim_batch_start(&batch, &p, r);
    double pairs[49] = {0}, batch_pairs[49] = {0}, distinct[49] = {0};
    uint32_t spare, prev = sim_pick_next(&pick, &p, r, &spare, 0), prev_b = batch.index[0];
    batch.pos = 1;
    for (int i = 0; i < SAMPLES; i++) {
        uint32_t k = sim_pick_next(&pick, &p, r, &spare, 0);
        assert_true(k < 7);
        pairs[7 * prev + k] += 1.0;
        prev = k;
        if (batch.pos == SIM_BATCH)
            sim_batch_advance(&batch, &p, r);
        uint32_t b = batch.index[batch.pos++];
        batch_pairs[7 * prev_b + b] += 1.0;
        prev_b = b;
        uint32_t j = (uint32_t)sim_rng_index(r, 6);
        distinct[7 * k + j + (j >= k)] += 1.0;
    }
    double chi = chi2_equal(pairs, 49, SAMPLES), chi_b = chi2_equal(batch_pairs, 49, SAMPLES);
    double wrong = chi2_equal(distinct, 49, SAMPLES);
    print_message("index pairs: chi^2 %.1f (pick), %.1f (batch); distinct pairs %.0f\n", chi,
                  chi_b, wrong);
    assert_true(chi < 84.04);
    assert_true(chi_b < 84.04);
    assert_true(wrong > 84.04);
    sim_particles_free(&p);
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

/* Word k of stream (seed, stream) is word k % 4 of the Philox4x64-10 block
 * with counter (k / 4, 0, 0, sub), whatever the refill does: compared with
 * Random123 directly over several refills, for a stream and a substream.  The
 * same comparison rejects the neighbouring stream. */
static int matches_philox(gsl_rng *r, uint64_t seed, uint64_t id, uint64_t sub, unsigned words)
{
    const philox4x64_key_t key = {{seed, id}};
    int same = 1;
    for (unsigned k = 0; k < words; k++) {
        const philox4x64_ctr_t ctr = {{k / 4, 0, 0, sub}};
        same &= sim_rng_u64(r) == philox4x64(ctr, key).v[k % 4];
    }
    return same;
}

static void test_stream_is_philox(void **state)
{
    (void)state;
    const unsigned words = 5 * SIM_RNG_WORDS + 3;
    gsl_rng *r = stream(2385, 7);
    assert_true(matches_philox(r, 2385, 7, 0, words));
    sim_rng_set_substream(r, 2385, 7, 1);
    assert_true(matches_philox(r, 2385, 7, 1, words));
    sim_rng_set_stream(r, 2385, 8);
    assert_false(matches_philox(r, 2385, 7, 0, words));   /* the wrong stream */
    gsl_rng_free(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_uniform),     cmocka_unit_test(test_normal),
        cmocka_unit_test(test_unit_sphere), cmocka_unit_test(test_index),
        cmocka_unit_test(test_streams),     cmocka_unit_test(test_index32),
        cmocka_unit_test(test_accept32),    cmocka_unit_test(test_unit_sphere_uniform),
        cmocka_unit_test(test_index_streams), cmocka_unit_test(test_stream_is_philox),
        cmocka_unit_test(test_ziggurat_table), cmocka_unit_test(test_normal_law),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
