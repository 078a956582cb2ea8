#include "references.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "background.h"
#include "heated.h"
#include "scene_refs.h"
#include "sonine.h"
#include "transport.h"

/* Paper C's estimates in d = 3 at the scene's restitution coefficient. */
#define SONINE(fn)                                                              \
    static double fn##_at(const sim_scene *s)                                   \
    {                                                                           \
        return ref_sonine_##fn(s->collisions.restitution, 3.0);                 \
    }
SONINE(a2_white_noise)
SONINE(a2_white_noise_ratio)
SONINE(a2_gaussian)
SONINE(a2_gaussian_alt)
SONINE(a2_nongaussian)
SONINE(a2_nongaussian_fit)
SONINE(mu2_0)
SONINE(mu2_1)
SONINE(mu4_0)
SONINE(mu4_1)
SONINE(tail_A_white_noise)
SONINE(tail_A_gaussian)
#undef SONINE

/* Paper D's first Sonine approximations in d = 3 at the scene's alpha, and
 * the exact elastic solution (reference/transport.h). */
#define TRANSPORT(fn)                                                           \
    static double fn##_at(const sim_scene *s)                                   \
    {                                                                           \
        return ref_transport_##fn(s->collisions.restitution, 3.0);              \
    }
TRANSPORT(kappa_prime_star)
TRANSPORT(kappa_prime_star_modified)
TRANSPORT(kappa_star)
TRANSPORT(mu_star)
#undef TRANSPORT
static double kappa_elastic_at(const sim_scene *s)
{
    (void)s;
    return ref_transport_kappa_elastic_exact();
}
#define ELASTIC_B(k)                                                            \
    static double b##k##_elastic_at(const sim_scene *s)                         \
    {                                                                           \
        (void)s;                                                                \
        return ref_transport_b_elastic_exact(k);                                \
    }
ELASTIC_B(1)
ELASTIC_B(2)
ELASTIC_B(3)
#undef ELASTIC_B

/* Paper E: the BGK model's steady state at the scene (alpha, a tau0), one
 * member of ref_bgk_steady; NAN where it has none (alpha = 1, no shear). */
static double bgk_steady(const sim_scene *s, size_t member_offset)
{
    if (!s->shear.present || !s->collisions.present)
        return NAN;
    const ref_bgk_params p = vfy_bgk_params(s);
    ref_bgk_steady st;
    if (ref_bgk_steady_state(&p, &st, NULL, 0) != REF_OK)
        return NAN;
    return *(const double *)((const char *)&st + member_offset);
}
#define BGK(name, member)                                                       \
    static double name##_at(const sim_scene *s)                                 \
    {                                                                           \
        return bgk_steady(s, offsetof(ref_bgk_steady, member));                 \
    }
BGK(a_star_bgk, a_star)
BGK(Pxy_reduced_bgk, shear_stress)
BGK(N1_bgk, normal_xy)
BGK(N2_bgk, normal_zy)
BGK(eta_star_bgk, eta_star)
BGK(T_ratio_bgk, T_ratio)
#undef BGK

/* Paper E: when the BGK model's T(t) from the scene's initial state stays
 * within RELAX_BAND of its steady value (ref_bgk_relaxation_time), the start
 * of a steady average (as-steady's window: from there to 1.25 times it).  At
 * 1e-4, a* ~ T^(-1/2) is within 5e-5 of its steady value, 1/30 of the
 * smallest half-width of a* at paper sizes (0.0010 on 0.67, N = 8); a tau0 = 4
 * gives t = 12.4-19.1 over alpha = 0.5-0.95, a tau0 = 0.1 (cooled first) t =
 * 415-633.  NAN without a steady state (no shear, alpha = 1). */
#define RELAX_BAND 1e-4
static double t_relaxed_bgk_at(const sim_scene *s)
{
    if (!s->shear.present || !s->collisions.present)
        return NAN;
    const ref_bgk_params p = vfy_bgk_params(s);
    double t;
    return ref_bgk_relaxation_time(&p, RELAX_BAND, &t, NULL, 0) == REF_OK ? t : NAN;
}
static double t_end_relaxed_bgk_at(const sim_scene *s) { return 1.25 * t_relaxed_bgk_at(s); }

