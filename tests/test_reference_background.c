/* Unit tests of the reference/ layer, paper B (background.h): the Maxwell closed
 * forms (B.14)-(B.18) against the checks of docs/theory.md §12 and against CVODE on (B.13), the
 * hard-sphere closures (B.21)/(B.22) and their steady states, and the traps.
 * Every known answer names its source: a docs/theory.md section or a paper's equation. */
#include "test_reference_util.h"

#include <string.h>

#include <gsl/gsl_integration.h>

#include "background.h"
#include "ode.h"

static const double PI = 3.14159265358979323846;

#define NG 129 /* output times i/128 in [0, 1] (paper B uses i/512; 129 keeps the tests fast) */

/* Paper B Ex 1 (docs/theory.md §12.1): f0 = (M1 + M2)/2 gives u0 = (0, 1, 0), T0 = 8/3;
 * rho_B = m_B = T_B = 1, u_B = 0, C1 = C2 = 1, e = 1/2, m = 1, rho = 1 (alpha = 1/2, Kn = 1). */
static ref_background_params ex1(void)
{
    ref_background_params p = {.mass = 1.0, .bg_density = 1.0, .bg_mass = 1.0,
                               .bg_temperature = 1.0, .bg_velocity = {0.0, 0.0, 0.0},
                               .C1 = 1.0, .density = 1.0, .C2 = 1.0, .restitution = 0.5,
                               .T0 = 8.0 / 3.0, .u0 = {0.0, 1.0, 0.0}};
    return p;
}

/* Paper B Ex 2: f0 Maxwellian u = 0, T = 1; u_B = (0, 1, 0); C2 = 1/8 (Kn = 1/8). */
static ref_background_params ex2(void)
{
    ref_background_params p = ex1();
    p.bg_velocity[1] = 1.0;
    p.u0[1] = 0.0;
    p.T0 = 1.0;
    p.C2 = 0.125;
    return p;
}

/* Paper B Ex 3: Ex 2 with m_B = 1/8 (alpha = 1/9). */
static ref_background_params ex3(void)
{
    ref_background_params p = ex2();
    p.bg_mass = 0.125;
    return p;
}

/* B = C exactly: alpha = 3/8 (m = 5, m_B = 3), Kn (1 - e^2) = 8 alpha^2 = 9/8 with
 * e = 1/2, Kn = C2 = 3/2: B = 8 pi alpha = 3 pi, C = 8 pi (15/64) + pi 9/8 = 3 pi.
 * High-entropy T_B, T0, u_B, u0: |u0 - u_B|^2 = 0.09 + 0.16 + 1.44 = 1.69. */
static ref_background_params b_equals_c(void)
{
    ref_background_params p = {.mass = 5.0, .bg_density = 1.0, .bg_mass = 3.0,
                               .bg_temperature = 1.3, .bg_velocity = {0.2, -0.1, 0.35},
                               .C1 = 1.0, .density = 1.0, .C2 = 1.5, .restitution = 0.5,
                               .T0 = 2.385, .u0 = {0.5, -0.5, 1.55}};
    return p;
}

/* Paper B Ex 4/5 (hard spheres, docs/theory.md §12.3): m = m_B = T_B = rho = rho_B = C1 = 1,
 * e = 1/2, u_B = (0, 1, 0), u0 = 0, T0 = 1, C2 = K. */
static ref_background_params hs_ex(double K)
{
    ref_background_params p = ex2();
    p.C2 = K;
    return p;
}

static void assert_u(const ref_background_params *p, double t, double u0, double u1, double u2,
                     double atol)
{
    double u[3];
    ref_background_maxwell_u(p, t, u);
    assert_close(u[0], u0, 0, atol);
    assert_close(u[1], u1, 0, atol);
    assert_close(u[2], u2, 0, atol);
}

/* ---------------------------------------------------------------- closed forms (B.14-B.18) */

/* Paper B Ex 1, Eqs. (37)-(38): u = (0, 1, 0) e^{-2 pi t},
 * T = (8/3)e^{-11 pi t/4} + (8/11)(1 - e^{-11 pi t/4}) - (8/15)(e^{-4 pi t} - e^{-11 pi t/4}),
 * T* = 8/11; at paper B's 513 output times t_i = i/512. */
static void test_maxwell_ex1(void **state)
{
    (void)state;
    ref_background_params p = ex1();
    assert_close(ref_background_maxwell_T_steady(&p), 8.0 / 11.0, 1e-15, 0);
    assert_close(ref_background_maxwell_T(&p, 0.0), 8.0 / 3.0, 1e-15, 0);
    for (int i = 0; i <= 512; i++) {
        double t = i / 512.0, eC = exp(-11.0 * PI * t / 4.0), eB = exp(-4.0 * PI * t);
        double T = 8.0 / 3.0 * eC + 8.0 / 11.0 * (1.0 - eC) - 8.0 / 15.0 * (eB - eC);
        assert_close(ref_background_maxwell_T(&p, t), T, 1e-14, 0);
        assert_u(&p, t, 0.0, exp(-2.0 * PI * t), 0.0, 1e-15);
    }
    /* Long times: T -> T*, u -> u_B = 0. */
    assert_close(ref_background_maxwell_T(&p, 30.0), 8.0 / 11.0, 1e-15, 0);
    assert_u(&p, 30.0, 0.0, 0.0, 0.0, 1e-60);
}

/* Paper B Ex 2 (docs/theory.md §12.1): C = 67 pi/32, B = 4 pi, T* = 64/67, A/(C - B) = -64/183,
 * T0 = 1, so T = e^{-Ct} + (64/67)(1 - e^{-Ct}) - (64/183)(e^{-4 pi t} - e^{-Ct});
 * u = (0, 1, 0)(1 - e^{-2 pi t}). */
static void test_maxwell_ex2(void **state)
{
    (void)state;
    ref_background_params p = ex2();
    assert_close(ref_background_maxwell_T_steady(&p), 64.0 / 67.0, 1e-15, 0);
    const double C = 67.0 * PI / 32.0;
    for (int i = 0; i <= 512; i++) {
        double t = i / 512.0, eC = exp(-C * t), eB = exp(-4.0 * PI * t);
        double T = eC + 64.0 / 67.0 * (1.0 - eC) - 64.0 / 183.0 * (eB - eC);
        assert_close(ref_background_maxwell_T(&p, t), T, 1e-14, 0);
        assert_u(&p, t, 0.0, 1.0 - exp(-2.0 * PI * t), 0.0, 1e-15);
    }
    /* B > C: A/(C - B) < 0 times e^{-Bt} - e^{-Ct} < 0 is a positive (frictional
     * heating) term, so T decays from T0 = 1 to T* = 64/67 from above. */
    for (int i = 1; i <= 64; i++)
        assert_true(ref_background_maxwell_T(&p, i / 16.0) > 64.0 / 67.0);
}

