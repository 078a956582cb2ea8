/* Heat-flux transport coefficients of paper D (docs/theory.md §14); see transport.h for
 * the contract, the sources and the derivations.  "D (N)" = paper D's Eq. (N);
 * "D ref. [28]" = Garzó, Santos and Montanero, Physica A 376 (2007) 94. */
#include "transport.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <threads.h>

#include <gsl/gsl_integration.h>

#include "message.h"
#include "sonine_a2.h" /* the a2 of (C.40) and the domain; not sonine.h, whose listing
                          * lists these coefficients */

static const double PI = 3.14159265358979323846;

static int alpha_ok(double alpha) { return alpha >= 0.0 && alpha <= 1.0; }

static int d_ok(double d) { return d >= REF_SONINE_D_MIN && d <= REF_SONINE_D_MAX; }

/* ------------------------------------------------------ first Sonine */

/* The coefficient c of a2 in nu*_kappa = ((1+a)/d)[... + c a2]:
 * D (2.46) for the Maxwellian weight, D ref. [28] for the HCS weight. */
static double nu_a2_coefficient(double alpha, double d, ref_transport_weight weight)
{
    if (weight == REF_TRANSPORT_MODIFIED)
        return (296.0 + 217.0 * d - 3.0 * (160.0 + 11.0 * d) * alpha) / 256.0;
    return (4.0 + 5.0 * d - 3.0 * (4.0 - d) * alpha) / 512.0;
}

ref_status ref_transport_first_sonine(double alpha, double d, double a2,
                                      ref_transport_weight weight, ref_transport_sonine *out,
                                      char *msg, size_t msglen)
{
    if (!alpha_ok(alpha)) {
        ref_say(msg, msglen, "alpha = %g is out of range (allowed 0 <= alpha <= 1)", alpha);
        return REF_EINVAL;
    }
    if (!d_ok(d)) {
        ref_say(msg, msglen, "d = %g is out of range (allowed %g <= d <= %g)", d,
                REF_SONINE_D_MIN, REF_SONINE_D_MAX);
        return REF_EINVAL;
    }
    if (!isfinite(a2)) {
        ref_say(msg, msglen, "a2 = %g is not finite", a2);
        return REF_EINVAL;
    }
    if (weight != REF_TRANSPORT_STANDARD && weight != REF_TRANSPORT_MODIFIED) {
        ref_say(msg, msglen,
                "weight = %d is not a ref_transport_weight (allowed REF_TRANSPORT_STANDARD, "
                "REF_TRANSPORT_MODIFIED)",
                (int)weight);
        return REF_EINVAL;
    }
    if (!out) {
        ref_say(msg, msglen, "out is NULL");
        return REF_EINVAL;
    }
    const double a = alpha;
    ref_transport_sonine s;
    s.a2 = a2;
    /* D (2.14): zeta^(0)/nu0. */
    s.zeta_star = (d + 2.0) / (4.0 * d) * (1.0 - a * a) * (1.0 + 3.0 / 16.0 * a2);
    /* D (2.46) (or its D ref. [28] form): nu_kappa/nu0 = nu_kappa'/nu0. */
    s.nu_kappa_star = (1.0 + a) / d
                      * (0.5 * (d - 1.0) + 3.0 / 16.0 * (d + 8.0) * (1.0 - a)
                         + nu_a2_coefficient(a, d, weight) * a2);
    /* D (2.41) and (2.42) divided by kappa0 = d(d+2)/(2(d-1)) nT/(m nu0), D (2.47). */
    s.kappa_star = (d - 1.0) / d * (1.0 + 2.0 * a2) / (s.nu_kappa_star - 2.0 * s.zeta_star);
    s.kappa_prime_star =
        (d - 1.0) / d * (1.0 + 1.5 * a2) / (s.nu_kappa_star - 1.5 * s.zeta_star);
    /* D (2.38): mu = (2T/n)(kappa - kappa'), so n mu/(T kappa0) = 2 (kappa* - kappa'*). */
    s.mu_star = 2.0 * (s.kappa_star - s.kappa_prime_star);
    *out = s;
    ref_say(msg, msglen, "%s", "");
    return REF_OK;
}

