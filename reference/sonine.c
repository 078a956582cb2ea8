/* Sonine-approximation formulas of paper C (docs/theory.md §13; paper C = Montanero and
 * Santos, seed 002).  Equation numbers "(N)" are paper C's; see sonine.h for
 * the contract.  tgamma, not lgamma: lgamma writes the global signgam. */
#include "sonine.h"

#include <math.h>

#include "transport.h"

static const double PI = 3.14159265358979323846;

static int alpha_ok(double alpha) { return alpha >= 0.0 && alpha <= 1.0; }

static int d_ok(double d) { return d >= REF_SONINE_D_MIN && d <= REF_SONINE_D_MAX; }

static int ok(double alpha, double d) { return alpha_ok(alpha) && d_ok(d); }

/* pi^((d-1)/2) / (sqrt(2) Gamma(d/2)): mu2^(0) without its (1 - alpha^2). */
static double mu2_prefactor(double d)
{
    return pow(PI, 0.5 * (d - 1.0)) / (sqrt(2.0) * tgamma(0.5 * d));
}

/* Eq. (A.7). */
double ref_sonine_beta(double n, double d)
{
    if (!(n > -1.0 && isfinite(n)) || !d_ok(d))
        return NAN;
    return pow(PI, 0.5 * (d - 1.0)) * tgamma(0.5 * (n + 1.0)) / tgamma(0.5 * (n + d));
}

/* Eq. (27). */
double ref_sonine_mu2_0(double alpha, double d)
{
    if (!ok(alpha, d))
        return NAN;
    return mu2_prefactor(d) * (1.0 - alpha * alpha);
}

/* Eq. (28). */
double ref_sonine_mu2_1(double alpha, double d)
{
    return 3.0 / 16.0 * ref_sonine_mu2_0(alpha, d);
}

/* Eq. (29). */
double ref_sonine_mu4_0(double alpha, double d)
{
    return (d + 1.5 + alpha * alpha) * ref_sonine_mu2_0(alpha, d);
}

/* Eq. (30), with (d-1)/(1-alpha) * (1-alpha^2) = (d-1)(1+alpha), finite at alpha = 1. */
double ref_sonine_mu4_1(double alpha, double d)
{
    if (!ok(alpha, d))
        return NAN;
    double a = alpha;
    return (3.0 / 32.0 * (10.0 * d + 39.0 + 10.0 * a * a) * (1.0 - a * a)
            + (d - 1.0) * (1.0 + a))
           * mu2_prefactor(d);
}

/* Eq. (26), p = 2. */
double ref_sonine_mu2(double alpha, double d, double a2)
{
    if (!isfinite(a2))
        return NAN;
    return ref_sonine_mu2_0(alpha, d) + ref_sonine_mu2_1(alpha, d) * a2;
}

/* Eq. (26), p = 4. */
double ref_sonine_mu4(double alpha, double d, double a2)
{
    if (!isfinite(a2))
        return NAN;
    return ref_sonine_mu4_0(alpha, d) + ref_sonine_mu4_1(alpha, d) * a2;
}

/* Eq. (72), d = 3. */
double ref_sonine_mu2_nongaussian_fit(double alpha, double d, double a2)
{
    if (d != 3.0 || !isfinite(a2))
        return NAN;
    return ref_sonine_mu2_0(alpha, d) + 21.0 / 20.0 * ref_sonine_mu2_1(alpha, d) * a2;
}

/* Eq. (73), d = 3. */
double ref_sonine_mu4_nongaussian_fit(double alpha, double d, double a2)
{
    if (d != 3.0 || !isfinite(a2))
        return NAN;
    return ref_sonine_mu4_0(alpha, d) + 13.0 / 15.0 * ref_sonine_mu4_1(alpha, d) * a2;
}

/* Eq. (48). */
double ref_sonine_mean_c(double d, double a2)
{
    if (!d_ok(d) || !isfinite(a2))
        return NAN;
    return tgamma(0.5 * (d + 1.0)) / tgamma(0.5 * d) * (1.0 - a2 / 8.0);
}