/* Paper B's hard-sphere closures' steady temperature (GSL Brent root of
 * dT/dt at u = u_B), for hard spheres in a hard-sphere background. */
static double hs_steady(const sim_scene *s, ref_background_closure closure)
{
    if (!s->background.present || s->background.kernel != SIM_KERNEL_HARD_SPHERES
        || !s->collisions.present || s->collisions.kernel != SIM_KERNEL_HARD_SPHERES)
        return NAN;
    const ref_background_params p = vfy_background_params(s);
    return ref_background_hs_T_steady(&p, closure);
}
/* Paper A Ex 5's first-Sonine closure's steady temperature (white-noise
 * heated hard spheres). */
static double T_steady_sonine_at(const sim_scene *s)
{
    if (!s->heating.present || s->heating.type != SIM_HEATING_WHITE_NOISE
        || !s->collisions.present || s->collisions.kernel != SIM_KERNEL_HARD_SPHERES)
        return NAN;
    const ref_heated_params p = vfy_heated_params(s);
    return ref_heated_hs_T_steady(&p, REF_HEATED_SONINE_CLOSURE);
}
/* The Maxwellian closure's steady temperature of a white-noise heated gas of
 * any kernel exponent (paper A Ex 6-8; exact for Maxwell molecules). */
static double T_steady_maxwellian_at(const sim_scene *s)
{
    if (!s->heating.present || s->heating.type != SIM_HEATING_WHITE_NOISE
        || !s->collisions.present)
        return NAN;
    const ref_heated_params p = vfy_heated_params(s);
    return ref_heated_vhs_T_steady_maxwellian(&p, s->collisions.exponent);
}
/* Paper C: the thermostat strength for which the steady T of heated hard
 * spheres is about T0 = particles.temperature, from the collisional loss
 * rate dT/dt = gamma (1 - alpha^2)/24 4 pi C (32/sqrt(pi)) T^{3/2} (1 + 3 a2/16)
 * (unit mass, docs/theory.md §11.4, the first Sonine factor) with each
 * thermostat's a2: white noise 2 beta = loss (a2 of C.10), Gaussian 2 zeta T0
 * = loss (C.40), non-Gaussian (2/3) g <|v|> = loss with <|v|> = sqrt(2 T0)
 * (2/sqrt(pi)) (1 - a2/8) (Eq. 48, a2 of C.76).  NAN for other kernels and
 * without a heating strength (keep_temperature). */
static double heating_strength_T0_at(const sim_scene *s)
{
    if (!s->heating.present || s->heating.keep_temperature || !s->collisions.present
        || s->collisions.kernel != SIM_KERNEL_HARD_SPHERES)
        return NAN;
    const double alpha = s->collisions.restitution, T0 = s->particles.maxwellian.temperature;
    const double a2 = s->heating.type == SIM_HEATING_WHITE_NOISE ? a2_white_noise_at(s)
                      : s->heating.type == SIM_HEATING_GAUSSIAN  ? a2_gaussian_alt_at(s)
                                                                 : a2_nongaussian_fit_at(s);
    const double loss = s->collisions.rate * (1.0 - alpha * alpha) / 24.0 * 4.0 * M_PI
                        * s->collisions.constant * 32.0 / sqrt(M_PI) * pow(T0, 1.5)
                        * (1.0 + 3.0 * a2 / 16.0);
    if (s->heating.type == SIM_HEATING_WHITE_NOISE)
        return 0.5 * loss;
    if (s->heating.type == SIM_HEATING_GAUSSIAN)
        return 0.5 * loss / T0;
    return 1.5 * loss / (sqrt(2.0 * T0) * 2.0 / sqrt(M_PI) * (1.0 - a2 / 8.0));
}
static double T_star_le_at(const sim_scene *s) { return hs_steady(s, REF_BACKGROUND_LE); }
static double T_star_grad_at(const sim_scene *s) { return hs_steady(s, REF_BACKGROUND_GRAD); }

