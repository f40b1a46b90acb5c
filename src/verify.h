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

#endif
