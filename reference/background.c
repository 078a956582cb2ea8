/* References for paper B, a granular gas in a host medium (docs/theory.md §12):
 * closed forms (B.14)-(B.18), CVODE for (B.13), (B.21) and (B.22), and the
 * closures' steady states by GSL root finding. */
#include "background.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "message.h"

static const double PI = 3.14159265358979323846;

static int positive(double x)
{
    return isfinite(x) && x > 0.0;
}

/* Describe the first out-of-range parameter into buf; return 0 when all are valid.
 * Ranges (docs/theory.md §12): masses, densities, T_B, C1, T0 finite and > 0; C2 finite
 * and >= 0; e in (0, 1]; velocities finite. */
static int bad_params(const ref_background_params *p, char *buf, size_t len)
{
    if (!p)
        return ref_say(buf, len, "p is NULL");
    const struct {
        const char *name;
        double value;
    } pos[] = {
        {"mass", p->mass},       {"bg_density", p->bg_density}, {"bg_mass", p->bg_mass},
        {"bg_temperature", p->bg_temperature}, {"C1", p->C1}, {"density", p->density},
        {"T0", p->T0},
    };
    for (size_t i = 0; i < sizeof pos / sizeof pos[0]; i++)
        if (!positive(pos[i].value))
            return ref_say(buf, len, "%s = %g must be finite and > 0", pos[i].name, pos[i].value);
    if (!(isfinite(p->C2) && p->C2 >= 0.0))
        return ref_say(buf, len, "C2 = %g must be finite and >= 0", p->C2);
    if (!(p->restitution > 0.0 && p->restitution <= 1.0))
        return ref_say(buf, len, "restitution = %g out of range (0, 1]", p->restitution);
    for (int i = 0; i < 3; i++) {
        if (!isfinite(p->bg_velocity[i]))
            return ref_say(buf, len, "bg_velocity[%d] = %g is not finite", i, p->bg_velocity[i]);
        if (!isfinite(p->u0[i]))
            return ref_say(buf, len, "u0[%d] = %g is not finite", i, p->u0[i]);
    }
    return 0;
}

static int valid(const ref_background_params *p)
{
    return !bad_params(p, NULL, 0);
}

/* alpha = m_B/(m + m_B), docs/theory.md §3.4 (a mass ratio, not a restitution coefficient). */
static double mass_ratio(const ref_background_params *p)
{
    return p->bg_mass / (p->mass + p->bg_mass);
}

static double dist2(const double a[3], const double b[3])
{
    double s = 0.0;
    for (int i = 0; i < 3; i++)
        s += (a[i] - b[i]) * (a[i] - b[i]);
    return s;
}

/* ---------------------------------------------------------------- Maxwell kernels */

/* Constants of (B.17) in the paper's scaled time s = rho_B C1 t, Kn = rho C2/(rho_B C1)
 * (Eq. 12).  B and C are pi times sums of the dimensionless rates, so that
 * parameters with B = C in exact arithmetic give B == C when the sums are exact. */
typedef struct maxwell_const {
    double alpha, Kn, A, B, C, D;
} maxwell_const;

static maxwell_const maxwell_constants(const ref_background_params *p)
{
    maxwell_const k;
    double e = p->restitution;
    k.alpha = mass_ratio(p);
    k.Kn = p->density * p->C2 / (p->bg_density * p->C1);
    double el = 8.0 * k.alpha * (1.0 - k.alpha); /* 8 alpha (1 - alpha) */
    k.A = 8.0 / 3.0 * PI * p->mass * k.alpha * k.alpha * dist2(p->u0, p->bg_velocity);
    k.B = PI * (8.0 * k.alpha);
    k.C = PI * (el + k.Kn * (1.0 - e * e));
    k.D = PI * el * p->bg_temperature;
    return k;
}

