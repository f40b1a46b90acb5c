#include "assemble.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void bl_system_free(bl_system *s)
{
    if (!s) return;
    free(s->colptr);
    free(s->rowind);
    free(s->val);
    free(s->lo);
    free(s->hi);
    free(s->rhs);
    free(s->obj);
    free(s->block_row);
    free(s->row_scale);
    free(s->col_point);
    free(s->col_kind);
    free(s->col_nt);
    free(s->col_twist);
    free(s->cohesion);
    free(s->mu);
    free(s->twist);
    free(s->lead);
    free(s->point_iface);
    free(s);
}

/* ---- for the builders (2D here, 3D in assemble3.c) -------------------- */

bl_system *bl_system_start(const bl_model *m, int per_block, bl_error *err)
{
    bl_system *s = calloc(1, sizeof *s);
    int nb = m->nblocks, nfree = 0;
    double wsum = 0.0, vsum = 0.0, lsum = 0.0;
    if (s) s->block_row = malloc((size_t)(nb ? nb : 1) * sizeof *s->block_row);
    if (!s || !s->block_row) {
        bl_system_free(s);
        bl_error_set(err, "solve: out of memory assembling the equilibrium system");
        return NULL;
    }
    s->dim = m->dim;
    s->uniform = 1;
    for (int i = 0; i < nb; i++) {
        const bl_block *b = &m->blocks[i];
        s->block_row[i] = b->support ? -1 : per_block * nfree++;
        if (!b->support) {
            double t = m->dim == 3 ? 1.0 : b->thickness;
            if (nfree == 1) s->rho0 = b->density, s->t0 = t;
            s->uniform = s->uniform && b->density == s->rho0 && t == s->t0;
            wsum += b->weight;
            vsum += m->dim == 3 ? b->volume : b->area;
        }
        lsum += m->dim == 3 ? cbrt(b->volume) : sqrt(b->area);
    }
    if (nfree == 0) {
        bl_system_free(s);
        bl_error_set(err, "solve: the model has no free block");
        return NULL;
    }
    s->V0 = vsum / nfree;
    s->W0 = s->uniform ? s->rho0 * s->V0 * s->t0 : wsum / nfree;
    s->L0 = lsum / nb;
    s->nrows = per_block * nfree;
    return s;
}

double bl_system_weight(const bl_system *s, const bl_block *b)
{
    if (!s->uniform) return b->weight / s->W0;
    return (s->dim == 3 ? b->volume : b->area) / s->V0;
}

int bl_system_allocate(bl_system *s, const bl_model *m, int nforce, int npoints, size_t nnz_max)
{
    s->nforce = nforce;
    s->ncols = nforce + 1;
    s->npoints = npoints;
    size_t nc = (size_t)s->ncols;
    s->colptr = malloc((nc + 1) * sizeof *s->colptr);
    s->rowind = malloc(nnz_max * sizeof *s->rowind);
    s->val = malloc(nnz_max * sizeof *s->val);
    s->lo = malloc(nc * sizeof *s->lo);
    s->hi = malloc(nc * sizeof *s->hi);
    s->obj = calloc(nc, sizeof *s->obj);
    s->rhs = calloc((size_t)s->nrows, sizeof *s->rhs);
    s->col_point = malloc(nc * sizeof *s->col_point);
    s->col_kind = malloc(nc * sizeof *s->col_kind);
    s->col_nt = calloc((size_t)s->dim * nc, sizeof *s->col_nt);
    s->col_twist = calloc(nc, sizeof *s->col_twist);
    s->cohesion = calloc((size_t)npoints + 1, sizeof *s->cohesion);
    s->mu = calloc((size_t)npoints + 1, sizeof *s->mu);
    s->twist = calloc((size_t)npoints + 1, sizeof *s->twist);
    s->lead = malloc(((size_t)npoints + 1) * sizeof *s->lead);
    for (int p = 0; s->lead && p < npoints; p++) s->lead[p] = p;
    s->point_iface = malloc(((size_t)npoints + 1) * sizeof *s->point_iface);
    for (int k = 0, p = 0; s->point_iface && k < m->ninterfaces; k++)
        for (int e = 0; e < (m->dim == 3 ? m->interfaces[k].np : 2); e++) s->point_iface[p++] = k;
    return s->cohesion && s->mu && s->twist && s->lead && s->point_iface && s->colptr && s->rowind && s->val && s->lo && s->hi && s->obj &&
                   s->rhs && s->col_point && s->col_kind && s->col_nt && s->col_twist
               ? 0
               : -1;
}

