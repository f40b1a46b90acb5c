/* normal.h - the normal matrix of the interior-point engine.
 *
 * M = F F^T + delta I, with F = A(:, map) diag(scale): column k of F is
 * column map[k] of the engine's matrix A, scaled.  The pattern is analysed
 * once; every iteration refills the values, refactors and solves.  Large
 * matrices are split by a vertex separator into two domains factored and
 * solved on two threads, joined through the separator's dense Schur
 * complement (doc/theory.md, "The interior-point engine").
 */
#ifndef BL_NORMAL_H
#define BL_NORMAL_H

#include "error.h"

typedef struct bl_normal bl_normal;

/* A by columns (kept by reference while the bl_normal lives) and the map
 * from F's n columns to A's. */
typedef struct bl_normal_pattern {
    int m, n;
    const int *colptr, *rowind, *map;
    const double *val;
} bl_normal_pattern;

/* threads >= 2 allows the split into two domains (done from about 10,000
 * rows).  NULL with err set on failure. */
bl_normal *bl_normal_analyse(const bl_normal_pattern *A, int threads, int verbose, bl_error *err);
void bl_normal_free(bl_normal *N);

/* Sets F's values for the column scales (n); returns the largest F entry
 * squared. */
double bl_normal_fill(bl_normal *N, const double *scale);

/* Factors F F^T + delta I: 0, 1 when a pivot was not positive (raise
 * delta), -1 on failure. */
int bl_normal_factor(bl_normal *N, double delta);

/* Solves M x = rhs[r] in place (m each) for nrhs = 1 or 2 right-hand
 * sides, reading the factor once for both; 0 or -1. */
int bl_normal_solve(bl_normal *N, double *const *rhs, int nrhs);

/* 2 when the matrix was split into two domains, else 1. */
int bl_normal_domains(const bl_normal *N);

/* Non-zeros of the factor (both domains and the separator) and the flops
 * of one factorization, as CHOLMOD's analysis counts them. */
double bl_normal_nnz(const bl_normal *N);
double bl_normal_flops(const bl_normal *N);

#endif
