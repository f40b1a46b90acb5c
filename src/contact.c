#include "contact3.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The coarsest resolution of the blocks' coordinates (0: all exact). */
static double coarsest(const bl_model *m)
{
    double r = 0.0;
    for (int i = 0; i < m->nblocks; i++) r = fmax(r, m->blocks[i].resolution);
    return r;
}

void bl_contact_tolerances(const bl_model *m, double *tol, double *gap)
{
    double typical = 0.0, resolution = coarsest(m);
    for (int i = 0; i < m->nblocks; i++)
        typical += m->dim == 3 ? cbrt(m->blocks[i].volume) : sqrt(m->blocks[i].area);
    if (m->nblocks) typical /= m->nblocks;
    /* by default, faces that meet to the last digit of a file's numbers
     * (or to an arc's chords; doc/guide.md, import) touch: 10 times the
     * coarsest resolution, but at most a thousandth of a typical block and
     * a tenth of a near-miss gap given, so that it never swallows a joint
     * or the near-miss check */
    double own = fmin(10.0 * resolution, 1e-3 * typical);
    if (m->contact_gap > 0.0) own = fmin(own, 0.1 * m->contact_gap);
    *tol = m->contact_tol > 0.0 ? m->contact_tol : fmax(1e-8 * bl_model_size(m), own);
    *gap = m->contact_gap > 0.0 ? m->contact_gap : 1e-2 * typical;
    if (m->contact_gap < 0.0) *gap = 0.0; /* near-miss check switched off */
    if (*gap < *tol) *gap = *tol;
}

typedef bl_contact_problems problems;

/* Edge i of block k: from v[i] to v[i+1]; outward normal (dy, -dx)/len since
 * polygons are counter-clockwise. */
static void pair_contacts(bl_model *m, int ia, int ib, double tol, double gap, problems *pr,
                          int *failed, bl_error *err)
{
    const bl_block *A = &m->blocks[ia], *B = &m->blocks[ib];
    int found = 0;
    double near_d = 0.0;
    for (int i = 0; i < A->nv; i++) {
        bl_vec2 p = A->v[i], q = A->v[(i + 1) % A->nv];
        bl_vec2 d = bl_v2_sub(q, p);
        double len = bl_v2_norm(d);
        bl_vec2 t = bl_v2_scale(d, 1.0 / len);
        bl_vec2 nrm = bl_v2(t.y, -t.x);
        for (int j = 0; j < B->nv; j++) {
            bl_vec2 r = B->v[j], s = B->v[(j + 1) % B->nv];
            bl_vec2 e = bl_v2_sub(s, r);
            if (bl_v2_dot(e, d) >= 0.0) continue; /* not facing opposite ways */
            double hr = bl_v2_dot(bl_v2_sub(r, p), nrm), hs = bl_v2_dot(bl_v2_sub(s, p), nrm);
            double tr = bl_v2_dot(bl_v2_sub(r, p), t), ts = bl_v2_dot(bl_v2_sub(s, p), t);
            double t0 = fmax(0.0, fmin(tr, ts)), t1 = fmin(len, fmax(tr, ts));
            if (t1 - t0 <= tol) continue;
            if (fabs(hr) <= tol && fabs(hs) <= tol) {
                bl_interface k = {0};
                k.a = ia;
                k.b = ib;
                k.p[0] = bl_v2_add(p, bl_v2_scale(t, t0));
                k.p[1] = bl_v2_add(p, bl_v2_scale(t, t1));
                k.normal = nrm;
                k.mu = m->mu;
                k.cohesion = m->cohesion;
                if (bl_model_add_interface(m, &k, err)) {
                    *failed = 1;
                    return;
                }
                found = 1;
            } else if (hr > tol && hs > tol && hr <= gap && hs <= gap) {
                near_d = fmax(near_d, fmin(hr, hs));
            }
        }
    }
    if (near_d > 0.0 && !found && !bl_contact_declared(m, ia, ib)) {
        if (pr->nnear < 5)
            snprintf(pr->near[pr->nnear], sizeof pr->near[0], "blocks %d and %d (%.3g apart)",
                     ia + 1, ib + 1, near_d);
        pr->nnear++;
    }
}

