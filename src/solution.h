/* solution.h - the answer of a solve: multiplier, forces, mechanism,
 * interface states, verification and timings.
 *
 * A solution owns a copy of the model it was computed for, so that drawing
 * and reporting stay correct when the user edits the model afterwards. */
#ifndef BL_SOLUTION_H
#define BL_SOLUTION_H

#include "lp.h"
#include "model.h"
#include "assemble.h"

typedef enum bl_status {
    BL_OPTIMAL,      /* alpha >= 0 found */
    BL_UNSTABLE,     /* cannot stand under dead load alone: alpha < 0, or
                        alpha = 0 has no equilibrium (stands = 0) */
    BL_UNBOUNDED,    /* the live load cannot produce a mechanism */
    BL_INFEASIBLE,   /* no equilibrium for any alpha */
    BL_ITERATION_LIMIT,
    BL_TIME_LIMIT,
    BL_INTERRUPTED,
    BL_NUMERICAL,    /* the LP engine failed */
    BL_UNCERTIFIED,  /* the sequence of LPs found no certified answer */
    BL_LOCALLY_INFEASIBLE, /* Ipopt: converged to a point of least infeasibility */
    BL_RESTORATION_FAILED, /* Ipopt: its restoration phase failed */
    BL_NOT_COMPLEMENTARY   /* Ipopt converged, but not to a solution: the
                              verifier rejects it (complementarity, flow) */
} bl_status;

/* The status word the Lua side shows ("optimal", "unstable", ...) and a
 * sentence that explains it. */
const char *bl_status_name(bl_status s);
const char *bl_status_sentence(bl_status s);

typedef enum bl_state {
    BL_CLOSED,       /* no relative motion */
    BL_ROCKING,      /* one end opens, a hinge at the other */
    BL_SLIDING,      /* tangential relative motion */
    BL_SEPARATING    /* both ends open */
} bl_state;

const char *bl_state_name(bl_state s);

/* Residuals of DESIGN 2.6, each scaled to be unit-free (doc/theory.md). */
typedef struct bl_residuals {
    double equilibrium;     /* |A x + alpha fL + fD| / W0 */
    double yield;           /* bound violation / W0 */
    double admissibility;   /* interpenetration / V */
    double complementarity; /* max |x_j (A^T u)_j| / (X V) */
    double normalization;   /* |fL . u - 1| */
    double work;            /* |alpha fL.u + fD.u + D| / |alpha fL . u| + |fD.u| */
    /* non-associative flow only (NAN otherwise): */
    double flow;            /* friction opposing the slip: |t dt + R |dt|| / (X V) */
    double dilatancy;       /* opening where a loaded point slides, / V */
    /* the relative motions nearest the slip threshold, over V: the largest
     * taken as none (below slip) and the least counted (at or above it) */
    double below, above;
} bl_residuals;

typedef struct bl_timings {
    double detection, assembly, solve, verification, total;
    double stands;  /* the dead-load check's LPs (part of total; beside the
                       solve, its own duration) */
} bl_timings;

/* One start of the sequence of LPs: where its alphas begin in the
 * solution's history, what it cost (its random stress state's LP, its fixed
 * LPs and certificates), and its certified alpha (NAN: none). */
typedef struct bl_start {
    int first;
    int continues;  /* the 1-based start this one goes on with, or 0 */
    int lps, iterations;
    int certificates, nearest; /* certificates tried, nearest-force steps */
    double seconds;
    double alpha;
    double search_mu; /* the friction its search was capped at (its stress
                         state, fixed LPs), or inf: each joint's own */
} bl_start;

