/* assemble.h - the equilibrium system of a 2D model in bounds-only form.
 *
 * Unknowns: the contact forces, written as non-negative combinations of the
 * edges of each contact point's friction cone (so that every yield condition
 * is a bound on one variable), and the load multiplier alpha, last column.
 * Rows: three per free block (force x, force y, moment about the centroid):
 *
 *     A x + alpha fL = -fD          (doc/theory.md, Eq. T4)
 *
 * Everything is scaled: lengths by L0, forces by W0, so that A, fL and fD
 * are of order one.  alpha does not change. */
#ifndef BL_ASSEMBLE_H
#define BL_ASSEMBLE_H

#include <stddef.h>

#include "model.h"

/* What one force column is, in the interface frame (normal, tangent). */
typedef enum bl_column_kind {
    BL_COL_CONE_POS,   /* n = 1, t = +mu,  x >= 0 */
    BL_COL_CONE_NEG,   /* n = 1, t = -mu,  x >= 0 */
    BL_COL_NORMAL,     /* n = 1, t = 0,    x >= 0 (mu = 0 or no sliding) */
    BL_COL_SHEAR,      /* n = 0, t = 1,    free (no sliding) */
    BL_COL_COHESION,   /* n = 0, t = 1,    -C <= x <= C */
    BL_COL_PYRAMID,    /* 3D: an edge of the friction pyramid, x >= 0 */
    BL_COL_TWIST       /* 3D resultant model, fixed form: a couple about the
                        * normal of rho (the joint's torsion lever) per unit
                        * x, |x| <= (mu_t / rho) N + C */
} bl_column_kind;

/* How a 3D contact point's Coulomb cone becomes linear: a pyramid of
 * `facets` edges (3 to 64), on the cone (inscribed: less friction than the
 * cone) or around it (circumscribed: more), an edge or a facet centred on
 * the contact polygon's first edge t2; adaptive: the inscribed pyramid with
 * edges added on the cone along the slip of every previous LP (assoc.c). */
typedef struct bl_cone {
    int facets;
    int circumscribed;
    int adaptive;          /* add edges along each point's slip, LP by LP */
    int nextra;            /* room for added edges per contact point */
    const int *extra_n;    /* per contact point: edges added, or NULL */
    const double *extra;   /* their angles from t2: nextra per point */
} bl_cone;

/* How friction enters the system.  BL_FRICTION_CONE: the Coulomb cone of
 * (T4), for the associative LP and the certificate of the sequence of LPs.
 * BL_FRICTION_FIXED: a normal column n >= 0 and a shear column whose bounds
 * -R <= t <= R are set from given normal forces (bl_system_fixed_bounds):
 * the seed's Eq. 19, a yield surface without dilatancy. */
typedef enum bl_friction_form { BL_FRICTION_CONE, BL_FRICTION_FIXED } bl_friction_form;

typedef struct bl_system {
    int dim;                 /* 2: rows x, y, moment per block; 3: forces x, y, z, moments */
    int nrows, ncols;        /* ncols = nforce + 1 */
    int nforce;              /* force columns; alpha is column nforce */
    int *colptr, *rowind;    /* CSC of [A fL], owned */
    double *val;
    double *lo, *hi;         /* column bounds, owned */
    double *rhs;             /* -fD, owned */
    double *obj;             /* 1 at alpha, owned */
    int *block_row;          /* per block: its first row, -1 for supports */
    int *col_point;          /* per force column: 2 * interface + end */
    signed char *col_kind;   /* per force column: bl_column_kind */
    double *col_nt;          /* per force column: (n, t) of a unit value; 3D (n, t2, t3) */
    double *col_twist;       /* 3D resultant model, per force column: the multiple of
                              * its joint's twist rho omega in its power (+-mu_t / rho
                              * for a pyramid edge, 1 for a twist or cohesive couple);
                              * 0 otherwise */
    double L0, W0;           /* length and force scales */
    int uniform;             /* the free blocks have one density rho0 and (2D)
                              * thickness t0: W0 = rho0 t0 V0, V0 their mean
                              * volume (2D: area); else W0 their mean weight */
    double rho0, t0, V0;
    double *row_scale;       /* per row: the factor a light block's rows were
                              * multiplied by (bl_system_finish), NULL: all 1 */
    bl_friction_form form;
    double *cohesion;        /* per contact point: C_p / W0 (3D resultant model:
                              * the joint's c A / W0 at its lead point, 0 at
                              * the others) */
    double *mu;              /* per contact point: the interface's mu */
    double *twist;           /* 3D resultant model, per lead point: mu_t / rho,
                              * the twist column's bound per unit normal force */
    int npoints;             /* 2 per interface; 3D the vertices of the contact polygons */
    int *point_iface;        /* per contact point: its interface */
    int *lead;               /* per contact point: the point whose columns carry its
                              * friction (itself; in the 3D resultant model the first
                              * vertex of its polygon, for the whole joint) */
} bl_system;

