/* contact3.c - interface detection in a 3D block model (contact.h).
 *
 * Two blocks share an interface where a face of one and a face of the other
 * lie in one plane (within tol), face opposite ways and overlap over a
 * positive area: the overlap of every convex piece of the one with every
 * convex piece of the other (faces that are not convex are cut into
 * triangles first) is a convex contact polygon.  Candidate pairs come from
 * a sweep along the longest axis of the model over the bounding boxes
 * sorted by their low end: n log n, plus one box test per pair whose
 * extents along that axis overlap (about 2 N per block in an N x N wall).
 * Interpenetration: the separating-axis test for two convex blocks; else a
 * point found inside both (overlapping_any). */
#include "contact3.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A face's plane and frame: n . x = d, u along its first edge, v = n x u. */
typedef struct plane {
    bl_vec3 n, u, v, o;
    double d;
} plane;

static plane face_plane(const bl_polyhedron *p, int k)
{
    plane f;
    f.n = bl_polyhedron_face_normal(p, k, NULL);
    f.o = p->v[p->fi[p->fs[k]]];
    bl_vec3 e = bl_v3_sub(p->v[p->fi[p->fs[k] + 1]], f.o);
    e = bl_v3_sub(e, bl_v3_scale(f.n, bl_v3_dot(e, f.n)));
    f.u = bl_v3_scale(e, 1.0 / bl_v3_norm(e));
    f.v = bl_v3_cross(f.n, f.u);
    f.d = bl_v3_dot(f.n, f.o);
    return f;
}

static bl_vec2 to2(const plane *f, bl_vec3 x)
{
    bl_vec3 r = bl_v3_sub(x, f->o);
    return bl_v2(bl_v3_dot(r, f->u), bl_v3_dot(r, f->v));
}

static bl_vec3 to3(const plane *f, bl_vec2 q)
{
    return bl_v3_add(f->o, bl_v3_add(bl_v3_scale(f->u, q.x), bl_v3_scale(f->v, q.y)));
}

/* Convex pieces of a counter-clockwise polygon q (n points): the polygon
 * itself when convex, else the triangles of ear clipping.  Writes the
 * pieces as index lists into idx (at most 3 (n - 2) entries) with their
 * sizes in len; returns the number of pieces. */
static int convex_pieces(const bl_vec2 *q, int n, int *idx, int *len)
{
    int convex = 1;
    for (int i = 0; i < n && convex; i++)
        convex = bl_v2_cross(bl_v2_sub(q[(i + 1) % n], q[i]), bl_v2_sub(q[(i + 2) % n], q[(i + 1) % n])) >= 0.0;
    if (convex) {
        for (int i = 0; i < n; i++) idx[i] = i;
        len[0] = n;
        return 1;
    }
    int ring[256], m = n, pieces = 0;
    if (n > 256) return 0;
    for (int i = 0; i < n; i++) ring[i] = i;
    while (m > 3) {
        int cut = -1;
        for (int i = 0; i < m && cut < 0; i++) {
            bl_vec2 a = q[ring[(i + m - 1) % m]], b = q[ring[i]], c = q[ring[(i + 1) % m]];
            if (bl_v2_cross(bl_v2_sub(b, a), bl_v2_sub(c, b)) <= 0.0) continue; /* reflex */
            int inside = 0;
            for (int j = 0; j < m && !inside; j++) {
                bl_vec2 p = q[ring[j]];
                if (j == i || j == (i + 1) % m || j == (i + m - 1) % m) continue;
                inside = bl_v2_cross(bl_v2_sub(b, a), bl_v2_sub(p, a)) >= 0.0 &&
                         bl_v2_cross(bl_v2_sub(c, b), bl_v2_sub(p, b)) >= 0.0 &&
                         bl_v2_cross(bl_v2_sub(a, c), bl_v2_sub(p, c)) >= 0.0;
            }
            if (!inside) cut = i;
        }
        if (cut < 0) cut = 0; /* degenerate: cut anyway */
        idx[3 * pieces] = ring[(cut + m - 1) % m];
        idx[3 * pieces + 1] = ring[cut];
        idx[3 * pieces + 2] = ring[(cut + 1) % m];
        len[pieces++] = 3;
        memmove(ring + cut, ring + cut + 1, (size_t)(m - cut - 1) * sizeof *ring);
        m--;
    }
    idx[3 * pieces] = ring[0];
    idx[3 * pieces + 1] = ring[1];
    idx[3 * pieces + 2] = ring[2];
    len[pieces++] = 3;
    return pieces;
}

