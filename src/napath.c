/* napath.c - the path of the non-associative problem (napath.h).
 *
 * Unknowns per contact point: the normal force n and u = t / mu (so that
 * Coulomb's cone is |u| <= n), the slacks s1 = n - u, s2 = n + u, the normal
 * motion z and the multipliers w1, w2 of the two edges; per row the block
 * motion y; and alpha.  With a_n and a_u = mu a_t the point's columns,
 *
 *   sum_p a_n n + a_u u + g alpha = b          equilibrium
 *   a_n . y = z,  a_u . y = w2 - w1,  g . y = 1   the mechanism, no dilatancy
 *   n z = s1 w1 = s2 w2 = tau                  complementarity, tau -> 0
 *
 * (with a_n . y = z + w1 + w2 instead, the associative LP's optimality
 * conditions).  A Newton step eliminates everything but y: per point the
 * 2 x 2 block K = [Z 0; D S] (Z = z / n, S = w1 / s1 + w2 / s2,
 * D = w2 / s2 - w1 / s1), not symmetric because the cone's bound moves with
 * n while the motion it allows does not open the joint, and
 *
 *   M = sum_p [a_n a_u] K^-1 [a_n a_u]^T
 *
 * is factored by MUMPS (LU), alpha bordered out with a second solve.  Steps:
 * Mehrotra's predictor and corrector, separate primal and dual lengths at
 * 0.99 of the way to the boundary, the primal rows refined after each
 * solve (doc/theory.md 6.3; the measurements in doc/seqlp.md 15).
 */
#include "napath.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <dmumps_c.h>

#define MAXR 6 /* rows a 2D contact point's columns reach: two blocks' three */
#define STALL 20
/* Past its target the path goes on towards `deep` only while its products
 * halve at least every DEEP_STALL steps: on 29 running-bond walls of 16 to
 * 36 courses it went from 10^-3 to 10^-6 in 2 to 16 steps; on the
 * 2,525-block wall it stays near 9 x 10^-4 (doc/seqlp.md 15). */
#define DEEP_STALL 10

typedef struct path {
    int m, P;
    const double *b;
    double *g;                  /* the live load's column (m) */
    int *nk, *rows;             /* per point: rows reached and which (MAXR each) */
    double *vn, *vu;            /* per point: a_n and a_u on those rows */
    int *Mp, *Mi, *pos, *diag;  /* the pattern of M, each point's entries in it, its diagonal */
    double *Mx;
    double *i11, *i21, *i22;    /* K^-1 per point (its (1, 2) entry is 0) */
    DMUMPS_STRUC_C id;          /* MUMPS: M's coordinates (1-based), its factor */
    int *irn, *jcn, mumps;      /* mumps: id was initialized */
} path;

static void path_free(path *p)
{
    if (p->mumps) {
        p->id.job = -2;
        dmumps_c(&p->id);
    }
    free(p->irn);
    free(p->jcn);
    free(p->g);
    free(p->nk);
    free(p->rows);
    free(p->vn);
    free(p->vu);
    free(p->Mp);
    free(p->Mi);
    free(p->pos);
    free(p->diag);
    free(p->Mx);
    free(p->i11);
    free(p->i21);
    free(p->i22);
}

int bl_napath_applies(const bl_system *s)
{
    if (s->dim != 2 || s->form != BL_FRICTION_FIXED) return 0;
    for (int p = 0; p < s->npoints; p++)
        if (!(isfinite(s->mu[p]) && s->mu[p] > 0.0) || s->cohesion[p] != 0.0) return 0;
    int *count = calloc((size_t)s->npoints + 1, sizeof *count);
    if (!count) return 0;
    int ok = 1;
    for (int k = 0; k < s->nforce; k++) {
        int kind = s->col_kind[k];
        if (kind == BL_COL_NORMAL) count[s->col_point[k]] += 1;
        else if (kind == BL_COL_SHEAR) count[s->col_point[k]] += 16;
        else ok = 0;
    }
    for (int p = 0; p < s->npoints && ok; p++) ok = count[p] == 17;
    free(count);
    return ok;
}

/* A (row, column) entry of M with the index of the point's local entry
 * that adds to it, for sorting into the pattern. */
