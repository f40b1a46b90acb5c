/* assemble3.c - the equilibrium system of a 3D model (assemble.h): a
 * force at every vertex of every contact polygon, within a pyramid of k
 * facets that approximates Coulomb's cone (the vertex model), or normal
 * forces at the vertices with the shear and the torsion of the joint as a
 * whole (the resultant model) (doc/theory.md, 3D statics). */
#include "assemble.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The columns at a contact point with friction mu: unit force directions
 * (n, t2, t3 components) and, in the resultant model, a torsion couple
 * (in units of mu_t times the normal force, about the normal): the
 * pyramid's k edges (plus the adaptive cone's added ones), inscribed in the
 * cone (on it) or circumscribed (its facets touching it, a facet centred on
 * t2); in the resultant model each edge twice, with the couple +1 and -1;
 * the normal alone without friction; when joints cannot slide, the normal
 * at every point, and two free shears and a free couple about the normal
 * (none where the joint has one point) at its first: free shears at every
 * point would leave all but the joint's resultant and twist unbounded in
 * every LP (the simplex called a dome of 128 blocks infeasible, 2D arches
 * stopped the interior point, doc/theory.md 2).  Returns the number of
 * columns. */
static int point_columns(double mu, const bl_cone *cone, int point, int resultant, int first,
                         int np, double nt[][3], double *couple, bl_column_kind *kind)
{
    int n = 0;
    if (isinf(mu)) {
        double d[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        int shears = first ? 2 : 0;
        for (int i = 0; i <= shears; i++, n++) {
            memcpy(nt[n], d[i], sizeof d[i]);
            couple[n] = 0.0;
            kind[n] = i ? BL_COL_SHEAR : BL_COL_NORMAL;
        }
        if (first && (resultant || np > 1)) {
            nt[n][0] = nt[n][1] = nt[n][2] = 0.0;
            couple[n] = 1.0;
            kind[n++] = BL_COL_SHEAR;
        }
        return n;
    }
    if (mu == 0.0) {
        nt[0][0] = 1, nt[0][1] = nt[0][2] = 0;
        couple[0] = 0.0;
        kind[0] = BL_COL_NORMAL;
        return 1;
    }
    int k = cone->facets, added = cone->extra_n ? cone->extra_n[point] : 0;
    double r = cone->circumscribed ? mu / cos(M_PI / k) : mu;
    double shift = cone->circumscribed ? M_PI / k : 0.0;
    for (int e = 0; e < k + added; e++) {
        double th = e < k ? 2.0 * M_PI * e / k + shift : cone->extra[point * cone->nextra + e - k];
        for (int rep = 0; rep < (resultant ? 2 : 1); rep++, n++) {
            /* an edge along t2 or t3 has an exact zero: a cos(pi/2) of
             * 6e-17 left in made CLP's scaling call a feasible
             * certificate infeasible */
            double ct = cos(th), st = sin(th);
            nt[n][0] = 1.0;
            nt[n][1] = fabs(ct) < 1e-15 ? 0.0 : r * ct;
            nt[n][2] = fabs(st) < 1e-15 ? 0.0 : r * st;
            couple[n] = resultant ? (rep ? 1.0 : -1.0) : 0.0;
            kind[n] = BL_COL_PYRAMID;
        }
    }
    return n;
}

/* The cohesion columns at a contact point: a tangential force within the
 * polygon of the pyramid's shape (its n-section) of "radius" C added to
 * the pyramid, so that the point's yield set is |t| <= mu n + C with both
 * disks approximated alike.  The polygon, centrally symmetric, is the sum
 * of m segments: m = k/2 for a pyramid of k facets (k even), m = k for an
 * odd k (a 2k-gon).  Inscribed (corners on the disk, one on t2): segments
 * along the sides, psi_j = pi/2 + pi/(2m) + j pi/m, of half-length
 * C sin(pi/(2m)); circumscribed (sides touching it, one across t2): along
 * pi/2 + j pi/m, half length C tan(pi/(2m)).  For even m the quarter turn
 * gives the same directions and is left out (their order kept); for odd m
 * it is what puts the corners where the pyramid's edges are (without it a
 * 6-facet hexagon was turned 30 degrees from the pyramid's, and no box
 * sliding on it certified).  Returns m. */
static int cohesion_columns(const bl_cone *cone, double nt[][3], double *couple,
                            bl_column_kind *kind, double *bound, double C)
{
    int k = cone->facets, m = k % 2 ? k : k / 2;
    double half = M_PI / (2.0 * m);
    double shift = (cone->circumscribed ? 0.0 : half) + (m % 2 ? M_PI / 2.0 : 0.0);
    double a = cone->circumscribed ? C * tan(half) : C * sin(half);
    for (int j = 0; j < m; j++) {
        double psi = shift + j * M_PI / m, c = cos(psi), s = sin(psi);
        nt[j][0] = 0.0;
        nt[j][1] = fabs(c) < 1e-15 ? 0.0 : c;
        nt[j][2] = fabs(s) < 1e-15 ? 0.0 : s;
        couple[j] = 0.0;
        kind[j] = BL_COL_COHESION;
        bound[j] = a;
    }
    return m;
}

/* The fixed form's columns at a point that can slide: the normal, and the
 * shears whose sum, each bounded by +-R = mu n + C (bl_system_fixed_bounds),
 * is the pyramid's section at n: the segments of cohesion_columns, scaled
 * by their half-lengths for C = 1 (for the default 8 facets inscribed, an
 * octagon with corners on +-t2, +-t3 and the diagonals; for 4 facets
 * circumscribed, the square |t2|, |t3| <= R).  The pyramid must have an
 * even number of facets (a centrally symmetric section).  In the resultant
 * model the shears come once per joint, with its first vertex (and act at
 * the centroid), bounded by mu N + C, and so does a twist column, a couple
 * of rho (the torsion lever) per unit within +-((mu_t / rho) N + C): the
 * section of the cone form's prism, the pyramid's section times
 * |M| <= mu_t N + C rho.  Returns the number of columns. */
static int fixed_columns(const bl_cone *cone, int resultant, int first, double nt[][3],
                         double *couple, bl_column_kind *kind)
{
    double half[64];
    nt[0][0] = 1.0;
    nt[0][1] = nt[0][2] = 0.0;
    couple[0] = 0.0;
    kind[0] = BL_COL_NORMAL;
    if (resultant && !first) return 1;
    int m = cohesion_columns(cone, nt + 1, couple + 1, kind + 1, half, 1.0);
    for (int j = 1; j <= m; j++) {
        nt[j][1] *= half[j - 1];
        nt[j][2] *= half[j - 1];
        kind[j] = BL_COL_SHEAR;
    }
    if (!resultant) return m + 1;
    nt[m + 1][0] = nt[m + 1][1] = nt[m + 1][2] = 0.0;
    couple[m + 1] = 1.0;
    kind[m + 1] = BL_COL_TWIST;
    return m + 2;
}

/* The cohesion of a joint in the resultant model, with its first vertex:
 * the polygon of cohesion_columns of "radius" C = c A at the centroid, and
 * a couple about the normal of rho (the torsion lever) per unit within
 * +-C, the torsion c A rho of a uniform shear stress c.  Returns the
 * number of columns. */
static int joint_cohesion_columns(const bl_cone *cone, double nt[][3], double *couple,
                                  bl_column_kind *kind, double *bound, double C)
{
    int m = cohesion_columns(cone, nt, couple, kind, bound, C);
    nt[m][0] = nt[m][1] = nt[m][2] = 0.0;
    couple[m] = 1.0;
    kind[m] = BL_COL_COHESION;
    bound[m] = C;
    return m + 1;
}

/* The torsion lever of a convex contact polygon: the mean distance of its
 * area from its centroid c, (1/A) integral |r - c| dA; times mu it is the
 * torsion capacity per unit normal force of a uniform pressure sliding
 * about c.  Exact, by polar integration over the triangles (c, u, v) of its
 * edges: with h the distance from c to the edge's line and t the position
 * along it over h, integral |r| dA = h^3 / 6 [G(t_v) - G(t_u)],
 * G(t) = t sqrt(1 + t^2) + asinh t. */
static double torsion_lever(const bl_interface *in, bl_vec3 *centroid)
{
    bl_vec3 c = {0, 0, 0};
    double area = 0.0;
    for (int i = 1; i + 1 < in->np; i++) {
        bl_vec3 a = in->poly[0], b = in->poly[i], d = in->poly[i + 1];
        double t = 0.5 * bl_v3_norm(bl_v3_cross(bl_v3_sub(b, a), bl_v3_sub(d, a)));
        area += t;
        c = bl_v3_add(c, bl_v3_scale(bl_v3_add(a, bl_v3_add(b, d)), t / 3.0));
    }
    c = bl_v3_scale(c, 1.0 / area);
    *centroid = c;
    double sum = 0.0;
    for (int i = 0; i < in->np; i++) {
        bl_vec3 u = bl_v3_sub(in->poly[i], c), v = bl_v3_sub(in->poly[(i + 1) % in->np], c);
        bl_vec3 e = bl_v3_sub(v, u);
        double len = bl_v3_norm(e);
        if (!(len > 0.0)) continue;
        e = bl_v3_scale(e, 1.0 / len);
        double su = bl_v3_dot(u, e), sv = bl_v3_dot(v, e);
        double h = bl_v3_norm(bl_v3_sub(u, bl_v3_scale(e, su)));
        if (!(h > 0.0)) continue;
        double tu = su / h, tv = sv / h;
        sum += h * h * h / 6.0 * ((tv * sqrt(1 + tv * tv) + asinh(tv)) - (tu * sqrt(1 + tu * tu) + asinh(tu)));
    }
    return sum / area;
}

/* A resultant joint's torsion coefficient: its own mu_t, else mu times
 * its torsion lever (no friction, none). */
static double joint_mu_t(const bl_interface *in, double lever)
{
    return in->mu_t > 0.0 ? in->mu_t : (isfinite(in->mu) ? in->mu : 0.0) * lever;
}

double bl_interface_torsion(const bl_interface *in)
{
    bl_vec3 c;
    return isinf(in->mu) ? INFINITY : joint_mu_t(in, torsion_lever(in, &c));
}

/* a x b, with the components below their own round-off set to zero (as in
 * 2D: a force through the centroid must have no moment at all). */
static bl_vec3 moment(bl_vec3 a, bl_vec3 b)
{
    bl_vec3 c = bl_v3_cross(a, b);
    double e = 8.0 * DBL_EPSILON;
    if (fabs(c.x) <= e * (fabs(a.y * b.z) + fabs(a.z * b.y))) c.x = 0.0;
    if (fabs(c.y) <= e * (fabs(a.z * b.x) + fabs(a.x * b.z))) c.y = 0.0;
    if (fabs(c.z) <= e * (fabs(a.x * b.y) + fabs(a.y * b.x))) c.z = 0.0;
    return c;
}

bl_system *bl_system_build3(const bl_model *m, const bl_cone *cone, bl_friction_form form,
                            bl_error *err)
{
    bl_system *s = bl_system_start(m, 6, err);
    if (!s) return NULL;
    s->form = form;
    double nt[256][3], couple[256], bound[256];
    bl_column_kind kind[256];
    int nforce = 0, npoints = 0;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        int resultant = in->imodel == BL_RESULTANT;
        double mu = form == BL_FRICTION_FIXED ? INFINITY : in->mu;
        int capped = form == BL_FRICTION_FIXED && isfinite(in->mu);
        int cohesive = in->cohesion > 0.0 && isfinite(mu);
        for (int q = 0; q < in->np; q++, npoints++)
            nforce += capped ? fixed_columns(cone, resultant, q == 0, nt, couple, kind)
                             : point_columns(mu, cone, npoints, resultant, q == 0, in->np, nt, couple, kind) +
                                   (cohesive && (!resultant || q == 0)
                                        ? (cone->facets % 2 ? cone->facets : cone->facets / 2) + resultant
                                        : 0);
    }
    double *fL = calloc((size_t)s->nrows, sizeof *fL);
    if (!fL || bl_system_allocate(s, m, nforce, npoints, 12 * (size_t)nforce + (size_t)s->nrows + 6)) {
        free(fL);
        goto oom;
    }

    int nb = m->nblocks, c = 0, nz = 0, point = 0;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        /* resultant model: shear at the polygon's centroid, torsion couples
         * of mu_t per unit normal force (mu times the torsion lever unless
         * the joint sets mu_t) */
        int resultant = in->imodel == BL_RESULTANT;
        bl_vec3 cen = in->poly[0];
        double mut = 0.0, lever = 0.0;
        if (resultant) {
            lever = torsion_lever(in, &cen);
            mut = joint_mu_t(in, lever);
        }
        /* the fixed form: a normal and the pyramid section's shears at
         * every point that can slide, a normal and two free shears where
         * it cannot */
        double mu = form == BL_FRICTION_FIXED ? INFINITY : in->mu;
        int capped = form == BL_FRICTION_FIXED && isfinite(in->mu);
        /* cohesion: an equal share of the joint's area at every vertex, or
         * in the resultant model the whole joint's with its first vertex */
        double CA = isfinite(in->mu) ? in->cohesion * in->area3 / s->W0 : 0.0;
        for (int q = 0; q < in->np; q++, point++) {
            int ncol = capped ? fixed_columns(cone, resultant, q == 0, nt, couple, kind)
                              : point_columns(mu, cone, point, resultant, q == 0, in->np, nt, couple, kind);
            for (int e = 0; e < ncol; e++) bound[e] = INFINITY;
            double C = resultant ? (q == 0 ? CA : 0.0) : CA / in->np;
            if (C > 0.0 && isfinite(mu))
                ncol += resultant ? joint_cohesion_columns(cone, nt + ncol, couple + ncol, kind + ncol,
                                                           bound + ncol, C)
                                  : cohesion_columns(cone, nt + ncol, couple + ncol, kind + ncol,
                                                     bound + ncol, C);
            s->mu[point] = in->mu;
            s->cohesion[point] = C;
            if (resultant) {
                s->lead[point] = point - q;
                s->twist[point] = q == 0 ? mut / lever : 0.0;
            }
            for (int e = 0; e < ncol; e++, c++) {
                bl_vec3 fn = bl_v3_scale(in->n3, nt[e][0]);
                bl_vec3 ft = bl_v3_add(bl_v3_scale(in->t2, nt[e][1]), bl_v3_scale(in->t3, nt[e][2]));
                bl_vec3 f = bl_v3_add(fn, ft);
                /* a free couple (rigid joints) has no force; a pyramid edge's
                 * couple is mu_t per unit of its normal force, a twist
                 * column's, and a joint's cohesive couple, rho per unit */
                double len = kind[e] == BL_COL_SHEAR ? 1.0 : kind[e] == BL_COL_PYRAMID ? mut : lever;
                bl_vec3 tw = bl_v3_scale(in->n3, couple[e] * len);
                int bounded = capped && (kind[e] == BL_COL_SHEAR || kind[e] == BL_COL_TWIST);
                s->colptr[c] = nz;
                s->lo[c] = kind[e] == BL_COL_SHEAR && !capped ? -INFINITY : 0.0;
                s->hi[c] = bounded ? 0.0 : INFINITY; /* bl_system_fixed_bounds */
                if (kind[e] == BL_COL_COHESION) {
                    s->lo[c] = -bound[e];
                    s->hi[c] = bound[e];
                }
                s->col_point[c] = point;
                s->col_kind[c] = (signed char)kind[e];
                memcpy(s->col_nt + 3 * c, nt[e], sizeof nt[e]);
                s->col_twist[c] = resultant ? couple[e] * len / lever : 0.0;
                /* f acts on b, -f on a: rows force x, y, z, moment x, y, z */
                int blk[2] = {in->a, in->b};
                for (int side = 0; side < 2; side++) {
                    int r = s->block_row[blk[side]];
                    if (r < 0) continue;
                    double sg = side ? 1.0 : -1.0;
                    bl_vec3 g = m->blocks[blk[side]].centroid3;
                    bl_vec3 arm = bl_v3_scale(bl_v3_sub(in->poly[q], g), 1.0 / s->L0);
                    bl_vec3 mo = bl_v3_add(moment(arm, f), bl_v3_scale(tw, 1.0 / s->L0));
                    if (resultant) {
                        bl_vec3 armc = bl_v3_scale(bl_v3_sub(cen, g), 1.0 / s->L0);
                        mo = bl_v3_add(bl_v3_add(moment(arm, fn), moment(armc, ft)),
                                       bl_v3_scale(tw, 1.0 / s->L0));
                    }
                    double v[6] = {f.x, f.y, f.z, mo.x, mo.y, mo.z};
                    for (int i = 0; i < 6; i++)
                        if (v[i] != 0.0) {
                            s->rowind[nz] = r + i;
                            s->val[nz++] = sg * v[i];
                        }
                }
            }
        }
    }

    /* self weight (dead, along gravity) and the weight-proportional live
     * load at the centroids; point forces with their moments, and couples
     * (a carried weight in both, at its point) */
    bl_vec3 g = bl_model_gravity3(m), d = m->live_dir3;
    for (int i = 0; i < nb; i++) {
        int r = s->block_row[i];
        if (r < 0) continue;
        double w = bl_system_weight(s, &m->blocks[i]);
        if (m->self_weight) {
            s->rhs[r] -= w * g.x;
            s->rhs[r + 1] -= w * g.y;
            s->rhs[r + 2] -= w * g.z;
        }
        if (m->live_weight) {
            fL[r] += w * d.x;
            fL[r + 1] += w * d.y;
            fL[r + 2] += w * d.z;
        }
    }
    for (int l = 0; l < m->nloads; l++) {
        const bl_point_load *pl = &m->loads[l];
        int r = s->block_row[pl->block];
        if (r < 0) continue;
        bl_vec3 arm = bl_v3_scale(bl_v3_sub(pl->at3, m->blocks[pl->block].centroid3), 1.0 / s->L0);
        bl_vec3 fd, fl, c = bl_v3_scale(pl->moment3, 1.0 / (s->W0 * s->L0)), zero = bl_v3(0.0, 0.0, 0.0);
        bl_point_load_forces3(m, pl, &fd, &fl);
        fd = bl_v3_scale(fd, 1.0 / s->W0);
        fl = bl_v3_scale(fl, 1.0 / s->W0);
        bl_vec3 md = bl_v3_add(moment(arm, fd), pl->live ? zero : c);
        bl_vec3 ml = bl_v3_add(moment(arm, fl), pl->live ? c : zero);
        double d6[6] = {fd.x, fd.y, fd.z, md.x, md.y, md.z}, l6[6] = {fl.x, fl.y, fl.z, ml.x, ml.y, ml.z};
        for (int i = 0; i < 6; i++) {
            s->rhs[r + i] -= d6[i];
            fL[r + i] += l6[i];
        }
    }
    s = bl_system_finish(s, nz, fL, err);
    free(fL);
    return s;