/* Clips the convex polygon s (ns points, counter-clockwise) by the convex
 * polygon c (nc, counter-clockwise) into out (room for ns + nc points);
 * returns the number of points. */
static int clip(const bl_vec2 *s, int ns, const bl_vec2 *c, int nc, bl_vec2 *out, bl_vec2 *tmp)
{
    int n = ns;
    memcpy(out, s, (size_t)ns * sizeof *s);
    for (int e = 0; e < nc && n > 0; e++) {
        bl_vec2 a = c[e], b = c[(e + 1) % nc], ab = bl_v2_sub(b, a);
        int m = 0;
        for (int i = 0; i < n; i++) {
            bl_vec2 p = out[i], q = out[(i + 1) % n];
            double hp = bl_v2_cross(ab, bl_v2_sub(p, a)), hq = bl_v2_cross(ab, bl_v2_sub(q, a));
            if (hp >= 0.0) tmp[m++] = p;
            if ((hp >= 0.0) != (hq >= 0.0)) {
                double t = hp / (hp - hq);
                tmp[m++] = bl_v2_add(p, bl_v2_scale(bl_v2_sub(q, p), t));
            }
        }
        memcpy(out, tmp, (size_t)m * sizeof *tmp);
        n = m;
    }
    return n;
}

enum { MAXV = 256 };

/* Points within this share of a polygon's extent of the line through
 * their neighbours lie on it but for round-off. */
#define ON_LINE 1e-9

/* Drops points closer than tol to the one before, then points on the line
 * through their two neighbours (to round-off, ON_LINE): where two faces
 * share an edge, the clipping cuts that edge at a point that round-off
 * places anywhere along it, and the polygon's points (the LP's contact
 * points) then depended on where the model lay (a wall turned by 30
 * degrees had square joints of 5 and 6 points at the origin, of 4 moved
 * away from it).  Each point is judged against its neighbours as given,
 * so that no removal moves the line the next is judged against. */
static int simplify(bl_vec2 *q, int n, double tol)
{
    int m = 0;
    for (int i = 0; i < n; i++)
        if (m == 0 || bl_v2_norm(bl_v2_sub(q[i], q[m - 1])) > tol) q[m++] = q[i];
    while (m > 1 && bl_v2_norm(bl_v2_sub(q[m - 1], q[0])) <= tol) m--;
    if (m <= 3) return m;
    double extent = 0.0;
    for (int i = 1; i < m; i++) extent = fmax(extent, bl_v2_norm(bl_v2_sub(q[i], q[0])));
    char on[2 * MAXV];
    int kept = m;
    for (int i = 0; i < m; i++) {
        bl_vec2 a = q[(i + m - 1) % m], b = q[(i + 1) % m], ab = bl_v2_sub(b, a);
        double len = bl_v2_norm(ab);
        on[i] = len > 0.0 && fabs(bl_v2_cross(ab, bl_v2_sub(q[i], a))) <= ON_LINE * extent * len;
        kept -= on[i];
    }
    if (kept < 3) return m;
    int k = 0;
    for (int i = 0; i < m; i++)
        if (!on[i]) q[k++] = q[i];
    return k;
}


/* Called for each overlap of two faces: the polygon (k points, in the
 * first face's frame) and its area; a nonzero return stops the search. */
typedef int overlap_fn(void *ctx, const bl_vec2 *q, int k, double area);

