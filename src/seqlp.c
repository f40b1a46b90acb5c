#include "seqlp.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "assemble.h"
#include "lp.h"
#include "verify.h"

void bl_seqlp_options_default(bl_seqlp_options *o)
{
    bl_solve_options_default(&o->base);
    o->beta = 0.7;
    o->settle = 1e-4;
    o->slip = 1e-4;
    o->max_lps = 100;
}

/* The state of one run, with everything it owns. */
typedef struct run {
    bl_system *cone, *fixed;
    bl_lp *lp_fixed, *lp_cone;
    double *n, *lo, *hi, *clo, *chi, *w, *dn, *dt;
} run;

static void run_free(run *r)
{
    bl_lp_free(r->lp_fixed);
    bl_lp_free(r->lp_cone);
    bl_system_free(r->cone);
    bl_system_free(r->fixed);
    free(r->n);
    free(r->lo);
    free(r->hi);
    free(r->clo);
    free(r->chi);
    free(r->w);
    free(r->dn);
    free(r->dt);
}

static bl_lp *make_lp(const bl_system *s, const double *lo, const double *hi,
                      const bl_solve_options *o, bl_error *err)
{
    bl_lp_settings ls;
    bl_lp_settings_default(&ls);
    ls.engine = o->lp;
    ls.verbose = o->verbose;
    ls.max_seconds = o->time_limit;
    ls.max_iterations = o->iterations;
    bl_lp_problem p = {s->nrows, s->ncols, s->colptr, s->rowind, s->val, lo, hi, s->rhs, s->obj};
    return bl_lp_create(&p, &ls, err);
}

/* The certificate: at alpha, forces in Coulomb's cone that fit the
 * mechanism y of the last LP: none where a point opens, on the cone's edge
 * against the slip where it slides, anywhere in the cone where it stays
 * closed.  Returns the LP status; the forces are bl_lp_primal(lp_cone). */
static bl_lp_status certify(run *r, double alpha, const double *y, double slip,
                            const bl_solve_options *o, bl_error *err)
{
    const bl_system *c = r->cone, *f = r->fixed;
    bl_system_power(f, y, r->w);
    for (int p = 0; p < f->npoints; p++) r->dn[p] = r->dt[p] = 0.0;
    double V = 0.0;
    for (int j = 0; j < f->nforce; j++) {
        int p = f->col_point[j];
        if (f->col_kind[j] == BL_COL_NORMAL) r->dn[p] = r->w[j];
        else r->dt[p] = r->w[j];
    }
    for (int p = 0; p < f->npoints; p++) V = fmax(V, hypot(r->dn[p], r->dt[p]));
    double eps = slip * V;
    for (int j = 0; j < c->nforce; j++) {
        int p = c->col_point[j];
        double lo = c->lo[j], hi = c->hi[j];
        if (r->dn[p] > eps) {
            lo = hi = 0.0; /* opening: no force */
        } else if (fabs(r->dt[p]) > eps) {
            /* sliding: friction opposes the slip of b on a */
            int up = r->dt[p] > 0.0;
            if ((c->col_kind[j] == BL_COL_CONE_POS && up) ||
                (c->col_kind[j] == BL_COL_CONE_NEG && !up))
                lo = hi = 0.0;
            if (c->col_kind[j] == BL_COL_COHESION) lo = hi = up ? c->lo[j] : c->hi[j];
        }
        r->clo[j] = lo;
        r->chi[j] = hi;
    }
    r->clo[c->nforce] = r->chi[c->nforce] = alpha;
    if (!r->lp_cone) {
        r->lp_cone = make_lp(c, r->clo, r->chi, o, err);
        if (!r->lp_cone) return BL_LP_FAILED;
    } else {
        bl_lp_set_bounds(r->lp_cone, r->clo, r->chi);
    }
    return bl_lp_solve(r->lp_cone);
}

static int append(bl_solution *s, double a)
{
    double *h = realloc(s->history, (size_t)(s->nhistory + 1) * sizeof *h);
    if (!h) return -1;
    h[s->nhistory++] = a;
    s->history = h;
    return 0;
}

