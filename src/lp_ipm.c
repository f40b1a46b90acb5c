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
 *     by CHOLMOD (normal.h): analysed once, refactored numerically every
 *     iteration, in two domains on two threads when it is large;
 *   - the iterates follow a central path weighted by the scale of the
 *     forces (path_weights), unless settings.weighted is 0.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <omp.h>

#include "lp_engine.h"
#include "normal.h"

/* The loops over the internal columns and the products with A and A^T run
 * on p->threads threads (OMP_NUM_THREADS or the processors, at most
 * MAX_THREADS) from BL_IPM_PAR_COLS columns (lp_engine.h); CHOLMOD's
 * factorization and solves stay on one (doc/performance.md, "Threads"). */
#define MAX_THREADS 4
#define PAR_FOR _Pragma("omp parallel for num_threads(p->threads) if (n >= BL_IPM_PAR_COLS) schedule(static)")
#define PAR_FOR_WITH(clauses) \
    _Pragma(STR(omp parallel for num_threads(p->threads) if (n >= BL_IPM_PAR_COLS) schedule(static) clauses))
#define STR(x) #x

enum { COL_LOWER, COL_BOXED };

/* A Newton direction: internal columns (x, z, s, w), rows (y), border (a). */
typedef struct step {
    double *x, *z, *s, *w, *y, a;
} step;

/* An iterate of a solve's path, kept in user terms for the next warm
 * start: x, the duals of its lower and upper bounds, y, the border a and
 * the iterate's mean product mu. */
typedef struct kept {
    double *x, *zl, *zu, *y, a, mu;
    int set;            /* the point is set */
    int warm;           /* the last solve was optimal: start from the point */
    int foreign;        /* set by bl_lp_warm, not by a solve */
} kept;

typedef struct ipm {
    bl_lp_settings set;
    /* the user's problem: bounds, right-hand side and objective copied */
    int m, nu;
    const int *ucp, *uri;   /* the matrix, by reference (lp.h) */
    const double *uval;
    double *lo, *hi, *rhs, *obj; /* copied */
    /* the internal problem: minimize c.x + ca a, A x + g a = b, 0 <= x (<= U) */
    int border;         /* user column kept out of the factor, -1 if none */
    int n;              /* internal columns */
    int *map;           /* internal column -> user column */
    double *sign;       /* x_user = shift + sign * x (per internal column) */
    double *shift;      /* per user column */
    signed char *kind;  /* COL_LOWER or COL_BOXED */
    double *U, *c, *b, *g, ca;
    bl_normal *N;       /* the normal matrix and its factor */
    /* iterates and work */
    double *x, *z, *s, *w, *y, a;
    double *theta, *rd, *rp, *ru, *rhat, *xz, *sw, *v, *tmp, *ntmp;
    double *part;       /* mul_A's per-thread sums (m per extra thread) */
    double *wt;         /* the weights of the products' targets (path_weights), NULL: all 1 */
    double wsum;        /* their sum over the pairs (x, z) and (s, w) */
    int threads;
    step dir, cor;      /* the direction and a centrality corrector */
    double *xu, *yu;    /* answers in user terms */
    int iterations;
    int factorizations, solves;    /* counted for the verbose summary */
    double factor_time, solve_time;
    kept k;             /* for the next warm start */
    kept saved;         /* bl_lp_mark's copy of k */
    bl_lp_status last;  /* the status of the last solve */
    double *yprev, *at; /* early_infeasible: the last y, A^T (y - yprev) */
} ipm;

static void *xcalloc(size_t n, size_t size) { return calloc(n ? n : 1, size); }

static void destroy(void *e)
{
    ipm *p = e;
    if (!p) return;
    bl_normal_free(p->N);
    double **d[] = {&p->lo,    &p->hi, &p->rhs,  &p->obj, &p->sign, &p->shift,
                    &p->U,    &p->c,     &p->b,  &p->g,    &p->x,   &p->z,
                    &p->s,    &p->w,     &p->y,  &p->theta, &p->rd,  &p->rp,  &p->ru,
                    &p->rhat, &p->xz,    &p->sw, &p->v,    &p->tmp,  &p->xu,  &p->yu,
                    &p->dir.x,  &p->dir.z,   &p->dir.s, &p->dir.w, &p->dir.y,  &p->cor.x, &p->cor.z,
                    &p->cor.s,  &p->cor.w,   &p->cor.y, &p->ntmp, &p->part,
                    &p->k.x, &p->k.zl, &p->k.zu, &p->k.y, &p->saved.x, &p->saved.zl, &p->saved.zu, &p->saved.y};
    for (size_t i = 0; i < sizeof d / sizeof *d; i++) free(*d[i]);
    free(p->map);
    free(p->kind);
    free(p->yprev);
    free(p->at);
    free(p->wt);
    free(p);
}

/* Builds the internal problem from the user's bounds: column mapping, the
 * analysis of the normal matrix, and the work arrays. */
static int build(ipm *p, bl_error *err)
{
    p->border = -1;
    for (int j = 0; j < p->nu; j++)
        if (isinf(p->lo[j]) && isinf(p->hi[j]) && p->obj[j] != 0.0) p->border = j;
    int n = 0;
    for (int j = 0; j < p->nu; j++) {
        if (j == p->border || p->lo[j] == p->hi[j]) continue;
        n += isinf(p->lo[j]) && isinf(p->hi[j]) ? 2 : 1;
    }
    /* the same internal columns as before (a bound moved, as in a sequence
     * of LPs): the normal matrix keeps its analysis */
    int *old_map = p->map, old_n = p->n;
    p->n = n;
    free(p->sign);
    free(p->kind);
    free(p->U);
    free(p->c);
    free(p->at); /* ray_test's, n entries */
    p->at = NULL;
    p->map = xcalloc((size_t)n, sizeof *p->map);
    p->sign = xcalloc((size_t)n, sizeof *p->sign);
    p->kind = xcalloc((size_t)n, sizeof *p->kind);
    p->U = xcalloc((size_t)n, sizeof *p->U);
    p->c = xcalloc((size_t)n, sizeof *p->c);
    if (!p->map || !p->sign || !p->kind || !p->U || !p->c) goto oom;

    /* b = rhs - sum of the constant parts; g = the border column */
    memcpy(p->b, p->rhs, (size_t)p->m * sizeof *p->b);
    memset(p->g, 0, (size_t)p->m * sizeof *p->g);
    p->ca = 0.0;
    int col = 0;
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
        }
    }

    /* the upper-bound pairs (s, w) and their residuals and directions only
     * when some column is boxed: 30 MB at 40,100 blocks otherwise */
    int nbox = 0;
    for (int k = 0; k < n; k++) nbox += p->kind[k] == COL_BOXED;
    size_t nn = (size_t)n;
    double **always[] = {&p->x,     &p->z,     &p->theta, &p->rd,    &p->rhat, &p->xz,
                         &p->dir.x, &p->dir.z, &p->cor.x, &p->cor.z, &p->ntmp};
    double **boxed[] = {&p->s,     &p->w,     &p->sw,    &p->ru,
                        &p->dir.s, &p->dir.w, &p->cor.s, &p->cor.w};
    for (size_t i = 0; i < sizeof always / sizeof *always; i++) {
        free(*always[i]);
        if (!(*always[i] = xcalloc(nn, sizeof(double)))) goto oom;
    }
    for (size_t i = 0; i < sizeof boxed / sizeof *boxed; i++) {
        free(*boxed[i]);
        *boxed[i] = nbox ? xcalloc(nn, sizeof(double)) : NULL;
        if (nbox && !*boxed[i]) goto oom;
    }
    if (p->N && old_map && old_n == n && !memcmp(old_map, p->map, (size_t)n * sizeof *p->map)) {
        free(p->map); /* the analysis holds the old one, equal */
        p->map = old_map;
        return 0;
    }
    free(old_map);
    free(p->wt);
    p->wt = NULL;
    bl_normal_free(p->N);
    p->N = NULL;
    bl_normal_pattern pat = {p->m, n, p->ucp, p->uri, p->map, p->uval};
    double t0 = bl_clock();
    p->N = bl_normal_analyse(&pat, p->threads, p->set.verbose, err);
    if (p->set.verbose) fprintf(stderr, "ipm: analysis %.3f s\n", bl_clock() - t0);
    return p->N ? 0 : -1;
