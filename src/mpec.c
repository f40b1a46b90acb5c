#include "mpec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <IpStdCInterface.h>

#include "assemble.h"
#include "verify.h"

void bl_mpec_options_default(bl_mpec_options *o)
{
    bl_seqlp_options_default(&o->seq);
    o->nonassociative = 1;
    o->comp = BL_MPEC_PENALTY;
    o->start = BL_MPEC_START_SEQLP;
    o->penalty = 100.0;
    o->iterations = 3000;
}

/* Ipopt's "infinite" bound. */
#define BIG 1e20

/* The nonlinear program (doc/theory.md, 6.1, Eqs. T17-T21).  Variables: alpha,
 * the force columns x of the cone system, the row multipliers u, then slip
 * rates s+, s- (per point that slides), distances c+, c- of a cohesion
 * column from its bounds, and one slack z per complementary pair whose
 * second member is a linear expression.  Constraints: the linear rows
 * (triplets), then, with a relaxation, one row a b <= eps per pair. */
typedef struct nlp {
    int n, m;                /* variables, constraints */
    int nlin;                /* linear constraint rows */
    int nnz;                 /* linear Jacobian entries */
    int *jr, *jc;            /* their rows and columns */
    double *jv;              /* and values */
    int npairs;
    int *pa, *pb;            /* complementary pairs of variables */
    double *lo, *hi, *glo, *ghi;
    int relax;               /* the a b <= eps rows are present */
    double rho;              /* penalty weight, 0 when off */
    int iterations;          /* counted by the intermediate callback */
    double deadline;         /* bl_clock() time to stop at (late), 0: none */
    int late;
} nlp;

static void nlp_free(nlp *p)
{
    free(p->jr);
    free(p->jc);
    free(p->jv);
    free(p->pa);
    free(p->pb);
    free(p->lo);
    free(p->hi);
    free(p->glo);
    free(p->ghi);
}

/* A growing list of triplets and constraint rows. */
static int add(nlp *p, int *cap, int row, int col, double v)
{
    if (v == 0.0) return 0;
    if (p->nnz == *cap) {
        int c = *cap ? 2 * *cap : 1024;
        int *r = realloc(p->jr, (size_t)c * sizeof *r);
        if (r) p->jr = r;
        int *k = realloc(p->jc, (size_t)c * sizeof *k);
        if (k) p->jc = k;
        double *x = realloc(p->jv, (size_t)c * sizeof *x);
        if (x) p->jv = x;
        if (!r || !k || !x) return -1;
        *cap = c;
    }
    p->jr[p->nnz] = row;
    p->jc[p->nnz] = col;
    p->jv[p->nnz++] = v;
    return 0;
}

/* Adds coef times a column of the fixed system (the relative velocity of
 * a contact point, as a linear form in u) to row `row`. */
static int add_motion(nlp *p, int *cap, const bl_system *f, int col, int u0, int row, double coef)
{
    for (int q = f->colptr[col]; q < f->colptr[col + 1]; q++)
        if (add(p, cap, row, u0 + f->rowind[q], coef * f->val[q])) return -1;
    return 0;
}

/* Where each contact point's variables are. */
typedef struct layout {
    int nx, nu, x0, u0;      /* x at x0 (alpha at 0), u at u0 */
    int *jn, *js;            /* per point: its normal and shear column in the fixed system */
    int *js2;                /* 3D: per point, a second shear column */
    int *jt;                 /* 3D resultant model: per lead point, its twist column */
    double *K;               /* 3D: per point, (dt2, dt3) = K (w[js], w[js2]), row-major 2x2 */
    int *sp;                 /* per point: index of s+ (s- follows), or -1; 3D: of eta */
    int *cc;                 /* per cone column: index of c+ (c- follows), or -1 */
    int *sg;                 /* 3D: per cohesion column, its slip sigma+ (sigma- follows) */
    int *vd;                 /* 3D: per point, its velocity dn (dt2, dt3 follow), or -1 */
    int *vw;                 /* 3D resultant model: per lead point, its twist rho omega, or -1 */
    int *zc;                 /* per cone column: its slack z, or -1 */
} layout;

static void layout_free(layout *l)
{
    free(l->jn);
    free(l->js);
    free(l->js2);
    free(l->jt);
    free(l->vw);
    free(l->K);
    free(l->sg);
    free(l->vd);
    free(l->sp);
    free(l->cc);
    free(l->zc);
}

/* 3D: adds c2 dt2 + c3 dt3 of point q, as linear forms in u, to row
 * `row`: the slip along t2 and t3, from the powers of two of the fixed
 * form's shear columns. */
static int add_tangent(nlp *p, int *cap, const bl_system *f, const layout *l, int q, int row,
                       double c2, double c3)
{
    const double *K = l->K + 4 * q;
    if (add_motion(p, cap, f, l->js[q], l->u0, row, c2 * K[0] + c3 * K[2])) return -1;
    return add_motion(p, cap, f, l->js2[q], l->u0, row, c2 * K[1] + c3 * K[3]);
}

/* 3D: adds cn dn + c2 dt2 + c3 dt3 + cw tw for point q to row `row`: dn
 * of q, the slip (dt2, dt3) and, in the resultant model, the twist tw of
 * the point that leads q's joint (q itself in the vertex model). */
static int add_velocity(nlp *p, int *cap, const bl_system *c, const layout *l, int q, int row,
                        double cn, double c2, double c3, double cw)
{
    int g = c->lead[q], v = l->vd[g];
    return add(p, cap, row, l->vd[q], cn) || add(p, cap, row, v + 1, c2) ||
           add(p, cap, row, v + 2, c3) || (l->vw[g] >= 0 && add(p, cap, row, l->vw[g], cw));
}

