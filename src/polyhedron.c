#include "polyhedron.h"
#include "geometry.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <libqhull_r/qhull_ra.h>

double bl_v3_norm(bl_vec3 a) { return sqrt(bl_v3_dot(a, a)); }

bl_vec3 bl_v3_unit(bl_vec3 a)
{
    double s = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (!(s > 0.0)) return a;
    a = bl_v3(a.x / s, a.y / s, a.z / s); /* its largest component 1: exact, whatever its size */
    if (fabs(a.x) < 1e-15) a.x = 0.0;
    if (fabs(a.y) < 1e-15) a.y = 0.0;
    if (fabs(a.z) < 1e-15) a.z = 0.0;
    return bl_v3_scale(a, 1.0 / bl_v3_norm(a));
}

bl_vec3 bl_longest_direction(const bl_vec3 *e, int n)
{
    double best = 0.0;
    for (int i = 0; i < n; i++) best = fmax(best, bl_v3_norm(e[i]));
    bl_vec3 along[2];
    int k = 0;
    for (int i = 0; i < n; i++) {
        if (bl_v3_norm(e[i]) < (1.0 - 1e-9) * best) continue;
        bl_vec3 u = bl_v3_scale(e[i], 1.0 / bl_v3_norm(e[i]));
        int same = 0;
        for (int c = 0; c < k; c++) same |= fabs(bl_v3_dot(u, along[c])) > 1.0 - 1e-9;
        if (same) continue;
        if (k == 2) return along[0];
        along[k++] = u;
    }
    double c = k == 2 ? bl_v3_dot(along[0], along[1]) : 0.0;
    if (fabs(c) < 1e-6) return along[0];
    bl_vec3 s = bl_v3_add(along[0], bl_v3_scale(along[1], c > 0.0 ? 1.0 : -1.0));
    return bl_v3_scale(s, 1.0 / bl_v3_norm(s));
}

int bl_polyhedron_make(bl_polyhedron *p, const bl_vec3 *v, int nv, const int *fs,
                       const int *fi, int nf)
{
    memset(p, 0, sizeof *p);
    p->v = malloc(((size_t)nv + 1) * sizeof *p->v);
    p->fs = malloc(((size_t)nf + 1) * sizeof *p->fs);
    p->fi = malloc(((size_t)fs[nf] + 1) * sizeof *p->fi);
    if (!p->v || !p->fs || !p->fi) {
        bl_polyhedron_free(p);
        return -1;
    }
    memcpy(p->v, v, (size_t)nv * sizeof *v);
    memcpy(p->fs, fs, ((size_t)nf + 1) * sizeof *fs);
    memcpy(p->fi, fi, (size_t)fs[nf] * sizeof *fi);
    p->nv = nv;
    p->nf = nf;
    return 0;
}

int bl_polyhedron_copy(bl_polyhedron *dst, const bl_polyhedron *src)
{
    if (!src->v) {
        memset(dst, 0, sizeof *dst);
        return 0;
    }
    return bl_polyhedron_make(dst, src->v, src->nv, src->fs, src->fi, src->nf);
}

void bl_polyhedron_free(bl_polyhedron *p)
{
    free(p->v);
    free(p->fs);
    free(p->fi);
    memset(p, 0, sizeof *p);
}

/* Newell's normal of face k: twice the area times the unit normal, for the
 * face's vertex order. */
static bl_vec3 newell(const bl_polyhedron *p, int k)
{
    bl_vec3 n = {0, 0, 0};
    int a = p->fs[k], m = p->fs[k + 1] - a;
    for (int i = 0; i < m; i++) {
        bl_vec3 u = p->v[p->fi[a + i]], w = p->v[p->fi[a + (i + 1) % m]];
        n.x += (u.y - w.y) * (u.z + w.z);
        n.y += (u.z - w.z) * (u.x + w.x);
        n.z += (u.x - w.x) * (u.y + w.y);
    }
    return n;
}

