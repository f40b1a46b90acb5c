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
}

static bl_status from_lp(bl_lp_status st)
{
    switch (st) {
    case BL_LP_OPTIMAL: return BL_OPTIMAL;
    case BL_LP_INFEASIBLE: return BL_INFEASIBLE;
    case BL_LP_UNBOUNDED: return BL_UNBOUNDED;
    case BL_LP_ITERATION_LIMIT: return BL_ITERATION_LIMIT;
    case BL_LP_TIME_LIMIT: return BL_TIME_LIMIT;
    case BL_LP_INTERRUPTED: return BL_INTERRUPTED;
    default: return BL_NUMERICAL;
    }
}

/* A solution with its arrays allocated for the model copy c (owned). */
static bl_solution *solution_new(bl_model *c)
{
    bl_solution *s = calloc(1, sizeof *s);
    if (!s) {
        bl_model_free(c);
        return NULL;
    }
    s->model = c;
    size_t nb = (size_t)c->nblocks, ni = (size_t)c->ninterfaces;
    s->u = calloc(3 * nb + 1, sizeof *s->u);
    s->force = calloc(4 * ni + 1, sizeof *s->force);
    s->state = calloc(ni + 1, sizeof *s->state);
    s->hinge = calloc(ni + 1, sizeof *s->hinge);
    if (!s->u || !s->force || !s->state || !s->hinge) {
        bl_solution_free(s);
        return NULL;
    }
    for (size_t k = 0; k < ni; k++) s->hinge[k] = -1;
    return s;
}

int bl_assoc_solve(bl_model *m, const bl_solve_options *o, bl_solution **out, bl_error *err)
{
    bl_interrupt_clear();
    double t0 = bl_clock();
    if (!m->contacts_valid && bl_contact_detect(m, err)) return -1;
    double t1 = bl_clock();

    bl_model *copy = bl_model_copy(m);
    bl_solution *s = copy ? solution_new(copy) : NULL;
    if (!s) return bl_error_set(err, "solve: out of memory");
    bl_system *sys = bl_system_build(m, err);
    if (!sys) {
        bl_solution_free(s);
        return -1;
    }
    bl_lp_settings ls;
    bl_lp_settings_default(&ls);
    ls.verbose = o->verbose;
    ls.max_seconds = o->time_limit;
    ls.max_iterations = o->iterations;
    ls.engine = o->lp;
    bl_lp_problem p = {sys->nrows, sys->ncols, sys->colptr, sys->rowind, sys->val,
                       sys->lo,    sys->hi,    sys->rhs,    sys->obj};
    bl_lp *lp = o->mps && bl_lp_write_mps(&p, o->mps, err) ? NULL : bl_lp_create(&p, &ls, err);
    if (!lp) {
        bl_system_free(sys);
        bl_solution_free(s);
        return -1;
    }
    double t2 = bl_clock();
    bl_lp_status st = bl_lp_solve(lp);
    double t3 = bl_clock();

    s->status = from_lp(st);
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
        bl_system_forces(sys, m, x, s->force);
        bl_system_mechanism(sys, m, y, s->u);
        bl_solution_classify(s);
        s->verified = bl_verify(sys, s->alpha, x, y, o->tolerance, &s->res);
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