oom: /* solve() reports the failure: no analysis */
    free(old_map);
    bl_normal_free(p->N);
    p->N = NULL;
    return bl_error_set(err, "lp: out of memory building the interior-point problem");
}

static void *create(const bl_lp_problem *pr, const bl_lp_settings *s, bl_error *err)
{
    bl_one_thread();
    omp_set_max_active_levels(1);
    ipm *p = calloc(1, sizeof *p);
    if (!p) {
        bl_error_set(err, "lp: out of memory");
        return NULL;
    }
    p->set = *s;
    if (p->set.tolerance <= 0) p->set.tolerance = 1e-8;
    if (p->set.max_iterations <= 0) p->set.max_iterations = 200;
    p->m = pr->nrows;
    p->nu = pr->ncols;
    size_t m = (size_t)pr->nrows, nu = (size_t)pr->ncols;
    p->ucp = pr->colptr;
    p->uri = pr->rowind;
    p->uval = pr->val;
    p->lo = xcalloc(nu, sizeof *p->lo);
    p->hi = xcalloc(nu, sizeof *p->hi);
    p->obj = xcalloc(nu, sizeof *p->obj);
    p->shift = xcalloc(nu, sizeof *p->shift);
    p->xu = xcalloc(nu, sizeof *p->xu);
    p->rhs = xcalloc(m, sizeof *p->rhs);
    p->b = xcalloc(m, sizeof *p->b);
    p->g = xcalloc(m, sizeof *p->g);
    p->y = xcalloc(m, sizeof *p->y);
    p->dir.y = xcalloc(m, sizeof *p->dir.y);
    p->cor.y = xcalloc(m, sizeof *p->cor.y);
    p->rp = xcalloc(m, sizeof *p->rp);
    p->v = xcalloc(m, sizeof *p->v);
    p->tmp = xcalloc(m, sizeof *p->tmp);
    p->yu = xcalloc(m, sizeof *p->yu);
    p->k.x = xcalloc(nu, sizeof *p->k.x);
    p->k.zl = xcalloc(nu, sizeof *p->k.zl);
    p->k.zu = xcalloc(nu, sizeof *p->k.zu);
    p->k.y = xcalloc(m, sizeof *p->k.y);
    int procs = s->threads > 0 ? s->threads : omp_get_max_threads();
    p->threads = procs < 1 ? 1 : procs > MAX_THREADS ? MAX_THREADS : procs;
    p->part = xcalloc(m * (size_t)(p->threads - 1), sizeof *p->part);
    if (!p->lo || !p->hi || !p->obj || !p->shift || !p->xu ||
        !p->rhs || !p->b || !p->g || !p->y || !p->dir.y || !p->cor.y || !p->rp || !p->v || !p->tmp || !p->yu || !p->part ||
        !p->k.x || !p->k.zl || !p->k.zu || !p->k.y) {
        bl_error_set(err, "lp: out of memory");
        destroy(p);
        return NULL;
    }
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
    }
}

static void set_objective(void *e, const double *obj)
{
    ipm *p = e;
    memcpy(p->obj, obj, (size_t)p->nu * sizeof *p->obj);
    p->k.warm = 0;
    bl_error err;
    if (build(p, &err)) {
        /* out of memory: solve will report failure */
    }
}

/* ---- linear algebra helpers ------------------------------------------------ */

static double inf_norm(const double *a, int n)
{
    double r = 0.0;
    for (int i = 0; i < n; i++)
        if (fabs(a[i]) > r) r = fabs(a[i]);
    return r;
}

static double dot(const double *a, const double *b, int n)
{
    double r = 0.0;
    for (int i = 0; i < n; i++) r += a[i] * b[i];
    return r;
}

/* The products with A read the user's matrix through map and sign: a
 * separate copy of A's values in F's pattern cost 23 MB at 40,100 blocks
 * and pushed the peak over 500 MB. */

/* out (m) = A v (n), over the internal columns: each thread scatters its
 * share of the columns into its own copy of out, then the copies are summed. */
static void mul_A(const ipm *p, const double *v, double *out)
{
    int n = p->n, m = p->m;
#pragma omp parallel num_threads(p->threads) if (n >= BL_IPM_PAR_COLS)
    {
        int t = omp_get_thread_num(), nt = omp_get_num_threads();
        double *o = t == 0 ? out : p->part + (size_t)(t - 1) * (size_t)m;
        memset(o, 0, (size_t)m * sizeof *o);
        int k0 = (int)((long)n * t / nt), k1 = (int)((long)n * (t + 1) / nt);
        for (int k = k0; k < k1; k++) {
            int j = p->map[k];
            double s = p->sign[k] * v[k];
            for (int q = p->ucp[j]; q < p->ucp[j + 1]; q++) o[p->uri[q]] += p->uval[q] * s;
        }
        if (nt > 1) {
#pragma omp barrier
#pragma omp for schedule(static)
            for (int i = 0; i < m; i++)
                for (int u = 1; u < nt; u++) out[i] += p->part[(size_t)(u - 1) * (size_t)m + (size_t)i];
        }
    }
}

