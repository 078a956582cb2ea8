/* Unit tests of the reference/ layer, first part: the CVODE adapter (ode.h),
 * paper A's references (heated.h) and the Sonine formula (C.10) (sonine.h).
 * Every known answer names its source: a docs/theory.md section or a paper's equation. */
#include "test_reference_util.h"

#include <stdlib.h>
#include <string.h>

#include "heated.h"
#include "ode.h"
#include "sonine.h"

#define NT 81 /* output times 0, 0.1, ..., 8 (paper A Ex 3-4: interval [0, 8]) */

static const double PI = 3.14159265358979323846;

/* Paper A Ex 3 (docs/theory.md §11.1): lambda = 0, alpha = 1/2, beta = 1, gamma = 4,
 * C0 = 1/(4 pi), T0 = 1. */
static ref_heated_params ex3(void)
{
    ref_heated_params p = {0.5, 1.0, 4.0, 1.0 / (4.0 * PI), 1.0};
    return p;
}

/* Paper A Ex 4: as Ex 3 with beta = 1/8.  Ex 5 (hard spheres) has the same numbers. */
static ref_heated_params ex4(void)
{
    ref_heated_params p = ex3();
    p.beta = 0.125;
    return p;
}

/* ---------------------------------------------------------------- closed form (A.13-14) */

static void test_maxwell_closed_form(void **state)
{
    (void)state;
    ref_heated_params p3 = ex3(), p4 = ex4();
    /* docs/theory.md §11.1: k = gamma pi C0 (1 - alpha^2) = 4 pi/(4 pi) 3/4 = 3/4,
     * T_inf = 2 beta/k. */
    assert_close(ref_heated_maxwell_rate(&p3), 0.75, 1e-15, 0);
    assert_close(ref_heated_maxwell_T_inf(&p3), 8.0 / 3.0, 1e-15, 0);
    assert_close(ref_heated_maxwell_T_inf(&p4), 1.0 / 3.0, 1e-15, 0);
    /* At t = (4/3) ln 2, e^{-kt} = 1/2: Ex 3 T = 1/2 + (8/3)/2 = 11/6, Ex 4 T = 1/2 + 1/6 = 2/3.
     * At t = (4/3) ln 4, e^{-kt} = 1/4: Ex 3 T = 1/4 + 2 = 9/4,      Ex 4 T = 1/4 + 1/4 = 1/2. */
    double t2 = 4.0 / 3.0 * log(2.0), t4 = 4.0 / 3.0 * log(4.0);
    assert_close(ref_heated_maxwell_T(&p3, 0.0), 1.0, 1e-15, 0);
    assert_close(ref_heated_maxwell_T(&p3, t2), 11.0 / 6.0, 1e-14, 0);
    assert_close(ref_heated_maxwell_T(&p3, t4), 9.0 / 4.0, 1e-14, 0);
    assert_close(ref_heated_maxwell_T(&p4, t2), 2.0 / 3.0, 1e-14, 0);
    assert_close(ref_heated_maxwell_T(&p4, t4), 0.5, 1e-14, 0);
    /* A.13 by hand at high-entropy times, and the approach to T_inf at t = 8 and 60. */
    const double ts[] = {0.0137, 0.385, 2.385, 5.71, 8.0};
    for (size_t i = 0; i < sizeof ts / sizeof ts[0]; i++) {
        double e = exp(-0.75 * ts[i]);
        assert_close(ref_heated_maxwell_T(&p3, ts[i]), e + 8.0 / 3.0 * (1.0 - e), 1e-14, 0);
        assert_close(ref_heated_maxwell_T(&p4, ts[i]), e + 1.0 / 3.0 * (1.0 - e), 1e-14, 0);
    }
    assert_close(ref_heated_maxwell_T(&p3, 60.0), 8.0 / 3.0, 1e-15, 0);
    /* Other parameters: alpha = 0.8, beta = 0.3, gamma = 2.5, C0 = 0.7, T0 = 2.385:
     * k = 2.5 pi 0.7 0.36 = 0.63 pi, T_inf = 0.6/(0.63 pi). */
    ref_heated_params q = {0.8, 0.3, 2.5, 0.7, 2.385};
    double k = 0.63 * PI, e = exp(-k * 1.7);
    assert_close(ref_heated_maxwell_rate(&q), k, 1e-14, 0);
    assert_close(ref_heated_maxwell_T(&q, 1.7), 2.385 * e + 0.6 / k * (1.0 - e), 1e-14, 0);
    /* Elastic limit alpha = 1: k = 0, dT/dt = 2 beta: T = T0 + 2 beta t = 2.385 + 2.4. */
    q.alpha = 1.0;
    assert_close(ref_heated_maxwell_rate(&q), 0.0, 0, 0);
    assert_true(isinf(ref_heated_maxwell_T_inf(&q)));
    assert_close(ref_heated_maxwell_T(&q, 4.0), 4.785, 1e-15, 0);
}

/* ---------------------------------------------------------------- CVODE adapter */

static int rhs_linear(double t, const double *y, double *ydot, void *params)
{
    const ref_heated_params *p = params; /* dT/dt = 2 beta - k T (A.13's ODE) */
    (void)t;
    ydot[0] = 2.0 * p->beta - ref_heated_maxwell_rate(p) * y[0];
    return 0;
}

/* CVODE on dT/dt = 2 beta - k T agrees with (A.13) to the solver tolerance,
 * rtol = 1e-10 -> 1e-8 relative, at 81 times in [0, 8], for BDF and Adams. */