typedef struct entry {
    long long key;
    int id;
} entry;

static int by_key(const void *a, const void *b)
{
    long long x = ((const entry *)a)->key, y = ((const entry *)b)->key;
    return x < y ? -1 : x > y;
}

/* The points' columns, the pattern of M and its symbolic analysis. */
static int setup(path *p, const bl_system *s, bl_error *err)
{
    int m = p->m = s->nrows, P = p->P = s->npoints;
    p->b = s->rhs;
    p->g = calloc((size_t)m, sizeof *p->g);
    p->nk = calloc((size_t)P, sizeof *p->nk);
    p->rows = calloc((size_t)P * MAXR, sizeof *p->rows);
    p->vn = calloc((size_t)P * MAXR, sizeof *p->vn);
    p->vu = calloc((size_t)P * MAXR, sizeof *p->vu);
    p->pos = calloc((size_t)P * MAXR * MAXR, sizeof *p->pos);
    p->diag = calloc((size_t)m, sizeof *p->diag);
    p->i11 = calloc((size_t)P, sizeof *p->i11);
    p->i21 = calloc((size_t)P, sizeof *p->i21);
    p->i22 = calloc((size_t)P, sizeof *p->i22);
    size_t T = (size_t)P * MAXR * MAXR;
    entry *e = malloc((T + 1) * sizeof *e);
    if (!p->g || !p->nk || !p->rows || !p->vn || !p->vu || !p->pos || !p->diag || !p->i11 ||
        !p->i21 || !p->i22 || !e) {
        free(e);
        return bl_error_set(err, "solve: out of memory for the non-associative path");
    }
    for (int q = s->colptr[s->nforce]; q < s->colptr[s->nforce + 1]; q++)
        p->g[s->rowind[q]] = s->val[q];
    for (int k = 0; k < s->nforce; k++) {
        int pt = s->col_point[k], normal = s->col_kind[k] == BL_COL_NORMAL;
        double scale = normal ? 1.0 : s->mu[pt];
        int *r = p->rows + MAXR * pt;
        for (int q = s->colptr[k]; q < s->colptr[k + 1]; q++) {
            int i = s->rowind[q], a = 0;
            while (a < p->nk[pt] && r[a] != i) a++;
            if (a == p->nk[pt]) {
                if (a == MAXR) {
                    free(e);
                    return bl_error_set(err, "solve: a contact point reaches more than %d rows", MAXR);
                }
                r[a] = i;
                p->nk[pt]++;
            }
            (normal ? p->vn : p->vu)[MAXR * pt + a] += scale * s->val[q];
        }
    }
    size_t t = 0;
    for (int pt = 0; pt < P; pt++)
        for (int a = 0; a < p->nk[pt]; a++)
            for (int c = 0; c < p->nk[pt]; c++) {
                int i = p->rows[MAXR * pt + a], j = p->rows[MAXR * pt + c];
                e[t].key = (long long)j * m + i;
                e[t].id = (pt * MAXR + a) * MAXR + c;
                t++;
            }
    qsort(e, t, sizeof *e, by_key);
    size_t nnz = 0;
    for (size_t q = 0; q < t; q++) nnz += q == 0 || e[q].key != e[q - 1].key;
    p->Mp = calloc((size_t)m + 1, sizeof *p->Mp);
    p->Mi = malloc((nnz + 1) * sizeof *p->Mi);
    p->Mx = calloc(nnz + 1, sizeof *p->Mx);
    if (!p->Mp || !p->Mi || !p->Mx) {
        free(e);
        return bl_error_set(err, "solve: out of memory for the non-associative path");
    }
    for (int i = 0; i < m; i++) p->diag[i] = -1;
    long long k = -1;
    for (size_t q = 0; q < t; q++) {
        if (q == 0 || e[q].key != e[q - 1].key) {
            k++;
            int j = (int)(e[q].key / m), i = (int)(e[q].key % m);
            p->Mi[k] = i;
            p->Mp[j + 1]++;
            if (i == j) p->diag[i] = (int)k;
        }
        p->pos[e[q].id] = (int)k;
    }
    free(e);
    for (int j = 0; j < m; j++) p->Mp[j + 1] += p->Mp[j];
    for (int i = 0; i < m; i++)
        if (p->diag[i] < 0) return bl_error_set(err, "solve: row %d reaches no contact point", i);
    /* MUMPS, sequential: unsymmetric LU, AMD order (METIS keeps one
     * random state for the process, and the LP beside this one orders
     * its factor with it), messages off */
    int nz = p->Mp[m];
    p->irn = malloc((size_t)nz * sizeof *p->irn);
    p->jcn = malloc((size_t)nz * sizeof *p->jcn);
    if (!p->irn || !p->jcn) return bl_error_set(err, "solve: out of memory for the non-associative path");
    for (int j = 0; j < m; j++)
        for (int q = p->Mp[j]; q < p->Mp[j + 1]; q++) {
            p->irn[q] = p->Mi[q] + 1;
            p->jcn[q] = j + 1;
        }
    p->id.comm_fortran = -987654; /* the sequential library's stand-in communicator */
    p->id.par = 1;
    p->id.sym = 0;
    p->id.job = -1;
    dmumps_c(&p->id);
    p->mumps = 1;
    p->id.icntl[0] = p->id.icntl[1] = p->id.icntl[2] = -1;
    p->id.icntl[3] = 0;
    p->id.icntl[6] = 0;
    p->id.n = m;
    p->id.nnz = nz;
    p->id.irn = p->irn;
    p->id.jcn = p->jcn;
    p->id.a = p->Mx;
    p->id.job = 1;
    dmumps_c(&p->id);
    if (p->id.infog[0] < 0)
        return bl_error_set(err, "solve: MUMPS could not analyse the path's matrix (%d)", p->id.infog[0]);
    return 0;
}