/* Paper B Ex 3 (docs/theory.md §12.1): alpha = 1/9, B = 8 pi/9, C = 2291 pi/2592, T* = 2048/2291,
 * A/(C - B) = -256/39; u = (0, 1, 0)(1 - e^{-4 pi t/9}).  C - B = -13 pi/2592 is
 * small, so this also exercises B close to C in (B.15). */
static void test_maxwell_ex3(void **state)
{
    (void)state;
    ref_background_params p = ex3();
    assert_close(ref_background_maxwell_T_steady(&p), 2048.0 / 2291.0, 1e-15, 0);
    const double C = 2291.0 * PI / 2592.0, B = 8.0 * PI / 9.0;
    for (int i = 0; i <= 512; i++) {
        double t = i / 512.0, eC = exp(-C * t), eB = exp(-B * t);
        double T = eC + 2048.0 / 2291.0 * (1.0 - eC) - 256.0 / 39.0 * (eB - eC);
        assert_close(ref_background_maxwell_T(&p, t), T, 1e-13, 0);
        assert_u(&p, t, 0.0, 1.0 - exp(-4.0 * PI * t / 9.0), 0.0, 1e-15);
    }
    assert_close(ref_background_maxwell_T(&p, 400.0), 2048.0 / 2291.0, 1e-14, 0);
}

/* (B.16) for B = C: T = T0 e^{-Bt} + (D/B)(1 - e^{-Bt}) + A t e^{-Bt} with, for
 * b_equals_c(), B = 3 pi, D/B = (1 - alpha) T_B = 0.625 * 1.3, and
 * A = (8/3) pi m alpha^2 |du|^2 = (8/3) pi 5 (9/64) 1.69 = 1.875 pi 1.69.
 * As C -> B the (B.15) value tends to it continuously, with T_eps - T_0 linear
 * in eps and no loss of digits even at relative distances 1e-14. */
static void test_maxwell_b_equals_c(void **state)
{
    (void)state;
    ref_background_params p = b_equals_c();
    const double B = 3.0 * PI, A = 1.875 * PI * 1.69, DB = 0.625 * 1.3;
    assert_close(ref_background_maxwell_T_steady(&p), DB, 1e-15, 0);
    const double ts[] = {0.0, 0.0137, 0.1, 0.2385, 0.5, 1.0, 3.7};
    for (size_t i = 0; i < sizeof ts / sizeof ts[0]; i++) {
        double t = ts[i], e = exp(-B * t);
        assert_close(ref_background_maxwell_T(&p, t), 2.385 * e + DB * (1.0 - e) + A * t * e, 1e-14, 0);
    }
    /* Continuity: C2 = 1.5 (1 + eps) moves C off B by pi 0.75 * 1.5 eps. */
    const double t = 0.2385, eps_big = 1e-4;
    double T0 = ref_background_maxwell_T(&p, t);
    ref_background_params q = p;
    q.C2 = 1.5 * (1.0 + eps_big);
    double slope = (ref_background_maxwell_T(&q, t) - T0) / eps_big; /* dT/deps */
    assert_true(fabs(slope) > 1e-3); /* the perturbation is visible: the checks below mean something */
    /* eps = 1e-4 is far enough from B = C for the naive (B.15) to be accurate to ~1e-11. */
    {
        double Kn = q.C2, al = 0.375, Bq = 8 * PI * al;
        double Cq = 8 * PI * al * (1 - al) + PI * Kn * 0.75, Dq = 8 * PI * al * (1 - al) * 1.3;
        double naive = 2.385 * exp(-Cq * t) + Dq / Cq * (1 - exp(-Cq * t))
                       + A / (Cq - Bq) * (exp(-Bq * t) - exp(-Cq * t));
        assert_close(ref_background_maxwell_T(&q, t), naive, 1e-10, 0);
    }
    const double eps[] = {1e-6, 1e-8, 1e-10, 1e-12, 1e-14, -1e-9, -1e-13};
    for (size_t i = 0; i < sizeof eps / sizeof eps[0]; i++) {
        q.C2 = 1.5 * (1.0 + eps[i]);
        double Te = ref_background_maxwell_T(&q, t);
        /* Linear in eps to O(eps^2), to within a few rounding errors of T. */
        assert_close(Te, T0 + slope * eps[i], 0, 1e-3 * fabs(slope * eps[i]) + 4e-16 * T0);
    }
    /* An offset of B from C through the mass ratio (relative 1e-13) changes T by O(1e-13). */
    q = p;
    q.mass = 5.0 * (1.0 + 1e-13);
    assert_close(ref_background_maxwell_T(&q, 1.0), ref_background_maxwell_T(&p, 1.0), 1e-12, 0);
}

/* The scaled time of (B.13)-(B.17) is rho_B C1 t and Kn = rho C2/(rho_B C1):
 * Ex 1's numbers with rho_B = 2, C1 = 0.5 give Ex 1; with rho_B = 1.6, C1 = 1.5
 * (rate 2.4) and rho = 0.8, C2 = 3 (Kn = 1) they give Ex 1 at time 2.4 t. */
static void test_maxwell_time_scale(void **state)
{
    (void)state;
    ref_background_params p = ex1(), q = ex1(), r = ex1();
    q.bg_density = 2.0;
    q.C1 = 0.5;
    r.bg_density = 1.6;
    r.C1 = 1.5;
    r.density = 0.8;
    r.C2 = 3.0;
    for (int i = 0; i <= 64; i++) {
        double t = i / 64.0, u[3], v[3];
        assert_close(ref_background_maxwell_T(&q, t), ref_background_maxwell_T(&p, t), 1e-15, 0);
        assert_close(ref_background_maxwell_T(&r, t), ref_background_maxwell_T(&p, 2.4 * t), 1e-13, 0);
        ref_background_maxwell_u(&r, t, u);
        ref_background_maxwell_u(&p, 2.4 * t, v);
        assert_close(u[1], v[1], 1e-13, 1e-300);
    }
    assert_close(ref_background_maxwell_T_steady(&r), 8.0 / 11.0, 1e-15, 0);
}

/* ---------------------------------------------------------------- CVODE on (B.13) */

/* CVODE (rtol 1e-10, atol 1e-12) on (B.13) agrees with (B.14)-(B.16) at 129 times in
 * [0, 1] to 1e-8 relative (T) and 1e-9 absolute (u), with BDF and Adams, for Ex 1-3,
 * the B = C case and the rescaled Ex 1. */