static void check_cvode_vs_closed_form(ref_ode_method method)
{
    ref_heated_params ps[2] = {ex3(), ex4()};
    double t[NT], T[NT];
    char msg[256] = "x";
    grid(t, NT, 8.0);
    for (int i = 0; i < 2; i++) {
        ref_ode_options o = opts(method, 1e-10, 1e-12);
        ref_status st = ref_ode_solve(rhs_linear, &ps[i], 1, &ps[i].T0, t, NT, &o, T, msg, sizeof msg);
        assert_int_equal(st, REF_OK);
        assert_string_equal(msg, "");
        for (size_t m = 0; m < NT; m++)
            assert_close(T[m], ref_heated_maxwell_T(&ps[i], t[m]), 1e-8, 0);
    }
}

static void test_cvode_bdf_vs_closed_form(void **state)
{
    (void)state;
    check_cvode_vs_closed_form(REF_ODE_BDF);
}

static void test_cvode_adams_vs_closed_form(void **state)
{
    (void)state;
    check_cvode_vs_closed_form(REF_ODE_ADAMS);
}

/* The tolerances are honoured: a loose rtol gives a visibly larger error than a
 * tight one (so the options reach CVODE). */
static void test_cvode_tolerance_matters(void **state)
{
    (void)state;
    ref_heated_params p = ex3();
    double t[NT], T[NT], err_loose = 0, err_tight = 0;
    grid(t, NT, 8.0);
    ref_ode_options loose = opts(REF_ODE_BDF, 1e-4, 1e-6), tight = opts(REF_ODE_BDF, 1e-10, 1e-12);
    assert_int_equal(ref_ode_solve(rhs_linear, &p, 1, &p.T0, t, NT, &loose, T, NULL, 0), REF_OK);
    for (size_t m = 0; m < NT; m++)
        err_loose = fmax(err_loose, fabs(T[m] / ref_heated_maxwell_T(&p, t[m]) - 1));
    assert_int_equal(ref_ode_solve(rhs_linear, &p, 1, &p.T0, t, NT, &tight, T, NULL, 0), REF_OK);
    for (size_t m = 0; m < NT; m++)
        err_tight = fmax(err_tight, fabs(T[m] / ref_heated_maxwell_T(&p, t[m]) - 1));
    assert_true(err_loose > 1e-7 && err_loose < 1e-2);
    assert_true(err_tight < 1e-8 && err_tight < 1e-3 * err_loose);
}

static int rhs_rotation(double t, const double *y, double *ydot, void *params)
{
    double w = *(const double *)params; /* y1' = -w y2, y2' = w y1 */
    (void)t;
    ydot[0] = -w * y[1];
    ydot[1] = w * y[0];
    return 0;
}

/* Dimension 2: rotation with omega = 2.385, y(0) = (1.3, -0.7); exact
 * y1 = A cos wt - B sin wt, y2 = A sin wt + B cos wt (A, B = y(0)), checked
 * at 17 times on [0.25, 5.35] (about two periods) with row-major y_out. */
static void test_cvode_two_dimensional(void **state)
{
    (void)state;
    enum { N = 17 };
    double w = 2.385, y0[2] = {1.3, -0.7}, t[N], y[2 * N];
    for (size_t m = 0; m < N; m++)
        t[m] = 0.25 + 5.1 * (double)m / (N - 1);
    for (int method = 0; method < 2; method++) {
        ref_ode_options o = opts(method ? REF_ODE_ADAMS : REF_ODE_BDF, 1e-11, 1e-13);
        char msg[256];
        assert_int_equal(ref_ode_solve(rhs_rotation, &w, 2, y0, t, N, &o, y, msg, sizeof msg), REF_OK);
        for (size_t m = 0; m < N; m++) {
            double c = cos(w * (t[m] - t[0])), s = sin(w * (t[m] - t[0]));
            assert_close(y[2 * m], 1.3 * c + 0.7 * s, 0, 2e-8);
            assert_close(y[2 * m + 1], 1.3 * s - 0.7 * c, 0, 2e-8);
        }
    }
}

/* nout = 1 returns y0 without integrating; opt = NULL means the defaults. */
static void test_cvode_single_output_and_defaults(void **state)
{
    (void)state;
    ref_ode_options d = ref_ode_default_options();
    assert_int_equal(d.method, REF_ODE_BDF); /* ode.h: BDF, 1e-10, 1e-12, 100000 */
    assert_close(d.rtol, 1e-10, 0, 0);
    assert_close(d.atol, 1e-12, 0, 0);
    assert_int_equal(d.max_steps, 100000);
    double w = 0.9, y0[2] = {0.37, 2.1}, t0 = 1.5, y[2];
    assert_int_equal(ref_ode_solve(rhs_rotation, &w, 2, y0, &t0, 1, NULL, y, NULL, 0), REF_OK);
    assert_close(y[0], 0.37, 0, 0);
    assert_close(y[1], 2.1, 0, 0);
    ref_heated_params p = ex4();
    double t[3] = {0.0, 1.1, 3.3}, T[3];
    assert_int_equal(ref_ode_solve(rhs_linear, &p, 1, &p.T0, t, 3, NULL, T, NULL, 0), REF_OK);
    assert_close(T[2], ref_heated_maxwell_T(&p, 3.3), 1e-8, 0);
}

/* ---------------------------------------------------------------- exact finite-n expectations */

typedef struct moment_params {
    double n, beta, k;
} moment_params;

/* Independent derivation (of docs/theory.md §11.2): S = Σ|v_i|^2, P2 = |Σ v_i|^2.  Heating adds
 * variance 2 beta per component and particle: dE[S]/dt = 6 n beta, and the total
 * momentum is a sum of n such walks: dE[P2]/dt = 6 n beta.  Collisions keep P and
 * remove k Σ|v_i - V|^2 = k (S - P2/n) on average. */