/* The rows of a block whose own loads (its weight, point loads, the live
 * load; fD and fL in units of W0) stay below LIGHT_LOAD are multiplied by
 * LIGHT_LOAD over them, at most LIGHT_SCALE_MAX: an LP engine's residuals
 * are relative to the largest load, and a block 10^-5 as heavy as W0 was
 * left unbalanced by its own weight within them (the interior point's
 * "numerical trouble" or a wrong alpha; doc/theory.md 3, scaling).  Its dual
 * rows, the block's velocity, are divided by the same factor
 * (bl_system_velocity undoes it).  A model without such a block is
 * assembled as before, row_scale NULL. */
#define LIGHT_LOAD 0.1
#define LIGHT_SCALE_MAX 1e8

static int scale_light_blocks(bl_system *s, double *fL)
{
    int per = s->dim == 3 ? 6 : 3;
    for (int r0 = 0; r0 < s->nrows; r0 += per) {
        double load = 0.0;
        for (int i = r0; i < r0 + per; i++) load = fmax(load, fmax(fabs(s->rhs[i]), fabs(fL[i])));
        if (!(load > 0.0) || load >= LIGHT_LOAD) continue;
        if (!s->row_scale) {
            if (!(s->row_scale = malloc((size_t)s->nrows * sizeof *s->row_scale))) return -1;
            for (int i = 0; i < s->nrows; i++) s->row_scale[i] = 1.0;
        }
        for (int i = r0; i < r0 + per; i++) s->row_scale[i] = fmin(LIGHT_LOAD / load, LIGHT_SCALE_MAX);
    }
    if (!s->row_scale) return 0;
    for (int p = 0; p < s->colptr[s->nforce]; p++) s->val[p] *= s->row_scale[s->rowind[p]];
    for (int i = 0; i < s->nrows; i++) {
        s->rhs[i] *= s->row_scale[i];
        fL[i] *= s->row_scale[i];
    }
    return 0;
}

double bl_system_velocity(const bl_system *s, const double *y, int row)
{
    return s->row_scale ? y[row] * s->row_scale[row] : y[row];
}

bl_system *bl_system_finish(bl_system *s, int nz, double *fL, bl_error *err)
{
    int c = s->nforce;
    s->colptr[c] = nz;
    if (scale_light_blocks(s, fL)) {
        bl_system_free(s);
        bl_error_set(err, "solve: out of memory assembling the equilibrium system");
        return NULL;
    }
    s->lo[c] = -INFINITY;
    s->hi[c] = INFINITY;
    s->obj[c] = 1.0;
    s->col_point[c] = -1;
    s->col_kind[c] = -1;
    for (int r = 0; r < s->nrows; r++)
        if (fL[r] != 0.0) {
            s->rowind[nz] = r;
            s->val[nz++] = fL[r];
        }
    s->colptr[c + 1] = nz;
    if (nz == s->colptr[c]) {
        bl_system_free(s);
        bl_error_set(err, "solve: the model has no live load; set one with "
                          "load{ live = \"horizontal\" } or a live point load");
        return NULL;
    }
    return s;
}

/* Columns at contact point e (0 or 1) of interface k.  A joint that
 * cannot slide has one free shear, at its first point: the shears of its
 * two points act along the same line, so that only their sum enters
 * equilibrium, and a free shear at each point leaves their difference
 * unbounded in every LP, which the interior point followed without
 * converging (an arch of 600 voussoirs at mu = inf: "numerical trouble",
 * doc/theory.md 2). */
static int point_columns(const bl_interface *k, double C, bl_friction_form form, int e,
                         bl_column_kind kind[3])
{
    int n = 0;
    if (isinf(k->mu)) {
        kind[n++] = BL_COL_NORMAL;
        if (e == 0) kind[n++] = BL_COL_SHEAR;
        return n;
    }
    if (form == BL_FRICTION_FIXED) {
        kind[n++] = BL_COL_NORMAL;
        kind[n++] = BL_COL_SHEAR;
        return n;
    }
    if (k->mu == 0.0) {
        kind[n++] = BL_COL_NORMAL;
    } else {
        kind[n++] = BL_COL_CONE_POS;
        kind[n++] = BL_COL_CONE_NEG;
    }
    if (C > 0.0) kind[n++] = BL_COL_COHESION;
    return n;
}

