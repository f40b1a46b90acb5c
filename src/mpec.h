/* mpec.h - limit analysis as one nonlinear program solved by Ipopt: the
 * seed's Eq. 12, a mathematical program with equilibrium constraints
 * (doc/theory.md, "The direct solve").
 *
 * Unknowns: alpha, the contact forces on the Coulomb cone's edges (as in
 * the associative LP), the block velocities, slip rates and complementarity
 * slacks.  Statics, kinematics and normalization are linear; the only
 * nonlinear terms are the products of complementary pairs, which either
 * enter the objective as a penalty rho sum(a b), or are bounded,
 * a b <= eps, with eps driven to zero, or both.  The associative variant
 * (flow = associative) solves the same problem with the associative flow
 * rule and must reproduce the LP's alpha. */
#ifndef BL_MPEC_H
#define BL_MPEC_H

#include "seqlp.h"

typedef enum bl_mpec_complementarity {
    BL_MPEC_PENALTY,     /* minimize alpha + rho sum(a b) */
    BL_MPEC_RELAXATION,  /* a b <= eps, eps = 1e-2 ... 1e-10, one solve each */
    BL_MPEC_HOMOTOPY     /* both: the penalty, and a b <= eps driven to zero */
} bl_mpec_complementarity;

typedef enum bl_mpec_start {
    BL_MPEC_START_COLD,  /* Ipopt's own start from zero */
    BL_MPEC_START_ASSOC, /* the associative LP's answer */
    BL_MPEC_START_SEQLP  /* the sequence of LPs' certified answer */
} bl_mpec_start;

typedef struct bl_mpec_options {
    bl_seqlp_options seq;          /* LP engine, tolerance, verbose, time limit; the
                                      sequence's settings for start = seqlp */
    int nonassociative;            /* the flow rule (1: no dilatancy) */
    bl_mpec_complementarity comp;
    bl_mpec_start start;
    double penalty;                /* rho (100) */
    int iterations;                /* Ipopt's iteration cap per solve (3000) */
} bl_mpec_options;

void bl_mpec_options_default(bl_mpec_options *o);

/* As bl_assoc_solve.  The solution's alpha is Ipopt's, verified by the
 * residuals of the chosen flow rule; an Ipopt failure is a status, with the
 * last point and its residuals. */
int bl_mpec_solve(bl_model *m, const bl_mpec_options *o, bl_solution **out, bl_error *err);

#endif