static const vfy_reference registry[] = {
    /* series, in groups (one name each): scene_refs.h decides which apply */
    {"T_exact ux_exact uy_exact uz_exact", VFY_REF_SERIES,
     "exact T(t) and mean velocity, Maxwell molecules: paper A (A.13), paper B (B.14-B.17)",
     NULL},
    {"T_finite_n T_raw_finite_n", VFY_REF_SERIES,
     "exact expectations of the n-particle estimators T and T_raw (reference/heated.h, "
     "reference/background.h)", NULL},
    {"T_maxwell_closure T_sonine_closure", VFY_REF_SERIES,
     "paper A Ex 5: Maxwellian and first-Sonine (a2 from C.10) closures (CVODE)", NULL},
    {"T_le ux_le uy_le uz_le", VFY_REF_SERIES, "paper B (B.21): local-equilibrium closure (CVODE)",
     NULL},
    {"T_grad ux_grad uy_grad uz_grad", VFY_REF_SERIES, "paper B (B.22): Grad closure (CVODE)",
     NULL},
    /* values at the scene's alpha: paper C, d = 3 */
    {"a2_C10", VFY_REF_VALUE, "paper C Eq. (10): white-noise a2", a2_white_noise_at},
    {"a2_C32", VFY_REF_VALUE, "paper C Eq. (32): white-noise a2, ratio route",
     a2_white_noise_ratio_at},
    {"a2_C5", VFY_REF_VALUE, "paper C Eq. (5): Gaussian-thermostat (HCS) a2", a2_gaussian_at},
    {"a2_C40", VFY_REF_VALUE, "paper C Eq. (40): Gaussian-thermostat a2, alternative",
     a2_gaussian_alt_at},
    {"a2_C50", VFY_REF_VALUE, "paper C Eq. (50): non-Gaussian a2", a2_nongaussian_at},
    {"a2_C76", VFY_REF_VALUE, "paper C Eq. (76): non-Gaussian a2, semi-empirical",
     a2_nongaussian_fit_at},
    {"mu2_0", VFY_REF_VALUE, "paper C: mu2 of a Maxwellian", mu2_0_at},
    {"mu2_1", VFY_REF_VALUE, "paper C: mu2's first-Sonine coefficient of a2", mu2_1_at},
    {"mu4_0", VFY_REF_VALUE, "paper C: mu4 of a Maxwellian", mu4_0_at},
    {"mu4_1", VFY_REF_VALUE, "paper C: mu4's first-Sonine coefficient of a2", mu4_1_at},
    {"A_white_noise", VFY_REF_VALUE, "paper C Eq. (36): white-noise tail amplitude",
     tail_A_white_noise_at},
    {"A_gaussian", VFY_REF_VALUE, "paper C: Gaussian-thermostat tail amplitude",
     tail_A_gaussian_at},
    {"heating_strength_T0", VFY_REF_VALUE,
     "paper C: the thermostat strength that holds hard spheres near T0 (first-Sonine "
     "loss, a2 of C.10, C.40, C.76)",
     heating_strength_T0_at},
    {"T_steady_sonine", VFY_REF_VALUE,
     "paper A Ex 5: steady T of the first-Sonine closure (a2 from C.10)", T_steady_sonine_at},
    /* values at the scene's alpha: paper D, d = 3 */
    {"kappa_prime_sonine", VFY_REF_VALUE,
     "paper D Eqs. (2.42), (2.46)-(2.47): kappa'/kappa0, first Sonine (a2 from C.40)",
     kappa_prime_star_at},
    {"kappa_prime_modified", VFY_REF_VALUE,
     "paper D ref. [28]: kappa'/kappa0, modified first Sonine (HCS weight)",
     kappa_prime_star_modified_at},
    {"kappa_sonine", VFY_REF_VALUE, "paper D Eq. (2.41): kappa/kappa0, first Sonine",
     kappa_star_at},
    {"mu_star_sonine", VFY_REF_VALUE, "paper D Eq. (2.38): mu* = 2 (kappa - kappa')/kappa0",
     mu_star_at},
    {"kappa_elastic_exact", VFY_REF_VALUE,
     "kappa/kappa0 of elastic hard spheres, converged Sonine expansion (1.025218)",
     kappa_elastic_at},
    {"b1_elastic_exact", VFY_REF_VALUE, "b'_1 of the exact elastic solution", b1_elastic_at},
    {"b2_elastic_exact", VFY_REF_VALUE, "b'_2 of the exact elastic solution", b2_elastic_at},
    {"b3_elastic_exact", VFY_REF_VALUE, "b'_3 of the exact elastic solution", b3_elastic_at},
    /* values of paper E's homogeneous shear scenes: the BGK model's steady state */
    {"a_star_bgk", VFY_REF_VALUE, "paper E, BGK model: steady a* = a tau_eta (docs/theory.md §15.2)",
     a_star_bgk_at},
    {"Pxy_reduced_bgk", VFY_REF_VALUE, "paper E, BGK model: steady -Pxy/p", Pxy_reduced_bgk_at},
    {"N1_bgk", VFY_REF_VALUE, "paper E, BGK model: steady (Pxx - Pyy)/p", N1_bgk_at},
    {"N2_bgk", VFY_REF_VALUE, "paper E, BGK model: steady (Pzz - Pyy)/p (0)", N2_bgk_at},
    {"eta_star_bgk", VFY_REF_VALUE, "paper E, BGK model: steady eta* = (-Pxy/p)/a*",
     eta_star_bgk_at},
    {"t_relaxed_bgk", VFY_REF_VALUE,
     "paper E, BGK model: the time after which T(t) stays within 1e-4 of its steady value",
     t_relaxed_bgk_at},
    {"t_end_relaxed_bgk", VFY_REF_VALUE, "paper E, BGK model: 1.25 t_relaxed_bgk",
     t_end_relaxed_bgk_at},
    {"T_ratio_bgk", VFY_REF_VALUE, "paper E, BGK model: steady T_s/T0 at the scene's a tau0",
     T_ratio_bgk_at},
    {"T_steady_maxwellian", VFY_REF_VALUE,
     "paper A, white-noise heating: steady T of the Maxwellian closure, any kernel exponent "
     "lambda (exact for Maxwell molecules)",
     T_steady_maxwellian_at},
    /* values of paper B's hard-sphere scenes */
    {"T_star_le", VFY_REF_VALUE, "paper B (B.21): steady T of the local-equilibrium closure",
     T_star_le_at},
    {"T_star_grad", VFY_REF_VALUE, "paper B (B.22): steady T of the Grad closure", T_star_grad_at},
};