/* The first Sonine values at a2 of (C.40) = D (2.16); NaN outside the domain. */
static ref_transport_sonine sonine_at(double alpha, double d, ref_transport_weight weight)
{
    ref_transport_sonine s = {NAN, NAN, NAN, NAN, NAN, NAN};
    if (!alpha_ok(alpha) || !d_ok(d))
        return s;
    ref_transport_first_sonine(alpha, d, ref_sonine_a2_gaussian_alt(alpha, d), weight, &s, NULL,
                               0);
    return s;
}

double ref_transport_zeta_star(double alpha, double d)
{
    return sonine_at(alpha, d, REF_TRANSPORT_STANDARD).zeta_star;
}

double ref_transport_nu_kappa_star(double alpha, double d)
{
    return sonine_at(alpha, d, REF_TRANSPORT_STANDARD).nu_kappa_star;
}

double ref_transport_kappa_star(double alpha, double d)
{
    return sonine_at(alpha, d, REF_TRANSPORT_STANDARD).kappa_star;
}

double ref_transport_kappa_prime_star(double alpha, double d)
{
    return sonine_at(alpha, d, REF_TRANSPORT_STANDARD).kappa_prime_star;
}

double ref_transport_mu_star(double alpha, double d)
{
    return sonine_at(alpha, d, REF_TRANSPORT_STANDARD).mu_star;
}

double ref_transport_zeta_star_modified(double alpha, double d)
{
    return sonine_at(alpha, d, REF_TRANSPORT_MODIFIED).zeta_star;
}

double ref_transport_nu_kappa_star_modified(double alpha, double d)
{
    return sonine_at(alpha, d, REF_TRANSPORT_MODIFIED).nu_kappa_star;
}

double ref_transport_kappa_star_modified(double alpha, double d)
{
    return sonine_at(alpha, d, REF_TRANSPORT_MODIFIED).kappa_star;
}

double ref_transport_kappa_prime_star_modified(double alpha, double d)
{
    return sonine_at(alpha, d, REF_TRANSPORT_MODIFIED).kappa_prime_star;
}

double ref_transport_mu_star_modified(double alpha, double d)
{
    return sonine_at(alpha, d, REF_TRANSPORT_MODIFIED).mu_star;
}

/* ------------------------------------------ exact elastic solution, d = 3 */

double ref_transport_sonine_P(int k)
{
    if (k < 0)
        return NAN;
    /* <c_x^2 L_k^2> = (1/3) ∫ x^(3/2) e^-x L_k^(3/2)(x)^2 dx / Gamma(3/2)
     *             = Gamma(k + 5/2)/(3 k! Gamma(3/2)), by D (2.11). */
    return 3.0 * tgamma(k + 1.0) * tgamma(1.5) / tgamma(k + 2.5);
}

double ref_transport_b1_per_kappa(void)
{
    /* (d/(d-1))/(nu0 tau) with nu0 tau = 8/(5 sqrt pi) (docs/theory.md §2.3), d = 3. */
    return 15.0 * sqrt(PI) / 16.0;
}

/* L_k^(3/2)(x), k = 0..n, by the three-term recurrence
 * (k+1) L_{k+1} = (2k + 5/2 - x) L_k - (k + 3/2) L_{k-1}. */
static void laguerre_32(int n, double x, double *L)
{
    L[0] = 1.0;
    if (n >= 1)
        L[1] = 2.5 - x;
    for (int k = 1; k < n; k++)
        L[k + 1] = ((2.0 * k + 2.5 - x) * L[k] - (k + 1.5) * L[k - 1]) / (k + 1.0);
}

