// lp_clp.cpp - the simplex engine of lp.h: COIN-OR CLP's dual simplex.
//
// C++ only because CLP's event handler, the one way to stop a running solve
// on Ctrl-C, is a C++ class; everything else is plain.

#include <ClpEventHandler.hpp>
#include <ClpSimplex.hpp>
#include <CoinMessageHandler.hpp>

#include <cmath>
#include <new>
#include <vector>

extern "C" {
#include "lp_engine.h"
}

namespace {

// Stops a solve on Ctrl-C or at the deadline (bl_clock() time, 0: none),
// which it notes in *late.
class InterruptHandler : public ClpEventHandler {
public:
    InterruptHandler(ClpSimplex *m, double deadline, bool *late)
        : ClpEventHandler(m), deadline_(deadline), late_(late) {}
    InterruptHandler(const InterruptHandler &o) = default;
    ClpEventHandler *clone() const override { return new InterruptHandler(*this); }
    int event(Event e) override
    {
        // Returning 0 makes CLP stop with status 5.
        if (e != endOfIteration && e != endOfFactorization) return -1;
        if (bl_interrupt_pending()) return 0;
        if (deadline_ > 0 && bl_clock() > deadline_) {
            *late_ = true;
            return 0;
        }
        return -1;
    }

private:
    double deadline_;
    bool *late_;
};

} // namespace

struct clp_lp {
    ClpSimplex model;
    int nrows = 0, ncols = 0;
    bool solved = false;
    bool objective_changed = false; // the next solve: primal, from the basis
    bool feasibility = false;       // no objective: the dual simplex from the start
    bool unscaled = false;          // the next solve: primal_unscaled
    std::vector<double> x, y, ray;
    int iterations = 0;
    bool late = false; // the last solve stopped at the deadline
};

static double clp_bound(double v)
{
    return std::isinf(v) ? (v > 0 ? COIN_DBL_MAX : -COIN_DBL_MAX) : v;
}

static void *create(const bl_lp_problem *p, const bl_lp_settings *s, bl_error *err)
{
    clp_lp *lp = new (std::nothrow) clp_lp;
    if (!lp) {
        bl_error_set(err, "lp: out of memory");
        return nullptr;
    }
    try {
        lp->nrows = p->nrows;
        lp->ncols = p->ncols;
        std::vector<double> lo(p->ncols), hi(p->ncols), obj(p->ncols);
        for (int j = 0; j < p->ncols; j++) {
            lo[j] = clp_bound(p->lo[j]);
            hi[j] = clp_bound(p->hi[j]);
            obj[j] = -p->obj[j]; // CLP minimizes
        }
        std::vector<CoinBigIndex> start(p->colptr, p->colptr + p->ncols + 1);
        // (free columns excepted: with them, joints that cannot slide, the
        // dual simplex called a check infeasible whose alpha_min was
        // below 0)
        lp->feasibility = true;
        for (int j = 0; j < p->ncols; j++)
            lp->feasibility = lp->feasibility && (obj[j] == 0.0 || lo[j] == hi[j]) &&
                              !(std::isinf(lo[j]) && std::isinf(hi[j]));
        lp->model.loadProblem(p->ncols, p->nrows, start.data(), p->rowind, p->val, lo.data(),
                              hi.data(), obj.data(), p->rhs, p->rhs);
        lp->model.setLogLevel(s->verbose ? 1 : 0);
        if (!s->verbose) lp->model.messageHandler()->setLogLevel(0);
        // Without a cap of its own, 50 pivots per row and column: CLP can
        // cycle (W4 at mu = 1e4, a restart's random stress state: two
        // bases in turn for minutes), and an LP that needs more is not
        // one the simplex should be solving (legitimate ones take a few
        // per row: 415,815 for 32 LPs of 3,120 rows, doc/seqlp.md 12).
        lp->model.setMaximumIterations(s->max_iterations > 0 ? s->max_iterations
                                                             : 50 * (p->nrows + p->ncols) + 10000);
        // CLP's default 1e-7 let a wrong fifth digit through on a 1,040-block
        // wall (doc/theory.md, verification).
        double tol = s->tolerance > 0 ? s->tolerance : 1e-9;
        lp->model.setPrimalTolerance(tol);
        lp->model.setDualTolerance(tol);
        InterruptHandler h(&lp->model, s->deadline, &lp->late);
        lp->model.passInEventHandler(&h);
        lp->x.assign(p->ncols, 0.0);
        lp->y.assign(p->nrows, 0.0);
    } catch (...) {
        delete lp;
        bl_error_set(err, "lp: CLP could not load the problem");
        return nullptr;
    }
    return lp;
}

static void destroy(void *e) { delete static_cast<clp_lp *>(e); }

static void set_bounds(void *e, const double *lo, const double *hi)
{
    clp_lp *lp = static_cast<clp_lp *>(e);
    for (int j = 0; j < lp->ncols; j++)
        lp->model.setColumnBounds(j, clp_bound(lo[j]), clp_bound(hi[j]));
}

static void set_objective(void *e, const double *obj)
{
    clp_lp *lp = static_cast<clp_lp *>(e);
    for (int j = 0; j < lp->ncols; j++) lp->model.setObjectiveCoefficient(j, -obj[j]);
    lp->objective_changed = true;
}