/* Where the contact points' motions are in the fixed system f: per point
 * its normal column, its (first two) shear columns and, in 3D, the inverse
 * K of their tangential directions.  Returns 0 or -1. */
static int motion_columns(layout *l, const bl_system *f)
{
    int np = f->npoints;
    l->jn = malloc(((size_t)np + 1) * sizeof *l->jn);
    l->js = malloc(((size_t)np + 1) * sizeof *l->js);
    l->js2 = malloc(((size_t)np + 1) * sizeof *l->js2);
    l->jt = malloc(((size_t)np + 1) * sizeof *l->jt);
    l->K = calloc(4 * (size_t)np + 1, sizeof *l->K);
    if (!l->jn || !l->js || !l->js2 || !l->jt || !l->K) return -1;
    for (int q = 0; q < np; q++) l->jn[q] = l->js[q] = l->js2[q] = l->jt[q] = -1;
    for (int j = 0; j < f->nforce; j++) {
        int q = f->col_point[j];
        if (f->col_kind[j] == BL_COL_NORMAL) l->jn[q] = j;
        if (f->col_kind[j] == BL_COL_TWIST) l->jt[q] = j;
        const double *nt = f->col_nt + f->dim * j;
        int along = nt[1] != 0.0 || (f->dim == 3 && nt[2] != 0.0); /* not a free couple */
        if (f->col_kind[j] == BL_COL_SHEAR && along) {
            if (l->js[q] < 0) l->js[q] = j;
            else if (l->js2[q] < 0) l->js2[q] = j;
        }
    }
    for (int q = 0; f->dim == 3 && q < np; q++) {
        if (f->lead[q] != q) continue; /* a resultant joint's slip is its lead's */
        if (l->js2[q] < 0) {
            /* a rigid joint's points but its first have none (assemble3.c):
             * their slip, held at zero, is not read from the motions */
            if (isinf(f->mu[q])) continue;
            return -1; /* every other 3D point has two */
        }
        const double *a = f->col_nt + 3 * l->js[q], *b = f->col_nt + 3 * l->js2[q];
        double det = a[1] * b[2] - a[2] * b[1], *K = l->K + 4 * q;
        K[0] = b[2] / det;
        K[1] = -a[2] / det;
        K[2] = -b[1] / det;
        K[3] = a[1] / det;
    }
    return 0;
}

/* Builds the program of the cone system c (and its fixed twin f) for the
 * flow rule asked.  Returns 0 or -1 (out of memory). */
