/* lp.c - the LP interface: dispatches to the engine chosen in the settings. */
#include "lp.h"

#include <omp.h>
#include <stdlib.h>

#include "lp_engine.h"

struct bl_lp {
    const bl_lp_backend *engine;
    void *impl;
};

bl_lp_engine_kind bl_lp_choose(bl_lp_engine_kind asked, int nrows, int ncols)
{
    if (asked != BL_LP_AUTO) return asked;
    int wide = ncols > BL_LP_AUTO_COLS && ncols > 5 * nrows;
    return nrows <= BL_LP_AUTO_ROWS && !wide ? BL_LP_SIMPLEX : BL_LP_IPM;
}

int bl_lp_cores(int threads)
{
    int allowed = threads > 0 ? threads : omp_get_max_threads(), procs = omp_get_num_procs();
    return allowed < procs ? allowed : procs;
}

int bl_lp_leaves_core(bl_lp_engine_kind asked, int threads, int nrows, int ncols)
{
    if (bl_lp_cores(threads) < 2) return 0;
    if (bl_lp_choose(asked, nrows, ncols) == BL_LP_SIMPLEX) return 1;
    return ncols < BL_IPM_PAR_COLS && nrows < BL_IPM_SPLIT_ROWS;
}

void bl_lp_settings_default(bl_lp_settings *s)
{
    s->engine = BL_LP_AUTO;
    s->verbose = 0;
    s->max_iterations = 0;
    s->deadline = 0;
    s->tolerance = 0; /* the engine's own default */
    s->threads = 0;
    s->early_infeasible = 0;
    s->weighted = 1;
    s->progress = 0;
}

bl_lp *bl_lp_create(const bl_lp_problem *p, const bl_lp_settings *s, bl_error *err)
{
    bl_lp *lp = malloc(sizeof *lp);
    if (!lp) {
        bl_error_set(err, "lp: out of memory");
        return NULL;
    }
    lp->engine = bl_lp_choose(s->engine, p->nrows, p->ncols) == BL_LP_IPM ? &bl_lp_ipm_engine
                                                                : &bl_lp_clp_engine;
    lp->impl = lp->engine->create(p, s, err);
    if (!lp->impl) {
        free(lp);
        return NULL;
    }
    return lp;
}

void bl_lp_free(bl_lp *lp)
{
    if (!lp) return;
    lp->engine->free(lp->impl);
    free(lp);
}

void bl_lp_set_bounds(bl_lp *lp, const double *lo, const double *hi)
{
    lp->engine->set_bounds(lp->impl, lo, hi);
}

void bl_lp_set_objective(bl_lp *lp, const double *obj)
{
    lp->engine->set_objective(lp->impl, obj);
}

bl_lp_status bl_lp_solve(bl_lp *lp) { return lp->engine->solve(lp->impl); }
const double *bl_lp_primal(const bl_lp *lp) { return lp->engine->primal(lp->impl); }
const double *bl_lp_dual(const bl_lp *lp) { return lp->engine->dual(lp->impl); }
int bl_lp_iterations(const bl_lp *lp) { return lp->engine->iterations(lp->impl); }
double bl_lp_factor_nnz(const bl_lp *lp) { return lp->engine->factor_nnz(lp->impl); }
const double *bl_lp_ray(const bl_lp *lp) { return lp->engine->ray(lp->impl); }
int bl_lp_mark(bl_lp *lp) { return lp->engine->mark ? lp->engine->mark(lp->impl) : -1; }
void bl_lp_rewind(bl_lp *lp)
{
    if (lp->engine->rewind) lp->engine->rewind(lp->impl);
}
int bl_lp_warm(bl_lp *lp, const double *x, const double *zl, const double *zu, const double *y,
               double mu)
{
    return lp->engine->warm ? lp->engine->warm(lp->impl, x, zl, zu, y, mu) : -1;
}
void bl_lp_cold(bl_lp *lp)
{
    if (lp->engine->cold) lp->engine->cold(lp->impl);
}
int bl_lp_tighten(bl_lp *lp, double factor)
{
    if (!lp->engine->tighten) return -1;
    lp->engine->tighten(lp->impl, factor);
    return 0;
}
const char *bl_lp_engine(const bl_lp *lp) { return lp->engine->name; }