/* Cohesive shear capacity of one contact point: half the joint's area. */
static double cohesion_share(const bl_model *m, const bl_interface *k)
{
    double len = bl_v2_norm(bl_v2_sub(k->p[1], k->p[0]));
    double th = fmin(m->blocks[k->a].thickness, m->blocks[k->b].thickness);
    return k->cohesion * len * th / 2.0;
}

bl_system *bl_system_build(const bl_model *m, bl_friction_form form, bl_error *err)
{
    if (m->dim == 3) {
        bl_error_set(err, "solve: 3D models are solved with the associative flow only so far "
                          "(flow = \"associative\")");
        return NULL;
    }
    bl_system *s = bl_system_start(m, 3, err);
    if (!s) return NULL;
    s->form = form;
    int nforce = 0;
    bl_column_kind kind[3];
    for (int k = 0; k < m->ninterfaces; k++)
        for (int e = 0; e < 2; e++)
            nforce += point_columns(&m->interfaces[k], cohesion_share(m, &m->interfaces[k]), form,
                                    e, kind);
    double *fL = calloc((size_t)s->nrows, sizeof *fL);
    if (!fL || bl_system_allocate(s, m, nforce, 2 * m->ninterfaces,
                                  6 * (size_t)nforce + (size_t)s->nrows)) {
        free(fL);
        goto oom;
    }

    int nb = m->nblocks, c = 0, nz = 0;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        double C = cohesion_share(m, in) / s->W0;
        s->cohesion[2 * k] = s->cohesion[2 * k + 1] = C;
        s->mu[2 * k] = s->mu[2 * k + 1] = in->mu;
        bl_vec2 nu = in->normal, tau = bl_v2(-nu.y, nu.x);
        for (int e = 0; e < 2; e++) {
            int nk = point_columns(in, C, form, e, kind);
            for (int q = 0; q < nk; q++, c++) {
                double dn = 1.0, dt = 0.0, lo = 0.0, hi = INFINITY;
                switch (kind[q]) {
                case BL_COL_CONE_POS: dt = in->mu; break;
                case BL_COL_CONE_NEG: dt = -in->mu; break;
                case BL_COL_NORMAL: break;
                case BL_COL_SHEAR: /* free without sliding; else bounded by R, from C */
                    dn = 0.0;
                    dt = 1.0;
                    lo = isinf(in->mu) ? -INFINITY : -C;
                    hi = isinf(in->mu) ? INFINITY : C;
                    break;
                case BL_COL_COHESION: dn = 0.0; dt = 1.0; lo = -C; hi = C; break;
                case BL_COL_PYRAMID: /* 3D only */
                case BL_COL_TWIST: break;
                }
                bl_vec2 f = bl_v2_add(bl_v2_scale(nu, dn), bl_v2_scale(tau, dt));
                s->colptr[c] = nz;
                s->lo[c] = lo;
                s->hi[c] = hi;
                s->col_point[c] = 2 * k + e;
                s->col_kind[c] = (signed char)kind[q];
                s->col_nt[2 * c] = dn;
                s->col_nt[2 * c + 1] = dt;
                /* f acts on b; -f on a.  Rows of a block in order x, y, moment. */
                int blk[2] = {in->a, in->b};
                for (int side = 0; side < 2; side++) {
                    int r = s->block_row[blk[side]];
                    if (r < 0) continue;
                    double sg = side ? 1.0 : -1.0;
                    bl_vec2 arm = bl_v2_scale(
                        bl_v2_sub(in->p[e], m->blocks[blk[side]].centroid), 1.0 / s->L0);
                    double mom = bl_v2_cross(arm, f);
                    /* A moment below the round-off of arm x f is zero: CLP's
                     * scaling blew a 5.6e-17 up into a false "infeasible"
                     * (a block with b/h = mu, where rocking and sliding tie). */
                    double noise = 8.0 * DBL_EPSILON * (fabs(arm.x * f.y) + fabs(arm.y * f.x));
                    if (fabs(mom) <= noise) mom = 0.0;
                    s->rowind[nz] = r;     s->val[nz++] = sg * f.x;
                    s->rowind[nz] = r + 1; s->val[nz++] = sg * f.y;
                    s->rowind[nz] = r + 2; s->val[nz++] = sg * mom;
                }
            }
        }
    }

    /* Loads: self weight (dead) and weight-proportional live load at the
     * centroids, point loads with their moments (a carried weight in both,
     * at its point). */
    bl_vec2 g = bl_model_gravity(m);
    for (int i = 0; i < nb; i++) {
        int r = s->block_row[i];
        if (r < 0) continue;
        double w = bl_system_weight(s, &m->blocks[i]);
        if (m->self_weight) {
            s->rhs[r] -= w * g.x;
            s->rhs[r + 1] -= w * g.y;
        }
        if (m->live_weight) {
            fL[r] += w * m->live_dir.x;
            fL[r + 1] += w * m->live_dir.y;
        }
    }
    for (int l = 0; l < m->nloads; l++) {
        const bl_point_load *pl = &m->loads[l];
        int r = s->block_row[pl->block];
        if (r < 0) continue;
        bl_vec2 arm = bl_v2_scale(bl_v2_sub(pl->at, m->blocks[pl->block].centroid), 1.0 / s->L0);
        bl_vec2 fd, fl;
        bl_point_load_forces(m, pl, &fd, &fl);
        fd = bl_v2_scale(fd, 1.0 / s->W0);
        fl = bl_v2_scale(fl, 1.0 / s->W0);
        double c = pl->moment / (s->W0 * s->L0);
        s->rhs[r] -= fd.x;
        s->rhs[r + 1] -= fd.y;
        s->rhs[r + 2] -= bl_v2_cross(arm, fd) + (pl->live ? 0.0 : c);
        fL[r] += fl.x;
        fL[r + 1] += fl.y;
        fL[r + 2] += bl_v2_cross(arm, fl) + (pl->live ? c : 0.0);
    }
    s = bl_system_finish(s, nz, fL, err);
    free(fL);
    return s;