static int build(nlp *p, layout *l, const bl_system *c, const bl_system *f, int nonassoc,
                 double eps)
{
    int np = c->npoints, nx = c->nforce, nu = c->nrows, d3 = c->dim == 3, st = c->dim;
    l->nx = nx;
    l->nu = nu;
    l->x0 = 1;
    l->u0 = 1 + nx;
    l->sp = malloc(((size_t)np + 1) * sizeof *l->sp);
    l->cc = malloc(((size_t)nx + 1) * sizeof *l->cc);
    l->sg = malloc(((size_t)nx + 1) * sizeof *l->sg);
    l->zc = malloc(((size_t)nx + 1) * sizeof *l->zc);
    l->vd = malloc(((size_t)np + 1) * sizeof *l->vd);
    l->vw = malloc(((size_t)np + 1) * sizeof *l->vw);
    if (!l->sp || !l->cc || !l->sg || !l->zc || !l->vd || !l->vw || motion_columns(l, f)) return -1;
    for (int q = 0; q < np; q++) l->sp[q] = l->vd[q] = l->vw[q] = -1;

    /* variables: per point the slip rates s+- (2D, where it can slide) or
     * eta (3D, pyramid edges, without dilatancy; per joint in the resultant
     * model); cohesion distances (and in 3D the slip along each cohesion
     * column); slacks.  3D: per point its velocity, and per resultant
     * joint its twist */
    int n = l->u0 + nu, npairs = 0;
    for (int q = 0; d3 && q < np; q++) {
        if (l->jn[q] >= 0) {
            l->vd[q] = n;
            n += 3;
        }
        if (l->jt[q] >= 0) l->vw[q] = n++;
    }
    for (int j = 0; j < nx; j++) {
        int q = c->col_point[j], k = c->col_kind[j];
        int cone = k == BL_COL_CONE_POS || k == BL_COL_CONE_NEG;
        if (!d3 && ((cone && nonassoc) || k == BL_COL_COHESION) && l->sp[q] < 0) {
            l->sp[q] = n;
            n += 2;
        }
        if (d3 && k == BL_COL_PYRAMID && nonassoc && l->sp[c->lead[q]] < 0) l->sp[c->lead[q]] = n++;
    }
    for (int j = 0; j < nx; j++) {
        int k = c->col_kind[j];
        l->cc[j] = l->sg[j] = l->zc[j] = -1;
        if (k == BL_COL_COHESION) {
            l->cc[j] = n;
            n += 2;
            if (d3) {
                l->sg[j] = n;
                n += 2;
            }
            npairs += 2;
        } else if (k != BL_COL_SHEAR) {
            l->zc[j] = n++;
            npairs++;
        }
    }
    p->n = n;
    p->npairs = npairs;
    p->lo = malloc((size_t)n * sizeof *p->lo);
    p->hi = malloc((size_t)n * sizeof *p->hi);
    p->pa = malloc(((size_t)npairs + 1) * sizeof *p->pa);
    p->pb = malloc(((size_t)npairs + 1) * sizeof *p->pb);
    if (!p->lo || !p->hi || !p->pa || !p->pb) return -1;
    for (int v = 0; v < n; v++) {
        p->lo[v] = 0.0;
        p->hi[v] = BIG;
    }
    p->lo[0] = -BIG;
    for (int j = 0; j < nx; j++) {
        p->lo[l->x0 + j] = isinf(c->lo[j]) ? -BIG : c->lo[j];
        p->hi[l->x0 + j] = isinf(c->hi[j]) ? BIG : c->hi[j];
    }
    for (int i = 0; i < nu; i++) p->lo[l->u0 + i] = -BIG;
    /* 3D: dn >= 0; free slip and twist, none where the joint is rigid (or
     * at a resultant joint's other points, whose slip is its lead's) */
    for (int q = 0; q < np; q++) {
        if (l->vd[q] >= 0 && !isinf(c->mu[q]) && c->lead[q] == q)
            p->lo[l->vd[q] + 1] = p->lo[l->vd[q] + 2] = -BIG;
        else if (l->vd[q] >= 0)
            p->hi[l->vd[q] + 1] = p->hi[l->vd[q] + 2] = 0.0;
        if (l->vw[q] >= 0) p->lo[l->vw[q]] = -BIG;
    }

    /* linear rows */
    int cap = 0, row = 0, rcap = nu + 2 + 4 * np + 4 * nx;
    p->glo = malloc(((size_t)rcap + npairs) * sizeof *p->glo);
    p->ghi = malloc(((size_t)rcap + npairs) * sizeof *p->ghi);
    if (!p->glo || !p->ghi) return -1;
#define ROW(a, b) (p->glo[row] = (a), p->ghi[row] = (b), row++)
    /* equilibrium (T5): A x + alpha fL = -fD */
    for (int j = 0; j <= nx; j++)
        for (int q = c->colptr[j]; q < c->colptr[j + 1]; q++)
            if (add(p, &cap, c->rowind[q], j < nx ? l->x0 + j : 0, c->val[q])) return -1;
    for (int i = 0; i < nu; i++) ROW(c->rhs[i], c->rhs[i]);
    /* normalization: fL . u = 1 */
    for (int q = c->colptr[nx]; q < c->colptr[nx + 1]; q++)
        if (add(p, &cap, row, l->u0 + c->rowind[q], c->val[q])) return -1;
    ROW(1.0, 1.0);
    /* per point: no interpenetration; the slip = s+ - s- (2D, sliding
     * points); no slip where the joint is rigid.  3D: the velocity
     * variables defined (their bounds say the rest), which keeps the rows
     * below short */
    for (int q = 0; q < np; q++) {
        if (l->jn[q] < 0) continue;
        if (d3) {
            if (add(p, &cap, row, l->vd[q], 1.0) ||
                add_motion(p, &cap, f, l->jn[q], l->u0, row, -1.0))
                return -1;
            ROW(0.0, 0.0);
            if (l->vw[q] >= 0) { /* tw, the power of the twist column */
                if (add(p, &cap, row, l->vw[q], 1.0) ||
                    add_motion(p, &cap, f, l->jt[q], l->u0, row, -1.0))
                    return -1;
                ROW(0.0, 0.0);
            }
            if (l->js2[q] < 0) continue; /* a resultant joint's other point */
            for (int t = 1; t <= 2; t++) {
                if (add(p, &cap, row, l->vd[q] + t, 1.0) ||
                    add_tangent(p, &cap, f, l, q, row, t == 1 ? -1.0 : 0.0, t == 2 ? -1.0 : 0.0))
                    return -1;
                ROW(0.0, 0.0);
            }
            continue;
        }
        if (add_motion(p, &cap, f, l->jn[q], l->u0, row, 1.0)) return -1;
        ROW(0.0, BIG);
        if (l->js[q] < 0) continue;
        int rigid = isinf(c->mu[q]);
        if (l->sp[q] < 0 && !rigid) continue;
        if (add_motion(p, &cap, f, l->js[q], l->u0, row, 1.0)) return -1;
        if (l->sp[q] >= 0 && (add(p, &cap, row, l->sp[q], -1.0) ||
                              add(p, &cap, row, l->sp[q] + 1, 1.0)))
            return -1;
        ROW(0.0, 0.0);
    }
    /* 3D: a rigid joint's free couple (assemble3.c) does no work, so the
     * joint does not twist: its power is zero (without this row a dome at
     * mu = inf twisted at its joints and ended "not complementary") */
    for (int j = 0; d3 && j < nx; j++) {
        const double *nt = c->col_nt + 3 * j;
        if (c->col_kind[j] != BL_COL_SHEAR || nt[0] != 0.0 || nt[1] != 0.0 || nt[2] != 0.0 ||
            !isinf(c->lo[j]))
            continue;
        if (add_motion(p, &cap, c, j, l->u0, row, 1.0)) return -1;
        ROW(0.0, 0.0);
    }
    /* the pairs: a force column and its slack, a cohesion distance and a slip */
    int k = 0;
    for (int j = 0; j < nx; j++) {
        int q = c->col_point[j], kind = c->col_kind[j];
        const double *nt = c->col_nt + st * j;
        if (l->cc[j] >= 0) { /* c+ = C - x, c- = x + C; pairs (c-, s+), (c+, s-) */
            if (add(p, &cap, row, l->cc[j], 1.0) || add(p, &cap, row, l->x0 + j, 1.0)) return -1;
            ROW(c->hi[j], c->hi[j]);
            if (add(p, &cap, row, l->cc[j] + 1, 1.0) || add(p, &cap, row, l->x0 + j, -1.0))
                return -1;
            ROW(-c->lo[j], -c->lo[j]);
            /* 3D: the slip along the column, sigma+ - sigma- (T22c) */
            int slip = d3 ? l->sg[j] : l->sp[q];
            if (d3) {
                if (add(p, &cap, row, slip, 1.0) || add(p, &cap, row, slip + 1, -1.0) ||
                    add_velocity(p, &cap, c, l, q, row, 0.0, -nt[1], -nt[2], -c->col_twist[j]))
                    return -1;
                ROW(0.0, 0.0);
            }
            p->pa[k] = l->cc[j] + 1;
            p->pb[k++] = slip;
            p->pa[k] = l->cc[j];
            p->pb[k++] = slip + 1;
            continue;
        }
        if (l->zc[j] < 0) continue;
        /* z = the column's power (associative: nt . (dn, dt)), or without
         * dilatancy z = dn + the slip rate the column's friction opposes
         * (3D: dn + eta + nt . dt, T22b) */
        if (add(p, &cap, row, l->zc[j], 1.0)) return -1;
        int pyr = kind == BL_COL_PYRAMID, g = c->lead[q];
        if (d3) {
            if (add_velocity(p, &cap, c, l, q, row, -nt[0], pyr ? -nt[1] : 0.0, pyr ? -nt[2] : 0.0,
                             pyr ? -c->col_twist[j] : 0.0))
                return -1;
        } else if (add_motion(p, &cap, f, l->jn[q], l->u0, row, -nt[0])) {
            return -1;
        }
        if (d3 && kind == BL_COL_PYRAMID) {
            if (l->sp[g] >= 0) {
                /* and eta + nt . dt >= 0 on its own: no edge resists the
                 * slip (and twist) more than eta (T22b) */
                if (add(p, &cap, row, l->sp[g], -1.0) || add(p, &cap, row + 1, l->sp[g], 1.0) ||
                    add_velocity(p, &cap, c, l, q, row + 1, 0.0, nt[1], nt[2], c->col_twist[j]))
                    return -1;
                ROW(0.0, 0.0);
                ROW(0.0, BIG);
                p->pa[k] = l->x0 + j;
                p->pb[k++] = l->zc[j];
                continue;
            }
        } else if (kind == BL_COL_CONE_POS || kind == BL_COL_CONE_NEG) {
            if (nonassoc) {
                if (add(p, &cap, row, l->sp[q] + (kind == BL_COL_CONE_NEG), -1.0)) return -1;
            } else if (add_motion(p, &cap, f, l->js[q], l->u0, row, -nt[1])) {
                return -1;
            }
        }
        ROW(0.0, 0.0);
        p->pa[k] = l->x0 + j;
        p->pb[k++] = l->zc[j];
    }
    p->nlin = row;
    p->relax = eps > 0.0;
    if (p->relax)
        for (int t = 0; t < npairs; t++) ROW(-BIG, eps);
#undef ROW
    p->m = row;
    return 0;
}