static int rhs_moments(double t, const double *y, double *ydot, void *params)
{
    const moment_params *q = params;
    (void)t;
    ydot[0] = 6.0 * q->n * q->beta - q->k * (y[0] - y[1] / q->n);
    ydot[1] = 6.0 * q->n * q->beta;
    return 0;
}

static void test_finite_n_expectations(void **state)
{
    (void)state;
    ref_heated_params p = ex3();
    double n = 64.0, T0 = p.T0;
    /* t = 0: E T_raw = T0 and E T_centred = (1 - 1/n) T0 (i.i.d. Maxwellian samples). */
    assert_close(ref_heated_maxwell_T_raw_mean(&p, n, 0.0), T0, 1e-15, 0);
    assert_close(ref_heated_maxwell_T_centred_mean(&p, n, 0.0), 63.0 / 64.0 * T0, 1e-15, 0);
    /* By hand at t = (4/3) ln 2 (T = 11/6, Ex 3), n = 64: T_raw = 11/6 + (1 + (8/3) ln 2 - 11/6)/64. */
    double t2 = 4.0 / 3.0 * log(2.0);
    assert_close(ref_heated_maxwell_T_raw_mean(&p, n, t2),
                 11.0 / 6.0 + (1.0 + 8.0 / 3.0 * log(2.0) - 11.0 / 6.0) / 64.0, 1e-14, 0);
    assert_close(ref_heated_maxwell_T_centred_mean(&p, n, t2), 63.0 / 64.0 * 11.0 / 6.0, 1e-14, 0);
    /* n -> infinity: both approach T(t). */
    for (double t = 0.0; t <= 8.0; t += 0.37) {
        assert_close(ref_heated_maxwell_T_raw_mean(&p, 1e12, t), ref_heated_maxwell_T(&p, t), 1e-11, 0);
        assert_close(ref_heated_maxwell_T_centred_mean(&p, 1e12, t), ref_heated_maxwell_T(&p, t), 1e-11, 0);
    }
    /* n = 1: no collision partner, T_raw is pure heating T0 + 2 beta t; T_centred = 0. */
    assert_close(ref_heated_maxwell_T_raw_mean(&p, 1.0, 2.385), 1.0 + 2.0 * 2.385, 1e-15, 0);
    assert_close(ref_heated_maxwell_T_centred_mean(&p, 1.0, 2.385), 0.0, 0, 1e-15);

    /* Against the moment ODEs integrated by CVODE, S(0) = P2(0) = 3 n T0, for
     * Ex 3, Ex 4 and a high-entropy case; E[S]/(3n) = E T_raw and
     * E[S - P2/n]/(3n) = E T_centred at 81 times in [0, 8]. */
    ref_heated_params cases[3] = {ex3(), ex4(), {0.37, 0.45, 1.7, 0.21, 2.385}};
    double ns[3] = {64.0, 256.0, 5.0};
    double t[NT], y[2 * NT];
    grid(t, NT, 8.0);
    for (int c = 0; c < 3; c++) {
        moment_params q = {ns[c], cases[c].beta, ref_heated_maxwell_rate(&cases[c])};
        double y0[2] = {3.0 * q.n * cases[c].T0, 3.0 * q.n * cases[c].T0};
        ref_ode_options o = opts(REF_ODE_BDF, 1e-11, 1e-12);
        char msg[256];
        assert_int_equal(ref_ode_solve(rhs_moments, &q, 2, y0, t, NT, &o, y, msg, sizeof msg), REF_OK);
        for (size_t m = 0; m < NT; m++) {
            double S = y[2 * m], P2 = y[2 * m + 1];
            assert_close(S / (3.0 * q.n), ref_heated_maxwell_T_raw_mean(&cases[c], q.n, t[m]), 1e-8, 0);
            assert_close((S - P2 / q.n) / (3.0 * q.n),
                         ref_heated_maxwell_T_centred_mean(&cases[c], q.n, t[m]), 1e-8, 0);
        }
    }
}

/* ---------------------------------------------------------------- hard-sphere closures (Ex 5) */

static void test_hs_steady_closed_form(void **state)
{
    (void)state;
    ref_heated_params p = ex4(); /* paper A Ex 5: alpha = 1/2, beta = 0.125, gamma = 4, C1 = 1/(4 pi) */
    /* Maxwellian closure: T* = (2 beta / (gamma (1-alpha^2)/24 4 pi C1 32/sqrt(pi)))^{2/3}
     *   = (0.25 / (4*0.75/24 * 32/sqrt(pi)))^{2/3} = (sqrt(pi)/16)^{2/3}
     *   = pi^{1/3} / 2^{8/3} = 0.23065876858050355. */
    double Tm = ref_heated_hs_T_steady(&p, REF_HEATED_MAXWELLIAN_CLOSURE);
    assert_close(Tm, cbrt(PI) / pow(2.0, 8.0 / 3.0), 1e-14, 0);
    assert_close(Tm, 0.23065876858050355, 1e-14, 0);
    /* Sonine closure: loss times 1 + 3 a2/16 with a2(1/2, d = 3) = 0.0256 (C.10), so
     * T* is lower by (1 + 3*0.0256/16)^{-2/3} = 1.0048^{-2/3}: 0.2299236004114194. */
    double Ts = ref_heated_hs_T_steady(&p, REF_HEATED_SONINE_CLOSURE);
    assert_close(Ts, Tm * pow(1.0048, -2.0 / 3.0), 1e-14, 0);
    assert_close(Ts, 0.2299236004114194, 1e-14, 0);
    assert_true(Ts < Tm);
    /* No heating: steady state T* = 0; elastic and heated: no steady state. */
    p.beta = 0.0;
    assert_close(ref_heated_hs_T_steady(&p, REF_HEATED_MAXWELLIAN_CLOSURE), 0.0, 0, 0);
    p.beta = 0.125;
    p.alpha = 1.0;
    assert_true(isinf(ref_heated_hs_T_steady(&p, REF_HEATED_SONINE_CLOSURE)));
}