/* (B.14): u(t) = u_B + (u0 - u_B) exp(-4 pi alpha rho_B C1 t). */
void ref_background_maxwell_u(const ref_background_params *p, double t, double u[3])
{
    if (!u)
        return;
    if (!valid(p) || !(isfinite(t) && t >= 0.0)) {
        u[0] = u[1] = u[2] = NAN;
        return;
    }
    double decay = exp(-4.0 * PI * mass_ratio(p) * p->bg_density * p->C1 * t);
    for (int i = 0; i < 3; i++)
        u[i] = p->bg_velocity[i] + (p->u0[i] - p->bg_velocity[i]) * decay;
}

/* (1 - e^{-k s})/k with expm1; s when k = 0. */
static double growth(double k, double s)
{
    return k == 0.0 ? s : -expm1(-k * s) / k;
}

/* (e^{-Bs} - e^{-Cs})/(C - B), symmetric in B and C, as e^{-lo s} (1 - e^{-(hi-lo) s})/(hi - lo)
 * with lo = min(B, C): no cancellation as C -> B, no overflow, and s e^{-Bs} (B.16) at B = C. */
static double exp_difference_quotient(double B, double C, double s)
{
    double lo = fmin(B, C), hi = fmax(B, C);
    return exp(-lo * s) * growth(hi - lo, s);
}

/* (B.15) for B != C, (B.16) for B = C (docs/theory.md §12.1), at s = rho_B C1 t. */
double ref_background_maxwell_T(const ref_background_params *p, double t)
{
    if (!valid(p) || !(isfinite(t) && t >= 0.0))
        return NAN;
    maxwell_const k = maxwell_constants(p);
    double s = p->bg_density * p->C1 * t;
    /* T0 e^{-Cs} + D (1 - e^{-Cs})/C + A (e^{-Bs} - e^{-Cs})/(C - B); with C = B the
     * last factor is s e^{-Bs} and D/C = D/B, which is (B.16). */
    return p->T0 * exp(-k.C * s) + k.D * growth(k.C, s)
           + k.A * exp_difference_quotient(k.B, k.C, s);
}

/* (B.18): T* = D/C. */
double ref_background_maxwell_T_steady(const ref_background_params *p)
{
    if (!valid(p))
        return NAN;
    maxwell_const k = maxwell_constants(p);
    if (k.C == 0.0) /* alpha underflowed to 0 and no loss: T(t) = T0 + A (1 - e^{-Bs})/B */
        return k.B > 0.0 ? p->T0 + k.A / k.B : p->T0;
    return k.D / k.C;
}

/* Right-hand side of (B.13) in physical time: the paper's (scaled-time) right-hand
 * side times rho_B C1.  y = (u_1, u_2, u_3, T). */
typedef struct maxwell_rhs_params {
    double rate;     /* rho_B C1 */
    double alpha, Kn, e, m, T_B;
    double u_B[3];
} maxwell_rhs_params;

static int maxwell_rhs(double t, const double *y, double *ydot, void *params)
{
    const maxwell_rhs_params *q = params;
    (void)t;
    double a = q->alpha, du2 = dist2(y, q->u_B);
    for (int i = 0; i < 3; i++)
        ydot[i] = q->rate * (-4.0 * PI * a * (y[i] - q->u_B[i]));
    ydot[3] = q->rate * (8.0 / 3.0 * PI * (q->m * a * a * du2 - 3.0 * a * (1.0 - a) * (y[3] - q->T_B))
                         - PI * q->Kn * (1.0 - q->e * q->e) * y[3]);
    return 0;
}