/* Interpenetration: edges crossing, or a vertex or edge midpoint of one block
 * deeper than tol inside the other, or one centroid inside the other. */
static int overlapping(const bl_block *A, const bl_block *B, double tol)
{
    for (int i = 0; i < A->nv; i++) {
        bl_vec2 p = A->v[i], q = A->v[(i + 1) % A->nv];
        for (int j = 0; j < B->nv; j++)
            if (bl_segments_cross(p, q, B->v[j], B->v[(j + 1) % B->nv], tol)) return 1;
    }
    for (int pass = 0; pass < 2; pass++) {
        const bl_block *X = pass ? B : A, *Y = pass ? A : B;
        for (int i = 0; i < X->nv; i++) {
            bl_vec2 mid = bl_v2_scale(bl_v2_add(X->v[i], X->v[(i + 1) % X->nv]), 0.5);
            if (bl_polygon_depth(Y->v, Y->nv, X->v[i]) > tol ||
                bl_polygon_depth(Y->v, Y->nv, mid) > tol)
                return 1;
        }
        if (bl_polygon_depth(Y->v, Y->nv, X->centroid) > tol) return 1;
    }
    return 0;
}

static int same_pair(const bl_interface *k, int a, int b)
{
    return (k->a == a && k->b == b) || (k->a == b && k->b == a);
}

int bl_contact_declared(const bl_model *m, int a, int b)
{
    for (int s = 0; s < m->njoints; s++) {
        const bl_joint_spec *j = &m->joints[s];
        if (j->npoints > 0 && ((j->a == a && j->b == b) || (j->a == b && j->b == a))) return 1;
    }
    return 0;
}

/* The depth of q in block B (inside positive; 2D: q's x, y). */
static double depth_at(const bl_block *B, int dim, bl_vec3 q)
{
    return dim == 3 ? bl_polyhedron_depth(&B->solid, q) : bl_polygon_depth(B->v, B->nv, bl_v2(q.x, q.y));
}

/* The angle in degrees between the unit normal nu (either way) and the
 * outward normal of the face (2D: edge) of block B whose plane q lies
 * farthest beyond: near 90 for a point past the block's side, small for
 * a point off a face the joint tilts from. */
static double tilt_at(const bl_block *B, int dim, bl_vec3 q, bl_vec3 nu)
{
    double far = -INFINITY, c = 0.0;
    int nf = dim == 3 ? B->solid.nf : B->nv;
    for (int k = 0; k < nf; k++) {
        bl_vec3 n, v0;
        if (dim == 3) {
            n = bl_polyhedron_face_normal(&B->solid, k, NULL);
            v0 = B->solid.v[B->solid.fi[B->solid.fs[k]]];
        } else { /* counter-clockwise: the outward normal is the edge turned right */
            bl_vec2 a = B->v[k], b = B->v[(k + 1) % B->nv];
            n = bl_v3_unit(bl_v3(b.y - a.y, a.x - b.x, 0.0));
            v0 = bl_v3(a.x, a.y, 0.0);
        }
        double h = bl_v3_dot(n, bl_v3_sub(q, v0));
        if (h > far) far = h, c = fabs(bl_v3_dot(n, nu));
    }
    return acos(fmin(c, 1.0)) * 180.0 / M_PI;
}

/* How well the side of a joint's plane through mid that the unit normal n
 * points to holds block b, and the other side block a: the depths (inside
 * positive) of probes a small step either side of mid.  The normal of a
 * declared joint is the one of the two with the larger score: by the
 * centroids alone, a cap stone whose downstands reach below its seat got
 * the normal reversed, and its model was called infeasible. */