/* The VHS Maxwellian closure is the hard-sphere one at lambda = 1 and paper A's
 * exact T_inf = 2 beta/k (A.14) for Maxwell molecules at lambda = 0; in between
 * it follows <|g|^(2+lambda)> = 4^(1+lambda/2) Gamma((5+lambda)/2)/Gamma(3/2) T^(1+lambda/2):
 * at lambda = 1/2 with Ex 5's parameters, 2 beta = 0.25 = (3/24) 4^(1.25)
 * Gamma(2.75)/Gamma(1.5) T^1.25, Gamma(2.75)/Gamma(1.5) = 1.8148393, so T* =
 * (0.25/(0.125 * 5.6568542 * 1.8148393))^(0.8) = 0.27020. */
static void test_vhs_maxwellian_closure(void **state)
{
    (void)state;
    ref_heated_params p = ex4();
    assert_close(ref_heated_vhs_T_steady_maxwellian(&p, 1.0),
                 ref_heated_hs_T_steady(&p, REF_HEATED_MAXWELLIAN_CLOSURE), 1e-14, 0);
    assert_close(ref_heated_vhs_T_steady_maxwellian(&p, 0.0), ref_heated_maxwell_T_inf(&p),
                 1e-14, 0);
    const double g = tgamma(2.75) / tgamma(1.5);
    assert_close(g, 1.8148393, 1e-7, 0);
    assert_close(ref_heated_vhs_T_steady_maxwellian(&p, 0.5),
                 pow(0.25 / (0.125 * pow(4.0, 1.25) * g), 0.8), 1e-14, 0);
    assert_close(ref_heated_vhs_T_steady_maxwellian(&p, 0.5), 0.27020, 1e-4, 0);
    assert_true(isnan(ref_heated_vhs_T_steady_maxwellian(&p, 1.5)));
    assert_true(isnan(ref_heated_vhs_T_steady_maxwellian(NULL, 0.5)));
}

/* The heated tail's amplitude (docs/theory.md §11.5, "The heated tail"): paper A's
 * Ex 6-8 parameters (beta = 30, gamma = 16, C = 1/(4 pi)) give a = sqrt(16/30)/b
 * in absolute speed; for hard spheres it is paper C's Eq. (36) (2/3) sqrt(6 pi/mu2)
 * when beta is the one the steady energy balance gives for mu2 and T: 2 beta =
 * gamma pi C (1 - alpha^2) <|g|^3>/6, <|g|^3> = 8 mu2 (2T)^(3/2)/(pi (1 - alpha^2)). */
static void test_heated_tail_amplitude(void **state)
{
    (void)state;
    ref_heated_params p = {.alpha = 0.1, .beta = 30.0, .gamma = 16.0, .C = 0.25 / M_PI,
                           .T0 = 1.0};
    const double T = 15.0;
    assert_close(ref_heated_tail_A(&p, 0.0, T), sqrt(16.0 / 30.0) * sqrt(2.0 * T), 1e-14, 0);
    assert_close(ref_heated_tail_A(&p, 0.5, T), sqrt(16.0 / 30.0) / 1.25 * pow(2.0 * T, 0.625),
                 1e-14, 0);
    const double mu2 = 2.385, Ths = 2.9;
    p.beta = 2.0 / 3.0 * p.gamma * p.C * mu2 * pow(2.0 * Ths, 1.5);
    assert_close(ref_heated_tail_A(&p, 1.0, Ths), ref_sonine_tail_A_white_noise_mu2(mu2, 3.0),
                 1e-13, 0);
    assert_true(isnan(ref_heated_tail_A(&p, 1.5, T)));
    assert_true(isnan(ref_heated_tail_A(&p, 1.0, 0.0)));
    p.beta = 0.0;
    assert_true(isnan(ref_heated_tail_A(&p, 1.0, T)));
    assert_true(isnan(ref_heated_tail_A(NULL, 1.0, T)));
}

/* Integrated closures relax to the closed-form T* (t in [0, 40], rate ~1.6) and
 * start at T0; both closures and both methods. */
static void test_hs_closure_reaches_steady_state(void **state)
{
    (void)state;
    ref_heated_params p = ex4();
    double t[NT], T[NT];
    grid(t, NT, 40.0);
    for (int c = 0; c < 2; c++) {
        ref_heated_closure cl = c ? REF_HEATED_SONINE_CLOSURE : REF_HEATED_MAXWELLIAN_CLOSURE;
        for (int method = 0; method < 2; method++) {
            ref_ode_options o = opts(method ? REF_ODE_ADAMS : REF_ODE_BDF, 1e-10, 1e-12);
            char msg[256];
            assert_int_equal(ref_heated_hs_T(&p, cl, t, NT, &o, T, msg, sizeof msg), REF_OK);
            assert_close(T[0], p.T0, 0, 0);
            assert_close(T[NT - 1], ref_heated_hs_T_steady(&p, cl), 1e-8, 0);
            for (size_t m = 1; m < NT; m++) /* T0 = 1 > T*: monotone decay (to solver noise) */
                assert_true(T[m] <= T[m - 1] * (1 + 1e-9) && T[m] >= T[NT - 1] * (1 - 1e-9));
        }
    }
}