/* Solve y' = f with y0 = (u0, T0) at the times t and split the rows into u_out and T_out. */
static ref_status solve_4(ref_rhs_fn f, void *params, const ref_background_params *p,
                          const double *t, size_t nt, const ref_ode_options *opt, double *u_out,
                          double *T_out, char *msg, size_t msglen)
{
    if (nt > SIZE_MAX / (4 * sizeof(double))) {
        ref_say(msg, msglen, "nt = %zu is too large to allocate the solution", nt);
        return REF_ENOMEM;
    }
    double *y = malloc(4 * nt * sizeof *y);
    if (!y) {
        ref_say(msg, msglen, "cannot allocate the solution for nt = %zu times", nt);
        return REF_ENOMEM;
    }
    double y0[4] = {p->u0[0], p->u0[1], p->u0[2], p->T0};
    ref_status st = ref_ode_solve(f, params, 4, y0, t, nt, opt, y, msg, msglen);
    if (st == REF_OK) {
        for (size_t m = 0; m < nt; m++) {
            if (u_out)
                for (int i = 0; i < 3; i++)
                    u_out[3 * m + i] = y[4 * m + i];
            T_out[m] = y[4 * m + 3];
        }
    }
    free(y);
    return st;
}

ref_status ref_background_maxwell_ode(const ref_background_params *p, const double *t, size_t nt,
                                      const ref_ode_options *opt, double *u_out, double *T_out,
                                      char *msg, size_t msglen)
{
    if (bad_params(p, msg, msglen) || ref_bad_times(t, nt, msg, msglen))
        return REF_EINVAL;
    if (!T_out) {
        ref_say(msg, msglen, "T_out is NULL");
        return REF_EINVAL;
    }
    maxwell_const k = maxwell_constants(p);
    maxwell_rhs_params q = {p->bg_density * p->C1, k.alpha, k.Kn, p->restitution, p->mass,
                            p->bg_temperature,
                            {p->bg_velocity[0], p->bg_velocity[1], p->bg_velocity[2]}};
    return solve_4(maxwell_rhs, &q, p, t, nt, opt, u_out, T_out, msg, msglen);
}

typedef struct finite_n_params {
    double lambda, alpha, k, theta, n;
} finite_n_params;

/* y = (Q, P) of ref_background_maxwell_T_mean. */
static int finite_n_rhs(double t, const double *y, double *ydot, void *params)
{
    const finite_n_params *q = params;
    (void)t;
    double a = q->alpha, la = q->lambda, source = 6.0 * q->n * la * a * a * q->theta;
    ydot[0] = -(2.0 * la * a * (1.0 - a) + q->k) * y[0] + q->k / q->n * y[1] + source;
    ydot[1] = 2.0 * la * a * a * y[0] - 2.0 * la * a * y[1] + source;
    return 0;
}

ref_status ref_background_maxwell_T_mean(const ref_background_params *p, double n,
                                         const double *t, size_t nt,
                                         const ref_ode_options *opt, double *T_out, char *msg,
                                         size_t msglen)
{
    if (bad_params(p, msg, msglen) || ref_bad_times(t, nt, msg, msglen))
        return REF_EINVAL;
    if (!(n >= 2.0 && isfinite(n))) {
        ref_say(msg, msglen, "n = %g out of range (allowed n >= 2)", n);
        return REF_EINVAL;
    }
    if (!T_out) {
        ref_say(msg, msglen, "T_out is NULL");
        return REF_EINVAL;
    }
    double *y = malloc(2 * nt * sizeof *y);
    if (!y) {
        ref_say(msg, msglen, "cannot allocate the solution for nt = %zu times", nt);
        return REF_ENOMEM;
    }
    const double e = p->restitution, d2 = dist2(p->u0, p->bg_velocity);
    finite_n_params q = {4.0 * PI * p->C1 * p->bg_density, mass_ratio(p),
                         PI * p->density * p->C2 * (1.0 - e * e),
                         p->bg_temperature / p->bg_mass, n};
    double Q0 = n * (d2 + 3.0 * p->T0 / p->mass);
    double y0[2] = {Q0, Q0 + n * (n - 1.0) * d2};
    ref_status st = ref_ode_solve(finite_n_rhs, &q, 2, y0, t, nt, opt, y, msg, msglen);
    if (st == REF_OK)
        for (size_t m = 0; m < nt; m++)
            T_out[m] = p->mass / (3.0 * n) * (y[2 * m] - y[2 * m + 1] / n);
    free(y);
    return st;
}

