/* lp.h - the thin interface every method uses to solve a linear program.
 *
 *     maximize obj . x   subject to   A x = rhs,   lo <= x <= hi
 *
 * (equality rows and variable bounds only: the bounds-only form of
 * assemble.h).  An opaque workspace is made once per problem; the bounds can
 * then be changed and the problem re-solved from the previous basis, which
 * is what a sequence of LPs needs.  An infeasible or unbounded LP is an
 * outcome, not an error. */
#ifndef BL_LP_H
#define BL_LP_H

#include "error.h"

typedef struct bl_lp_problem {
    int nrows, ncols;
    const int *colptr, *rowind; /* CSC, borrowed for the call to create */
    const double *val;
    const double *lo, *hi, *rhs, *obj;
} bl_lp_problem;

typedef enum bl_lp_engine_kind {
    BL_LP_AUTO,          /* chosen by bl_lp_choose from the size */
    BL_LP_SIMPLEX,       /* CLP: primal simplex cold, dual simplex warm */
    BL_LP_IPM            /* interior point on CHOLMOD (lp_ipm.c) */
} bl_lp_engine_kind;

/* The engine "auto" means for an LP of nrows equality rows and ncols
 * columns: the simplex up to BL_LP_AUTO_ROWS rows (its answer is a vertex:
 * one clean mechanism) unless the columns outnumber BL_LP_AUTO_COLS and 5
 * per row (3D pyramids: a dome of 576 rows and 11,747 columns took the
 * simplex 49 s, the interior point 1.1 s), the interior point otherwise
 * (doc/performance.md has the measurements). */
#define BL_LP_AUTO_ROWS 600
#define BL_LP_AUTO_COLS 2000
bl_lp_engine_kind bl_lp_choose(bl_lp_engine_kind asked, int nrows, int ncols);

/* The cores a solve may use: the threads allowed (threads, 0:
 * OMP_NUM_THREADS or every core), at most the processors. */
int bl_lp_cores(int threads);

/* 1 when bl_lp_cores(threads) is two or more and an LP of nrows x ncols on the
 * engine chosen for "asked" keeps only one of them busy: the simplex
 * always, the interior point below the sizes where it threads its loops
 * and splits its factor (lp_engine.h).  Another computation can then run
 * beside it without slowing it much; threads = 1 keeps a whole solve on
 * one core. */
int bl_lp_leaves_core(bl_lp_engine_kind asked, int threads, int nrows, int ncols);

/* Forces beyond this many per equality row, in units of the block weights
 * (W0), are taken as the self-stress of blocks confined between supports,
 * which no equilibrium needs (some 30 times a model's weight): the
 * associative solve caps its forces there (assoc.c), and the interior
 * point's stall test reads larger ones as an unbounded optimal face. */
#define BL_LP_CONFINED 10.0

typedef struct bl_lp_settings {
    bl_lp_engine_kind engine;
    int verbose;         /* 0: the engine prints nothing */
    int max_iterations;  /* 0: engine default */
    double deadline;     /* bl_clock() time at which a solve stops, BL_LP_TIME_LIMIT;
                            0: none */
    double tolerance;    /* simplex: primal and dual feasibility;
                            ipm: relative residuals and gap */
    int threads;         /* ipm: threads, 0: OMP_NUM_THREADS or every core */
    int early_infeasible; /* ipm: infeasible at the first step of y that
                             proves any equilibrium would need ten times
                             the path's forces (lp_ipm.c, ray_test): for
                             LPs whose "infeasible" only means "go on" */
    int weighted;        /* ipm: the weighted central path (lp_ipm.c,
                             path_weights); 0: the analytic centre's */
    int progress;        /* ipm: from half a second into a solve, one line on
                            standard error with its iteration and largest
                            residual, rewritten at each and cleared at the
                            end (not with verbose) */
} bl_lp_settings;

void bl_lp_settings_default(bl_lp_settings *s);