/* Builds the system for m (whose interfaces must be detected).  Returns NULL
 * with err set when the model cannot be assembled.  2D models only. */
bl_system *bl_system_build(const bl_model *m, bl_friction_form form, bl_error *err);

/* The system of a 3D model (src/assemble3.c): six rows per free block, a
 * force at every vertex of every contact polygon; BL_FRICTION_CONE: the
 * cone linearized as given; BL_FRICTION_FIXED: a normal per point and
 * shear columns whose bounds +-mu n come from bl_system_fixed_bounds (the
 * pyramid's section at the fixed n; in the resultant model once per joint,
 * with a twist column). */
bl_system *bl_system_build3(const bl_model *m, const bl_cone *cone, bl_friction_form form,
                            bl_error *err);

/* 3D: the forces (n, t2, t3 per contact point, physical units) from x, and
 * the mechanism (vx, vy, vz, wx, wy, wz per block) from y. */
void bl_system_forces3(const bl_system *s, const double *x, double *force);
void bl_system_mechanism3(const bl_system *s, const bl_model *m, const double *y, double *u);

/* 3D: the tangential relative velocity of every contact point (slip of b
 * on a, components along t2 and t3; in the resultant model the slip at the
 * joint's centroid, where its friction acts) from the row multipliers y, in
 * the scaled units of y. */
void bl_system_slip3(const bl_system *s, const bl_model *m, const double *y, double *slip);

/* For a 3D BL_FRICTION_FIXED system: the tangential relative velocity of
 * every contact point along t2 (dt) and t3 (dt3) from the powers w of its
 * shear columns (bl_system_point_motion): w_k = d_k . slip over the
 * columns' tangential directions d_k, solved in the least-squares sense. */
void bl_system_tangent3(const bl_system *s, const double *w, double *dt, double *dt3);

/* For a BL_FRICTION_FIXED system: the bounds of every column when the
 * contact points carry the normal forces n (per point, scaled by W0):
 * R = mu N + C on the shear columns, R = (mu_t / rho) N + C on a twist
 * column, where N is the normal force of the points the column's point
 * leads (its own, or the joint's in the resultant model), and C the
 * point's cohesion (s->cohesion).  lo and hi have ncols entries. */
void bl_system_fixed_bounds(const bl_system *s, const double *n, double *lo, double *hi);

/* For a BL_FRICTION_FIXED system, from the powers w of its columns and
 * the tangential motion (dt, and dt3 in 3D, or NULL) of every point: how
 * fast each point slides, |dt| and, at the lead point of a 3D resultant
 * joint, its twist too (the twist column's power, rho omega). */
void bl_system_speed(const bl_system *s, const double *w, const double *dt, const double *dt3,
                     double *speed);

/* The motion of every rigid joint (mu = inf in s) as a whole, from the
 * normal motion dn and the speed (bl_system_speed) of every point: at
 * each of its points, how fast the joint slides (its fastest point) in
 * slide and how far it opens (its least opening point) in open; 0 at the
 * points of other joints.  A rigid joint that slides carries nothing,
 * and one whose every point opens no shear (doc/theory.md 6). */
void bl_system_rigid_motion(const bl_system *s, const double *dn, const double *speed,
                            double *slide, double *open);