double ref_background_hs_E1(const ref_background_params *p, const double v[3])
{
    if (!valid(p) || !v || !isfinite(v[0]) || !isfinite(v[1]) || !isfinite(v[2]))
        return NAN;
    const double a = sqrt(dist2(v, p->bg_velocity));
    const double b = sqrt(2.0 * p->bg_temperature / p->bg_mass);
    const double scale = 4.0 * PI * p->C1 * p->bg_density;
    if (a < 1e-8 * b)   /* the limit a -> 0; the next term is O(a^2/b) */
        return scale * 2.0 * b / sqrt(PI);
    return scale * (b / sqrt(PI) * exp(-a * a / (b * b))
                    + (2.0 * a * a + b * b) / (2.0 * a) * erf(a / b));
}

double ref_background_hs_E1_majorant(const ref_background_params *p, const double v[3])
{
    if (!valid(p) || !v || !isfinite(v[0]) || !isfinite(v[1]) || !isfinite(v[2]))
        return NAN;
    const double a = sqrt(dist2(v, p->bg_velocity));
    const double b = sqrt(2.0 * p->bg_temperature / p->bg_mass);
    return p->C1 * p->bg_density * (4.0 * PI * a + 8.0 * sqrt(PI) * b);
}

/* ---------------------------------------------------------------- hard-sphere closures */

/* Parameters of (B.21)/(B.22) in physical time (see background.h): the background
 * terms are multiplied by rate_bg = rho_B C1, the grain-grain terms (those with K)
 * by rate_gg = rho C2 in place of K rho_B C1. */
typedef struct hs_rhs_params {
    ref_background_closure closure;
    double rate_bg, rate_gg;
    double alpha, beta, m, T_B;
    double u_B[3];
} hs_rhs_params;

static hs_rhs_params hs_params(const ref_background_params *p, ref_background_closure c)
{
    hs_rhs_params q = {c,
                       p->bg_density * p->C1,
                       p->density * p->C2,
                       mass_ratio(p),
                       (1.0 - p->restitution) / 2.0,
                       p->mass,
                       p->bg_temperature,
                       {p->bg_velocity[0], p->bg_velocity[1], p->bg_velocity[2]}};
    return q;
}

/* Local equilibrium, (B.21), scaled time: du/dt = U (u - u_B) and dT/dt = E - K L;
 * *U, *E and *L are returned.  S = (1-alpha) T_B + alpha T, w = S/(alpha m).
 * The last bracket alpha - alpha T/S is written alpha (1-alpha)(T_B - T)/S (the
 * same number, exactly 0 at T = T_B). */
static void le_terms(const hs_rhs_params *q, double T, double du2, double *U, double *E, double *L)
{
    double a = q->alpha, m = q->m;
    double S = (1.0 - a) * q->T_B + a * T, w = S / (a * m), r = sqrt(a * m / S);
    double x = a * T / S; /* alpha T / S */
    *U = -a * (16.0 / 3.0) * sqrt(2.0 * PI) * r * (du2 / 5.0 + 2.0 * w);
    *E = a * (8.0 / 3.0) * m * sqrt(2.0 * PI) * r
         * ((a + x / 3.0) * du2 * du2 / 5.0 + 4.0 * w * (a - x / 3.0) * du2
            + 8.0 * w * w * (a * (1.0 - a) * (q->T_B - T) / S));
    double Tm = T / m;
    *L = (64.0 / 3.0) * sqrt(PI) * m * q->beta * (1.0 - q->beta) * Tm * sqrt(Tm);
}

/* Grad, (B.22), scaled time, in the same form as le_terms. */
static void grad_terms(const hs_rhs_params *q, double T, double du2, double *U, double *E, double *L)
{
    double a = q->alpha, m = q->m, TB = q->T_B;
    double k = sqrt(a) * (32.0 / 3.0) * sqrt(PI) * sqrt(2.0 * TB / m);
    *U = -k;
    *E = -2.0 * k * ((1.0 - a) * (T - TB) - a * m * du2 / 3.0);
    double b = (m / TB) * du2 + 3.0 * (T - TB) / TB, TBm = TB / m;
    *L = (4.0 / 3.0) * sqrt(PI) * m * q->beta * (1.0 - q->beta)
         * (b * b / 3.0 + 8.0 * (3.0 * T - TB) / TB) * TBm * sqrt(TBm);
}

