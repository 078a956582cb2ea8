/* Paper E's BGK-model reference for homogeneous uniform shear flow (docs/theory.md §15,
 * §16): rates, the closed-form steady state, the steady marginals (E 3.18-3.20),
 * and CVODE on the second-moment system with the collision counter s0.  The
 * derivations are in bgk.h. */
#include "bgk.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>

#include "message.h"

static const double PI = 3.14159265358979323846;

/* Describe the first out-of-range parameter into buf; return 0 when all are valid.
 * Ranges: bgk.h ("Bad input"). */
static int bad_params(const ref_bgk_params *p, char *buf, size_t len)
{
    if (!p)
        return ref_say(buf, len, "p is NULL");
    if (!(p->alpha > 0.0 && p->alpha <= 1.0))
        return ref_say(buf, len, "alpha = %g out of range (0, 1]", p->alpha);
    if (!(isfinite(p->shear_rate) && p->shear_rate >= 0.0))
        return ref_say(buf, len, "shear_rate = %g must be finite and >= 0", p->shear_rate);
    const struct {
        const char *name;
        double value;
    } pos[] = {
        {"gamma", p->gamma}, {"C", p->C},         {"mass", p->mass},
        {"T0", p->T0},       {"c_eta", p->c_eta}, {"c_eta_nu", p->c_eta_nu},
    };
    for (size_t i = 0; i < sizeof pos / sizeof pos[0]; i++)
        if (!(isfinite(pos[i].value) && pos[i].value > 0.0))
            return ref_say(buf, len, "%s = %g must be finite and > 0", pos[i].name, pos[i].value);
    if (p->model != REF_BGK_IHS && p->model != REF_BGK_EHS)
        return ref_say(buf, len, "model = %d is not REF_BGK_IHS or REF_BGK_EHS", (int)p->model);
    return 0;
}

/* Rates at T0 in units of 1/tau0 (dimensionless; docs/theory.md §2.3, E 2.16-2.18):
 *   nu' tau0 = beta/(c_eta_nu 5 sqrt(pi)/8),  zeta0 tau0 = (2/(3 sqrt(pi)))(1 - alpha^2). */
typedef struct reduced_rates {
    double beta, nu_tau, zeta_tau, tau_eta_over_tau;
} reduced_rates;

static reduced_rates reduced(const ref_bgk_params *p)
{
    const double k = 5.0 * sqrt(PI) / 8.0;
    reduced_rates r;
    r.beta = (1.0 + p->alpha) / 2.0;
    r.nu_tau = r.beta / (p->c_eta_nu * k);
    r.zeta_tau = 2.0 / (3.0 * sqrt(PI)) * (1.0 - p->alpha) * (1.0 + p->alpha);
    r.tau_eta_over_tau = p->c_eta * k;
    return r;
}

/* E 2.12-2.13 with n sigma^2 = 4 gamma C (docs/theory.md §2.3). */
static double lambda0(const ref_bgk_params *p)
{
    return 1.0 / (sqrt(2.0) * PI * 4.0 * p->gamma * p->C);
}

static double tau_at(const ref_bgk_params *p, double T)
{
    return lambda0(p) / sqrt(2.0 * T / p->mass);
}

ref_bgk_params ref_bgk_default_params(void)
{
    ref_bgk_params p = {.alpha = 0.9, .shear_rate = 0.0, .gamma = 1.0, .C = 1.0, .mass = 1.0,
                        .T0 = 1.0, .c_eta = REF_BGK_C_ETA, .c_eta_nu = REF_BGK_C_ETA,
                        .model = REF_BGK_IHS};
    p.shear_rate = 4.0 / tau_at(&p, p.T0);
    return p;
}

