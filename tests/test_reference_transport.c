/* Unit tests of paper D's heat-flux transport coefficients (transport.h).
 * Every known answer names its source: a docs/theory.md section (§14),
 * "D (N)" = paper D's Eq. (N), "C&C" = Chapman and Cowling, The Mathematical
 * Theory of Non-Uniform Gases (3rd ed., 1970), chs. 9-10.
 *
 * The formulas are checked three ways: against the numbers docs/theory.md §14 quotes,
 * against the formulas written out again here, and, for the collision
 * frequencies and the cooling rate, against an independent evaluation of the
 * inelastic hard-sphere collision integrals by exact Gaussian quadrature (so a
 * wrong coefficient in D (2.14), D (2.46) or the modified first Sonine
 * approximation of D ref. [28] fails). */
#include "test_reference_util.h"

#include <string.h>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_laguerre.h>

#include "sonine.h"
#include "transport.h"

static const double PI = 3.14159265358979323846;

/* |x - printed| <= half a unit of the last printed digit (digits after the point). */
#define assert_printed(x, printed, digits) \
    assert_close((x), (printed), 0.0, 0.5 * pow(10.0, -(digits)) + 1e-12)

static ref_transport_sonine sonine(double alpha, double d, double a2, ref_transport_weight w)
{
    ref_transport_sonine s;
    char msg[128];
    assert_int_equal(ref_transport_first_sonine(alpha, d, a2, w, &s, msg, sizeof msg), REF_OK);
    assert_string_equal(msg, "");
    return s;
}

/* ------------------------------------------------ first Sonine, docs/theory.md §14.1 */

static void test_check_values(void **state)
{
    (void)state;
    /* docs/theory.md §14.1: alpha = 0.5 gives kappa'/kappa0 = 1.31870, kappa/kappa0 = 1.90108. */
    assert_printed(ref_transport_kappa_prime_star(0.5, 3.0), 1.31870, 5);
    assert_printed(ref_transport_kappa_star(0.5, 3.0), 1.90108, 5);
    /* D (2.38): mu* = 2 (kappa - kappa')/kappa0 = 2 (1.90108 - 1.31870) within rounding. */
    assert_close(ref_transport_mu_star(0.5, 3.0), 2.0 * (1.90108 - 1.31870), 0, 2e-5);
    /* a2 is paper C's (C.40) = D (2.16), not (C.5). */
    ref_transport_sonine s = sonine(0.5, 3.0, ref_sonine_a2_gaussian_alt(0.5, 3.0),
                                    REF_TRANSPORT_STANDARD);
    assert_close(s.kappa_star, ref_transport_kappa_star(0.5, 3.0), 1e-15, 0);
    ref_transport_sonine c5 = sonine(0.5, 3.0, ref_sonine_a2_gaussian(0.5, 3.0),
                                     REF_TRANSPORT_STANDARD);
    assert_true(fabs(c5.kappa_star - 1.90108) > 1e-4); /* the printed digits pick (C.40) */
}

