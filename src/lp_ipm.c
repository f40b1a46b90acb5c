/* lp_ipm.c - the interior-point engine of lp.h, on CHOLMOD.
 *
 * A primal-dual Mehrotra predictor-corrector method specialized for the
 * bounds-only LP of blocklim (doc/theory.md, "The interior-point engine"):
 *
 *   - every user column becomes zero, one or two internal columns x >= 0
 *     (shifted by its lower bound, mirrored when it has only an upper bound,
 *     split in two when free, removed when fixed), with an upper bound U
 *     where the user column is boxed;
 *   - the one free column with an objective (the load multiplier, dense in
 *     the rows) is kept out of the normal matrix: a bordered system solved
 *     with one extra right-hand side per factorization;
 *   - the normal matrix M = F F^T + delta I, F = A Theta^(1/2), is factored
 *     by CHOLMOD (supernodal, METIS ordering): analysed once, refactored
 *     numerically every iteration.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <suitesparse/cholmod.h>

#include "lp_engine.h"

enum { COL_LOWER, COL_BOXED };

typedef struct ipm {
    bl_lp_settings set;
    /* the user's problem (copied) */
    int m, nu;
    int *ucp, *uri;
    double *uval, *lo, *hi, *rhs, *obj;
    /* the internal problem: minimize c.x + ca a, A x + g a = b, 0 <= x (<= U) */
    int border;         /* user column kept out of the factor, -1 if none */
    int n;              /* internal columns */
    int *map;           /* internal column -> user column */
    double *sign;       /* x_user = shift + sign * x (per internal column) */
    double *shift;      /* per user column */
    signed char *kind;  /* COL_LOWER or COL_BOXED */
    double *U, *c, *b, *g, ca;
    /* CHOLMOD */
    cholmod_common cm;
    cholmod_sparse *F;  /* A with columns scaled by sqrt(Theta) */
    cholmod_factor *L;
    double *aval;       /* values of A, in F's pattern */
    /* iterates and work */
    double *x, *z, *s, *w, *y, a;
    double *theta, *rd, *rp, *ru, *rhat, *dx, *dz, *ds, *dw, *dy, *xz, *sw, *v, *tmp;
    double *xu, *yu;    /* answers in user terms */
    int iterations;
} ipm;

static void *xcalloc(size_t n, size_t size) { return calloc(n ? n : 1, size); }

static void destroy(void *e)
{
    ipm *p = e;
    if (!p) return;
    if (p->F) cholmod_free_sparse(&p->F, &p->cm);
    if (p->L) cholmod_free_factor(&p->L, &p->cm);
    cholmod_finish(&p->cm);
    double **d[] = {&p->uval, &p->lo,    &p->hi, &p->rhs,  &p->obj, &p->sign, &p->shift,
                    &p->U,    &p->c,     &p->b,  &p->g,    &p->aval, &p->x,   &p->z,
                    &p->s,    &p->w,     &p->y,  &p->theta, &p->rd,  &p->rp,  &p->ru,
                    &p->rhat, &p->dx,    &p->dz, &p->ds,   &p->dw,   &p->dy,  &p->xz,
                    &p->sw,   &p->v,     &p->tmp, &p->xu,  &p->yu};
    for (size_t i = 0; i < sizeof d / sizeof *d; i++) free(*d[i]);
    free(p->ucp);
    free(p->uri);
    free(p->map);
    free(p->kind);
    free(p);
}

/* Builds the internal problem from the user's bounds: column mapping, F's
 * pattern and values of A, the symbolic analysis, and the work arrays. */