static void test_maxwell_cvode_vs_closed_form(void **state)
{
    (void)state;
    ref_background_params ps[5] = {ex1(), ex2(), ex3(), b_equals_c(), ex1()};
    ps[4].bg_density = 1.6;
    ps[4].C1 = 1.5;
    ps[4].density = 0.8;
    ps[4].C2 = 3.0;
    double t[NG], u[3 * NG], T[NG];
    grid(t, NG, 1.0);
    for (int method = 0; method < 2; method++) {
        for (int c = 0; c < 5; c++) {
            ref_ode_options o = opts(method ? REF_ODE_ADAMS : REF_ODE_BDF, 1e-10, 1e-12);
            char msg[256] = "x";
            assert_int_equal(ref_background_maxwell_ode(&ps[c], t, NG, &o, u, T, msg, sizeof msg),
                             REF_OK);
            assert_string_equal(msg, "");
            for (size_t m = 0; m < NG; m++) {
                double uc[3];
                ref_background_maxwell_u(&ps[c], t[m], uc);
                assert_close(T[m], ref_background_maxwell_T(&ps[c], t[m]), 1e-8, 0);
                for (int i = 0; i < 3; i++)
                    assert_close(u[3 * m + i], uc[i], 0, 1e-9);
            }
        }
    }
    /* u_out may be NULL; T alone is the same. */
    double T2[NG];
    assert_int_equal(ref_background_maxwell_ode(&ps[0], t, NG, NULL, NULL, T2, NULL, 0), REF_OK);
    for (size_t m = 0; m < NG; m++)
        assert_close(T2[m], ref_background_maxwell_T(&ps[0], t[m]), 1e-8, 0);
}

/* The tolerance reaches CVODE: rtol 1e-4 gives a visibly larger error than rtol 1e-10
 * (so the 1e-8 agreement above is the solver's accuracy, not luck). */
static void test_maxwell_cvode_tolerance_matters(void **state)
{
    (void)state;
    ref_background_params p = ex3();
    double t[NG], u[3 * NG], T[NG], err_loose = 0.0, err_tight = 0.0;
    grid(t, NG, 1.0);
    ref_ode_options loose = opts(REF_ODE_BDF, 1e-4, 1e-6), tight = opts(REF_ODE_BDF, 1e-10, 1e-12);
    assert_int_equal(ref_background_maxwell_ode(&p, t, NG, &loose, u, T, NULL, 0), REF_OK);
    for (size_t m = 0; m < NG; m++)
        err_loose = fmax(err_loose, fabs(T[m] / ref_background_maxwell_T(&p, t[m]) - 1.0));
    assert_int_equal(ref_background_maxwell_ode(&p, t, NG, &tight, u, T, NULL, 0), REF_OK);
    for (size_t m = 0; m < NG; m++)
        err_tight = fmax(err_tight, fabs(T[m] / ref_background_maxwell_T(&p, t[m]) - 1.0));
    assert_true(err_loose > 1e-8 && err_loose < 1e-2);
    assert_true(err_tight < 1e-8 && err_tight < 1e-2 * err_loose);
}

/* ---------------------------------------------------------------- hard-sphere closures */

/* Grad steady state in closed form (independent of the root finder): with u = u_B
 * and x = T/T_B, (B.22) gives -a (x - 1) - c (3x^2 + 18x - 5) = 0 with
 * a = sqrt(alpha)(64/3) sqrt(pi) sqrt(2 T_B/m)(1 - alpha) T_B and
 * c = (4/3) sqrt(pi) Kn m beta (1-beta) (T_B/m)^{3/2}; the root in (0, 1) is
 * x = 2 (5c + a)/((18c + a) + sqrt((18c + a)^2 + 12 c (5c + a))). */
static double grad_steady_quadratic(const ref_background_params *p)
{
    double m = p->mass, TB = p->bg_temperature, al = p->bg_mass / (p->mass + p->bg_mass);
    double be = (1.0 - p->restitution) / 2.0, Kn = p->density * p->C2 / (p->bg_density * p->C1);
    double a = sqrt(al) * 64.0 / 3.0 * sqrt(PI) * sqrt(2.0 * TB / m) * (1.0 - al) * TB;
    double c = 4.0 / 3.0 * sqrt(PI) * Kn * m * be * (1.0 - be) * pow(TB / m, 1.5);
    double b = 18.0 * c + a;
    return TB * 2.0 * (5.0 * c + a) / (b + sqrt(b * b + 12.0 * c * (5.0 * c + a)));
}

/* docs/theory.md §12.3: steady temperatures 0.9557 (LE), 0.9562 (Grad) for K = 1/8 and
 * 0.7428 (LE), 0.7574 (Grad) for K = 1 (paper: 0.956, 0.956, 0.743, 0.757).
 * More digits from an independent bisection (Python, 200 halvings on [0, 1]) of
 * the forms of docs/theory.md §12.3: 0.9557111983467963, 0.956188617760106, 0.7428166454917884,
 * 0.7573504538999856. */