oom:
    bl_system_free(s);
    bl_error_set(err, "solve: out of memory assembling the equilibrium system");
    return NULL;
}

void bl_system_tangent3(const bl_system *s, const double *w, double *dt, double *dt3)
{
    double *G = calloc(5 * (size_t)s->npoints + 1, sizeof *G); /* g11 g12 g22 h1 h2 */
    if (!G) return;
    for (int j = 0; j < s->nforce; j++) {
        if (s->col_kind[j] != BL_COL_SHEAR) continue;
        double *g = G + 5 * s->col_point[j], a = s->col_nt[3 * j + 1], b = s->col_nt[3 * j + 2];
        g[0] += a * a;
        g[1] += a * b;
        g[2] += b * b;
        g[3] += a * w[j];
        g[4] += b * w[j];
    }
    for (int p = 0; p < s->npoints; p++) {
        const double *g = G + 5 * p;
        double det = g[0] * g[2] - g[1] * g[1];
        dt[p] = det > 0.0 ? (g[2] * g[3] - g[1] * g[4]) / det : 0.0;
        dt3[p] = det > 0.0 ? (g[0] * g[4] - g[1] * g[3]) / det : 0.0;
    }
    free(G);
}

void bl_system_forces3(const bl_system *s, const double *x, double *force)
{
    memset(force, 0, 3 * (size_t)s->npoints * sizeof *force);
    for (int j = 0; j < s->nforce; j++)
        for (int c = 0; c < 3; c++)
            force[3 * s->col_point[j] + c] += s->W0 * x[j] * s->col_nt[3 * j + c];
}