/* Eq. (49). */
double ref_sonine_mean_c3(double d, double a2)
{
    if (!d_ok(d) || !isfinite(a2))
        return NAN;
    return tgamma(0.5 * (d + 3.0)) / tgamma(0.5 * d) * (1.0 + 3.0 * a2 / 8.0);
}

/* Eq. (36). */
double ref_sonine_tail_A_white_noise_mu2(double mu2, double d)
{
    if (!(mu2 >= 0.0 && isfinite(mu2)) || !d_ok(d))
        return NAN;
    if (mu2 == 0.0)
        return INFINITY;
    return 2.0 / 3.0 * sqrt(2.0 * d * ref_sonine_beta(1.0, d) / mu2);
}

/* Eq. (42). */
double ref_sonine_tail_A_gaussian_mu2(double mu2, double d)
{
    if (!(mu2 >= 0.0 && isfinite(mu2)) || !d_ok(d))
        return NAN;
    if (mu2 == 0.0)
        return INFINITY;
    return d * ref_sonine_beta(1.0, d) / mu2;
}

/* Eq. (36) at mu2 of Eq. (26) with a2 of Eq. (10); see sonine.h for the choice. */
double ref_sonine_tail_A_white_noise(double alpha, double d)
{
    double mu2 = ref_sonine_mu2(alpha, d, ref_sonine_a2_white_noise(alpha, d));
    return ref_sonine_tail_A_white_noise_mu2(mu2, d);
}

/* Eq. (42) at mu2 of Eq. (26) with a2 of Eq. (40); see sonine.h for the choice. */
double ref_sonine_tail_A_gaussian(double alpha, double d)
{
    double mu2 = ref_sonine_mu2(alpha, d, ref_sonine_a2_gaussian_alt(alpha, d));
    return ref_sonine_tail_A_gaussian_mu2(mu2, d);
}

/* Eq. (52) at a2 = 0. */
double ref_sonine_tail_Aprime_nongaussian(double alpha, double d)
{
    double mu2 = ref_sonine_mu2_0(alpha, d);
    if (isnan(mu2))
        return NAN;
    if (mu2 == 0.0)
        return INFINITY;
    return ref_sonine_beta(1.0, d) * ref_sonine_mean_c(d, 0.0) / mu2;
}

