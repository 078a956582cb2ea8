/* Moment ODEs and closures integrated with SUNDIALS CVODE (docs/theory.md §16).
 *
 * ode_cvode.c is the one file that calls SUNDIALS: it creates the context,
 * vector, linear solver and integrator, maps negative CVODE flags through
 * CVodeGetReturnFlagName into the caller's message, and frees everything on
 * every path.  Callers see plain double arrays.
 */
#ifndef GDSMC_REF_ODE_H
#define GDSMC_REF_ODE_H

#include <stddef.h>

typedef enum ref_status {
    REF_OK = 0,
    REF_EINVAL,   /* bad argument: dimension 0, tolerances <= 0, times not increasing ... */
    REF_ESOLVER,  /* CVODE failed (message names the flag) or the right-hand side failed */
    REF_ENOMEM
} ref_status;

const char *ref_strerror(ref_status status);

/* Right-hand side y' = f(t, y) of dimension dim.  Return 0 on success, a
 * positive value for a recoverable failure (CVODE retries with a smaller step),
 * a negative value for an unrecoverable one (CVODE's convention). */
typedef int (*ref_rhs_fn)(double t, const double *y, double *ydot, void *params);

typedef enum ref_ode_method {
    REF_ODE_BDF,    /* stiff problems (dense Newton) */
    REF_ODE_ADAMS   /* non-stiff problems (fixed-point iteration) */
} ref_ode_method;

typedef struct ref_ode_options {
    ref_ode_method method;
    double rtol;      /* relative tolerance, > 0 */
    double atol;      /* absolute tolerance, > 0 */
    long max_steps;   /* per output interval; 0 means CVODE's default (500) */
} ref_ode_options;

/* Defaults used by every reference unless the caller says otherwise:
 * BDF, rtol = 1e-10, atol = 1e-12, max_steps = 100000. */
ref_ode_options ref_ode_default_options(void);

/* Integrate y' = f(t, y), y(t_out[0]) = y0, and store y(t_out[m]) in
 * y_out[m * dim + i] for m = 0 .. nout-1 (the row m = 0 is y0).  t_out must be
 * finite and strictly increasing, y0 finite; opt may be NULL (defaults).  A
 * non-finite ydot counts as a recoverable RHS failure (CVODE cuts the step);
 * a negative return from f is final.  On failure returns REF_EINVAL (message
 * names the argument, its value and the allowed range) or REF_ESOLVER
 * ("CVODE failed at t = ...: CV_FLAG (CVODE's message)", plus the RHS failure
 * if any), or REF_ENOMEM; y_out is then unspecified, and a solution that is
 * not finite is never returned.  msg gets msglen bytes (msg may be NULL when
 * msglen is 0) and is "" on success.  Nothing is printed.  Thread-safe: every
 * call has its own SUNDIALS context. */
ref_status ref_ode_solve(ref_rhs_fn f, void *params, size_t dim, const double *y0,
                         const double *t_out, size_t nout, const ref_ode_options *opt,
                         double *y_out, char *msg, size_t msglen);

#endif
