/* verify.h - the evidence that an answer (alpha, x, u) is right.
 *
 * Every residual of doc/theory.md, "Verification", computed in the scaled
 * system, independently of how the answer was found.  An answer is verified
 * when all of them are at most the tolerance. */
#ifndef BL_VERIFY_H
#define BL_VERIFY_H

#include "assemble.h"
#include "solution.h"

/* x: force columns (s->nforce), y: scaled row multipliers (s->nrows).
 * Returns 1 when every residual is <= tol. */
int bl_verify(const bl_system *s, double alpha, const double *x, const double *y, double tol,
              bl_residuals *res);

/* The residuals of the seed's Eq. 12 for a non-associative answer: forces
 * xc on the cone system (the certificate's), the mechanism y (scaled row
 * multipliers, from the fixed-capacity LP; both systems share their rows).
 * Kinematics are judged per contact point from the relative velocity
 * (dn, dt); motions below slip times the largest one count as zero.
 * Returns 1 when equilibrium, yield, admissibility and normalization are
 * <= tol and the flow-rule residuals (complementarity, flow, dilatancy,
 * work) are <= slip, and never above BL_FLOW_TOL_MAX: with slip = 0.1 a
 * wall's sequence certified an alpha 8 % low, its work residual 0.05. */
#define BL_FLOW_TOL_MAX 1e-3
int bl_verify_nonassoc(const bl_system *cone, const bl_system *fixed, double alpha,
                       const double *xc, const double *y, double tol, double slip,
                       bl_residuals *res);

#endif
