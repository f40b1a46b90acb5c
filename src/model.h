/* model.h - an assembly of rigid blocks: blocks, interfaces, loads, material.
 *
 * A model is 2D (blocks are polygons with an out-of-plane thickness) or 3D
 * (blocks are polyhedra).  In 3D, blocks, their volumes, centroids and
 * weights are built; interfaces, loads and solves are 2D only so far.
 *
 * Blocks are numbered from 0 in the order they are added (the Lua side shows
 * them from 1).  A support block is fixed and carries no unknowns.  The model
 * owns every array it points to; bl_model_free releases them all. */
#ifndef BL_MODEL_H
#define BL_MODEL_H

#include "error.h"
#include "geometry.h"
#include "polyhedron.h"

typedef struct bl_block {
    int nv;
    bl_vec2 *v;          /* owned; counter-clockwise (2D) */
    int support;
    double density;      /* weight per unit volume */
    double thickness;    /* out of plane (2D) */
    double area;
    bl_vec2 centroid;
    double weight;       /* density * area * thickness, or density * volume */
    double box[4];       /* bounding box (2D) */
    double resolution;   /* the last digit its coordinates were written to (import); 0 exact */
    /* 3D */
    bl_polyhedron solid; /* owned, faces outward */
    double volume;
    bl_vec3 centroid3;
    double box3[6];
} bl_block;

/* How a 3D interface carries force (doc/theory.md 3.3). */
typedef enum bl_interface_model {
    BL_VERTEX,           /* a force in the friction pyramid at every vertex */
    BL_RESULTANT         /* normal forces at the vertices, the shear resultant in
                            the pyramid at the centroid, torsion |M1| <= mu_t N */
} bl_interface_model;

/* An interface joins block a (minus side) and block b (plus side).  Its unit
 * normal points from a into b; the tangent is the normal turned by +90
 * degrees.  The contact region is the segment p[0]-p[1]; the vertex model
 * puts one contact force at each end. */
typedef struct bl_interface {
    int a, b;
    bl_vec2 p[2];
    bl_vec2 normal;
    double mu;           /* friction coefficient; INFINITY: no sliding */
    double cohesion;     /* per unit area of the joint */
    int manual;          /* declared by interface{ points = ... } */
    /* 3D: a convex contact polygon of np vertices (owned), its unit normal
     * from a into b, and a frame t2 (along its first edge), t3 = n x t2 */
    int np;
    bl_vec3 *poly;
    bl_vec3 n3, t2, t3;
    double area3;
    bl_interface_model imodel; /* 3D: how the joint carries force */
    double mu_t;         /* 3D resultant model: torsion per unit normal force
                            (a length); 0: mu times the joint's torsion lever */
} bl_interface;

/* A user setting for the interfaces between two blocks, kept across
 * re-detection: a friction, cohesion or (3D) interface model override, or
 * (with npoints > 0) a
 * joint declared by hand that replaces the detected ones: in 2D its two
 * ends p, in 3D a convex polygon p3 of npoints >= 3. */
#define BL_JOINT_POINTS 16
typedef struct bl_joint_spec {
    int a, b;
    int has_mu, has_cohesion, has_imodel, has_mu_t;
    double mu, cohesion, mu_t;
    bl_interface_model imodel;
    int npoints;
    bl_vec2 p[2];
    bl_vec3 p3[BL_JOINT_POINTS];
} bl_joint_spec;

/* A point load on a free block: a force at a point with a couple, dead or
 * live; or (weight > 0, dead, no force nor couple) a weight the block
 * carries at 'at' (a floor, a fill): the force weight along gravity, and
 * a mass, so that the weight-proportional live load also acts on it, at
 * 'at' (bl_point_load_forces). */
typedef struct bl_point_load {
    int block;
    bl_vec2 at, force;
    double moment;       /* 2D: a couple, counter-clockwise */
    int live;
    bl_vec3 at3, force3, moment3; /* 3D: point, force, and a couple */
    double weight;
} bl_point_load;

typedef struct bl_model {
    char name[64];
    int dim;             /* 2 or 3 */
    bl_interface_model interface_model; /* 3D: the interfaces' default */
    double mu_t;         /* 3D: the resultant interfaces' default mu_t */
    /* material defaults, applied to blocks and interfaces as they are made */
    double mu, cohesion, density, thickness;
    bl_vec2 gravity;     /* unit vector of the dead load (before tilt) */
    double tilt;         /* radians, rotates gravity counter-clockwise */

    int nblocks, cap_blocks;
    bl_block *blocks;

    int ninterfaces, cap_interfaces;
    bl_interface *interfaces;
    int contacts_valid;  /* interfaces are up to date with the blocks */
    double contact_tol, contact_gap; /* absolute; 0 = defaults */

    int njoints, cap_joints;
    bl_joint_spec *joints;

    int self_weight;     /* dead load: self weight along gravity */
    int live_weight;     /* live load: weight along live_dir */
    bl_vec2 live_dir;    /* unit */
    bl_vec3 gravity3;    /* 3D: unit vector of the dead load (before tilt), (0, 0, -1) */
    bl_vec2 tilt_axis;   /* 3D: the horizontal axis gravity turns about by tilt,
                            (0, -1) by default (as in 2D, seen in the x-z plane) */
    bl_vec3 live_dir3;   /* 3D: unit vector of the live load, (1, 0, 0) by default */
    int nloads, cap_loads;
    bl_point_load *loads;
} bl_model;