static int build(ipm *p, bl_error *err)
{
    if (p->F) cholmod_free_sparse(&p->F, &p->cm);
    if (p->L) cholmod_free_factor(&p->L, &p->cm);
    p->border = -1;
    for (int j = 0; j < p->nu; j++)
        if (isinf(p->lo[j]) && isinf(p->hi[j]) && p->obj[j] != 0.0) p->border = j;
    int n = 0, nnz = 0;
    for (int j = 0; j < p->nu; j++) {
        if (j == p->border || p->lo[j] == p->hi[j]) continue;
        int k = isinf(p->lo[j]) && isinf(p->hi[j]) ? 2 : 1;
        n += k;
        nnz += k * (p->ucp[j + 1] - p->ucp[j]);
    }
    p->n = n;
    free(p->map);
    free(p->sign);
    free(p->kind);
    free(p->U);
    free(p->c);
    free(p->aval);
    p->map = xcalloc((size_t)n, sizeof *p->map);
    p->sign = xcalloc((size_t)n, sizeof *p->sign);
    p->kind = xcalloc((size_t)n, sizeof *p->kind);
    p->U = xcalloc((size_t)n, sizeof *p->U);
    p->c = xcalloc((size_t)n, sizeof *p->c);
    p->aval = xcalloc((size_t)nnz, sizeof *p->aval);
    p->F = cholmod_allocate_sparse((size_t)p->m, (size_t)n, (size_t)nnz, 1, 1, 0, CHOLMOD_REAL,
                                   &p->cm);
    if (!p->map || !p->sign || !p->kind || !p->U || !p->c || !p->aval || !p->F)
        return bl_error_set(err, "lp: out of memory building the interior-point problem");

    /* b = rhs - sum of the constant parts; g = the border column */
    memcpy(p->b, p->rhs, (size_t)p->m * sizeof *p->b);
    memset(p->g, 0, (size_t)p->m * sizeof *p->g);
    p->ca = 0.0;
    int *Fp = p->F->p, *Fi = p->F->i, col = 0, q = 0;
    for (int j = 0; j < p->nu; j++) {
        double lo = p->lo[j], hi = p->hi[j];
        if (j == p->border) {
            p->ca = -p->obj[j];
            p->shift[j] = 0.0;
            for (int t = p->ucp[j]; t < p->ucp[j + 1]; t++) p->g[p->uri[t]] = p->uval[t];
            continue;
        }
        p->shift[j] = isfinite(lo) ? lo : isfinite(hi) ? hi : 0.0;
        for (int t = p->ucp[j]; t < p->ucp[j + 1]; t++)
            p->b[p->uri[t]] -= p->uval[t] * p->shift[j];
        if (lo == hi) continue;
        int parts = isinf(lo) && isinf(hi) ? 2 : 1;
        for (int k = 0; k < parts; k++, col++) {
            double sg = (isinf(lo) && !isinf(hi)) || k == 1 ? -1.0 : 1.0;
            p->map[col] = j;
            p->sign[col] = sg;
            p->kind[col] = isfinite(lo) && isfinite(hi) ? COL_BOXED : COL_LOWER;
            p->U[col] = p->kind[col] == COL_BOXED ? hi - lo : INFINITY;
            p->c[col] = -p->obj[j] * sg;
            Fp[col] = q;
            for (int t = p->ucp[j]; t < p->ucp[j + 1]; t++, q++) {
                Fi[q] = p->uri[t];
                p->aval[q] = sg * p->uval[t];
            }
        }
    }
    Fp[col] = q;
    memcpy(p->F->x, p->aval, (size_t)q * sizeof *p->aval);

    size_t nn = (size_t)n;
    double **arr[] = {&p->x, &p->z, &p->s, &p->w, &p->theta, &p->rd, &p->rhat,
                      &p->dx, &p->dz, &p->ds, &p->dw, &p->xz, &p->sw, &p->ru};
    for (size_t i = 0; i < sizeof arr / sizeof *arr; i++) {
        free(*arr[i]);
        *arr[i] = xcalloc(nn, sizeof(double));
        if (!*arr[i]) return bl_error_set(err, "lp: out of memory");
    }
    p->L = cholmod_analyze(p->F, &p->cm);
    if (!p->L) return bl_error_set(err, "lp: CHOLMOD could not analyse the normal matrix");
    return 0;
}