/* The overlaps of face fa of A (in its frame f) and face fb of B, convex
 * piece by convex piece, each larger in area than tol times its piece's
 * size, passed to each(); B's face is taken the other way round where it
 * faces A (reverse).  Returns the first nonzero return of each(), or 0. */
static int face_overlaps(const bl_polyhedron *A, int fa, const plane *f, const bl_polyhedron *B, int fb,
                         int reverse, double tol, overlap_fn *each, void *ctx)
{
    int a0 = A->fs[fa], na = A->fs[fa + 1] - a0, b0 = B->fs[fb], nb = B->fs[fb + 1] - b0;
    if (na > MAXV || nb > MAXV) return 0;
    bl_vec2 qa[MAXV], qb[MAXV], out[2 * MAXV], tmp[2 * MAXV], sa[MAXV], sb[MAXV];
    int ia_idx[3 * MAXV], ia_len[MAXV], ib_idx[3 * MAXV], ib_len[MAXV];
    for (int i = 0; i < na; i++) qa[i] = to2(f, A->v[A->fi[a0 + i]]);
    for (int i = 0; i < nb; i++) qb[i] = to2(f, B->v[B->fi[b0 + (reverse ? nb - 1 - i : i)]]);
    int pa = convex_pieces(qa, na, ia_idx, ia_len), pb = convex_pieces(qb, nb, ib_idx, ib_len);
    for (int x = 0, ox = 0; x < pa; ox += ia_len[x], x++) {
        for (int i = 0; i < ia_len[x]; i++) sa[i] = qa[ia_idx[ox + i]];
        for (int y = 0, oy = 0; y < pb; oy += ib_len[y], y++) {
            for (int i = 0; i < ib_len[y]; i++) sb[i] = qb[ib_idx[oy + i]];
            int k = simplify(out, clip(sa, ia_len[x], sb, ib_len[y], out, tmp), tol);
            if (k < 3) continue;
            double area = bl_polygon_area(out, k);
            if (!(area > tol * sqrt(fabs(bl_polygon_area(sa, ia_len[x]))))) continue;
            int rc = each(ctx, out, k, area);
            if (rc) return rc;
        }
    }
    return 0;
}

/* How far the unit normals of two faces may differ for the faces to lie in
 * one plane: to within tol over face k's extent (a file's rounding tilts
 * a small face more than a large one), and 1e-6 at least. */
static double parallel_limit(const bl_polyhedron *p, int k, double tol)
{
    double area;
    bl_polyhedron_face_normal(p, k, &area);
    return fmax(1e-6, 2.0 * tol / sqrt(area));
}

/* What pair3 passes to its overlap callback. */
typedef struct pair_ctx {
    bl_model *m;
    int ia, ib, found;
    const plane *f;
    double h, tol, near_d;
    bl_error *err;
} pair_ctx;

/* An overlap of two faces that face each other h apart: an interface
 * (h within tol), else a near-miss. */
static int add_contact(void *ctx, const bl_vec2 *q, int k, double area)
{
    pair_ctx *c = ctx;
    if (c->h > c->tol) { /* parallel, overlapping, apart: a near-miss */
        c->near_d = c->near_d > 0.0 ? fmin(c->near_d, c->h) : c->h;
        return 0;
    }
    bl_model *m = c->m;
    bl_interface j = {0};
    j.a = c->ia;
    j.b = c->ib;
    j.mu = m->mu;
    j.cohesion = m->cohesion;
    j.imodel = m->interface_model;
    j.mu_t = m->mu_t;
    j.np = k;
    j.poly = malloc((size_t)k * sizeof *j.poly);
    if (!j.poly) return bl_error_set(c->err, "contacts: out of memory");
    for (int i = 0; i < k; i++) j.poly[i] = to3(c->f, q[i]);
    j.n3 = c->f->n;
    /* the frame along the polygon's longest edge, which does not depend
     * on where the clipping began (along the first edge, a dome's
     * symmetric joints got pyramids turned apart, and moving the dome
     * changed alpha by 0.2 %), nor, where two edges tie, on which of them
     * the round-off makes the longer (a dome's head joints, whose two bed
     * edges are as long: moved, 56 of 3,840 joints turned by 3 degrees
     * and alpha by 4e-5) */
    bl_vec3 *e = malloc((size_t)k * sizeof *e);
    if (!e) {
        free(j.poly);
        return bl_error_set(c->err, "contacts: out of memory");
    }
    for (int i = 0; i < k; i++) e[i] = bl_v3_sub(j.poly[(i + 1) % k], j.poly[i]);
    j.t2 = bl_longest_direction(e, k);
    free(e);
    j.t3 = bl_v3_cross(j.n3, j.t2);
    j.area3 = area;
    if (bl_model_add_interface(m, &j, c->err)) {
        free(j.poly);
        return -1;
    }
    c->found = 1;
    return 0;
}