/* ---- Ipopt's callbacks ------------------------------------------------------ */

static Bool eval_f(Index n, Number *x, Bool new_x, Number *f, UserDataPtr ud)
{
    (void)n, (void)new_x;
    const nlp *p = ud;
    double s = 0.0;
    for (int k = 0; k < p->npairs; k++) s += x[p->pa[k]] * x[p->pb[k]];
    *f = x[0] + p->rho * s;
    return 1;
}

static Bool eval_grad_f(Index n, Number *x, Bool new_x, Number *g, UserDataPtr ud)
{
    (void)new_x;
    const nlp *p = ud;
    memset(g, 0, (size_t)n * sizeof *g);
    g[0] = 1.0;
    for (int k = 0; k < p->npairs; k++) {
        g[p->pa[k]] += p->rho * x[p->pb[k]];
        g[p->pb[k]] += p->rho * x[p->pa[k]];
    }
    return 1;
}

static Bool eval_g(Index n, Number *x, Bool new_x, Index m, Number *g, UserDataPtr ud)
{
    (void)n, (void)new_x;
    const nlp *p = ud;
    memset(g, 0, (size_t)m * sizeof *g);
    for (int t = 0; t < p->nnz; t++) g[p->jr[t]] += p->jv[t] * x[p->jc[t]];
    if (p->relax)
        for (int k = 0; k < p->npairs; k++) g[p->nlin + k] = x[p->pa[k]] * x[p->pb[k]];
    return 1;
}

static Bool eval_jac_g(Index n, Number *x, Bool new_x, Index m, Index nele, Index *ir,
                       Index *jc, Number *v, UserDataPtr ud)
{
    (void)n, (void)new_x, (void)m, (void)nele;
    const nlp *p = ud;
    if (!v) {
        memcpy(ir, p->jr, (size_t)p->nnz * sizeof *ir);
        memcpy(jc, p->jc, (size_t)p->nnz * sizeof *jc);
        if (p->relax)
            for (int k = 0, t = p->nnz; k < p->npairs; k++, t += 2) {
                ir[t] = ir[t + 1] = p->nlin + k;
                jc[t] = p->pa[k];
                jc[t + 1] = p->pb[k];
            }
    } else {
        memcpy(v, p->jv, (size_t)p->nnz * sizeof *v);
        if (p->relax)
            for (int k = 0, t = p->nnz; k < p->npairs; k++, t += 2) {
                v[t] = x[p->pb[k]];
                v[t + 1] = x[p->pa[k]];
            }
    }
    return 1;
}

/* The Hessian of the Lagrangian: one entry per pair, (max, min) of its two
 * variables: obj_factor rho from the penalty, lambda_k from its relaxation
 * row. */
static Bool eval_h(Index n, Number *x, Bool new_x, Number obj_factor, Index m, Number *lambda,
                   Bool new_lambda, Index nele, Index *ir, Index *jc, Number *v, UserDataPtr ud)
{
    (void)n, (void)x, (void)new_x, (void)m, (void)new_lambda, (void)nele;
    const nlp *p = ud;
    for (int k = 0; k < p->npairs; k++) {
        if (!v) {
            int a = p->pa[k], b = p->pb[k];
            ir[k] = a > b ? a : b;
            jc[k] = a > b ? b : a;
        } else {
            v[k] = obj_factor * p->rho + (p->relax ? lambda[p->nlin + k] : 0.0);
        }
    }
    return 1;
}

