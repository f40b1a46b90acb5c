#include "solution.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const status_names[] = {
    [BL_OPTIMAL] = "optimal",
    [BL_UNSTABLE] = "unstable",
    [BL_UNBOUNDED] = "unbounded",
    [BL_INFEASIBLE] = "infeasible",
    [BL_ITERATION_LIMIT] = "iteration limit",
    [BL_TIME_LIMIT] = "time limit",
    [BL_INTERRUPTED] = "interrupted",
    [BL_NUMERICAL] = "numerical trouble",
    [BL_UNCERTIFIED] = "not certified",
    [BL_LOCALLY_INFEASIBLE] = "locally infeasible",
    [BL_RESTORATION_FAILED] = "restoration failed",
    [BL_NOT_COMPLEMENTARY] = "not complementary",
};

static const char *const status_sentences[] = {
    [BL_OPTIMAL] = "collapse load multiplier found",
    [BL_UNSTABLE] = "the structure cannot stand under its dead load alone",
    [BL_UNBOUNDED] = "no collapse: the live load cannot produce a mechanism, however large",
    [BL_INFEASIBLE] = "no equilibrium for any alpha: the dead and live loads cannot both be carried",
    [BL_ITERATION_LIMIT] = "stopped at the iteration limit before an answer was found",
    [BL_TIME_LIMIT] = "stopped at the time limit before an answer was found",
    [BL_INTERRUPTED] = "interrupted by the user before an answer was found",
    [BL_NUMERICAL] = "the LP engine failed numerically; no answer",
    [BL_UNCERTIFIED] = "no start of the sequence of LPs ended with a certified answer",
    [BL_LOCALLY_INFEASIBLE] = "Ipopt converged to a point that violates the constraints least; "
                              "no answer",
    [BL_RESTORATION_FAILED] = "Ipopt's restoration phase failed to regain feasibility; no answer",
    [BL_NOT_COMPLEMENTARY] = "Ipopt converged to a point the residuals reject (complementarity or "
                             "flow rule not met): not an answer",
};

const char *bl_status_name(bl_status s) { return status_names[s]; }
const char *bl_status_sentence(bl_status s) { return status_sentences[s]; }

const char *bl_state_name(bl_state s)
{
    static const char *const names[] = {"closed", "rocking", "sliding", "separating"};
    return names[s];
}

bl_solution *bl_solution_new(bl_model *c)
{
    bl_solution *s = calloc(1, sizeof *s);
    if (!s) {
        bl_model_free(c);
        return NULL;
    }
    s->model = c;
    size_t nb = (size_t)c->nblocks, ni = (size_t)c->ninterfaces, np = 0;
    for (size_t k = 0; k < ni; k++) np += (size_t)c->interfaces[k].np;
    /* 2D: 3 velocities per block, n and t at both ends of an interface;
     * 3D: 6 per block, n, t2, t3 at every vertex of a contact polygon */
    s->u = calloc((c->dim == 3 ? 6 : 3) * nb + 1, sizeof *s->u);
    s->force = calloc((c->dim == 3 ? 3 * np : 4 * ni) + 1, sizeof *s->force);
    s->state = calloc(ni + 1, sizeof *s->state);
    s->hinge = calloc(ni + 1, sizeof *s->hinge);
    s->speed = calloc(ni + 1, sizeof *s->speed);
    s->reaction = calloc(6 * nb + 1, sizeof *s->reaction);
    if (!s->u || !s->force || !s->state || !s->hinge || !s->speed || !s->reaction) {
        bl_solution_free(s);
        return NULL;
    }
    for (size_t k = 0; k < ni; k++) s->hinge[k] = -1;
    s->method = "assoc";
    s->flow = "associative";
    s->res.flow = s->res.dilatancy = s->res.below = s->res.above = NAN;
    s->stands = -1;
    s->alpha = s->alpha_min = NAN; /* until there is an answer */
    return s;
}

bl_status bl_status_of_lp(bl_lp_status st)
{
    switch (st) {
    case BL_LP_OPTIMAL: return BL_OPTIMAL;
    case BL_LP_INFEASIBLE: return BL_INFEASIBLE;
    case BL_LP_UNBOUNDED: return BL_UNBOUNDED;
    case BL_LP_ITERATION_LIMIT: return BL_ITERATION_LIMIT;
    case BL_LP_TIME_LIMIT: return BL_TIME_LIMIT;
    case BL_LP_INTERRUPTED: return BL_INTERRUPTED;
    default: return BL_NUMERICAL;
    }
}