/* The distance from x to the segment a-b. */
static double to_segment(bl_vec3 x, bl_vec3 a, bl_vec3 b)
{
    bl_vec3 d = bl_v3_sub(b, a);
    double dd = bl_v3_dot(d, d), t = dd > 0.0 ? bl_v3_dot(bl_v3_sub(x, a), d) / dd : 0.0;
    t = fmin(1.0, fmax(0.0, t));
    return bl_v3_norm(bl_v3_sub(x, bl_v3_add(a, bl_v3_scale(d, t))));
}

/* Whether the edge of interface g[i] whose middle is x lies on an edge of
 * another of the n interfaces g (within tol): inside their union. */
static int inner_edge(const bl_model *m, const int *g, int n, int i, bl_vec3 x, double tol)
{
    for (int j = 0; j < n; j++) {
        const bl_interface *q = &m->interfaces[g[j]];
        for (int e = 0; e < q->np && j != i; e++)
            if (to_segment(x, q->poly[e], q->poly[(e + 1) % q->np]) <= tol) return 1;
    }
    return 0;
}

/* The interfaces first..m->ninterfaces-1 join one pair of blocks; those
 * in one plane (within tol) share one frame, along the longest edge of
 * their union's boundary (bl_longest_direction; an edge no other of them
 * shares).  A lone interface keeps its own, along its
 * longest edge.  Each piece's own, along an edge that may be a cut, gave
 * an L-shaped bed, cut into triangles (by the detection where its face is
 * not convex, or by the file it came from), pyramids along the diagonals,
 * and it slid at 0.92 mu where a square bed of the same stone slides at
 * mu.  The union's boundary does not depend on how the faces were cut,
 * nor on which block is which. */
static int share_frames(bl_model *m, int first, double tol, bl_error *err)
{
    int n = m->ninterfaces - first;
    if (n < 2) return 0;
    int *g = malloc((size_t)n * sizeof *g), ne = 0;
    for (int i = 0; i < n; i++) ne += m->interfaces[first + i].np;
    char *done = calloc((size_t)n, 1);
    bl_vec3 *edges = malloc((size_t)ne * sizeof *edges);
    if (!g || !done || !edges) {
        free(g), free(done), free(edges);
        return bl_error_set(err, "contacts: out of memory");
    }
    for (int i = 0; i < n; i++) {
        if (done[i]) continue;
        const bl_interface *p = &m->interfaces[first + i];
        int k = 0;
        for (int j = i; j < n; j++) {
            const bl_interface *q = &m->interfaces[first + j];
            if (!done[j] && bl_v3_dot(p->n3, q->n3) > 1.0 - 1e-9 &&
                fabs(bl_v3_dot(p->n3, bl_v3_sub(q->poly[0], p->poly[0]))) <= tol)
                g[k++] = first + j, done[j] = 1;
        }
        if (k < 2) continue;
        int nb = 0; /* the union's boundary */
        for (int a = 0; a < k; a++) {
            const bl_interface *q = &m->interfaces[g[a]];
            for (int v = 0; v < q->np; v++) {
                bl_vec3 x = q->poly[v], y = q->poly[(v + 1) % q->np];
                if (!inner_edge(m, g, k, a, bl_v3_scale(bl_v3_add(x, y), 0.5), tol))
                    edges[nb++] = bl_v3_sub(y, x);
            }
        }
        if (nb == 0) continue;
        bl_vec3 e = bl_longest_direction(edges, nb);
        for (int a = 0; a < k; a++) {
            bl_interface *q = &m->interfaces[g[a]];
            /* (in each one's plane: a file's rounding may tilt them apart) */
            bl_vec3 t = bl_v3_sub(e, bl_v3_scale(q->n3, bl_v3_dot(e, q->n3)));
            q->t2 = bl_v3_scale(t, 1.0 / bl_v3_norm(t));
            q->t3 = bl_v3_cross(q->n3, q->t2);
        }
    }
    free(g), free(done), free(edges);
    return 0;
}