typedef enum bl_lp_status {
    BL_LP_OPTIMAL,
    BL_LP_INFEASIBLE,
    BL_LP_UNBOUNDED,
    BL_LP_ITERATION_LIMIT,
    BL_LP_TIME_LIMIT,
    BL_LP_INTERRUPTED,
    BL_LP_FAILED
} bl_lp_status;

typedef struct bl_lp bl_lp;

/* NULL with err set on failure.  The matrix (colptr, rowind, val) is kept
 * by reference and must outlive the bl_lp; the other arrays are copied. */
bl_lp *bl_lp_create(const bl_lp_problem *p, const bl_lp_settings *s, bl_error *err);
void bl_lp_free(bl_lp *lp);

/* Replaces all column bounds (arrays of ncols). */
void bl_lp_set_bounds(bl_lp *lp, const double *lo, const double *hi);

/* Replaces the objective (ncols, maximized).  The next solve starts
 * afresh from the last answer: the simplex by its primal method from its
 * basis (still feasible where only the objective changed), the interior
 * point cold, keeping its analysis. */
void bl_lp_set_objective(bl_lp *lp, const double *obj);

/* Solves (warm from the last basis when there is one), polling
 * bl_interrupt_pending() between iterations. */
bl_lp_status bl_lp_solve(bl_lp *lp);

/* After an optimal solve: x (ncols) and the row multipliers y (nrows), with
 * the sign for which the reduced costs obj - A^T y are <= 0 at columns on
 * their lower bound and >= 0 on their upper bound.  Owned by lp. */
const double *bl_lp_primal(const bl_lp *lp);
const double *bl_lp_dual(const bl_lp *lp);
int bl_lp_iterations(const bl_lp *lp);
/* After an infeasible solve: a Farkas ray y of the rows (nrows; y.b > 0
 * while A^T y <= 0 within the bounds), owned by lp; NULL when the engine has
 * none.  Rows with large |y| are the ones whose equilibrium cannot be met. */
const double *bl_lp_ray(const bl_lp *lp);

/* A solve that turns out not to be needed (one solved ahead of a decision
 * that then made it unnecessary) can be taken back as far as later solves
 * see it: bl_lp_mark remembers where the next warm start would begin,
 * bl_lp_rewind returns there, and the solves after it run as if the one in
 * between had not been made (its answer is gone too: copy what is needed
 * first).  bl_lp_mark returns -1 when the engine cannot (the simplex, whose
 * warm start is its basis). */
int bl_lp_mark(bl_lp *lp);
void bl_lp_rewind(bl_lp *lp);

/* The next solve starts from the interior point x (ncols; alpha among them)
 * with the duals zl, zu of the lower and upper bounds (ncols; 0 where a
 * bound is infinite), the row multipliers y (nrows, the sign of
 * bl_lp_dual) and mean product mu: a point of the path of another problem
 * that is near this LP's (napath.h).  -1 when the engine cannot (the
 * simplex). */
int bl_lp_warm(bl_lp *lp, const double *x, const double *zl, const double *zu, const double *y,
               double mu);

/* The next solve starts as the first did: the interior point from its
 * starting point (for an LP whose answer lies far from the last one's),
 * keeping the analysis of its normal matrix; the simplex keeps its basis,
 * whose warm start costs it little. */
void bl_lp_cold(bl_lp *lp);

/* The next solve goes on from the last answer with the engine's
 * feasibility tolerances times factor (< 1), for an answer that the
 * verification finds short of its own tolerance.  -1 when the engine
 * cannot (the interior point, whose tolerances stop its path). */
int bl_lp_tighten(bl_lp *lp, double factor);

/* Non-zeros of the interior point's Cholesky factor (0 for the simplex). */
double bl_lp_factor_nnz(const bl_lp *lp);
/* Writes p to file in MPS format, as the minimization of -obj (free MPS
 * has no objective sense), with full precision.  0 or -1 with err. */
int bl_lp_write_mps(const bl_lp_problem *p, const char *file, bl_error *err);

/* Name of the engine ("simplex", "ipm"). */
const char *bl_lp_engine(const bl_lp *lp);

#endif