/* The Galerkin matrix A (n x n, row-major, full) of transport.h for psi_k,
 * k = 1..n.  Variables: c = G + g/2, c1 = G - g/2, c' = G + g'/2,
 * c1' = G - g'/2, phi_M phi_M1 = pi^-3 e^(-2G^2 - g^2/2).  By rotation
 * invariance of Σ_i Δpsi_j,i Δpsi_k,i, fix g = |g| z and g' = |g|(sin chi, 0,
 * cos chi) (factor 4 pi for g's direction, 2 pi for g''s azimuth):
 *   A_jk = (1/4)(1/3) pi^-3 4 pi 2 pi ∫ g^3 e^(-g^2/2) dg ∫ d(cos chi)
 *          ∫ d^3G e^(-2G^2) Σ_i Δpsi_j,i Δpsi_k,i,
 * the 1/3 because psi has one component and the sum three.  With u = g^2/2,
 * g^3 dg = 2u du.  The integrand is a polynomial of degree <= 4n + 2 in G, in
 * |g| (even: c <-> c1 swaps g, g' -> -g, -g') and in cos chi (sin chi enters
 * to even powers after the G integral), so Gauss rules with 2n + 2 Hermite,
 * n + 1 Laguerre (weight u e^-u) and 2n + 2 Legendre nodes are exact.  The
 * integrand is even in G and in G_y, hence in (G_x, G_z) -> -(G_x, G_z):
 * the G_x > 0, G_y > 0 nodes (none is 0: 2n + 2 is even) count four times. */
static ref_status elastic_matrix(int n, double *A, char *msg, size_t msglen)
{
    const int nh = 2 * n + 2, nl = n + 1, nm = 2 * n + 2;
    ref_status st = REF_OK;
    gsl_integration_fixed_workspace *wh =
        gsl_integration_fixed_alloc(gsl_integration_fixed_hermite, (size_t)nh, 0.0, 2.0, 0.0, 0.0);
    gsl_integration_fixed_workspace *wl =
        gsl_integration_fixed_alloc(gsl_integration_fixed_laguerre, (size_t)nl, 0.0, 1.0, 1.0, 0.0);
    gsl_integration_fixed_workspace *wm =
        gsl_integration_fixed_alloc(gsl_integration_fixed_legendre, (size_t)nm, -1.0, 1.0, 0, 0);
    double *L = malloc((size_t)(n + 1) * sizeof *L);
    double *D = malloc((size_t)(3 * n) * sizeof *D);
    double *acc = calloc((size_t)(n * n), sizeof *acc);
    if (!wh || !wl || !wm || !L || !D || !acc) {
        ref_say(msg, msglen, "out of memory for the order-%d quadrature", n);
        st = REF_ENOMEM;
        goto done;
    }
    const double *xh = gsl_integration_fixed_nodes(wh), *wgh = gsl_integration_fixed_weights(wh);
    const double *xl = gsl_integration_fixed_nodes(wl), *wgl = gsl_integration_fixed_weights(wl);
    const double *xm = gsl_integration_fixed_nodes(wm), *wgm = gsl_integration_fixed_weights(wm);
    for (int iu = 0; iu < nl; iu++) {
        const double g = sqrt(2.0 * xl[iu]);
        for (int im = 0; im < nm; im++) {
            const double mu = xm[im], s = sqrt(fmax(0.0, 1.0 - mu * mu));
            /* half of g and g': ±g/2 = (0, 0, ±g/2), ±g'/2 = ±(g s/2, 0, g mu/2) */
            const double hz = 0.5 * g, hpx = 0.5 * g * s, hpz = 0.5 * g * mu;
            const double w_gm = wgl[iu] * wgm[im];
            for (int ix = 0; ix < nh; ix++) {
                if (!(xh[ix] > 0.0))
                    continue;
                for (int iy = 0; iy < nh; iy++) {
                    if (!(xh[iy] > 0.0))
                        continue;
                    for (int iz = 0; iz < nh; iz++) {
                        const double Gx = xh[ix], Gy = xh[iy], Gz = xh[iz];
                        const double w = 4.0 * w_gm * wgh[ix] * wgh[iy] * wgh[iz];
                        /* the four velocities, with signs: c' and c1' count +,
                         * c and c1 count - */
                        const double vx[4] = {Gx + hpx, Gx - hpx, Gx, Gx};
                        const double vz[4] = {Gz + hpz, Gz - hpz, Gz + hz, Gz - hz};
                        const double sign[4] = {1.0, 1.0, -1.0, -1.0};
                        memset(D, 0, (size_t)(3 * n) * sizeof *D);
                        for (int p = 0; p < 4; p++) {
                            const double c2 = vx[p] * vx[p] + Gy * Gy + vz[p] * vz[p];
                            laguerre_32(n, c2, L);
                            for (int k = 0; k < n; k++) {
                                const double l = sign[p] * L[k + 1];
                                D[k] += l * vx[p];
                                D[n + k] += l * Gy;
                                D[2 * n + k] += l * vz[p];
                            }
                        }
                        for (int j = 0; j < n; j++) {
                            const double dxj = w * D[j], dyj = w * D[n + j], dzj = w * D[2 * n + j];
                            double *row = acc + (size_t)j * (size_t)n;
                            for (int k = 0; k <= j; k++)
                                row[k] += dxj * D[k] + dyj * D[n + k] + dzj * D[2 * n + k];
                        }
                    }
                }
            }
        }
    }
    /* (1/4)(1/3) pi^-3 (4 pi)(2 pi) and g^3 dg = 2u du: 4/(3 pi). */
    const double pref = 4.0 / (3.0 * PI);
    for (int j = 0; j < n; j++)
        for (int k = 0; k <= j; k++) {
            A[j * n + k] = pref * acc[j * n + k];
            A[k * n + j] = A[j * n + k];
        }
done:
    free(acc);
    free(D);
    free(L);
    gsl_integration_fixed_free(wm);
    gsl_integration_fixed_free(wl);
    gsl_integration_fixed_free(wh);
    return st;
}