static void *create(const bl_lp_problem *pr, const bl_lp_settings *s, bl_error *err)
{
    ipm *p = calloc(1, sizeof *p);
    if (!p) {
        bl_error_set(err, "lp: out of memory");
        return NULL;
    }
    cholmod_start(&p->cm);
    p->cm.print = s->verbose ? 3 : 0;
    p->cm.error_handler = NULL;
    p->cm.supernodal = CHOLMOD_SUPERNODAL;
    p->cm.nmethods = 1;
    p->cm.method[0].ordering = CHOLMOD_METIS;
    p->cm.postorder = 1;
    p->cm.quick_return_if_not_posdef = 1;
    p->set = *s;
    if (p->set.tolerance <= 0) p->set.tolerance = 1e-8;
    if (p->set.max_iterations <= 0) p->set.max_iterations = 200;
    p->m = pr->nrows;
    p->nu = pr->ncols;
    size_t m = (size_t)pr->nrows, nu = (size_t)pr->ncols, nnz = (size_t)pr->colptr[pr->ncols];
    p->ucp = xcalloc(nu + 1, sizeof *p->ucp);
    p->uri = xcalloc(nnz, sizeof *p->uri);
    p->uval = xcalloc(nnz, sizeof *p->uval);
    p->lo = xcalloc(nu, sizeof *p->lo);
    p->hi = xcalloc(nu, sizeof *p->hi);
    p->obj = xcalloc(nu, sizeof *p->obj);
    p->shift = xcalloc(nu, sizeof *p->shift);
    p->xu = xcalloc(nu, sizeof *p->xu);
    p->rhs = xcalloc(m, sizeof *p->rhs);
    p->b = xcalloc(m, sizeof *p->b);
    p->g = xcalloc(m, sizeof *p->g);
    p->y = xcalloc(m, sizeof *p->y);
    p->dy = xcalloc(m, sizeof *p->dy);
    p->rp = xcalloc(m, sizeof *p->rp);
    p->v = xcalloc(m, sizeof *p->v);
    p->tmp = xcalloc(m, sizeof *p->tmp);
    p->yu = xcalloc(m, sizeof *p->yu);
    if (!p->ucp || !p->uri || !p->uval || !p->lo || !p->hi || !p->obj || !p->shift || !p->xu ||
        !p->rhs || !p->b || !p->g || !p->y || !p->dy || !p->rp || !p->v || !p->tmp || !p->yu) {
        bl_error_set(err, "lp: out of memory");
        destroy(p);
        return NULL;
    }
    memcpy(p->ucp, pr->colptr, (nu + 1) * sizeof *p->ucp);
    memcpy(p->uri, pr->rowind, nnz * sizeof *p->uri);
    memcpy(p->uval, pr->val, nnz * sizeof *p->uval);
    memcpy(p->lo, pr->lo, nu * sizeof *p->lo);
    memcpy(p->hi, pr->hi, nu * sizeof *p->hi);
    memcpy(p->obj, pr->obj, nu * sizeof *p->obj);
    memcpy(p->rhs, pr->rhs, m * sizeof *p->rhs);
    if (build(p, err)) {
        destroy(p);
        return NULL;
    }
    return p;
}

static void set_bounds(void *e, const double *lo, const double *hi)
{
    ipm *p = e;
    memcpy(p->lo, lo, (size_t)p->nu * sizeof *p->lo);
    memcpy(p->hi, hi, (size_t)p->nu * sizeof *p->hi);
    bl_error err;
    if (build(p, &err)) {
        /* out of memory: solve will report failure */
        if (p->L) cholmod_free_factor(&p->L, &p->cm);
    }
}

/* ---- linear algebra helpers ------------------------------------------------ */

static double inf_norm(const double *a, int n)
{
    double r = 0.0;
    for (int i = 0; i < n; i++) r = fmax(r, fabs(a[i]));
    return r;
}

static double dot(const double *a, const double *b, int n)
{
    double r = 0.0;
    for (int i = 0; i < n; i++) r += a[i] * b[i];
    return r;
}

/* out (m) = A v (n), over the internal columns */
static void mul_A(const ipm *p, const double *v, double *out)
{
    const int *Fp = p->F->p, *Fi = p->F->i;
    memset(out, 0, (size_t)p->m * sizeof *out);
    for (int j = 0; j < p->n; j++)
        for (int q = Fp[j]; q < Fp[j + 1]; q++) out[Fi[q]] += p->aval[q] * v[j];
}