/* tn, tu = a_n . y, a_u . y per point */
static void products_t(const path *p, const double *y, double *tn, double *tu)
{
    for (int pt = 0; pt < p->P; pt++) {
        double sn = 0.0, su = 0.0;
        for (int a = 0; a < p->nk[pt]; a++) {
            double yi = y[p->rows[MAXR * pt + a]];
            sn += p->vn[MAXR * pt + a] * yi;
            su += p->vu[MAXR * pt + a] * yi;
        }
        tn[pt] = sn;
        tu[pt] = su;
    }
}

/* out = sum_p a_n dn + a_u du (m) */
static void products(const path *p, const double *dn, const double *du, double *out)
{
    memset(out, 0, (size_t)p->m * sizeof *out);
    for (int pt = 0; pt < p->P; pt++)
        for (int a = 0; a < p->nk[pt]; a++)
            out[p->rows[MAXR * pt + a]] += p->vn[MAXR * pt + a] * dn[pt] + p->vu[MAXR * pt + a] * du[pt];
}

/* Fills M from i11, i21, i22 and factors it: 0 or -1. */
static int factor(path *p, double reg)
{
    memset(p->Mx, 0, (size_t)p->Mp[p->m] * sizeof *p->Mx);
    for (int pt = 0; pt < p->P; pt++) {
        const double *vn = p->vn + MAXR * pt, *vu = p->vu + MAXR * pt;
        const int *pos = p->pos + MAXR * MAXR * pt;
        double i11 = p->i11[pt], i21 = p->i21[pt], i22 = p->i22[pt];
        int nk = p->nk[pt];
        for (int a = 0; a < nk; a++)
            for (int c = 0; c < nk; c++)
                p->Mx[pos[MAXR * a + c]] += i11 * vn[a] * vn[c] + i21 * vu[a] * vn[c] + i22 * vu[a] * vu[c];
    }
    for (int i = 0; i < p->m; i++) p->Mx[p->diag[i]] += reg;
    p->id.job = 2;
    dmumps_c(&p->id);
    return p->id.infog[0] < 0 ? -1 : 0;
}

static int msolve(path *p, double *x, const double *rhs)
{
    memcpy(x, rhs, (size_t)p->m * sizeof *x);
    p->id.rhs = x;
    p->id.job = 3;
    dmumps_c(&p->id);
    return p->id.infog[0] < 0 ? -1 : 0;
}


static double amax(const double *v, int n)
{
    double a = 0.0;
    for (int i = 0; i < n; i++) a = fmax(a, fabs(v[i]));
    return a;
}