/* The formulas of docs/theory.md §14.1 written out again, at high-entropy (alpha, d, a2). */
static void test_formulas(void **state)
{
    (void)state;
    const double alphas[] = {0.0, 0.385, 0.7213, 1.0}, ds[] = {2.0, 3.0, 4.5};
    const double a2s[] = {0.0, 0.0371, -0.1129};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 3; j++)
            for (int l = 0; l < 3; l++) {
                const double a = alphas[i], d = ds[j], a2 = a2s[l];
                const double zeta = (d + 2) / (4 * d) * (1 - a * a) * (1 + 3 * a2 / 16);
                const double nu0 = (1 + a) / d * ((d - 1) / 2 + 3 * (d + 8) * (1 - a) / 16);
                const double nu = nu0 + (1 + a) / d * (4 + 5 * d - 3 * (4 - d) * a) / 512 * a2;
                const double num = nu0 + (1 + a) / d * (296 + 217 * d - 3 * (160 + 11 * d) * a)
                                             / 256 * a2;
                ref_transport_sonine s = sonine(a, d, a2, REF_TRANSPORT_STANDARD);
                ref_transport_sonine m = sonine(a, d, a2, REF_TRANSPORT_MODIFIED);
                assert_close(s.a2, a2, 0, 0);
                assert_close(s.zeta_star, zeta, 1e-14, 1e-300);
                assert_close(m.zeta_star, zeta, 1e-14, 1e-300);
                assert_close(s.nu_kappa_star, nu, 1e-14, 0);
                assert_close(m.nu_kappa_star, num, 1e-14, 0);
                const double k = (d - 1) / d * (1 + 2 * a2) / (nu - 2 * zeta);
                const double kp = (d - 1) / d * (1 + 1.5 * a2) / (nu - 1.5 * zeta);
                const double km = (d - 1) / d * (1 + 2 * a2) / (num - 2 * zeta);
                const double kpm = (d - 1) / d * (1 + 1.5 * a2) / (num - 1.5 * zeta);
                assert_close(s.kappa_star, k, 1e-13, 0);
                assert_close(s.kappa_prime_star, kp, 1e-13, 0);
                assert_close(s.mu_star, 2 * (k - kp), 1e-12, 1e-14);
                assert_close(m.kappa_star, km, 1e-13, 0);
                assert_close(m.kappa_prime_star, kpm, 1e-13, 0);
                assert_close(m.mu_star, 2 * (km - kpm), 1e-12, 1e-14);
            }
    /* The (alpha, d) shorthands are these at a2 (C.40). */
    const double a = 0.385, d = 3.0, a2 = ref_sonine_a2_gaussian_alt(a, d);
    ref_transport_sonine s = sonine(a, d, a2, REF_TRANSPORT_STANDARD);
    ref_transport_sonine m = sonine(a, d, a2, REF_TRANSPORT_MODIFIED);
    assert_close(ref_transport_zeta_star(a, d), s.zeta_star, 0, 0);
    assert_close(ref_transport_nu_kappa_star(a, d), s.nu_kappa_star, 0, 0);
    assert_close(ref_transport_kappa_star(a, d), s.kappa_star, 0, 0);
    assert_close(ref_transport_kappa_prime_star(a, d), s.kappa_prime_star, 0, 0);
    assert_close(ref_transport_mu_star(a, d), s.mu_star, 0, 0);
    assert_close(ref_transport_zeta_star_modified(a, d), m.zeta_star, 0, 0);
    assert_close(ref_transport_nu_kappa_star_modified(a, d), m.nu_kappa_star, 0, 0);
    assert_close(ref_transport_kappa_star_modified(a, d), m.kappa_star, 0, 0);
    assert_close(ref_transport_kappa_prime_star_modified(a, d), m.kappa_prime_star, 0, 0);
    assert_close(ref_transport_mu_star_modified(a, d), m.mu_star, 0, 0);
}

/* D §2: in the elastic case zeta = 0, A = A', kappa = kappa' = kappa0 (first
 * Sonine, D (2.47)) and mu = 0; both approximations, every d. */
static void test_alpha_one(void **state)
{
    (void)state;
    double (*const fns[][2])(double, double) = {
        {ref_transport_kappa_star, ref_transport_kappa_star_modified},
        {ref_transport_kappa_prime_star, ref_transport_kappa_prime_star_modified},
    };
    const double ds[] = {2.0, 2.5, 3.0, 7.0};
    for (int j = 0; j < 4; j++) {
        const double d = ds[j];
        for (int i = 0; i < 2; i++)
            for (int w = 0; w < 2; w++)
                assert_close(fns[i][w](1.0, d), 1.0, 1e-15, 0);
        assert_close(ref_transport_mu_star(1.0, d), 0.0, 0, 0);
        assert_close(ref_transport_mu_star_modified(1.0, d), 0.0, 0, 0);
        assert_close(ref_transport_zeta_star(1.0, d), 0.0, 0, 0);
        assert_close(ref_transport_zeta_star_modified(1.0, d), 0.0, 0, 0);
        /* D (2.46) at alpha = 1, a2 = 0: nu*_kappa = (d-1)/d. */
        assert_close(ref_transport_nu_kappa_star(1.0, d), (d - 1) / d, 1e-15, 0);
        assert_close(ref_transport_nu_kappa_star_modified(1.0, d), (d - 1) / d, 1e-15, 0);
    }
}

/* ------------------------------ collision integrals by exact quadrature */

