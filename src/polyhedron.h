/* polyhedron.h - solid geometry of 3D blocks: points, polyhedra given by
 * their faces, their checks, volume and centroid, and the convex hull of a
 * point set (qhull).
 *
 * A polyhedron owns its arrays: nv vertices, and nf faces, face k listing
 * the vertex indices fi[fs[k]] ... fi[fs[k+1] - 1] in order around it,
 * counter-clockwise seen from outside once checked. */
#ifndef BL_POLYHEDRON_H
#define BL_POLYHEDRON_H

#include "error.h"

typedef struct bl_vec3 {
    double x, y, z;
} bl_vec3;

static inline bl_vec3 bl_v3(double x, double y, double z) { return (bl_vec3){x, y, z}; }
static inline bl_vec3 bl_v3_sub(bl_vec3 a, bl_vec3 b) { return bl_v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline bl_vec3 bl_v3_add(bl_vec3 a, bl_vec3 b) { return bl_v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline bl_vec3 bl_v3_scale(bl_vec3 a, double s) { return bl_v3(s * a.x, s * a.y, s * a.z); }
static inline double bl_v3_dot(bl_vec3 a, bl_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline bl_vec3 bl_v3_cross(bl_vec3 a, bl_vec3 b)
{
    return bl_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
double bl_v3_norm(bl_vec3 a);
/* A direction, as bl_v2_unit in 3D. */
bl_vec3 bl_v3_unit(bl_vec3 a);
/* The direction of a joint's frame from its boundary edges e[0..n-1]: the
 * longest's; where the edges within 1e-9 of the longest lie along two
 * directions at an acute angle (an isosceles trapezoid's legs), its
 * bisector, which no round-off in their lengths turns; where they are
 * square to each other (a square's sides: a pyramid of 4k facets is the
 * same along either), or along three or more directions (a regular
 * hexagon: the order of e decides, doc/theory.md 7), the first's.  A unit
 * vector. */
bl_vec3 bl_longest_direction(const bl_vec3 *e, int n);

typedef struct bl_polyhedron {
    int nv, nf;
    bl_vec3 *v;
    int *fs;  /* nf + 1 */
    int *fi;  /* fs[nf] */
} bl_polyhedron;

/* Copies the vertices and faces given (faces as a flat list with starts,
 * as in the struct).  Returns 0, or -1 when out of memory. */
int bl_polyhedron_make(bl_polyhedron *p, const bl_vec3 *v, int nv, const int *fs,
                       const int *fi, int nf);
int bl_polyhedron_copy(bl_polyhedron *dst, const bl_polyhedron *src);
void bl_polyhedron_free(bl_polyhedron *p);

/* Checks a polyhedron and puts its faces outward.  Every face needs 3 or
 * more distinct vertices, all within tol of its plane; every edge must
 * belong to exactly two faces (a closed surface); faces whose order
 * disagrees with their neighbours' are turned round, and all of them when
 * the surface encloses a negative volume; the volume must exceed tol
 * times the surface area (no thinner than tol).
 * On failure returns -1 with a message naming block `id` (1-based) and
 * the face (1-based) or edge at fault. */
int bl_polyhedron_check(bl_polyhedron *p, double tol, int id, bl_error *err);

/* Volume and centroid of a checked polyhedron. */
double bl_polyhedron_volume(const bl_polyhedron *p, bl_vec3 *centroid);

/* Unit outward normal and area of face k of a checked polyhedron. */
bl_vec3 bl_polyhedron_face_normal(const bl_polyhedron *p, int k, double *area);

/* Whether q lies on face k (within tol of its plane, and inside it or
 * within tol of its boundary). */
int bl_polyhedron_on_face(const bl_polyhedron *p, int k, bl_vec3 q, double tol);

/* Signed distance of q to the surface of a checked polyhedron: positive
 * inside, negative outside (as bl_polygon_depth in 2D). */
double bl_polyhedron_depth(const bl_polyhedron *p, bl_vec3 q);

/* Whether the segment ab passes through a face of p into it: a and b
 * farther than tol from the face's plane on either side of it, the point
 * where ab crosses the plane inside the face, farther than tol from its
 * edges, and the point of ab 2 tol past the plane deeper than tol in p. */
int bl_polyhedron_pierced(const bl_polyhedron *p, bl_vec3 a, bl_vec3 b, double tol);

/* Checks a polygon of n points in space (in order, either way round):
 * returns 0 with its unit normal (right hand along the order) and area;
 * -1 when it has no area, -2 when it is not convex, -(k + 3) when its
 * point k (1-based) alone lies off the plane of the others by more than
 * tol, or -3 when the points lie in no plane and no one point is to blame
 * (always so for 4 points: any 3 lie in a plane). */
int bl_polygon3_check(const bl_vec3 *p, int n, double tol, bl_vec3 *normal, double *area);

/* Bounding box: box[0..5] = xmin, ymin, zmin, xmax, ymax, zmax. */
void bl_polyhedron_bbox(const bl_polyhedron *p, double box[6]);

/* The convex hull of n points as a polyhedron (coplanar facets merged into
 * polygonal faces).  Returns -1 with err naming block `id` when the points
 * span no volume. */
int bl_convex_hull(const bl_vec3 *pts, int n, int id, bl_polyhedron *out, bl_error *err);

#endif