static void test_hs_steady_root(void **state)
{
    (void)state;
    ref_background_params p8 = hs_ex(0.125), p1 = hs_ex(1.0);
    double le8 = ref_background_hs_T_steady(&p8, REF_BACKGROUND_LE);
    double gr8 = ref_background_hs_T_steady(&p8, REF_BACKGROUND_GRAD);
    double le1 = ref_background_hs_T_steady(&p1, REF_BACKGROUND_LE);
    double gr1 = ref_background_hs_T_steady(&p1, REF_BACKGROUND_GRAD);
    assert_close(le8, 0.9557, 0, 5e-5);
    assert_close(gr8, 0.9562, 0, 5e-5);
    assert_close(le1, 0.7428, 0, 5e-5);
    assert_close(gr1, 0.7574, 0, 5e-5);
    assert_close(le8, 0.9557111983467963, 1e-13, 0);
    assert_close(gr8, 0.956188617760106, 1e-13, 0);
    assert_close(le1, 0.7428166454917884, 1e-13, 0);
    assert_close(gr1, 0.7573504538999856, 1e-13, 0);
    /* Grad against its quadratic, also for high-entropy parameters. */
    assert_close(gr8, grad_steady_quadratic(&p8), 1e-13, 0);
    assert_close(gr1, grad_steady_quadratic(&p1), 1e-13, 0);
    ref_background_params q = {.mass = 1.7, .bg_density = 0.9, .bg_mass = 0.6,
                               .bg_temperature = 2.385, .bg_velocity = {0.1, 0.2, 0.3},
                               .C1 = 1.3, .density = 0.45, .C2 = 0.77, .restitution = 0.37,
                               .T0 = 0.5, .u0 = {0.0, 0.0, 0.0}};
    double grq = ref_background_hs_T_steady(&q, REF_BACKGROUND_GRAD);
    assert_close(grq, grad_steady_quadratic(&q), 1e-13, 0);
    double leq = ref_background_hs_T_steady(&q, REF_BACKGROUND_LE);
    assert_true(leq > 0.0 && leq < 2.385 && grq > 0.0 && grq < 2.385);
    /* Loss-free limits: e = 1 or C2 = 0 give T* = T_B for both closures. */
    q.restitution = 1.0;
    assert_close(ref_background_hs_T_steady(&q, REF_BACKGROUND_LE), 2.385, 0, 0);
    assert_close(ref_background_hs_T_steady(&q, REF_BACKGROUND_GRAD), 2.385, 0, 0);
    q.restitution = 0.37;
    q.C2 = 0.0;
    assert_close(ref_background_hs_T_steady(&q, REF_BACKGROUND_LE), 2.385, 0, 0);
    assert_close(ref_background_hs_T_steady(&q, REF_BACKGROUND_GRAD), 2.385, 0, 0);
    /* Only the rates' ratio rho C2/(rho_B C1) matters: rho = 2, C2 = 1/16 with
     * rho_B = 4, C1 = 1/4 (ratio 1/8) reproduce K = 1/8. */
    ref_background_params r = hs_ex(0.0625);
    r.density = 2.0;
    r.bg_density = 4.0;
    r.C1 = 0.25;
    assert_close(ref_background_hs_T_steady(&r, REF_BACKGROUND_LE), le8, 1e-13, 0);
    assert_close(ref_background_hs_T_steady(&r, REF_BACKGROUND_GRAD), gr8, 1e-13, 0);
    /* More loss, lower T*; and LE below Grad at K = 1 (paper B Ex 5). */
    assert_true(le1 < le8 && gr1 < gr8 && le1 < gr1);
}

/* CVODE on (B.21)/(B.22) from paper B Ex 4/5's initial state (u0 = 0, T0 = 1,
 * u_B = (0, 1, 0)) reaches the root-found T* and u_B by t = 5 (rates ~ 19),
 * for K = 1/8 and 1, both closures, both methods. */
static void test_hs_cvode_reaches_steady_state(void **state)
{
    (void)state;
    enum { N = 101 };
    double t[N], u[3 * N], T[N];
    grid(t, N, 5.0);
    const double Ks[2] = {0.125, 1.0};
    for (int k = 0; k < 2; k++) {
        ref_background_params p = hs_ex(Ks[k]);
        for (int c = 0; c < 2; c++) {
            ref_background_closure cl = c ? REF_BACKGROUND_GRAD : REF_BACKGROUND_LE;
            double Ts = ref_background_hs_T_steady(&p, cl);
            for (int method = 0; method < 2; method++) {
                ref_ode_options o = opts(method ? REF_ODE_ADAMS : REF_ODE_BDF, 1e-10, 1e-12);
                char msg[256] = "x";
                assert_int_equal(ref_background_hs(&p, cl, t, N, &o, u, T, msg, sizeof msg), REF_OK);
                assert_string_equal(msg, "");
                assert_close(T[0], 1.0, 0, 0);
                assert_close(u[1], 0.0, 0, 0);
                assert_close(T[N - 1], Ts, 1e-9, 0);
                assert_close(u[3 * (N - 1) + 1], 1.0, 0, 1e-9);
                for (size_t m = 0; m < N; m++) { /* u - u_B stays along (0, 1, 0) */
                    assert_close(u[3 * m], 0.0, 0, 1e-15);
                    assert_close(u[3 * m + 2], 0.0, 0, 1e-15);
                }
            }
        }
    }
}

/* The physical time of ref_background_hs: background terms at rate rho_B C1,
 * grain-grain terms at rate rho C2 (background.h).  rho_B = 1.6, C1 = 1.5,
 * rho = 0.8, C2 = 0.375 (rho C2 = 0.3 = 2.4 * 1/8) must give Ex 4 (K = 1/8) at
 * time 2.4 t.  (The paper's t̄ = (rho_B/rho) rho_B C1 t would run the background
 * terms at rate 4.8 instead.) */
static void test_hs_time_scale(void **state)
{
    (void)state;
    enum { N = 41 };
    ref_background_params p = hs_ex(0.125), q = hs_ex(0.375);
    q.bg_density = 1.6;
    q.C1 = 1.5;
    q.density = 0.8;
    double t[N], ts[N], u[3 * N], us[3 * N], T[N], Ts[N];
    grid(t, N, 0.5);
    for (size_t m = 0; m < N; m++)
        ts[m] = 2.4 * t[m];
    ref_ode_options o = opts(REF_ODE_BDF, 1e-11, 1e-13);
    for (int c = 0; c < 2; c++) {
        ref_background_closure cl = c ? REF_BACKGROUND_GRAD : REF_BACKGROUND_LE;
        assert_int_equal(ref_background_hs(&q, cl, t, N, &o, u, T, NULL, 0), REF_OK);
        assert_int_equal(ref_background_hs(&p, cl, ts, N, &o, us, Ts, NULL, 0), REF_OK);
        for (size_t m = 0; m < N; m++) {
            assert_close(T[m], Ts[m], 1e-8, 0);
            assert_close(u[3 * m + 1], us[3 * m + 1], 1e-8, 1e-11);
        }
        assert_close(ref_background_hs_T_steady(&q, cl), ref_background_hs_T_steady(&p, cl), 1e-13, 0);
    }
}

/* u0 != u_B relaxes towards u_B along u0 - u_B.  Grad (B.22): du/dt is linear, so
 * u = u_B + (u0 - u_B) e^{-k rho_B C1 t}, k = sqrt(alpha)(32/3) sqrt(pi) sqrt(2 T_B/m),
 * exactly, for high-entropy parameters.  LE (B.21): |u - u_B| decreases strictly,
 * and once du and T - T* are small its decay rate is
 * alpha (32/3) sqrt(2 pi) sqrt(S_s/(alpha m)) rho_B C1, S_s = (1-alpha) T_B + alpha T*. */