/* In-place Cholesky factor (lower, row-major) of the n x n matrix A; 0, or 1
 * with the failing pivot in *bad when A is not positive definite.  Own code so
 * that GSL's error handler (which aborts by default) is never called. */
static int cholesky(double *A, int n, int *bad)
{
    for (int j = 0; j < n; j++) {
        double s = A[j * n + j];
        for (int k = 0; k < j; k++)
            s -= A[j * n + k] * A[j * n + k];
        if (!(s > 0.0) || !isfinite(s)) {
            *bad = j + 1;
            return 1;
        }
        const double ljj = sqrt(s);
        A[j * n + j] = ljj;
        for (int i = j + 1; i < n; i++) {
            double t = A[i * n + j];
            for (int k = 0; k < j; k++)
                t -= A[i * n + k] * A[j * n + k];
            A[i * n + j] = t / ljj;
        }
    }
    return 0;
}

/* Solve (L L^T) x = r e_1 with the leading m x m block of the factor of
 * order n (the leading block of a Cholesky factor is the factor of the
 * leading block). */
static void solve_leading(const double *Lf, int n, int m, double r, double *x)
{
    double y[REF_TRANSPORT_ELASTIC_MAX_ORDER];
    for (int i = 0; i < m; i++) {
        double t = i == 0 ? r : 0.0;
        for (int k = 0; k < i; k++)
            t -= Lf[i * n + k] * y[k];
        y[i] = t / Lf[i * n + i];
    }
    for (int i = m - 1; i >= 0; i--) {
        double t = y[i];
        for (int k = i + 1; k < m; k++)
            t -= Lf[k * n + i] * x[k];
        x[i] = t / Lf[i * n + i];
    }
}

/* The Galerkin matrix of order n, Cholesky-factored in place into *factor
 * (malloc'ed, n x n; the caller frees it). */
static ref_status elastic_factor(int n, double **factor, char *msg, size_t msglen)
{
    double *A = malloc((size_t)(n * n) * sizeof *A);
    if (!A) {
        ref_say(msg, msglen, "out of memory for the order-%d matrix", n);
        return REF_ENOMEM;
    }
    ref_status st = elastic_matrix(n, A, msg, msglen);
    int bad = 0;
    if (st == REF_OK && cholesky(A, n, &bad)) {
        ref_say(msg, msglen,
                "the order-%d Galerkin matrix is not positive definite (pivot %d); rounding", n,
                bad);
        st = REF_ESOLVER;
    }
    if (st != REF_OK) {
        free(A);
        return st;
    }
    *factor = A;
    return REF_OK;
}

/* The solution with m <= n terms from the order-n factor: its leading m x m
 * block is the order-m matrix, the quadrature being exact at every order. */