size_t ref_sonine_all(double alpha, double d, ref_sonine_value *out, size_t cap)
{
    if (!ok(alpha, d))
        return 0;
    const double a2_wn = ref_sonine_a2_white_noise(alpha, d);
    const double a2_g = ref_sonine_a2_gaussian(alpha, d);
    const double a2_ga = ref_sonine_a2_gaussian_alt(alpha, d);
    const double a2_ng = ref_sonine_a2_nongaussian(alpha, d);
    const double a2_ngf = ref_sonine_a2_nongaussian_fit(alpha, d);
    const int elastic = d == 3.0; /* the exact elastic solution is for hard spheres */
    const ref_sonine_value all[REF_SONINE_ALL_COUNT] = {
        {"beta_1", ref_sonine_beta(1.0, d), "(A.7)"},
        {"beta_3", ref_sonine_beta(3.0, d), "(A.7)"},
        {"mu2_0", ref_sonine_mu2_0(alpha, d), "(27)"},
        {"mu2_1", ref_sonine_mu2_1(alpha, d), "(28)"},
        {"mu4_0", ref_sonine_mu4_0(alpha, d), "(29)"},
        {"mu4_1", ref_sonine_mu4_1(alpha, d), "(30)"},
        {"a2_white_noise", a2_wn, "(10)"},
        {"a2_white_noise_ratio", ref_sonine_a2_white_noise_ratio(alpha, d), "(32)"},
        {"a2_gaussian", a2_g, "(5)"},
        {"a2_gaussian_alt", a2_ga, "(40)"},
        {"a2_nongaussian", a2_ng, "(50)"},
        {"a2_nongaussian_fit", a2_ngf, "(76), d = 3 only"},
        {"mu2_white_noise", ref_sonine_mu2(alpha, d, a2_wn), "(26) at a2 (10)"},
        {"mu4_white_noise", ref_sonine_mu4(alpha, d, a2_wn), "(26) at a2 (10)"},
        {"mu2_gaussian", ref_sonine_mu2(alpha, d, a2_g), "(26) at a2 (5)"},
        {"mu4_gaussian", ref_sonine_mu4(alpha, d, a2_g), "(26) at a2 (5)"},
        {"mu2_gaussian_alt", ref_sonine_mu2(alpha, d, a2_ga), "(26) at a2 (40)"},
        {"mu4_gaussian_alt", ref_sonine_mu4(alpha, d, a2_ga), "(26) at a2 (40)"},
        {"mu2_nongaussian", ref_sonine_mu2(alpha, d, a2_ng), "(26) at a2 (50)"},
        {"mu4_nongaussian", ref_sonine_mu4(alpha, d, a2_ng), "(26) at a2 (50)"},
        {"mu2_nongaussian_fit", ref_sonine_mu2_nongaussian_fit(alpha, d, a2_ngf),
         "(72) at a2 (76), d = 3 only"},
        {"mu4_nongaussian_fit", ref_sonine_mu4_nongaussian_fit(alpha, d, a2_ngf),
         "(73) at a2 (76), d = 3 only"},
        {"A_white_noise", ref_sonine_tail_A_white_noise(alpha, d), "(36), mu2 (26) at a2 (10)"},
        {"A_gaussian", ref_sonine_tail_A_gaussian(alpha, d), "(42), mu2 (26) at a2 (40)"},
        {"A_white_noise_mu2_0",
         ref_sonine_tail_A_white_noise_mu2(ref_sonine_mu2_0(alpha, d), d), "(36), mu2^(0)"},
        {"A_gaussian_mu2_0", ref_sonine_tail_A_gaussian_mu2(ref_sonine_mu2_0(alpha, d), d),
         "(42), mu2^(0)"},
        {"Aprime_nongaussian", ref_sonine_tail_Aprime_nongaussian(alpha, d),
         "(52), loss term only, a2 = 0"},
        /* Paper D (docs/theory.md §14), transport.h. */
        {"zeta_star", ref_transport_zeta_star(alpha, d), "D (2.14) at a2 (40) = D (2.16)"},
        {"nu_kappa_star", ref_transport_nu_kappa_star(alpha, d), "D (2.46)"},
        {"kappa_over_kappa0", ref_transport_kappa_star(alpha, d), "D (2.41), (2.47)"},
        {"kappa_prime_over_kappa0", ref_transport_kappa_prime_star(alpha, d),
         "D (2.42), (2.47)"},
        {"mu_star", ref_transport_mu_star(alpha, d), "D (2.38)"},
        {"zeta_star_modified", ref_transport_zeta_star_modified(alpha, d),
         "D (2.14), modified first Sonine (D ref. [28])"},
        {"nu_kappa_star_modified", ref_transport_nu_kappa_star_modified(alpha, d),
         "modified first Sonine (D ref. [28])"},
        {"kappa_over_kappa0_modified", ref_transport_kappa_star_modified(alpha, d),
         "D (2.41), modified first Sonine (D ref. [28])"},
        {"kappa_prime_over_kappa0_modified", ref_transport_kappa_prime_star_modified(alpha, d),
         "D (2.42), modified first Sonine (D ref. [28])"},
        {"mu_star_modified", ref_transport_mu_star_modified(alpha, d),
         "D (2.38), modified first Sonine (D ref. [28])"},
        {"kappa_elastic_exact", elastic ? ref_transport_kappa_elastic_exact() : NAN,
         "elastic Sonine expansion to convergence (D ref. [37]), d = 3 only"},
        {"b1_elastic_exact", elastic ? ref_transport_b_elastic_exact(1) : NAN,
         "D (3.10), elastic exact, d = 3 only"},
        {"b2_elastic_exact", elastic ? ref_transport_b_elastic_exact(2) : NAN,
         "D (3.10), elastic exact, d = 3 only"},
        {"b3_elastic_exact", elastic ? ref_transport_b_elastic_exact(3) : NAN,
         "D (3.10), elastic exact, d = 3 only"},
    };
    for (size_t i = 0; i < REF_SONINE_ALL_COUNT && i < cap; i++)
        out[i] = all[i];
    return REF_SONINE_ALL_COUNT;
}
