#include "geometry.h"

#include <math.h>

double bl_v2_norm(bl_vec2 a) { return hypot(a.x, a.y); }

bl_vec2 bl_v2_unit(bl_vec2 a)
{
    double s = fmax(fabs(a.x), fabs(a.y));
    if (!(s > 0.0)) return a;
    a = bl_v2(a.x / s, a.y / s); /* its largest component 1: exact, whatever its size */
    if (fabs(a.x) < 1e-15) a.x = 0.0;
    if (fabs(a.y) < 1e-15) a.y = 0.0;
    return bl_v2_scale(a, 1.0 / bl_v2_norm(a));
}

double bl_polygon_area(const bl_vec2 *p, int n)
{
    double s = 0.0;
    for (int i = 0; i < n; i++) {
        bl_vec2 a = p[i], b = p[(i + 1) % n];
        s += bl_v2_cross(bl_v2_sub(a, p[0]), bl_v2_sub(b, p[0]));
    }
    return 0.5 * s;
}

bl_vec2 bl_polygon_centroid(const bl_vec2 *p, int n)
{
    /* Triangles fanned from p[0], so that the sums stay well conditioned
     * for polygons far from the origin. */
    double a2 = 0.0, cx = 0.0, cy = 0.0;
    for (int i = 1; i + 1 < n; i++) {
        bl_vec2 u = bl_v2_sub(p[i], p[0]), v = bl_v2_sub(p[i + 1], p[0]);
        double w = bl_v2_cross(u, v);
        a2 += w;
        cx += w * (u.x + v.x);
        cy += w * (u.y + v.y);
    }
    return bl_v2(p[0].x + cx / (3.0 * a2), p[0].y + cy / (3.0 * a2));
}

void bl_polygon_reverse(bl_vec2 *p, int n)
{
    for (int i = 0, j = n - 1; i < j; i++, j--) {
        bl_vec2 t = p[i];
        p[i] = p[j];
        p[j] = t;
    }
}

double bl_segment_distance(bl_vec2 a, bl_vec2 b, bl_vec2 q)
{
    bl_vec2 d = bl_v2_sub(b, a);
    double l2 = bl_v2_dot(d, d);
    double s = l2 > 0.0 ? bl_v2_dot(bl_v2_sub(q, a), d) / l2 : 0.0;
    if (s < 0.0) s = 0.0;
    if (s > 1.0) s = 1.0;
    return bl_v2_norm(bl_v2_sub(q, bl_v2_add(a, bl_v2_scale(d, s))));
}

/* Signed distance of q from the line through a, b (positive to the left). */
static double side(bl_vec2 a, bl_vec2 b, bl_vec2 q)
{
    bl_vec2 d = bl_v2_sub(b, a);
    double l = bl_v2_norm(d);
    return l > 0.0 ? bl_v2_cross(d, bl_v2_sub(q, a)) / l : 0.0;
}

int bl_segments_cross(bl_vec2 a, bl_vec2 b, bl_vec2 c, bl_vec2 d, double tol)
{
    double s1 = side(a, b, c), s2 = side(a, b, d);
    double s3 = side(c, d, a), s4 = side(c, d, b);
    return ((s1 > tol && s2 < -tol) || (s1 < -tol && s2 > tol)) &&
           ((s3 > tol && s4 < -tol) || (s3 < -tol && s4 > tol));
}

/* 1 if segments [a,b] and [c,d] come within tol of each other. */
static int segments_touch(bl_vec2 a, bl_vec2 b, bl_vec2 c, bl_vec2 d, double tol)
{
    if (bl_segments_cross(a, b, c, d, 0.0)) return 1;
    return bl_segment_distance(a, b, c) <= tol || bl_segment_distance(a, b, d) <= tol ||
           bl_segment_distance(c, d, a) <= tol || bl_segment_distance(c, d, b) <= tol;
}

int bl_polygon_self_intersection(const bl_vec2 *p, int n, double tol, int *ei, int *ej)
{
    for (int i = 0; i < n; i++) {
        bl_vec2 a = p[i], b = p[(i + 1) % n];
        if (bl_v2_norm(bl_v2_sub(b, a)) <= tol) {
            *ei = i;
            *ej = (i + 1) % n;
            return 1;
        }
        for (int j = i + 2; j < n; j++) {
            if (i == 0 && j == n - 1) continue; /* adjacent through the closing edge */
            if (segments_touch(a, b, p[j], p[(j + 1) % n], tol)) {
                *ei = i;
                *ej = j;
                return 1;
            }
        }
    }
    /* Adjacent edges folding back on each other overlap along a segment. */
    for (int i = 0; i < n; i++) {
        bl_vec2 a = p[(i + n - 1) % n], b = p[i], c = p[(i + 1) % n];
        bl_vec2 u = bl_v2_sub(a, b), v = bl_v2_sub(c, b);
        if (fabs(bl_v2_cross(u, v)) <= tol * (bl_v2_norm(u) + bl_v2_norm(v)) &&
            bl_v2_dot(u, v) > 0.0) {
            *ei = (i + n - 1) % n;
            *ej = i;
            return 1;
        }
    }
    return 0;
}

double bl_polygon_depth(const bl_vec2 *p, int n, bl_vec2 q)
{
    int inside = 0;
    double dmin = INFINITY;
    for (int i = 0, j = n - 1; i < n; j = i++) {
        if (((p[i].y > q.y) != (p[j].y > q.y)) &&
            q.x < (p[j].x - p[i].x) * (q.y - p[i].y) / (p[j].y - p[i].y) + p[i].x)
            inside = !inside;
        double d = bl_segment_distance(p[j], p[i], q);
        if (d < dmin) dmin = d;
    }
    return inside ? dmin : -dmin;
}

void bl_polygon_bbox(const bl_vec2 *p, int n, double box[4])
{
    box[0] = box[2] = p[0].x;
    box[1] = box[3] = p[0].y;
    for (int i = 1; i < n; i++) {
        box[0] = fmin(box[0], p[i].x);
        box[1] = fmin(box[1], p[i].y);
        box[2] = fmax(box[2], p[i].x);
        box[3] = fmax(box[3], p[i].y);
    }
}