/* Every interface between blocks ia and ib; a near-miss or nothing. */
static int pair3(bl_model *m, int ia, int ib, double tol, double gap, bl_contact_problems *pr, bl_error *err)
{
    const bl_polyhedron *A = &m->blocks[ia].solid, *B = &m->blocks[ib].solid;
    pair_ctx c = {.m = m, .ia = ia, .ib = ib, .tol = tol, .err = err};
    int first = m->ninterfaces;
    for (int fa = 0; fa < A->nf; fa++) {
        plane f = face_plane(A, fa);
        double lim = parallel_limit(A, fa, tol);
        c.f = &f;
        for (int fb = 0; fb < B->nf; fb++) {
            bl_vec3 n = bl_polyhedron_face_normal(B, fb, NULL);
            if (bl_v3_norm(bl_v3_add(n, f.n)) > lim) continue; /* not facing each other */
            c.h = bl_v3_dot(f.n, bl_v3_sub(B->v[B->fi[B->fs[fb]]], f.o));
            if (c.h < -tol || c.h > gap) continue;
            if (face_overlaps(A, fa, &f, B, fb, 1, tol, add_contact, &c)) return -1;
        }
    }
    if (share_frames(m, first, tol, err)) return -1;
    if (c.near_d > 0.0 && !c.found && !bl_contact_declared(m, ia, ib)) {
        if (pr->nnear < 5)
            snprintf(pr->near[pr->nnear], sizeof pr->near[0], "blocks %d and %d (%.3g apart)",
                     ia + 1, ib + 1, c.near_d);
        pr->nnear++;
    }
    return 0;
}

/* Depth of x inside the convex hull of the faces' planes of p: the least
 * distance to a face plane, positive inside.  For a block that is not
 * convex this is a lower bound only where x is inside. */
static double depth3(const bl_polyhedron *p, bl_vec3 x)
{
    double d = INFINITY;
    for (int k = 0; k < p->nf; k++) {
        bl_vec3 n = bl_polyhedron_face_normal(p, k, NULL);
        d = fmin(d, bl_v3_dot(n, bl_v3_sub(p->v[p->fi[p->fs[k]]], x)));
    }
    return d;
}

/* Projections of a polyhedron's vertices on the axis a: [*lo, *hi]. */
static void project(const bl_polyhedron *p, bl_vec3 a, double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int i = 0; i < p->nv; i++) {
        double t = bl_v3_dot(p->v[i], a);
        *lo = fmin(*lo, t);
        *hi = fmax(*hi, t);
    }
}

/* 1 when the projections on the unit axis a overlap by more than tol. */
static int overlap_on(const bl_polyhedron *A, const bl_polyhedron *B, bl_vec3 a, double tol)
{
    double alo, ahi, blo, bhi;
    project(A, a, &alo, &ahi);
    project(B, a, &blo, &bhi);
    return fmin(ahi, bhi) - fmax(alo, blo) > tol;
}