static double side_score(const bl_model *m, int a, int b, bl_vec3 mid, bl_vec3 n)
{
    const bl_block *A = &m->blocks[a], *B = &m->blocks[b];
    double size = m->dim == 3 ? fmin(cbrt(A->volume), cbrt(B->volume)) : fmin(sqrt(A->area), sqrt(B->area));
    bl_vec3 step = bl_v3_scale(n, 1e-4 * size);
    return depth_at(B, m->dim, bl_v3_add(mid, step)) + depth_at(A, m->dim, bl_v3_sub(mid, step));
}

/* A 3D joint declared by hand: its polygon, the normal from a into b (the
 * side that holds b, side_score), the frame along its longest edge, and its
 * area. */
static int add_joint3(bl_model *m, const bl_joint_spec *s, bl_error *err)
{
    bl_interface k = {0};
    k.a = s->a;
    k.b = s->b;
    k.np = s->npoints;
    k.poly = malloc((size_t)k.np * sizeof *k.poly);
    if (!k.poly) return bl_error_set(err, "interface: out of memory");
    memcpy(k.poly, s->p3, (size_t)k.np * sizeof *k.poly);
    bl_vec3 n = {0, 0, 0};
    for (int i = 1; i + 1 < k.np; i++)
        n = bl_v3_add(n, bl_v3_cross(bl_v3_sub(k.poly[i], k.poly[0]), bl_v3_sub(k.poly[i + 1], k.poly[0])));
    k.area3 = 0.5 * bl_v3_norm(n);
    k.n3 = bl_v3_scale(n, 0.5 / k.area3);
    bl_vec3 mid = {0, 0, 0};
    for (int i = 0; i < k.np; i++) mid = bl_v3_add(mid, bl_v3_scale(k.poly[i], 1.0 / k.np));
    if (side_score(m, s->a, s->b, mid, bl_v3_scale(k.n3, -1.0)) > side_score(m, s->a, s->b, mid, k.n3))
        k.n3 = bl_v3_scale(k.n3, -1.0);
    bl_vec3 e[BL_JOINT_POINTS];
    for (int i = 0; i < k.np; i++) e[i] = bl_v3_sub(k.poly[(i + 1) % k.np], k.poly[i]);
    k.t2 = bl_longest_direction(e, k.np); /* as a detected joint's: either way round, the same */
    k.t3 = bl_v3_cross(k.n3, k.t2);
    k.mu = s->has_mu ? s->mu : m->mu;
    k.cohesion = s->has_cohesion ? s->cohesion : m->cohesion;
    k.imodel = s->has_imodel ? s->imodel : m->interface_model;
    k.mu_t = s->has_mu_t ? s->mu_t : m->mu_t;
    k.manual = 1;
    if (bl_model_add_interface(m, &k, err)) {
        free(k.poly);
        return -1;
    }
    return 0;
}

static int apply_joint(bl_model *m, const bl_joint_spec *s, bl_error *err)
{
    if (s->npoints > 0) {
        int n = 0;
        for (int i = 0; i < m->ninterfaces; i++) {
            if (!same_pair(&m->interfaces[i], s->a, s->b)) m->interfaces[n++] = m->interfaces[i];
            else free(m->interfaces[i].poly);
        }
        m->ninterfaces = n;
        if (m->dim == 3) return add_joint3(m, s, err);
        bl_vec2 d = bl_v2_sub(s->p[1], s->p[0]);
        double len = bl_v2_norm(d);
        bl_interface k = {0};
        k.a = s->a;
        k.b = s->b;
        k.p[0] = s->p[0];
        k.p[1] = s->p[1];
        k.normal = bl_v2(-d.y / len, d.x / len);
        bl_vec3 mid = {0.5 * (s->p[0].x + s->p[1].x), 0.5 * (s->p[0].y + s->p[1].y), 0.0};
        bl_vec3 nu = {k.normal.x, k.normal.y, 0.0};
        if (side_score(m, s->a, s->b, mid, bl_v3_scale(nu, -1.0)) > side_score(m, s->a, s->b, mid, nu))
            k.normal = bl_v2_scale(k.normal, -1.0);
        k.mu = s->has_mu ? s->mu : m->mu;
        k.cohesion = s->has_cohesion ? s->cohesion : m->cohesion;
        k.manual = 1;
        return bl_model_add_interface(m, &k, err);
    }
    int hit = 0;
    for (int i = 0; i < m->ninterfaces; i++) {
        bl_interface *k = &m->interfaces[i];
        if (!same_pair(k, s->a, s->b)) continue;
        if (s->has_mu) k->mu = s->mu;
        if (s->has_cohesion) k->cohesion = s->cohesion;
        if (s->has_imodel) k->imodel = s->imodel;
        if (s->has_mu_t) k->mu_t = s->mu_t;
        hit = 1;
    }
    if (!hit)
        return bl_error_set(err,
                            "interface: blocks %d and %d share no interface to change; "
                            "give points = %s to declare one",
                            s->a + 1, s->b + 1,
                            m->dim == 3 ? "{{x1, y1, z1}, {x2, y2, z2}, {x3, y3, z3}, ...}"
                                        : "{{x1, y1}, {x2, y2}}");
    return 0;
}