/* Independent evaluation, in reduced units (c = V/v0, phi_M = pi^(-d/2)
 * e^(-c^2)), of the collision integrals behind D (2.14) and D (2.46) for
 * inelastic hard spheres, by Gaussian quadrature in the centre-of-mass
 * G = (c1 + c2)/2 and relative g = c1 - c2 velocities.  The weak form
 *   ∫psi J[F1, F2] = ∫∫ F1(c1) F2(c2) ∫dsigma Θ(sigma·g)(sigma·g) [psi(c1') - psi(c1)],
 *   c1' = c1 - ((1 + alpha)/2)(sigma·g) sigma,
 * with g along e_1 (times the area of the unit sphere), |g| by Gauss-Laguerre
 * in u = |g|^2/2 (the parts even and odd in |g| separately, so that the rule
 * is exact), G by Gauss-Hermite, sigma = cos t e_1 + sin t omega over the
 * hemisphere.  With F = phi_M (1 + a2 S2(c^2)), S2 = L_2^(d/2-1), and
 * s(c) = (c^2 - (d+2)/2) c, the sums are linear in a2 after dropping a2^2:
 *   E  = ∫ c^2 J[f0, f0]:           E0 + a2 E1,
 *   N  = ∫ s·L[phi_M s] (standard): N0 + a2 N1, L X = -J[f0, X] - J[X, f0],
 *   N' = ∫ s·L[f0 s] (modified):    N0 + a2 N1m. */
typedef struct collision_sums {
    double E0, E1, N0, N1, N1m;
} collision_sums;

static double S2(double x, double d) { return x * x / 2 - (d + 2) * x / 2 + d * (d + 2) / 8; }

static void integrand(int dim, const double *G, double g, const double *sig, double mu,
                      double alpha, double out[5])
{
    double c1[3], c2[3], c1p[3], x1 = 0, x2 = 0, x1p = 0;
    for (int i = 0; i < dim; i++) {
        const double gi = i == 0 ? g : 0.0;
        c1[i] = G[i] + gi / 2;
        c2[i] = G[i] - gi / 2;
    }
    const double sg = g * mu; /* sigma·g */
    for (int i = 0; i < dim; i++) {
        c1p[i] = c1[i] - (1 + alpha) / 2 * sg * sig[i];
        x1 += c1[i] * c1[i];
        x2 += c2[i] * c2[i];
        x1p += c1p[i] * c1p[i];
    }
    const double d = dim, h = (d + 2) / 2, s21 = S2(x1, d), s22 = S2(x2, d);
    double n0 = 0, n1 = 0, n1m = 0;
    for (int i = 0; i < dim; i++) {
        const double dpsi = (x1p - h) * c1p[i] - (x1 - h) * c1[i];
        const double sa = (x1 - h) * c1[i], sb = (x2 - h) * c2[i];
        n0 += (sb + sa) * dpsi;                          /* F1 = 1, X2 = s; F2 = 1, X1 = s */
        n1 += (s21 * sb + sa * s22) * dpsi;              /* the a2 of f0 in L */
        n1m += (s21 * sb + sa * s22 + s22 * sb + s21 * sa) * dpsi; /* and of X = f0 s */
    }
    out[0] = (x1p - x1) * mu;
    out[1] = (s21 + s22) * (x1p - x1) * mu;
    out[2] = -n0 * mu; /* L = -J[f0, .] - J[., f0] */
    out[3] = -n1 * mu;
    out[4] = -n1m * mu;
}