/* Interpenetration of two convex blocks by the separating-axis test: they
 * overlap deeper than tol unless their projections on a face normal of
 * either, or on the cross product of an edge of each, overlap by tol or
 * less. */
static int overlapping3(const bl_block *X, const bl_block *Y, double tol)
{
    const bl_polyhedron *A = &X->solid, *B = &Y->solid;
    for (int pass = 0; pass < 2; pass++) {
        const bl_polyhedron *P = pass ? B : A;
        for (int k = 0; k < P->nf; k++)
            if (!overlap_on(A, B, bl_polyhedron_face_normal(P, k, NULL), tol)) return 0;
    }
    for (int k = 0; k < A->nf; k++)
        for (int i = A->fs[k]; i < A->fs[k + 1]; i++) {
            int i1 = i + 1 < A->fs[k + 1] ? i + 1 : A->fs[k];
            bl_vec3 ea = bl_v3_sub(A->v[A->fi[i1]], A->v[A->fi[i]]);
            for (int l = 0; l < B->nf; l++)
                for (int j = B->fs[l]; j < B->fs[l + 1]; j++) {
                    int j1 = j + 1 < B->fs[l + 1] ? j + 1 : B->fs[l];
                    bl_vec3 c = bl_v3_cross(ea, bl_v3_sub(B->v[B->fi[j1]], B->v[B->fi[j]]));
                    double len = bl_v3_norm(c);
                    if (len <= 1e-12 * (bl_v3_norm(ea) + 1e-300) * (bl_v3_norm(ea) + 1e-300))
                        continue; /* parallel edges */
                    if (!overlap_on(A, B, bl_v3_scale(c, 1.0 / len), tol)) return 0;
                }
        }
    return 1;
}

static int any_overlap(void *ctx, const bl_vec2 *q, int k, double area)
{
    (void)ctx, (void)q, (void)k, (void)area;
    return 1;
}

/* Whether a face of A and a face of B lie in one plane (within tol), look
 * the same way and overlap over an area (more than tol times the piece's
 * size): the blocks then overlap next to it, on the same side of it. */
static int same_way_faces_overlap(const bl_polyhedron *A, const bl_polyhedron *B, double tol)
{
    for (int fa = 0; fa < A->nf; fa++) {
        plane f = face_plane(A, fa);
        double lim = parallel_limit(A, fa, tol);
        for (int fb = 0; fb < B->nf; fb++) {
            if (bl_v3_norm(bl_v3_sub(bl_polyhedron_face_normal(B, fb, NULL), f.n)) > lim) continue;
            if (fabs(bl_v3_dot(f.n, bl_v3_sub(B->v[B->fi[B->fs[fb]]], f.o))) > tol) continue;
            if (face_overlaps(A, fa, &f, B, fb, 0, tol, any_overlap, NULL)) return 1;
        }
    }
    return 0;
}

/* Interpenetration of two blocks either of which is not convex: faces of
 * both in one plane, looking the same way, that overlap (two prisms of one
 * depth that cross: no vertex or edge of one goes into the other); else a
 * point deeper than tol inside both: a vertex of one (on its surface,
 * inside it next to it), the point 2 tol inside each face from the middle
 * of each of its edges, or an edge of one through a face of the other
 * (where two surfaces cross, an edge of one meets a face of the other). */