/* out (n) = A^T v (m) */
static void mul_At(const ipm *p, const double *v, double *out)
{
    int n = p->n;
    PAR_FOR
    for (int k = 0; k < n; k++) {
        int j = p->map[k];
        double t = 0.0;
        for (int q = p->ucp[j]; q < p->ucp[j + 1]; q++) t += p->uval[q] * v[p->uri[q]];
        out[k] = p->sign[k] * t;
    }
}

/* Factors A Theta A^T + delta I; raises delta when a pivot is not
 * positive.  Returns 0 or -1. */
static int factor(ipm *p, double *delta)
{
    double *scale = p->ntmp; /* free between the uses in refine() */
    int n = p->n;
    PAR_FOR
    for (int k = 0; k < n; k++) scale[k] = p->sign[k] * sqrt(p->theta[k]);
    double t0 = bl_clock();
    /* A tiny regularization: larger relative values stalled the primal
     * residual in the prototype (DESIGN 3.1). */
    *delta = fmax(1e-20 * bl_normal_fill(p->N, scale), 1e-10);
    p->factorizations++;
    int r = 1;
    for (int tries = 0; tries < 8 && r > 0; tries++) {
        r = bl_normal_factor(p->N, *delta);
        if (r > 0) *delta *= 100.0;
    }
    p->factor_time += bl_clock() - t0;
    return r == 0 ? 0 : -1;
}

/* Solves M out = rhs in place (m), and M v = g as well when v is given
 * (one pass through the factor for both). */
static int msolve(ipm *p, double *rhs, double *v)
{
    double t0 = bl_clock(), *two[2] = {rhs, v};
    if (v) memcpy(v, p->g, (size_t)p->m * sizeof *v);
    int r = bl_normal_solve(p->N, two, v ? 2 : 1);
    p->solves++;
    p->solve_time += bl_clock() - t0;
    return r;
}

/* The rest of a direction from its dx: dz, ds, dw. */
static void complete(ipm *p, step *d, int full)
{
    int n = p->n;
    PAR_FOR
    for (int j = 0; j < n; j++) {
        d->z[j] = (p->xz[j] - p->z[j] * d->x[j]) / p->x[j];
        if (p->kind[j] == COL_BOXED) {
            d->s[j] = (full ? p->ru[j] : 0.0) - d->x[j];
            d->w[j] = (p->sw[j] - p->w[j] * d->s[j]) / p->s[j];
        } else if (d->s) {
            d->s[j] = d->w[j] = 0.0;
        }
    }
}

/* One Newton direction into d for the complementarity targets xz (n) and
 * sw (n, boxed columns).  With full = 1 it also removes the residuals rp,
 * rd, ru and ra; with full = 0 it is a pure centrality correction.
 * v = M^-1 g and *gv = g.v must be current, or with new_v = 1 they are
 * computed here, in the same solve (the first direction after a
 * factorization).  Returns 0 or -1. */
static int direction(ipm *p, step *d, int full, double ra, double *gv, int new_v)
{
    int n = p->n, m = p->m;
    PAR_FOR
    for (int j = 0; j < n; j++) {
        double r = (full ? p->rd[j] : 0.0) - p->xz[j] / p->x[j];
        if (p->kind[j] == COL_BOXED) r += (p->sw[j] - (full ? p->w[j] * p->ru[j] : 0.0)) / p->s[j];
        p->rhat[j] = r;
        d->x[j] = p->theta[j] * r;
    }
    mul_A(p, d->x, d->y);
    if (full)
        for (int i = 0; i < m; i++) d->y[i] += p->rp[i];
    if (msolve(p, d->y, new_v ? p->v : NULL)) return -1;
    if (new_v) *gv = dot(p->g, p->v, m);
    d->a = *gv != 0.0 ? (dot(p->g, d->y, m) - (full ? ra : 0.0)) / *gv : 0.0;
    for (int i = 0; i < m; i++) d->y[i] -= p->v[i] * d->a;
    mul_At(p, d->y, d->x);
    PAR_FOR
    for (int j = 0; j < n; j++) d->x[j] = p->theta[j] * (d->x[j] - p->rhat[j]);
    complete(p, d, full);
    return 0;
}

/* Refines the primal rows of the direction that will be taken: M is nearly
 * singular along the mechanism, so A dx + g da drifts from rp by round-off
 * in q - v da (the primal residual of the iterates grew to 1e-5 at 10,050
 * blocks without this).  The correction M dy' + g da' = e, g.dy' = 0,
 * dx' = Theta A^T dy' (with dz', ds', dw' from the linearized
 * complementarity) leaves the other equations of the step as they were. */
static int refine(ipm *p, step *d, double gv)
{
    int n = p->n, m = p->m;
    for (int pass = 0; pass < 2; pass++) {
        mul_A(p, d->x, p->tmp);
        double en = 0.0, rn = 0.0;
        for (int i = 0; i < m; i++) {
            p->tmp[i] = p->rp[i] - p->tmp[i] - p->g[i] * d->a;
            if (fabs(p->tmp[i]) > en) en = fabs(p->tmp[i]);
            if (fabs(p->rp[i]) > rn) rn = fabs(p->rp[i]);
        }
        if (en <= 1e-14 * (1.0 + rn)) break;
        if (msolve(p, p->tmp, NULL)) return -1;
        double da = gv != 0.0 ? dot(p->g, p->tmp, m) / gv : 0.0;
        for (int i = 0; i < m; i++) {
            p->tmp[i] -= p->v[i] * da;
            d->y[i] += p->tmp[i];
        }
        d->a += da;
        mul_At(p, p->tmp, p->ntmp);
        PAR_FOR
        for (int j = 0; j < n; j++) {
            double dx = p->theta[j] * p->ntmp[j];
            d->x[j] += dx;
            d->z[j] -= p->z[j] / p->x[j] * dx;
            if (p->kind[j] == COL_BOXED) {
                d->s[j] -= dx;
                d->w[j] += p->w[j] / p->s[j] * dx;
            }
        }
    }
    return 0;
}

/* Largest step in (0, 1] keeping v + t dv >= 0, over both pairs. */
static double max_step(const ipm *p, const double *v1, const double *d1, const double *v2,
                       const double *d2)
{
    /* over x (or z) and, on boxed columns, s (or w) */
    double t = 1.0;
    int n = p->n;
    PAR_FOR_WITH(reduction(min : t))
    for (int j = 0; j < n; j++) {
        if (d1[j] < 0.0 && -v1[j] / d1[j] < t) t = -v1[j] / d1[j];
        if (p->kind[j] == COL_BOXED && d2[j] < 0.0 && -v2[j] / d2[j] < t) t = -v2[j] / d2[j];
    }
    return t;
}