oom:
    bl_system_free(s);
    bl_error_set(err, "solve: out of memory assembling the equilibrium system");
    return NULL;
}

void bl_system_fixed_bounds(const bl_system *s, const double *n, double *lo, double *hi)
{
    const double *C = s->cohesion;
    for (int j = 0; j < s->ncols; j++) {
        lo[j] = s->lo[j];
        hi[j] = s->hi[j];
        int kind = j < s->nforce ? s->col_kind[j] : -1;
        if ((kind == BL_COL_SHEAR && isfinite(s->hi[j])) || kind == BL_COL_TWIST) {
            int p = s->col_point[j];
            double N = 0.0; /* the points p leads follow it */
            for (int q = p; q < s->npoints && s->lead[q] == p; q++) N += fmax(n[q], 0.0);
            double R = (kind == BL_COL_TWIST ? s->twist[p] : s->mu[p]) * N + C[p];
            lo[j] = -R;
            hi[j] = R;
        }
    }
}

void bl_system_cost_normal(const bl_system *s, double eps, double *obj)
{
    for (int j = 0; j < s->nforce; j++) obj[j] -= eps * s->col_nt[s->dim * j];
}

void bl_system_speed(const bl_system *s, const double *w, const double *dt, const double *dt3,
                     double *speed)
{
    for (int p = 0; p < s->npoints; p++) speed[p] = hypot(dt[p], dt3 ? dt3[p] : 0.0);
    for (int j = 0; j < s->nforce; j++)
        if (s->col_kind[j] == BL_COL_TWIST) speed[s->col_point[j]] = hypot(speed[s->col_point[j]], w[j]);
}

void bl_system_rigid_motion(const bl_system *s, const double *dn, const double *speed,
                            double *slide, double *open)
{
    for (int p = 0, q; p < s->npoints; p = q) {
        int k = s->point_iface[p];
        double fastest = 0.0, least = INFINITY;
        for (q = p; q < s->npoints && s->point_iface[q] == k; q++) {
            fastest = fmax(fastest, speed[q]);
            least = fmin(least, dn[q]);
        }
        for (int i = p; i < q; i++) {
            slide[i] = isinf(s->mu[i]) ? fastest : 0.0;
            open[i] = isinf(s->mu[i]) ? least : 0.0;
        }
    }
}

void bl_system_forces(const bl_system *s, const bl_model *m, const double *x, double *force)
{
    memset(force, 0, 4 * (size_t)m->ninterfaces * sizeof *force);
    for (int j = 0; j < s->nforce; j++) {
        int p = s->col_point[j];
        force[2 * p] += s->W0 * x[j] * s->col_nt[2 * j];
        force[2 * p + 1] += s->W0 * x[j] * s->col_nt[2 * j + 1];
    }
}

