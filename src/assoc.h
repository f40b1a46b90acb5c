/* assoc.h - limit analysis with associative flow: one LP.
 *
 * The static LP (maximize alpha subject to equilibrium and yield, the seed's
 * Eq. 10) gives alpha and the contact forces; its row multipliers are the
 * mechanism of the kinematic LP (Eq. 11), so no second solve is needed. */
#ifndef BL_ASSOC_H
#define BL_ASSOC_H

#include "lp.h"
#include "model.h"
#include "solution.h"
#include "assemble.h"

typedef struct bl_solve_options {
    double tolerance;   /* verification tolerance (default 1e-7) */
    int verbose;        /* let the LP engine print */
    double deadline;    /* bl_clock() time at which the solve stops (time_limit
                         * seconds after it began), 0: none */
    int iterations;     /* iteration cap of the LP engine, 0: its default */
    int threads;        /* of the interior point, 0: every core */
    bl_lp_engine_kind lp;
    const char *mps;    /* write the LP to this MPS file first, or NULL */
    bl_cone cone;       /* 3D: the friction pyramid (8 facets, inscribed) */
    int early_infeasible; /* the LP's "infeasible" only means "go on": the
                             interior point may stop at an early dual ray
                             (lp.h); not a user option */
    double lp_tolerance;  /* the LP engine's stopping tolerance, 0: its
                             default (lp.h: 1e-8 for the interior point,
                             1e-9 for the simplex) */
    int weighted;       /* the interior point's weighted path (lp.h); the
                           sequence of LPs and the direct solve leave it
                           off for their own LPs and their start */
    int progress;       /* the interior point's progress line on the
                           associative LP and the checks after it (lp.h),
                           not on a dead-load check beside it; the
                           sequence's fixed LPs show none (seqlp.c) */
    int dead_load;      /* the check that the dead load alone has an
                           equilibrium (bl_assoc_solve): BL_DEAD_BESIDE (the
                           default), BL_DEAD_AFTER or BL_DEAD_NONE; not a
                           user option */
} bl_solve_options;

/* When the dead-load check runs: beside the LP on the core it leaves idle
 * (after it where none is), after it, or not at all. */
enum { BL_DEAD_NONE, BL_DEAD_AFTER, BL_DEAD_BESIDE };

void bl_solve_options_default(bl_solve_options *o);

/* An LP of the system s (assemble.h) with the given bounds and objective
 * (NULL: the system's own), on the engine and limits of o.  NULL with err
 * set on failure. */
bl_lp *bl_solve_lp(const bl_system *s, const double *lo, const double *hi,
                   const double *obj, const bl_solve_options *o, bl_error *err);

/* Whether an LP of m with nrows rows that the interior point failed is
 * solved again by the simplex: up to BL_SIMPLEX_ROWS rows, or
 * BL_SIMPLEX_CHAIN_ROWS on a chain of blocks (assoc.c). */
int bl_simplex_rescues(const bl_model *m, int nrows);

/* Detects interfaces when needed (which may fail: err says why), assembles,
 * solves and verifies.  Maximizing alpha finds the top of the interval of
 * alphas with an equilibrium; one more LP, alpha fixed at 0, tells whether
 * it holds 0 (s->stands).  Where it does not, the live load holds the
 * structure up: the status is BL_UNSTABLE and s->alpha_min the bottom of
 * the interval (doc/theory.md 8).  On success *out is a new solution whose status may
 * be any bl_status: an infeasible model is an answer, not an error. */
int bl_assoc_solve(bl_model *m, const bl_solve_options *o, bl_solution **out, bl_error *err);

/* Why a model is infeasible: the dead load alone, made the live load (no
 * other), solved as bl_assoc_solve does.  Its alpha is the largest multiple
 * of the dead load that has an equilibrium, below 1 where the dead load
 * alone cannot stand, and its mechanism how it then fails
 * (doc/theory.md 8). */
int bl_assoc_dead_alone(const bl_model *m, const bl_solve_options *o, bl_solution **out, bl_error *err);

#endif