static Bool intermediate(Index mode, Index iter, Number obj, Number inf_pr, Number inf_du,
                         Number mu, Number d_norm, Number reg, Number alpha_du, Number alpha_pr,
                         Index ls, UserDataPtr ud)
{
    (void)mode, (void)obj, (void)inf_pr, (void)inf_du, (void)mu, (void)d_norm, (void)reg;
    (void)alpha_du, (void)alpha_pr, (void)ls;
    nlp *p = ud;
    if (iter > 0) p->iterations++; /* (iteration 0 is the start, as Ipopt counts) */
    if (p->deadline > 0 && bl_clock() > p->deadline) p->late = 1;
    return !bl_interrupt_pending() && !p->late;
}

/* ---- the solve -------------------------------------------------------------- */

/* The start of the program from a solution's scaled answer (x: cone
 * columns and alpha, y: rows); slip rates, cohesion distances and slacks
 * follow from their definitions, clipped at zero. */
static void start_from(const nlp *p, const layout *l, const bl_system *c, const bl_system *f,
                       const double *x, const double *y, int nonassoc, double *v)
{
    memset(v, 0, (size_t)p->n * sizeof *v);
    v[0] = x[l->nx];
    memcpy(v + l->x0, x, (size_t)l->nx * sizeof *v);
    memcpy(v + l->u0, y, (size_t)l->nu * sizeof *v);
    int np = c->npoints, st = c->dim;
    double *w = malloc(((size_t)f->nforce + 1) * sizeof *w);
    double *dt = malloc(2 * ((size_t)np + 1) * sizeof *dt); /* per point: along t2, t3 */
    double *al = malloc(((size_t)l->nx + 1) * sizeof *al);   /* per cone column: along */
    if (!w || !dt || !al) {
        free(w);
        free(dt);
        free(al);
        return;
    }
    bl_system_power(f, y, w);
    for (int q = 0; q < np; q++) {
        double a = l->js[q] >= 0 ? w[l->js[q]] : 0.0, b = l->js2[q] >= 0 ? w[l->js2[q]] : 0.0;
        const double *K = l->K + 4 * q;
        dt[2 * q] = st == 3 ? K[0] * a + K[1] * b : a;
        dt[2 * q + 1] = st == 3 ? K[2] * a + K[3] * b : 0.0;
        if (l->vd[q] >= 0) {
            v[l->vd[q]] = fmax(w[l->jn[q]], 0.0);
            v[l->vd[q] + 1] = dt[2 * q];
            v[l->vd[q] + 2] = dt[2 * q + 1];
        }
        if (l->vw[q] >= 0) v[l->vw[q]] = w[l->jt[q]];
        if (st == 2 && l->sp[q] >= 0 && l->js[q] >= 0) {
            v[l->sp[q]] = fmax(a, 0.0);
            v[l->sp[q] + 1] = fmax(-a, 0.0);
        }
    }
    /* 3D: along, the tangential part of a column's power (the slip and
     * twist of its point's joint); eta, the most a pyramid edge resists */
    for (int j = 0; j < l->nx; j++) {
        int q = c->col_point[j], g = c->lead[q];
        const double *nt = c->col_nt + st * j;
        double along = nt[1] * dt[2 * g];
        if (st == 3) along += nt[2] * dt[2 * g + 1] + (l->vw[g] >= 0 ? c->col_twist[j] * v[l->vw[g]] : 0.0);
        al[j] = along;
        if (st == 3 && l->sp[g] >= 0 && c->col_kind[j] == BL_COL_PYRAMID)
            v[l->sp[g]] = fmax(v[l->sp[g]], -along);
    }
    for (int j = 0; j < l->nx; j++) {
        int q = c->col_point[j], g = c->lead[q], kind = c->col_kind[j];
        const double *nt = c->col_nt + st * j;
        double along = al[j];
        if (l->cc[j] >= 0) {
            v[l->cc[j]] = fmax(c->hi[j] - x[j], 0.0);
            v[l->cc[j] + 1] = fmax(x[j] - c->lo[j], 0.0);
            if (l->sg[j] >= 0) {
                v[l->sg[j]] = fmax(along, 0.0);
                v[l->sg[j] + 1] = fmax(-along, 0.0);
            }
        } else if (l->zc[j] >= 0) {
            double z = nt[0] * w[l->jn[q]];
            if (kind == BL_COL_PYRAMID)
                z += along + (l->sp[g] >= 0 ? v[l->sp[g]] : 0.0);
            else if (kind == BL_COL_CONE_POS || kind == BL_COL_CONE_NEG)
                z += nonassoc ? v[l->sp[q] + (kind == BL_COL_CONE_NEG)] : along;
            v[l->zc[j]] = fmax(z, 0.0);
        }
    }
    free(w);
    free(dt);
    free(al);
}