bl_vec3 bl_polyhedron_face_normal(const bl_polyhedron *p, int k, double *area)
{
    bl_vec3 n = newell(p, k);
    double len = bl_v3_norm(n);
    if (area) *area = 0.5 * len;
    return len > 0.0 ? bl_v3_scale(n, 1.0 / len) : n;
}

/* Distance from q to the segment ab. */
static double segment_distance(bl_vec3 q, bl_vec3 a, bl_vec3 b)
{
    bl_vec3 ab = bl_v3_sub(b, a), aq = bl_v3_sub(q, a);
    double ll = bl_v3_dot(ab, ab), t = ll > 0.0 ? bl_v3_dot(aq, ab) / ll : 0.0;
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    return bl_v3_norm(bl_v3_sub(aq, bl_v3_scale(ab, t)));
}

/* Whether q, taken in the plane of face k (normal n), lies inside the
 * face: crossings of a ray in the plane of the two coordinates along which
 * the face is widest. */
static int inside_face(const bl_polyhedron *p, int k, bl_vec3 n, bl_vec3 q)
{
    int a0 = p->fs[k], len = p->fs[k + 1] - a0;
    double an[3] = {fabs(n.x), fabs(n.y), fabs(n.z)};
    int drop = an[0] >= an[1] && an[0] >= an[2] ? 0 : an[1] >= an[2] ? 1 : 2;
    int u = (drop + 1) % 3, v = (drop + 2) % 3, inside = 0;
    double Q[3] = {q.x, q.y, q.z};
    for (int i = 0; i < len; i++) {
        bl_vec3 a = p->v[p->fi[a0 + i]], b = p->v[p->fi[a0 + (i + 1) % len]];
        double A[3] = {a.x, a.y, a.z}, B[3] = {b.x, b.y, b.z};
        if ((A[v] > Q[v]) != (B[v] > Q[v]) &&
            Q[u] < A[u] + (Q[v] - A[v]) * (B[u] - A[u]) / (B[v] - A[v]))
            inside = !inside;
    }
    return inside;
}

/* Distance from q to the edges of face k. */
static double edge_distance(const bl_polyhedron *p, int k, bl_vec3 q)
{
    int a0 = p->fs[k], len = p->fs[k + 1] - a0;
    double d = INFINITY;
    for (int i = 0; i < len; i++)
        d = fmin(d, segment_distance(q, p->v[p->fi[a0 + i]], p->v[p->fi[a0 + (i + 1) % len]]));
    return d;
}

int bl_polyhedron_on_face(const bl_polyhedron *p, int k, bl_vec3 q, double tol)
{
    bl_vec3 n = bl_polyhedron_face_normal(p, k, NULL);
    if (fabs(bl_v3_dot(n, bl_v3_sub(q, p->v[p->fi[p->fs[k]]]))) > tol) return 0;
    return edge_distance(p, k, q) <= tol || inside_face(p, k, n, q);
}

int bl_polyhedron_pierced(const bl_polyhedron *p, bl_vec3 a, bl_vec3 b, double tol)
{
    for (int k = 0; k < p->nf; k++) {
        bl_vec3 n = bl_polyhedron_face_normal(p, k, NULL), o = p->v[p->fi[p->fs[k]]];
        double ha = bl_v3_dot(n, bl_v3_sub(a, o)), hb = bl_v3_dot(n, bl_v3_sub(b, o));
        if (!((ha > tol && hb < -tol) || (ha < -tol && hb > tol))) continue;
        bl_vec3 x = bl_v3_add(a, bl_v3_scale(bl_v3_sub(b, a), ha / (ha - hb)));
        if (!inside_face(p, k, n, x) || !(edge_distance(p, k, x) > tol)) continue;
        /* and on into p: where ab is 2 tol inside the plane, deeper than tol */
        double s = fmin(1.0, fmax(0.0, (ha + 2.0 * tol) / (ha - hb)));
        if (bl_polyhedron_depth(p, bl_v3_add(a, bl_v3_scale(bl_v3_sub(b, a), s))) > tol) return 1;
    }
    return 0;
}