static collision_sums collision_quadrature(int dim, double alpha)
{
    enum { NH = 8, NL = 9, NT = 24, NP = 12 };
    const double d = dim;
    gsl_integration_fixed_workspace *wh =
        gsl_integration_fixed_alloc(gsl_integration_fixed_hermite, NH, 0, 2, 0, 0);
    gsl_integration_fixed_workspace *wl[2] = {
        gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, NL, 0, 1, (d - 1) / 2, 0),
        gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, NL, 0, 1, d / 2, 0)};
    gsl_integration_fixed_workspace *wt =
        gsl_integration_fixed_alloc(gsl_integration_fixed_legendre, NT, 0, PI / 2, 0, 0);
    assert_non_null(wh);
    assert_non_null(wl[0]);
    assert_non_null(wl[1]);
    assert_non_null(wt);
    const double *xh = gsl_integration_fixed_nodes(wh), *hw = gsl_integration_fixed_weights(wh);
    const double *xt = gsl_integration_fixed_nodes(wt), *tw = gsl_integration_fixed_weights(wt);
    /* omega on the unit sphere of the plane orthogonal to e_1: ±e_2 (d = 2), a circle (d = 3) */
    const int nom = dim == 2 ? 2 : NP;
    double sum[5] = {0, 0, 0, 0, 0};
    const int ng = dim == 2 ? NH * NH : NH * NH * NH;
    for (int par = 0; par < 2; par++) {
        const double *xu = gsl_integration_fixed_nodes(wl[par]);
        const double *uw = gsl_integration_fixed_weights(wl[par]);
        for (int iu = 0; iu < NL; iu++) {
            const double g = sqrt(2 * xu[iu]);
            for (int it = 0; it < NT; it++) {
                const double mu = cos(xt[it]), st = sin(xt[it]);
                const double wt_t = tw[it] * (dim == 3 ? st : 1.0); /* sin^(d-2) t dt */
                for (int io = 0; io < nom; io++) {
                    double sig[3] = {mu, 0, 0}, wo;
                    if (dim == 2) {
                        sig[1] = io == 0 ? st : -st;
                        wo = 1.0;
                    } else {
                        sig[1] = st * cos(2 * PI * io / NP);
                        sig[2] = st * sin(2 * PI * io / NP);
                        wo = 2 * PI / NP;
                    }
                    for (int ig = 0; ig < ng; ig++) {
                        double G[3] = {0, 0, 0}, wg = 1;
                        for (int i = 0, r = ig; i < dim; i++, r /= NH) {
                            G[i] = xh[r % NH];
                            wg *= hw[r % NH];
                        }
                        double p[5], m[5];
                        integrand(dim, G, g, sig, mu, alpha, p);
                        integrand(dim, G, -g, sig, mu, alpha, m);
                        const double w = uw[iu] * wt_t * wo * wg;
                        /* the even part, or the odd part / g (sqrt2: u^(1/2) = g/sqrt2) */
                        for (int q = 0; q < 5; q++)
                            sum[q] += w * (par == 0 ? (p[q] + m[q]) / 2
                                                    : (p[q] - m[q]) / (2 * g) * sqrt(2.0));
                    }
                }
            }
        }
    }
    gsl_integration_fixed_free(wt);
    gsl_integration_fixed_free(wl[1]);
    gsl_integration_fixed_free(wl[0]);
    gsl_integration_fixed_free(wh);
    /* pi^-d from phi_M phi_M, the area of S^(d-1) for g's direction, and
     * |g|^d d|g| = 2^((d-1)/2) u^((d-1)/2) du. */
    const double f = pow(PI, -d) * 2 * pow(PI, d / 2) / tgamma(d / 2) * pow(2.0, (d - 1) / 2);
    collision_sums c = {f * sum[0], f * sum[1], f * sum[2], f * sum[3], f * sum[4]};
    return c;
}

/* <s·s> and <S2 s·s> under phi_M: moments of c^2 ~ Gamma(d/2). */
static void s_norms(double d, double *den0, double *den1)
{
    gsl_integration_fixed_workspace *w =
        gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, 12, 0, 1, d / 2 - 1, 0);
    assert_non_null(w);
    const double *x = gsl_integration_fixed_nodes(w), *wt = gsl_integration_fixed_weights(w);
    *den0 = *den1 = 0;
    for (int k = 0; k < 12; k++) {
        const double ss = x[k] * (x[k] - (d + 2) / 2) * (x[k] - (d + 2) / 2);
        *den0 += wt[k] * ss / tgamma(d / 2);
        *den1 += wt[k] * ss * S2(x[k], d) / tgamma(d / 2);
    }
    gsl_integration_fixed_free(w);
}