int bl_joint_check(const bl_model *m, const bl_joint_spec *s, bl_error *err)
{
    if (s->npoints == 0) return 0;
    double tol, gap;
    bl_contact_tolerances(m, &tol, &gap);
    const bl_block *blk[2] = {&m->blocks[s->a], &m->blocks[s->b]};
    double size = m->dim == 3 ? fmin(cbrt(blk[0]->volume), cbrt(blk[1]->volume))
                              : fmin(sqrt(blk[0]->area), sqrt(blk[1]->area));
    double far = fmax(BL_JOINT_REACH * size, gap);
    int n = s->npoints;
    bl_vec2 mid = bl_v2_scale(bl_v2_add(s->p[0], s->p[1]), 0.5);
    bl_vec3 mean = {0, 0, 0};
    for (int i = 0; i < n && m->dim == 3; i++) mean = bl_v3_add(mean, bl_v3_scale(s->p3[i], 1.0 / n));
    /* the joint's unit normal (either way) */
    bl_vec3 nu = {0, 0, 0};
    if (m->dim == 3) {
        for (int i = 1; i + 1 < n; i++)
            nu = bl_v3_add(nu, bl_v3_cross(bl_v3_sub(s->p3[i], s->p3[0]), bl_v3_sub(s->p3[i + 1], s->p3[0])));
    } else {
        nu = bl_v3(s->p[0].y - s->p[1].y, s->p[1].x - s->p[0].x, 0.0);
    }
    nu = bl_v3_scale(nu, 1.0 / bl_v3_norm(nu));
    /* every point, then the middle (a joint cut across a block) */
    for (int i = 0; i <= n; i++)
        for (int j = 0; j < 2; j++) {
            bl_vec3 q = m->dim == 3 ? (i < n ? s->p3[i] : mean)
                                    : (i < n ? bl_v3(s->p[i].x, s->p[i].y, 0.0) : bl_v3(mid.x, mid.y, 0.0));
            double d = depth_at(blk[j], m->dim, q);
            if (i < n && d < -tol) {
                /* outside the block: across the joint (a gap) is allowed,
                 * along it (past the block's edge, a capacity it does not
                 * have: 1.18 for a unit block rocking at 1 on a joint 0.09
                 * wider each side) is not */
                double back = fmax(depth_at(blk[j], m->dim, bl_v3_add(q, bl_v3_scale(nu, -d))),
                                   depth_at(blk[j], m->dim, bl_v3_sub(q, bl_v3_scale(nu, -d))));
                double tilt = back < -fmax(tol, 1e-3 * -d) ? tilt_at(blk[j], m->dim, q, nu) : -1.0;
                if (tilt >= 0.0 && tilt < 45.0) {
                    char deg[32];
                    snprintf(deg, sizeof deg, "%.2g", tilt);
                    return bl_error_set(err,
                                        "interface: point %d of field 'points' lies %.3g outside "
                                        "block %d, and the joint%s %s degree%s from the block's "
                                        "%s there; a declared joint must lie on the %s of both blocks",
                                        i + 1, -d, (j ? s->b : s->a) + 1,
                                        m->dim == 3 ? "'s plane tilts" : " tilts", deg,
                                        strcmp(deg, "1") == 0 ? "" : "s", m->dim == 3 ? "face" : "edge",
                                        m->dim == 3 ? "faces" : "edges");
                }
                if (tilt >= 0.0)
                    return bl_error_set(err,
                                        "interface: point %d of field 'points' lies %.3g beyond the "
                                        "%s of block %d, along the joint; a declared joint must not "
                                        "be wider than the blocks it joins",
                                        i + 1, -d, m->dim == 3 ? "faces" : "edges",
                                        (j ? s->b : s->a) + 1);
            }
            if (fabs(d) <= far) continue;
            char what[48];
            if (i < n) snprintf(what, sizeof what, "point %d of field 'points'", i + 1);
            else snprintf(what, sizeof what, "the %s of field 'points'", m->dim == 3 ? "centroid" : "middle");
            return bl_error_set(err,
                                "interface: %s lies %.3g %s block %d; a declared joint must lie "
                                "on the %s of both blocks (within %.3g, a tenth of the smaller "
                                "block's size, or the near-miss gap)",
                                what, fabs(d), d > 0 ? "inside" : "outside", (j ? s->b : s->a) + 1,
                                m->dim == 3 ? "faces" : "edges", far);
        }
    return 0;
}

