/* geometry.h - plane geometry of polygons and segments.
 *
 * Polygons are arrays of n points, in either orientation, implicitly closed.
 * Nothing here allocates. */
#ifndef BL_GEOMETRY_H
#define BL_GEOMETRY_H

typedef struct bl_vec2 {
    double x, y;
} bl_vec2;

static inline bl_vec2 bl_v2(double x, double y) { return (bl_vec2){x, y}; }
static inline bl_vec2 bl_v2_sub(bl_vec2 a, bl_vec2 b) { return bl_v2(a.x - b.x, a.y - b.y); }
static inline bl_vec2 bl_v2_add(bl_vec2 a, bl_vec2 b) { return bl_v2(a.x + b.x, a.y + b.y); }
static inline bl_vec2 bl_v2_scale(bl_vec2 a, double s) { return bl_v2(s * a.x, s * a.y); }
static inline double bl_v2_dot(bl_vec2 a, bl_vec2 b) { return a.x * b.x + a.y * b.y; }
/* z component of the cross product a x b */
static inline double bl_v2_cross(bl_vec2 a, bl_vec2 b) { return a.x * b.y - a.y * b.x; }
double bl_v2_norm(bl_vec2 a);
/* A direction: a over its length, for any finite a (1e-320 or 1e308
 * long), its components below 1e-15 of the largest set to 0 (the
 * cos(pi/2) = 6e-17 of a direction meant along an axis: a load along y
 * with it stopped the 3D sequence's certificates passing); zero stays
 * zero. */
bl_vec2 bl_v2_unit(bl_vec2 a);

/* Signed area: positive for counter-clockwise polygons. */
double bl_polygon_area(const bl_vec2 *p, int n);
/* Centroid of the enclosed region (the polygon must have non-zero area). */
bl_vec2 bl_polygon_centroid(const bl_vec2 *p, int n);
/* Reverses the order of the points in place. */
void bl_polygon_reverse(bl_vec2 *p, int n);
/* Finds two non-adjacent edges that touch or cross (within tol).  Returns 1
 * and the edge indices (edge i runs from p[i] to p[i+1]) if there are, 0 if
 * the polygon is simple.  Also reports repeated consecutive vertices. */
int bl_polygon_self_intersection(const bl_vec2 *p, int n, double tol, int *ei, int *ej);
/* Signed distance of q to the boundary: positive inside, negative outside. */
double bl_polygon_depth(const bl_vec2 *p, int n, bl_vec2 q);
/* Bounding box: box[0..3] = xmin, ymin, xmax, ymax. */
void bl_polygon_bbox(const bl_vec2 *p, int n, double box[4]);

/* Distance from q to the segment [a, b]. */
double bl_segment_distance(bl_vec2 a, bl_vec2 b, bl_vec2 q);
/* 1 if the open segments [a,b] and [c,d] cross at a point interior to both,
 * each endpoint being more than tol away from the other segment's line. */
int bl_segments_cross(bl_vec2 a, bl_vec2 b, bl_vec2 c, bl_vec2 d, double tol);

#endif