/* The weighted central path (settings.weighted).  The iterates follow
 * x_j z_j = mu w_j (and s_j w_j = mu w_j) instead of x_j z_j = mu: the
 * same optimum alpha, reached through the weighted analytic centres of the
 * feasible sets, with
 *     w_j = (max(|x~_j|, W_FLOOR m) / m)^W_EXP,
 * x~ the least-norm solution of A x = b (the start's first solve) and m the
 * mean of |x~|.  The columns that carry large forces (at the foot of a
 * wall) keep larger products as mu falls.  Associative solves of running-
 * bond walls, five frictions each (mu = 0.60 to 0.70): 40.2 -> 34.2
 * iterations on average at 10,050 blocks, 58.8 -> 45.6 at 40,100, and 79
 * -> 62 at 100,014 (mu = 0.65); exponents 0.2-0.4 did as well, 0.125 and
 * 0.75 less, 1 and 2 worse than none, and negative ones worse still
 * (doc/performance.md, "The weighted path"). */
#define W_EXP 0.25
#define W_FLOOR 0.01

static inline double weight(const ipm *p, int j) { return p->wt ? p->wt[j] : 1.0; }

static void path_weights(ipm *p)
{
    int n = p->n;
    double mean = 0.0;
    for (int j = 0; j < n; j++) mean += fabs(p->x[j]);
    mean /= n > 0 ? n : 1;
    if (!p->set.weighted || !(mean > 0.0) || !isfinite(mean)) {
        free(p->wt);
        p->wt = NULL;
        return;
    }
    if (!p->wt && !(p->wt = malloc((size_t)n * sizeof *p->wt))) return; /* all 1 */
    for (int j = 0; j < n; j++) p->wt[j] = pow(fmax(fabs(p->x[j]), W_FLOOR * mean) / mean, W_EXP);
}

/* The sum of the weights over the complementary pairs: mu = (x.z + s.w) / wsum. */
static void weight_sum(ipm *p)
{
    double sum = 0.0;
    for (int j = 0; j < p->n; j++) sum += weight(p, j) * (p->kind[j] == COL_BOXED ? 2.0 : 1.0);
    p->wsum = sum > 0.0 ? sum : 1.0;
}

/* Mehrotra's starting point: the least-norm solution of A x = b and a dual
 * point y = -g / |g|^2 that satisfies the border's dual row, both shifted
 * into the interior by amounts that balance x.z.  One factorization of
 * A A^T.  Returns 0 or -1. */
static int starting_point(ipm *p)
{
    int n = p->n, m = p->m;
    double delta;
    for (int j = 0; j < n; j++) p->theta[j] = 1.0;
    if (factor(p, &delta)) return -1;
    memcpy(p->tmp, p->b, (size_t)m * sizeof *p->tmp);
    if (msolve(p, p->tmp, NULL)) return -1;
    mul_At(p, p->tmp, p->x);
    path_weights(p);
    double gg = dot(p->g, p->g, m);
    for (int i = 0; i < m; i++) p->y[i] = gg > 0.0 ? p->ca * p->g[i] / gg : 0.0;
    mul_At(p, p->y, p->z);
    double xmin = INFINITY, zmin = INFINITY;
    for (int j = 0; j < n; j++) {
        p->z[j] = p->c[j] - p->z[j];
        if (p->kind[j] == COL_BOXED) p->x[j] = fmin(fmax(p->x[j], 0.1 * p->U[j]), 0.9 * p->U[j]);
        xmin = fmin(xmin, p->x[j]);
        zmin = fmin(zmin, p->z[j]);
    }
    double dx = fmax(-1.5 * xmin, 0.0), dz = fmax(-1.5 * zmin, 0.0);
    double xz = 0.0, sx = 0.0, sz = 0.0;
    for (int j = 0; j < n; j++) {
        xz += (p->x[j] + dx) * (p->z[j] + dz);
        sx += p->x[j] + dx;
        sz += p->z[j] + dz;
    }
    double hx = dx + (sz > 0.0 ? 0.5 * xz / sz : 1.0);
    double hz = dz + (sx > 0.0 ? 0.5 * xz / sx : 1.0);
    if (!(hx > 0.0)) hx = 1.0;
    if (!(hz > 0.0)) hz = 1.0;
    for (int j = 0; j < n; j++) {
        p->z[j] += hz;
        if (p->kind[j] == COL_BOXED) {
            p->x[j] = fmin(p->x[j] + hx, 0.9 * p->U[j]);
            p->s[j] = p->U[j] - p->x[j];
            p->w[j] = p->z[j];
        } else {
            p->x[j] += hx;
            if (p->s) p->s[j] = p->w[j] = 0.0;
        }
    }
    p->a = 0.0;
    return 0;
}

/* Warm starts.  A re-solve after a bound change starts from an iterate of
 * the previous solve's path, the first whose relative residuals and gap
 * were all below KEEP_AT, not from its answer: the answer sits on the old
 * optimal face, far from the new central path, and pushing it into the
 * interior (by 0.01, as before) does not centre it.  The kept
 * iterate is mapped onto the new bounds, with every product between kept
 * mu and KEEP_CAP times it (a bound that moved away leaves its x far from
 * it: its dual is lowered, not its x raised).  On the sequence of LPs of
 * the 1,040-block wall this took 11 iterations per re-solve against 16
 * from the pushed answer, on the 2,525-block wall 16 against 23
 * (doc/performance.md, "Warm starts"); 0.3 and 0.03 for KEEP_AT, and 30
 * for KEEP_CAP, did about as well, 10^-3 and below far worse. */
#define KEEP_AT 0.1
#define KEEP_CAP 100.0
#define WARM_PATIENCE 10

static void keep_point(ipm *p, double mu)
{
    for (int j = 0; j < p->nu; j++) p->k.x[j] = p->shift[j];
    for (int k = 0; k < p->n; k++) {
        int j = p->map[k];
        p->k.x[j] += p->sign[k] * p->x[k];
        if (p->sign[k] > 0.0) p->k.zl[j] = p->z[k];
        else p->k.zu[j] = p->z[k];
        if (p->kind[k] == COL_BOXED) p->k.zu[j] = p->w[k];
    }
    if (p->border >= 0) p->k.x[p->border] = p->a;
    memcpy(p->k.y, p->y, (size_t)p->m * sizeof *p->k.y);
    p->k.a = p->a;
    p->k.mu = mu;
    p->k.set = 1;
}

static void warm_point(ipm *p)
{
    int n = p->n;
    double mu = p->k.mu;
    memcpy(p->y, p->k.y, (size_t)p->m * sizeof *p->y);
    PAR_FOR
    for (int k = 0; k < n; k++) {
        int j = p->map[k];
        double v = p->sign[k] * (p->k.x[j] - p->shift[j]);
        p->z[k] = fmax(p->sign[k] > 0.0 ? p->k.zl[j] : p->k.zu[j], mu);
        p->x[k] = fmax(v, mu / p->z[k]);
        if (p->kind[k] == COL_BOXED) {
            p->w[k] = fmax(p->k.zu[j], mu);
            double gap = mu / p->w[k];
            if (p->x[k] > p->U[k] - gap) p->x[k] = fmax(p->U[k] - gap, 0.5 * p->U[k]);
            p->s[k] = fmax(p->U[k] - p->x[k], gap);
            p->w[k] = fmin(p->w[k], KEEP_CAP * mu / p->s[k]);
        } else if (p->s) {
            p->s[k] = p->w[k] = 0.0;
        }
        p->z[k] = fmin(p->z[k], KEEP_CAP * mu / p->x[k]);
    }
    p->a = p->k.a;
}