/* Free cooling (beta = 0, Haff's law): dT/dt = -L T^{3/2} has the exact solution
 * T(t) = T0 / (1 + L sqrt(T0) t / 2)^2.  With Ex 5's alpha, gamma, C1 the
 * Maxwellian L = 4*0.75/24 * 32/sqrt(pi) = 4/sqrt(pi); Sonine L = 4/sqrt(pi) * 1.0048. */
static void test_hs_closure_haff_law(void **state)
{
    (void)state;
    ref_heated_params p = ex4();
    p.beta = 0.0;
    p.T0 = 2.385;
    double t[NT], T[NT];
    grid(t, NT, 8.0);
    for (int c = 0; c < 2; c++) {
        double L = 4.0 / sqrt(PI) * (c ? 1.0048 : 1.0);
        char msg[256];
        assert_int_equal(ref_heated_hs_T(&p, c ? REF_HEATED_SONINE_CLOSURE : REF_HEATED_MAXWELLIAN_CLOSURE,
                                         t, NT, NULL, T, msg, sizeof msg),
                         REF_OK);
        for (size_t m = 0; m < NT; m++) {
            double x = 1.0 + L * sqrt(2.385) * t[m] / 2.0;
            assert_close(T[m], 2.385 / (x * x), 1e-8, 0);
        }
    }
}

/* ---------------------------------------------------------------- Sonine a2, (C.10) */

static void test_sonine_a2_white_noise(void **state)
{
    (void)state;
    /* Elastic limit: a2 = 0 (factor 1 - a). */
    assert_close(ref_sonine_a2_white_noise(1.0, 3.0), 0.0, 0, 0);
    assert_close(ref_sonine_a2_white_noise(1.0, 2.0), 0.0, 0, 0);
    /* docs/theory.md §13.3: sign change at alpha = 1/sqrt(2) (factor 1 - 2a^2). */
    for (double d = 2.0; d <= 3.0; d += 1.0) {
        assert_close(ref_sonine_a2_white_noise(1.0 / sqrt(2.0), d), 0.0, 0, 1e-16);
        assert_true(ref_sonine_a2_white_noise(0.7, d) > 0.0);
        assert_true(ref_sonine_a2_white_noise(0.72, d) < 0.0);
    }
    /* d = 3, alpha = 0.5: 16*0.5*0.5 / (73 + 168 - 1.5*59 + 30*0.5*0.25) = 4/156.25 = 0.0256. */
    assert_close(ref_sonine_a2_white_noise(0.5, 3.0), 0.0256, 1e-14, 0);
    /* d = 3, alpha = 0.3: 16*0.7*0.82 / (241 - 0.9*59 + 30*0.7*0.09) = 9.184/189.79. */
    assert_close(ref_sonine_a2_white_noise(0.3, 3.0), 9.184 / 189.79, 1e-14, 0);
    /* d = 2, alpha = 0.5: 4 / (73 + 112 - 1.5*(35 + 16) + 3.75) = 4/112.25 = 16/449. */
    assert_close(ref_sonine_a2_white_noise(0.5, 2.0), 16.0 / 449.0, 1e-14, 0);
    /* d = 3 agrees with van Noije-Ernst's 16(1-a)(1-2a^2)/(241 - 177a + 30a^2(1-a)). */
    for (double a = 0.0; a <= 1.0; a += 0.0625)
        assert_close(ref_sonine_a2_white_noise(a, 3.0),
                     16 * (1 - a) * (1 - 2 * a * a) / (241 - 177 * a + 30 * a * a * (1 - a)), 1e-14,
                     1e-17);
}

/* ---------------------------------------------------------------- traps */

static void test_trap_strerror(void **state)
{
    (void)state;
    const ref_status all[] = {REF_OK, REF_EINVAL, REF_ESOLVER, REF_ENOMEM};
    for (size_t i = 0; i < 4; i++) {
        assert_non_null(ref_strerror(all[i]));
        for (size_t j = 0; j < i; j++)
            assert_string_not_equal(ref_strerror(all[i]), ref_strerror(all[j]));
    }
    assert_string_equal(ref_strerror((ref_status)42), "unknown status");
}