/* Lists the first few items of a problem class into buf. */
static void list(char *buf, size_t size, char items[][128], int shown, int total)
{
    size_t len = strlen(buf);
    for (int i = 0; i < shown && len < size; i++) {
        snprintf(buf + len, size - len, "%s%s", i ? ", " : "", items[i]);
        len = strlen(buf);
    }
    if (total > shown && len < size) snprintf(buf + len, size - len, " and %d more", total - shown);
}

/* The 2D pair tests: a grid of cells about the mean block size, capped to
 * O(n) cells, gives the candidate pairs.  Returns 0, or -1 with err set. */
static int pairs2(bl_model *m, double tol, double gap, problems *pr, bl_error *err)
{
    int n = m->nblocks;
    double box[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY}, mean = 0.0;
    for (int i = 0; i < n; i++) {
        const double *b = m->blocks[i].box;
        box[0] = fmin(box[0], b[0]);
        box[1] = fmin(box[1], b[1]);
        box[2] = fmax(box[2], b[2]);
        box[3] = fmax(box[3], b[3]);
        mean += fmax(b[2] - b[0], b[3] - b[1]);
    }
    mean /= n;
    double W = box[2] - box[0] + 2 * gap, H = box[3] - box[1] + 2 * gap;
    double cell = fmax(mean, sqrt(W * H / (4.0 * n)));
    int nx = (int)(W / cell) + 1, ny = (int)(H / cell) + 1;
    int *range = malloc((size_t)n * 4 * sizeof *range);
    int *start = calloc((size_t)nx * ny + 1, sizeof *start);
    int *fill = NULL, *items = NULL, failed = 0;
    if (!range || !start) goto oom;
    long total = 0;
    for (int i = 0; i < n; i++) {
        const double *b = m->blocks[i].box;
        int *r = range + 4 * i;
        r[0] = (int)((b[0] - gap - box[0] + gap) / cell);
        r[1] = (int)((b[1] - gap - box[1] + gap) / cell);
        r[2] = (int)((b[2] + gap - box[0] + gap) / cell);
        r[3] = (int)((b[3] + gap - box[1] + gap) / cell);
        if (r[2] >= nx) r[2] = nx - 1;
        if (r[3] >= ny) r[3] = ny - 1;
        for (int y = r[1]; y <= r[3]; y++)
            for (int x = r[0]; x <= r[2]; x++) start[y * nx + x + 1]++;
        total += (long)(r[2] - r[0] + 1) * (r[3] - r[1] + 1);
    }
    for (int c = 0; c < nx * ny; c++) start[c + 1] += start[c];
    fill = malloc((size_t)nx * ny * sizeof *fill);
    items = malloc((size_t)(total ? total : 1) * sizeof *items);
    if (!fill || !items) goto oom;
    memcpy(fill, start, (size_t)nx * ny * sizeof *fill);
    for (int i = 0; i < n; i++) {
        const int *r = range + 4 * i;
        for (int y = r[1]; y <= r[3]; y++)
            for (int x = r[0]; x <= r[2]; x++) items[fill[y * nx + x]++] = i;
    }

    for (int c = 0; c < nx * ny && !failed; c++) {
        int cx = c % nx, cy = c / nx;
        for (int s = start[c]; s < start[c + 1] && !failed; s++) {
            for (int t = s + 1; t < start[c + 1] && !failed; t++) {
                int i = items[s], j = items[t];
                if (i > j) { int tmp = i; i = j; j = tmp; }
                const int *ri = range + 4 * i, *rj = range + 4 * j;
                /* visit each pair once: in the first cell the two share */
                if (cx != (ri[0] > rj[0] ? ri[0] : rj[0]) || cy != (ri[1] > rj[1] ? ri[1] : rj[1]))
                    continue;
                const bl_block *A = &m->blocks[i], *B = &m->blocks[j];
                if (A->support && B->support) continue;
                if (A->box[0] > B->box[2] + gap || B->box[0] > A->box[2] + gap ||
                    A->box[1] > B->box[3] + gap || B->box[1] > A->box[3] + gap)
                    continue;
                if (A->box[0] < B->box[2] - tol && B->box[0] < A->box[2] - tol &&
                    A->box[1] < B->box[3] - tol && B->box[1] < A->box[3] - tol &&
                    overlapping(A, B, tol)) {
                    if (pr->noverlap < 5)
                        snprintf(pr->overlap[pr->noverlap], sizeof pr->overlap[0],
                                 "blocks %d and %d", i + 1, j + 1);
                    pr->noverlap++;
                    continue;
                }
                pair_contacts(m, i, j, tol, gap, pr, &failed, err);
            }
        }
    }
    free(range);
    free(start);
    free(fill);
    free(items);
    return failed ? -1 : 0;
oom:
    free(range);
    free(start);
    free(fill);
    free(items);
    return bl_error_set(err, "contacts: out of memory");
}