static void answers(ipm *p)
{
    for (int j = 0; j < p->nu; j++) p->xu[j] = p->shift[j];
    for (int k = 0; k < p->n; k++) p->xu[p->map[k]] += p->sign[k] * p->x[k];
    if (p->border >= 0) p->xu[p->border] = p->a;
    /* internal duals are for minimizing -obj: the user's sign is flipped */
    for (int i = 0; i < p->m; i++) p->yu[i] = -p->y[i];
}

/* The early test for a dual ray (settings.early_infeasible).  Along an
 * infeasible problem's path y grows as y0 + t r, r a Farkas ray, long
 * before it passes the divergence test; the step r = y - yprev cancels
 * y0 (and with it g . y, which must vanish for the free alpha).  For a
 * feasible x, with e the largest positive (A^T r)_j over the columns
 * without an upper bound,
 *     b.r - sum over boxed columns of max(0, (A^T r)_j) U_j
 *         <= e sum_j x_j + alpha g.r,
 * so a positive left side L proves every feasible point to have
 * sum x >= L / (2e) or |alpha| >= L / (2 |g.r|).  The test passes when
 * L is more than round-off (RAY_MARGIN of |r| |b|: the dual of a feasible
 * set without interior also grows, along an r with b.r = 0) and both
 * bounds exceed RAY_FAR times the iterate's own, on RAY_RUN iterations in
 * a row: an equilibrium would need ten times the forces (or the load
 * multiplier) of the path.  Returns 1 when it passes, with r in
 * p->yprev (doc/theory.md 3.2, "Early dual ray"). */
#define RAY_FAR 10.0
#define RAY_RUN 2
#define RAY_MARGIN 1e-6
static int ray_test(ipm *p, int it, int *run)
{
    int m = p->m, n = p->n;
    if (!p->yprev) p->yprev = xcalloc((size_t)m, sizeof *p->yprev);
    if (!p->at) p->at = xcalloc((size_t)n, sizeof *p->at);
    if (!p->yprev || !p->at) return 0;
    double *r = p->yprev;
    for (int i = 0; i < m; i++) r[i] = p->y[i] - r[i];
    mul_At(p, r, p->at);
    double L = 0.0, e = 0.0, sx = 0.0;
    for (int i = 0; i < m; i++) L += p->b[i] * r[i];
    for (int j = 0; j < n; j++) {
        if (p->kind[j] == COL_BOXED) L -= fmax(p->at[j], 0.0) * p->U[j];
        else e = fmax(e, p->at[j]);
        sx += p->x[j];
    }
    double gr = p->border >= 0 ? fabs(dot(p->g, r, m)) : 0.0;
    double rn = inf_norm(r, m), bn = 1.0 + inf_norm(p->b, m);
    int pass = it >= 1 && L > RAY_MARGIN * rn * bn && L >= 2.0 * e * RAY_FAR * fmax(sx, 1.0) &&
               L >= 2.0 * gr * RAY_FAR * fmax(fabs(p->a), 1.0);
    *run = pass ? *run + 1 : 0;
    if (*run >= RAY_RUN) return 1;
    memcpy(r, p->y, (size_t)m * sizeof *r); /* yprev for the next iteration */
    return 0;
}

/* An iterate feasible to the tolerance whose gap is within NEAR_GAP times
 * it is kept; when the iterates after it lose their feasibility to
 * round-off and the solve fails, it is the answer (solve).  A dome of 2,000
 * voussoirs: primal residual 1.5e-10 and gap 9e-8 at iteration 31, then
 * the gap closed while the primal residual grew to 1e-5 ("numerical
 * trouble"); the answer is verified as any other. */
#define NEAR_GAP 10.0

typedef struct best_point {
    double *x, *z, *s, *w, *y, a, gap; /* x, z, s, w: n entries; y: m */
} best_point;

/* Copies the iterate into b (keep 1, allocating it the first time) or
 * back from it (keep 0). */
static void best_copy(ipm *p, best_point *b, int keep)
{
    size_t n = (size_t)p->n, m = (size_t)p->m;
    if (keep && !b->x) {
        b->x = malloc((4 * n + m + 1) * sizeof *b->x);
        if (!b->x) return;
        b->z = b->x + n, b->s = b->z + n, b->w = b->s + n, b->y = b->w + n;
    }
    /* the pairs of the upper bounds (s, w) exist where some column is boxed */
    double *it[] = {p->x, p->z, p->s, p->w, p->y}, *kept[] = {b->x, b->z, b->s, b->w, b->y};
    size_t len[] = {n, n, n, n, m};
    for (int k = 0; k < 5; k++)
        if (it[k]) memcpy(keep ? kept[k] : it[k], keep ? it[k] : kept[k], len[k] * sizeof(double));
    if (keep) b->a = p->a;
    else p->a = b->a;
}