ref_status ref_bgk_rates_at(const ref_bgk_params *p, double T, ref_bgk_rates *out, char *msg,
                            size_t msglen)
{
    if (bad_params(p, msg, msglen))
        return REF_EINVAL;
    if (!(isfinite(T) && T > 0.0)) {
        ref_say(msg, msglen, "T = %g must be finite and > 0", T);
        return REF_EINVAL;
    }
    if (!out) {
        ref_say(msg, msglen, "out is NULL");
        return REF_EINVAL;
    }
    reduced_rates r = reduced(p);
    out->lambda0 = lambda0(p);
    out->tau = tau_at(p, T);
    out->tau_eta = r.tau_eta_over_tau * out->tau;
    out->beta = r.beta;
    out->nu = r.nu_tau / out->tau;
    out->zeta0 = r.zeta_tau / out->tau;
    ref_say(msg, msglen, "%s", "");
    return REF_OK;
}

/* Steady state, bgk.h: x = zeta0/nu', a/nu' = sqrt(3x/2)(1 + x),
 * -Pxy/p = sqrt(3x/2)/(1 + x), (Pxx - Pyy)/p = 3x/(1 + x). */
ref_status ref_bgk_steady_state(const ref_bgk_params *p, ref_bgk_steady *out, char *msg,
                                size_t msglen)
{
    if (bad_params(p, msg, msglen))
        return REF_EINVAL;
    if (!(p->alpha < 1.0)) {
        ref_say(msg, msglen,
                "alpha = %g has no steady state (zeta0 = 0: viscous heating only, T grows "
                "without bound); allowed range (0, 1)", p->alpha);
        return REF_EINVAL;
    }
    if (!(p->shear_rate > 0.0)) {
        ref_say(msg, msglen,
                "shear_rate = %g has no steady shear state (the gas cools to T = 0); "
                "allowed range (0, inf)", p->shear_rate);
        return REF_EINVAL;
    }
    if (!out) {
        ref_say(msg, msglen, "out is NULL");
        return REF_EINVAL;
    }
    reduced_rates r = reduced(p);
    const double x = r.zeta_tau / r.nu_tau, q = sqrt(1.5 * x);
    const double a_tau = q * (1.0 + x) * r.nu_tau;    /* a tau_s = (a/nu') (nu' tau) */
    const double a_tau0 = p->shear_rate * tau_at(p, p->T0);
    out->x = x;
    out->a_tau = a_tau;
    out->a_star = a_tau * r.tau_eta_over_tau;
    out->shear_stress = q / (1.0 + x);
    out->normal_xy = 3.0 * x / (1.0 + x);
    out->normal_zy = 0.0;
    out->eta_star = out->shear_stress / out->a_star;
    out->T_ratio = (a_tau0 / a_tau) * (a_tau0 / a_tau);
    out->eta_star_ns = 1.0 / (r.tau_eta_over_tau * (r.nu_tau + r.zeta_tau / 2.0));
    ref_say(msg, msglen, "%s", "");
    return REF_OK;
}

/* ---------------------------------------------------------------- marginals */

/* Quadrature of the marginals (bgk.h, "Numerics"): sigma = L t/(1 - t), t in [0, 1),
 * the u integral of F over [0, 1].  The tolerances asked of CQUAD are 100 times
 * tighter than the ones accepted: its error estimates are pessimistic (measured
 * errors 1e-12-4e-11 for these settings against a 1e-13 run). */
enum { QUAD_INTERVALS = 200 };
static const double SIGMA_RTOL = 1e-9, U_RTOL = 1e-10, ACCEPT_RTOL = 1e-8, U_ACCEPT_RTOL = 1e-9;
static const double SIGMA_SCALE = 4.0; /* L: t = 1/2 at sigma = 4, t = 0.9 at sigma = 36 */
/* The integrands are taken as 0 beyond sigma = 1500 or x sigma = 700 (k = e^{x sigma}
 * about to overflow): for x < 1 the weight e^{-(1 - x/2) sigma} is below e^{-350} there,
 * and F's and the g's Gaussians have underflowed unless |C| < 1e-150. */