// The primal simplex on the unscaled problem, from the current values
// (CLP's values pass), CLP's own scaling kept for later solves.
static void primal_unscaled(clp_lp *lp)
{
    int scaling = lp->model.scalingFlag();
    lp->model.scaling(0);
    lp->model.primal(1);
    lp->model.scaling(scaling);
}

static bl_lp_status solve(void *e)
{
    clp_lp *lp = static_cast<clp_lp *>(e);
    lp->late = false;
    try {
        // Cold, the primal simplex took 7x fewer iterations than the dual on
        // a 1,040-block wall (doc/performance.md); after a bound change
        // the previous basis stays primal-infeasible but dual-feasible, the
        // dual simplex's warm start.  After an objective change it stays
        // primal-feasible instead: the primal simplex's.  Without an
        // objective (the dead-load check) every basis is dual-feasible, and
        // the dual simplex needs no first phase: 1,230 rows, 0.31 s against
        // 0.73 s where the check holds, 1.4 s against 5.9 s where it fails
        // (doc/theory.md 8).
        if (lp->unscaled) {
            primal_unscaled(lp);
            lp->unscaled = false;
        } else if ((lp->solved || lp->feasibility) && !lp->objective_changed) lp->model.dual(0);
        else lp->model.primal(0);
        lp->objective_changed = false;
        lp->solved = true;
        lp->iterations = lp->model.numberIterations();
        // "Optimal" for CLP's internally scaled problem can leave primal or
        // dual infeasibilities in the unscaled one (secondary status 2-4,
        // met on an arch with cohesion): finish from there unscaled.
        if (lp->model.status() == 0 && lp->model.secondaryStatus() >= 2 &&
            lp->model.secondaryStatus() <= 4) {
            primal_unscaled(lp);
            lp->iterations += lp->model.numberIterations();
        }
    } catch (...) {
        return BL_LP_FAILED;
    }
    int st = lp->model.status();
    lp->ray.clear();
    if (st == 1) {
        double *r = lp->model.infeasibilityRay();
        if (r) {
            lp->ray.assign(r, r + lp->nrows);
            delete[] r;
        }
    }
    if (st == 0) {
        const double *x = lp->model.primalColumnSolution();
        const double *y = lp->model.dualRowSolution();
        for (int j = 0; j < lp->ncols; j++) lp->x[j] = x[j];
        // CLP's prices are for the minimization of -obj: flip them.
        for (int i = 0; i < lp->nrows; i++) lp->y[i] = -y[i];
    }
    switch (st) {
    case 0: return BL_LP_OPTIMAL;
    case 1: return BL_LP_INFEASIBLE;
    case 2: return BL_LP_UNBOUNDED;
    case 3:
        // stopped on its iteration cap or (below it: a dome at mu = 0.4) on
        // numerical trouble
        if (lp->model.numberIterations() >= lp->model.maximumIterations())
            return BL_LP_ITERATION_LIMIT;
        return BL_LP_FAILED;
    case 5: return lp->late ? BL_LP_TIME_LIMIT : BL_LP_INTERRUPTED;
    default: return BL_LP_FAILED;
    }
}

// Tighter tolerances, and the primal simplex from the answer next, on the
// unscaled problem: the reduced costs it left within the old tolerance may
// now price in (scaled, they need not: a wall of 1,406 blocks kept an
// admissibility of 1.4e-6 at 1e-11, and met 4e-9 unscaled in 26 pivots).
static void tighten(void *e, double factor)
{
    clp_lp *lp = static_cast<clp_lp *>(e);
    lp->model.setPrimalTolerance(lp->model.primalTolerance() * factor);
    lp->model.setDualTolerance(lp->model.dualTolerance() * factor);
    lp->objective_changed = true;
    lp->unscaled = true;
}

static const double *primal(const void *e) { return static_cast<const clp_lp *>(e)->x.data(); }
static const double *dual(const void *e) { return static_cast<const clp_lp *>(e)->y.data(); }
static int iterations(const void *e) { return static_cast<const clp_lp *>(e)->iterations; }
static double factor_nnz(const void *) { return 0.0; }
static const double *ray(const void *e)
{
    const clp_lp *lp = static_cast<const clp_lp *>(e);
    return lp->ray.empty() ? nullptr : lp->ray.data();
}

extern "C" int bl_lp_write_mps(const bl_lp_problem *p, const char *file, bl_error *err)
{
    try {
        ClpSimplex model;
        std::vector<double> lo(p->ncols), hi(p->ncols), obj(p->ncols);
        for (int j = 0; j < p->ncols; j++) {
            lo[j] = clp_bound(p->lo[j]);
            hi[j] = clp_bound(p->hi[j]);
            obj[j] = -p->obj[j];
        }
        std::vector<CoinBigIndex> start(p->colptr, p->colptr + p->ncols + 1);
        model.loadProblem(p->ncols, p->nrows, start.data(), p->rowind, p->val, lo.data(),
                          hi.data(), obj.data(), p->rhs, p->rhs);
        model.messageHandler()->setLogLevel(0);
        if (model.writeMps(file, 1) != 0)
            return bl_error_set(err, "solve: cannot write the MPS file '%s'", file);
    } catch (...) {
        return bl_error_set(err, "solve: cannot write the MPS file '%s'", file);
    }
    return 0;
}

extern "C" const bl_lp_backend bl_lp_clp_engine = {
    "simplex", create, destroy, set_bounds, set_objective, solve, primal, dual, iterations, factor_nnz, ray,
    NULL, NULL, NULL, NULL, tighten,
};