static void test_collision_integrals(void **state)
{
    (void)state;
    const int dims[] = {3, 2};
    const double alphas[] = {0.5, 0.2385};
    for (int i = 0; i < 2; i++) {
        const int dim = dims[i];
        const double d = dim, a = alphas[i];
        collision_sums c = collision_quadrature(dim, a);
        /* nu0 of D (2.15) in the unit n sigma^(d-1) v0. */
        const double nu0 = 8 / (d + 2) * pow(PI, (d - 1) / 2) / (tgamma(d / 2) * sqrt(2.0));
        /* zeta = -(m/(d n T)) ∫ V^2 J = -(2/d) n sigma^(d-1) v0 E. */
        const double zeta0 = -2 / d * c.E0 / nu0, zeta1 = -2 / d * c.E1 / nu0;
        double den0, den1;
        s_norms(d, &den0, &den1);
        assert_close(den0, d * (d + 2) / 4, 1e-13, 0);
        /* nu_kappa = ∫S·L A/∫S·A: standard, A = f_M S; modified, A = f0 S,
         * with the solubility term -((d+2)/2) zeta ∫V·A/∫S·A = -((d+2)/2) zeta a2
         * of the projection of D (2.28) (transport.h). */
        const double nu_0 = c.N0 / den0 / nu0;
        const double nu_1 = c.N1 / den0 / nu0;
        const double num_1 = (c.N1m / den0 - c.N0 * den1 / (den0 * den0)) / nu0
                             - (d + 2) / 2 * zeta0;
        /* The library's values are linear in a2: slope = value(a2 = 1) - value(a2 = 0). */
        ref_transport_sonine s0 = sonine(a, d, 0.0, REF_TRANSPORT_STANDARD);
        ref_transport_sonine s1 = sonine(a, d, 1.0, REF_TRANSPORT_STANDARD);
        ref_transport_sonine m0 = sonine(a, d, 0.0, REF_TRANSPORT_MODIFIED);
        ref_transport_sonine m1 = sonine(a, d, 1.0, REF_TRANSPORT_MODIFIED);
        assert_close(zeta0, s0.zeta_star, 1e-10, 0);                        /* D (2.14) */
        assert_close(zeta1, s1.zeta_star - s0.zeta_star, 1e-10, 0);         /* its 3/16 */
        assert_close(nu_0, s0.nu_kappa_star, 1e-10, 0);                     /* D (2.46) */
        assert_close(nu_1, s1.nu_kappa_star - s0.nu_kappa_star, 1e-9, 0);   /* its a2 term */
        assert_close(nu_0, m0.nu_kappa_star, 1e-10, 0);
        assert_close(num_1, m1.nu_kappa_star - m0.nu_kappa_star, 1e-9, 0); /* D ref. [28] */
    }
}

/* ------------------------------------------- exact elastic solution */

static void test_sonine_P(void **state)
{
    (void)state;
    /* docs/theory.md §10.5: P_k = 4/5, 16/35, 32/105. */
    assert_close(ref_transport_sonine_P(1), 4.0 / 5.0, 1e-15, 0);
    assert_close(ref_transport_sonine_P(2), 16.0 / 35.0, 1e-15, 0);
    assert_close(ref_transport_sonine_P(3), 32.0 / 105.0, 1e-15, 0);
    /* P_k = 1/<c_x^2 L_k(c^2)^2>: <c_x^2 h(c^2)> = (1/3) ∫ x^(3/2) e^-x h dx/Gamma(3/2). */
    gsl_integration_fixed_workspace *w =
        gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, 12, 0, 1, 1.5, 0);
    assert_non_null(w);
    const double *x = gsl_integration_fixed_nodes(w), *wt = gsl_integration_fixed_weights(w);
    for (int k = 0; k <= 5; k++) {
        double m = 0;
        for (int i = 0; i < 12; i++) {
            const double l = gsl_sf_laguerre_n(k, 1.5, x[i]) /* GSL's L_k^(3/2) */;
            m += wt[i] * l * l / (3 * tgamma(1.5));
        }
        assert_close(ref_transport_sonine_P(k), 1 / m, 1e-12, 0);
    }
    gsl_integration_fixed_free(w);
}

static void test_b1_identity_constant(void **state)
{
    (void)state;
    /* docs/theory.md §14.2: b'_1 = (15 sqrt(pi)/16) kappa'/kappa0 = 1.661675 kappa'/kappa0;
     * = (d/(d-1))/(nu0 tau) with nu0 tau = 8/(5 sqrt(pi)). */
    assert_printed(ref_transport_b1_per_kappa(), 1.661675, 6);
    assert_close(ref_transport_b1_per_kappa(), 1.5 / (8 / (5 * sqrt(PI))), 1e-15, 0);
}