/* out (n) = A^T v (m) */
static void mul_At(const ipm *p, const double *v, double *out)
{
    const int *Fp = p->F->p, *Fi = p->F->i;
    for (int j = 0; j < p->n; j++) {
        double t = 0.0;
        for (int q = Fp[j]; q < Fp[j + 1]; q++) t += p->aval[q] * v[Fi[q]];
        out[j] = t;
    }
}

/* Factors A Theta A^T + delta I; raises delta when CHOLMOD meets a
 * non-positive pivot.  Returns 0 or -1. */
static int factor(ipm *p, double *delta)
{
    const int *Fp = p->F->p;
    double *Fx = p->F->x, dmax = 0.0;
    for (int j = 0; j < p->n; j++) {
        double r = sqrt(p->theta[j]);
        for (int q = Fp[j]; q < Fp[j + 1]; q++) {
            Fx[q] = p->aval[q] * r;
            dmax = fmax(dmax, Fx[q] * Fx[q]);
        }
    }
    /* A tiny regularization: larger relative values stalled the primal
     * residual in the prototype (DESIGN 3.1). */
    *delta = fmax(1e-20 * dmax, 1e-10);
    for (int tries = 0; tries < 8; tries++, *delta *= 100.0) {
        double beta[2] = {*delta, 0.0};
        p->cm.status = CHOLMOD_OK;
        cholmod_factorize_p(p->F, beta, NULL, 0, p->L, &p->cm);
        if (p->cm.status == CHOLMOD_OK && p->L->minor == p->L->n) return 0;
        if (p->cm.status < 0) return -1;
    }
    return -1;
}

/* Solves M out = rhs in place (m). */
static int msolve(ipm *p, double *rhs)
{
    cholmod_dense B = {0};
    B.nrow = B.d = (size_t)p->m;
    B.ncol = 1;
    B.nzmax = (size_t)p->m;
    B.x = rhs;
    B.xtype = CHOLMOD_REAL;
    B.dtype = CHOLMOD_DOUBLE;
    cholmod_dense *X = cholmod_solve(CHOLMOD_A, p->L, &B, &p->cm);
    if (!X) return -1;
    memcpy(rhs, X->x, (size_t)p->m * sizeof *rhs);
    cholmod_free_dense(&X, &p->cm);
    return 0;
}

/* One Newton direction for the complementarity targets xz (n) and sw (n,
 * boxed columns), given the residuals; v = M^-1 g must be current. */
static int direction(ipm *p, double ra, double gv)
{
    int n = p->n;
    for (int j = 0; j < n; j++) {
        double r = p->rd[j] - p->xz[j] / p->x[j];
        if (p->kind[j] == COL_BOXED) r += (p->sw[j] - p->w[j] * p->ru[j]) / p->s[j];
        p->rhat[j] = r;
        p->dx[j] = p->theta[j] * r;
    }
    mul_A(p, p->dx, p->dy);
    for (int i = 0; i < p->m; i++) p->dy[i] += p->rp[i];
    if (msolve(p, p->dy)) return -1;
    double da = gv != 0.0 ? (dot(p->g, p->dy, p->m) - ra) / gv : 0.0;
    for (int i = 0; i < p->m; i++) p->dy[i] -= p->v[i] * da;
    p->tmp[0] = da;
    mul_At(p, p->dy, p->dx);
    for (int j = 0; j < n; j++) {
        p->dx[j] = p->theta[j] * (p->dx[j] - p->rhat[j]);
        p->dz[j] = (p->xz[j] - p->z[j] * p->dx[j]) / p->x[j];
        if (p->kind[j] == COL_BOXED) {
            p->ds[j] = p->ru[j] - p->dx[j];
            p->dw[j] = (p->sw[j] - p->w[j] * p->ds[j]) / p->s[j];
        } else {
            p->ds[j] = p->dw[j] = 0.0;
        }
    }
    return 0;
}

