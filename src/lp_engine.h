/* lp_engine.h - what an LP engine provides to lp.c (internal to the lp
 * module: methods include lp.h only). */
#ifndef BL_LP_ENGINE_H
#define BL_LP_ENGINE_H

#include "lp.h"

typedef struct bl_lp_backend {
    const char *name;
    void *(*create)(const bl_lp_problem *p, const bl_lp_settings *s, bl_error *err);
    void (*free)(void *e);
    void (*set_bounds)(void *e, const double *lo, const double *hi);
    void (*set_objective)(void *e, const double *obj);
    bl_lp_status (*solve)(void *e);
    const double *(*primal)(const void *e);
    const double *(*dual)(const void *e);
    int (*iterations)(const void *e);
    double (*factor_nnz)(const void *e);
    const double *(*ray)(const void *e);
    int (*mark)(void *e);    /* NULL: the engine cannot (lp.h, bl_lp_mark) */
    void (*rewind)(void *e);
    int (*warm)(void *e, const double *x, const double *zl, const double *zu, const double *y,
                double mu); /* NULL: the engine cannot (lp.h, bl_lp_warm) */
    void (*cold)(void *e);   /* NULL: nothing to forget (lp.h, bl_lp_cold) */
    void (*tighten)(void *e, double factor); /* NULL: the engine cannot (lp.h, bl_lp_tighten) */
} bl_lp_backend;

/* Where the interior point uses more than one core: its loops over the
 * internal columns and its products with A from BL_IPM_PAR_COLS columns
 * (below, the fork costs more than it gives: 1,040 blocks, 12,000
 * columns, 0.17 s on one thread against 0.24 s on two), its two domains
 * from BL_IPM_SPLIT_ROWS rows (below, one factorization is faster than
 * two threads' wake-ups); doc/performance.md, "Threads". */
#define BL_IPM_PAR_COLS 20000
#define BL_IPM_SPLIT_ROWS 10000

extern const bl_lp_backend bl_lp_clp_engine;
extern const bl_lp_backend bl_lp_ipm_engine;

#endif