static void test_hs_velocity_relaxation(void **state)
{
    (void)state;
    enum { N = 141 };
    ref_background_params p = {.mass = 1.7, .bg_density = 0.9, .bg_mass = 0.6,
                               .bg_temperature = 1.3, .bg_velocity = {0.1, -0.2, 0.3},
                               .C1 = 1.3, .density = 0.45, .C2 = 0.77, .restitution = 0.37,
                               .T0 = 2.385, .u0 = {0.4, -1.2, 0.75}};
    const double du0[3] = {0.3, -1.0, 0.45}, rate = 0.9 * 1.3;
    double al = 0.6 / 2.3, t[N], u[3 * N], T[N];
    grid(t, N, 1.4);
    /* Grad: to the solver's global error (about the number of steps times the
     * local tolerance: ~1e-11 absolute once |u - u_B| < atol/rtol). */
    double k = sqrt(al) * 32.0 / 3.0 * sqrt(PI) * sqrt(2.0 * 1.3 / 1.7) * rate;
    char msg[256];
    ref_ode_options o = opts(REF_ODE_BDF, 1e-11, 1e-14);
    assert_int_equal(ref_background_hs(&p, REF_BACKGROUND_GRAD, t, N, &o, u, T, msg, sizeof msg),
                     REF_OK);
    for (size_t m = 0; m < N; m++)
        for (int i = 0; i < 3; i++)
            assert_close(u[3 * m + i] - p.bg_velocity[i], du0[i] * exp(-k * t[m]), 1e-7, 1e-10);
    /* LE */
    assert_int_equal(ref_background_hs(&p, REF_BACKGROUND_LE, t, N, &o, u, T, msg, sizeof msg),
                     REF_OK);
    double prev = INFINITY, n0 = sqrt(0.09 + 1.0 + 0.2025);
    for (size_t m = 0; m < N; m++) {
        double d[3], n = 0.0;
        for (int i = 0; i < 3; i++) {
            d[i] = u[3 * m + i] - p.bg_velocity[i];
            n += d[i] * d[i];
        }
        n = sqrt(n);
        assert_true(n < prev);
        prev = n;
        for (int i = 0; i < 3; i++) /* parallel to u0 - u_B */
            assert_close(d[i] / n, du0[i] / n0, 1e-7, 1e-12);
    }
    assert_true(prev < 1e-6 * n0);
    double Tst = ref_background_hs_T_steady(&p, REF_BACKGROUND_LE);
    double S = (1.0 - al) * 1.3 + al * Tst;
    double k_le = al * 32.0 / 3.0 * sqrt(2.0 * PI) * sqrt(S / (al * 1.7)) * rate;
    size_t m1 = 80, m2 = 100; /* t = 0.8, 1.0 */
    double d1 = fabs(u[3 * m1 + 1] - p.bg_velocity[1]), d2 = fabs(u[3 * m2 + 1] - p.bg_velocity[1]);
    assert_close(T[m1], Tst, 1e-5, 0);
    assert_close(-log(d2 / d1) / (t[m2] - t[m1]), k_le, 1e-4, 0);
    /* ... which differs from Grad's k by more than the tolerance (the check can fail). */
    assert_true(fabs(k_le / k - 1.0) > 1e-2);
}

/* An independent transcription of docs/theory.md §12.3's (B.21)/(B.22), written term by term as
 * printed (not in background.c's factorised form), in physical time: background
 * terms times rho_B C1, the K terms with K rho_B C1 = rho C2.  y = (u, T). */
static void spec_rhs(const ref_background_params *p, ref_background_closure c, const double *y,
                     double *dy)
{
    double m = p->mass, TB = p->bg_temperature, al = p->bg_mass / (p->mass + p->bg_mass);
    double be = (1.0 - p->restitution) / 2.0, T = y[3];
    double rb = p->bg_density * p->C1, rg = p->density * p->C2;
    double d[3], du2 = 0.0;
    for (int i = 0; i < 3; i++) {
        d[i] = y[i] - p->bg_velocity[i];
        du2 += d[i] * d[i];
    }
    double U, E, L;
    if (c == REF_BACKGROUND_LE) {
        double S = (1.0 - al) * TB + al * T;
        U = -al * (16.0 / 3.0) * sqrt(2.0 * PI) * sqrt(al * m / S) * (du2 / 5.0 + 2.0 * S / (al * m));
        E = al * (8.0 / 3.0) * m * sqrt(2.0 * PI) * sqrt(al * m / S)
            * ((1.0 / 5.0) * (al + (1.0 / 3.0) * al * T / S) * du2 * du2
               + 4.0 * (S / (al * m)) * (al - (1.0 / 3.0) * al * T / S) * du2
               + 8.0 * (S / (al * m)) * (S / (al * m)) * (al - al * T / S));
        L = (64.0 / 3.0) * sqrt(PI) * m * be * (1.0 - be) * pow(T / m, 1.5);
    } else {
        U = -sqrt(al) * (32.0 / 3.0) * sqrt(PI) * sqrt(2.0 * TB / m);
        E = -sqrt(al) * (64.0 / 3.0) * sqrt(PI) * sqrt(2.0 * TB / m)
            * ((1.0 - al) * (T - TB) - (1.0 / 3.0) * al * m * du2);
        double br = (m / TB) * du2 + 3.0 * (T - TB) / TB;
        L = (4.0 / 3.0) * sqrt(PI) * m * be * (1.0 - be)
            * ((1.0 / 3.0) * br * br + 8.0 * (3.0 * T - TB) / TB) * pow(TB / m, 1.5);
    }
    for (int i = 0; i < 3; i++)
        dy[i] = rb * U * d[i];
    dy[3] = rb * E - rg * L;
}