static const double SIGMA_MAX = 1500.0, X_SIGMA_MAX = 700.0;

typedef struct marginal_q {
    double x, A, c;       /* x = zeta0/nu', A = a/nu', the argument */
    double kc2, l2, dl;   /* F's u integrand at one sigma: k C^2, l2, l1 - l2 */
    gsl_integration_cquad_workspace *wu;
    int u_failed;         /* an inner (u) integral missed its tolerance */
} marginal_q;

/* g_x^(+): the sigma integrand of bgk.h. */
static double gx_plus_sigma(marginal_q *q, double s)
{
    const double k = exp(q->x * s), b = q->A * s, d = 1.0 + b * b;
    return exp(-(1.0 - 0.5 * q->x) * s) * exp(-k * q->c * q->c / d)
           * erfc(b * q->c * sqrt(k / d)) / (2.0 * sqrt(PI) * sqrt(d));
}

/* g_y^(+), bgk.h. */
static double gy_plus_sigma(marginal_q *q, double s)
{
    const double k = exp(q->x * s), b = q->A * s;
    return exp(-(1.0 - 0.5 * q->x) * s) * exp(-k * q->c * q->c) * erfc(b * q->c * sqrt(k))
           / (2.0 * sqrt(PI));
}

/* F's u integrand (bgk.h): exp(-k C^2 [u^2 + (1 - u^2) l2]) I0s(k C^2 (1 - u^2) (l1 - l2)/2). */
static double f_speed_u(double u, void *vp)
{
    const marginal_q *q = vp;
    const double v = 1.0 - u * u, e = q->kc2 * (u * u + v * q->l2);
    if (!(e < 746.0))
        return 0.0; /* exp(-e) underflows (I0s <= 1) */
    gsl_sf_result i0s;
    if (gsl_sf_bessel_I0_scaled_e(0.5 * q->kc2 * v * q->dl, &i0s) != GSL_SUCCESS)
        return NAN; /* not expected for a finite argument; CQUAD drops the node */
    return exp(-e) * i0s.val;
}

/* F, bgk.h: (4 C^2/sqrt(pi)) e^{-(1 - 3x/2) sigma} ∫_0^1 du (...). */
static double f_speed_sigma(marginal_q *q, double s)
{
    const double k = exp(q->x * s), b = q->A * s, c2 = q->c * q->c;
    const double w = 4.0 * c2 / sqrt(PI) * exp(-(1.0 - 1.5 * q->x) * s);
    q->l2 = 1.0 / (1.0 + 0.5 * b * b + 0.5 * b * sqrt(b * b + 4.0)); /* 1/l1, stable */
    q->dl = b * sqrt(b * b + 4.0);
    q->kc2 = k * c2;
    /* the u integrand is below exp(-k C^2 l2): skip the sigmas where w times it underflows
     * (also k C^2 = inf) */
    if (!(q->kc2 * q->l2 - log(w) < 740.0))
        return 0.0;
    gsl_function fu = {f_speed_u, q};
    double r, err;
    size_t nev;
    if (gsl_integration_cquad(&fu, 0.0, 1.0, 0.0, U_RTOL, q->wu, &r, &err, &nev) != GSL_SUCCESS
        || !(err <= U_ACCEPT_RTOL * fabs(r) + DBL_MIN))
        q->u_failed = 1;
    return w * r;
}

typedef struct marginal_t {
    marginal_q *q;
    double (*of_sigma)(marginal_q *q, double s);
    double s0; /* the start of the mapped tail */
} marginal_t;

/* The sigma integrands (the three above) on a finite piece, in sigma itself. */
static double marginal_sigma(double s, void *vp)
{
    const marginal_t *m = vp;
    return m->of_sigma(m->q, s);
}