/* Largest step in (0, 1] keeping v + t dv >= 0, over both pairs. */
static double max_step(const ipm *p, const double *v1, const double *d1, const double *v2,
                       const double *d2)
{
    double t = 1.0;
    for (int j = 0; j < p->n; j++) {
        if (d1[j] < 0.0) t = fmin(t, -v1[j] / d1[j]);
        if (p->kind[j] == COL_BOXED && d2[j] < 0.0) t = fmin(t, -v2[j] / d2[j]);
    }
    return t;
}

static void starting_point(ipm *p)
{
    int n = p->n;
    for (int j = 0; j < n; j++) {
        if (p->kind[j] == COL_BOXED) {
            p->x[j] = p->s[j] = 0.5 * p->U[j];
            p->w[j] = 1.0;
        } else {
            p->x[j] = 1.0;
            p->s[j] = p->w[j] = 0.0;
        }
        p->z[j] = 1.0;
    }
    memset(p->y, 0, (size_t)p->m * sizeof *p->y);
    p->a = 0.0;
}

static void answers(ipm *p)
{
    for (int j = 0; j < p->nu; j++) p->xu[j] = p->shift[j];
    for (int k = 0; k < p->n; k++) p->xu[p->map[k]] += p->sign[k] * p->x[k];
    if (p->border >= 0) p->xu[p->border] = p->a;
    /* internal duals are for minimizing -obj: the user's sign is flipped */
    for (int i = 0; i < p->m; i++) p->yu[i] = -p->y[i];
}