/* Writes "contacts: <what>s 3, 7 and N more" into msg, naming the blocks
 * i with mark[i] set (up to eight, "<what>" alone for one).  Returns how
 * many are marked; msg is left alone when none is. */
static int name_blocks(char *msg, size_t size, const char *what, const char *mark, int n)
{
    int total = 0, shown = 0;
    for (int i = 0; i < n; i++) total += mark[i] != 0;
    if (!total) return 0;
    size_t len = (size_t)snprintf(msg, size, "contacts: %s%s", what, total > 1 ? "s" : "");
    for (int i = 0; i < n && shown < 8 && len < size; i++)
        if (mark[i]) len += (size_t)snprintf(msg + len, size - len, "%s %d", shown++ ? "," : "", i + 1);
    if (total > shown && len < size) snprintf(msg + len, size - len, " and %d more", total - shown);
    return total;
}

/* The root of block i's group of blocks joined by interfaces. */
static int root(int *parent, int i)
{
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

/* Free blocks that no chain of interfaces joins to a support (a pair of
 * blocks on each other in the air, or a model without supports) have no
 * equilibrium under any load that is not balanced by itself: named in msg,
 * which stays empty when there are none.  Returns -1 out of memory. */
static int floating(const bl_model *m, char *msg, size_t size)
{
    int n = m->nblocks, *parent = malloc((size_t)n * sizeof *parent);
    char *grounded = calloc((size_t)n, 1), *air = calloc((size_t)n, 1);
    if (!parent || !grounded || !air) {
        free(parent), free(grounded), free(air);
        return -1;
    }
    for (int i = 0; i < n; i++) parent[i] = i;
    for (int k = 0; k < m->ninterfaces; k++)
        parent[root(parent, m->interfaces[k].a)] = root(parent, m->interfaces[k].b);
    int supports = 0;
    for (int i = 0; i < n; i++)
        if (m->blocks[i].support) grounded[root(parent, i)] = 1, supports++;
    for (int i = 0; i < n; i++) air[i] = !m->blocks[i].support && !grounded[root(parent, i)];
    int total = name_blocks(msg, size, "free block", air, n);
    size_t len = strlen(msg);
    if (total && len < size)
        snprintf(msg + len, size - len, " %s on no support, directly or through other blocks%s",
                 total > 1 ? "rest" : "rests",
                 supports ? "" : " (the model has none: make one with block{ ..., support = true })");
    free(parent), free(grounded), free(air);
    return 0;
}

int bl_contact_detect(bl_model *m, bl_error *err)
{
    double tol, gap;
    bl_contact_tolerances(m, &tol, &gap);
    bl_model_clear_interfaces(m);
    m->contacts_valid = 0;
    int n = m->nblocks;
    if (n == 0) return bl_error_set(err, "contacts: the model has no blocks");

    problems pr = {0};
    if (m->dim == 3 ? bl_contact_pairs3(m, tol, gap, &pr, err) : pairs2(m, tol, gap, &pr, err))
        goto fail;

    char msg[sizeof err->msg] = "";
    if (pr.noverlap) {
        snprintf(msg, sizeof msg, "contacts: overlapping ");
        list(msg, sizeof msg, pr.overlap, pr.noverlap < 5 ? pr.noverlap : 5,
             pr.noverlap);
    }
    if (pr.nnear) {
        size_t len = strlen(msg);
        snprintf(msg + len, sizeof msg - len, "%snear-miss (%s %.3g apart or less, "
                 "neither touching within tol = %.3g): ", len ? "; " : "contacts: ",
                 m->dim == 3 ? "faces" : "edges", gap, tol);
        list(msg, sizeof msg, pr.near, pr.nnear < 5 ? pr.nnear : 5, pr.nnear);
    }
    /* blocks from a rounded file: the rounding may be the cause, and a
     * larger tol the cure (the default stops at 1e-3 of a typical block) */
    double resolution = coarsest(m);
    if ((pr.noverlap || pr.nnear) && resolution > 0.0 && m->contact_tol <= 0.0) {
        size_t len = strlen(msg);
        snprintf(msg + len, sizeof msg - len, " (imported blocks are drawn to %.3g, the file's rounding or their "
                 "arcs' chords: if that is the cause, contacts{ tol = %.3g } takes edges that close as touching)",
                 resolution, 2.0 * resolution);
    }
    for (int s = 0; s < m->njoints && !msg[0]; s++)
        if (apply_joint(m, &m->joints[s], err)) {
            /* an interface{} given before, which these contacts do not
             * have (another tol): say so, with its own message */
            if (err) {
                char own[sizeof err->msg];
                snprintf(own, sizeof own, "%s", err->msg);
                bl_error_set(err, "contacts: the interface{ %d, %d, ... } given before does not apply "
                                  "to the contacts found with tol = %g: %s",
                             m->joints[s].a + 1, m->joints[s].b + 1, tol, own);
            }
            goto fail;
        }
    if (!msg[0]) {
        char *touched = calloc((size_t)n, 1);
        if (!touched) goto oom;
        for (int k = 0; k < m->ninterfaces; k++)
            touched[m->interfaces[k].a] = touched[m->interfaces[k].b] = 1;
        for (int i = 0; i < n; i++) touched[i] = !touched[i] && !m->blocks[i].support; /* lonely */
        name_blocks(msg, sizeof msg, "no interface on free block", touched, n);
        free(touched);
    }
    if (!msg[0] && floating(m, msg, sizeof msg)) goto oom;
    if (msg[0]) {
        bl_error_set(err, "%s", msg);
        goto fail;
    }
    m->contacts_valid = 1;
    return 0;
oom:
    bl_error_set(err, "contacts: out of memory");
fail:
    bl_model_clear_interfaces(m);
    return -1;
}