/* ... and on the tail [s0, inf), in t: sigma = s0 + L t/(1 - t), dsigma = L dt/(1 - t)^2. */
static double marginal_tail(double t, void *vp)
{
    const marginal_t *m = vp;
    if (!(t < 1.0))
        return 0.0;
    const double s = m->s0 + SIGMA_SCALE * t / (1.0 - t);
    if (!(s < SIGMA_MAX && m->q->x * s < X_SIGMA_MAX))
        return 0.0;
    return m->of_sigma(m->q, s) * SIGMA_SCALE / ((1.0 - t) * (1.0 - t));
}

/* ∫_0^inf dsigma of_sigma over the pieces [0, h], [h, 4h], [4h, 16h], ... up to
 * sigma = SIGMA_SCALE and the mapped tail beyond, with h = 1/(1 + C^2 (x + A) + A |C|)
 * the shortest scale of the integrands near sigma = 0: k C^2/(1 + b^2) and k C^2 l2
 * change at the rates C^2 x and C^2 A there (l2 = 1 - b + O(b^2)), the erfc's at
 * A |C|.  For |C| >> 1 the integrands are a spike at sigma = 0 (the Maxwellian
 * tail) that one CQUAD run over the whole range can miss (-6% on g_y^(+)(20) at
 * alpha = 0.5). */
static int integrate_sigma(marginal_t *m, gsl_integration_cquad_workspace *ws, double *r,
                           double *err)
{
    const marginal_q *q = m->q;
    const double h = 1.0 / (1.0 + q->c * q->c * (q->x + q->A) + q->A * fabs(q->c));
    gsl_function f = {marginal_sigma, m};
    double ri, ei;
    size_t nev;
    *r = *err = 0.0;
    /* (h >= 1e-12: at most 20 pieces; the integrands have underflowed long before) */
    for (double a = 0.0, b = fmax(h, 1e-12); a < SIGMA_SCALE; b *= 4.0) {
        const double e = fmin(b, SIGMA_SCALE);
        const int gs = gsl_integration_cquad(&f, a, e, 0.0, SIGMA_RTOL, ws, &ri, &ei, &nev);
        if (gs != GSL_SUCCESS)
            return gs;
        *r += ri;
        *err += ei;
        a = e;
    }
    m->s0 = SIGMA_SCALE;
    gsl_function g = {marginal_tail, m};
    const int gs = gsl_integration_cquad(&g, 0.0, 1.0, 0.0, SIGMA_RTOL, ws, &ri, &ei, &nev);
    *r += ri;
    *err += ei;
    return gs;
}

static const char *marginal_name(ref_bgk_marginal which)
{
    return which == REF_BGK_GX_PLUS ? "g_x^(+)" : which == REF_BGK_GY_PLUS ? "g_y^(+)" : "F";
}