static int run_ipopt(nlp *p, double *v, double *mult, const bl_mpec_options *o,
                     enum ApplicationReturnStatus *rs)
{
    int nhess = p->npairs, njac = p->nnz + (p->relax ? 2 * p->npairs : 0);
    IpoptProblem ip = CreateIpoptProblem(p->n, p->lo, p->hi, p->m, p->glo, p->ghi, njac, nhess, 0,
                                         eval_f, eval_g, eval_grad_f, eval_jac_g, eval_h);
    if (!ip) return -1;
    AddIpoptIntOption(ip, "print_level", o->seq.base.verbose ? 5 : 0);
    AddIpoptStrOption(ip, "sb", "yes");
    AddIpoptIntOption(ip, "max_iter", o->iterations);
    AddIpoptNumOption(ip, "tol", 1e-10);
    AddIpoptStrOption(ip, "mu_strategy", "adaptive");
    /* Ipopt relaxes bounds by 1e-8 by default: the answer then violated
     * admissibility by 1.4e-7 on W4, above the verification tolerance. */
    AddIpoptNumOption(ip, "bound_relax_factor", 0.0);
    /* MUMPS's pivot order 0 (AMD): 2.7-3.6 times faster than Ipopt's default
     * on W4 and a 150-block wall (doc/mpec.md) */
    AddIpoptIntOption(ip, "mumps_pivot_order", 0);
    /* and a pivot tolerance of 1e-10 instead of 1e-6 (Ipopt raises it when a
     * solve is inaccurate): the 3D W4 took 15.3 s with the default, its
     * delayed pivots growing MUMPS's workspace again and again, 0.8 s with
     * this; the 2D tests' answers are unchanged (doc/mpec.md) */
    AddIpoptNumOption(ip, "mumps_pivtol", 1e-10);
    p->deadline = o->seq.base.deadline;
    SetIntermediateCallback(ip, intermediate);
    double obj;
    double *ml = mult + p->m, *mu = mult + p->m + p->n;
    *rs = IpoptSolve(ip, v, NULL, &obj, mult, ml, mu, p);
    FreeIpoptProblem(ip);
    return 0;
}

static const char *ipopt_word(enum ApplicationReturnStatus r)
{
    switch (r) {
    case Solve_Succeeded: return "solved";
    case Solved_To_Acceptable_Level: return "solved to acceptable level";
    case Infeasible_Problem_Detected: return "locally infeasible";
    case Search_Direction_Becomes_Too_Small: return "search direction too small";
    case Diverging_Iterates: return "diverging iterates";
    case User_Requested_Stop: return "interrupted";
    case Maximum_Iterations_Exceeded: return "iteration limit";
    case Restoration_Failed: return "restoration failed";
    case Error_In_Step_Computation: return "error in step computation";
    case Maximum_CpuTime_Exceeded: return "time limit";
    default: return "failed";
    }
}

static bl_status status_of(enum ApplicationReturnStatus r)
{
    switch (r) {
    case Solve_Succeeded:
    case Solved_To_Acceptable_Level: return BL_OPTIMAL;
    case Infeasible_Problem_Detected: return BL_LOCALLY_INFEASIBLE;
    case User_Requested_Stop: return BL_INTERRUPTED;
    case Maximum_Iterations_Exceeded: return BL_ITERATION_LIMIT;
    case Maximum_CpuTime_Exceeded: return BL_TIME_LIMIT;
    case Restoration_Failed: return BL_RESTORATION_FAILED;
    default: return BL_NUMERICAL;
    }
}

/* Reads the point v of the program into s: alpha, forces (xa, the cone
 * system's columns and alpha), mechanism, joint states, residuals and
 * s->verified. */
static void answer_from(bl_solution *s, const double *v, const layout *l, const bl_system *c,
                        const bl_system *f, int nonassoc, const bl_mpec_options *o, double *xa)
{
    const bl_model *mc = s->model;
    s->alpha = v[0];
    memcpy(xa, v + l->x0, (size_t)l->nx * sizeof *xa);
    xa[l->nx] = v[0];
    s->has_mechanism = 1;
    s->res.flow = s->res.dilatancy = s->res.below = s->res.above = NAN; /* set by the non-associative check only */
    if (mc->dim == 3) {
        bl_system_forces3(c, xa, s->force);
        bl_system_mechanism3(c, mc, v + l->u0, s->u);
    } else {
        bl_system_forces(c, mc, xa, s->force);
        bl_system_mechanism(c, mc, v + l->u0, s->u);
    }
    bl_system_reactions(c, mc, xa, s->reaction);
    bl_solution_classify(s);
    s->verified = nonassoc ? bl_verify_nonassoc(c, f, s->alpha, xa, v + l->u0, o->seq.base.tolerance,
                                                o->seq.slip, &s->res)
                           : bl_verify(c, s->alpha, xa, v + l->u0, o->seq.base.tolerance, &s->res);
}

static const char *comp_name(const bl_mpec_options *o)
{
    return o->comp == BL_MPEC_PENALTY ? "penalty" : o->comp == BL_MPEC_RELAXATION ? "relaxation" : "homotopy";
}

/* The start's result s as the mpec method's where Ipopt did not run (the
 * start had no answer: a limit, no equilibrium, unbounded): its status,
 * alpha and residuals stand, under the method and flow asked for. */
static void not_run(bl_solution *s, const bl_mpec_options *o, const char *start_kind,
                    const char *start_why)
{
    s->method = "mpec";
    s->flow = o->nonassociative ? "nonassociative" : "associative";
    s->nlp_status = "not run";
    s->comp = comp_name(o);
    s->start_kind = start_kind;
    s->start_why = start_why;
    s->alpha_start = s->alpha;
    s->alpha_ipopt = NAN;
    s->pair_sum = NAN;
    s->kept_start = 0;
    s->iterations = 0; /* Ipopt's */
}