static bl_lp_status solve(void *e)
{
    ipm *p = e;
    int n = p->n, m = p->m, nbox = 0;
    if (!p->L) return BL_LP_FAILED;
    for (int j = 0; j < n; j++) nbox += p->kind[j] == COL_BOXED;
    double t0 = bl_clock();
    double tol = p->set.tolerance;
    double bnorm = 1.0 + inf_norm(p->b, m), cnorm = 1.0 + inf_norm(p->c, n) + fabs(p->ca);
    double unorm = 1.0;
    for (int j = 0; j < n; j++)
        if (p->kind[j] == COL_BOXED) unorm = fmax(unorm, 1.0 + p->U[j]);
    starting_point(p);
    p->iterations = 0;
    bl_lp_status status = BL_LP_ITERATION_LIMIT;
    for (int it = 0; it < p->set.max_iterations; it++) {
        if (bl_interrupt_pending()) { status = BL_LP_INTERRUPTED; break; }
        if (p->set.max_seconds > 0 && bl_clock() - t0 > p->set.max_seconds) {
            status = BL_LP_TIME_LIMIT;
            break;
        }
        /* residuals */
        mul_A(p, p->x, p->rp);
        for (int i = 0; i < m; i++) p->rp[i] = p->b[i] - p->rp[i] - p->g[i] * p->a;
        mul_At(p, p->y, p->rd);
        double gap_c = 0.0;
        for (int j = 0; j < n; j++) {
            p->rd[j] = p->c[j] - p->rd[j] - p->z[j];
            gap_c += p->x[j] * p->z[j];
            if (p->kind[j] == COL_BOXED) {
                p->rd[j] += p->w[j];
                p->ru[j] = p->U[j] - p->x[j] - p->s[j];
                gap_c += p->s[j] * p->w[j];
            } else {
                p->ru[j] = 0.0;
            }
        }
        double ra = p->ca - dot(p->g, p->y, m);
        double mu = gap_c / (double)(n + nbox > 0 ? n + nbox : 1);
        double pobj = dot(p->c, p->x, n) + p->ca * p->a;
        double dobj = dot(p->b, p->y, m);
        for (int j = 0; j < n; j++)
            if (p->kind[j] == COL_BOXED) dobj -= p->U[j] * p->w[j];
        double ep = inf_norm(p->rp, m) / bnorm, eu = inf_norm(p->ru, n) / unorm;
        double ed = fmax(inf_norm(p->rd, n), fabs(ra)) / cnorm;
        double eg = fabs(pobj - dobj) / (1.0 + fabs(pobj));
        if (ep <= tol && eu <= tol && ed <= tol && eg <= tol) {
            status = BL_LP_OPTIMAL;
            break;
        }
        /* divergence: a ray of the primal (unbounded) or of the dual
         * (infeasible); see doc/theory.md for the certificates */
        double xn = fmax(inf_norm(p->x, n), fabs(p->a)), yn = inf_norm(p->y, m);
        if (xn > 1e10 && ed <= 1e-6) { status = BL_LP_UNBOUNDED; break; }
        if (yn > 1e10 && ep <= 1e-6 * xn) { status = BL_LP_INFEASIBLE; break; }
        if (xn > 1e12) { status = BL_LP_UNBOUNDED; break; }
        if (yn > 1e12) { status = BL_LP_INFEASIBLE; break; }

        for (int j = 0; j < n; j++) {
            double d = p->z[j] / p->x[j];
            if (p->kind[j] == COL_BOXED) d += p->w[j] / p->s[j];
            p->theta[j] = 1.0 / d;
        }
        double delta;
        if (factor(p, &delta)) { status = BL_LP_FAILED; break; }
        memcpy(p->v, p->g, (size_t)m * sizeof *p->v);
        if (msolve(p, p->v)) { status = BL_LP_FAILED; break; }
        double gv = dot(p->g, p->v, m);

        /* predictor */
        for (int j = 0; j < n; j++) {
            p->xz[j] = -p->x[j] * p->z[j];
            p->sw[j] = p->kind[j] == COL_BOXED ? -p->s[j] * p->w[j] : 0.0;
        }
        if (direction(p, ra, gv)) { status = BL_LP_FAILED; break; }
        double tp = max_step(p, p->x, p->dx, p->s, p->ds);
        double td = max_step(p, p->z, p->dz, p->w, p->dw);
        double mu_aff = 0.0;
        for (int j = 0; j < n; j++) {
            mu_aff += (p->x[j] + tp * p->dx[j]) * (p->z[j] + td * p->dz[j]);
            if (p->kind[j] == COL_BOXED)
                mu_aff += (p->s[j] + tp * p->ds[j]) * (p->w[j] + td * p->dw[j]);
        }
        mu_aff /= (double)(n + nbox > 0 ? n + nbox : 1);
        double sigma = pow(mu_aff / mu, 3.0);
        if (sigma > 1.0) sigma = 1.0;

        /* corrector: centring plus the second-order term of the predictor */
        for (int j = 0; j < n; j++) {
            p->xz[j] = sigma * mu - p->x[j] * p->z[j] - p->dx[j] * p->dz[j];
            p->sw[j] = p->kind[j] == COL_BOXED
                           ? sigma * mu - p->s[j] * p->w[j] - p->ds[j] * p->dw[j]
                           : 0.0;
        }
        if (direction(p, ra, gv)) { status = BL_LP_FAILED; break; }
        double da = p->tmp[0];
        tp = fmin(1.0, 0.99 * max_step(p, p->x, p->dx, p->s, p->ds));
        td = fmin(1.0, 0.99 * max_step(p, p->z, p->dz, p->w, p->dw));
        for (int j = 0; j < n; j++) {
            p->x[j] += tp * p->dx[j];
            p->z[j] += td * p->dz[j];
            if (p->kind[j] == COL_BOXED) {
                p->s[j] += tp * p->ds[j];
                p->w[j] += td * p->dw[j];
            }
        }
        p->a += tp * da;
        for (int i = 0; i < m; i++) p->y[i] += td * p->dy[i];
        p->iterations = it + 1;
    }
    answers(p);
    return status;
}

static const double *primal(const void *e) { return ((const ipm *)e)->xu; }
static const double *dual(const void *e) { return ((const ipm *)e)->yu; }
static int iterations(const void *e) { return ((const ipm *)e)->iterations; }

const bl_lp_backend bl_lp_ipm_engine = {
    "ipm", create, destroy, set_bounds, solve, primal, dual, iterations,
};