void bl_solution_answer_status(bl_solution *s)
{
    /* alpha within the tolerance below 0 is 0 to round-off (the interior
     * point's -1e-10 where blocks rest on frictionless joints): the
     * dead-load check decides it, as it does alpha >= 0 */
    if (s->alpha < -s->tolerance) s->stands = 0;
    s->status = s->stands == 0 ? BL_UNSTABLE : BL_OPTIMAL;
}

void bl_solution_free(bl_solution *s)
{
    if (!s) return;
    bl_model_free(s->model);
    free(s->u);
    free(s->force);
    free(s->state);
    free(s->hinge);
    free(s->speed);
    free(s->reaction);
    free(s->history);
    free(s->start);
    free(s->x);
    free(s->y);
    free(s);
}

int bl_solution_keep(bl_solution *s, const double *x, int nx, const double *y, int ny)
{
    free(s->x);
    free(s->y);
    s->x = malloc(((size_t)nx + 1) * sizeof *s->x);
    s->y = malloc(((size_t)ny + 1) * sizeof *s->y);
    if (!s->x || !s->y) {
        free(s->x);
        free(s->y);
        s->x = s->y = NULL;
        return -1;
    }
    memcpy(s->x, x, (size_t)nx * sizeof *x);
    memcpy(s->y, y, (size_t)ny * sizeof *y);
    s->nx = nx;
    s->ny = ny;
    return 0;
}

bl_vec3 bl_solution_velocity(const bl_solution *s, int b, bl_vec3 p)
{
    const bl_block *B = &s->model->blocks[b];
    if (s->model->dim == 3) {
        const double *u = s->u + 6 * b;
        bl_vec3 r = bl_v3_sub(p, B->centroid3);
        return bl_v3_add(bl_v3(u[0], u[1], u[2]), bl_v3_cross(bl_v3(u[3], u[4], u[5]), r));
    }
    const double *u = s->u + 3 * b;
    return bl_v3(u[0] - u[2] * (p.y - B->centroid.y), u[1] + u[2] * (p.x - B->centroid.x), 0.0);
}

bl_vec2 bl_solution_relative_velocity(const bl_solution *s, int a, int b, bl_vec2 p)
{
    bl_vec3 q = bl_v3(p.x, p.y, 0.0), d = bl_v3_sub(bl_solution_velocity(s, b, q), bl_solution_velocity(s, a, q));
    return bl_v2(d.x, d.y);
}

int bl_solution_moves(const bl_solution *s)
{
    return s->has_mechanism && s->u && (s->status == BL_OPTIMAL || s->status == BL_UNSTABLE);
}

double bl_solution_block_speed(const bl_solution *s, int b)
{
    const bl_block *B = &s->model->blocks[b];
    double d = 0.0;
    int nv = s->model->dim == 3 ? B->solid.nv : B->nv;
    for (int i = 0; i < nv; i++) {
        bl_vec3 p = s->model->dim == 3 ? B->solid.v[i] : bl_v3(B->v[i].x, B->v[i].y, 0.0);
        d = fmax(d, bl_v3_norm(bl_solution_velocity(s, b, p)));
    }
    return d;
}

/* The group of block b: the root of its tree in up (path halving). */
static int group_of(int *up, int b)
{
    while (up[b] != b) b = up[b] = up[up[b]];
    return b;
}