int bl_seqlp_solve(bl_model *m, const bl_seqlp_options *o, bl_solution **out, bl_error *err)
{
    double t0 = bl_clock();
    bl_solution *s;
    if (bl_assoc_solve(m, &o->base, &s, err)) return -1;
    s->method = "seqlp";
    s->flow = "nonassociative";
    s->alpha_assoc = s->alpha;
    s->slip = o->slip;
    s->lps = 1;
    s->certified = 0;
    s->verified = 0;
    if (s->status != BL_OPTIMAL && s->status != BL_UNSTABLE) {
        *out = s; /* no associative answer: none without dilatancy either */
        return 0;
    }
    append(s, s->alpha);

    run r = {0};
    const bl_model *mc = s->model;
    r.cone = bl_system_build(mc, BL_FRICTION_CONE, err);
    r.fixed = r.cone ? bl_system_build(mc, BL_FRICTION_FIXED, err) : NULL;
    if (!r.fixed) goto fail;
    int np = r.fixed->npoints, nc = r.fixed->ncols, ncc = r.cone->ncols;
    r.n = calloc((size_t)np + 1, sizeof *r.n);
    r.dn = calloc((size_t)np + 1, sizeof *r.dn);
    r.dt = calloc((size_t)np + 1, sizeof *r.dt);
    r.lo = malloc((size_t)nc * sizeof *r.lo);
    r.hi = malloc((size_t)nc * sizeof *r.hi);
    r.clo = malloc((size_t)ncc * sizeof *r.clo);
    r.chi = malloc((size_t)ncc * sizeof *r.chi);
    r.w = malloc((size_t)(nc > ncc ? nc : ncc) * sizeof *r.w);
    if (!r.n || !r.dn || !r.dt || !r.lo || !r.hi || !r.clo || !r.chi || !r.w) {
        bl_error_set(err, "solve: out of memory");
        goto fail;
    }
    /* normal forces of the associative answer, per point, scaled */
    for (int p = 0; p < np; p++) r.n[p] = s->force[2 * p] / r.fixed->W0;

    double prev = s->alpha;
    s->status = BL_UNCERTIFIED;
    for (int j = 1; j < o->max_lps; j++) {
        bl_system_fixed_bounds(r.fixed, r.n, r.lo, r.hi);
        if (!r.lp_fixed) {
            r.lp_fixed = make_lp(r.fixed, r.lo, r.hi, &o->base, err);
            if (!r.lp_fixed) goto fail;
        } else {
            bl_lp_set_bounds(r.lp_fixed, r.lo, r.hi);
        }
        bl_lp_status st = bl_lp_solve(r.lp_fixed);
        s->lps++;
        s->iterations += bl_lp_iterations(r.lp_fixed);
        if (st != BL_LP_OPTIMAL) {
            /* an infeasible LP here means the relaxed normal forces cannot
             * carry some block by friction alone (DESIGN 2.4) */
            s->status = st == BL_LP_INFEASIBLE ? BL_UNCERTIFIED : bl_status_of_lp(st);
            break;
        }
        const double *x = bl_lp_primal(r.lp_fixed), *y = bl_lp_dual(r.lp_fixed);
        double a = x[r.fixed->nforce];
        append(s, a);
        if (o->base.verbose) fprintf(stderr, "seqlp LP %d: alpha %.8g\n", j + 1, a);
        if (fabs(a - prev) <= o->settle * fabs(a)) {
            bl_lp_status cs = certify(&r, a, y, o->slip, &o->base, err);
            s->lps++;
            if (cs == BL_LP_FAILED && !r.lp_cone) goto fail;
            if (cs == BL_LP_OPTIMAL) {
                const double *xc = bl_lp_primal(r.lp_cone);
                s->alpha = a;
                s->status = a < 0.0 ? BL_UNSTABLE : BL_OPTIMAL;
                s->certified = 1;
                bl_system_forces(r.cone, mc, xc, s->force);
                bl_system_mechanism(r.fixed, mc, y, s->u);
                bl_solution_classify(s);
                s->verified = bl_verify_nonassoc(r.cone, r.fixed, a, xc, y, o->base.tolerance,
                                                 o->slip, &s->res);
                break;
            }
            if (cs != BL_LP_INFEASIBLE) {
                s->status = bl_status_of_lp(cs);
                break;
            }
        }
        /* relax the normal forces towards this LP's */
        for (int p = 0; p < np; p++) r.n[p] *= 1.0 - o->beta;
        for (int k = 0; k < r.fixed->nforce; k++)
            if (r.fixed->col_kind[k] == BL_COL_NORMAL) r.n[r.fixed->col_point[k]] += o->beta * x[k];
        prev = a;
    }
    if (!s->certified) {
        s->has_mechanism = 0;
        s->alpha = s->history[s->nhistory - 1];
    }
    if (r.lp_fixed) s->lp = bl_lp_engine(r.lp_fixed);
    run_free(&r);
    s->time.total = bl_clock() - t0;
    s->time.solve = s->time.total - s->time.detection - s->time.assembly - s->time.verification;
    *out = s;
    return 0;
fail:
    run_free(&r);
    bl_solution_free(s);
    return -1;
}