static void test_trap_ode_arguments(void **state)
{
    (void)state;
    ref_heated_params p = ex3();
    double y0 = 1.0, bad_y0 = NAN, t[4] = {0.0, 0.5, 1.0, 2.0}, y[8];
    double t_eq[3] = {0.0, 0.5, 0.5}, t_dec[3] = {0.0, 0.5, 0.25}, t_nan[3] = {0.0, NAN, 1.0};
    ref_ode_options o = ref_ode_default_options();
    char msg[256];
#define SOLVE(f_, dim_, y0_, t_, nout_, opt_, yout_) \
    ref_ode_solve(f_, &p, dim_, y0_, t_, nout_, opt_, yout_, msg, sizeof msg)
    assert_failure(SOLVE(NULL, 1, &y0, t, 4, &o, y), REF_EINVAL, msg, "f is NULL", NULL);
    assert_failure(SOLVE(rhs_linear, 0, &y0, t, 4, &o, y), REF_EINVAL, msg, "dim = 0", "[1, ");
    assert_failure(SOLVE(rhs_linear, 1, &y0, t, 0, &o, y), REF_EINVAL, msg, "nout = 0", NULL);
    assert_failure(SOLVE(rhs_linear, 1, NULL, t, 4, &o, y), REF_EINVAL, msg, "y0 is NULL", NULL);
    assert_failure(SOLVE(rhs_linear, 1, &y0, NULL, 4, &o, y), REF_EINVAL, msg, "t_out is NULL", NULL);
    assert_failure(SOLVE(rhs_linear, 1, &y0, t, 4, &o, NULL), REF_EINVAL, msg, "y_out is NULL", NULL);
    assert_failure(SOLVE(rhs_linear, 1, &bad_y0, t, 4, &o, y), REF_EINVAL, msg, "y0[0] = nan", "finite");
    assert_failure(SOLVE(rhs_linear, 1, &y0, t_eq, 3, &o, y), REF_EINVAL, msg, "t_out[2] = 0.5",
                   "strictly increasing");
    assert_failure(SOLVE(rhs_linear, 1, &y0, t_dec, 3, &o, y), REF_EINVAL, msg, "t_out[2] = 0.25",
                   "strictly increasing");
    assert_failure(SOLVE(rhs_linear, 1, &y0, t_nan, 3, &o, y), REF_EINVAL, msg, "t_out[1] = nan",
                   "not finite");
    const double bad_tol[] = {0.0, -1e-8, NAN, INFINITY};
    const char *bad_txt[] = {"= 0 ", "= -1e-08 ", "= nan ", "= inf "};
    for (size_t i = 0; i < 4; i++) {
        o = ref_ode_default_options();
        o.rtol = bad_tol[i];
        assert_failure(SOLVE(rhs_linear, 1, &y0, t, 4, &o, y), REF_EINVAL, msg, "rtol ", bad_txt[i]);
        assert_non_null(strstr(msg, "> 0"));
        o = ref_ode_default_options();
        o.atol = bad_tol[i];
        assert_failure(SOLVE(rhs_linear, 1, &y0, t, 4, &o, y), REF_EINVAL, msg, "atol ", bad_txt[i]);
    }
    o = ref_ode_default_options();
    o.max_steps = -3;
    assert_failure(SOLVE(rhs_linear, 1, &y0, t, 4, &o, y), REF_EINVAL, msg, "max_steps = -3", ">= 0");
    o = ref_ode_default_options();
    o.method = (ref_ode_method)7;
    assert_failure(SOLVE(rhs_linear, 1, &y0, t, 4, &o, y), REF_EINVAL, msg, "method = 7", NULL);
    /* A NULL message buffer is allowed on failure and on success. */
    assert_int_equal(ref_ode_solve(rhs_linear, &p, 0, &y0, t, 4, NULL, y, NULL, 0), REF_EINVAL);
    assert_int_equal(ref_ode_solve(rhs_linear, &p, 1, &y0, t, 4, NULL, y, NULL, 0), REF_OK);
    /* A short buffer is truncated, never overrun (ASan checks). */
    char tiny[8];
    assert_int_equal(ref_ode_solve(NULL, &p, 1, &y0, t, 4, NULL, y, tiny, sizeof tiny), REF_EINVAL);
    assert_string_equal(tiny, "f is NU");
#undef SOLVE
}

typedef struct failing_rhs {
    double t_fail; /* from this time on the RHS fails */
    int mode;      /* 0: return -1, 1: return NaN, 2: return +1 (recoverable) forever */
    long calls;    /* number of calls */
} failing_rhs;

static int rhs_failing(double t, const double *y, double *ydot, void *params)
{
    failing_rhs *q = params;
    q->calls++;
    ydot[0] = -0.83 * y[0];
    if (t < q->t_fail)
        return 0;
    if (q->mode == 1)
        ydot[0] = NAN;
    return q->mode == 0 ? -1 : q->mode == 2 ? 1 : 0;
}

/* A failing right-hand side gives REF_ESOLVER with the flag name, never a result. */
static void test_trap_rhs_failure(void **state)
{
    (void)state;
    double y0 = 1.7, t[3] = {0.0, 1.0, 2.0}, y[3];
    char msg[512];
    for (int method = 0; method < 2; method++) {
        ref_ode_options o = opts(method ? REF_ODE_ADAMS : REF_ODE_BDF, 1e-9, 1e-12);
        /* Unrecoverable (-1) from t = 0.5 on: BDF stops with CV_RHSFUNC_FAIL; Adams'
         * fixed-point solver in SUNDIALS 6.4.1 reports it as a convergence failure,
         * and the adapter keeps the failure sticky so it also stops within a few
         * calls instead of shrinking the step max_steps (100000) times. */
        failing_rhs unrec = {0.5, 0, 0};
        assert_failure(ref_ode_solve(rhs_failing, &unrec, 1, &y0, t, 3, &o, y, msg, sizeof msg),
                       REF_ESOLVER, msg, method ? ": CV_" : ": CV_RHSFUNC_FAIL",
                       "right-hand side returned -1 at t = 0.5");
        assert_non_null(strstr(msg, "CVODE failed at t = "));
        assert_true(unrec.calls < 1000);
        /* A non-finite ydot is a recoverable failure: CVODE cuts the step until it
         * gives up at t = 0.5 (CV_TOO_MUCH_WORK here), and the message says why. */
        failing_rhs nan_later = {0.5, 1, 0};
        assert_failure(ref_ode_solve(rhs_failing, &nan_later, 1, &y0, t, 3, &o, y, msg, sizeof msg),
                       REF_ESOLVER, msg, ": CV_", "non-finite ydot[0] at t = 0.5");
        assert_close(strtod(strstr(msg, "t = ") + 4, NULL), 0.5, 1e-12, 0);
        failing_rhs nan_first = {-1.0, 1, 0};
        assert_failure(ref_ode_solve(rhs_failing, &nan_first, 1, &y0, t, 3, &o, y, msg, sizeof msg),
                       REF_ESOLVER, msg, "CV_FIRST_RHSFUNC_ERR", "non-finite ydot[0] at t = 0");
        failing_rhs rec = {0.5, 2, 0};
        assert_failure(ref_ode_solve(rhs_failing, &rec, 1, &y0, t, 3, &o, y, msg, sizeof msg),
                       REF_ESOLVER, msg, ": CV_", "right-hand side returned 1 at t = 0.5");
    }
}