static void test_elastic_low_orders(void **state)
{
    (void)state;
    ref_transport_elastic e;
    char msg[128];
    /* Order 1: the first Sonine value, kappa = kappa0 and b'_1 = 15 sqrt(pi)/16
     * (the absolute normalisation of the Galerkin matrix and right-hand side). */
    assert_int_equal(ref_transport_elastic_sonine(1, &e, msg, sizeof msg), REF_OK);
    assert_string_equal(msg, "");
    assert_int_equal(e.order, 1);
    assert_close(e.kappa, 1.0, 1e-14, 0);
    assert_close(e.b[1], 15 * sqrt(PI) / 16, 1e-12, 0);
    assert_true(isnan(e.b[0]) && isnan(e.b[2]) && isnan(e.kappa_by_order[2]));
    /* Order 2: C&C's bracket integrals for thermal conduction,
     *   a11 = 4 W22, a12 = 7 W22 - 2 W23, a22 = (77/4) W22 - 7 W23 + W24,
     * with rigid spheres' W2r proportional to (r+1)!/2 (3, 12, 60): a11 = 12,
     * a12 = -3, a22 = 135/4, so [lambda]_2/[lambda]_1 = a11 a22/(a11 a22 - a12^2)
     * = 45/44 = 1 + 1/44 (C&C's second approximation for rigid elastic
     * spheres) and b'_2/b'_1 = -a12/a22 = 4/45. */
    const double W22 = 3, W23 = 12, W24 = 60;
    const double a11 = 4 * W22, a12 = 7 * W22 - 2 * W23, a22 = 77.0 / 4 * W22 - 7 * W23 + W24;
    assert_int_equal(ref_transport_elastic_sonine(2, &e, msg, sizeof msg), REF_OK);
    assert_close(e.kappa, a11 * a22 / (a11 * a22 - a12 * a12), 1e-13, 0);
    assert_close(e.kappa, 45.0 / 44.0, 1e-13, 0);
    assert_close(e.kappa_by_order[1], 1.0, 1e-14, 0);
    assert_close(e.b[2] / e.b[1], -a12 / a22, 1e-12, 0);
    assert_close(e.b[2] / e.b[1], 4.0 / 45.0, 1e-12, 0);
    /* Order 3: this module's own matrix entries are rationals times a11
     * (A13/A11 = -1/32, A23/A11 = -103/128, A33/A11 = 5657/1024); solving by
     * hand gives kappa_3 = 60989/59512, b'_2/b'_1 = 5760/60989 and
     * b'_3/b'_1 = 1184/60989.  (A regression value derived here, not a
     * published one.) */
    assert_int_equal(ref_transport_elastic_sonine(3, &e, msg, sizeof msg), REF_OK);
    assert_close(e.kappa, 60989.0 / 59512.0, 1e-13, 0);
    assert_close(e.b[2] / e.b[1], 5760.0 / 60989.0, 1e-12, 0);
    assert_close(e.b[3] / e.b[1], 1184.0 / 60989.0, 1e-12, 0);
    assert_close(e.kappa_by_order[2], 45.0 / 44.0, 1e-13, 0);
    /* The heat-flux identity holds at every order: b'_1 = 1.661675 kappa'/kappa0. */
    assert_int_equal(ref_transport_elastic_sonine(6, &e, msg, sizeof msg), REF_OK);
    assert_close(e.b[1], ref_transport_b1_per_kappa() * e.kappa, 1e-12, 0);
    for (int n = 2; n <= 6; n++) /* each added term raises kappa (variational bound) */
        assert_true(e.kappa_by_order[n] > e.kappa_by_order[n - 1]);
}

static void test_elastic_exact(void **state)
{
    (void)state;
    ref_transport_elastic e;
    char msg[256];
    assert_int_equal(ref_transport_elastic_exact(&e, msg, sizeof msg), REF_OK);
    assert_string_equal(msg, "");
    /* D §4 (its ref. [37], Pekeris-Alterman; docs/theory.md §14.3): kappa/kappa0 = 1.025218. */
    assert_close(e.kappa, 1.025218, 0, 1e-6);
    assert_printed(ref_transport_kappa_elastic_exact(), 1.025218, 6);
    /* Converged in the sense of transport.h, and not before. */
    assert_true(e.order >= 3 && e.order <= REF_TRANSPORT_ELASTIC_MAX_ORDER);
    assert_true(fabs(e.kappa_by_order[e.order] - e.kappa_by_order[e.order - 1])
                <= REF_TRANSPORT_ELASTIC_TOL);
    for (int n = 2; n < e.order; n++)
        assert_true(fabs(e.kappa_by_order[n] - e.kappa_by_order[n - 1])
                    > REF_TRANSPORT_ELASTIC_TOL);
    assert_close(e.kappa_by_order[2], 45.0 / 44.0, 1e-13, 0);
    /* docs/theory.md §14.2 identity: b'_1 = 1.661675 kappa'/kappa0 (kappa' = kappa at alpha = 1),
     * so b'_1 exact = 1.7036. */
    assert_close(ref_transport_b_elastic_exact(1), 1.661675 * e.kappa, 0, 1e-6);
    assert_printed(ref_transport_b_elastic_exact(1), 1.7036, 4);
    /* b'_2, b'_3: no published value found; this module's converged values
     * (order 11), which move by less than 1e-6 between the last orders. */
    assert_close(ref_transport_b_elastic_exact(2), 0.1625698, 0, 2e-6);
    assert_close(ref_transport_b_elastic_exact(3), 0.0370531, 0, 2e-6);
    assert_close(ref_transport_b_elastic_exact(2), e.b[2], 0, 0);
    assert_true(isnan(ref_transport_b_elastic_exact(0)));
    assert_true(isnan(ref_transport_b_elastic_exact(e.order + 1)));
    /* The cache answers the same. */
    ref_transport_elastic again;
    assert_int_equal(ref_transport_elastic_exact(&again, NULL, 0), REF_OK);
    assert_memory_equal(&again, &e, sizeof e);
}

