#include "assoc.h"

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
    o->lp = BL_LP_AUTO;
    o->mps = NULL;
    o->cone.facets = 8;
    o->cone.circumscribed = 0;
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
    bl_lp_problem p = {s->nrows, s->ncols, s->colptr, s->rowind, s->val,
                       lo,       hi,       s->rhs,    obj ? obj : s->obj};
    return bl_lp_create(&p, &ls, err);
}

int bl_assoc_solve(bl_model *m, const bl_solve_options *o, bl_solution **out, bl_error *err)
{
    bl_interrupt_clear();
    double t0 = bl_clock();
    if (!m->contacts_valid && bl_contact_detect(m, err)) return -1;
    double t1 = bl_clock();

    bl_model *copy = bl_model_copy(m);
    bl_solution *s = copy ? bl_solution_new(copy) : NULL;
    if (!s) return bl_error_set(err, "solve: out of memory");
    bl_system *sys = m->dim == 3 ? bl_system_build3(m, &o->cone, err)
                                 : bl_system_build(m, BL_FRICTION_CONE, err);
    if (!sys) {
        bl_solution_free(s);
        return -1;
    }
    bl_lp_problem p = {sys->nrows, sys->ncols, sys->colptr, sys->rowind, sys->val,
                       sys->lo,    sys->hi,    sys->rhs,    sys->obj};
    bl_lp *lp = o->mps && bl_lp_write_mps(&p, o->mps, err)
                    ? NULL
                    : bl_solve_lp(sys, sys->lo, sys->hi, NULL, o, err);
    if (!lp) {
        bl_system_free(sys);
        bl_solution_free(s);
        return -1;
    }
    double t2 = bl_clock();
    bl_lp_status st = bl_lp_solve(lp);
    double t3 = bl_clock();

    s->status = bl_status_of_lp(st);
    s->lp = bl_lp_engine(lp);
    s->iterations = bl_lp_iterations(lp);
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