static double dot(const double *a, const double *b, int n)
{
    double s = 0.0;
    for (int i = 0; i < n; i++) s += a[i] * b[i];
    return s;
}

/* The iterate and a direction, per point (n, u, z, w1, w2, s1, s2), per row
 * (y) and alpha. */
typedef struct point {
    double *n, *u, *z, *w1, *w2, *s1, *s2, *y, a;
} point;

/* Its per-point vectors, the primal ones (n, u, s1, s2) first. */
enum { NV = 7, NPRIMAL = 4 };
static void vecs(point *x, double ***v)
{
    double **a[NV] = {&x->n, &x->u, &x->s1, &x->s2, &x->z, &x->w1, &x->w2};
    memcpy(v, a, sizeof a);
}

static int point_alloc(point *x, int P, int m)
{
    double **v[NV];
    vecs(x, v);
    for (int k = 0; k < NV; k++)
        if (!(*v[k] = calloc((size_t)P + 1, sizeof **v[k]))) return -1;
    return (x->y = calloc((size_t)m + 1, sizeof *x->y)) ? 0 : -1;
}

static void point_free(point *x)
{
    double **v[NV];
    vecs(x, v);
    for (int k = 0; k < NV; k++) free(*v[k]);
    free(x->y);
}

/* Residuals of the current iterate (their signs as the Newton step removes them). */
typedef struct resid {
    double *rp, *rn, *ru, *rs1, *rs2, ra;
} resid;

/* The work of one Newton direction. */
typedef struct work {
    double *tn, *tu, *hn, *hu, *qn, *qu, *r1, *v1, *vg, *e;
    double gvg;
} work;

/* One direction d for the complementarity targets c0, c1, c2 (per point:
 * n z, s1 w1, s2 w2 are to become c + current), from the factor of M. */
static int direction(path *p, const point *x, const resid *r, work *w,
                     const double *c0, const double *c1, const double *c2, point *d)
{
    int P = p->P, m = p->m;
    double *e0 = d->z, *e1 = d->w1, *e2 = d->w2; /* used as scratch, set below */
    for (int q = 0; q < P; q++) {
        e0[q] = c0[q] / x->n[q];
        e1[q] = (c1[q] - x->w1[q] * r->rs1[q]) / x->s1[q];
        e2[q] = (c2[q] - x->w2[q] * r->rs2[q]) / x->s2[q];
        w->hn[q] = -r->rn[q] + e0[q];
        w->hu[q] = -r->ru[q] + e2[q] - e1[q];
        w->qn[q] = p->i11[q] * w->hn[q];
        w->qu[q] = p->i21[q] * w->hn[q] + p->i22[q] * w->hu[q];
    }
    products(p, w->qn, w->qu, w->r1);
    for (int i = 0; i < m; i++) w->r1[i] = r->rp[i] - w->r1[i];
    if (msolve(p, w->v1, w->r1)) return -1;
    d->a = (-r->ra + dot(p->g, w->v1, m)) / w->gvg;
    for (int i = 0; i < m; i++) d->y[i] = w->vg[i] * d->a - w->v1[i];
    products_t(p, d->y, w->tn, w->tu);
    for (int q = 0; q < P; q++) {
        d->n[q] = w->qn[q] - p->i11[q] * w->tn[q];
        d->u[q] = w->qu[q] - (p->i21[q] * w->tn[q] + p->i22[q] * w->tu[q]);
    }
    /* refine the primal rows and g . dy (round-off in M^-1 along the
     * mechanism, as in the LP engine) */
    double rpn = amax(r->rp, m);
    for (int pass = 0; pass < 3; pass++) {
        products(p, d->n, d->u, w->e);
        for (int i = 0; i < m; i++) w->e[i] = r->rp[i] - w->e[i] - p->g[i] * d->a;
        double ea = -r->ra - dot(p->g, d->y, m);
        if (amax(w->e, m) <= 1e-14 * (1.0 + rpn) && fabs(ea) <= 1e-15) break;
        if (msolve(p, w->v1, w->e)) return -1;
        double da = (ea + dot(p->g, w->v1, m)) / w->gvg;
        for (int i = 0; i < m; i++) {
            double dy = w->vg[i] * da - w->v1[i];
            d->y[i] += dy;
            w->v1[i] = dy;
        }
        d->a += da;
        products_t(p, w->v1, w->tn, w->tu);
        for (int q = 0; q < P; q++) {
            d->n[q] -= p->i11[q] * w->tn[q];
            d->u[q] -= p->i21[q] * w->tn[q] + p->i22[q] * w->tu[q];
        }
    }
    for (int q = 0; q < P; q++) {
        d->s1[q] = d->n[q] - d->u[q] + r->rs1[q];
        d->s2[q] = d->n[q] + d->u[q] + r->rs2[q];
        double W1 = x->w1[q] / x->s1[q], W2 = x->w2[q] / x->s2[q];
        d->z[q] = e0[q] - x->z[q] / x->n[q] * d->n[q];
        d->w1[q] = e1[q] - W1 * (d->n[q] - d->u[q]);
        d->w2[q] = e2[q] - W2 * (d->n[q] + d->u[q]);
    }
    return 0;
}