/* Defaults: mu 0.65, no cohesion, density 1, thickness 1, gravity (0,-1),
 * self weight as dead load, horizontal live load along +x. */
bl_model *bl_model_new(void);
void bl_model_free(bl_model *m);
/* Deep copy (NULL when out of memory). */
bl_model *bl_model_copy(const bl_model *m);

/* Adds a block.  Validates the polygon (at least 3 points, simple, non-zero
 * area), puts it counter-clockwise, computes area, centroid, weight.
 * density or thickness <= 0 takes the model's default. */
int bl_model_add_block(bl_model *m, const bl_vec2 *v, int nv, int support,
                       double density, double thickness, bl_error *err);

/* Adds a 3D block, taking over *solid (emptied, also on failure): checks
 * it (bl_polyhedron_check, tolerance 1e-9 of its size for planarity,
 * orientation fixed), computes volume, centroid and weight.  density <= 0
 * takes the model's default. */
int bl_model_add_solid(bl_model *m, bl_polyhedron *solid, int support, double density,
                       bl_error *err);

/* Appends an interface (used by contact detection), taking over its 3D
 * polygon. */
int bl_model_add_interface(bl_model *m, const bl_interface *k, bl_error *err);

/* Records a joint spec (see bl_joint_spec) and invalidates interfaces. */
int bl_model_add_joint(bl_model *m, const bl_joint_spec *s, bl_error *err);

/* The largest finite friction coefficient: above it the LPs lose their
 * round-off (W4 at mu = 1e5: "numerical trouble" on the interior point; at
 * 1e20 "infeasible"; at 1e7 a simplex that cycled), and no joint of
 * masonry needs it: mu = inf (math.huge) is a joint that never slides. */
#define BL_MU_MAX 1e3

/* A point load above BL_LOAD_RATIO times its block's weight (a couple above
 * that times the weight and the block's size) is refused: the LP, scaled
 * by the blocks' weights, no longer holds it (a dead load of 1e35 W read
 * "infeasible", one of 1e100 W stopped CLP on an assertion), and no
 * masonry carries such a load. */
#define BL_LOAD_RATIO 1e12

/* Whether a point load can be added (BL_LOAD_RATIO): 0, or -1 with a
 * message.  Adding one (after that check) fails only out of memory. */
int bl_model_check_point_load(const bl_model *m, const bl_point_load *l, bl_error *err);
int bl_model_add_point_load(bl_model *m, const bl_point_load *l, bl_error *err);

/* The forces of point load l at its point: *dead (times 1) and *live
 * (times alpha), each zero where l has none.  A carried weight gives W
 * along the tilted gravity, and W along the live direction while the
 * weight-proportional live load is on. */
void bl_point_load_forces(const bl_model *m, const bl_point_load *l, bl_vec2 *dead, bl_vec2 *live);
void bl_point_load_forces3(const bl_model *m, const bl_point_load *l, bl_vec3 *dead, bl_vec3 *live);

/* Removes every interface (freeing their 3D polygons). */
void bl_model_clear_interfaces(bl_model *m);

/* Removes the blocks from number nblocks on (0-based), with the joint
 * specs and point loads that name them, and the interfaces: a command
 * that made several blocks and then failed leaves the model as it was. */
void bl_model_truncate(bl_model *m, int nblocks);

/* Size of the model: the diagonal of the bounding box of all blocks. */
double bl_model_size(const bl_model *m);
/* Current direction of the dead load (gravity turned by tilt). */
bl_vec2 bl_model_gravity(const bl_model *m);
bl_vec3 bl_model_gravity3(const bl_model *m);

/* Whether some detected interface has finite, non-zero friction: where
 * none has, solve{}'s default flow is the associative one (doc/theory.md
 * 6, "Rigid joints"). */
int bl_model_finite_friction(const bl_model *m);
int bl_model_free_blocks(const bl_model *m);
/* Whether a 3D model's interfaces take the resultant model: all by
 * default (1, with *a = *b = -1), or those between blocks *a and *b by
 * interface{} (1); 0 if none.  Needs no interface detection. */
int bl_model_uses_resultant(const bl_model *m, int *a, int *b);

#endif