typedef struct bl_solution {
    bl_model *model;         /* owned copy, interfaces detected */
    bl_status status;
    double alpha;
    int has_mechanism;       /* u, state and hinge are meaningful */
    double *u;               /* 3 per block: vx, vy, omega (1/force units,
                                live load does unit work); 0 for supports */
    double *force;           /* 2D, 4 per interface: n0, t0, n1, t1 at p[0], p[1];
                                3D, 3 per polygon vertex: n, t2, t3 */
    double *reaction;        /* 6 per block: what the free blocks exert on
                                a support, force and moment about the
                                origin (bl_system_reactions); 0 elsewhere */
    /* the scaled answer on the Coulomb-cone system (assemble.h), owned,
     * NULL when there is none: its columns (forces, then alpha) and its
     * row multipliers (the mechanism); a start for another method */
    double *x, *y;
    int nx, ny;
    bl_state *state;         /* per interface */
    int *hinge;              /* per interface: 0 or 1 for a rocking joint's
                                closed end, -1 otherwise (2D) */
    double motion_eps;       /* relative velocities up to this count as zero */
    double *speed;           /* per interface: its largest relative velocity */
    double speed_max;        /* the largest over the interfaces */
    int stands;              /* alpha = 0 has an equilibrium within the yield
                                conditions: 1, 0 (the check's LP is
                                infeasible), -1 (not decided: not checked, or
                                the check stopped at a limit) */
    double alpha_min;        /* stands = 0: the least alpha with an
                                equilibrium (NAN otherwise) */
    bl_residuals res;
    double tolerance;        /* what "verified" was judged against */
    int verified;
    bl_timings time;
    int iterations;          /* LP engine iterations */
    int cone_rounds;         /* 3D: LPs solved (more than 1 with the adaptive cone) */
    bl_cone cone;            /* 3D: the pyramid used (theta0 not kept) */
    int rows, cols;          /* size of the LP */
    double factor_nnz;       /* interior point: non-zeros of the Cholesky factor */
    const char *lp;          /* engine name, static */
    /* the method and, for the sequence of LPs, its record */
    const char *method;      /* "assoc" or "seqlp", static */
    const char *flow;        /* "associative" or "nonassociative", static */
    double alpha_assoc;      /* the associative multiplier */
    int assoc_verified;      /* ... passed its own checks */
    double alpha_rigid;      /* ... with unlimited friction (INFINITY: unbounded) */
    double alpha_settled;    /* the alpha of the LP whose mechanism the answer's
                                certificate holds (the answer is at or below it) */
    int given;               /* the answer is that of the given-th mechanism the
                                solve was given to try (1-based), or 0 */
    int given_tried, given_certified; /* of the mechanisms given: tried, certified */
    int early;               /* that LP came before its sequence settled, below the
                                lowest alpha certified until then (seqlp.c) */
    int assoc_is_solution;   /* alpha_assoc = alpha_rigid: friction limits nothing */
    const char *restarts_why; /* why the default ran restarts (static), or NULL */
    int skipped;             /* restarts skipped: no stress state could be drawn */
    int lp_switched;         /* the sequence's fixed LPs went to the other engine (lp) */
    int certified;           /* a certificate LP accepted (alpha, x, u) */
    int interrupted;         /* Ctrl-C ended the search early */
    int time_up;             /* the time limit ended it, after an answer */
    int live_scales_dead;    /* the live load is the self weight along
                                gravity: unbounded where it stands */
    int none_dilates;        /* no joint has friction (mu = 0 everywhere):
                                the associative answer, no sequence */
    double slip;             /* the slip threshold used, relative */
    int lps;                 /* LPs solved (all kinds) */
    int nhistory;
    double *history;         /* alpha of each LP of the sequence, owned */
    int nstarts;
    bl_start *start;         /* each start of the sequence, owned */
    char note[256];          /* why a start ended without an answer, or "" */
    int path_steps;          /* the path of the non-associative problem (napath.h):
                                its Newton steps, 0 when none ran */
    int path_taken;          /* whether it started the sequence (else start 0
                                began from the associative forces) */
    int path_stopped;        /* Ctrl-C or the time limit stopped it */
    double path_alpha, path_products, path_seconds;
    /* the direct solve (method "mpec") */
    double alpha_start;      /* alpha of the point it started from (NAN: cold) */
    const char *nlp_status;  /* Ipopt's outcome in words, static */
    const char *comp;        /* "penalty", "relaxation" or "homotopy", static */
    const char *start_kind;  /* where it started ("cold", "assoc", "seqlp"), static */
    const char *start_why;   /* why from there, when not as asked; or NULL */
    double pair_sum;         /* sum of the complementary products at the end */
    double alpha_ipopt;      /* alpha of Ipopt's last point */
    bl_residuals res_ipopt;  /* ... its residuals, where the start was kept */
    int kept_start;          /* Ipopt's point was not a lower verified answer than
                                the certified start, which is the answer */
} bl_solution;