static double ratio(const double *v, const double *dv, int n)
{
    double t = 1.0;
    for (int i = 0; i < n; i++)
        if (dv[i] < 0.0 && -v[i] / dv[i] < t) t = -v[i] / dv[i];
    return t;
}

static void lengths(const point *x, const point *d, int P, double *tp, double *td)
{
    *tp = fmin(ratio(x->n, d->n, P), fmin(ratio(x->s1, d->s1, P), ratio(x->s2, d->s2, P)));
    *td = fmin(ratio(x->z, d->z, P), fmin(ratio(x->w1, d->w1, P), ratio(x->w2, d->w2, P)));
}

/* The starting point: forces from the least-squares solution of the
 * equilibrium rows, moved inside the cone by a tenth of the largest; the
 * mechanism g / |g|^2; unit motions and multipliers. */
static int start(path *p, point *x, work *w)
{
    int P = p->P, m = p->m;
    for (int q = 0; q < P; q++) {
        p->i11[q] = p->i22[q] = 1.0;
        p->i21[q] = 0.0;
    }
    if (factor(p, 1e-8) || msolve(p, w->v1, p->b)) return -1;
    products_t(p, w->v1, w->tn, w->tu);
    double sc = fmax(1.0, amax(w->tn, P));
    for (int q = 0; q < P; q++) {
        x->u[q] = w->tu[q];
        x->n[q] = fabs(w->tn[q]) + 0.1 * sc + fabs(w->tu[q]);
        x->s1[q] = x->n[q] - x->u[q];
        x->s2[q] = x->n[q] + x->u[q];
        x->z[q] = x->w1[q] = x->w2[q] = 1.0;
    }
    double gg = dot(p->g, p->g, m);
    for (int i = 0; i < m; i++) x->y[i] = gg > 0.0 ? p->g[i] / gg : 0.0;
    x->a = 0.0;
    return 0;
}

/* The point x in the terms of s's columns (bl_napath_run); 1 when it is
 * not finite (nothing is written). */
static int export_point(const bl_system *s, const point *x, int m, double *xo, double *zl,
                        double *zu, double *yo)
{
    for (int q = 0; q < s->npoints; q++)
        if (!isfinite(x->n[q]) || !isfinite(x->u[q])) return 1;
    for (int k = 0; k < s->nforce; k++) {
        int q = s->col_point[k];
        double mu_q = s->mu[q];
        if (s->col_kind[k] == BL_COL_NORMAL) {
            xo[k] = x->n[q];
            zl[k] = x->z[q];
            zu[k] = 0.0;
        } else { /* t = mu u; t + mu n = mu s2, mu n - t = mu s1 */
            xo[k] = mu_q * x->u[q];
            zl[k] = x->w2[q] / mu_q;
            zu[k] = x->w1[q] / mu_q;
        }
    }
    xo[s->nforce] = x->a;
    zl[s->nforce] = zu[s->nforce] = 0.0;
    memcpy(yo, x->y, (size_t)m * sizeof *yo);
    return 0;
}