/* Classical RK4 with step h from (u0, T0) to t_end; y gets the final state. */
static void spec_rk4(const ref_background_params *p, ref_background_closure c, double t_end,
                     double h, double y[4])
{
    double k1[4], k2[4], k3[4], k4[4], z[4];
    long n = lround(t_end / h);
    y[0] = p->u0[0], y[1] = p->u0[1], y[2] = p->u0[2], y[3] = p->T0;
    for (long s = 0; s < n; s++) {
        spec_rhs(p, c, y, k1);
        for (int i = 0; i < 4; i++) z[i] = y[i] + 0.5 * h * k1[i];
        spec_rhs(p, c, z, k2);
        for (int i = 0; i < 4; i++) z[i] = y[i] + 0.5 * h * k2[i];
        spec_rhs(p, c, z, k3);
        for (int i = 0; i < 4; i++) z[i] = y[i] + h * k3[i];
        spec_rhs(p, c, z, k4);
        for (int i = 0; i < 4; i++)
            y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
}

/* The full trajectories with u0 != u_B, where every du term of (B.21)/(B.22)
 * matters, against RK4 (h = 1/16384, global error ~ (20 h)^4 ~ 1e-12) on the
 * independent transcription above: Ex 5 (K = 1, du0 = 1) and high-entropy
 * parameters (T0 > T_B, du0 = 1.14, rho != rho_B), at t = 1/8, 1/4, 1/2. */
static void test_hs_closures_vs_independent_rk4(void **state)
{
    (void)state;
    ref_background_params ps[2] = {
        hs_ex(1.0),
        {.mass = 1.7, .bg_density = 0.9, .bg_mass = 0.6, .bg_temperature = 1.3,
         .bg_velocity = {0.1, -0.2, 0.3}, .C1 = 1.3, .density = 0.45, .C2 = 0.77,
         .restitution = 0.37, .T0 = 2.385, .u0 = {0.4, -1.2, 0.75}},
    };
    const double t[4] = {0.0, 0.125, 0.25, 0.5};
    for (int k = 0; k < 2; k++) {
        for (int c = 0; c < 2; c++) {
            ref_background_closure cl = c ? REF_BACKGROUND_GRAD : REF_BACKGROUND_LE;
            double u[12], T[4], y[4];
            ref_ode_options o = opts(REF_ODE_BDF, 1e-12, 1e-14);
            assert_int_equal(ref_background_hs(&ps[k], cl, t, 4, &o, u, T, NULL, 0), REF_OK);
            for (int m = 1; m < 4; m++) {
                spec_rk4(&ps[k], cl, t[m], 1.0 / 16384.0, y);
                assert_close(T[m], y[3], 1e-9, 0);
                for (int i = 0; i < 3; i++)
                    assert_close(u[3 * m + i], y[i], 1e-9, 1e-12);
            }
        }
    }
}

/* Grad (B.22) without grain-grain loss (e = 1) is linear: with k as above,
 * c = 2k(1 - alpha), g = (2/3) k alpha m |u0 - u_B|^2 (rates times rho_B C1),
 *   T' = -c (T - T_B) + g e^{-2kt}  =>
 *   T = T_B + (T0 - T_B) e^{-ct} + g (e^{-2kt} - e^{-ct})/(c - 2k),
 * the same structure as (B.15); checked for high-entropy parameters. */
static void test_hs_grad_elastic_closed_form(void **state)
{
    (void)state;
    enum { N = 33 };
    ref_background_params p = {.mass = 1.7, .bg_density = 0.9, .bg_mass = 0.6,
                               .bg_temperature = 1.3, .bg_velocity = {0.1, -0.2, 0.3},
                               .C1 = 1.3, .density = 0.45, .C2 = 0.77, .restitution = 1.0,
                               .T0 = 2.385, .u0 = {0.4, -1.2, 0.75}};
    double al = 0.6 / 2.3, du2 = 0.09 + 1.0 + 0.2025;
    double k = sqrt(al) * 32.0 / 3.0 * sqrt(PI) * sqrt(2.0 * 1.3 / 1.7) * 0.9 * 1.3;
    double c = 2.0 * k * (1.0 - al), g = 2.0 / 3.0 * k * al * 1.7 * du2;
    double t[N], u[3 * N], T[N];
    grid(t, N, 1.0);
    ref_ode_options o = opts(REF_ODE_BDF, 1e-12, 1e-14);
    assert_int_equal(ref_background_hs(&p, REF_BACKGROUND_GRAD, t, N, &o, u, T, NULL, 0), REF_OK);
    for (size_t m = 0; m < N; m++) {
        double ec = exp(-c * t[m]), e2k = exp(-2.0 * k * t[m]);
        assert_close(T[m], 1.3 + (2.385 - 1.3) * ec + g * (e2k - ec) / (c - 2.0 * k), 1e-9, 0);
    }
    assert_close(ref_background_hs_T_steady(&p, REF_BACKGROUND_GRAD), 1.3, 0, 0);
}

/* ---------------------------------------------------------------- traps */

static void test_trap_bad_parameters(void **state)
{
    (void)state;
    double t[3] = {0.0, 0.5, 1.0}, u[9], T[3];
    char msg[256];
    struct {
        const char *field;
        double value;
        const char *frag;
    } bad[] = {
        {"T0", -1.0, "T0 = -1 must be finite and > 0"},
        {"T0", INFINITY, "T0 = inf"},
        {"restitution", 1.7, "restitution = 1.7 out of range (0, 1]"},
        {"restitution", 0.0, "restitution = 0 out of range (0, 1]"},
        {"restitution", NAN, "restitution = nan"},
        {"mass", 0.0, "mass = 0 must be finite and > 0"},
        {"bg_mass", NAN, "bg_mass = nan must be finite and > 0"},
        {"bg_density", -2.0, "bg_density = -2 must be finite and > 0"},
        {"bg_temperature", -0.5, "bg_temperature = -0.5 must be finite and > 0"},
        {"C1", 0.0, "C1 = 0 must be finite and > 0"},
        {"density", INFINITY, "density = inf must be finite and > 0"},
        {"C2", -0.1, "C2 = -0.1 must be finite and >= 0"},
        {"u0", NAN, "u0[1] = nan is not finite"},
        {"bg_velocity", INFINITY, "bg_velocity[2] = inf is not finite"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        ref_background_params p = ex1();
        const char *f = bad[i].field;
        double v = bad[i].value;
        if (!strcmp(f, "T0"))
            p.T0 = v;
        else if (!strcmp(f, "restitution"))
            p.restitution = v;
        else if (!strcmp(f, "mass"))
            p.mass = v;
        else if (!strcmp(f, "bg_mass"))
            p.bg_mass = v;
        else if (!strcmp(f, "bg_density"))
            p.bg_density = v;
        else if (!strcmp(f, "bg_temperature"))
            p.bg_temperature = v;
        else if (!strcmp(f, "C1"))
            p.C1 = v;
        else if (!strcmp(f, "density"))
            p.density = v;
        else if (!strcmp(f, "C2"))
            p.C2 = v;
        else if (!strcmp(f, "u0"))
            p.u0[1] = v;
        else
            p.bg_velocity[2] = v;
        assert_failure(ref_background_maxwell_ode(&p, t, 3, NULL, u, T, msg, sizeof msg), REF_EINVAL,
                       msg, bad[i].frag, NULL);
        assert_failure(ref_background_hs(&p, REF_BACKGROUND_LE, t, 3, NULL, u, T, msg, sizeof msg),
                       REF_EINVAL, msg, bad[i].frag, NULL);
        assert_failure(ref_background_hs(&p, REF_BACKGROUND_GRAD, t, 3, NULL, u, T, msg, sizeof msg),
                       REF_EINVAL, msg, bad[i].frag, NULL);
        /* Functions without a status return NaN. */
        double w[3] = {1.0, 2.0, 3.0};
        ref_background_maxwell_u(&p, 0.5, w);
        assert_true(isnan(w[0]) && isnan(w[1]) && isnan(w[2]));
        assert_true(isnan(ref_background_maxwell_T(&p, 0.5)));
        assert_true(isnan(ref_background_maxwell_T_steady(&p)));
        assert_true(isnan(ref_background_hs_T_steady(&p, REF_BACKGROUND_LE)));
        assert_true(isnan(ref_background_hs_T_steady(&p, REF_BACKGROUND_GRAD)));
    }
    /* e = 1 and C2 = 0 are allowed (elastic grains, no grain-grain collisions). */
    ref_background_params ok = ex1();
    ok.restitution = 1.0;
    ok.C2 = 0.0;
    assert_false(isnan(ref_background_maxwell_T(&ok, 0.5)));
    assert_int_equal(ref_background_hs(&ok, REF_BACKGROUND_LE, t, 3, NULL, u, T, msg, sizeof msg),
                     REF_OK);
}

/* Call integrator c (0: Maxwell ODE, 1: LE, 2: Grad) of p. */
static ref_status integrate(int c, const ref_background_params *p, const double *t, size_t nt,
                            const ref_ode_options *o, double *u, double *T, char *msg, size_t len)
{
    if (c == 0)
        return ref_background_maxwell_ode(p, t, nt, o, u, T, msg, len);
    return ref_background_hs(p, c == 1 ? REF_BACKGROUND_LE : REF_BACKGROUND_GRAD, t, nt, o, u, T,
                             msg, len);
}

static void test_trap_bad_arguments(void **state)
{
    (void)state;
    ref_background_params p = ex1();
    double t[3] = {0.0, 0.5, 1.0}, t_dec[3] = {0.0, 0.5, 0.25}, t_nan[3] = {0.0, NAN, 1.0};
    double u[9], T[3], w[3] = {1.0, 1.0, 1.0};
    char msg[256];
    /* NULL p */
    assert_failure(ref_background_maxwell_ode(NULL, t, 3, NULL, u, T, msg, sizeof msg), REF_EINVAL,
                   msg, "p is NULL", NULL);
    assert_failure(ref_background_hs(NULL, REF_BACKGROUND_GRAD, t, 3, NULL, u, T, msg, sizeof msg),
                   REF_EINVAL, msg, "p is NULL", NULL);
    ref_background_maxwell_u(NULL, 0.5, w);
    assert_true(isnan(w[0]) && isnan(w[1]) && isnan(w[2]));
    ref_background_maxwell_u(&p, 0.5, NULL); /* harmless */
    assert_true(isnan(ref_background_maxwell_T(NULL, 0.5)));
    assert_true(isnan(ref_background_maxwell_T_steady(NULL)));
    assert_true(isnan(ref_background_hs_T_steady(NULL, REF_BACKGROUND_LE)));
    /* Bad times of the closed forms: negative or not finite. */
    const double bad_t[] = {-0.1, NAN, INFINITY};
    for (size_t i = 0; i < 3; i++) {
        w[1] = 1.0;
        ref_background_maxwell_u(&p, bad_t[i], w);
        assert_true(isnan(w[1]));
        assert_true(isnan(ref_background_maxwell_T(&p, bad_t[i])));
    }
    /* Bad closure. */
    ref_background_closure bad_c = (ref_background_closure)7;
    assert_failure(ref_background_hs(&p, bad_c, t, 3, NULL, u, T, msg, sizeof msg), REF_EINVAL, msg,
                   "closure = 7", NULL);
    assert_true(isnan(ref_background_hs_T_steady(&p, bad_c)));
    /* Bad time arrays, outputs and options, all three integrators. */
    for (int c = 0; c < 3; c++) {
        assert_failure(integrate(c, &p, NULL, 3, NULL, u, T, msg, sizeof msg), REF_EINVAL, msg,
                       "t is NULL", NULL);
        assert_failure(integrate(c, &p, t, 0, NULL, u, T, msg, sizeof msg), REF_EINVAL, msg,
                       "nt = 0", NULL);
        assert_failure(integrate(c, &p, t, 3, NULL, u, NULL, msg, sizeof msg), REF_EINVAL, msg,
                       "T_out is NULL", NULL);
        assert_failure(integrate(c, &p, t_dec, 3, NULL, u, T, msg, sizeof msg), REF_EINVAL, msg,
                       "t[2] = 0.25", "strictly increasing");
        assert_failure(integrate(c, &p, t_nan, 3, NULL, u, T, msg, sizeof msg), REF_EINVAL, msg,
                       "t[1] = nan", "not finite");
        /* Solver failures propagate: one step per output interval is not enough. */
        ref_ode_options o = opts(REF_ODE_BDF, 1e-10, 1e-12);
        o.max_steps = 1;
        assert_failure(integrate(c, &p, t, 3, &o, u, T, msg, sizeof msg), REF_ESOLVER, msg,
                       "CVODE failed at t = ", "CV_TOO_MUCH_WORK");
        /* Bad options reach ref_ode_solve's checks. */
        o = opts(REF_ODE_BDF, -1.0, 1e-12);
        assert_failure(integrate(c, &p, t, 3, &o, u, T, msg, sizeof msg), REF_EINVAL, msg,
                       "rtol = -1", NULL);
        /* A single time returns the initial state; msg may be NULL. */
        T[0] = u[1] = 0.0;
        assert_int_equal(integrate(c, &p, t, 1, NULL, u, T, NULL, 0), REF_OK);
        assert_close(T[0], 8.0 / 3.0, 0, 0);
        assert_close(u[1], 1.0, 0, 0);
        assert_int_equal(integrate(c, &p, t, 0, NULL, u, T, NULL, 0), REF_EINVAL);
    }
    /* A short buffer is truncated, never overrun. */
    char tiny[8];
    assert_int_equal(ref_background_maxwell_ode(NULL, t, 3, NULL, u, T, tiny, sizeof tiny), REF_EINVAL);
    assert_string_equal(tiny, "p is NU");
}

/* ---- finite-n expectation (Maxwell) and E1 (hard spheres) ---- */

/* n -> infinity: the finite-n system becomes (B.13), so E T_n -> T(t); at
 * t = 0, E T_n = (1 - 1/n) T0 exactly; for finite n the steady state solves the
 * 2x2 linear system (checked by its residual through a long integration). */
static void test_maxwell_finite_n_mean(void **state)
{
    (void)state;
    const ref_background_params cases[] = {ex1(), ex2(), ex3(), b_equals_c()};
    double t[NG], T[NG];
    grid(t, NG, 1.0);
    char msg[256];
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        const ref_background_params *p = &cases[c];
        assert_int_equal(ref_background_maxwell_T_mean(p, 1e12, t, NG, NULL, T, msg, sizeof msg),
                         REF_OK);
        for (size_t m = 0; m < NG; m++)
            assert_close(T[m], ref_background_maxwell_T(p, t[m]), 1e-8, 0.0);
        assert_int_equal(ref_background_maxwell_T_mean(p, 4.0, t, NG, NULL, T, msg, sizeof msg),
                         REF_OK);
        assert_close(T[0], 0.75 * p->T0, 1e-14, 0.0);
        /* the bias is O(1/n) and negative late in the relaxation for these cases */
        assert_true(T[NG - 1] < ref_background_maxwell_T(p, 1.0));
    }
    /* Steady state of Ex 1 at n = 4: solve the 2x2 system by hand.  lambda = 4 pi,
     * alpha = 1/2, k = pi (1 - 1/4) = 3 pi/4, theta = 1:
     * source 6 n lambda alpha^2 theta = 24 pi:
     *   0 = -(2 pi + 3 pi/4) Q + (3 pi/16) P + 24 pi,   0 = 2 pi Q - 4 pi P + 24 pi. */
    double A11 = -(2.0 * PI + 0.75 * PI), A12 = 0.75 * PI / 4.0, A21 = 2.0 * PI, A22 = -4.0 * PI;
    double b1 = -24.0 * PI, b2 = -24.0 * PI, det = A11 * A22 - A12 * A21;
    double Q = (b1 * A22 - A12 * b2) / det, P = (A11 * b2 - A21 * b1) / det;
    double t_long[2] = {0.0, 20.0}, T_long[2];
    ref_background_params p = ex1();
    assert_int_equal(ref_background_maxwell_T_mean(&p, 4.0, t_long, 2, NULL, T_long, msg,
                                                   sizeof msg), REF_OK);
    assert_close(T_long[1], (Q - P / 4.0) / 12.0, 1e-8, 0.0);
    assert_int_equal(ref_background_maxwell_T_mean(&p, 1.0, t_long, 2, NULL, T_long, msg,
                                                   sizeof msg), REF_EINVAL);
    assert_non_null(strstr(msg, "n = 1"));
}

typedef struct e1_integrand {
    double a, b, mu;
} e1_integrand;

/* |v - w| f^B(w)/rho_B in speed s = |w - u_B| and mu = cos(angle), u_B = 0,
 * |v| = a: 2 pi s^2 (pi b^2)^{-3/2} e^{-s^2/b^2} sqrt(a^2 + s^2 - 2 a s mu). */
static double e1_inner(double mu, void *params)
{
    e1_integrand *q = params;
    double s = q->mu;   /* the outer variable, passed through mu */
    return sqrt(fmax(0.0, q->a * q->a + s * s - 2.0 * q->a * s * mu));
}

static double e1_outer(double s, void *params)
{
    e1_integrand *q = params;
    e1_integrand inner = {q->a, q->b, s};
    gsl_function f = {e1_inner, &inner};
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(200);
    double r, err;
    gsl_integration_qag(&f, -1.0, 1.0, 1e-13, 1e-12, 200, GSL_INTEG_GAUSS61, w, &r, &err);
    gsl_integration_workspace_free(w);
    double b = q->b;
    return 2.0 * PI * s * s * pow(PI * b * b, -1.5) * exp(-s * s / (b * b)) * r;
}

/* E1(v) of docs/theory.md §5.1 against GSL quadrature of 4 pi C1 rho_B ∫ |v - w| f^B dw/rho_B,
 * its v = u_B limit, and the majorant E1max >= E1. */
static void test_hs_E1(void **state)
{
    (void)state;
    ref_background_params p = hs_ex(1.0);
    p.C1 = 0.7;
    p.bg_density = 1.3;
    p.bg_temperature = 1.8;
    p.bg_mass = 0.6;
    const double b = sqrt(2.0 * 1.8 / 0.6);
    const double a_list[] = {0.0, 1e-9, 0.05, 0.3, 1.0, 2.5, 6.0, 20.0};
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(200);
    for (size_t i = 0; i < sizeof a_list / sizeof *a_list; i++) {
        double v[3] = {p.bg_velocity[0] + a_list[i] * 0.6, p.bg_velocity[1] - a_list[i] * 0.8,
                       p.bg_velocity[2]};
        e1_integrand q = {a_list[i], b, 0.0};
        gsl_function f = {e1_outer, &q};
        double r, err;
        gsl_integration_qagiu(&f, 0.0, 1e-13, 1e-11, 200, w, &r, &err);
        double exact = 4.0 * PI * p.C1 * p.bg_density * r;
        double E1 = ref_background_hs_E1(&p, v), E1max = ref_background_hs_E1_majorant(&p, v);
        assert_close(E1, exact, 1e-9, 0.0);
        assert_true(a_list[i] < 0.01 ? E1max >= E1 * (1.0 - 1e-15) : E1max > E1);
        if (a_list[i] == 0.0) {
            assert_close(E1, 8.0 * sqrt(PI) * p.C1 * p.bg_density * b, 1e-15, 0.0);
            assert_close(E1max, E1, 1e-15, 0.0);   /* equal at v = u_B */
        }
    }
    gsl_integration_workspace_free(w);
    double bad[3] = {NAN, 0.0, 0.0};
    assert_true(isnan(ref_background_hs_E1(&p, bad)));
    p.bg_temperature = -1.0;
    assert_true(isnan(ref_background_hs_E1_majorant(&p, bad)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_maxwell_ex1),
        cmocka_unit_test(test_maxwell_ex2),
        cmocka_unit_test(test_maxwell_ex3),
        cmocka_unit_test(test_maxwell_b_equals_c),
        cmocka_unit_test(test_maxwell_time_scale),
        cmocka_unit_test(test_maxwell_cvode_vs_closed_form),
        cmocka_unit_test(test_maxwell_cvode_tolerance_matters),
        cmocka_unit_test(test_hs_steady_root),
        cmocka_unit_test(test_hs_cvode_reaches_steady_state),
        cmocka_unit_test(test_hs_time_scale),
        cmocka_unit_test(test_hs_velocity_relaxation),
        cmocka_unit_test(test_hs_closures_vs_independent_rk4),
        cmocka_unit_test(test_hs_grad_elastic_closed_form),
        cmocka_unit_test(test_maxwell_finite_n_mean),
        cmocka_unit_test(test_hs_E1),
        cmocka_unit_test(test_trap_bad_parameters),
        cmocka_unit_test(test_trap_bad_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