/* E Eqs. (3.18)-(3.20) by the sigma integrals of bgk.h. */
ref_status ref_bgk_steady_marginal(const ref_bgk_params *p, ref_bgk_marginal which, double c,
                                   double *value, char *msg, size_t msglen)
{
    ref_bgk_steady st;
    if (ref_bgk_steady_state(p, &st, msg, msglen) != REF_OK)
        return REF_EINVAL;
    if (!(st.x < 1.0)) {
        ref_say(msg, msglen,
                "x = zeta0/nu' = %g (alpha = %g, c_eta_nu = %g) must be < 1 for the "
                "marginals", st.x, p->alpha, p->c_eta_nu);
        return REF_EINVAL;
    }
    if (which != REF_BGK_GX_PLUS && which != REF_BGK_GY_PLUS && which != REF_BGK_F_SPEED) {
        ref_say(msg, msglen,
                "which = %d is not REF_BGK_GX_PLUS, REF_BGK_GY_PLUS or REF_BGK_F_SPEED",
                (int)which);
        return REF_EINVAL;
    }
    if (!isfinite(c)) {
        ref_say(msg, msglen, "c = %g must be finite", c);
        return REF_EINVAL;
    }
    if (which == REF_BGK_F_SPEED && !(c >= 0.0)) {
        ref_say(msg, msglen, "c = %g: the speed C of F(C) must be >= 0", c);
        return REF_EINVAL;
    }
    if (!value) {
        ref_say(msg, msglen, "value is NULL");
        return REF_EINVAL;
    }
    if (which == REF_BGK_F_SPEED && c * c == 0.0) { /* F = C^2 (...) */
        *value = 0.0;
        ref_say(msg, msglen, "%s", "");
        return REF_OK;
    }
    marginal_q q = {.x = st.x, .A = sqrt(1.5 * st.x) * (1.0 + st.x), .c = c};
    gsl_integration_cquad_workspace *ws = gsl_integration_cquad_workspace_alloc(QUAD_INTERVALS);
    if (which == REF_BGK_F_SPEED)
        q.wu = gsl_integration_cquad_workspace_alloc(QUAD_INTERVALS);
    if (!ws || (which == REF_BGK_F_SPEED && !q.wu)) {
        gsl_integration_cquad_workspace_free(ws);
        gsl_integration_cquad_workspace_free(q.wu);
        ref_say(msg, msglen, "cannot allocate the quadrature workspaces");
        return REF_ENOMEM;
    }
    marginal_t m = {&q,
                    which == REF_BGK_GX_PLUS   ? gx_plus_sigma
                    : which == REF_BGK_GY_PLUS ? gy_plus_sigma
                                               : f_speed_sigma,
                    0.0};
    double r = NAN, err = NAN;
    const int gs = integrate_sigma(&m, ws, &r, &err);
    gsl_integration_cquad_workspace_free(ws);
    gsl_integration_cquad_workspace_free(q.wu);
    if (gs != GSL_SUCCESS || q.u_failed || !isfinite(r)
        || !(err <= ACCEPT_RTOL * fabs(r) + DBL_MIN)) {
        ref_say(msg, msglen,
                "%s(%g) at x = %g: the quadrature missed its tolerance (value %.17g, "
                "estimated error %g, GSL status %d%s)", marginal_name(which), c, st.x, r, err,
                gs, q.u_failed ? ", an angular integral failed" : "");
        return REF_ESOLVER;
    }
    *value = r;
    ref_say(msg, msglen, "%s", "");
    return REF_OK;
}

/* The system of bgk.h in y = (Pxx, Pyy, Pzz, Pxy)/(n T0), s0, physical time:
 * nu' = nu0 sqrt(theta), zeta0 = zeta00 sqrt(theta), theta = T/T0 = tr y/3,
 * ds0/dt = s_rate sqrt(theta). */
typedef struct bgk_rhs_params {
    double a, nu0, zeta00, s_rate;
} bgk_rhs_params;

static int bgk_rhs(double t, const double *y, double *ydot, void *params)
{
    const bgk_rhs_params *q = params;
    (void)t;
    const double theta = (y[0] + y[1] + y[2]) / 3.0;
    if (!(theta > 0.0))
        return 1; /* a trial step overshot to T <= 0 (sqrt T): recoverable, CVODE cuts the step */
    const double r = sqrt(theta), nu = q->nu0 * r, zeta = q->zeta00 * r;
    ydot[0] = -2.0 * q->a * y[3] - nu * (y[0] - theta) - zeta * y[0];
    ydot[1] = -nu * (y[1] - theta) - zeta * y[1];
    ydot[2] = -nu * (y[2] - theta) - zeta * y[2];
    ydot[3] = -q->a * y[1] - (nu + zeta) * y[3];
    ydot[4] = q->s_rate * r;
    return 0;
}

enum { DIM = 5 };