/* ------------------------------------------------------ the listing */

static void test_listing(void **state)
{
    (void)state;
    static const char *const names[] = {
        "zeta_star", "nu_kappa_star", "kappa_over_kappa0", "kappa_prime_over_kappa0",
        "mu_star", "zeta_star_modified", "nu_kappa_star_modified",
        "kappa_over_kappa0_modified", "kappa_prime_over_kappa0_modified", "mu_star_modified",
        "kappa_elastic_exact", "b1_elastic_exact", "b2_elastic_exact", "b3_elastic_exact"};
    enum { NEW = sizeof names / sizeof names[0] };
    ref_sonine_value v[REF_SONINE_ALL_COUNT];
    const double a = 0.5;
    assert_int_equal(ref_sonine_all(a, 3.0, v, REF_SONINE_ALL_COUNT), REF_SONINE_ALL_COUNT);
    /* Paper C's 27 rows first, unchanged; paper D's after them, in this order. */
    assert_int_equal(REF_SONINE_ALL_COUNT, 27 + NEW);
    assert_string_equal(v[0].name, "beta_1");
    assert_string_equal(v[26].name, "Aprime_nongaussian");
    for (int i = 0; i < NEW; i++) {
        assert_string_equal(v[27 + i].name, names[i]);
        assert_true(strlen(v[27 + i].source) > 0);
    }
    const double want[NEW] = {ref_transport_zeta_star(a, 3),
                              ref_transport_nu_kappa_star(a, 3),
                              ref_transport_kappa_star(a, 3),
                              ref_transport_kappa_prime_star(a, 3),
                              ref_transport_mu_star(a, 3),
                              ref_transport_zeta_star_modified(a, 3),
                              ref_transport_nu_kappa_star_modified(a, 3),
                              ref_transport_kappa_star_modified(a, 3),
                              ref_transport_kappa_prime_star_modified(a, 3),
                              ref_transport_mu_star_modified(a, 3),
                              ref_transport_kappa_elastic_exact(),
                              ref_transport_b_elastic_exact(1),
                              ref_transport_b_elastic_exact(2),
                              ref_transport_b_elastic_exact(3)};
    for (int i = 0; i < NEW; i++)
        assert_close(v[27 + i].value, want[i], 0, 0);
    /* docs/theory.md §14.1 check values through the listing. */
    assert_printed(lookup(v, REF_SONINE_ALL_COUNT, "kappa_over_kappa0"), 1.90108, 5);
    assert_printed(lookup(v, REF_SONINE_ALL_COUNT, "kappa_prime_over_kappa0"), 1.31870, 5);
    assert_printed(lookup(v, REF_SONINE_ALL_COUNT, "kappa_elastic_exact"), 1.025218, 6);
    /* d = 2: the first Sonine values exist, the elastic solution (hard spheres) does not. */
    assert_int_equal(ref_sonine_all(a, 2.0, v, REF_SONINE_ALL_COUNT), REF_SONINE_ALL_COUNT);
    for (int i = 0; i < NEW; i++) {
        if (strstr(names[i], "elastic_exact"))
            assert_true(isnan(v[27 + i].value));
        else
            assert_true(isfinite(v[27 + i].value));
    }
    assert_close(lookup(v, REF_SONINE_ALL_COUNT, "kappa_over_kappa0"),
                 ref_transport_kappa_star(a, 2.0), 0, 0);
}

