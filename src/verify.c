#include "verify.h"

#include <math.h>
#include <stdlib.h>

/* An answer that carries no load: alpha 0 to round-off where the live load
 * is the only one (the dead load made the live one, r.dead, in a model that
 * carries none of it).  Its forces are round-off too, 1e-13: its blocks'
 * scales take the live load once, not as light blocks (their residuals
 * read 1e-4), and its products are measured against forces of at least
 * FORCE_FLOOR W0 (against 1e-13 they read 0.07). */
#define ALPHA_ZERO 1e-9
#define FORCE_FLOOR 1e-2

static int unloaded(const bl_system *s, double alpha)
{
    if (fabs(alpha) > ALPHA_ZERO) return 0;
    for (int i = 0; i < s->nrows; i++)
        if (s->rhs[i] != 0.0) return 0;
    return 1;
}

/* Normalization and the virtual-work balance: the static alpha equals the
 * kinematic one, (dissipation - fD . u) / fL . u, relative to the larger
 * of the works and the live load's unit work fL . u (where alpha = 0 and
 * nothing works, a block on a frictionless joint, the works alone left
 * round-off over round-off). */
static void work(const bl_system *s, double alpha, const double *y, double dissipation,
                 bl_residuals *res)
{
    double fLu = 0.0, fDu = 0.0;
    for (int j = s->colptr[s->nforce]; j < s->colptr[s->nforce + 1]; j++)
        fLu += s->val[j] * y[s->rowind[j]];
    for (int i = 0; i < s->nrows; i++) fDu -= s->rhs[i] * y[i];
    double scale = fmax(fabs(alpha * fLu) + fabs(fDu) + fabs(dissipation), fabs(fLu));
    res->normalization = fabs(fLu - 1.0);
    res->work = scale > 0.0 ? fabs(alpha * fLu + fDu - dissipation) / scale : 0.0;
}

/* What a residual of a block whose balance has terms up to S is measured
 * against: W0 (1), or S where the block is lighter; and never less than
 * ROUNDOFF S, as the round-off of sums of terms of size S is about 1e-16 S
 * (a point load of 1e10 W0, balanced to 5.7e-6 W0, was NOT verified). */
#define ROUNDOFF 1e-8
static double measure(double S) { return fmax(fmin(1.0, S), ROUNDOFF * S); }

/* Equilibrium, in units of the typical block weight W0, and for a block
 * lighter than that (whose loads and forces are all small) in units of
 * its own: a block 1e-13 as heavy as the rest left its whole weight
 * unbalanced, and its LP a wrong alpha, at 5e-14 W0 (doc/theory.md 5).
 * r receives the residual rows, S (nrows) each row's block scale in units
 * of W0 (the largest of its rows' loads and force terms, before the
 * scaling of light blocks, bl_system_finish). */
static void equilibrium(const bl_system *s, const double *x, double alpha, double *r, double *S,
                       double *eq)
{
    bl_system_residual(s, x, alpha, r);
    for (int i = 0; i < s->nrows; i++) S[i] = fabs(s->rhs[i]);
    for (int j = 0; j < s->ncols; j++) {
        double xj = j < s->nforce ? x[j] : unloaded(s, alpha) ? 1.0 : alpha;
        for (int p = s->colptr[j]; p < s->colptr[j + 1]; p++) S[s->rowind[p]] += fabs(s->val[p] * xj);
    }
    int rows = s->dim == 3 ? 6 : 3; /* a block's, one after the other */
    *eq = 0.0;
    for (int b = 0; b < s->nrows; b += rows) {
        double Sb = 0.0, worst = 0.0;
        for (int i = b; i < b + rows && i < s->nrows; i++) {
            double unscale = s->row_scale ? 1.0 / s->row_scale[i] : 1.0;
            Sb = fmax(Sb, S[i] * unscale);
            worst = fmax(worst, fabs(r[i]) * unscale);
        }
        for (int i = b; i < b + rows && i < s->nrows; i++) S[i] = Sb;
        *eq = fmax(*eq, Sb > 0.0 ? worst / measure(Sb) : worst);
    }
}

/* Yield: how far force column j lies outside its bounds, in units of W0,
 * or of the scale S of the lighter of its blocks where that is below W0
 * (a bound broken by 3e-13 at the joint of a block weighing 6e-13 is
 * broken by half the block's forces). */
static double yield_violation(const bl_system *s, const double *S, int j, double xj)
{
    double v = fmax(s->lo[j] - xj, xj - s->hi[j]);
    if (!(v > 0.0)) return 0.0;
    double local = INFINITY;
    for (int p = s->colptr[j]; p < s->colptr[j + 1]; p++) local = fmin(local, S[s->rowind[p]]);
    local = isinf(local) ? 1.0 : measure(local);
    return local > 0.0 ? v / local : INFINITY;
}