void bl_system_reactions(const bl_system *s, const bl_model *m, const double *x, double *R)
{
    int per = s->dim == 3 ? 6 : 3;
    memset(R, 0, 6 * (size_t)m->nblocks * sizeof *R);
    for (int j = 0; j < s->nforce; j++) {
        const bl_interface *in = &m->interfaces[s->point_iface[s->col_point[j]]];
        int sa = m->blocks[in->a].support, sb = m->blocks[in->b].support;
        if (sa == sb) continue;
        int sup = sa ? in->a : in->b, f = sa ? in->b : in->a, r = s->block_row[f];
        /* the column's wrench on the free block, from its rows (unscaled:
         * forces times W0, moments about the centroid times W0 L0) */
        double w[6] = {0, 0, 0, 0, 0, 0};
        for (int q = s->colptr[j]; q < s->colptr[j + 1]; q++) {
            int row = s->rowind[q];
            if (row < r || row >= r + per) continue;
            w[row - r] += s->val[q] * x[j] / (s->row_scale ? s->row_scale[row] : 1.0);
        }
        bl_vec3 F, M, g;
        if (s->dim == 3) {
            F = bl_v3(w[0], w[1], w[2]);
            M = bl_v3(w[3], w[4], w[5]);
            g = m->blocks[f].centroid3;
        } else {
            F = bl_v3(w[0], w[1], 0.0);
            M = bl_v3(0.0, 0.0, w[2]);
            g = bl_v3(m->blocks[f].centroid.x, m->blocks[f].centroid.y, 0.0);
        }
        F = bl_v3_scale(F, s->W0);
        M = bl_v3_add(bl_v3_scale(M, s->W0 * s->L0), bl_v3_cross(g, F));
        /* what the free block exerts on the support: the opposite */
        double *Rs = R + 6 * sup;
        Rs[0] -= F.x, Rs[1] -= F.y, Rs[2] -= F.z;
        Rs[3] -= M.x, Rs[4] -= M.y, Rs[5] -= M.z;
    }
}

void bl_system_mechanism(const bl_system *s, const bl_model *m, const double *y, double *u)
{
    /* Rows were scaled by 1/W0 (forces) and 1/(W0 L0) (moments), so the
     * physical velocities are y scaled the same way; fL . u = 1 carries over
     * (doc/theory.md, "scaling"). */
    for (int i = 0; i < m->nblocks; i++) {
        int r = s->block_row[i];
        double *ui = u + 3 * i;
        if (r < 0) {
            ui[0] = ui[1] = ui[2] = 0.0;
            continue;
        }
        ui[0] = bl_system_velocity(s, y, r) / s->W0;
        ui[1] = bl_system_velocity(s, y, r + 1) / s->W0;
        ui[2] = bl_system_velocity(s, y, r + 2) / (s->W0 * s->L0);
    }
}

void bl_system_rows_of_mechanism(const bl_system *s, const bl_model *m, const double *u, double *y)
{
    int per = s->dim == 3 ? 6 : 3, forces = s->dim == 3 ? 3 : 2; /* rows per block; force rows */
    for (int i = 0; i < m->nblocks; i++) {
        int r = s->block_row[i];
        if (r < 0) continue;
        for (int c = 0; c < per; c++) {
            double v = u[per * i + c] * (c < forces ? s->W0 : s->W0 * s->L0);
            y[r + c] = s->row_scale ? v / s->row_scale[r + c] : v;
        }
    }
}

void bl_system_residual(const bl_system *s, const double *x, double alpha, double *r)
{
    for (int i = 0; i < s->nrows; i++) r[i] = -s->rhs[i];
    for (int j = 0; j < s->ncols; j++) {
        double xj = j < s->nforce ? x[j] : alpha;
        for (int p = s->colptr[j]; p < s->colptr[j + 1]; p++) r[s->rowind[p]] += s->val[p] * xj;
    }
}

void bl_system_power(const bl_system *s, const double *y, double *w)
{
    for (int j = 0; j < s->nforce; j++) {
        double t = 0.0;
        for (int p = s->colptr[j]; p < s->colptr[j + 1]; p++) t += s->val[p] * y[s->rowind[p]];
        w[j] = t;
    }
}

void bl_system_point_motion(const bl_system *s, const double *y, double *w, double *dn,
                            double *dt)
{
    /* the power of a unit normal (shear) force is the normal (tangential)
     * relative velocity */
    bl_system_power(s, y, w);
    for (int p = 0; p < s->npoints; p++) dn[p] = dt[p] = 0.0;
    for (int j = 0; j < s->nforce; j++) {
        int p = s->col_point[j];
        if (s->col_kind[j] == BL_COL_NORMAL) dn[p] = w[j];
        else dt[p] = w[j];
    }
}