int bl_solution_participation(const bl_solution *s, bl_participation *p)
{
    const bl_model *m = s->model;
    memset(p, 0, sizeof *p);
    if (!s->has_mechanism || !s->u || s->status != BL_OPTIMAL || !m->live_weight) return -1;
    for (int l = 0; l < m->nloads; l++)
        if (m->loads[l].live) return -1;
    bl_vec3 d = m->dim == 3 ? m->live_dir3 : bl_v3(m->live_dir.x, m->live_dir.y, 0.0);
    int nb = m->nblocks, *group = malloc(2 * (size_t)nb * sizeof *group), *body = group + nb;
    /* per body: its weight and its weights' work; per group: chain,
     * work, square, blocks, bodies */
    double *bw = calloc(7 * (size_t)nb, sizeof *bw), *bv = bw + nb, *sum = bv + nb;
    char *moving = malloc((size_t)nb);
    double fastest = 0.0;
    int rc = -1;
    if (!group || !bw || !moving) goto done;
    for (int b = 0; b < nb; b++) {
        double v = m->blocks[b].support ? 0.0 : bl_solution_block_speed(s, b);
        if (!isfinite(v)) goto done;
        fastest = fmax(fastest, v);
        bv[b] = v;
        group[b] = body[b] = b;
    }
    if (!(fastest > 0.0)) goto done;
    /* The moving blocks, in groups joined by their interfaces: each group
     * is a mechanism of its own (an interior point's blend of mechanisms
     * tied at alpha moves several); within a group, blocks joined by
     * interfaces that move less than BL_STILL_FRACTION of the fastest (no
     * crack in the picture) move as one rigid body, whose weight counts at
     * its centre (the codes' macro-block). */
    for (int b = 0; b < nb; b++) {
        moving[b] = bv[b] >= BL_STILL_FRACTION * fastest;
        bv[b] = 0.0;
    }
    for (int k = 0; k < m->ninterfaces; k++) {
        int a = m->interfaces[k].a, b = m->interfaces[k].b;
        if (!moving[a] || !moving[b]) continue;
        group[group_of(group, a)] = group_of(group, b);
        if (!(s->speed[k] >= BL_STILL_FRACTION * s->speed_max)) body[group_of(body, a)] = group_of(body, b);
    }
    /* each block's weight at its centroid into its body (l >= nloads); the
     * carried weights at their points, each a mass of its own (l < nloads) */
    for (int l = 0; l < m->nloads + nb; l++) {
        int own = l >= m->nloads, b = own ? l - m->nloads : m->loads[l].block;
        const bl_block *B = &m->blocks[b];
        if (!moving[b] || (!own && !(m->loads[l].weight > 0.0))) continue;
        double P = own ? B->weight : m->loads[l].weight;
        bl_vec3 at = own ? (m->dim == 3 ? B->centroid3 : bl_v3(B->centroid.x, B->centroid.y, 0.0))
                         : (m->dim == 3 ? m->loads[l].at3 : bl_v3(m->loads[l].at.x, m->loads[l].at.y, 0.0));
        double v = bl_v3_dot(bl_solution_velocity(s, b, at), d), *g = sum + 5 * group_of(group, b);
        if (own) {
            int r = group_of(body, b);
            bw[r] += P;
            bv[r] += P * v;
            g[3] += 1.0;
        } else {
            g[0] += P;
            g[1] += P * v;
            g[2] += P * v * v;
        }
    }
    /* a body's weight moves as its centre does: at the mean of its
     * blocks' velocities, Σ P v / Σ P (exact for a rigid motion) */
    for (int b = 0; b < nb; b++) {
        if (!(bw[b] > 0.0)) continue;
        double *g = sum + 5 * group_of(group, b);
        g[0] += bw[b];
        g[1] += bv[b];
        g[2] += bv[b] * bv[b] / bw[b];
        g[4] += 1.0;
    }
    /* the group that the least acceleration activates */
    for (int b = 0; b < nb; b++) {
        const double *g = sum + 5 * b;
        if (!(g[0] > 0.0)) continue;
        p->groups++;
        if (!(g[2] > 0.0)) continue; /* it moves across d only */
        double ms = g[1] * g[1] / g[2], e = ms / g[0], acc = fmax(s->alpha, 0.0) / e;
        if (p->blocks == 0 || acc < p->acceleration) {
            p->chain = g[0];
            p->participating = ms;
            p->ratio = e;
            p->acceleration = acc;
            p->blocks = (int)g[3];
            p->bodies = (int)g[4];
        }
    }
    rc = p->blocks > 0 ? 0 : -1;
done:
    free(group);
    free(bw);
    free(moving);
    return rc;
}

/* Relative threshold below which a relative velocity counts as zero. */
#define MOTION_THRESHOLD 1e-5

/* Relative velocity of b with respect to a at the 3D point p. */
static bl_vec3 relative3(const bl_solution *s, int a, int b, bl_vec3 p)
{
    return bl_v3_sub(bl_solution_velocity(s, b, p), bl_solution_velocity(s, a, p));
}

/* Whether s is an answer of the non-associative flow, where a point that
 * opens at all is open: the associative flow's sliding points open by mu
 * times their slip, and only those that open by more are open. */
static int nonassociative(const bl_solution *s)
{
    return s->flow && strcmp(s->flow, "nonassociative") == 0;
}

/* 3D states, from the relative velocity at every vertex of the contact
 * polygon: sliding where a vertex moves along the joint and does not open
 * (associative flow: by no more than mu times its slip), separating where
 * every vertex opens, rocking where some do. */