int bl_verify(const bl_system *s, double alpha, const double *x, const double *y, double tol,
              bl_residuals *res)
{
    double *r = malloc((size_t)(s->nrows > s->nforce ? s->nrows : s->nforce + 1) * sizeof *r);
    double *S = malloc(((size_t)s->nrows + 1) * sizeof *S);
    double eq = 0.0;
    if (!r || !S) {
        free(r);
        free(S);
        res->equilibrium = res->yield = res->admissibility = res->complementarity =
            res->normalization = res->work = INFINITY;
        return 0;
    }
    equilibrium(s, x, alpha, r, S, &eq);

    double yield = 0.0, X = 0.0;
    for (int j = 0; j < s->nforce; j++) {
        yield = fmax(yield, yield_violation(s, S, j, x[j]));
        X = fmax(X, fabs(x[j]));
    }
    free(S);
    if (unloaded(s, alpha)) X = fmax(X, FORCE_FLOOR);
    if (X == 0.0) X = 1.0;

    /* Kinematics: w_j = (A^T y)_j is the power of a unit value of column j,
     * the relative velocity along the column's force direction.  V is the
     * velocity scale: the largest block velocity (omega times L0). */
    double V = 0.0;
    for (int i = 0; i < s->nrows; i++) V = fmax(V, fabs(bl_system_velocity(s, y, i)));
    if (V == 0.0) V = 1.0;
    double *w = r;
    bl_system_power(s, y, w);
    double adm = 0.0, comp = 0.0, dissipation = 0.0;
    for (int j = 0; j < s->nforce; j++) {
        int lower = isfinite(s->lo[j]), upper = isfinite(s->hi[j]);
        if (lower && !upper) {          /* x >= lo: needs w >= 0, x w = 0 */
            adm = fmax(adm, -w[j] / V);
            comp = fmax(comp, fabs((x[j] - s->lo[j]) * w[j]) / (X * V));
        } else if (!lower && !upper) {  /* free: needs w = 0 */
            adm = fmax(adm, fabs(w[j]) / V);
        } else if (!lower) {            /* x <= hi: needs w <= 0, x w = 0 */
            adm = fmax(adm, w[j] / V);
            comp = fmax(comp, fabs((s->hi[j] - x[j]) * w[j]) / (X * V));
        } else {                        /* lo <= x <= hi: x = lo where w > 0, hi where w < 0 */
            double cap = w[j] > 0.0 ? s->lo[j] : s->hi[j];
            comp = fmax(comp, fabs((cap - x[j]) * w[j]) / (X * V));
            dissipation -= cap * w[j];  /* C |w|: the resisting force opposes the motion */
        }
    }

    res->equilibrium = eq;
    res->yield = fmax(yield, 0.0);
    res->admissibility = fmax(adm, 0.0);
    res->complementarity = comp;
    work(s, alpha, y, dissipation, res);
    free(r);
    return res->equilibrium <= tol && res->yield <= tol && res->admissibility <= tol &&
           res->complementarity <= tol && res->normalization <= tol && res->work <= tol;
}

