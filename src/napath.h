/* napath.h - the path of the non-associative problem: an interior point on
 * the complementarity conditions of the seed's Eq. 12 themselves (doc/theory.md
 * §6.3), as a start for the sequence of LPs.
 *
 * Equilibrium with alpha free, Coulomb's cone |t| <= mu n at every contact
 * point, the mechanism's normal motion complementary to n and its slip
 * opposing t at the cone's edge, normalized by the live load's power: the
 * associative LP's optimality conditions without the dilatancy term.  The
 * products of the complementary pairs are driven to zero along a smoothed
 * path from a point inside every bound, by Newton steps on a linear system
 * that is not symmetric.  The problem is not monotone, so the
 * path need not reach a solution; its normal forces, part of the way
 * there, start the sequence of LPs, which then certifies an answer in far
 * fewer LPs than from the associative forces (doc/seqlp.md 15).  The
 * linear systems are factored by MUMPS (LU). */
#ifndef BL_NAPATH_H
#define BL_NAPATH_H

#include <stdatomic.h>

#include "assemble.h"
#include "error.h"

typedef struct bl_napath_result {
    int iterations;        /* Newton steps taken */
    double alpha;          /* the path's alpha at the last one */
    double complementarity; /* sum of the products over 1 + |alpha| */
    double mu;             /* their mean */
    int deep;              /* the point went on past target to deep */
    int stopped;           /* Ctrl-C or the deadline stopped it */
    double seconds;
} bl_napath_result;

/* What bl_napath_run writes on stderr: nothing; a line per step; or,
 * from half a second on, one progress line rewritten at every step
 * ("seqlp: the path, step k, products p") and cleared at the end. */
enum { BL_NAPATH_QUIET, BL_NAPATH_VERBOSE, BL_NAPATH_PROGRESS };

/* Whether s (a BL_FRICTION_FIXED system) is one the path is made for: 2D,
 * every contact point with finite, non-zero friction and no cohesion. */
int bl_napath_applies(const bl_system *s);

/* Follows the path on s until the complementarity (sum of the products
 * over 1 + |alpha|) is at most target with the residuals below 1e-6, in at
 * most max_iterations steps; a path that stalls (products not halved in 20
 * steps) or reaches its last step is still taken when its complementarity
 * is at most near (>= target).  From a point at target it goes on, while
 * the products halve at least every few steps, to one at most deep
 * (< target; res->deep is then 1), and returns that one instead; when it
 * does not get there, the point at target and its result stand (deep >=
 * target: no such phase).  The last point in the terms of s's columns (ncols
 * each): x (forces and alpha), zl and zu the multipliers of the bounds
 * 0 <= n and -mu n <= t <= mu n, and y (nrows) the mechanism, with the sign
 * of bl_lp_dual: the point of the fixed LP whose capacities are mu times
 * these normal forces, near its own path (lp.h, bl_lp_warm).  Returns 0,
 * 1 when the path did not get there (stalled or at the cap farther than
 * near, a step that is not finite, a factorization that failed: nothing
 * is set), or -1 with err set (out of memory).  Ctrl-C, the deadline (0:
 * none) and *cancel turning non-zero (cancel may be NULL) stop it between
 * steps (res->stopped). */
int bl_napath_run(const bl_system *s, double target, double near, double deep, int max_iterations,
                  double deadline, const atomic_int *cancel, int report, double *x, double *zl,
                  double *zu, double *y, bl_napath_result *res, bl_error *err);

#endif
