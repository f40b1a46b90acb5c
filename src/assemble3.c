/* assemble3.c - the equilibrium system of a 3D model (assemble.h), vertex
 * model: a force at every vertex of every contact polygon, within a
 * pyramid of k facets that approximates Coulomb's cone (doc/theory.md,
 * 3D statics). */
#include "assemble.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Unit force directions (n, t2, t3 components) of the columns at a contact
 * point with friction mu: the pyramid's k edges, inscribed in the cone (on
 * it) or circumscribed (its facets touching it, a facet centred on t2);
 * the normal alone without friction; the normal and two free shears when
 * joints cannot slide.  Returns the number of columns. */
static int point_columns(double mu, const bl_cone *cone, int point, double nt[][3],
                         bl_column_kind *kind)
{
    if (isinf(mu)) {
        double d[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        memcpy(nt, d, sizeof d);
        kind[0] = BL_COL_NORMAL;
        kind[1] = kind[2] = BL_COL_SHEAR;
        return 3;
    }
    if (mu == 0.0) {
        nt[0][0] = 1, nt[0][1] = nt[0][2] = 0;
        kind[0] = BL_COL_NORMAL;
        return 1;
    }
    int k = cone->facets, added = cone->extra_n ? cone->extra_n[point] : 0;
    double r = cone->circumscribed ? mu / cos(M_PI / k) : mu;
    double shift = cone->circumscribed ? M_PI / k : 0.0;
    for (int e = 0; e < k + added; e++) {
        double th = e < k ? 2.0 * M_PI * e / k + shift : cone->extra[point * cone->nextra + e - k];
        nt[e][0] = 1.0;
        nt[e][1] = r * cos(th);
        nt[e][2] = r * sin(th);
        kind[e] = BL_COL_PYRAMID;
    }
    return k + added;
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

bl_system *bl_system_build3(const bl_model *m, const bl_cone *cone, bl_error *err)
{
    bl_system *s = calloc(1, sizeof *s);
    if (!s) goto oom;
    s->dim = 3;
    s->form = BL_FRICTION_CONE;
    int nb = m->nblocks, nfree = 0;
    double wsum = 0.0, lsum = 0.0;
    s->block_row = malloc((size_t)(nb ? nb : 1) * sizeof *s->block_row);
    if (!s->block_row) goto oom;
    for (int i = 0; i < nb; i++) {
        const bl_block *b = &m->blocks[i];
        s->block_row[i] = b->support ? -1 : 6 * nfree++;
        if (!b->support) wsum += b->weight;
        lsum += cbrt(b->volume);
    }
    if (nfree == 0) {
        bl_system_free(s);
        bl_error_set(err, "solve: the model has no free block");
        return NULL;
    }
    s->W0 = wsum / nfree;
    s->L0 = lsum / nb;
    s->nrows = 6 * nfree;

    double nt[128][3];
    bl_column_kind kind[128];
    int nforce = 0, npoints = 0;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        if (in->cohesion > 0.0) {
            bl_system_free(s);
            bl_error_set(err, "solve: cohesion is not built for 3D models yet (interface of "
                              "blocks %d and %d)", in->a + 1, in->b + 1);
            return NULL;
        }
        for (int q = 0; q < in->np; q++, npoints++)
            nforce += point_columns(in->mu, cone, npoints, nt, kind);
    }
    s->nforce = nforce;
    s->ncols = nforce + 1;
    s->npoints = npoints;
    size_t nc = (size_t)s->ncols, nnz_max = 12 * (size_t)nforce + (size_t)s->nrows;
    s->colptr = malloc((nc + 1) * sizeof *s->colptr);
    s->rowind = malloc(nnz_max * sizeof *s->rowind);
    s->val = malloc(nnz_max * sizeof *s->val);
    s->lo = malloc(nc * sizeof *s->lo);
    s->hi = malloc(nc * sizeof *s->hi);
    s->obj = calloc(nc, sizeof *s->obj);
    s->rhs = calloc((size_t)s->nrows, sizeof *s->rhs);
    s->col_point = malloc(nc * sizeof *s->col_point);
    s->col_kind = malloc(nc * sizeof *s->col_kind);
    s->col_nt = malloc(3 * nc * sizeof *s->col_nt);
    s->cohesion = calloc((size_t)npoints + 1, sizeof *s->cohesion);
    s->mu = calloc((size_t)npoints + 1, sizeof *s->mu);
    double *fL = calloc((size_t)s->nrows, sizeof *fL);
    if (!s->cohesion || !s->mu || !s->colptr || !s->rowind || !s->val || !s->lo || !s->hi ||
        !s->obj || !s->rhs || !s->col_point || !s->col_kind || !s->col_nt || !fL) {
        free(fL);
        goto oom;
    }

    int c = 0, nz = 0, point = 0;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        for (int q = 0; q < in->np; q++, point++) {
            int ncol = point_columns(in->mu, cone, point, nt, kind);
            s->mu[point] = in->mu;
            for (int e = 0; e < ncol; e++, c++) {
                bl_vec3 f = bl_v3_add(bl_v3_scale(in->n3, nt[e][0]),
                                      bl_v3_add(bl_v3_scale(in->t2, nt[e][1]),
                                                bl_v3_scale(in->t3, nt[e][2])));
                s->colptr[c] = nz;
                s->lo[c] = kind[e] == BL_COL_SHEAR ? -INFINITY : 0.0;
                s->hi[c] = INFINITY;
                s->col_point[c] = point;
                s->col_kind[c] = (signed char)kind[e];
                memcpy(s->col_nt + 3 * c, nt[e], sizeof nt[e]);
                /* f acts on b, -f on a: rows force x, y, z, moment x, y, z */
                int blk[2] = {in->a, in->b};
                for (int side = 0; side < 2; side++) {
                    int r = s->block_row[blk[side]];
                    if (r < 0) continue;
                    double sg = side ? 1.0 : -1.0;
                    bl_vec3 arm = bl_v3_scale(bl_v3_sub(in->poly[q], m->blocks[blk[side]].centroid3),
                                              1.0 / s->L0);
                    bl_vec3 mo = moment(arm, f);
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
     * load at the centroids; point forces with their moments, and couples */
    bl_vec3 g = m->gravity3, d = m->live_dir3;
    for (int i = 0; i < nb; i++) {
        int r = s->block_row[i];
        if (r < 0) continue;
        double w = m->blocks[i].weight / s->W0;
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
        bl_vec3 f = bl_v3_scale(pl->force3, 1.0 / s->W0);
        bl_vec3 arm = bl_v3_scale(bl_v3_sub(pl->at3, m->blocks[pl->block].centroid3), 1.0 / s->L0);
        bl_vec3 mo = bl_v3_add(moment(arm, f), bl_v3_scale(pl->moment3, 1.0 / (s->W0 * s->L0)));
        double v[6] = {f.x, f.y, f.z, mo.x, mo.y, mo.z};
        double *dst = pl->live ? fL : s->rhs, sg = pl->live ? 1.0 : -1.0;
        for (int i = 0; i < 6; i++) dst[r + i] += sg * v[i];
    }
    s->colptr[c] = nz;
    s->lo[c] = -INFINITY;
    s->hi[c] = INFINITY;
    s->obj[c] = 1.0;
    s->col_point[c] = -1;
    s->col_kind[c] = -1;
    s->col_nt[3 * c] = s->col_nt[3 * c + 1] = s->col_nt[3 * c + 2] = 0.0;
    for (int r = 0; r < s->nrows; r++)
        if (fL[r] != 0.0) {
            s->rowind[nz] = r;
            s->val[nz++] = fL[r];
        }
    s->colptr[c + 1] = nz;
    free(fL);
    if (nz == s->colptr[c]) {
        bl_system_free(s);
        bl_error_set(err, "solve: the model has no live load; set one with "
                          "load{ live = \"horizontal\" } or a live point load");
        return NULL;
    }
    return s;
oom:
    bl_system_free(s);
    bl_error_set(err, "solve: out of memory assembling the equilibrium system");
    return NULL;
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
            ui[c] = r < 0 ? 0.0 : y[r + c] / (c < 3 ? s->W0 : s->W0 * s->L0);
    }
}

void bl_system_slip3(const bl_system *s, const bl_model *m, const double *y, double *slip)
{
    int point = 0;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        for (int q = 0; q < in->np; q++, point++) {
            /* velocity of each side at the point: v + w x (p - g) / L0 (the
             * moment rows were scaled by 1/L0) */
            bl_vec3 d = {0, 0, 0};
            int blk[2] = {in->a, in->b};
            for (int side = 0; side < 2; side++) {
                int r = s->block_row[blk[side]];
                if (r < 0) continue;
                bl_vec3 arm = bl_v3_scale(bl_v3_sub(in->poly[q], m->blocks[blk[side]].centroid3),
                                          1.0 / s->L0);
                bl_vec3 v = bl_v3_add(bl_v3(y[r], y[r + 1], y[r + 2]),
                                      bl_v3_cross(bl_v3(y[r + 3], y[r + 4], y[r + 5]), arm));
                d = side ? bl_v3_add(d, v) : bl_v3_sub(d, v);
            }
            slip[2 * point] = bl_v3_dot(d, in->t2);
            slip[2 * point + 1] = bl_v3_dot(d, in->t3);
        }
    }
}
