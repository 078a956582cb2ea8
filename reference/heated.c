/* References for paper A, the uniformly heated granular gas (docs/theory.md §11). */
#include "heated.h"

#include <math.h>
#include <stdio.h>

#include "message.h"
#include "sonine.h"

static const double PI = 3.14159265358979323846;

/* Describe the first out-of-range parameter into buf; return 0 when all are valid.
 * Ranges: docs/theory.md §11 (alpha in (0,1], beta >= 0, gamma > 0), C > 0, T0 > 0, all finite. */
static int bad_params(const ref_heated_params *p, char *buf, size_t len)
{
    if (!p)
        return ref_say(buf, len, "p is NULL");
    if (!(p->alpha > 0.0 && p->alpha <= 1.0))
        return ref_say(buf, len, "alpha = %g out of range (0, 1]", p->alpha);
    if (!(p->beta >= 0.0 && isfinite(p->beta)))
        return ref_say(buf, len, "beta = %g must be finite and >= 0", p->beta);
    if (!(p->gamma > 0.0 && isfinite(p->gamma)))
        return ref_say(buf, len, "gamma = %g must be finite and > 0", p->gamma);
    if (!(p->C > 0.0 && isfinite(p->C)))
        return ref_say(buf, len, "C = %g must be finite and > 0", p->C);
    if (!(p->T0 > 0.0 && isfinite(p->T0)))
        return ref_say(buf, len, "T0 = %g must be finite and > 0", p->T0);
    return 0;
}

static int valid(const ref_heated_params *p)
{
    return !bad_params(p, NULL, 0);
}

/* k = gamma pi C0 (1 - alpha^2)  (docs/theory.md §11.1, paper A Eq. A.13-14). */
double ref_heated_maxwell_rate(const ref_heated_params *p)
{
    if (!valid(p))
        return NAN;
    return p->gamma * PI * p->C * (1.0 - p->alpha * p->alpha);
}

/* T_inf = 2 beta / k (A.14). */
double ref_heated_maxwell_T_inf(const ref_heated_params *p)
{
    double k = ref_heated_maxwell_rate(p);
    if (isnan(k))
        return NAN;
    if (k == 0.0)
        return p->beta > 0.0 ? INFINITY : p->T0;
    return 2.0 * p->beta / k;
}

/* T(t) = T0 e^{-kt} + T_inf (1 - e^{-kt}) (A.13), written as
 * T0 e^{-kt} + 2 beta (1 - e^{-kt})/k with expm1 so that k -> 0 gives T0 + 2 beta t. */
double ref_heated_maxwell_T(const ref_heated_params *p, double t)
{
    double k = ref_heated_maxwell_rate(p);
    if (isnan(k) || !isfinite(t))
        return NAN;
    double growth = k == 0.0 ? t : -expm1(-k * t) / k; /* (1 - e^{-kt}) / k */
    return p->T0 * exp(-k * t) + 2.0 * p->beta * growth;
}

/* docs/theory.md §11.2 (exact finite-n behaviour): E T_centred = (1 - 1/n) T(t). */
double ref_heated_maxwell_T_centred_mean(const ref_heated_params *p, double n, double t)
{
    if (!(n >= 1.0 && isfinite(n)))
        return NAN;
    return (1.0 - 1.0 / n) * ref_heated_maxwell_T(p, t);
}

/* docs/theory.md §11.2: E T_raw = T(t) + (T0 + 2 beta t - T(t)) / n; the 1/n term is the
 * random walk of the total momentum under white-noise heating (docs/theory.md §1.2). */
double ref_heated_maxwell_T_raw_mean(const ref_heated_params *p, double n, double t)
{
    if (!(n >= 1.0 && isfinite(n)))
        return NAN;
    double T = ref_heated_maxwell_T(p, t);
    if (isnan(T))
        return NAN;
    return T + (p->T0 + 2.0 * p->beta * t - T) / n;
}

/* Loss coefficient L of dT/dt = 2 beta - L T^{3/2} (docs/theory.md §11.4):
 * L = gamma (1-alpha^2)/24 * 4 pi C1 * 32/sqrt(pi) * factor, with factor
 * 1 (Maxwellian closure) or 1 + 3 a2/16, a2 from paper C Eq. (C.10), d = 3. */
