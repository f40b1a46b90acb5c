#include "assoc.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "assemble.h"
#include "contact.h"
#include "lp.h"
#include "verify.h"

void bl_solve_options_default(bl_solve_options *o)
{
    o->tolerance = 1e-7;
    o->verbose = 0;
    o->time_limit = 0;
    o->iterations = 0;
    o->threads = 0;
    o->lp = BL_LP_AUTO;
    o->mps = NULL;
    o->cone = (bl_cone){.facets = 8};
    o->early_infeasible = 0;
    o->lp_tolerance = 0;
    o->weighted = 1;
}

bl_lp *bl_solve_lp(const bl_system *s, const double *lo, const double *hi, const double *obj,
                   const bl_solve_options *o, bl_error *err)
{
    bl_lp_settings ls;
    bl_lp_settings_default(&ls);
    ls.engine = o->lp;
    ls.verbose = o->verbose;
    ls.max_seconds = o->time_limit;
    ls.max_iterations = o->iterations;
    ls.threads = o->threads;
    ls.early_infeasible = o->early_infeasible;
    ls.tolerance = o->lp_tolerance;
    ls.weighted = o->weighted;
    bl_lp_problem p = {s->nrows, s->ncols, s->colptr, s->rowind, s->val,
                       lo,       hi,       s->rhs,    obj ? obj : s->obj};
    return bl_lp_create(&p, &ls, err);
}