/* ---------------------------------------------------------------- traps */

static void test_trap_bad_input(void **state)
{
    (void)state;
    double (*const fns[])(double, double) = {
        ref_transport_zeta_star, ref_transport_nu_kappa_star, ref_transport_kappa_star,
        ref_transport_kappa_prime_star, ref_transport_mu_star,
        ref_transport_zeta_star_modified, ref_transport_nu_kappa_star_modified,
        ref_transport_kappa_star_modified, ref_transport_kappa_prime_star_modified,
        ref_transport_mu_star_modified};
    const double bad_alpha[] = {-0.1, 1.0000001, NAN, INFINITY};
    const double bad_d[] = {1.999, 100.5, NAN, -INFINITY};
    for (size_t f = 0; f < sizeof fns / sizeof fns[0]; f++) {
        assert_true(isfinite(fns[f](0.5, 3.0)));
        assert_true(isfinite(fns[f](0.0, REF_SONINE_D_MAX)));
        for (size_t i = 0; i < 4; i++) {
            assert_true(isnan(fns[f](bad_alpha[i], 3.0)));
            assert_true(isnan(fns[f](0.5, bad_d[i])));
        }
    }
    ref_transport_sonine s = {1, 2, 3, 4, 5, 6};
    char msg[200];
    assert_failure(ref_transport_first_sonine(1.5, 3, 0, REF_TRANSPORT_STANDARD, &s, msg,
                                              sizeof msg),
                   REF_EINVAL, msg, "alpha = 1.5 is out of range", "0 <= alpha <= 1");
    assert_failure(ref_transport_first_sonine(0.5, 1, 0, REF_TRANSPORT_MODIFIED, &s, msg,
                                              sizeof msg),
                   REF_EINVAL, msg, "d = 1 is out of range", "2 <= d <= 100");
    assert_failure(ref_transport_first_sonine(0.5, 3, NAN, REF_TRANSPORT_STANDARD, &s, msg,
                                              sizeof msg),
                   REF_EINVAL, msg, "a2 = nan is not finite", NULL);
    assert_failure(ref_transport_first_sonine(0.5, 3, 0, (ref_transport_weight)7, &s, msg,
                                              sizeof msg),
                   REF_EINVAL, msg, "weight = 7", "REF_TRANSPORT_MODIFIED");
    assert_close(s.a2, 1, 0, 0); /* out untouched */
    assert_failure(ref_transport_first_sonine(0.5, 3, 0, REF_TRANSPORT_STANDARD, NULL, msg,
                                              sizeof msg),
                   REF_EINVAL, msg, "out is NULL", NULL);
    assert_int_equal(ref_transport_first_sonine(0.5, 3, 0, REF_TRANSPORT_STANDARD, &s, NULL, 0),
                     REF_OK);
    ref_transport_elastic e;
    assert_failure(ref_transport_elastic_sonine(0, &e, msg, sizeof msg), REF_EINVAL, msg,
                   "order = 0 is out of range", "1 <= order <= 24");
    assert_failure(ref_transport_elastic_sonine(REF_TRANSPORT_ELASTIC_MAX_ORDER + 1, &e, msg,
                                                sizeof msg),
                   REF_EINVAL, msg, "order = 25 is out of range", NULL);
    assert_failure(ref_transport_elastic_sonine(2, NULL, msg, sizeof msg), REF_EINVAL, msg,
                   "out is NULL", NULL);
    assert_failure(ref_transport_elastic_exact(NULL, msg, sizeof msg), REF_EINVAL, msg,
                   "out is NULL", NULL);
    assert_true(isnan(ref_transport_sonine_P(-1)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_check_values),
        cmocka_unit_test(test_formulas),
        cmocka_unit_test(test_alpha_one),
        cmocka_unit_test(test_collision_integrals),
        cmocka_unit_test(test_sonine_P),
        cmocka_unit_test(test_b1_identity_constant),
        cmocka_unit_test(test_elastic_low_orders),
        cmocka_unit_test(test_elastic_exact),
        cmocka_unit_test(test_listing),
        cmocka_unit_test(test_trap_bad_input),
    };
    return cmocka_run_group_tests(tests, 0, 0);
}