/* Solid angle of the triangle abc seen from the origin, signed by the
 * triangle's orientation (Van Oosterom and Strackee). */
static double solid_angle(bl_vec3 a, bl_vec3 b, bl_vec3 c)
{
    double la = bl_v3_norm(a), lb = bl_v3_norm(b), lc = bl_v3_norm(c);
    return 2.0 * atan2(bl_v3_dot(a, bl_v3_cross(b, c)),
                       la * lb * lc + bl_v3_dot(a, b) * lc + bl_v3_dot(a, c) * lb + bl_v3_dot(b, c) * la);
}

double bl_polyhedron_depth(const bl_polyhedron *p, bl_vec3 q)
{
    double d = INFINITY, omega = 0.0;
    for (int k = 0; k < p->nf; k++) {
        bl_vec3 n = bl_polyhedron_face_normal(p, k, NULL);
        int a0 = p->fs[k], len = p->fs[k + 1] - a0;
        bl_vec3 v0 = bl_v3_sub(p->v[p->fi[a0]], q);
        double h = bl_v3_dot(n, v0);
        bl_vec3 foot = bl_v3_add(q, bl_v3_scale(n, h));
        d = fmin(d, inside_face(p, k, n, foot) ? fabs(h) : edge_distance(p, k, q));
        /* q in the face's plane: the face subtends nothing (or q is on it,
         * and d is 0); its fan's triangles, seen edge on, would give +-2 pi
         * each by the sign of a round-off */
        if (fabs(h) <= 1e-10 * bl_v3_norm(v0)) continue;
        for (int i = 1; i + 1 < len; i++)
            omega += solid_angle(v0, bl_v3_sub(p->v[p->fi[a0 + i]], q),
                                 bl_v3_sub(p->v[p->fi[a0 + i + 1]], q));
    }
    /* the faces turn outward: 4 pi inside, 0 outside */
    return fabs(omega) > 2.0 * M_PI ? d : -d;
}

/* The unit normal of the plane of the first three corners (but corner
 * skip) that make a triangle; 0 when they all lie on a line. */
static int corner_plane(const bl_vec3 *p, int n, int skip, double tol, bl_vec3 *nu)
{
    int a = skip == 0 ? 1 : 0, b = skip == 0 || skip == 1 ? 2 : 1;
    *nu = (bl_vec3){0, 0, 0};
    for (int k = b + 1; k < n && !(bl_v3_norm(*nu) > tol * tol); k++)
        if (k != skip) *nu = bl_v3_cross(bl_v3_sub(p[b], p[a]), bl_v3_sub(p[k], p[a]));
    double len = bl_v3_norm(*nu);
    if (!(len > tol * tol)) return 0;
    *nu = bl_v3_scale(*nu, 1.0 / len);
    return 1;
}

/* The first corner (but skip) farther than tol from the plane nu through
 * corner o, or -1. */
static int off_plane(const bl_vec3 *p, int n, int skip, bl_vec3 nu, int o, double tol)
{
    for (int i = 0; i < n; i++)
        if (i != skip && fabs(bl_v3_dot(nu, bl_v3_sub(p[i], p[o]))) > tol) return i;
    return -1;
}