size_t vfy_reference_count(void) { return sizeof registry / sizeof *registry; }

const vfy_reference *vfy_reference_at(size_t i)
{
    return i < vfy_reference_count() ? &registry[i] : NULL;
}

/* Whether `name` is one of the space-separated words of names (never the
 * empty word). */
static int names_word(const char *names, const char *name)
{
    size_t len = strlen(name);
    if (len == 0)
        return 0;
    for (const char *p = strstr(names, name); p; p = strstr(p + 1, name))
        if ((p == names || p[-1] == ' ') && (p[len] == ' ' || p[len] == '\0'))
            return 1;
    return 0;
}

const vfy_reference *vfy_reference_find(const char *name)
{
    for (size_t i = 0; i < vfy_reference_count(); i++)
        if (names_word(registry[i].name, name))
            return &registry[i];
    return NULL;
}

double vfy_reference_value(const char *name, const sim_scene *s)
{
    const vfy_reference *r = vfy_reference_find(name);
    return r && r->kind == VFY_REF_VALUE ? r->value(s) : NAN;
}

double vfy_reference_tail_A(const sim_scene *s, double mu2)
{
    if (!s->heating.present)
        return NAN;
    switch (s->heating.type) {
    case SIM_HEATING_WHITE_NOISE:
        return ref_sonine_tail_A_white_noise_mu2(mu2, 3.0);
    case SIM_HEATING_GAUSSIAN:
        return ref_sonine_tail_A_gaussian_mu2(mu2, 3.0);
    default:
        return NAN;
    }
}