static void classify3(bl_solution *s)
{
    int nonassoc = nonassociative(s);
    const bl_model *m = s->model;
    double vmax = 0.0;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        s->speed[k] = 0.0;
        for (int e = 0; e < in->np; e++)
            s->speed[k] = fmax(s->speed[k], bl_v3_norm(relative3(s, in->a, in->b, in->poly[e])));
        vmax = fmax(vmax, s->speed[k]);
    }
    s->speed_max = vmax;
    double eps = s->motion_eps = MOTION_THRESHOLD * vmax;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        int open = 0, sliding = 0;
        for (int e = 0; e < in->np; e++) {
            bl_vec3 d = relative3(s, in->a, in->b, in->poly[e]);
            double dn = bl_v3_dot(d, in->n3);
            double dt = bl_v3_norm(bl_v3_sub(d, bl_v3_scale(in->n3, dn)));
            double mu = isinf(in->mu) || nonassoc ? 0.0 : in->mu;
            if (bl_v3_norm(d) <= eps) continue;
            if (dt > eps && dn <= mu * dt + eps) sliding++;
            else open++;
        }
        s->hinge[k] = -1;
        s->state[k] = sliding ? BL_SLIDING : open == in->np ? BL_SEPARATING
                                : open ? BL_ROCKING : BL_CLOSED;
    }
}

int bl_solution_closed3(const bl_solution *s, int k, int e)
{
    const bl_interface *in = &s->model->interfaces[k];
    return bl_v3_norm(relative3(s, in->a, in->b, in->poly[e])) <= s->motion_eps;
}

void bl_solution_classify(bl_solution *s)
{
    const bl_model *m = s->model;
    if (m->dim == 3) {
        classify3(s);
        return;
    }
    int nonassoc = nonassociative(s);
    double vmax = 0.0;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        s->speed[k] = 0.0;
        for (int e = 0; e < 2; e++)
            s->speed[k] = fmax(s->speed[k], bl_v2_norm(bl_solution_relative_velocity(s, in->a, in->b, in->p[e])));
        vmax = fmax(vmax, s->speed[k]);
    }
    s->speed_max = vmax;
    double eps = s->motion_eps = MOTION_THRESHOLD * vmax;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        bl_vec2 tau = bl_v2(-in->normal.y, in->normal.x);
        int open = 0, sliding = 0, closed_end = -1;
        for (int e = 0; e < 2; e++) {
            bl_vec2 d = bl_solution_relative_velocity(s, in->a, in->b, in->p[e]);
            double dn = bl_v2_dot(d, in->normal), dt = fabs(bl_v2_dot(d, tau));
            double mu = isinf(in->mu) || nonassoc ? 0.0 : in->mu;
            if (bl_v2_norm(d) <= eps) {
                closed_end = e;
            } else if (dt > eps && dn <= mu * dt + eps) {
                sliding++;
            } else {
                open++;
            }
        }
        s->hinge[k] = -1;
        if (sliding) {
            s->state[k] = BL_SLIDING;
        } else if (open == 2) {
            s->state[k] = BL_SEPARATING;
        } else if (open == 1) {
            s->state[k] = BL_ROCKING;
            s->hinge[k] = closed_end;
        } else {
            s->state[k] = BL_CLOSED;
        }
    }
}

void bl_solution_resultants(const bl_solution *s, bl_vec3 *F, double *N, bl_vec3 *C)
{
    const bl_model *m = s->model;
    const double *f = s->force;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        bl_vec3 force = {0, 0, 0}, moment = {0, 0, 0}, mid = {0, 0, 0};
        double n = 0.0;
        int np = m->dim == 3 ? in->np : 2;
        for (int e = 0; e < np; e++) {
            /* normal and shear(s) at point e: 3 numbers in 3D, 2 in 2D */
            bl_vec3 p, nrm, fe;
            if (m->dim == 3) {
                p = in->poly[e];
                nrm = in->n3;
                fe = bl_v3_add(bl_v3_scale(in->n3, f[0]),
                               bl_v3_add(bl_v3_scale(in->t2, f[1]), bl_v3_scale(in->t3, f[2])));
                f += 3;
            } else {
                p = bl_v3(in->p[e].x, in->p[e].y, 0.0);
                nrm = bl_v3(in->normal.x, in->normal.y, 0.0);
                bl_vec3 tau = bl_v3(-in->normal.y, in->normal.x, 0.0);
                fe = bl_v3_add(bl_v3_scale(nrm, f[0]), bl_v3_scale(tau, f[1]));
                f += 2;
            }
            double ne = bl_v3_dot(fe, nrm);
            force = bl_v3_add(force, fe);
            moment = bl_v3_add(moment, bl_v3_scale(p, ne));
            mid = bl_v3_add(mid, bl_v3_scale(p, 1.0 / np));
            n += ne;
        }
        F[k] = force;
        N[k] = n;
        C[k] = n > 0.0 ? bl_v3_scale(moment, 1.0 / n) : mid;
    }
}

void bl_solution_reactions(const bl_solution *s, bl_vec3 *R, bl_vec3 *M)
{
    for (int i = 0; i < s->model->nblocks; i++) {
        const double *w = s->reaction + 6 * i;
        R[i] = bl_v3(w[0], w[1], w[2]);
        M[i] = bl_v3(w[3], w[4], w[5]);
    }
}