int bl_polygon3_check(const bl_vec3 *p, int n, double tol, bl_vec3 *normal, double *area)
{
    bl_vec3 nu;
    if (!corner_plane(p, n, -1, tol, &nu)) return -1;
    if (off_plane(p, n, -1, nu, 0, tol) >= 0) {
        /* the one corner without which the others lie in one plane, if
         * there is just one (any three corners do) */
        int found = -1, count = 0;
        for (int k = 0; n > 4 && k < n; k++) {
            bl_vec3 mu;
            if (corner_plane(p, n, k, tol, &mu) && off_plane(p, n, k, mu, k == 0, tol) < 0)
                found = k, count++;
        }
        return count == 1 ? -(found + 4) : -3;
    }
    /* convex: every corner turns the same way (or goes straight on) */
    int pos = 0, neg = 0;
    for (int i = 0; i < n; i++) {
        bl_vec3 e1 = bl_v3_sub(p[(i + 1) % n], p[i]), e2 = bl_v3_sub(p[(i + 2) % n], p[(i + 1) % n]);
        double t = bl_v3_dot(bl_v3_cross(e1, e2), nu), eps = tol * (bl_v3_norm(e1) + bl_v3_norm(e2));
        pos += t > eps;
        neg += t < -eps;
    }
    if (pos && neg) return -2;
    bl_vec3 s = {0, 0, 0};
    for (int i = 1; i + 1 < n; i++)
        s = bl_v3_add(s, bl_v3_cross(bl_v3_sub(p[i], p[0]), bl_v3_sub(p[i + 1], p[0])));
    double len = bl_v3_norm(s);
    if (!(len > tol * tol)) return -1;
    *normal = bl_v3_scale(s, 1.0 / len);
    *area = 0.5 * len;
    return 0;
}

static void reverse_face(bl_polyhedron *p, int k)
{
    for (int i = p->fs[k], j = p->fs[k + 1] - 1; i < j; i++, j--) {
        int t = p->fi[i];
        p->fi[i] = p->fi[j];
        p->fi[j] = t;
    }
}

/* An edge of a face, for matching faces along their edges. */
typedef struct edge {
    int lo, hi;   /* vertex indices, lo < hi */
    int face;
    int forward;  /* the face runs lo -> hi */
} edge;

static int edge_cmp(const void *x, const void *y)
{
    const edge *a = x, *b = y;
    if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi) return a->hi < b->hi ? -1 : 1;
    return a->face - b->face;
}

double bl_polyhedron_volume(const bl_polyhedron *p, bl_vec3 *centroid)
{
    bl_vec3 r = p->v[0], c = {0, 0, 0};
    double vol = 0.0;
    for (int k = 0; k < p->nf; k++) {
        int a = p->fs[k], m = p->fs[k + 1] - a;
        bl_vec3 u = bl_v3_sub(p->v[p->fi[a]], r);
        for (int i = 1; i + 1 < m; i++) {
            bl_vec3 w = bl_v3_sub(p->v[p->fi[a + i]], r), z = bl_v3_sub(p->v[p->fi[a + i + 1]], r);
            double t = bl_v3_dot(u, bl_v3_cross(w, z)) / 6.0;
            vol += t;
            c = bl_v3_add(c, bl_v3_scale(bl_v3_add(u, bl_v3_add(w, z)), t / 4.0));
        }
    }
    if (centroid) *centroid = vol != 0.0 ? bl_v3_add(r, bl_v3_scale(c, 1.0 / vol)) : r;
    return vol;
}

void bl_polyhedron_bbox(const bl_polyhedron *p, double box[6])
{
    box[0] = box[1] = box[2] = INFINITY;
    box[3] = box[4] = box[5] = -INFINITY;
    for (int i = 0; i < p->nv; i++) {
        box[0] = fmin(box[0], p->v[i].x);
        box[1] = fmin(box[1], p->v[i].y);
        box[2] = fmin(box[2], p->v[i].z);
        box[3] = fmax(box[3], p->v[i].x);
        box[4] = fmax(box[4], p->v[i].y);
        box[5] = fmax(box[5], p->v[i].z);
    }
}