void bl_system_mechanism3(const bl_system *s, const bl_model *m, const double *y, double *u)
{
    for (int i = 0; i < m->nblocks; i++) {
        int r = s->block_row[i];
        double *ui = u + 6 * i;
        for (int c = 0; c < 6; c++)
            ui[c] = r < 0 ? 0.0 : bl_system_velocity(s, y, r + c) / (c < 3 ? s->W0 : s->W0 * s->L0);
    }
}

void bl_system_slip3(const bl_system *s, const bl_model *m, const double *y, double *slip)
{
    int point = 0;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        /* the resultant model's friction acts at the centroid: its slip there */
        bl_vec3 cen = in->poly[0];
        if (in->imodel == BL_RESULTANT) torsion_lever(in, &cen);
        for (int q = 0; q < in->np; q++, point++) {
            bl_vec3 at = in->imodel == BL_RESULTANT ? cen : in->poly[q];
            /* velocity of each side at the point: v + w x (p - g) / L0 (the
             * moment rows were scaled by 1/L0) */
            bl_vec3 d = {0, 0, 0};
            int blk[2] = {in->a, in->b};
            for (int side = 0; side < 2; side++) {
                int r = s->block_row[blk[side]];
                if (r < 0) continue;
                bl_vec3 arm = bl_v3_scale(bl_v3_sub(at, m->blocks[blk[side]].centroid3), 1.0 / s->L0);
                double yb[6];
                for (int c = 0; c < 6; c++) yb[c] = bl_system_velocity(s, y, r + c);
                bl_vec3 v = bl_v3_add(bl_v3(yb[0], yb[1], yb[2]),
                                      bl_v3_cross(bl_v3(yb[3], yb[4], yb[5]), arm));
                d = side ? bl_v3_add(d, v) : bl_v3_sub(d, v);
            }
            slip[2 * point] = bl_v3_dot(d, in->t2);
            slip[2 * point + 1] = bl_v3_dot(d, in->t3);
        }
    }
}