static void elastic_fill(const double *Lf, int n, int m, ref_transport_elastic *out)
{
    /* Right-hand side 5 sqrt2 pi e_1 (transport.h): b'_k in the units of docs/theory.md §14. */
    const double r = 5.0 * sqrt(2.0) * PI;
    double x[REF_TRANSPORT_ELASTIC_MAX_ORDER];
    out->order = m;
    for (int k = 0; k <= REF_TRANSPORT_ELASTIC_MAX_ORDER; k++)
        out->kappa_by_order[k] = out->b[k] = NAN;
    solve_leading(Lf, n, 1, r, x);
    const double b1_first = x[0]; /* = 15 sqrt(pi)/16 up to rounding */
    for (int j = 1; j <= m; j++) {
        solve_leading(Lf, n, j, r, x);
        out->kappa_by_order[j] = x[0] / b1_first;
    }
    for (int k = 1; k <= m; k++)
        out->b[k] = x[k - 1]; /* x holds the order-m solution after the last solve */
    out->kappa = out->kappa_by_order[m];
}

ref_status ref_transport_elastic_sonine(int order, ref_transport_elastic *out, char *msg,
                                        size_t msglen)
{
    if (order < 1 || order > REF_TRANSPORT_ELASTIC_MAX_ORDER) {
        ref_say(msg, msglen, "order = %d is out of range (allowed 1 <= order <= %d)", order,
                REF_TRANSPORT_ELASTIC_MAX_ORDER);
        return REF_EINVAL;
    }
    if (!out) {
        ref_say(msg, msglen, "out is NULL");
        return REF_EINVAL;
    }
    double *Lf = NULL;
    ref_status st = elastic_factor(order, &Lf, msg, msglen);
    if (st != REF_OK)
        return st;
    elastic_fill(Lf, order, order, out);
    free(Lf);
    ref_say(msg, msglen, "%s", "");
    return REF_OK;
}

/* The cache of ref_transport_elastic_exact, written once under call_once. */
static once_flag exact_once = ONCE_FLAG_INIT;
static ref_transport_elastic exact_value;
static ref_status exact_status;
static char exact_msg[256];

/* Increase the order until kappa settles (transport.h); the sequence of a
 * try is read from one factor, the leading blocks being the lower orders. */
static void exact_compute(void)
{
    static const int tries[] = {8, 12, 16, 20, REF_TRANSPORT_ELASTIC_MAX_ORDER};
    ref_transport_elastic e;
    for (size_t t = 0; t < sizeof tries / sizeof tries[0]; t++) {
        double *Lf = NULL;
        exact_status = elastic_factor(tries[t], &Lf, exact_msg, sizeof exact_msg);
        if (exact_status != REF_OK)
            return;
        elastic_fill(Lf, tries[t], tries[t], &e);
        for (int m = 2; m <= e.order; m++) {
            if (fabs(e.kappa_by_order[m] - e.kappa_by_order[m - 1]) <= REF_TRANSPORT_ELASTIC_TOL) {
                elastic_fill(Lf, tries[t], m, &exact_value);
                free(Lf);
                exact_msg[0] = '\0';
                return;
            }
        }
        free(Lf);
    }
    ref_say(exact_msg, sizeof exact_msg,
            "the elastic Sonine expansion did not converge to %g by order %d (last change %g)",
            REF_TRANSPORT_ELASTIC_TOL, e.order,
            fabs(e.kappa_by_order[e.order] - e.kappa_by_order[e.order - 1]));
    exact_status = REF_ESOLVER;
}

ref_status ref_transport_elastic_exact(ref_transport_elastic *out, char *msg, size_t msglen)
{
    if (!out) {
        ref_say(msg, msglen, "out is NULL");
        return REF_EINVAL;
    }
    call_once(&exact_once, exact_compute);
    ref_say(msg, msglen, "%s", exact_msg);
    if (exact_status == REF_OK)
        *out = exact_value;
    return exact_status;
}

double ref_transport_kappa_elastic_exact(void)
{
    ref_transport_elastic e;
    return ref_transport_elastic_exact(&e, NULL, 0) == REF_OK ? e.kappa : NAN;
}

double ref_transport_b_elastic_exact(int k)
{
    ref_transport_elastic e;
    if (ref_transport_elastic_exact(&e, NULL, 0) != REF_OK || k < 1 || k > e.order)
        return NAN;
    return e.b[k];
}