int bl_napath_run(const bl_system *s, double target, double near, double deep, int max_iterations,
                  double deadline, const atomic_int *cancel, int report, double *xo, double *zl,
                  double *zu, double *yo, bl_napath_result *res, bl_error *err)
{
    double t0 = bl_clock();
    memset(res, 0, sizeof *res);
    path p = {0};
    point x = {0}, d = {0}, c = {0};
    resid r = {0};
    work w = {0};
    double *c0 = NULL, *c1 = NULL, *c2 = NULL;
    int ret = -1;
    int at_target = 0;           /* the outputs hold the point at target; going deeper */
    int shown = 0;               /* a progress line is on the screen */
    bl_napath_result snap = {0}; /* that point's result */
    if (setup(&p, s, err)) goto done;
    int P = p.P, m = p.m;
    double **rv[] = {&r.rp, &r.rn, &r.ru, &r.rs1, &r.rs2, &w.tn, &w.tu, &w.hn, &w.hu, &w.qn,
                     &w.qu, &w.r1, &w.v1, &w.vg, &w.e, &c0, &c1, &c2};
    int bad = point_alloc(&x, P, m) || point_alloc(&d, P, m) || point_alloc(&c, P, m);
    for (size_t k = 0; k < sizeof rv / sizeof *rv; k++)
        bad |= !(*rv[k] = calloc((size_t)(P > m ? P : m) + 1, sizeof **rv[k]));
    if (bad) {
        bl_error_set(err, "solve: out of memory for the non-associative path");
        goto done;
    }
    ret = 1;
    if (start(&p, &x, &w)) goto done;
    double bn = 1.0 + amax(p.b, m), best = INFINITY;
    int best_it = 0;
    for (int it = 0; it < max_iterations; it++) {
        if (bl_interrupt_pending() || (deadline > 0 && bl_clock() > deadline) ||
            (cancel && atomic_load(cancel))) {
            res->stopped = 1;
            goto done;
        }
        /* residuals */
        products(&p, x.n, x.u, r.rp);
        for (int i = 0; i < m; i++) r.rp[i] = p.b[i] - r.rp[i] - p.g[i] * x.a;
        products_t(&p, x.y, w.tn, w.tu);
        double gap = 0.0;
        for (int q = 0; q < P; q++) {
            r.rn[q] = w.tn[q] - x.z[q];
            r.ru[q] = w.tu[q] - x.w2[q] + x.w1[q];
            r.rs1[q] = x.n[q] - x.u[q] - x.s1[q];
            r.rs2[q] = x.n[q] + x.u[q] - x.s2[q];
            gap += x.n[q] * x.z[q] + x.s1[q] * x.w1[q] + x.s2[q] * x.w2[q];
        }
        r.ra = dot(p.g, x.y, m) - 1.0;
        double mu = gap / (3.0 * P);
        double ep = fmax(amax(r.rp, m), fmax(amax(r.rs1, P), amax(r.rs2, P))) / bn;
        double ed = fmax(fmax(amax(r.rn, P), amax(r.ru, P)), fabs(r.ra)) / (1.0 + amax(x.y, m));
        res->complementarity = gap / (1.0 + fabs(x.a));
        res->mu = mu;
        res->alpha = x.a;
        res->iterations = it;
        if (report == BL_NAPATH_VERBOSE)
            fprintf(stderr, "napath %3d  alpha %.10g  primal %.1e  dual %.1e  products %.1e\n", it, x.a,
                    ep, ed, res->complementarity);
        else if (report == BL_NAPATH_PROGRESS && bl_clock() - t0 > 0.5) {
            fprintf(stderr, "\rseqlp: the path, step %d, products %.1e   ", it, res->complementarity);
            shown = 1;
        }
        if (!isfinite(gap) || !isfinite(ep) || !isfinite(ed)) goto done;
        int central = ep <= 1e-6 && ed <= 1e-6;
        if (at_target) {
            if (central && res->complementarity <= deep) {
                res->deep = 1;
                break;
            }
            if (res->complementarity < 0.5 * best) {
                best = res->complementarity;
                best_it = it;
            }
            if (it - best_it >= DEEP_STALL || it == max_iterations - 1) goto done;
        } else if (central && res->complementarity <= target) {
            ret = 0;
            if (deep >= target || it == max_iterations - 1) break;
            if (export_point(s, &x, m, xo, zl, zu, yo)) {
                ret = 1;
                goto done;
            }
            snap = *res;
            at_target = 1;
            best = res->complementarity;
            best_it = it;
        } else {
            /* stalled (the products not halved in STALL steps: random wall
             * 11 of the tests at mu = 1 stays at 2e-2 from step 11 on) or
             * at the last step: taken when near enough */
            if (res->complementarity < 0.5 * best) {
                best = res->complementarity;
                best_it = it;
            }
            if (it - best_it >= STALL || it == max_iterations - 1) {
                if (central && res->complementarity <= near) ret = 0;
                break;
            }
        }
        /* the blocks of K^-1 and the factor */
        for (int q = 0; q < P; q++) {
            double Z = x.z[q] / x.n[q], W1 = x.w1[q] / x.s1[q], W2 = x.w2[q] / x.s2[q];
            double S = W1 + W2, D = W2 - W1;
            p.i11[q] = 1.0 / Z;
            p.i21[q] = -D / (Z * S);
            p.i22[q] = 1.0 / S;
        }
        if (factor(&p, 1e-12) || msolve(&p, w.vg, p.g)) goto done;
        w.gvg = dot(p.g, w.vg, m);
        /* predictor */
        for (int q = 0; q < P; q++) {
            c0[q] = -x.n[q] * x.z[q];
            c1[q] = -x.s1[q] * x.w1[q];
            c2[q] = -x.s2[q] * x.w2[q];
        }
        double tp, td;
        if (direction(&p, &x, &r, &w, c0, c1, c2, &d)) goto done;
        lengths(&x, &d, P, &tp, &td);
        double aff = 0.0;
        for (int q = 0; q < P; q++)
            aff += (x.n[q] + tp * d.n[q]) * (x.z[q] + td * d.z[q]) +
                   (x.s1[q] + tp * d.s1[q]) * (x.w1[q] + td * d.w1[q]) +
                   (x.s2[q] + tp * d.s2[q]) * (x.w2[q] + td * d.w2[q]);
        double sigma = fmin(1.0, pow(aff / (3.0 * P) / mu, 3.0));
        /* corrector: centring and the predictor's second-order term */
        for (int q = 0; q < P; q++) {
            c0[q] = sigma * mu - x.n[q] * x.z[q] - d.n[q] * d.z[q];
            c1[q] = sigma * mu - x.s1[q] * x.w1[q] - d.s1[q] * d.w1[q];
            c2[q] = sigma * mu - x.s2[q] * x.w2[q] - d.s2[q] * d.w2[q];
        }
        if (direction(&p, &x, &r, &w, c0, c1, c2, &c)) goto done;
        lengths(&x, &c, P, &tp, &td);
        tp = fmin(1.0, 0.99 * tp);
        td = fmin(1.0, 0.99 * td);
        double **xv[NV], **cv[NV];
        vecs(&x, xv);
        vecs(&c, cv);
        for (int k = 0; k < NV; k++) {
            double t = k < NPRIMAL ? tp : td;
            for (int q = 0; q < P; q++) (*xv[k])[q] += t * (*cv[k])[q];
        }
        for (int i = 0; i < m; i++) x.y[i] += td * c.y[i];
        x.a += tp * c.a;
        res->iterations = it + 1;
    }
    if (ret == 0 && export_point(s, &x, m, xo, zl, zu, yo)) {
        if (!at_target) ret = 1;
        res->deep = 0;
    }
done:
    /* not deeper: the point at target stands, as exported (the steps
     * counted are all that were taken) */
    if (at_target && !res->deep) {
        int steps = res->iterations;
        *res = snap;
        res->iterations = steps;
    }
    res->seconds = bl_clock() - t0;
    if (shown) fprintf(stderr, "\r%60s\r", "");
    path_free(&p);
    point_free(&x);
    point_free(&d);
    point_free(&c);
    double **rv2[] = {&r.rp, &r.rn, &r.ru, &r.rs1, &r.rs2, &w.tn, &w.tu, &w.hn, &w.hu, &w.qn,
                      &w.qu, &w.r1, &w.v1, &w.vg, &w.e, &c0, &c1, &c2};
    for (size_t k = 0; k < sizeof rv2 / sizeof *rv2; k++) free(*rv2[k]);
    return ret;
}
