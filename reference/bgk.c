/* Paper E's BGK-model reference for homogeneous uniform shear flow (SPEC §7,
 * §8): rates, the closed-form steady state, and CVODE on the second-moment
 * system with the collision counter s0.  The derivations are in bgk.h. */
#include "bgk.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

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

/* Rates at T0 in units of 1/tau0 (dimensionless; SPEC §7, E 2.16-2.18):
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

/* E 2.12-2.13 with n sigma^2 = 4 gamma C (SPEC §7 corrections). */
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
