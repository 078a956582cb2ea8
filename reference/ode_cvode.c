/* The one adapter between gdsmc and SUNDIALS 6.4.1 CVODE (docs/theory.md §16, STYLE "Errors").
 *
 * Lifecycle per call, as in SUNDIALS' examples/cvode/serial/cvRoberts_dns.c:
 * context -> vector -> CVodeCreate/Init/tolerances -> (BDF: dense matrix and
 * linear solver | Adams: fixed-point nonlinear solver) -> CVode at each output
 * time -> free everything.  CVODE's own messages are routed into the caller's
 * msg by an error handler, so nothing is printed.
 */
#include "ode.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

const char *ref_strerror(ref_status status)
{
    switch (status) {
    case REF_OK: return "success";
    case REF_EINVAL: return "invalid argument";
    case REF_ESOLVER: return "ODE solver failure";
    case REF_ENOMEM: return "out of memory";
    }
    return "unknown status";
}

ref_ode_options ref_ode_default_options(void)
{
    ref_ode_options o = {REF_ODE_BDF, 1e-10, 1e-12, 100000};
    return o;
}

/* The one place that records an error: every failure path goes through here. */
static ref_status fail(char *msg, size_t msglen, ref_status status, const char *fmt, ...)
{
    if (msg && msglen > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, msglen, fmt, ap);
        va_end(ap);
    }
    return status;
}

/* State shared with the RHS wrapper and the error handler (CVODE user data). */
typedef struct ode_state {
    ref_rhs_fn f;
    void *params;
    size_t dim;
    int rhs_flag;         /* nonzero value the user's f returned (a negative one sticks) */
    double rhs_t;         /* time of that failure or of the last non-finite ydot */
    size_t bad_index;     /* component of the last non-finite ydot, or dim if none */
    char cvode_msg[256];  /* last CVODE error message (warnings ignored) */
} ode_state;

static int rhs_wrapper(realtype t, N_Vector y, N_Vector ydot, void *user_data)
{
    ode_state *s = user_data;
    /* An unrecoverable failure stays one.  SUNDIALS 6.4.1's fixed-point solver
     * (Adams) turns any failing RHS call into a recoverable convergence failure,
     * so without this CVODE would shrink the step until max_steps. */
    if (s->rhs_flag < 0)
        return s->rhs_flag;
    double *dy = N_VGetArrayPointer(ydot);
    int r = s->f(t, N_VGetArrayPointer(y), dy, s->params);
    if (r != 0) {
        s->rhs_flag = r;
        s->rhs_t = t;
        return r;
    }
    /* A non-finite derivative is a recoverable failure: CVODE retries with a
     * smaller step; if that never helps it fails (a RHSFUNC, convergence or
     * too-much-work flag) and the message names the component. */
    for (size_t i = 0; i < s->dim; i++) {
        if (!isfinite(dy[i])) {
            s->bad_index = i;
            s->rhs_t = t;
            return 1;
        }
    }
    return 0;
}

static void err_handler(int error_code, const char *module, const char *function, char *text,
                        void *eh_data)
{
    ode_state *s = eh_data;
    if (error_code < 0)
        snprintf(s->cvode_msg, sizeof s->cvode_msg, "%s in %s: %s", module, function, text);
}

/* Map a negative CVODE flag to REF_ESOLVER with its name, time and messages. */
static ref_status cvode_fail(char *msg, size_t msglen, const ode_state *s, const char *call,
                             int flag, double t)
{
    char *name = CVodeGetReturnFlagName(flag); /* malloc'ed by SUNDIALS */
    char extra[160] = "";
    if (s->rhs_flag != 0)
        snprintf(extra, sizeof extra, "; the right-hand side returned %d at t = %.17g",
                 s->rhs_flag, s->rhs_t);
    else if (s->bad_index < s->dim)
        snprintf(extra, sizeof extra, "; the right-hand side gave a non-finite ydot[%zu] at t = %.17g",
                 s->bad_index, s->rhs_t);
    ref_status st = fail(msg, msglen, REF_ESOLVER, "%s failed at t = %.17g: %s (%s)%s", call, t,
                         name ? name : "unknown flag", s->cvode_msg[0] ? s->cvode_msg : "no message",
                         extra);
    free(name);
    return st;
}

static ref_status check_args(ref_rhs_fn f, size_t dim, const double *y0, const double *t_out,
                             size_t nout, const ref_ode_options *o, const double *y_out,
                             char *msg, size_t msglen)
{
    if (!f)
        return fail(msg, msglen, REF_EINVAL, "f is NULL (a right-hand side is required)");
    if (dim == 0 || dim > (size_t)INT32_MAX)
        return fail(msg, msglen, REF_EINVAL, "dim = %zu out of range [1, %ld]", dim,
                    (long)INT32_MAX);
    if (nout == 0)
        return fail(msg, msglen, REF_EINVAL, "nout = 0: at least one output time is required");
    if (!y0 || !t_out || !y_out)
        return fail(msg, msglen, REF_EINVAL, "%s is NULL", !y0 ? "y0" : !t_out ? "t_out" : "y_out");
    for (size_t i = 0; i < dim; i++)
        if (!isfinite(y0[i]))
            return fail(msg, msglen, REF_EINVAL, "y0[%zu] = %g is not finite", i, y0[i]);
    for (size_t m = 0; m < nout; m++) {
        if (!isfinite(t_out[m]))
            return fail(msg, msglen, REF_EINVAL, "t_out[%zu] = %g is not finite", m, t_out[m]);
        if (m > 0 && !(t_out[m] > t_out[m - 1]))
            return fail(msg, msglen, REF_EINVAL,
                        "t_out[%zu] = %.17g must be > t_out[%zu] = %.17g (strictly increasing)",
                        m, t_out[m], m - 1, t_out[m - 1]);
    }
    if (o->method != REF_ODE_BDF && o->method != REF_ODE_ADAMS)
        return fail(msg, msglen, REF_EINVAL, "method = %d is not REF_ODE_BDF or REF_ODE_ADAMS",
                    (int)o->method);
    if (!(isfinite(o->rtol) && o->rtol > 0))
        return fail(msg, msglen, REF_EINVAL, "rtol = %g must be finite and > 0", o->rtol);
    if (!(isfinite(o->atol) && o->atol > 0))
        return fail(msg, msglen, REF_EINVAL, "atol = %g must be finite and > 0", o->atol);
    if (o->max_steps < 0)
        return fail(msg, msglen, REF_EINVAL, "max_steps = %ld must be >= 0 (0: CVODE default)",
                    o->max_steps);
    return REF_OK;
}