static bl_lp_status solve(void *e)
{
    ipm *p = e;
    int n = p->n, m = p->m, nbox = 0;
    if (!p->N) return BL_LP_FAILED;
    for (int j = 0; j < n; j++) nbox += p->kind[j] == COL_BOXED;
    double t0 = bl_clock();
    double tol = p->set.tolerance;
    double bnorm = 1.0 + inf_norm(p->b, m), cnorm = 1.0 + inf_norm(p->c, n) + fabs(p->ca);
    double unorm = 1.0;
    for (int j = 0; j < n; j++)
        if (p->kind[j] == COL_BOXED) unorm = fmax(unorm, 1.0 + p->U[j]);
    p->iterations = p->factorizations = p->solves = 0;
    p->factor_time = p->solve_time = 0.0;
    bl_lp_status status = BL_LP_ITERATION_LIMIT;
    int keep = 1; /* no iterate of this solve kept yet */
    int shown = 0; /* a progress line is on the screen */
    double stall_gap = INFINITY, stall_mu = INFINITY; /* the last real fall of the gap */
    int stall_it = 0;
    double stall_ep = INFINITY; /* the last real fall of the primal residual */
    int stall_ep_it = 0;
    double low_ep = INFINITY, low_mu = INFINITY; /* the lowest primal residual yet, mu then */
    int low_ep_it = 0;
    int ray_run = 0; /* iterations in a row that passed ray_test */
    best_point best = {.gap = INFINITY};
    double xn_prev = INFINITY; /* the last iterate's largest force (divergence) */
    int foreign = p->k.foreign; /* the start is another problem's point */
    p->k.foreign = 0;
    int warm = p->k.warm && p->k.set; /* until the warm start has taken */
    double warm_r = INFINITY;         /* its first iteration's residual */
    if (warm) warm_point(p);
    else if (starting_point(p)) status = BL_LP_FAILED;
    weight_sum(p);
    for (int it = 0; status == BL_LP_ITERATION_LIMIT && it < p->set.max_iterations; it++) {
        if (bl_interrupt_pending()) { status = BL_LP_INTERRUPTED; break; }
        if (p->set.deadline > 0 && bl_clock() > p->set.deadline) {
            status = BL_LP_TIME_LIMIT;
            break;
        }
        /* residuals */
        mul_A(p, p->x, p->rp);
        for (int i = 0; i < m; i++) p->rp[i] = p->b[i] - p->rp[i] - p->g[i] * p->a;
        mul_At(p, p->y, p->rd);
        double gap_c = 0.0;
        PAR_FOR_WITH(reduction(+ : gap_c))
        for (int j = 0; j < n; j++) {
            p->rd[j] = p->c[j] - p->rd[j] - p->z[j];
            gap_c += p->x[j] * p->z[j];
            if (p->kind[j] == COL_BOXED) {
                p->rd[j] += p->w[j];
                p->ru[j] = p->U[j] - p->x[j] - p->s[j];
                gap_c += p->s[j] * p->w[j];
            } else if (p->ru) {
                p->ru[j] = 0.0;
            }
        }
        double ra = p->ca - dot(p->g, p->y, m);
        double mu = gap_c / p->wsum;
        double pobj = dot(p->c, p->x, n) + p->ca * p->a;
        double dobj = dot(p->b, p->y, m);
        for (int j = 0; j < n; j++)
            if (p->kind[j] == COL_BOXED) dobj -= p->U[j] * p->w[j];
        double ep = inf_norm(p->rp, m) / bnorm, eu = p->ru ? inf_norm(p->ru, n) / unorm : 0.0;
        double ed = fmax(inf_norm(p->rd, n), fabs(ra)) / cnorm;
        double eg = fabs(pobj - dobj) / (1.0 + fabs(pobj));
        if (p->set.verbose)
            fprintf(stderr, "ipm %3d  alpha %.10g  primal %.1e  dual %.1e  gap %.1e  mu %.1e\n",
                    it, p->a, ep, ed, eg, mu);
        else if (p->set.progress && bl_clock() - t0 > 0.5) {
            fprintf(stderr, "\rinterior point: iteration %d, largest residual %.1e (done at %.0e)   ", it,
                    fmax(fmax(ep, eu), fmax(ed, eg)), tol);
            shown = 1;
        }
        if (ep <= tol && eu <= tol && ed <= tol && eg <= tol) {
            status = BL_LP_OPTIMAL;
            break;
        }
        if (ep <= tol && eu <= tol && ed <= tol && eg <= NEAR_GAP * tol && eg < best.gap) {
            best_copy(p, &best, 1);
            if (best.x) best.gap = eg;
        }
        /* A warm start that does not take: its largest residual not halved
         * (nor within the tolerance) in WARM_PATIENCE iterations.  The
         * solve starts again from Mehrotra's point.  A certificate of the
         * 10,050-block wall's sequence, its slip threshold divided by 10,
         * started from the kept point of the certificate before it with a
         * primal residual of 120 and mu 1e-7, and its steps stayed below
         * 10^-2 until the limit of 200 iterations (doc/seqlp.md 12;
         * tests/test_warm.c). */
        if (warm) {
            double r = fmax(fmax(ep, eu), ed);
            if (it == 0) warm_r = r;
            if (r <= 0.5 * warm_r || r <= tol) {
                warm = 0;
            } else if (it >= WARM_PATIENCE) {
                warm = 0;
                if (p->set.verbose) fprintf(stderr, "ipm: the warm start did not take; a cold start\n");
                if (starting_point(p)) { status = BL_LP_FAILED; break; }
                weight_sum(p);
                if (p->yprev) memcpy(p->yprev, p->y, (size_t)m * sizeof *p->yprev);
                keep = 1;
                stall_gap = stall_ep = low_ep = low_mu = stall_mu = INFINITY;
                stall_it = stall_ep_it = low_ep_it = it;
                ray_run = 0;
                continue;
            }
        }
        if (p->set.early_infeasible && ep > tol && ray_test(p, it, &ray_run)) {
            memcpy(p->y, p->yprev, (size_t)m * sizeof *p->y); /* the ray, for ray() */
            status = BL_LP_INFEASIBLE;
            break;
        }
        if (keep && it >= 1 && fmax(fmax(ep, eu), fmax(ed, eg)) <= KEEP_AT) {
            /* a solve that began far below the level, from another
             * problem's point (bl_lp_warm), keeps its first iterate with
             * the products raised to it: at its own level the next bound
             * change would leave it off centre (the 1,040-block wall's
             * sequence from the path: re-solves of 20 and 17 iterations
             * instead of 8) */
            double level = fmax(fmax(ep, eu), fmax(ed, eg));
            keep = 0;
            keep_point(p, foreign && level < 0.1 * KEEP_AT ? mu * KEEP_AT / fmax(level, 1e-12) : mu);
        }
        /* A stalled gap: feasible to the tolerance, mu falling, the gap
         * not.  On an unbounded optimal face (blocks confined between
         * supports) the iterate follows the growing forces and the gap,
         * which then carries x times the residuals, never closes; that
         * ran to the iteration limit (doc/seqlp.md 13).  No solve that
         * converged was seen to keep its gap within 1 % for 10 iterations
         * while mu fell a hundredfold. */
        int feasible = ep <= tol && eu <= tol && ed <= tol;
        if (!feasible || eg < 0.99 * stall_gap) {
            stall_gap = feasible ? eg : INFINITY;
            stall_mu = mu;
            stall_it = it;
        } else if (it - stall_it >= 10 && mu < 0.01 * stall_mu) {
            /* ... unless what keeps the objectives apart is the primal
             * residual's round-off times the multipliers, with the
             * products themselves within the tolerance and the forces
             * bounded (at most BL_LP_CONFINED per row, lp.h; those of
             * confined blocks grew past 1e7 with the
             * products at 7e-9): then the point is optimal to the
             * tolerance (a 900-block wall with windows at mu = 0.5: the
             * primal residual stayed at 1.6e-10, y . rp made the gap
             * 1.1e-7, the products summed to 1e-16, the forces 193; its
             * answers are verified as any other) */
            double yr = dot(p->y, p->rp, m);
            status = gap_c <= tol * (1.0 + fabs(pobj)) && fabs(yr) >= 0.5 * fabs(pobj - dobj) &&
                             inf_norm(p->x, n) <= BL_LP_CONFINED * m
                         ? BL_LP_OPTIMAL
                         : BL_LP_FAILED;
            break;
        }
        /* A stalled primal residual, the other way round: gap and dual
         * residual within the tolerance, the primal residual above it and
         * not halving for 15 iterations.  Round-off in the steps does
         * that: a random-objective LP of the 10,050-block wall (the
         * sequence's restart, doc/seqlp.md 14) reached 1e-13 at iteration
         * 19, then stayed between 1e-7 and 1e-1 until the limit of 200. */
        if (!(eg <= tol && ed <= tol && eu <= tol) || ep < 0.5 * stall_ep) {
            stall_ep = eg <= tol && ed <= tol && eu <= tol ? ep : INFINITY;
            stall_ep_it = it;
        } else if (it - stall_ep_it >= 15) {
            status = BL_LP_FAILED;
            break;
        }
        /* Products gone, primal residual left: the residual not halving
         * for 30 iterations while mu fell a millionfold.  The iterate is
         * then pinned to the boundary and cannot remove the residual; an
         * LP with alpha fixed at a settled value (a certificate of the
         * sequence on a 4,258-block wall) reached 4e-3 at iteration 32,
         * then stayed at 0.2-0.8 with mu at 1e-10 until the limit of 200. */
        if (ep < 0.5 * low_ep) {
            low_ep = ep;
            low_mu = mu;
            low_ep_it = it;
        } else if (ep > tol && it - low_ep_it >= 30 && mu < 1e-6 * low_mu) {
            status = BL_LP_FAILED;
            break;
        }
        /* Divergence: an iterate growing without bound follows a ray.  A
         * dual ray whose objective grows (b.y - U.w > 0 while A^T y stays
         * feasible) certifies that no primal point exists; a primal ray
         * along which alpha grows (A x + g a = 0, x >= 0) that the problem
         * is unbounded.  Infeasibility is tested first: a model can have
         * both rays, and then it has no equilibrium. */
        double xn = fmax(inf_norm(p->x, n), fabs(p->a)), yn = inf_norm(p->y, m);
        if (xn > 1e8 || yn > 1e8) {
            double rdn = fmax(inf_norm(p->rd, n), fabs(ra));
            if (yn > 1e6 && dobj / yn > 1e-7 && rdn / yn < 1e-6) {
                status = BL_LP_INFEASIBLE;
                break;
            }
            /* ... and still growing: the forces under a dead point load
             * of 1e9 block weights are that large at the answer, and were
             * taken for a ray ("unbounded") */
            if (xn > 1e6 && xn > 1.5 * xn_prev && -pobj / xn > 1e-7 && inf_norm(p->rp, m) / xn < 1e-6) {
                status = BL_LP_UNBOUNDED;
                break;
            }
            if (xn > 1e14 || yn > 1e14) {
                status = BL_LP_FAILED;
                break;
            }
        }
        xn_prev = xn;

        PAR_FOR
        for (int j = 0; j < n; j++) {
            double d = p->z[j] / p->x[j];
            if (p->kind[j] == COL_BOXED) d += p->w[j] / p->s[j];
            p->theta[j] = 1.0 / d;
        }
        double delta;
        if (factor(p, &delta)) { status = BL_LP_FAILED; break; }
        double gv = 0.0;

        /* predictor: the affine-scaling direction */
        step *d = &p->dir;
        PAR_FOR
        for (int j = 0; j < n; j++) {
            p->xz[j] = -p->x[j] * p->z[j];
            if (p->sw) p->sw[j] = p->kind[j] == COL_BOXED ? -p->s[j] * p->w[j] : 0.0;
        }
        if (direction(p, d, 1, ra, &gv, 1)) { status = BL_LP_FAILED; break; }
        double tp = max_step(p, p->x, d->x, p->s, d->s);
        double td = max_step(p, p->z, d->z, p->w, d->w);
        double mu_aff = 0.0;
        PAR_FOR_WITH(reduction(+ : mu_aff))
        for (int j = 0; j < n; j++) {
            mu_aff += (p->x[j] + tp * d->x[j]) * (p->z[j] + td * d->z[j]);
            if (p->kind[j] == COL_BOXED)
                mu_aff += (p->s[j] + tp * d->s[j]) * (p->w[j] + td * d->w[j]);
        }
        mu_aff /= p->wsum;
        double sigma = fmin(pow(mu_aff / mu, 3.0), 1.0);

        /* Mehrotra's corrector: centring (on the weighted path) plus the
         * predictor's second-order term */
        PAR_FOR
        for (int j = 0; j < n; j++) {
            double wj = weight(p, j);
            p->xz[j] = sigma * mu * wj - p->x[j] * p->z[j] - d->x[j] * d->z[j];
            if (p->sw)
                p->sw[j] = p->kind[j] == COL_BOXED
                               ? sigma * mu * wj - p->s[j] * p->w[j] - d->s[j] * d->w[j]
                               : 0.0;
        }
        if (direction(p, d, 1, ra, &gv, 0)) { status = BL_LP_FAILED; break; }
        tp = max_step(p, p->x, d->x, p->s, d->s);
        td = max_step(p, p->z, d->z, p->w, d->w);

        /* Gondzio's correctors: push the products of the trial point at a
         * step longer by 0.2 back into [0.1, 10] sigma mu w_j, and keep the
         * correction while it lengthens the step.  Up to 10: a corrector
         * costs one solve, about 1/18 of a factorization, and most
         * iterations stop on their own after 1-5.  With the neighbourhood
         * safeguard below, 10 took 21/22/34/52 iterations at 1,040 /
         * 2,525 / 10,050 / 40,100 blocks against 22/26/35/58 with 5;
         * 15 gave 32 at 10,050 but 54 at 40,100. */
        for (int k = 0; k < 10 && fmin(tp, td) < 1.0; k++) {
            double ttp = fmin(1.0, tp + 0.2), ttd = fmin(1.0, td + 0.2);
            PAR_FOR
            for (int j = 0; j < n; j++) {
                double wj = weight(p, j);
                double lo = 0.1 * sigma * mu * wj, hi = 10.0 * sigma * mu * wj;
                double v = (p->x[j] + ttp * d->x[j]) * (p->z[j] + ttd * d->z[j]);
                p->xz[j] = v < lo ? lo - v : v > hi ? (v < 2.0 * hi ? hi - v : -hi) : 0.0;
                if (p->sw) p->sw[j] = 0.0;
                if (p->kind[j] == COL_BOXED) {
                    v = (p->s[j] + ttp * d->s[j]) * (p->w[j] + ttd * d->w[j]);
                    p->sw[j] = v < lo ? lo - v : v > hi ? (v < 2.0 * hi ? hi - v : -hi) : 0.0;
                }
            }
            step *c = &p->cor;
            if (direction(p, c, 0, 0.0, &gv, 0)) break;
            PAR_FOR
            for (int j = 0; j < n; j++) {
                c->x[j] += d->x[j];
                c->z[j] += d->z[j];
                if (c->s) {
                    c->s[j] += d->s[j];
                    c->w[j] += d->w[j];
                }
            }
            for (int i = 0; i < m; i++) c->y[i] += d->y[i];
            c->a += d->a;
            double np = max_step(p, p->x, c->x, p->s, c->s);
            double nd = max_step(p, p->z, c->z, p->w, c->w);
            if (fmin(np, nd) < fmin(tp, td) + 0.01) break;
            step t = p->dir;
            p->dir = *c;
            p->cor = t;
            d = &p->dir;
            tp = np;
            td = nd;
        }

        if (refine(p, d, gv)) { status = BL_LP_FAILED; break; }
        tp = fmin(1.0, 0.99 * max_step(p, p->x, d->x, p->s, d->s));
        td = fmin(1.0, 0.99 * max_step(p, p->z, d->z, p->w, d->w));
        /* Neighbourhood safeguard: shorten both steps until every product
         * is at least 0.01 mu w_j (mu the weighted mean).  A pair left at 1 % of its value
         * by the 0.99 rule blocks the following steps; 0.01 is the value
         * that helped at every size (0.1 and 0.02 cost iterations, and an
         * upper bound on the products, which grow on columns that change
         * class late, stalled the method). */
        for (int tries = 0; tries < 40; tries++) {
            double sum = 0.0, low = INFINITY;
            PAR_FOR_WITH(reduction(+ : sum) reduction(min : low))
            for (int j = 0; j < n; j++) {
                double wj = weight(p, j);
                double v = (p->x[j] + tp * d->x[j]) * (p->z[j] + td * d->z[j]);
                sum += v;
                if (v / wj < low) low = v / wj;
                if (p->kind[j] == COL_BOXED) {
                    v = (p->s[j] + tp * d->s[j]) * (p->w[j] + td * d->w[j]);
                    sum += v;
                    if (v / wj < low) low = v / wj;
                }
            }
            if (low >= 0.01 * sum / p->wsum) break;
            tp *= 0.95;
            td *= 0.95;
        }
        PAR_FOR
        for (int j = 0; j < n; j++) {
            p->x[j] += tp * d->x[j];
            p->z[j] += td * d->z[j];
            if (p->kind[j] == COL_BOXED) {
                p->s[j] += tp * d->s[j];
                p->w[j] += td * d->w[j];
            }
        }
        if (p->set.verbose) fprintf(stderr, "      steps %.3f %.3f sigma %.2e\n", tp, td, sigma);
        p->a += tp * d->a;
        for (int i = 0; i < m; i++) p->y[i] += td * d->y[i];
        p->iterations = it + 1;
    }
    if (status == BL_LP_FAILED && best.x) {
        best_copy(p, &best, 0);
        status = BL_LP_OPTIMAL;
        if (p->set.verbose)
            fprintf(stderr, "ipm: the iterates lost their feasibility: the best one, gap %.1e\n", best.gap);
    }
    free(best.x);
    if (shown) fprintf(stderr, "\r%79s\r", "");
    answers(p);
    if (p->set.verbose)
        fprintf(stderr, "ipm: %d iterations in %.3f s: %d factorizations %.3f s, %d solves %.3f s\n",
                p->iterations, bl_clock() - t0, p->factorizations, p->factor_time, p->solves,
                p->solve_time);
    p->k.warm = status == BL_LP_OPTIMAL;
    p->last = status;
    return status;
}