int bl_assoc_solve(bl_model *m, const bl_solve_options *o, bl_solution **out, bl_error *err)
{
    double t0 = bl_clock();
    if (!m->contacts_valid && bl_contact_detect(m, err)) return -1;
    double t1 = bl_clock();

    bl_model *copy = bl_model_copy(m);
    bl_solution *s = copy ? bl_solution_new(copy) : NULL;
    if (!s) return bl_error_set(err, "solve: out of memory");
    /* 3D with the adaptive cone: the inscribed pyramid of every point gets
     * an edge along the slip the previous LP found there, until alpha
     * settles; edges are only added, so alpha rises towards the exact
     * cone's (doc/theory.md 3.3) */
    enum { ROUNDS = 40 };
    bl_cone cone = o->cone;
    double *extra = NULL, *slip = NULL;
    int *extra_n = NULL, np = 0;
    for (int k = 0; k < m->ninterfaces; k++) np += m->interfaces[k].np;
    if (m->dim == 3 && cone.adaptive) {
        extra = calloc((size_t)np * ROUNDS + 1, sizeof *extra);
        extra_n = calloc((size_t)np + 1, sizeof *extra_n);
        slip = calloc(2 * (size_t)np + 1, sizeof *slip);
        if (!extra || !extra_n || !slip) {
            free(extra), free(extra_n), free(slip);
            bl_solution_free(s);
            return bl_error_set(err, "solve: out of memory");
        }
        cone.circumscribed = 0;
        cone.nextra = ROUNDS;
        cone.extra = extra;
        cone.extra_n = extra_n;
    }
    bl_system *sys = NULL;
    bl_lp *lp = NULL;
    bl_lp_status st = BL_LP_FAILED;
    double t2 = bl_clock(), t3 = t2, prev = NAN, solve_time = 0.0;
    int lost = 0; /* iterations of LPs solved again */
    for (int round = 1;; round++) {
        sys = m->dim == 3 ? bl_system_build3(m, &cone, BL_FRICTION_CONE, err) : bl_system_build(m, BL_FRICTION_CONE, err);
        if (!sys) break;
        bl_lp_problem p = {sys->nrows, sys->ncols, sys->colptr, sys->rowind, sys->val,
                           sys->lo,    sys->hi,    sys->rhs,    sys->obj};
        lp = o->mps && bl_lp_write_mps(&p, o->mps, err) ? NULL
                                                       : bl_solve_lp(sys, sys->lo, sys->hi, NULL, o, err);
        if (!lp) break;
        t2 = bl_clock();
        st = bl_lp_solve(lp);
        if ((st == BL_LP_FAILED || st == BL_LP_ITERATION_LIMIT) &&
            strcmp(bl_lp_engine(lp), "ipm") == 0) {
            /* Blocks confined between supports can carry any compression,
             * and the interior point does not converge on the unbounded
             * optimal face (doc/seqlp.md 13).  Every force column capped
             * far above any force equilibrium needs (BL_LP_CONFINED)
             * bounds it without a cost that would tilt the mechanism,
             * which the verification checks. */
            double cap = BL_LP_CONFINED * sys->nrows;
            for (int j = 0; j < sys->nforce; j++)
                if (isinf(sys->hi[j])) sys->hi[j] = cap;
            lost += bl_lp_iterations(lp);
            bl_lp_free(lp);
            lp = bl_solve_lp(sys, sys->lo, sys->hi, NULL, o, err);
            if (!lp) break;
            st = bl_lp_solve(lp);
        }
        t3 = bl_clock();
        solve_time += t3 - t2;
        s->cone_rounds = round;
        s->cone = o->cone;
        s->cone.extra = NULL;
        s->cone.extra_n = NULL;
        if (!extra || st != BL_LP_OPTIMAL || round == ROUNDS) break;
        /* the slip of every contact point (from the mechanism: the forces
         * sit on corners of the pyramid); the friction on b opposes it */
        double a = bl_lp_primal(lp)[sys->nforce], smax = 0.0;
        if (fabs(a - prev) <= o->tolerance * fmax(1.0, fabs(a))) break;
        prev = a;
        bl_system_slip3(sys, m, bl_lp_dual(lp), slip);
        for (int q = 0; q < np; q++) smax = fmax(smax, hypot(slip[2 * q], slip[2 * q + 1]));
        for (int q = 0; q < np; q++)
            if (hypot(slip[2 * q], slip[2 * q + 1]) > 1e-6 * smax)
                extra[q * ROUNDS + extra_n[q]++] = atan2(-slip[2 * q + 1], -slip[2 * q]);
        bl_lp_free(lp);
        bl_system_free(sys);
        lp = NULL;
        sys = NULL;
    }
    free(extra);
    free(extra_n);
    free(slip);
    if (!lp) {
        bl_system_free(sys);
        bl_solution_free(s);
        return -1;
    }
    t2 = t3 - solve_time;

    s->status = bl_status_of_lp(st);
    s->lp = bl_lp_engine(lp);
    s->iterations = bl_lp_iterations(lp) + lost;
    s->factor_nnz = bl_lp_factor_nnz(lp);
    s->rows = sys->nrows;
    s->cols = sys->ncols;
    s->tolerance = o->tolerance;
    if (st == BL_LP_OPTIMAL) {
        const double *x = bl_lp_primal(lp), *y = bl_lp_dual(lp);
        s->alpha = x[sys->nforce];
        if (s->alpha < 0.0) s->status = BL_UNSTABLE;
        s->has_mechanism = 1;
        if (sys->dim == 3) {
            bl_system_forces3(sys, x, s->force);
            bl_system_mechanism3(sys, m, y, s->u);
        } else {
            bl_system_forces(sys, m, x, s->force);
            bl_system_mechanism(sys, m, y, s->u);
        }
        bl_solution_classify(s);
        s->verified = bl_verify(sys, s->alpha, x, y, o->tolerance, &s->res);
        if (bl_solution_keep(s, x, sys->ncols, y, sys->nrows)) {
            bl_lp_free(lp);
            bl_system_free(sys);
            bl_solution_free(s);
            return bl_error_set(err, "solve: out of memory");
        }
    }
    double t4 = bl_clock();
    s->time.detection = t1 - t0;
    s->time.assembly = t2 - t1;
    s->time.solve = t3 - t2;
    s->time.verification = t4 - t3;
    s->time.total = t4 - t0;
    bl_lp_free(lp);
    bl_system_free(sys);
    *out = s;
    return 0;
}