static int rhs_square(double t, const double *y, double *ydot, void *params)
{
    (void)t;
    (void)params;
    ydot[0] = y[0] * y[0]; /* y' = y^2, y(0) = 1: y = 1/(1 - t), blows up at t = 1 */
    return 0;
}

/* Blow-up: asking for y past t = 1 fails cleanly with a CVODE flag at a time
 * in (0.5, 1]; up to t = 0.9 the same problem is solved (y = 10). */
static void test_trap_blow_up(void **state)
{
    (void)state;
    double y0 = 1.0, t[3] = {0.0, 0.5, 2.0}, y[3];
    char msg[512];
    for (int method = 0; method < 2; method++) {
        ref_ode_options o = opts(method ? REF_ODE_ADAMS : REF_ODE_BDF, 1e-10, 1e-12);
        ref_status st = ref_ode_solve(rhs_square, NULL, 1, &y0, t, 3, &o, y, msg, sizeof msg);
        assert_failure(st, REF_ESOLVER, msg, "CVODE failed at t = ", ": CV_");
        double t_fail = strtod(strstr(msg, "t = ") + 4, NULL);
        assert_true(t_fail > 0.5 && t_fail <= 1.0);
        double t_ok[2] = {0.0, 0.9};
        assert_int_equal(ref_ode_solve(rhs_square, NULL, 1, &y0, t_ok, 2, &o, y, msg, sizeof msg), REF_OK);
        assert_close(y[1], 10.0, 1e-7, 0);
    }
}

static int rhs_overflow(double t, const double *y, double *ydot, void *params)
{
    (void)t;
    (void)params;
    ydot[0] = 1.5e308; /* y(t) = 1.5e308 t overflows before t = 3 */
    ydot[1] = -0.3 * y[1];
    return 0;
}

/* Overflow: y' = 1.5e308 cannot be represented at t = 3; the call fails with
 * REF_ESOLVER and a CVODE message instead of returning inf. */
static void test_trap_overflow(void **state)
{
    (void)state;
    double y0[2] = {0.0, 1.0}, t[3] = {0.0, 0.5, 3.0}, y[6];
    char msg[512];
    for (int method = 0; method < 2; method++) {
        ref_ode_options o = opts(method ? REF_ODE_ADAMS : REF_ODE_BDF, 1e-10, 1e-12);
        assert_failure(ref_ode_solve(rhs_overflow, NULL, 2, y0, t, 3, &o, y, msg, sizeof msg),
                       REF_ESOLVER, msg, "failed at t = ", ": CV_");
    }
}

static int rhs_stiff(double t, const double *y, double *ydot, void *params)
{
    (void)params;
    ydot[0] = -1000.0 * (y[0] - cos(t)); /* stiff: Adams needs thousands of steps */
    return 0;
}

/* max_steps reaches CVODE: a stiff problem with Adams and 50 steps per interval
 * gives CV_TOO_MUCH_WORK, and so does CVODE's default (500) since Adams is
 * stability-limited to h ~ 2/1000; with 100000 steps Adams finishes, and BDF
 * (dense Newton) finishes within CVODE's default 500. */
static void test_trap_too_much_work(void **state)
{
    (void)state;
    double y0 = 0.0, t[2] = {0.0, 10.0}, y[2];
    char msg[512];
    ref_ode_options o = opts(REF_ODE_ADAMS, 1e-8, 1e-10);
    o.max_steps = 50;
    assert_failure(ref_ode_solve(rhs_stiff, NULL, 1, &y0, t, 2, &o, y, msg, sizeof msg), REF_ESOLVER,
                   msg, "CVODE failed at t = ", "CV_TOO_MUCH_WORK");
    o.max_steps = 0;
    assert_failure(ref_ode_solve(rhs_stiff, NULL, 1, &y0, t, 2, &o, y, msg, sizeof msg), REF_ESOLVER,
                   msg, "CVODE failed at t = ", "CV_TOO_MUCH_WORK");
    for (int method = 0; method < 2; method++) {
        o.method = method ? REF_ODE_ADAMS : REF_ODE_BDF;
        o.max_steps = method ? 100000 : 0;
        assert_int_equal(ref_ode_solve(rhs_stiff, NULL, 1, &y0, t, 2, &o, y, msg, sizeof msg), REF_OK);
        /* Outer solution y ~ cos t + 1e-3 sin t (next term O(1e-6)). */
        assert_close(y[1], cos(10.0) + 1e-3 * sin(10.0), 0, 1e-5);
    }
}

