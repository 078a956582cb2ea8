/* The hard suite (`gdsmc verify --suite hard`): cases chosen to break a
 * careless solver (issue #5 item 1; the cases are listed in case_hard.c).
 *
 * Statistical checks (z-scores against exact expectations, Sonine estimates,
 * exact steady relations) go through checks.h.  The invariant checks below
 * are pure functions over a run's summary, so that a test can hand each of
 * them a corrupted summary (a NaN, a majorant violation, a momentum drift, a
 * CVODE result that is garbage) and see it fail (a check must be
 * able to fail, docs/verdicts.md).
 */
#ifndef GDSMC_VFY_CASE_HARD_H
#define GDSMC_VFY_CASE_HARD_H

#include <stddef.h>
#include <stdint.h>

#include "checks.h"
#include "ensemble.h"
#include "ode.h"

/* What the hard checks need from one simulation (sim_ensemble_result). */
typedef struct vfy_hard_summary {
    size_t ensembles;        /* N */
    size_t n;                /* particles per ensemble */
    uint64_t candidates;     /* candidate events, all ensembles */
    uint64_t collisions;     /* accepted binary collisions, all ensembles */
    uint64_t violations;     /* majorant violations, all ensembles */
    size_t values;           /* numbers inspected: every mean, variance and half-width of
                                every output time and steady average */
    size_t nonfinite;        /* ... of which NaN or infinite */
    size_t first_nonfinite;  /* index of the first of those in res->mean/var/ci order */
    double momentum;         /* max over output times and components k of
                                sqrt(N (var + mean^2)) of V_k: an upper bound on
                                max_j |V_k| over the ensembles j (population variance) */
    double speed;            /* max over output times of sqrt(3 sqrt(N (var + mean^2)))
                                of T_raw/m: bounds the r.m.s. speed sqrt(3 T_raw/m) of
                                every ensemble */
    double T_first;          /* ensemble mean of T at the first and the last output */
    double T_last;
    double T_min, T_max;     /* smallest and largest ensemble mean of T over the outputs */
} vfy_hard_summary;

/* Summarise res (particles of mass `mass`). */
void vfy_hard_summarize(const sim_ensemble_result *res, double mass, vfy_hard_summary *s);

/* Round-off bound on |V_k| of every ensemble at every output time, for a
 * system whose initial momentum was removed (particles.zero_momentum) and
 * whose momentum only momentum-conserving updates changed: `updates` of them
 * per ensemble (binary collisions, plus one per particle and step of a
 * momentum-keeping thermostat).  Random-rounding model (round to nearest:
 * independent errors, zero mean, |delta| <= u = DBL_EPSILON/2): one update
 * adds to the total momentum an error vector with E|err|^2 <= 2 u^2 s^2, s the
 * r.m.s. speed (collide.h: v' + w' = fl(c + h) + fl(c - h), c = fl(v + w)/2),
 * so after U updates |P - P(0)| has standard deviation <= u s sqrt(2U); the
 * observation's own sum adds a few u s.  Bound:
 *     6 u s (sqrt(2 U) / n + 2),
 * six standard deviations (VFY_TOL_HARD_ROUNDING_SIGMAS, tolerances.h), with
 * s = summary->speed. */
double vfy_hard_momentum_bound(const vfy_hard_summary *s, double updates);

/* Round-off bound on |T(t)/T(0) - 1| of the ensemble mean for a system whose
 * energy is conserved exactly in real arithmetic (elastic collisions, no
 * other effect), after C = `collisions` collisions per ensemble.  Same model
 * as above: a collision changes |v|^2 + |w|^2 by at most a few u times the
 * pair's energy E_pair (the stored v' and w', the rounded centre, |g| and
 * |e| = 1 to a few u); with standard deviation <= 4 u E_pair and E_pair about
 * 6 T/m, relative to the total 3 n T/m that is 8 u/n per collision, a random
 * walk of 8 u sqrt(C)/n; the observation's sum of n positive terms has a
 * relative error of standard deviation about u sqrt(n), twice (T(0), T(t)).
 * Bound: 6 u (8 sqrt(C)/n + 2 sqrt(n)), six standard deviations as above. */
double vfy_hard_energy_bound(const vfy_hard_summary *s, double collisions);

/* "<label> no NaN or infinity": every inspected value finite. */
vfy_verdict vfy_hard_check_finite(vfy_report *r, const char *label, const vfy_hard_summary *s);

/* "<label> majorant violations": the count is 0 (docs/theory.md §8.3: counted and
 * reported, 0 in the paper cases). */
vfy_verdict vfy_hard_check_violations(vfy_report *r, const char *label,
                                      const vfy_hard_summary *s);

/* "<label> momentum kept to round-off": s->momentum <= the bound of
 * vfy_hard_momentum_bound(s, updates) (also FAIL when either is NaN). */
vfy_verdict vfy_hard_check_momentum(vfy_report *r, const char *label, const vfy_hard_summary *s,
                                    double updates);

/* "<label> energy kept to round-off": |T_last/T_first - 1| and
 * |T_min/T_first - 1|, |T_max/T_first - 1| within vfy_hard_energy_bound. */
vfy_verdict vfy_hard_check_energy(vfy_report *r, const char *label, const vfy_hard_summary *s,
                                  double collisions);

/* "<label> T in its physical range": every ensemble mean of T finite and
 * positive, and (cooling gas: no heating) at most T_first (1 + 1e-12). */
vfy_verdict vfy_hard_check_cooling_range(vfy_report *r, const char *label,
                                         const vfy_hard_summary *s);

/* One integration of a reference ODE with CVODE (reference/ode.h), and what
 * it is judged against. */
typedef struct vfy_hard_ode {
    ref_status status;      /* what the reference function returned */
    const char *msg;        /* its message ("" on success) */
    size_t nt;              /* output times */
    const double *T;        /* T at the output times (read only when status = REF_OK) */
    const double *u;        /* 3 nt bulk velocities, or NULL */
    const double *T_exact;  /* a closed form at the same times, or NULL */
    double T_steady;        /* the steady state found independently (GSL Brent), or NaN */
    double rtol;            /* allowed relative deviation from T_exact and from T_steady at
                               the last output time */
    int must_succeed;       /* a failure, even a clean one, fails */
} vfy_hard_ode;

/* "<name>": CVODE succeeded with every value finite, T positive, T within
 * rtol of T_exact at every time and of T_steady at the last; or it failed
 * with a message (non-empty and naming CVODE or the bad argument): a clean
 * failure, which passes and says so unless run->must_succeed.  Success with garbage (NaN, T <= 0, a
 * result off the closed form or the steady state) and a failure without a
 * message fail. */
vfy_verdict vfy_hard_check_ode(vfy_report *r, const char *name, const vfy_hard_ode *run);

#endif