int bl_polyhedron_check(bl_polyhedron *p, double tol, int id, bl_error *err)
{
    if (p->nf < 4) return bl_error_set(err, "block %d: a polyhedron needs at least 4 faces, got %d", id, p->nf);
    for (int i = 0; i < p->nv; i++)
        if (!isfinite(p->v[i].x) || !isfinite(p->v[i].y) || !isfinite(p->v[i].z))
            return bl_error_set(err, "block %d: vertex %d is not a finite point", id, i + 1);
    /* faces: enough distinct vertices in range, flat */
    for (int k = 0; k < p->nf; k++) {
        int a = p->fs[k], m = p->fs[k + 1] - a;
        if (m < 3)
            return bl_error_set(err, "block %d: face %d has %d vertices, at least 3 needed", id,
                                k + 1, m);
        for (int i = 0; i < m; i++) {
            int q = p->fi[a + i];
            if (q < 0 || q >= p->nv)
                return bl_error_set(err, "block %d: face %d names vertex %d, which does not exist",
                                    id, k + 1, q + 1);
            for (int j = i + 1; j < m; j++)
                if (p->fi[a + j] == q)
                    return bl_error_set(err, "block %d: face %d visits vertex %d twice", id,
                                        k + 1, q + 1);
        }
        double area;
        bl_vec3 n = bl_polyhedron_face_normal(p, k, &area);
        if (isnan(area) || isinf(area))
            return bl_error_set(err, "block %d: face %d is too large to compute with (its area "
                                     "overflows); give the model in other units", id, k + 1);
        if (!(area > tol * tol))
            return bl_error_set(err, "block %d: face %d has zero area", id, k + 1);
        bl_vec3 o = {0, 0, 0};
        for (int i = 0; i < m; i++) o = bl_v3_add(o, p->v[p->fi[a + i]]);
        o = bl_v3_scale(o, 1.0 / m);
        for (int i = 0; i < m; i++) {
            double d = bl_v3_dot(bl_v3_sub(p->v[p->fi[a + i]], o), n);
            if (fabs(d) > tol)
                return bl_error_set(err,
                                    "block %d: face %d is not planar (vertex %d is %.3g off its "
                                    "mean plane; tolerance %.3g)",
                                    id, k + 1, p->fi[a + i] + 1, fabs(d), tol);
        }
        /* simple: in its plane no two edges cross (a crossed face has no
         * inside; its signed area gave a wrong volume and contact) */
        bl_vec3 u = fabs(n.x) < 0.9 ? bl_v3(1, 0, 0) : bl_v3(0, 1, 0);
        u = bl_v3_cross(n, u);
        u = bl_v3_scale(u, 1.0 / bl_v3_norm(u));
        bl_vec3 w = bl_v3_cross(n, u);
        bl_vec2 *flat = malloc((size_t)m * sizeof *flat);
        if (!flat) return bl_error_set(err, "block %d: out of memory", id);
        for (int i = 0; i < m; i++) {
            bl_vec3 d = bl_v3_sub(p->v[p->fi[a + i]], o);
            flat[i] = bl_v2(bl_v3_dot(d, u), bl_v3_dot(d, w));
        }
        int ei, ej, crossed = bl_polygon_self_intersection(flat, m, tol, &ei, &ej);
        free(flat);
        if (crossed)
            return bl_error_set(err, "block %d: face %d crosses itself (its edges %d and %d)", id,
                                k + 1, ei + 1, ej + 1);
    }
    /* every vertex on some face: an unused one is a slip of the pen, and it
     * stretched the block's bounding box (and with it the model's size and
     * tolerances) */
    char *used = calloc((size_t)p->nv + 1, 1);
    if (!used) return bl_error_set(err, "block %d: out of memory", id);
    for (int t = 0; t < p->fs[p->nf]; t++) used[p->fi[t]] = 1;
    for (int i = 0; i < p->nv; i++)
        if (!used[i]) {
            free(used);
            return bl_error_set(err, "block %d: vertex %d is on no face", id, i + 1);
        }
    free(used);

    /* edges: each shared by exactly two faces */
    int ne = p->fs[p->nf];
    edge *e = malloc((size_t)ne * sizeof *e);
    int *flip = malloc((size_t)p->nf * sizeof *flip), *queue = malloc((size_t)p->nf * sizeof *queue);
    int *nb = malloc((size_t)ne * sizeof *nb); /* per edge entry: the other face's entry */
    if (!e || !flip || !queue || !nb) {
        free(e), free(flip), free(queue), free(nb);
        return bl_error_set(err, "block %d: out of memory", id);
    }
    int rc = 0;
    for (int k = 0, t = 0; k < p->nf; k++) {
        int a = p->fs[k], m = p->fs[k + 1] - a;
        for (int i = 0; i < m; i++, t++) {
            int u = p->fi[a + i], w = p->fi[a + (i + 1) % m];
            e[t] = (edge){u < w ? u : w, u < w ? w : u, k, u < w};
        }
    }
    qsort(e, (size_t)ne, sizeof *e, edge_cmp);
    for (int t = 0; t < ne && !rc;) {
        int s = t;
        while (t < ne && e[t].lo == e[s].lo && e[t].hi == e[s].hi) t++;
        if (t - s == 1)
            rc = bl_error_set(err,
                              "block %d: the surface is open: edge %d-%d belongs to face %d only",
                              id, e[s].lo + 1, e[s].hi + 1, e[s].face + 1);
        else if (t - s > 2)
            rc = bl_error_set(err, "block %d: edge %d-%d is shared by %d faces (%d, %d, %d...)", id,
                              e[s].lo + 1, e[s].hi + 1, t - s, e[s].face + 1, e[s + 1].face + 1,
                              e[s + 2].face + 1);
        else if (e[s].face == e[s + 1].face)
            rc = bl_error_set(err, "block %d: face %d runs along edge %d-%d twice", id,
                              e[s].face + 1, e[s].lo + 1, e[s].hi + 1);
        else {
            nb[s] = s + 1;
            nb[s + 1] = s;
        }
    }

    /* orientation: faces agree with their neighbours when they run along a
     * shared edge in opposite directions; turn the ones that do not */
    if (!rc) {
        /* per face, its edge entries: walk the sorted list once per face */
        int *first = calloc((size_t)p->nf + 1, sizeof *first), *order = malloc((size_t)ne * sizeof *order);
        if (!first || !order) {
            rc = bl_error_set(err, "block %d: out of memory", id);
        } else {
            for (int t = 0; t < ne; t++) first[e[t].face + 1]++;
            for (int k = 0; k < p->nf; k++) first[k + 1] += first[k];
            int *fill = malloc(((size_t)p->nf + 1) * sizeof *fill);
            if (!fill) {
                rc = bl_error_set(err, "block %d: out of memory", id);
            } else {
                memcpy(fill, first, ((size_t)p->nf + 1) * sizeof *fill);
                for (int t = 0; t < ne; t++) order[fill[e[t].face]++] = t;
                free(fill);
                for (int k = 0; k < p->nf; k++) flip[k] = -1;
                flip[0] = 0;
                int head = 0, tail = 0;
                queue[tail++] = 0;
                while (head < tail && !rc) {
                    int f = queue[head++];
                    for (int q = first[f]; q < first[f + 1] && !rc; q++) {
                        int t = order[q], o = nb[t], g = e[o].face;
                        /* same direction along the edge: one of the two is turned */
                        int want = flip[f] ^ (e[t].forward == e[o].forward);
                        if (flip[g] < 0) {
                            flip[g] = want;
                            queue[tail++] = g;
                        } else if (flip[g] != want) {
                            rc = bl_error_set(err,
                                              "block %d: the surface cannot be oriented "
                                              "(faces %d and %d at edge %d-%d)",
                                              id, f + 1, g + 1, e[t].lo + 1, e[t].hi + 1);
                        }
                    }
                }
                if (!rc && tail < p->nf)
                    for (int k = 0; k < p->nf; k++)
                        if (flip[k] < 0) {
                            rc = bl_error_set(err,
                                              "block %d: the faces form more than one surface "
                                              "(face %d is not connected to face 1)",
                                              id, k + 1);
                            break;
                        }
            }
        }
        free(first);
        free(order);
    }
    if (!rc) {
        for (int k = 0; k < p->nf; k++)
            if (flip[k]) reverse_face(p, k);
        double vol = bl_polyhedron_volume(p, NULL), surface = 0.0, a;
        if (vol < 0.0)
            for (int k = 0; k < p->nf; k++) reverse_face(p, k);
        for (int k = 0; k < p->nf; k++) bl_polyhedron_face_normal(p, k, &a), surface += a;
        /* thinner than tol: a slab of that surface and thickness */
        if (!(fabs(vol) > tol * surface))
            rc = bl_error_set(err, "block %d: the polyhedron has zero volume", id);
    }
    free(e);
    free(flip);
    free(queue);
    free(nb);
    return rc;
}