int bl_mpec_solve(bl_model *m, const bl_mpec_options *o, bl_solution **out, bl_error *err)
{
    double t0 = bl_clock();
    bl_one_thread();

    /* 3D: on the sequence's pyramid (an even number of facets: its section
     * is the fixed form's polygon of shears), from either start */
    bl_mpec_options oo = *o;
    bl_cone pyramid = bl_seqlp_pyramid(&o->seq.base.cone);
    if (m->dim == 3) oo.seq.base.cone = pyramid;
    oo.seq.base.weighted = 0; /* the start from the analytic centre, as the sequence's (seqlp.c) */
    oo.seq.base.progress = o->seq.progress; /* the associative LP's line (the sequence keeps its own) */
    o = &oo;
    /* the start: the associative LP (also for a cold start: it detects,
     * copies the model and tells models without an answer apart), or the
     * sequence of LPs */
    bl_solution *s;
    int rc = o->start == BL_MPEC_START_SEQLP ? bl_seqlp_solve(m, &o->seq, &s, err)
                                              : bl_assoc_solve(m, &o->seq.base, &s, err);
    if (rc) return -1;
    const char *start_kind = o->start == BL_MPEC_START_COLD    ? "cold"
                             : o->start == BL_MPEC_START_ASSOC ? "assoc"
                                                               : "seqlp",
               *start_why = NULL;
    if (o->start == BL_MPEC_START_SEQLP && !s->x && s->status != BL_INTERRUPTED && !s->interrupted &&
        s->status != BL_TIME_LIMIT && s->status != BL_UNBOUNDED &&
        !(isinf(s->alpha_assoc) && s->alpha_assoc > 0)) {
        /* no certified answer to start from: the associative one (but an
         * unbounded sequence, no mechanism for any flow rule, is the
         * answer, and where the associative LP is unbounded it is no
         * start; after the time limit nothing more is solved) */
        bl_solution_free(s);
        if (bl_assoc_solve(m, &o->seq.base, &s, err)) return -1;
        start_kind = "assoc";
        start_why = "the sequence of LPs had no answer";
    }
    /* An unbounded associative LP proves nothing without dilatancy (a
     * block wedged between supports, seqlp.c): the sequence of LPs, which
     * decides it, is the start instead */
    int from_seq = o->start == BL_MPEC_START_SEQLP;
    if (o->start == BL_MPEC_START_ASSOC && o->nonassociative && s->status == BL_UNBOUNDED) {
        from_seq = 1;
        bl_solution_free(s);
        if (bl_seqlp_solve(m, &o->seq, &s, err)) return -1;
        start_kind = "seqlp";
        start_why = "the associative LP is unbounded";
    }
    int cold = o->start == BL_MPEC_START_COLD;
    /* the associative answer beside the non-associative one: the
     * sequence's, or the associative start's own (a cold start's too) */
    if (strcmp(start_kind, "seqlp") != 0) {
        s->alpha_assoc = s->alpha;
        s->assoc_verified = s->verified;
    }
    /* Ctrl-C during the start: its result is the answer, as the start's
     * (a sequence stopped by it keeps what it certified, and says so) */
    if (s->status == BL_INTERRUPTED || s->interrupted) {
        *out = s;
        return 0;
    }
    if (!cold && !s->x) {
        /* no answer to start from: the start's status is the answer */
        not_run(s, o, start_kind, start_why);
        *out = s;
        return 0;
    }
    double alpha_start = s->x && !cold ? s->alpha : NAN;
    double t_start = bl_clock() - t0;

    const bl_model *mc = s->model;
    int d3 = mc->dim == 3;
    bl_system *c = d3 ? bl_system_build3(mc, &pyramid, BL_FRICTION_CONE, err)
                      : bl_system_build(mc, BL_FRICTION_CONE, err);
    bl_system *f = !c ? NULL
                   : d3 ? bl_system_build3(mc, &pyramid, BL_FRICTION_FIXED, err)
                        : bl_system_build(mc, BL_FRICTION_FIXED, err);
    nlp p = {0};
    layout l = {0};
    double *v = NULL, *v0 = NULL, *mult = NULL;
    if (!f) goto fail;
    int nonassoc = o->nonassociative;
    double eps0 = o->comp == BL_MPEC_PENALTY ? 0.0 : 1e-2;
    if (build(&p, &l, c, f, nonassoc, eps0)) goto oom;
    p.rho = o->comp == BL_MPEC_RELAXATION ? 0.0 : o->penalty;
    v = calloc((size_t)p.n, sizeof *v);
    mult = calloc((size_t)p.m + 2 * (size_t)p.n, sizeof *mult);
    if (!v || !mult) goto oom;
    if (!cold) start_from(&p, &l, c, f, s->x, s->y, nonassoc, v);
    /* a start that is itself an answer to the same problem, kept: the
     * sequence's certified one, or for the associative flow the LP's
     * verified one (Ipopt at penalty 0.5 ended at -0.5 on a pier, not
     * complementary, and there was no answer) */
    if (nonassoc ? from_seq && s->certified : !from_seq && !cold && s->verified) {
        v0 = malloc((size_t)p.n * sizeof *v0);
        if (!v0) goto oom;
        memcpy(v0, v, (size_t)p.n * sizeof *v0);
    }
    if (o->seq.base.verbose) {
        double sum = 0.0, big = 0.0;
        int kbig = -1;
        for (int k = 0; k < p.npairs; k++) {
            double t = v[p.pa[k]] * v[p.pb[k]];
            sum += t;
            if (t > big) big = t, kbig = k;
        }
        fprintf(stderr, "mpec: %d variables, %d constraints, %d pairs; start alpha %.10g, "
                        "products %.3e (largest %.3e, pair %d: variables %d, %d)\n",
                p.n, p.m, p.npairs, v[0], sum, big, kbig, kbig >= 0 ? p.pa[kbig] : -1,
                kbig >= 0 ? p.pb[kbig] : -1);
    }

    /* one solve, or the relaxation's sequence of eps, each from the last */
    enum ApplicationReturnStatus r = Solve_Succeeded;
    double t1 = bl_clock();
    for (double eps = eps0;; eps *= 1e-2) {
        if (p.relax)
            for (int k = 0; k < p.npairs; k++) p.ghi[p.nlin + k] = eps;
        if (run_ipopt(&p, v, mult, o, &r)) goto oom;
        if (p.late) r = Maximum_CpuTime_Exceeded; /* stopped at the solve's deadline */
        if (o->seq.base.verbose && p.relax)
            fprintf(stderr, "mpec: eps %.0e, alpha %.10g, Ipopt %s\n", eps, v[0], ipopt_word(r));
        if (!p.relax || eps <= 1e-10 || (r != Solve_Succeeded && r != Solved_To_Acceptable_Level))
            break;
    }
    double t2 = bl_clock();

    /* the answer, or the last point, with its residuals; when Ipopt
     * converged to a point that is not a verified answer below a certified
     * start, the start's point: Eq. 12 asks for the lowest alpha, and the
     * start already solves it (Ipopt's push into the interior can lose the
     * start and end higher, or at a point that is not complementary,
     * doc/mpec.md).  Ipopt's failures (limits, numerical trouble) stay
     * statuses. */
    s->method = "mpec";
    s->flow = nonassoc ? "nonassociative" : "associative";
    s->status = status_of(r);
    s->alpha = v[0];
    int stands = s->stands; /* the start's dead-load check, whatever Ipopt's alpha says */
    if (s->status == BL_OPTIMAL) bl_solution_answer_status(s);
    s->alpha_start = alpha_start;
    s->iterations = p.iterations;
    s->nlp_status = ipopt_word(r);
    s->comp = comp_name(o);
    s->start_kind = start_kind;
    s->start_why = start_why;
    s->rows = p.m;
    s->cols = p.n;
    s->lp = "ipopt";
    s->factor_nnz = 0.0;
    s->certified = 0;
    s->time_up = 0;
    s->slip = o->seq.slip;
    s->alpha_ipopt = v[0];
    s->kept_start = 0;
    double *xa = malloc(((size_t)l.nx + 1) * sizeof *xa);
    if (!xa) goto oom;
    answer_from(s, v, &l, c, f, nonassoc, o, xa);
    int converged = s->status == BL_OPTIMAL || s->status == BL_UNSTABLE;
    /* Ipopt's own failures do not make its point wrong: one that passes
     * every check is an answer (a pier cold ended "restoration failed"
     * after 1,189 iterations at b/h, every residual at round-off); its
     * limits and Ctrl-C stay statuses */
    if (!converged && s->verified && s->status != BL_ITERATION_LIMIT && s->status != BL_TIME_LIMIT &&
        s->status != BL_INTERRUPTED) {
        converged = 1;
        bl_solution_answer_status(s);
    }
    if (!converged) s->verified = 0;
    else if (!s->verified) s->status = BL_NOT_COMPLEMENTARY;
    s->res_ipopt = s->res;
    /* (where the dead load alone stands, an alpha below 0 is no answer for
     * a live load applied from zero, as in the sequence's certificates:
     * Ipopt went to -0.052 on a wall that stands, and called it unstable) */
    if (v0 && converged && (!s->verified || s->alpha > alpha_start || (stands == 1 && s->alpha < 0.0))) {
        answer_from(s, v0, &l, c, f, nonassoc, o, xa);
        s->kept_start = 1;
        s->certified = nonassoc && s->verified; /* the sequence's certified answer */
        s->stands = stands; /* (penalty 0.5: Ipopt at -0.5 called a pier unstable) */
        if (s->verified) bl_solution_answer_status(s);
        else s->status = BL_NOT_COMPLEMENTARY;
    } else if (v0 && !converged) {
        /* Ipopt stopped short (a limit, Ctrl-C, numerical trouble): a start that
         * is itself a verified answer stands (Ipopt's word says why it did
         * not improve on it); else no answer, and the status says why
         * (Ipopt's last point stays in alpha_ipopt) */
        bl_status why = s->status;
        answer_from(s, v0, &l, c, f, nonassoc, o, xa);
        s->kept_start = s->verified;
        s->stands = stands;
        if (s->verified) {
            bl_solution_answer_status(s);
            s->certified = nonassoc;
            s->interrupted = why == BL_INTERRUPTED; /* Ctrl-C: kept for last() */
            s->time_up = why == BL_TIME_LIMIT;
        } else {
            s->status = why;
            answer_from(s, v, &l, c, f, nonassoc, o, xa);
            s->verified = 0;
        }
    }
    /* no answer: a point Ipopt did not converge to, or one the residuals
     * reject (its alpha stays in alpha_ipopt) */
    if ((!converged && !s->kept_start) || s->status == BL_NOT_COMPLEMENTARY) s->alpha = NAN;
    const double *end = s->kept_start ? v0 : v;
    s->pair_sum = 0.0;
    for (int k = 0; k < p.npairs; k++) s->pair_sum += fabs(end[p.pa[k]] * end[p.pb[k]]);
    int kept = bl_solution_keep(s, xa, l.nx + 1, end + l.u0, l.nu);
    free(xa);
    if (kept) goto oom;
    /* the start's own solve and checks count as solving; building the
     * program as assembly */
    double t3 = bl_clock();
    s->time.solve = t_start - s->time.detection - s->time.assembly + (t2 - t1);
    s->time.assembly += t1 - (t0 + t_start);
    s->time.verification = t3 - t2;
    s->time.total = t3 - t0;

    nlp_free(&p);
    layout_free(&l);
    free(v);
    free(v0);
    free(mult);
    bl_system_free(c);
    bl_system_free(f);
    *out = s;
    return 0;
oom:
    bl_error_set(err, "solve: out of memory building the nonlinear program");
fail:
    nlp_free(&p);
    layout_free(&l);
    free(v);
    free(v0);
    free(mult);
    bl_system_free(c);
    bl_system_free(f);
    bl_solution_free(s);
    return -1;
}