/* A solution for the model copy c (taken over: freed with the solution, or
 * at once when allocation fails), with its arrays allocated; NULL when out
 * of memory. */
bl_solution *bl_solution_new(bl_model *c);
void bl_solution_free(bl_solution *s);

/* Keeps copies of the scaled answer x (nx) and y (ny) in s.  Returns 0, or
 * -1 when out of memory. */
int bl_solution_keep(bl_solution *s, const double *x, int nx, const double *y, int ny);

/* The status of a solve whose LP ended with st (alpha's sign aside). */
bl_status bl_status_of_lp(bl_lp_status st);

/* Sets the status of an answer s->alpha: where alpha < 0 the interval of
 * alphas with an equilibrium lies below 0 (s->stands = 0); BL_UNSTABLE when
 * the structure cannot stand under its dead load alone, else BL_OPTIMAL. */
void bl_solution_answer_status(bl_solution *s);

/* The velocity of block b at point p in the mechanism u: v + omega x
 * (p - g) (2D: p.z is ignored and the velocity's z is 0). */
bl_vec3 bl_solution_velocity(const bl_solution *s, int b, bl_vec3 p);

/* Relative velocity of block b with respect to block a at point p,
 * from the mechanism u (either block may be a support). */
bl_vec2 bl_solution_relative_velocity(const bl_solution *s, int a, int b, bl_vec2 p);

/* The largest speed of a vertex of block b in the mechanism u. */
double bl_solution_block_speed(const bl_solution *s, int b);

/* Whether s has a mechanism to show: an answer (optimal or unstable) with
 * its velocities.  Ipopt's last point that is no answer ("not
 * complementary", a limit) keeps its residuals, not a mechanism. */
int bl_solution_moves(const bl_solution *s);

/* A free block whose fastest vertex moves at less than this share of the
 * fastest block's is still: drawn pale, and outside the moving chain of
 * bl_solution_participation. */
#define BL_STILL_FRACTION 0.01

/* The mechanism's participating weight under the weight-proportional live
 * load along d (doc/theory.md, T4.1).  The moving blocks (BL_STILL_FRACTION)
 * fall into groups joined by their interfaces, each a mechanism of its
 * own, and within a group into rigid bodies joined by the interfaces that
 * move less than BL_STILL_FRACTION of the fastest.
 * For each group, with P_i the weights of its bodies at their centres and
 * of the weights its blocks carry at their points, and d_i the velocity
 * of each along d: participating = (sum P_i d_i)^2 / sum P_i d_i^2, chain =
 * sum P_i, ratio = participating / chain, acceleration = alpha / ratio;
 * the group with the least acceleration is reported, with the number of
 * groups. */
typedef struct bl_participation {
    double chain, participating, ratio, acceleration;
    int blocks, bodies; /* the group's blocks, and its rigid bodies */
    int groups;         /* the groups of moving blocks */
} bl_participation;

/* 0 with *p filled; -1 where it is not defined: no mechanism, a status
 * other than optimal, a live load other than the weights', no motion
 * along d, a velocity that is not finite, or out of memory. */
int bl_solution_participation(const bl_solution *s, bl_participation *p);

/* Classifies every interface from the mechanism (doc/theory.md, "states"):
 * fills state and hinge. */
void bl_solution_classify(bl_solution *s);

/* Per interface k: the resultant force F[k] that block a exerts on block b
 * (global axes; 2D in x, y), its normal part N[k], and C[k], where that
 * normal part acts (the centre of pressure; the thrust line passes there;
 * the joint's middle where N <= 0).  From s->force. */
void bl_solution_resultants(const bl_solution *s, bl_vec3 *F, double *N, bl_vec3 *C);

/* What the free blocks exert on each support i: the force R[i] and its
 * moment M[i] about the origin (global axes; in 2D only M[i].z is not
 * zero), from s->reaction; zero for free blocks. */
void bl_solution_reactions(const bl_solution *s, bl_vec3 *R, bl_vec3 *M);

/* 3D: whether vertex e of interface k's contact polygon stays closed (its
 * relative velocity counts as zero), after bl_solution_classify. */
int bl_solution_closed3(const bl_solution *s, int k, int e);

#endif