int bl_convex_hull(const bl_vec3 *pts, int n, int id, bl_polyhedron *out, bl_error *err)
{
    memset(out, 0, sizeof *out);
    if (n < 4) return bl_error_set(err, "block %d: a convex hull needs at least 4 points, got %d", id, n);
    coordT *xyz = malloc((size_t)n * 3 * sizeof *xyz);
    int *map = malloc((size_t)n * sizeof *map);
    FILE *quiet = fopen("/dev/null", "w");
    if (!xyz || !map || !quiet) {
        free(xyz), free(map);
        if (quiet) fclose(quiet);
        return bl_error_set(err, "block %d: out of memory", id);
    }
    for (int i = 0; i < n; i++) {
        xyz[3 * i] = pts[i].x;
        xyz[3 * i + 1] = pts[i].y;
        xyz[3 * i + 2] = pts[i].z;
        map[i] = -1;
    }
    qhT qh_qh, *qh = &qh_qh;
    qh_zero(qh, quiet);
    int rc = 0;
    /* "qhull": merge coplanar facets into polygons; no output */
    if (qh_new_qhull(qh, 3, n, xyz, False, (char *)"qhull", NULL, quiet)) {
        rc = bl_error_set(err, "block %d: the points span no volume (all on one plane or line)",
                          id);
    } else {
        int nf = 0, nfi = 0, nv = 0;
        facetT *facet;
        vertexT *vertex, **vertexp;
        FORALLfacets {
            nf++;
            nfi += qh_setsize(qh, facet->vertices);
        }
        bl_vec3 *v = malloc((size_t)n * sizeof *v);
        int *fs = malloc(((size_t)nf + 1) * sizeof *fs), *fi = malloc((size_t)nfi * sizeof *fi);
        if (!v || !fs || !fi) {
            rc = bl_error_set(err, "block %d: out of memory", id);
        } else {
            int k = 0, t = 0;
            FORALLfacets {
                setT *ring = qh_facet3vertex(qh, facet); /* in order around the facet */
                fs[k++] = t;
                FOREACHvertex_(ring) {
                    int q = qh_pointid(qh, vertex->point);
                    if (map[q] < 0) {
                        map[q] = nv;
                        v[nv++] = pts[q];
                    }
                    fi[t++] = map[q];
                }
                qh_settempfree(qh, &ring);
            }
            fs[k] = t;
            if (bl_polyhedron_make(out, v, nv, fs, fi, nf))
                rc = bl_error_set(err, "block %d: out of memory", id);
        }
        free(v);
        free(fs);
        free(fi);
    }
    int curlong, totlong;
    qh_freeqhull(qh, !qh_ALL);
    qh_memfreeshort(qh, &curlong, &totlong);
    fclose(quiet);
    free(xyz);
    free(map);
    return rc;
}