static const double *primal(const void *e) { return ((const ipm *)e)->xu; }
static const double *dual(const void *e) { return ((const ipm *)e)->yu; }
static int iterations(const void *e) { return ((const ipm *)e)->iterations; }

/* After an infeasibility certificate the dual iterate y points along the
 * ray (answers() left it, sign-flipped, in yu). */
static const double *ray(const void *e)
{
    const ipm *p = e;
    return p->last == BL_LP_INFEASIBLE ? p->yu : NULL;
}

static double factor_nnz(const void *e)
{
    const ipm *p = e;
    return p->N ? bl_normal_nnz(p->N) : 0.0;
}

/* bl_lp_mark, bl_lp_rewind: all that a solve leaves to the next is k
 * (the bounds are set again before it). */
static void copy_kept(kept *to, const kept *from, size_t nu, size_t m)
{
    memcpy(to->x, from->x, nu * sizeof *to->x);
    memcpy(to->zl, from->zl, nu * sizeof *to->zl);
    memcpy(to->zu, from->zu, nu * sizeof *to->zu);
    memcpy(to->y, from->y, m * sizeof *to->y);
    to->a = from->a;
    to->mu = from->mu;
    to->set = from->set;
    to->warm = from->warm;
}

static int mark(void *e)
{
    ipm *p = e;
    size_t nu = (size_t)p->nu, m = (size_t)p->m;
    kept *c = &p->saved;
    if (!c->x) {
        c->x = xcalloc(nu, sizeof *c->x);
        c->zl = xcalloc(nu, sizeof *c->zl);
        c->zu = xcalloc(nu, sizeof *c->zu);
        c->y = xcalloc(m, sizeof *c->y);
        if (!c->x || !c->zl || !c->zu || !c->y) return -1;
    }
    copy_kept(c, &p->k, nu, m);
    return 0;
}