static double hs_loss(const ref_heated_params *p, ref_heated_closure closure)
{
    double factor = 1.0;
    if (closure == REF_HEATED_SONINE_CLOSURE)
        factor += 3.0 * ref_sonine_a2_white_noise(p->alpha, 3.0) / 16.0;
    else if (closure != REF_HEATED_MAXWELLIAN_CLOSURE)
        return NAN;
    return p->gamma * (1.0 - p->alpha * p->alpha) / 24.0 * 4.0 * PI * p->C
           * (32.0 / sqrt(PI)) * factor;
}

/* T* = (2 beta / L)^{2/3}; with no loss (alpha = 1) T* is +inf if heated, else T0. */
double ref_heated_hs_T_steady(const ref_heated_params *p, ref_heated_closure closure)
{
    if (!valid(p))
        return NAN;
    double L = hs_loss(p, closure);
    if (isnan(L))
        return NAN;
    if (L == 0.0)
        return p->beta > 0.0 ? INFINITY : p->T0;
    return pow(2.0 * p->beta / L, 2.0 / 3.0);
}

double ref_heated_vhs_T_steady_maxwellian(const ref_heated_params *p, double lambda)
{
    if (!valid(p) || !(lambda >= 0.0 && lambda <= 1.0))
        return NAN;
    const double q = 2.0 + lambda;
    const double g_moment = pow(4.0, 0.5 * q) * tgamma(0.5 * (3.0 + q)) / tgamma(1.5);
    const double L = p->gamma * (1.0 - p->alpha * p->alpha) / 24.0 * 4.0 * PI * p->C * g_moment;
    if (L == 0.0)
        return p->beta > 0.0 ? INFINITY : p->T0;
    return pow(2.0 * p->beta / L, 2.0 / q);
}

double ref_heated_tail_A(const ref_heated_params *p, double lambda, double T)
{
    if (!valid(p) || !(lambda >= 0.0 && lambda <= 1.0) || !(p->beta > 0.0) || !(T > 0.0))
        return NAN;
    const double b = 1.0 + 0.5 * lambda;
    return sqrt(4.0 * PI * p->gamma * p->C / p->beta) / b * pow(2.0 * T, 0.5 * b);
}

typedef struct hs_rhs_params {
    double two_beta, L;
} hs_rhs_params;

static int hs_rhs(double t, const double *y, double *ydot, void *params)
{
    const hs_rhs_params *q = params;
    (void)t;
    if (!(y[0] >= 0.0))
        return 1; /* trial step overshot below T = 0: recoverable, CVODE cuts the step */
    ydot[0] = q->two_beta - q->L * y[0] * sqrt(y[0]);
    return 0;
}

/* Describe the first bad argument of ref_heated_hs_T into msg; 0 when all are valid. */
static int bad_hs_args(const ref_heated_params *p, ref_heated_closure closure, const double *t,
                       size_t nt, const double *T_out, char *buf, size_t len)
{
    if (bad_params(p, buf, len))
        return 1;
    if (closure != REF_HEATED_MAXWELLIAN_CLOSURE && closure != REF_HEATED_SONINE_CLOSURE)
        return ref_say(buf, len, "closure = %d is not MAXWELLIAN or SONINE", (int)closure);
    if (!t || !T_out)
        return ref_say(buf, len, "%s is NULL", !t ? "t" : "T_out");
    return ref_bad_times(t, nt, buf, len);
}

ref_status ref_heated_hs_T(const ref_heated_params *p, ref_heated_closure closure,
                           const double *t, size_t nt, const ref_ode_options *opt,
                           double *T_out, char *msg, size_t msglen)
{
    if (bad_hs_args(p, closure, t, nt, T_out, msg, msglen))
        return REF_EINVAL;
    hs_rhs_params q = {2.0 * p->beta, hs_loss(p, closure)};
    return ref_ode_solve(hs_rhs, &q, 1, &p->T0, t, nt, opt, T_out, msg, msglen);
}