static void test_trap_heated_arguments(void **state)
{
    (void)state;
    double t[3] = {0.0, 1.0, 2.0}, t_dec[3] = {0.0, 1.0, 0.9}, T[3];
    char msg[256];
    struct {
        ref_heated_params p;
        const char *frag;
    } bad[] = {
        {{0.0, 0.125, 4.0, 0.08, 1.0}, "alpha = 0 out of range (0, 1]"},
        {{1.5, 0.125, 4.0, 0.08, 1.0}, "alpha = 1.5 out of range (0, 1]"},
        {{NAN, 0.125, 4.0, 0.08, 1.0}, "alpha = nan"},
        {{0.5, -0.2, 4.0, 0.08, 1.0}, "beta = -0.2 must be finite and >= 0"},
        {{0.5, INFINITY, 4.0, 0.08, 1.0}, "beta = inf"},
        {{0.5, 0.125, 0.0, 0.08, 1.0}, "gamma = 0 must be finite and > 0"},
        {{0.5, 0.125, 4.0, -0.08, 1.0}, "C = -0.08 must be finite and > 0"},
        {{0.5, 0.125, 4.0, NAN, 1.0}, "C = nan"},
        {{0.5, 0.125, 4.0, 0.08, 0.0}, "T0 = 0 must be finite and > 0"},
        {{0.5, 0.125, 4.0, 0.08, INFINITY}, "T0 = inf"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        ref_heated_params *p = &bad[i].p;
        assert_failure(ref_heated_hs_T(p, REF_HEATED_MAXWELLIAN_CLOSURE, t, 3, NULL, T, msg, sizeof msg),
                       REF_EINVAL, msg, bad[i].frag, NULL);
        /* Functions without a status return NaN for bad parameters. */
        assert_true(isnan(ref_heated_maxwell_rate(p)));
        assert_true(isnan(ref_heated_maxwell_T_inf(p)));
        assert_true(isnan(ref_heated_maxwell_T(p, 1.0)));
        assert_true(isnan(ref_heated_maxwell_T_raw_mean(p, 64.0, 1.0)));
        assert_true(isnan(ref_heated_maxwell_T_centred_mean(p, 64.0, 1.0)));
        assert_true(isnan(ref_heated_hs_T_steady(p, REF_HEATED_SONINE_CLOSURE)));
    }
    ref_heated_params p = ex4();
    assert_failure(ref_heated_hs_T(NULL, REF_HEATED_MAXWELLIAN_CLOSURE, t, 3, NULL, T, msg, sizeof msg),
                   REF_EINVAL, msg, "p is NULL", NULL);
    assert_failure(ref_heated_hs_T(&p, (ref_heated_closure)5, t, 3, NULL, T, msg, sizeof msg), REF_EINVAL,
                   msg, "closure = 5", NULL);
    assert_failure(ref_heated_hs_T(&p, REF_HEATED_SONINE_CLOSURE, t, 0, NULL, T, msg, sizeof msg),
                   REF_EINVAL, msg, "nt = 0", NULL);
    assert_failure(ref_heated_hs_T(&p, REF_HEATED_SONINE_CLOSURE, NULL, 3, NULL, T, msg, sizeof msg),
                   REF_EINVAL, msg, "t is NULL", NULL);
    assert_failure(ref_heated_hs_T(&p, REF_HEATED_SONINE_CLOSURE, t, 3, NULL, NULL, msg, sizeof msg),
                   REF_EINVAL, msg, "T_out is NULL", NULL);
    assert_failure(ref_heated_hs_T(&p, REF_HEATED_SONINE_CLOSURE, t_dec, 3, NULL, T, msg, sizeof msg),
                   REF_EINVAL, msg, "t[2] = 0.9", "strictly increasing");
    ref_ode_options o = ref_ode_default_options();
    o.atol = -1.0; /* options are checked by the adapter, named in its words */
    assert_failure(ref_heated_hs_T(&p, REF_HEATED_SONINE_CLOSURE, t, 3, &o, T, msg, sizeof msg),
                   REF_EINVAL, msg, "atol = -1", NULL);
    assert_true(isnan(ref_heated_hs_T_steady(&p, (ref_heated_closure)5)));
    assert_true(isnan(ref_heated_maxwell_T(&p, NAN)));
    assert_true(isnan(ref_heated_maxwell_T_raw_mean(&p, 0.5, 1.0)));
    assert_true(isnan(ref_heated_maxwell_T_centred_mean(&p, INFINITY, 1.0)));
    /* (C.10) outside alpha in [0, 1], d >= 2 finite: NaN. */
    assert_true(isnan(ref_sonine_a2_white_noise(-0.1, 3.0)));
    assert_true(isnan(ref_sonine_a2_white_noise(1.2, 3.0)));
    assert_true(isnan(ref_sonine_a2_white_noise(NAN, 3.0)));
    assert_true(isnan(ref_sonine_a2_white_noise(0.5, 1.0)));
    assert_true(isnan(ref_sonine_a2_white_noise(0.5, INFINITY)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_maxwell_closed_form),
        cmocka_unit_test(test_vhs_maxwellian_closure),
        cmocka_unit_test(test_heated_tail_amplitude),
        cmocka_unit_test(test_cvode_bdf_vs_closed_form),
        cmocka_unit_test(test_cvode_adams_vs_closed_form),
        cmocka_unit_test(test_cvode_tolerance_matters),
        cmocka_unit_test(test_cvode_two_dimensional),
        cmocka_unit_test(test_cvode_single_output_and_defaults),
        cmocka_unit_test(test_finite_n_expectations),
        cmocka_unit_test(test_hs_steady_closed_form),
        cmocka_unit_test(test_hs_closure_reaches_steady_state),
        cmocka_unit_test(test_hs_closure_haff_law),
        cmocka_unit_test(test_sonine_a2_white_noise),
        cmocka_unit_test(test_trap_strerror),
        cmocka_unit_test(test_trap_ode_arguments),
        cmocka_unit_test(test_trap_rhs_failure),
        cmocka_unit_test(test_trap_blow_up),
        cmocka_unit_test(test_trap_overflow),
        cmocka_unit_test(test_trap_too_much_work),
        cmocka_unit_test(test_trap_heated_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