static void rewind_to_mark(void *e)
{
    ipm *p = e;
    if (p->saved.x) copy_kept(&p->k, &p->saved, (size_t)p->nu, (size_t)p->m);
}

/* bl_lp_warm: the point becomes the kept one (in the internal signs: y
 * for minimizing -obj). */
static int warm(void *e, const double *x, const double *zl, const double *zu, const double *y,
                double mu)
{
    ipm *p = e;
    memcpy(p->k.x, x, (size_t)p->nu * sizeof *x);
    memcpy(p->k.zl, zl, (size_t)p->nu * sizeof *zl);
    memcpy(p->k.zu, zu, (size_t)p->nu * sizeof *zu);
    for (int i = 0; i < p->m; i++) p->k.y[i] = -y[i];
    p->k.a = p->border >= 0 ? x[p->border] : 0.0;
    p->k.mu = mu;
    p->k.set = p->k.warm = p->k.foreign = 1;
    return 0;
}

/* bl_lp_cold: the kept point is not used; the next solve takes the
 * starting point. */
static void cold(void *e)
{
    ipm *p = e;
    p->k.warm = 0;
}

const bl_lp_backend bl_lp_ipm_engine = {
    "ipm", create, destroy, set_bounds, set_objective, solve, primal, dual, iterations, factor_nnz, ray,
    mark, rewind_to_mark, warm, cold, NULL,
};