static void hs_terms(const hs_rhs_params *q, double T, double du2, double *U, double *E, double *L)
{
    if (q->closure == REF_BACKGROUND_LE)
        le_terms(q, T, du2, U, E, L);
    else
        grad_terms(q, T, du2, U, E, L);
}

static int hs_rhs(double t, const double *y, double *ydot, void *params)
{
    const hs_rhs_params *q = params;
    (void)t;
    if (q->closure == REF_BACKGROUND_LE && !(y[3] > 0.0))
        return 1; /* a trial step overshot to T <= 0 (sqrt T): recoverable, CVODE cuts the step */
    double U, E, L;
    hs_terms(q, y[3], dist2(y, q->u_B), &U, &E, &L);
    for (int i = 0; i < 3; i++)
        ydot[i] = q->rate_bg * U * (y[i] - q->u_B[i]);
    ydot[3] = q->rate_bg * E - q->rate_gg * L;
    return 0;
}

static int bad_closure(ref_background_closure c, char *buf, size_t len)
{
    if (c != REF_BACKGROUND_LE && c != REF_BACKGROUND_GRAD)
        return ref_say(buf, len, "closure = %d is not REF_BACKGROUND_LE or REF_BACKGROUND_GRAD", (int)c);
    return 0;
}

ref_status ref_background_hs(const ref_background_params *p, ref_background_closure c,
                             const double *t, size_t nt, const ref_ode_options *opt,
                             double *u_out, double *T_out, char *msg, size_t msglen)
{
    if (bad_params(p, msg, msglen) || bad_closure(c, msg, msglen)
        || ref_bad_times(t, nt, msg, msglen))
        return REF_EINVAL;
    if (!T_out) {
        ref_say(msg, msglen, "T_out is NULL");
        return REF_EINVAL;
    }
    hs_rhs_params q = hs_params(p, c);
    return solve_4(hs_rhs, &q, p, t, nt, opt, u_out, T_out, msg, msglen);
}

/* dT/dt at u = u_B divided by rho_B C1 (the root does not depend on the time scale). */
static double hs_steady_fn(double T, void *params)
{
    const hs_rhs_params *q = params;
    double U, E, L;
    hs_terms(q, T, 0.0, &U, &E, &L);
    return E - (q->rate_gg / q->rate_bg) * L;
}

double ref_background_hs_T_steady(const ref_background_params *p, ref_background_closure c)
{
    if (!valid(p) || bad_closure(c, NULL, 0))
        return NAN;
    hs_rhs_params q = hs_params(p, c);
    double lo = 0.0, hi = q.T_B;
    double f_lo = hs_steady_fn(lo, &q), f_hi = hs_steady_fn(hi, &q);
    if (f_hi == 0.0) /* no inelastic loss (C2 = 0 or e = 1): the background's temperature */
        return hi;
    /* Check the bracket here so that gsl_root_fsolver_set never calls GSL's error handler. */
    if (!(isfinite(f_lo) && isfinite(f_hi) && f_lo > 0.0 && f_hi < 0.0))
        return NAN;
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s)
        return NAN;
    gsl_function F = {hs_steady_fn, &q};
    double root = NAN;
    if (gsl_root_fsolver_set(s, &F, lo, hi) == GSL_SUCCESS) {
        for (int iter = 0; iter < 200; iter++) {
            if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS)
                break;
            double a = gsl_root_fsolver_x_lower(s), b = gsl_root_fsolver_x_upper(s);
            if (gsl_root_test_interval(a, b, 0.0, 1e-14) == GSL_SUCCESS || a == b) {
                root = gsl_root_fsolver_root(s);
                break;
            }
        }
    }
    gsl_root_fsolver_free(s);
    return root;
}