ref_status ref_bgk_solve(const ref_bgk_params *p, const double *t, size_t nt,
                         const ref_ode_options *opt, const ref_bgk_output *out, char *msg,
                         size_t msglen)
{
    if (bad_params(p, msg, msglen) || ref_bad_times(t, nt, msg, msglen))
        return REF_EINVAL;
    if (!out) {
        ref_say(msg, msglen, "out is NULL");
        return REF_EINVAL;
    }
    if (nt > SIZE_MAX / (DIM * sizeof(double))) {
        ref_say(msg, msglen, "nt = %zu is too large to allocate the solution", nt);
        return REF_ENOMEM;
    }
    double *y = malloc(DIM * nt * sizeof *y);
    if (!y) {
        ref_say(msg, msglen, "cannot allocate the solution for nt = %zu times", nt);
        return REF_ENOMEM;
    }
    const reduced_rates r = reduced(p);
    const double tau0 = tau_at(p, p->T0);
    bgk_rhs_params q = {p->shear_rate, r.nu_tau / tau0, r.zeta_tau / tau0,
                        (p->model == REF_BGK_EHS ? r.beta : 1.0) / (sqrt(PI) * tau0)};
    const double y0[DIM] = {1.0, 1.0, 1.0, 0.0, 0.0}; /* E 3.12: local equilibrium at T0 */
    ref_status st = ref_ode_solve(bgk_rhs, &q, DIM, y0, t, nt, opt, y, msg, msglen);
    if (st == REF_OK) {
        for (size_t m = 0; m < nt; m++) {
            const double *ym = y + DIM * m;
            const double theta = (ym[0] + ym[1] + ym[2]) / 3.0;
            if (out->T)
                out->T[m] = p->T0 * theta;
            if (out->Pxx)
                out->Pxx[m] = p->T0 * ym[0];
            if (out->Pyy)
                out->Pyy[m] = p->T0 * ym[1];
            if (out->Pzz)
                out->Pzz[m] = p->T0 * ym[2];
            if (out->Pxy)
                out->Pxy[m] = p->T0 * ym[3];
            if (out->s0)
                out->s0[m] = ym[4];
            if (out->a_star) /* a tau_eta(T) = a tau_eta(T0)/sqrt(theta) */
                out->a_star[m] = p->shear_rate * r.tau_eta_over_tau * tau0 / sqrt(theta);
        }
    }
    free(y);
    return st;
}

ref_status ref_bgk_relaxation_time(const ref_bgk_params *p, double band, double *t_relaxed,
                                   char *msg, size_t msglen)
{
    ref_bgk_steady st;
    ref_status status = ref_bgk_steady_state(p, &st, msg, msglen);
    if (status != REF_OK)
        return status;
    if (!(band > 0.0) || !t_relaxed) {
        ref_say(msg, msglen, "band = %g is not positive or t_relaxed is NULL", band);
        return REF_EINVAL;
    }
    enum { NT = 4000 };
    double *t = malloc(2 * NT * sizeof *t);
    if (!t) {
        ref_say(msg, msglen, "cannot allocate %d output times", NT);
        return REF_ENOMEM;
    }
    double *T = t + NT;
    const ref_bgk_output out = {.T = T};
    const double Ts = st.T_ratio * p->T0;
    status = REF_ESOLVER;
    ref_say(msg, msglen, "T(t) not within %g of its steady value by t = 1e5", band);
    for (double t_max = 64.0; t_max <= 1e5; t_max *= 2) {
        for (size_t k = 0; k < NT; k++)
            t[k] = t_max * (double)k / (NT - 1);
        if ((status = ref_bgk_solve(p, t, NT, NULL, &out, msg, msglen)) != REF_OK)
            break;
        size_t last = 0;   /* the last time still outside the band */
        for (size_t k = 0; k < NT; k++)
            if (!(fabs(T[k] / Ts - 1.0) <= band))
                last = k;
        if (last + 1 < NT * 3 / 4) {   /* the band holds over the last quarter at least */
            *t_relaxed = t[last + 1];
            break;
        }
        status = REF_ESOLVER;
    }
    free(t);
    return status;
}