/* The torsion per unit normal force of a 3D interface in the resultant
 * model: its own mu_t, else mu times its torsion lever (the mean distance
 * of its area from its centroid); infinite where it cannot slide. */
double bl_interface_torsion(const bl_interface *in);

void bl_system_free(bl_system *s);

/* For the builders (2D in assemble.c, 3D in assemble3.c): a system with
 * per_block rows per free block, its block rows and scales W0, L0 (NULL
 * with err set when out of memory or without a free block); room for
 * nforce force columns and alpha, npoints contact points and nnz_max
 * entries (0, or -1 when out of memory); and the alpha column from the
 * live load fL, the columns before it filled up to entry nz (NULL with err
 * set, the system freed, when there is no live load). */
bl_system *bl_system_start(const bl_model *m, int per_block, bl_error *err);
/* Block b's weight in units of W0: with one density and thickness V / V0,
 * so that the LP does not change with them by a bit, where W / W0 rounds
 * differently (the sequence of LPs then reached other solutions: W5
 * 0.20930 at density 1, 0.21956 at 18); else W / W0. */
double bl_system_weight(const bl_system *s, const bl_block *b);
int bl_system_allocate(bl_system *s, const bl_model *m, int nforce, int npoints, size_t nnz_max);
bl_system *bl_system_finish(bl_system *s, int nz, double *fL, bl_error *err);

/* Row `row` of the LP's dual y in the rows' units before the scaling of
 * light blocks (bl_system_finish): a block velocity times W0 (forces) or
 * W0 L0 (moments). */
double bl_system_velocity(const bl_system *s, const double *y, int row);

/* What the free blocks exert on each support through their joints, from
 * x: per block 6 numbers, the force (x, y, z) and its moment about the
 * origin (x, y, z), in physical units; 2D: z force and x, y moment 0.
 * Read from the columns' own rows, so that every column counts as the
 * equilibrium counts it (3D couples, shear at a joint's centroid). */
void bl_system_reactions(const bl_system *s, const bl_model *m, const double *x, double *R);

/* Physical contact forces (n0, t0, n1, t1 per interface) from x. */
void bl_system_forces(const bl_system *s, const bl_model *m, const double *x, double *force);

/* Physical mechanism (vx, vy, omega per block) from the row multipliers y. */
void bl_system_mechanism(const bl_system *s, const bl_model *m, const double *y, double *u);

/* The other way: the row multipliers y of a mechanism u given per block
 * (3 numbers in 2D, 6 in 3D, as bl_system_mechanism and
 * bl_system_mechanism3 give them). */
void bl_system_rows_of_mechanism(const bl_system *s, const bl_model *m, const double *u, double *y);

/* obj[j] -= eps n_j over the force columns, n_j the normal force of a unit
 * of column j (in units of W0): with eps > 0 an LP that maximizes obj takes,
 * among its optimal force fields, one with less total normal force.  Blocks
 * confined between supports can carry any compression, and without such a
 * cost their LPs' optimal force fields are unbounded (doc/seqlp.md 13). */
void bl_system_cost_normal(const bl_system *s, double eps, double *obj);

/* The cost per unit normal force with which an LP the interior point could
 * not finish is solved again: with 1e-10 a 1,040-block wall between two
 * abutments certifies (0.56082, verified); 1e-8 left mechanisms whose
 * interpenetration of that order failed the verification. */
#define BL_LEAST_N 1e-10

/* r = A x + alpha fL + fD, over the force columns x and alpha. */
void bl_system_residual(const bl_system *s, const double *x, double alpha, double *r);

/* w = A^T y over the force columns (w[j]: power of a unit value of column j). */
void bl_system_power(const bl_system *s, const double *y, double *w);

/* For a BL_FRICTION_FIXED system: the relative velocity of every contact
 * point, normal dn and tangential dt (npoints each, scaled), from the row
 * multipliers y; w is workspace of nforce entries. */
void bl_system_point_motion(const bl_system *s, const double *y, double *w, double *dn,
                            double *dt);

#endif