static int overlapping_any(const bl_block *X, const bl_block *Y, double tol)
{
    if (same_way_faces_overlap(&X->solid, &Y->solid, tol)) return 1;
    for (int pass = 0; pass < 2; pass++) {
        const bl_polyhedron *A = pass ? &Y->solid : &X->solid, *B = pass ? &X->solid : &Y->solid;
        for (int i = 0; i < A->nv; i++)
            if (bl_polyhedron_depth(B, A->v[i]) > tol) return 1;
        for (int k = 0; k < A->nf; k++) {
            bl_vec3 n = bl_polyhedron_face_normal(A, k, NULL);
            for (int i = A->fs[k]; i < A->fs[k + 1]; i++) {
                int i1 = i + 1 < A->fs[k + 1] ? i + 1 : A->fs[k];
                bl_vec3 a = A->v[A->fi[i]], b = A->v[A->fi[i1]];
                if (bl_polyhedron_pierced(B, a, b, tol)) return 1;
                /* the face turns counter-clockwise seen from outside: n x e points into it */
                bl_vec3 in = bl_v3_unit(bl_v3_cross(n, bl_v3_sub(b, a)));
                bl_vec3 p = bl_v3_add(bl_v3_scale(bl_v3_add(a, b), 0.5), bl_v3_scale(bl_v3_sub(in, n), 2.0 * tol));
                if (bl_polyhedron_depth(A, p) > tol && bl_polyhedron_depth(B, p) > tol) return 1;
            }
        }
    }
    return 0;
}

/* Blocks in order of the low end of their boxes along one axis. */
static int sweep_axis;
static const bl_block *sweep_blocks;
static int by_low(const void *x, const void *y)
{
    double a = sweep_blocks[*(const int *)x].box3[sweep_axis];
    double b = sweep_blocks[*(const int *)y].box3[sweep_axis];
    return (a > b) - (a < b);
}

static int convex(const bl_polyhedron *p, double tol)
{
    for (int i = 0; i < p->nv; i++)
        if (depth3(p, p->v[i]) < -tol) return 0;
    return 1;
}

int bl_contact_pairs3(bl_model *m, double tol, double gap, bl_contact_problems *pr, bl_error *err)
{
    int n = m->nblocks;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < n; i++)
        for (int d = 0; d < 3; d++) {
            lo[d] = fmin(lo[d], m->blocks[i].box3[d]);
            hi[d] = fmax(hi[d], m->blocks[i].box3[d + 3]);
        }
    int axis = 0;
    for (int d = 1; d < 3; d++)
        if (hi[d] - lo[d] > hi[axis] - lo[axis]) axis = d;
    int *order = malloc((size_t)n * sizeof *order);
    char *is_convex = malloc((size_t)n + 1);
    if (!order || !is_convex) {
        free(order);
        free(is_convex);
        return bl_error_set(err, "contacts: out of memory");
    }
    for (int i = 0; i < n; i++) {
        order[i] = i;
        is_convex[i] = (char)convex(&m->blocks[i].solid, tol);
    }
    sweep_axis = axis;
    sweep_blocks = m->blocks;
    qsort(order, (size_t)n, sizeof *order, by_low);

    int rc = 0;
    for (int s = 0; s < n && !rc; s++) {
        int i = order[s];
        const bl_block *A = &m->blocks[i];
        for (int t = s + 1; t < n && !rc; t++) {
            int j = order[t];
            const bl_block *B = &m->blocks[j];
            if (B->box3[axis] > A->box3[axis + 3] + gap) break;
            if (A->support && B->support) continue;
            int apart = 0, deep = 1;
            for (int d = 0; d < 3; d++) {
                apart |= A->box3[d] > B->box3[d + 3] + gap || B->box3[d] > A->box3[d + 3] + gap;
                deep &= A->box3[d] < B->box3[d + 3] - tol && B->box3[d] < A->box3[d + 3] - tol;
            }
            if (apart) continue;
            int a = i < j ? i : j, b = i < j ? j : i;
            if (deep && (is_convex[a] && is_convex[b] ? overlapping3(&m->blocks[a], &m->blocks[b], tol)
                                                      : overlapping_any(&m->blocks[a], &m->blocks[b], tol))) {
                if (pr->noverlap < 5)
                    snprintf(pr->overlap[pr->noverlap], sizeof pr->overlap[0], "blocks %d and %d",
                             a + 1, b + 1);
                pr->noverlap++;
                continue;
            }
            rc = pair3(m, a, b, tol, gap, pr, err);
        }
    }
    free(order);
    free(is_convex);
    return rc;
}