int bl_verify_nonassoc(const bl_system *cone, const bl_system *fixed, double alpha,
                       const double *xc, const double *y, double tol, double slip,
                       bl_residuals *res)
{
    int np = cone->npoints;
    int nw = fixed->nforce > cone->nrows ? fixed->nforce : cone->nrows;
    if (cone->nforce > nw) nw = cone->nforce;
    double *w = malloc(((size_t)nw + 1) * sizeof *w);
    double *buf = malloc((11 * (size_t)np + 1) * sizeof *buf);
    double *S = malloc(((size_t)cone->nrows + 1) * sizeof *S);
    if (!w || !buf || !S) {
        free(w);
        free(buf);
        free(S);
        res->equilibrium = res->yield = res->admissibility = res->complementarity =
            res->normalization = res->work = res->flow = res->dilatancy = INFINITY;
        res->below = res->above = NAN;
        return 0;
    }
    /* per point: normal and tangential motion and force; 3D: the tangent
     * split along t2 (dt, t) and t3 (dt3, t3); per joint (its lead point,
     * bl_system): how fast it slides, the friction's power and its
     * dissipation */
    double *dn = buf, *dt = buf + np, *n = buf + 2 * np, *t = buf + 3 * np;
    double *dt3 = buf + 4 * np, *t3 = buf + 5 * np, *speed = buf + 6 * np;
    double *power = buf + 7 * np, *h = buf + 8 * np, *slide = buf + 9 * np, *open = buf + 10 * np;
    int d3 = cone->dim == 3, st = cone->dim;

    /* statics, on the cone system */
    double eq = 0.0;
    equilibrium(cone, xc, alpha, w, S, &eq);
    double yield = 0.0;
    for (int p = 0; p < np; p++) n[p] = t[p] = t3[p] = dt3[p] = 0.0;
    for (int j = 0; j < cone->nforce; j++) {
        yield = fmax(yield, yield_violation(cone, S, j, xc[j]));
        n[cone->col_point[j]] += xc[j] * cone->col_nt[st * j];
        t[cone->col_point[j]] += xc[j] * cone->col_nt[st * j + 1];
        if (d3) t3[cone->col_point[j]] += xc[j] * cone->col_nt[3 * j + 2];
    }

    /* kinematics, per contact point */
    bl_system_point_motion(fixed, y, w, dn, dt);
    if (d3) bl_system_tangent3(fixed, w, dt, dt3);
    double X = 0.0;
    for (int p = 0; p < np; p++) {
        X = fmax(X, fabs(n[p]));
        power[p] = 0.0;
        h[p] = d3 ? -INFINITY : 0.0;
    }
    if (unloaded(cone, alpha)) X = fmax(X, FORCE_FLOOR);
    if (X == 0.0) X = 1.0;
    /* the speed of every joint (with its twist) and the velocity scale V.
     * 3D: the tangential power of a cone column, along, is its power less
     * its normal part; the friction's dissipation is N times the most a
     * pyramid edge resists (-along per unit normal force), plus each
     * cohesion column's bound times |along| (the support function of the
     * joint's yield set); the friction's power is x . along. */
    bl_system_speed(fixed, w, dt, dt3, speed);
    bl_system_rigid_motion(cone, dn, speed, slide, open);
    double V = 0.0;
    for (int p = 0; p < np; p++) V = fmax(V, hypot(dn[p], speed[p]));
    if (V == 0.0) V = 1.0;
    if (d3) bl_system_power(cone, y, w);
    for (int j = 0; d3 && j < cone->nforce; j++) {
        int p = cone->col_point[j], g = cone->lead[p];
        double along = w[j] - dn[p] * cone->col_nt[3 * j];
        power[g] += xc[j] * along;
        if (cone->col_kind[j] == BL_COL_PYRAMID) h[g] = fmax(h[g], -along);
    }
    for (int p = 0; d3 && p < np; p++) {
        if (cone->lead[p] != p) {
            h[p] = 0.0; /* its joint's is with the lead */
            continue;
        }
        double N = 0.0;
        for (int q = p; q < np && cone->lead[q] == p; q++) N += n[q];
        h[p] = isfinite(h[p]) ? fmax(h[p], 0.0) * N : 0.0;
    }
    for (int j = 0; d3 && j < cone->nforce; j++)
        if (cone->col_kind[j] == BL_COL_COHESION) {
            int p = cone->col_point[j];
            double along = w[j] - dn[p] * cone->col_nt[3 * j];
            h[cone->lead[p]] += cone->hi[j] * fabs(along);
        }
    double adm = 0.0, comp = 0.0, flow = 0.0, dil = 0.0, dissipation = 0.0;
    double below = 0.0, above = INFINITY;
    int unknown = 0;
    for (int p = 0; p < np; p++) {
        double R = isinf(cone->mu[p]) ? 0.0 : cone->mu[p] * n[p] + cone->cohesion[p];
        adm = fmax(adm, -dn[p] / V);
        comp = fmax(comp, fabs(n[p] * dn[p]) / (X * V));
        if (isfinite(cone->mu[p]) && d3) {
            flow = fmax(flow, fabs(power[p] + h[p]) / (X * V));
            dissipation += h[p];
        } else if (isfinite(cone->mu[p])) {
            flow = fmax(flow, fabs(t[p] * dt[p] + R * fabs(dt[p])) / (X * V));
            dissipation += R * fabs(dt[p]);
        }
        if (speed[cone->lead[p]] > slip * V && n[p] > slip * X) dil = fmax(dil, dn[p] / V);
        /* the motions the flow rule was judged on: opening and sliding,
         * and a rigid joint's as a whole */
        double m[4] = {fmax(dn[p], 0.0), speed[cone->lead[p]], slide[p], fmax(open[p], 0.0)};
        for (int k = 0; k < 4; k++) {
            if (m[k] < slip * V) below = fmax(below, m[k] / V);
            else if (m[k] >= slip * V) above = fmin(above, m[k] / V);
            else unknown = 1; /* a motion that is not a number: neither is known */
        }
    }
    /* rigid joints (mu = inf): no force where the joint slides (the flow
     * rule's limit: its shear would do unbounded work), no shear or couple
     * where it opens at every point (as no normal force where a point
     * opens) */
    for (int j = 0; j < cone->nforce; j++) {
        int p = cone->col_point[j];
        if (!isinf(cone->mu[p])) continue;
        flow = fmax(flow, fabs(xc[j]) * slide[p] / (X * V));
        if (cone->col_kind[j] == BL_COL_SHEAR) comp = fmax(comp, fabs(xc[j]) * fmax(open[p], 0.0) / (X * V));
    }
    res->equilibrium = eq;
    res->yield = fmax(yield, 0.0);
    res->admissibility = fmax(adm, 0.0);
    res->complementarity = comp;
    work(cone, alpha, y, dissipation, res);
    res->flow = flow;
    res->dilatancy = dil;
    res->below = unknown ? NAN : below;
    res->above = unknown ? NAN : above;
    free(w);
    free(buf);
    free(S);
    double ftol = fmin(slip, BL_FLOW_TOL_MAX);
    return res->equilibrium <= tol && res->yield <= tol && res->admissibility <= tol &&
           res->normalization <= tol && res->complementarity <= ftol && res->flow <= ftol &&
           res->dilatancy <= ftol && res->work <= ftol;
}