ref_status ref_ode_solve(ref_rhs_fn f, void *params, size_t dim, const double *y0,
                         const double *t_out, size_t nout, const ref_ode_options *opt,
                         double *y_out, char *msg, size_t msglen)
{
    ref_ode_options o = opt ? *opt : ref_ode_default_options();
    ref_status st = check_args(f, dim, y0, t_out, nout, &o, y_out, msg, msglen);
    if (st != REF_OK)
        return st;
    if (msg && msglen > 0)
        msg[0] = '\0';
    memcpy(y_out, y0, dim * sizeof *y_out);
    if (nout == 1)
        return REF_OK;

    ode_state s = {f, params, dim, 0, 0.0, dim, ""};
    SUNContext ctx = NULL;
    N_Vector y = NULL;
    SUNMatrix A = NULL;
    SUNLinearSolver LS = NULL;
    SUNNonlinearSolver NLS = NULL;
    void *mem = NULL;
    int flag;
    sunindextype n = (sunindextype)dim;

    if (SUNContext_Create(NULL, &ctx) != 0 || !(y = N_VNew_Serial(n, ctx)) ||
        !(mem = CVodeCreate(o.method == REF_ODE_BDF ? CV_BDF : CV_ADAMS, ctx))) {
        st = fail(msg, msglen, REF_ENOMEM, "cannot allocate the CVODE context, vector or memory");
        goto done;
    }
    memcpy(N_VGetArrayPointer(y), y0, dim * sizeof(double));

    const char *call = "CVodeSetErrHandlerFn";
    if ((flag = CVodeSetErrHandlerFn(mem, err_handler, &s)) < 0 ||
        (call = "CVodeInit", flag = CVodeInit(mem, rhs_wrapper, t_out[0], y)) < 0 ||
        (call = "CVodeSetUserData", flag = CVodeSetUserData(mem, &s)) < 0 ||
        (call = "CVodeSStolerances", flag = CVodeSStolerances(mem, o.rtol, o.atol)) < 0 ||
        (call = "CVodeSetMaxNumSteps", flag = CVodeSetMaxNumSteps(mem, o.max_steps)) < 0 ||
        (call = "CVodeSetStopTime", flag = CVodeSetStopTime(mem, t_out[nout - 1])) < 0) {
        st = cvode_fail(msg, msglen, &s, call, flag, t_out[0]);
        goto done;
    }
    if (o.method == REF_ODE_BDF) {
        if (!(A = SUNDenseMatrix(n, n, ctx)) || !(LS = SUNLinSol_Dense(y, A, ctx))) {
            st = fail(msg, msglen, REF_ENOMEM, "cannot allocate a %zu x %zu dense solver", dim, dim);
            goto done;
        }
        call = "CVodeSetLinearSolver";
        flag = CVodeSetLinearSolver(mem, LS, A);
    } else {
        if (!(NLS = SUNNonlinSol_FixedPoint(y, 0, ctx))) {
            st = fail(msg, msglen, REF_ENOMEM, "cannot allocate the fixed-point solver");
            goto done;
        }
        call = "CVodeSetNonlinearSolver";
        flag = CVodeSetNonlinearSolver(mem, NLS);
    }
    if (flag < 0) {
        st = cvode_fail(msg, msglen, &s, call, flag, t_out[0]);
        goto done;
    }

    for (size_t m = 1; m < nout; m++) {
        realtype t = t_out[m];
        flag = CVode(mem, t_out[m], y, &t, CV_NORMAL);
        if (flag < 0) {
            st = cvode_fail(msg, msglen, &s, "CVODE", flag, t);
            goto done;
        }
        const double *ym = N_VGetArrayPointer(y);
        for (size_t i = 0; i < dim; i++) {
            if (!isfinite(ym[i])) {
                st = fail(msg, msglen, REF_ESOLVER, "CVODE returned a non-finite y[%zu] = %g at t = %.17g",
                          i, ym[i], t_out[m]);
                goto done;
            }
        }
        memcpy(y_out + m * dim, ym, dim * sizeof(double));
    }

done:
    CVodeFree(&mem);
    SUNNonlinSolFree(NLS);
    SUNLinSolFree(LS);
    SUNMatDestroy(A);
    N_VDestroy(y);
    SUNContext_Free(&ctx);
    return st;
}
