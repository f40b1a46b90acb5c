#include "seqlp.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "assemble.h"
#include "contact.h"
#include "lp.h"
#include "napath.h"
#include "verify.h"

void bl_seqlp_options_default(bl_seqlp_options *o)
{
    bl_solve_options_default(&o->base);
    o->beta = 0.7;
    o->settle = 1e-4;
    o->slip = 1e-4;
    o->max_lps = 100;
    o->starts = -1;
    o->seed = 1;
    o->nearest = -1;
    o->path = -1;
    o->progress = 0;
    o->when_sliding = 0;
    o->nmechanisms = 0;
    o->mechanisms = NULL;
}

/* The state of one run, with everything it owns. */
typedef struct run {
    bl_system *cone, *fixed;
    bl_system *states; /* the cone system the stress states of start 0 and the
                          restarts come from: the cone's, but with rigid
                          joints at mu_rigid (search_system); or the cone
                          itself */
    const bl_model *model;
    double mu_rigid;   /* the friction of rigid joints in this start's search */
    double mu_cap;     /* and the most friction of the others (infinite: their own) */
    bl_cone pyramid;   /* 3D: the sequence's */
    bl_lp *lp_fixed, *lp_cone;
    double *n, *lo, *hi, *clo, *chi, *obj, *w, *dn, *dt, *dt3; /* dt3: 3D, along t3 */
    double *resist; /* 3D: per joint, the most a pyramid edge resists its motion */
    double *speed;  /* 3D: per joint, how fast it slides (and twists) */
    double *slide, *open; /* per point of a rigid joint: bl_system_rigid_motion */
    double *n_first; /* r->n where start 0 stopped */
    double t0;             /* when the run began */
    int iterations;        /* of the random-state LPs */
    int shown;             /* a progress line is on the screen */
    int planned;           /* starts in all, once start 0 has decided it */
    int found;             /* a certified answer is kept in best_* */
    int least_n;           /* the fixed LPs prefer the least normal force */
    int switched;          /* the fixed LPs went to the other engine after a failure */
    int bounded;           /* some fixed LP of the run had an answer */
    double first_alpha;    /* the alpha of the first one */
    int cone_other;        /* lp_cone was made with another objective than the
                              lowest alpha (lean_work, nearest_forces) */
    int rigid_beside;      /* the LP of unlimited friction runs on rigid_thread */
    pthread_t rigid_thread;
    double best_alpha, best_settled, *best_x, *best_y;
    int best_early;        /* best_* certified before its sequence settled */
    int best_given;        /* ... from the k-th mechanism given (1-based), or 0 */
    double *yc;            /* a settled LP's mechanism, for its certificate */
    double *xc;            /* the certificate's forces (certify) */
    const struct path_job *warm; /* the point the first fixed LP starts from, or NULL */
    double floor;          /* the least alpha a certificate may give: 0 where
                            * the dead load alone stands, else -inf */
} run;

/* The path of the non-associative problem, followed on the calling
 * thread or beside the associative solve. */
typedef struct path_job {
    bl_system *system;
    double *x, *zl, *zu, *y; /* its last point (napath.h) */
    int report, status, beside; /* report: BL_NAPATH_QUIET, ... */
    double deadline;            /* the solve's (bl_solve_options) */
    atomic_int cancel;          /* set when its answer is no longer wanted */
    bl_napath_result res;
    bl_error err;
    pthread_t thread;
} path_job;

/* The first fixed LP starts from the path's point (lp.h, bl_lp_warm); from
 * a point past the target, with its products raised to the target's level. */
static void path_warm(const path_job *j, bl_lp *lp)
{
    double raise = j->res.deep ? BL_SEQLP_PATH_PRODUCTS / j->res.complementarity : 1.0;
    bl_lp_warm(lp, j->x, j->zl, j->zu, j->y, j->res.mu * raise);
}

static void run_free(run *r)
{
    bl_lp_free(r->lp_fixed);
    bl_lp_free(r->lp_cone);
    if (r->states != r->cone) bl_system_free(r->states);
    bl_system_free(r->cone);
    bl_system_free(r->fixed);
    free(r->n);
    free(r->n_first);
    free(r->lo);
    free(r->hi);
    free(r->clo);
    free(r->chi);
    free(r->w);
    free(r->dn);
    free(r->dt);
    free(r->dt3);
    free(r->resist);
    free(r->speed);
    free(r->slide);
    free(r->open);
    free(r->obj);
    free(r->best_x);
    free(r->best_y);
    free(r->yc);
    free(r->xc);
}

/* The systems of the run: in 3D on bl_seqlp_pyramid. */
static bl_system *build(const bl_model *m, const bl_cone *pyramid, bl_friction_form form,
                        bl_error *err)
{
    if (m->dim != 3) return bl_system_build(m, form, err);
    return bl_system_build3(m, pyramid, form, err);
}

/* The friction a joint of friction mu has in a search whose rigid joints
 * slide at mu_rigid and whose others have at most mu_cap. */
static double search_mu(double mu, double mu_rigid, double mu_cap)
{
    return isinf(mu) ? mu_rigid : fmin(mu, mu_cap);
}

/* Whether some joint of m is rigid (mu = inf). */
static int has_rigid(const bl_model *m)
{
    for (int k = 0; k < m->ninterfaces; k++)
        if (isinf(m->interfaces[k].mu)) return 1;
    return 0;
}

/* Whether the model's LPs have at most rows rows in 2D, cols3 columns in
 * 3D: the small models (BL_SEQLP_SEARCH_ROWS, BL_SEQLP_SEARCH_COLUMNS3),
 * and the medium ones up to which the default searches where one start's
 * answer leaves doubt (medium: BL_SEQLP_MARGIN_ROWS,
 * BL_SEQLP_MARGIN_COLUMNS3). */
static int within(const run *r, const bl_model *mc, int rows, int cols3)
{
    return (mc->dim == 2 && r->fixed->nrows <= rows) || (mc->dim == 3 && r->fixed->ncols <= cols3);
}
static int medium(const run *r, const bl_model *mc)
{
    return within(r, mc, BL_SEQLP_MARGIN_ROWS, BL_SEQLP_MARGIN_COLUMNS3);
}

/* Whether the default runs BL_SEQLP_SEARCH restarts after the first start
 * to certify (start 0, or a retry where start 0 did not), and why
 * (r.restarts_why), or NULL: it settled at the associative alpha; or, up
 * to a size (BL_SEQLP_MARGIN_ROWS, BL_SEQLP_MARGIN_COLUMNS3), it certified
 * more than BL_SEQLP_MARGIN below a finite associative alpha, or the
 * associative alpha is within that of unlimited friction's (doc/seqlp.md
 * 17, 18). */
static const char *search_after(const run *r, const bl_solution *s, const bl_model *mc,
                                const bl_seqlp_options *o)
{
    if (!r->found) return NULL;
    if (r->best_settled >= s->alpha_assoc - o->settle * fabs(s->alpha_assoc)) return "settled";
    if (!medium(r, mc)) return NULL;
    if (isfinite(s->alpha_assoc) && r->best_alpha < s->alpha_assoc - BL_SEQLP_MARGIN * fabs(s->alpha_assoc))
        return "below";
    if (isfinite(s->alpha_rigid) && !has_rigid(mc) &&
        s->alpha_assoc >= s->alpha_rigid - BL_SEQLP_MARGIN * fabs(s->alpha_rigid))
        return "near rigid";
    return NULL;
}

/* How many different alphas the starts of s certified (to 1e-6 of each). */
static int different_answers(const bl_solution *s)
{
    int n = 0;
    for (int i = 0; i < s->nstarts; i++) {
        double a = s->start[i].alpha;
        int seen = !isfinite(a);
        for (int j = 0; j < i && !seen; j++)
            seen = fabs(s->start[j].alpha - a) <= 1e-6 * fmax(fabs(a), 1e-12);
        n += !seen;
    }
    return n;
}

/* Whether the search at (mu_rigid, mu_cap) changes some joint's friction. */
static int search_differs(const bl_model *m, double mu_rigid, double mu_cap)
{
    for (int k = 0; k < m->ninterfaces; k++)
        if (search_mu(m->interfaces[k].mu, mu_rigid, mu_cap) != m->interfaces[k].mu) return 1;
    return 0;
}

/* A system of the sequence's search: its rigid joints (mu = inf) slide at
 * friction mu_rigid, so that a joint that carries nothing can slide open,
 * and the others at most at mu_cap; its stress states load a joint no more
 * than that friction allows.  The certificates hold every joint to its
 * own friction (doc/theory.md 6). */
static bl_system *search_system(const bl_model *m, const bl_cone *pyramid, bl_friction_form form,
                                double mu_rigid, double mu_cap, bl_error *err)
{
    if (!search_differs(m, mu_rigid, mu_cap)) return build(m, pyramid, form, err);
    bl_model *c = bl_model_copy(m);
    if (!c) {
        bl_error_set(err, "solve: out of memory");
        return NULL;
    }
    for (int k = 0; k < c->ninterfaces; k++) {
        bl_interface *in = &c->interfaces[k];
        double mu = search_mu(in->mu, mu_rigid, mu_cap);
        /* a torsion coefficient of the joint's own (3D resultant model)
         * scales with its friction, as fixed_bounds scales its column's
         * capacity from the fixed system's friction */
        double from = isinf(in->mu) ? BL_SEQLP_MU_RIGID : in->mu;
        if (in->mu_t > 0.0 && from > 0.0) in->mu_t *= mu / from;
        in->mu = mu;
    }
    bl_system *s = build(c, pyramid, form, err);
    bl_model_free(c);
    return s;
}

bl_cone bl_seqlp_pyramid(const bl_cone *asked)
{
    bl_cone p = {.facets = 8};
    if (!asked->adaptive && asked->facets % 2 == 0) {
        p.facets = asked->facets;
        p.circumscribed = asked->circumscribed;
    }
    return p;
}

/* The relative velocity of every contact point from the mechanism y:
 * normal dn, tangential dt (3D: along t2, and dt3 along t3), and per
 * joint's lead point (bl_system) how fast it slides: the slip and, in the
 * 3D resultant model, the twist (the torsion lever times the rotation
 * about the normal, the power of a twist column).  Returns the velocity
 * scale V, the largest of hypot(dn, speed). */
static double point_motion(run *r, const double *y)
{
    const bl_system *f = r->fixed;
    bl_system_point_motion(f, y, r->w, r->dn, r->dt);
    if (f->dim == 3) bl_system_tangent3(f, r->w, r->dt, r->dt3);
    bl_system_speed(f, r->w, r->dt, f->dim == 3 ? r->dt3 : NULL, r->speed);
    bl_system_rigid_motion(r->cone, r->dn, r->speed, r->slide, r->open);
    double V = 0.0;
    for (int p = 0; p < f->npoints; p++) V = fmax(V, hypot(r->dn[p], r->speed[p]));
    return V;
}

/* The work a force field does on the mechanism beyond Coulomb's
 * dissipation, W = sum over points of n dn + t.dt + mu n |dt| >= 0, is
 * linear in the force columns; by virtual work alpha = alpha_D - W, with
 * alpha_D the mechanism's alpha from its dissipation.  At the certificate's
 * free points (motions below slip) W need not vanish, and the lowest alpha
 * leans on it; the verification's work residual is W over the balance's
 * terms.  Adds -rho times each column's W per unit value to obj (a
 * maximization), from the point motions of certificate_bounds.  In 3D the
 * dissipation is the pyramid's: per unit normal force the most an edge
 * resists (r->resist), and t.dt the column's tangential power (r->w). */
static void lean_work(run *r, double rho, double *obj)
{
    const bl_system *c = r->cone;
    for (int j = 0; j < c->nforce; j++) {
        int p = c->col_point[j];
        double w;
        if (c->dim == 3) {
            w = c->col_nt[3 * j] * r->dn[p] + r->w[j];
            if (c->col_kind[j] == BL_COL_PYRAMID) w += fmax(r->resist[c->lead[p]], 0.0);
        } else {
            double nj = c->col_nt[2 * j], tj = c->col_nt[2 * j + 1];
            double mu = isfinite(c->mu[p]) ? c->mu[p] : 0.0;
            w = nj * r->dn[p] + tj * r->dt[p] + mu * nj * fabs(r->dt[p]);
        }
        obj[j] -= rho * w;
    }
}

/* Solves the certificate LP with the bounds in clo, chi (creating it the
 * first time): the interior point, or, with alpha fixed, the simplex where
 * the interior point does not converge.  Counts it in s. */
static bl_lp_status certificate_lp(run *r, const bl_solve_options *asked, double rho,
                                   bl_solution *s, bl_error *err)
{
    /* a certificate that fails only sends the sequence on: the interior
     * point may end at an early dual ray (lp.h) */
    bl_solve_options own = *asked;
    own.early_infeasible = 1;
    const bl_solve_options *o = &own;
    int fixed = r->clo[r->cone->nforce] == r->chi[r->cone->nforce];
    const bl_system *c = r->cone;
    /* the objective: the lowest alpha, plus rho times the work the forces
     * do on the motions taken as none (lean_work) */
    for (int j = 0; j < c->ncols; j++) r->obj[j] = j == c->nforce ? -1.0 : 0.0;
    if (rho > 0.0) lean_work(r, rho, r->obj);
    if (r->lp_cone && (rho > 0.0 || r->cone_other)) { /* another objective: made anew */
        bl_lp_free(r->lp_cone);
        r->lp_cone = NULL;
    }
    r->cone_other = rho > 0.0;
    if (!r->lp_cone) {
        r->lp_cone = bl_solve_lp(c, r->clo, r->chi, r->obj, o, err);
        if (!r->lp_cone) return BL_LP_FAILED;
    } else {
        bl_lp_set_bounds(r->lp_cone, r->clo, r->chi);
    }
    bl_lp_status st = bl_lp_solve(r->lp_cone);
    if (fixed && (st == BL_LP_ITERATION_LIMIT || st == BL_LP_FAILED) &&
        strcmp(bl_lp_engine(r->lp_cone), "ipm") == 0 &&
        bl_lp_choose(BL_LP_AUTO, c->nrows, c->ncols) == BL_LP_SIMPLEX) {
        /* At the settled alpha the certificate's feasible set can be a
         * single point, which an interior point approaches without
         * converging (met on a stack-bond wall): the simplex decides it,
         * on models small enough for it to be quick.  With alpha free
         * the certificate at the settled alpha comes next instead; on
         * larger models the simplex took minutes (3D models; 68,119
         * iterations on a 4,258-block wall, doc/seqlp.md 12), and the
         * certificate counts as failed (certify). */
        bl_solve_options so = *o;
        so.lp = BL_LP_SIMPLEX;
        bl_lp_free(r->lp_cone);
        r->lp_cone = bl_solve_lp(c, r->clo, r->chi, r->obj, &so, err);
        if (!r->lp_cone) return BL_LP_FAILED;
        st = bl_lp_solve(r->lp_cone);
    }
    s->lps++;
    s->iterations += bl_lp_iterations(r->lp_cone);
    return st;
}

/* The certificate's bounds in clo, chi: forces in Coulomb's cone that fit
 * the mechanism y of the last LP, its motions below slip times the largest
 * taken as none: no normal force (nor friction) where a point opens, on
 * the cone's edge against the slip where it slides, anywhere in the cone
 * where it stays closed; cohesion at its bound against the slip where the
 * point slides (opening or not), anywhere within its bounds elsewhere:
 * the yield surface of (T3) with its tension cut-off; a rigid joint
 * (mu = inf) carrying nothing where it slides and no shear where it opens
 * at every point, any shear elsewhere; alpha free. */
static void certificate_bounds(run *r, const double *y, double slip)
{
    const bl_system *c = r->cone;
    double V = point_motion(r, y);
    /* 3D: the power of every column of the cone (the tangential part,
     * -along, is what an edge resists per unit normal force) and, per
     * joint, the most an edge resists */
    double *best = c->dim == 3 ? r->resist : NULL, *along = r->w, *speed = r->speed;
    double eps = slip * V;
    if (best) {
        for (int p = 0; p < c->npoints; p++) best[p] = -INFINITY;
        bl_system_power(c, y, along);
        for (int j = 0; j < c->nforce; j++) {
            int p = c->col_point[j], g = c->lead[p];
            along[j] -= r->dn[p] * c->col_nt[3 * j];
            if (c->col_kind[j] == BL_COL_PYRAMID) best[g] = fmax(best[g], -along[j]);
        }
    }
    for (int j = 0; j < c->nforce; j++) {
        int p = c->col_point[j];
        double lo = c->lo[j], hi = c->hi[j];
        if (isinf(c->mu[p])) {
            if (r->slide[p] > eps || (c->col_kind[j] == BL_COL_NORMAL ? r->dn[p] : r->open[p]) > eps)
                lo = hi = 0.0;
        } else if (r->dn[p] > eps && c->col_kind[j] != BL_COL_COHESION) {
            lo = hi = 0.0; /* opening: no normal force, hence no friction */
        } else if (c->dim == 3) {
            /* 3D, sliding: friction only on the pyramid's edges (the
             * octagon's corner, or side) that resist the slip most, and
             * cohesion at its bounds against the slip.  Resistances within
             * slip times the joint's speed of the most count as the most:
             * an interior point's slip square to a side of the octagon is
             * square to it only to that accuracy (with 1e-9 instead, the
             * dome of models/ never certified, doc/seqlp.md 11). */
            int g = c->lead[p];
            if (speed[g] > eps) {
                if (c->col_kind[j] == BL_COL_PYRAMID && -along[j] < best[g] - slip * speed[g])
                    lo = hi = 0.0;
                if (c->col_kind[j] == BL_COL_COHESION && fabs(along[j]) > slip * speed[g])
                    lo = hi = along[j] > 0.0 ? c->lo[j] : c->hi[j];
            }
        } else if (fabs(r->dt[p]) > eps) {
            /* sliding: friction opposes the slip of b on a */
            int up = r->dt[p] > 0.0;
            if ((c->col_kind[j] == BL_COL_CONE_POS && up) ||
                (c->col_kind[j] == BL_COL_CONE_NEG && !up))
                lo = hi = 0.0;
            if (c->col_kind[j] == BL_COL_COHESION) lo = hi = up ? c->lo[j] : c->hi[j];
        }
        r->clo[j] = lo;
        r->chi[j] = hi;
    }
    r->clo[c->nforce] = -INFINITY;
    r->chi[c->nforce] = INFINITY;
}

/* Whether the certificate LP's answer at alpha, with the mechanism y,
 * passes bl_verify_nonassoc. */
static int verified(run *r, double alpha, const double *y, const bl_seqlp_options *so)
{
    bl_residuals res;
    return bl_verify_nonassoc(r->cone, r->fixed, alpha, bl_lp_primal(r->lp_cone), y,
                              so->base.tolerance, so->slip, &res);
}

/* One certificate on the bounds of certificate_bounds: Eq. 12 minimizes
 * alpha, and with the mechanism held the lowest alpha such forces carry is
 * an LP.  Its answer is kept when it passes the checks of
 * bl_verify_nonassoc; else (unbounded, or a force field that leans on
 * motions below the threshold) the forces at the LP's alpha, the settled
 * one.  Returns the LP status, the alpha in *cert and in *ok whether the
 * answer passed the checks. */
static bl_lp_status certificate(run *r, double alpha, const double *y,
                                const bl_seqlp_options *so, bl_solution *s, double *cert,
                                int *ok, bl_error *err)
{
    const bl_solve_options *o = &so->base;
    int na = r->cone->nforce;
    *ok = 0;
    bl_lp_status st = certificate_lp(r, o, 0.0, s, err);
    if (st == BL_LP_OPTIMAL && bl_lp_primal(r->lp_cone)[na] < r->floor) {
        /* forces fit the mechanism below the least alpha that may be
         * certified: at it, or not at all (bounding alpha in the LP
         * itself cost the interior point digits everywhere) */
        r->clo[na] = r->chi[na] = *cert = r->floor;
        bl_lp_free(r->lp_cone);
        r->lp_cone = NULL;
        st = certificate_lp(r, o, 0.0, s, err);
        if (st == BL_LP_FAILED && !r->lp_cone) return st;
        if (st == BL_LP_OPTIMAL) *ok = verified(r, *cert, y, so);
        return st == BL_LP_OPTIMAL && *ok ? st : BL_LP_INFEASIBLE;
    }
    if (st == BL_LP_OPTIMAL) {
        *cert = bl_lp_primal(r->lp_cone)[na];
        *ok = verified(r, *cert, y, so);
        if (o->verbose)
            fprintf(stderr, "seqlp certificate: lowest alpha %.8g, %s\n", *cert,
                    *ok ? "verified" : "not verified: at the LP's alpha");
        if (*ok) return st;
    } else if (o->verbose) {
        fprintf(stderr, "seqlp certificate: %s\n", st == BL_LP_INFEASIBLE ? "infeasible" : "no lowest alpha");
    }
    if (st != BL_LP_OPTIMAL && st != BL_LP_UNBOUNDED && st != BL_LP_ITERATION_LIMIT &&
        st != BL_LP_FAILED)
        return st;
    /* below what may be certified, or no settled alpha (a mechanism given) */
    if (!(alpha >= r->floor)) return BL_LP_INFEASIBLE;
    r->clo[na] = r->chi[na] = *cert = alpha;
    /* from scratch: the interior point re-solving from the lowest alpha's
     * path did not converge on the 3D 4,935-block wall (and handed the LP
     * to the simplex, for minutes) */
    bl_lp_free(r->lp_cone);
    r->lp_cone = NULL;
    st = certificate_lp(r, o, 0.0, s, err);
    if (st == BL_LP_OPTIMAL) *ok = verified(r, alpha, y, so);
    return st;
}

/* The certificate of the mechanism y of the LP at alpha; with it the
 * mechanism solves the seed's Eq. 12.  Motions below slip times the
 * largest count as none; when the answer does not pass the checks (a
 * slip just below the threshold that its forces work against: a random
 * wall of the tests at mu = 1, work residual 1.5e-4), the certificate is
 * tried again with slip / 10 and slip / 100, and the first that passes is
 * the answer; if none does, the default's, kept from its solve
 * (doc/seqlp.md 12).  Returns the LP status, with the certified alpha in
 * *cert and the forces in r->xc. */
static bl_lp_status certify(run *r, double alpha, const double *y, const bl_seqlp_options *so,
                            bl_solution *s, double *cert, bl_error *err)
{
    int ok;
    size_t nc = (size_t)r->cone->ncols;
    certificate_bounds(r, y, so->slip);
    bl_lp_status st = certificate(r, alpha, y, so, s, cert, &ok, err);
    if (st == BL_LP_OPTIMAL) memcpy(r->xc, bl_lp_primal(r->lp_cone), nc * sizeof *r->xc);
    double first = *cert;
    static const double finer[] = {0.1, 0.01};
    for (int k = 0; st == BL_LP_OPTIMAL && !ok && k < 2; k++) {
        certificate_bounds(r, y, finer[k] * so->slip);
        bl_lp_status sf = certificate(r, alpha, y, so, s, cert, &ok, err);
        if (sf == BL_LP_FAILED && !r->lp_cone) return sf;
        if (sf == BL_LP_OPTIMAL && ok) memcpy(r->xc, bl_lp_primal(r->lp_cone), nc * sizeof *r->xc);
    }
    if (st == BL_LP_OPTIMAL && !ok) *cert = first; /* the default's, its forces in r->xc */
    /* a certificate the interior point cannot finish decides nothing:
     * it counts as failed, and the sequence goes on */
    if ((st == BL_LP_ITERATION_LIMIT || st == BL_LP_FAILED) && r->lp_cone) return BL_LP_INFEASIBLE;
    if (st != BL_LP_OPTIMAL) return st;
    if (ok && *cert != alpha) return st;
    /* Verified only at the LP's alpha, or not at all: the lowest alpha
     * leaned on motions taken as none (lean_work).  The lowest alpha with a
     * cost of rho times that work, for rho = 10, 100, 1000 until one
     * passes, is kept instead when it is lower, or passes where nothing did
     * (the 4,935-block wall: 0.42272 at rho = 100 against 0.43178 at the
     * LP's alpha; in 3D 0.41994 against 0.42998, doc/seqlp.md 12). */
    for (double rho = 10.0; rho <= 1000.0; rho *= 10.0) {
        certificate_bounds(r, y, so->slip);
        bl_lp_status sl = certificate_lp(r, &so->base, rho, s, err);
        if (sl == BL_LP_FAILED && !r->lp_cone) return sl;
        if (sl != BL_LP_OPTIMAL) break;
        double al = bl_lp_primal(r->lp_cone)[r->cone->nforce];
        int pass = al >= r->floor && verified(r, al, y, so);
        if (so->base.verbose)
            fprintf(stderr, "seqlp certificate: with a cost %g on leaning, alpha %.8g, %s\n", rho,
                    al, pass ? "verified" : "not verified");
        if (!pass) continue;
        if (al < alpha || !ok) {
            *cert = al;
            memcpy(r->xc, bl_lp_primal(r->lp_cone), nc * sizeof *r->xc);
        }
        break;
    }
    return st;
}

static int append(bl_solution *s, double a)
{
    double *h = realloc(s->history, (size_t)(s->nhistory + 1) * sizeof *h);
    if (!h) return -1;
    h[s->nhistory++] = a;
    s->history = h;
    return 0;
}

/* Opens the history of a new start, whose first entry is the alpha it
 * starts from. */
static int start_history(bl_solution *s, double from)
{
    bl_start *st = realloc(s->start, (size_t)(s->nstarts + 1) * sizeof *st);
    if (!st) return -1;
    s->start = st;
    st[s->nstarts++] = (bl_start){.first = s->nhistory, .alpha = NAN, .search_mu = INFINITY};
    return append(s, from);
}

/* The number the user knows the current start by: a start that went on
 * after the restarts is the one it continues. */
static int start_number(const bl_solution *s)
{
    const bl_start *st = &s->start[s->nstarts - 1];
    return st->continues ? st->continues : s->nstarts;
}

/* LP lp of the start (numbered as in its history; its certificate: what =
 * "'s certificate") ended the run with status st: *stop, and, unless
 * Ctrl-C or the time limit (said elsewhere), a note that says where (a
 * note on an earlier start's infeasible LP read as the cause of
 * "numerical trouble"). */
static void stopped(bl_solution *s, bl_lp_status *stop, bl_lp_status st, int lp, const char *what)
{
    *stop = st;
    if (st != BL_LP_INTERRUPTED && st != BL_LP_TIME_LIMIT)
        snprintf(s->note, sizeof s->note, "start %d, LP %d%s ended with %s", start_number(s), lp, what,
                 bl_status_name(bl_status_of_lp(st)));
}

/* Writes into s->note which blocks the Farkas ray of the infeasible fixed
 * LP weighs on: those whose equilibrium the capacities cannot meet. */
static void name_blocks(run *r, bl_solution *s, int lp)
{
    const double *ray = bl_lp_ray(r->lp_fixed);
    const bl_model *m = s->model;
    size_t len = (size_t)snprintf(s->note, sizeof s->note,
                                  "start %d, LP %d had no equilibrium with the relaxed friction "
                                  "capacities", start_number(s), lp + 1);
    if (!ray) {
        snprintf(s->note + len, sizeof s->note - len, " (the LP engine did not say at which blocks)");
        return;
    }
    double big = 0.0;
    for (int i = 0; i < r->fixed->nrows; i++) big = fmax(big, fabs(ray[i]));
    int n = r->fixed->dim == 3 ? 6 : 3, total = 0, named = 0;
    for (int pass = 0; pass < 2; pass++) {
        for (int b = 0; b < m->nblocks; b++) {
            int row = r->fixed->block_row[b];
            if (row < 0) continue;
            double w = 0.0;
            for (int i = 0; i < n; i++) w = fmax(w, fabs(ray[row + i]));
            if (w < 1e-3 * big) continue;
            if (pass == 0) {
                total++;
            } else if (named < 8 && len < sizeof s->note) {
                len += (size_t)snprintf(s->note + len, sizeof s->note - len, "%s%d",
                                        named ? ", " : total == 1 ? " at block " : " at blocks ", b + 1);
                named++;
            }
        }
    }
    if (total > 8 && len < sizeof s->note)
        snprintf(s->note + len, sizeof s->note - len, " and %d more", total - 8);
}

/* After LP j (forces x, alpha a; the alpha before it prev):
 * the damping of beta and the normal forces of the next LP. */
static void relax(run *r, const bl_seqlp_options *o, int j, const double *x,
                  double a, double prev, double *beta, double *last, int *turns)
{
    const bl_system *f = r->fixed;
    /* Damping: from the 21st LP on, every third reversal of alpha halves
     * beta, down to a tenth of it.  The first 20 keep beta: a sequence
     * converges or swings on to another solution there (the stack-bond
     * wall's lower answer came from such a swing); one that keeps
     * oscillating (the corner model: +-0.3 % for 100 LPs) then slows down
     * until a certificate succeeds (doc/seqlp.md 6). */
    if (fabs(a - prev) > o->settle * fabs(a)) {
        if (j >= 20 && (a - prev) * *last < 0.0 && ++*turns % 3 == 0 && *beta > 0.1 * o->beta)
            *beta *= 0.5;
        *last = a - prev;
    }
    /* relax the normal forces towards this LP's */
    for (int p = 0; p < f->npoints; p++) r->n[p] *= 1.0 - *beta;
    for (int k = 0; k < f->nforce; k++)
        if (f->col_kind[k] == BL_COL_NORMAL) r->n[f->col_point[k]] += *beta * x[k];
}

/* The nearest forces, after a failed certificate of the LP at alpha a
 * with mechanism y: forces in Coulomb's cone at that alpha that fit the
 * mechanism as the certificate asks, except that the columns it forbids
 * (the cone's edges where a point opens, and with the slip where it
 * slides) are allowed at a cost of one per unit: the least total force on
 * them.  Their normal forces become the next LP's, unrelaxed (seqlp.h,
 * BL_SEQLP_NEAREST; doc/seqlp.md 12).  The LP is made anew each time, in
 * lp_cone's place (its objective changes with the forbidden columns; a
 * third LP of the cone's size took 400 MB more at 4,935 blocks in 3D).
 * Unless it is optimal r->n stays the relaxed one.  Returns 0, or -1 when
 * the LP could not be made (err). */
static int nearest_forces(run *r, double a, const double *y, const bl_seqlp_options *o,
                          bl_solution *s, bl_error *err)
{
    const bl_system *c = r->cone;
    int na = c->nforce;
    certificate_bounds(r, y, o->slip);
    for (int j = 0; j < c->ncols; j++) r->obj[j] = 0.0;
    for (int j = 0; j < na; j++) {
        int k = c->col_kind[j];
        if ((k == BL_COL_CONE_POS || k == BL_COL_CONE_NEG || k == BL_COL_PYRAMID) &&
            r->chi[j] == 0.0 && c->hi[j] > 0.0) {
            r->clo[j] = c->lo[j];
            r->chi[j] = c->hi[j];
            r->obj[j] = -1.0; /* maximized: the least force */
        }
    }
    r->clo[na] = r->chi[na] = a;
    bl_lp_free(r->lp_cone);
    r->cone_other = 1;
    bl_lp *lp = r->lp_cone = bl_solve_lp(c, r->clo, r->chi, r->obj, &o->base, err);
    if (!lp) return -1;
    bl_lp_status st = bl_lp_solve(lp);
    s->lps++;
    s->iterations += bl_lp_iterations(lp);
    s->start[s->nstarts - 1].nearest++;
    double lent = 0.0;
    if (st == BL_LP_OPTIMAL) {
        const double *x = bl_lp_primal(lp);
        for (int p = 0; p < r->fixed->npoints; p++) r->n[p] = 0.0;
        for (int j = 0; j < na; j++) {
            r->n[c->col_point[j]] += c->col_nt[c->dim * j] * x[j];
            if (r->obj[j] != 0.0) lent += x[j];
        }
    }
    if (o->base.verbose) {
        if (st == BL_LP_OPTIMAL)
            fprintf(stderr, "seqlp nearest forces: %.4g W0 on the forbidden columns\n", lent);
        else
            fprintf(stderr, "seqlp nearest forces: %s, the relaxed ones kept\n",
                    st == BL_LP_INFEASIBLE ? "infeasible" : "no answer");
    }
    return 0;
}

/* Keeps a certificate's answer (alpha ac, of the LP at a with mechanism
 * y; its forces in r->xc) when it is the lowest yet; early: 1 where that
 * LP came before its sequence settled, -k for the k-th mechanism given
 * (bl_seqlp_options), which belongs to no start. */
static void keep_certified(run *r, bl_solution *s, double ac, double a, const double *y, int early)
{
    if (early >= 0) s->start[s->nstarts - 1].alpha = ac; /* (< 0: a mechanism given, no start) */
    /* a mechanism given replaces the starts' answer only below its round-off */
    double tie = early < 0 ? 1e-9 * fabs(r->best_alpha) : 0.0;
    if (r->found && ac >= r->best_alpha - tie) return;
    r->found = 1;
    r->best_alpha = ac;
    r->best_settled = a;
    r->best_early = early > 0;
    r->best_given = early < 0 ? -early : 0;
    memcpy(r->best_x, r->xc, (size_t)r->cone->ncols * sizeof *r->best_x);
    memcpy(r->best_y, y, (size_t)r->fixed->nrows * sizeof *r->best_y);
}

/* A certificate on another thread (certify, beside the next fixed LP). */
typedef struct beside_cert {
    run *r;
    double alpha, cert;
    const double *y;
    const bl_seqlp_options *o;
    bl_solution *s;
    bl_lp_status status;
    bl_error err;
} beside_cert;

static void *certify_beside(void *arg)
{
    beside_cert *c = arg;
    c->status = certify(c->r, c->alpha, c->y, c->o, c->s, &c->cert, &c->err);
    return NULL;
}

/* The options the fixed LPs are made with: o's, except that a 3D one
 * with more than BL_SEQLP_IPM_COLUMNS3 columns and 5 per row takes the
 * interior point where "auto" would take the simplex (seqlp.h). */
static bl_solve_options fixed_options(const bl_system *f, const bl_solve_options *o)
{
    bl_solve_options fo = *o;
    if (f->dim == 3 && o->lp == BL_LP_AUTO && f->ncols > BL_SEQLP_IPM_COLUMNS3 && f->ncols > 5 * f->nrows)
        fo.lp = BL_LP_IPM;
    return fo;
}

/* Whether the certificate of a settled LP can run beside the next fixed
 * LP: both on the interior point, each leaving the other a core (lp.h),
 * and no verbose lines to interleave.  Most certificates fail and the next
 * LP is needed anyway; when one passes, that LP is taken back
 * (bl_lp_rewind), so every start, LP and answer is the one-thread run's. */
static int certify_ahead(const run *r, const bl_seqlp_options *o)
{
    const bl_solve_options *b = &o->base;
    return !b->verbose && strcmp(bl_lp_engine(r->lp_fixed), "ipm") == 0 &&
           bl_lp_choose(b->lp, r->cone->nrows, r->cone->ncols) == BL_LP_IPM &&
           bl_lp_leaves_core(fixed_options(r->fixed, b).lp, b->threads, r->fixed->nrows, r->fixed->ncols) &&
           bl_lp_leaves_core(b->lp, b->threads, r->cone->nrows, r->cone->ncols);
}

/* The fixed LP's bounds from the normal forces r->n, at this start's
 * friction (r->fixed has every joint's own, and rigid ones'
 * BL_SEQLP_MU_RIGID): R = mu N + C scaled in its friction part. */
static void fixed_bounds(run *r)
{
    const bl_system *f = r->fixed;
    bl_system_fixed_bounds(f, r->n, r->lo, r->hi);
    for (int j = 0; j < f->nforce; j++) {
        int p = f->col_point[j];
        if ((f->col_kind[j] != BL_COL_SHEAR && f->col_kind[j] != BL_COL_TWIST) || !(f->mu[p] > 0.0) ||
            !isfinite(r->hi[j]))
            continue;
        double mu = search_mu(r->cone->mu[p], r->mu_rigid, r->mu_cap);
        if (mu == f->mu[p]) continue;
        double C = f->cohesion[p], R = (r->hi[j] - C) * (mu / f->mu[p]) + C;
        r->lo[j] = -R;
        r->hi[j] = R;
    }
}

/* Sets the friction of the search, and the system its stress states
 * come from, at turn 0 (start 0) with every joint's own friction (rigid
 * ones at BL_SEQLP_MU_RIGID), at turn k > 0 (the restarts' k-th
 * friction) at the k-th of BL_SEQLP_MU_TRIED in turn, rigid joints at it
 * and others at most at it: a low friction lets the search find
 * mechanisms that open as they slide, which high friction hides (W1 at
 * mu = 20: 1.861 instead of 0.686; doc/seqlp.md 16), and at k < 0 (the
 * restarts after a search, BL_SEQLP_LOW_STARTS) its finite frictions at
 * most BL_SEQLP_LOW of the highest.  -1 with err set when the system
 * cannot be made. */
static int search_friction(run *r, int k, bl_error *err)
{
    static const double tried[] = BL_SEQLP_MU_TRIED;
    int ntried = (int)(sizeof tried / sizeof tried[0]);
    double rigid = BL_SEQLP_MU_RIGID, cap = INFINITY;
    if (k < 0) { /* BL_SEQLP_LOW of the highest finite friction, rigid joints as in start 0 */
        double top = 0.0;
        for (int j = 0; j < r->model->ninterfaces; j++)
            if (isfinite(r->model->interfaces[j].mu)) top = fmax(top, r->model->interfaces[j].mu);
        cap = BL_SEQLP_LOW * top;
    } else if (k > 0) {
        rigid = cap = tried[(k - 1) % ntried];
    }
    if (rigid == r->mu_rigid && cap == r->mu_cap) return 0;
    r->mu_rigid = rigid;
    r->mu_cap = cap;
    bl_system *st = search_differs(r->model, rigid, cap)
                        ? search_system(r->model, &r->pyramid, BL_FRICTION_CONE, rigid, cap, err)
                        : r->cone;
    if (!st) return -1;
    if (r->states != r->cone) bl_system_free(r->states);
    r->states = st;
    return 0;
}

/* What a start carries from one fixed LP to the next besides the normal
 * forces (r->n), so that a start cut at its cap can
 * go on where it stopped (bl_seqlp_solve). */
typedef struct start_state {
    double beta, last; /* the relaxation and the last change of alpha */
    double prev;       /* the alpha before the next LP */
    int turns, fails;  /* reversals of alpha; failed certificates */
    int done, cap;     /* fixed LPs solved; the last one allowed */
} start_state;

static start_state fresh_start(const bl_seqlp_options *o, double from)
{
    return (start_state){.beta = o->beta, .prev = from, .cap = o->max_lps};
}

/* One start, or the rest of one: LPs with fixed shear capacities from the
 * normal forces r->n until alpha settles and a certificate is found
 * (returns 1, and keeps the answer in r->best when it is the lowest yet),
 * the cap is reached (0, with ss->done == ss->cap) or an LP fails (0, with
 * *stop set for a failure that should end the whole run), or an error
 * (-1). */
static int one_start(run *r, const bl_seqlp_options *o, bl_solution *s, start_state *ss,
                     bl_lp_status *stop, bl_error *err)
{
    const bl_system *f = r->fixed;
    bl_solve_options fo = fixed_options(f, &o->base);
    *stop = BL_LP_OPTIMAL;
    double beta = ss->beta, last = ss->last, prev = ss->prev;
    int turns = ss->turns;
    int ahead = 0; /* LP j was solved beside the certificate of LP j - 1 */
    int fails = ss->fails; /* failed certificates of this start */
    int nearest = o->nearest >= 0 ? o->nearest : BL_SEQLP_NEAREST;
    bl_lp_status st = BL_LP_OPTIMAL;
    int j;
    for (j = ss->done; j < ss->cap; j++) {
        if (!ahead) {
            fixed_bounds(r);
            if (!r->lp_fixed) {
                r->lp_fixed = bl_solve_lp(f, r->lo, r->hi, NULL, &fo, err);
                if (!r->lp_fixed) return -1;
                if (r->warm) path_warm(r->warm, r->lp_fixed);
                r->warm = NULL;
            } else {
                bl_lp_set_bounds(r->lp_fixed, r->lo, r->hi);
            }
            st = bl_lp_solve(r->lp_fixed);
        }
        ahead = 0;
        int least_now = 0; /* the least normal force tried on this LP */
        if ((st == BL_LP_ITERATION_LIMIT || st == BL_LP_FAILED) && !r->least_n &&
            strcmp(bl_lp_engine(r->lp_fixed), "ipm") == 0) {
            /* Blocks confined between supports (a wall between two
             * abutments) can carry any compression across them: the
             * fixed LP's optimal force fields are then unbounded, and the
             * interior point, heading for the centre of that face, does
             * not converge.  From here on the fixed LPs take, among their
             * optimal force fields, one with the least total normal force
             * (BL_LEAST_N): a bounded face, and for friction the
             * conservative choice (doc/seqlp.md 13). */
            r->least_n = least_now = 1;
            bl_system_cost_normal(f, BL_LEAST_N, r->fixed->obj);
            s->lps++;
            s->iterations += bl_lp_iterations(r->lp_fixed);
            if (o->base.verbose)
                fprintf(stderr, "seqlp start %d LP %d: no convergence, again with the least normal "
                                "force\n", start_number(s), j + 1);
            bl_lp_free(r->lp_fixed);
            r->lp_fixed = bl_solve_lp(f, r->lo, r->hi, NULL, &fo, err);
            if (!r->lp_fixed) return -1;
            st = bl_lp_solve(r->lp_fixed);
        }
        int ipm = strcmp(bl_lp_engine(r->lp_fixed), "ipm") == 0;
        if ((st == BL_LP_FAILED || (st == BL_LP_ITERATION_LIMIT && o->base.iterations == 0)) &&
            o->base.lp == BL_LP_AUTO && !r->switched && (!ipm || bl_simplex_rescues(s->model, f->nrows))) {
            /* Under lp = "auto", once per run, the other engine solves an
             * LP that this one cannot finish, and every later fixed LP of
             * the run.  Round-off can stop the interior point short of the
             * answer (an arch of 1,500 voussoirs at mu = inf): as in the
             * associative solve, the simplex, from its basis then, with
             * its own objective if the least normal force did not help
             * (its cost moved the mechanism: admissibility 1.3e-7 on that
             * arch).  The simplex can cycle among degenerate bases (a
             * two-bay arcade at mu = inf: its cap after 14 s, at LP 20,
             * where the interior point certified 0.2100). */
            if (least_now && ipm) {
                r->least_n = 0;
                bl_system_cost_normal(f, -BL_LEAST_N, r->fixed->obj);
            }
            s->lps++;
            s->iterations += bl_lp_iterations(r->lp_fixed);
            if (o->base.verbose)
                fprintf(stderr, "seqlp start %d LP %d: %s, again on the %s\n", start_number(s), j + 1,
                        st == BL_LP_FAILED ? "the engine failed" : "the engine's iteration cap",
                        ipm ? "simplex" : "interior point");
            bl_solve_options other = o->base;
            other.lp = ipm ? BL_LP_SIMPLEX : BL_LP_IPM;
            bl_lp_free(r->lp_fixed);
            r->lp_fixed = bl_solve_lp(f, r->lo, r->hi, NULL, &other, err);
            if (!r->lp_fixed) return -1;
            st = bl_lp_solve(r->lp_fixed);
            r->switched = 1;
        }
        s->lps++;
        s->iterations += bl_lp_iterations(r->lp_fixed);
        if (st == BL_LP_UNBOUNDED && r->bounded) {
            /* Whether a fixed LP is unbounded does not depend on its
             * capacities (its dual, a mechanism, is feasible or not
             * whatever they are): after one with an answer, this one's
             * capacities have grown past what the engine tells from
             * unbounded, and the start ends uncertified. */
            snprintf(s->note, sizeof s->note,
                     "start %d, LP %d: the relaxed friction capacities grew without bound",
                     start_number(s), j + 2);
            return 0;
        }
        if (st != BL_LP_OPTIMAL) {
            /* Infeasible: the relaxed normal forces cannot carry some block
             * by friction alone (DESIGN 2.4); this start ends uncertified. */
            if (st == BL_LP_INFEASIBLE) name_blocks(r, s, j + 1);
            else stopped(s, stop, st, j + 2, "");
            return 0;
        }
        const double *x = bl_lp_primal(r->lp_fixed), *y = bl_lp_dual(r->lp_fixed);
        double a = x[f->nforce];
        if (!r->bounded) r->first_alpha = a;
        r->bounded = 1;
        if (append(s, a)) return bl_error_set(err, "solve: out of memory");
        if (o->base.verbose)
            fprintf(stderr, "seqlp start %d LP %d: alpha %.8g\n", start_number(s), j + 1, a);
        else if (o->progress && bl_clock() - r->t0 > 0.5) {
            char of[24] = "", low[40] = "";
            if (r->planned - s->skipped > 1) snprintf(of, sizeof of, " of %d", r->planned - s->skipped);
            if (r->found) snprintf(low, sizeof low, ", lowest certified %.6g", r->best_alpha);
            fprintf(stderr, "\rseqlp: start %d%s, LP %d, alpha %.6g%s   ", start_number(s), of, j + 1, a,
                    low);
            r->shown = 1;
        }
        int near_now = 0; /* the nearest forces follow this LP's failed certificate */
        /* (after an unbounded associative LP, prev is infinite: its
         * frictionless first LP is certified at once) */
        if (fabs(a - prev) <= o->settle * fabs(a) || isinf(prev)) {
            bl_lp_status cs;
            beside_cert c = {.r = r, .alpha = a, .y = r->yc, .o = o, .s = s};
            pthread_t other;
            /* the next LP waits for the nearest forces once they follow */
            int near_next = nearest > 0 && fails + 1 >= nearest;
            s->start[s->nstarts - 1].certificates++;
            if (j + 1 < ss->cap && !near_next && certify_ahead(r, o) &&
                bl_lp_mark(r->lp_fixed) == 0) {
                /* the certificate on another thread, the next LP here */
                memcpy(r->yc, y, (size_t)f->nrows * sizeof *r->yc);
                relax(r, o, j, x, a, prev, &beta, &last, &turns);
                fixed_bounds(r);
                bl_lp_set_bounds(r->lp_fixed, r->lo, r->hi);
                int two = pthread_create(&other, NULL, certify_beside, &c) == 0;
                if (!two) certify_beside(&c);
                st = bl_lp_solve(r->lp_fixed);
                if (two) pthread_join(other, NULL);
                cs = c.status;
                ahead = cs == BL_LP_INFEASIBLE;
                if (!ahead) bl_lp_rewind(r->lp_fixed);
                y = r->yc;
            } else {
                cs = certify(r, a, y, o, s, &c.cert, &c.err);
            }
            if (cs == BL_LP_FAILED && !r->lp_cone) {
                bl_error_set(err, "%s", c.err.msg);
                return -1;
            }
            if (cs == BL_LP_OPTIMAL) {
                keep_certified(r, s, c.cert, a, y, 0);
                return 1;
            }
            if (cs != BL_LP_INFEASIBLE) {
                stopped(s, stop, cs, j + 2, "'s certificate");
                return 0;
            }
            fails++;
            near_now = near_next;
        } else if (r->found && a < r->best_alpha - o->settle * fabs(r->best_alpha)) {
            /* Below the lowest certified alpha before it settles: its
             * mechanism can be a solution the next LPs leave (their
             * forces load a joint that slides without opening in it).
             * A wall 0.5 x 3 beside a buttress, pulled away from it,
             * rocks whole about its toe at b/h = 1/6 where that joint
             * carries nothing; restarts reached 1/6 in their first LP
             * and moved on to 0.25 (doc/seqlp.md 18).  Kept only above
             * the floor: there such a certificate found a mechanism that
             * does no work at all (W4 in 3D: a jamb's half block
             * turning about a vertical hinge, hung by friction on its
             * head joint, alpha = 0), which no settled sequence reached. */
            double cert;
            s->start[s->nstarts - 1].certificates++;
            bl_lp_status cs = certify(r, a, y, o, s, &cert, err);
            if (cs == BL_LP_FAILED && !r->lp_cone) return -1;
            if (cs == BL_LP_OPTIMAL && cert > r->floor + o->settle * fabs(r->best_alpha)) {
                keep_certified(r, s, cert, a, y, 1);
                return 1;
            }
            if (cs == BL_LP_INTERRUPTED || cs == BL_LP_TIME_LIMIT) {
                stopped(s, stop, cs, j + 2, "'s certificate");
                return 0;
            }
        }
        if (!ahead) relax(r, o, j, x, a, prev, &beta, &last, &turns);
        /* damping as relaxed, the normal forces the nearest */
        if (near_now && nearest_forces(r, a, y, o, s, err)) return -1;
        prev = a;
    }
    *ss = (start_state){beta, last, prev, turns, fails, j, ss->cap};
    return 0;
}

/* The mechanisms given (bl_seqlp_options), each tried as a certificate
 * after the starts: a parameter study hands on its last answer (W1 under
 * a floor at mu = 1.0500000000000003, from a loop, certified 0.613618 by
 * default and 0.557536, its answer at the mu before, so; doc/seqlp.md
 * 18).  A stop (Ctrl-C, the time limit) sets *stop and, 1-based, *given.
 * Returns 0, or -1 with err set. */
static int try_given(run *r, const bl_seqlp_options *o, bl_solution *s, bl_lp_status *stop, int *given,
                     bl_error *err)
{
    const bl_system *f = r->fixed;
    const bl_model *mc = s->model;
    size_t per = (size_t)(mc->dim == 3 ? 6 : 3) * (size_t)mc->nblocks;
    for (int k = 0; k < o->nmechanisms; k++) {
        bl_lp_status cs = bl_interrupt_pending() ? BL_LP_INTERRUPTED
                          : o->base.deadline > 0 && bl_clock() > o->base.deadline ? BL_LP_TIME_LIMIT
                                                                                  : BL_LP_INFEASIBLE;
        if (cs != BL_LP_INFEASIBLE) {
            *stop = cs;
            *given = k + 1;
            return 0;
        }
        /* its rows, scaled so that the live load does unit work on it, as
         * on an LP's mechanism; none where it does none */
        bl_system_rows_of_mechanism(f, mc, o->mechanisms + (size_t)k * per, r->yc);
        double work = 0.0, cert;
        for (int q = f->colptr[f->nforce]; q < f->colptr[f->nforce + 1]; q++)
            work += f->val[q] * r->yc[f->rowind[q]];
        s->given_tried++;
        if (work > 0.0 && isfinite(work)) {
            for (int i = 0; i < f->nrows; i++) r->yc[i] /= work;
            /* (no settled alpha to fall back to: its lowest alpha, verified, or nothing) */
            cs = certify(r, NAN, r->yc, o, s, &cert, err);
            if (cs == BL_LP_FAILED && !r->lp_cone) return -1;
        }
        if (o->base.verbose)
            fprintf(stderr, "seqlp mechanism %d given: %s\n", k + 1,
                    !(work > 0.0) ? "the live load does no work on it"
                    : cs == BL_LP_OPTIMAL ? "certified" : "not certified");
        if (cs == BL_LP_INTERRUPTED || cs == BL_LP_TIME_LIMIT) {
            *stop = cs;
            *given = k + 1;
            return 0;
        }
        if (cs == BL_LP_OPTIMAL) {
            s->given_certified++;
            keep_certified(r, s, cert, cert, r->yc, -(k + 1));
        }
    }
    return 0;
}

/* one_start with a history of its own (continuing the 1-based start
 * `continues`, or 0) and what it cost: the LPs and iterations since lps0
 * and its0 and the time since t0, which include the LP of a restart's
 * random state. */
static int timed_start(run *r, const bl_seqlp_options *o, bl_solution *s, start_state *ss,
                       int continues, int lps0, int its0, double t0, bl_lp_status *stop,
                       bl_error *err)
{
    if (start_history(s, ss->prev)) return bl_error_set(err, "solve: out of memory");
    s->start[s->nstarts - 1].continues = continues;
    int done = one_start(r, o, s, ss, stop, err);
    bl_start *st = &s->start[s->nstarts - 1];
    st->lps = s->lps - lps0;
    st->iterations = s->iterations + r->iterations - its0;
    st->seconds = bl_clock() - t0;
    return done;
}

/* splitmix64: a small, well-mixed generator; the same seed gives the same
 * starts on every machine. */
static double uniform(unsigned long long *state)
{
    unsigned long long z = (*state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1.0p-53;
}

/* Solves the random state's LP on the cone system's bounds in clo, chi and
 * the objective obj (freeing *lp first); -1 when it cannot be made. */
static int state_lp(run *r, const bl_solve_options *o, bl_lp **lp, bl_lp_status *st,
                    bl_error *err)
{
    bl_lp_free(*lp);
    *lp = bl_solve_lp(r->states, r->clo, r->chi, r->obj, o, err);
    if (!*lp) return -1;
    *st = bl_lp_solve(*lp);
    r->iterations += bl_lp_iterations(*lp);
    return 0;
}

/* The normal forces of a stress state's LP (of r->states) in r->n where it
 * is optimal; frees the LP. */
static void state_forces(run *r, bl_lp *lp, bl_lp_status st)
{
    const bl_system *c = r->states;
    if (st == BL_LP_OPTIMAL) {
        const double *x = bl_lp_primal(lp);
        for (int q = 0; q < c->npoints; q++) r->n[q] = 0.0;
        for (int j = 0; j < c->nforce; j++) r->n[c->col_point[j]] += x[j] * c->col_nt[c->dim * j];
    }
    bl_lp_free(lp);
}

/* Start 0's normal forces where some joint is rigid, and a retry's: the
 * associative answer's in r->states (rigid joints at the search's
 * friction), which loads them no more than the fixed LPs let them carry
 * (the associative forces with mu = inf leaned on the shear of joints
 * with no normal force: a dome's first fixed LP had no equilibrium).
 * r->n as it was unless that LP is optimal; its status in *status.  -1
 * with err set when it cannot be made. */
static int search_start(run *r, const bl_seqlp_options *o, bl_solution *s, bl_lp_status *status,
                        bl_error *err)
{
    const bl_system *c = r->states;
    for (int j = 0; j < c->ncols; j++) {
        r->clo[j] = c->lo[j];
        r->chi[j] = c->hi[j];
        r->obj[j] = c->obj[j];
    }
    bl_lp *lp = NULL;
    bl_lp_status st;
    if (state_lp(r, &o->base, &lp, &st, err)) return -1;
    s->lps++;
    state_forces(r, lp, st);
    *status = st;
    return 0;
}

/* Another admissible stress state (the seed's Eq. 22): maximize a random
 * c . x, c uniform in [0, 1), over equilibrium and the Coulomb cone (of
 * r->states) with alpha fixed, or with least set minimize it; its normal
 * forces seed the next start.  The seed draws these states at the
 * current alpha and maximizes; the caller draws alpha uniformly below the
 * best so far instead, because on a stack-bond wall (3 columns of 12
 * blocks, mu = 5) states at the best alpha, 0.5714, never led elsewhere,
 * while states below it led to certified answers down to 0.2078 in 20
 * starts; and every other restart minimizes, because the most loaded
 * states load every joint and, at high friction, none of their sequences
 * let a joint slide where it carries nothing: the mechanisms that rock
 * while blocks part along joints, which the least loaded states leave
 * unloaded (W4 at mu = 2 to 100: 0.3182 to 0.4571 in every one of six
 * seeds, where the pier rocking at 0.2637 is a solution; doc/seqlp.md
 * 17).  The LP status in *status; -1 (err set) when the LP cannot be
 * made. */
static int random_state(run *r, double alpha, int least, unsigned long long *rng,
                        const bl_seqlp_options *o, bl_lp_status *status, bl_error *err)
{
    const bl_system *c = r->states;
    for (int j = 0; j < c->nforce; j++) {
        r->clo[j] = c->lo[j];
        r->chi[j] = c->hi[j];
        r->obj[j] = least ? -uniform(rng) : uniform(rng);
    }
    r->clo[c->nforce] = r->chi[c->nforce] = alpha;
    r->obj[c->nforce] = 0.0;
    bl_lp *lp = NULL;
    bl_lp_status st;
    const bl_solve_options *so = &o->base;
    if (state_lp(r, so, &lp, &st, err)) return -1;
    /* The state only seeds the normal forces: where the interior point
     * does not reach the tolerance, 1e-6 is enough (the 10,050-block
     * wall's state met 1e-8 but for a primal residual that round-off kept
     * near 1e-6 for 180 iterations, doc/seqlp.md 14). */
    bl_solve_options loose = o->base;
    loose.lp_tolerance = fmax(loose.lp_tolerance, 1e-6);
    if (st == BL_LP_ITERATION_LIMIT || st == BL_LP_FAILED) {
        so = &loose;
        if (state_lp(r, so, &lp, &st, err)) return -1;
    }
    if (st == BL_LP_UNBOUNDED || st == BL_LP_ITERATION_LIMIT || st == BL_LP_FAILED) {
        /* Blocks confined between supports can carry any compression,
         * and c . x then has no maximum (doc/seqlp.md 13): the state
         * maximizes c . x - sum n instead, every unit of normal force
         * costing more than its c gives. */
        bl_system_cost_normal(c, 1.0, r->obj);
        if (state_lp(r, so, &lp, &st, err)) return -1;
    }
    state_forces(r, lp, st);
    *status = st;
    return 0;
}

/* The cone system of the model with every joint rigid against sliding. */
static bl_system *rigid_system(const bl_model *m, const bl_cone *pyramid, bl_error *err)
{
    bl_model *c = bl_model_copy(m);
    if (!c) {
        bl_error_set(err, "solve: out of memory");
        return NULL;
    }
    for (int k = 0; k < c->ninterfaces; k++) c->interfaces[k].mu = INFINITY;
    bl_system *s = build(c, pyramid, BL_FRICTION_CONE, err);
    bl_model_free(c);
    return s;
}

/* Whether the live load is the self weight along gravity, and nothing but
 * weights (the blocks' and carried ones) loads the model. */
static int live_scales_dead(const bl_model *m)
{
    if (!m->self_weight || !m->live_weight) return 0;
    for (int l = 0; l < m->nloads; l++)
        if (!(m->loads[l].weight > 0.0)) return 0;
    if (m->dim == 3) return bl_v3_norm(bl_v3_sub(m->live_dir3, bl_model_gravity3(m))) < 1e-12;
    return bl_v2_norm(bl_v2_sub(m->live_dir, bl_model_gravity(m))) < 1e-12;
}

/* Whether normal forces alone carry the live load (no friction, no dead
 * load: the fixed LP without capacities and with a right-hand side of
 * zero is unbounded).  Such forces x_L give every mechanism u, in any flow
 * rule, a live work f_L . u = -x_L . (A^T u) <= 0, for they push only
 * where the joints close: no mechanism moves, and alpha is infinite
 * whether the joints dilate or not.  1 yes, 0 no or not decided, -1 with
 * err set (out of memory, or an LP that could not be made). */
static int live_on_normals(const bl_model *m, const bl_cone *pyramid, const bl_solve_options *o,
                           bl_error *err)
{
    bl_system *f = search_system(m, pyramid, BL_FRICTION_FIXED, BL_SEQLP_MU_RIGID, INFINITY, err);
    if (!f) return -1;
    double *n = calloc((size_t)f->npoints + 1, sizeof *n);
    double *lo = malloc((size_t)f->ncols * sizeof *lo), *hi = malloc((size_t)f->ncols * sizeof *hi);
    int yes = -1;
    if (!n || !lo || !hi) bl_error_set(err, "solve: out of memory");
    if (n && lo && hi) {
        bl_system_fixed_bounds(f, n, lo, hi);
        for (int i = 0; i < f->nrows; i++) f->rhs[i] = 0.0;
        bl_lp *lp = bl_solve_lp(f, lo, hi, NULL, o, err);
        yes = lp ? bl_lp_solve(lp) == BL_LP_UNBOUNDED : -1;
        bl_lp_free(lp);
    }
    free(n), free(lo), free(hi);
    bl_system_free(f);
    return yes;
}

/* The LP with unlimited friction, solved on the calling thread or another.
 * It is made on the calling thread: METIS, which orders the interior
 * point's factor when an LP is made, draws from one generator for the
 * whole process, and two orderings at once changed the sequence's path. */
typedef struct rigid_lp {
    bl_system *system;
    bl_lp *lp;
    bl_lp_status status;
} rigid_lp;

static void *solve_rigid(void *arg)
{
    rigid_lp *j = arg;
    j->status = bl_lp_solve(j->lp);
    return NULL;
}

/* Waits for the LP with unlimited friction, puts its answer in s and frees
 * it. */
static void rigid_answer(run *r, rigid_lp *j, bl_solution *s)
{
    if (r->rigid_beside) pthread_join(r->rigid_thread, NULL);
    r->rigid_beside = 0;
    s->lps++;
    if (j->lp) s->iterations += bl_lp_iterations(j->lp);
    s->alpha_rigid = j->status == BL_LP_OPTIMAL     ? bl_lp_primal(j->lp)[j->system->nforce]
                     : j->status == BL_LP_UNBOUNDED ? INFINITY
                                                    : NAN;
    /* (not with rigid joints, whose shear the associative forces may
     * carry across a joint that opens: doc/theory.md 6) */
    s->assoc_is_solution = fabs(s->alpha_rigid - s->alpha_assoc) <=
                               1e-7 * fmax(1.0, fabs(s->alpha_assoc)) &&
                           !has_rigid(s->model);
    bl_lp_free(j->lp);
    bl_system_free(j->system);
    j->lp = NULL;
    j->system = NULL;
}

static void *run_path(void *arg)
{
    path_job *j = arg;
    j->status = bl_napath_run(j->system, BL_SEQLP_PATH_PRODUCTS, BL_SEQLP_PATH_NEAR,
                              BL_SEQLP_PATH_DEEP, BL_SEQLP_PATH_STEPS, j->deadline, &j->cancel,
                              j->report, j->x, j->zl, j->zu, j->y, &j->res, &j->err);
    return NULL;
}

/* Stops the path (its answer is no longer wanted) and frees it. */
static void path_free(path_job *j)
{
    if (j->beside) {
        atomic_store(&j->cancel, 1);
        pthread_join(j->thread, NULL);
    }
    j->beside = 0;
    bl_system_free(j->system);
    free(j->x);
    free(j->zl);
    free(j->zu);
    free(j->y);
    j->system = NULL;
    j->x = j->zl = j->zu = j->y = NULL;
}

/* Starts the path for m (2D, its contacts detected) when o asks for it and
 * it applies: beside the associative solve where there are two cores, else
 * at once.  -1 with err set when the system cannot be made. */
static int path_start(bl_model *m, const bl_seqlp_options *o, path_job *j, bl_error *err)
{
    j->status = 1;
    if (!o->path || m->dim != 2) return 0;
    j->system = bl_system_build(m, BL_FRICTION_FIXED, err);
    if (!j->system) return -1;
    const bl_system *f = j->system;
    /* by default only where the fixed LPs run on the interior point (from
     * the path the simplex's sequences took more LPs on W1 and W4 and
     * ended higher on W5) and up to BL_SEQLP_PATH_ROWS (doc/seqlp.md 15) */
    if (o->path < 0 &&
        (bl_lp_choose(o->base.lp, f->nrows, f->ncols) != BL_LP_IPM || f->nrows > BL_SEQLP_PATH_ROWS)) {
        path_free(j);
        return 0;
    }
    size_t nc = (size_t)f->ncols, nr = (size_t)f->nrows;
    if (bl_napath_applies(f)) {
        j->x = malloc(nc * sizeof *j->x);
        j->zl = malloc(nc * sizeof *j->zl);
        j->zu = malloc(nc * sizeof *j->zu);
        j->y = malloc(nr * sizeof *j->y);
    }
    if (!j->x || !j->zl || !j->zu || !j->y) {
        path_free(j);
        return 0;
    }
    j->deadline = o->base.deadline;
    j->report = o->base.verbose ? BL_NAPATH_VERBOSE
                : o->progress     ? BL_NAPATH_PROGRESS
                                  : BL_NAPATH_QUIET;
    /* beside the associative solve on a second core: the path runs on one
     * thread and is the longer of the two; where the LP uses both cores
     * they share them, and the run still takes 5-10 % less than one after
     * the other (doc/seqlp.md 15) */
    if (!o->base.verbose && bl_lp_cores(o->base.threads) >= 2)
        j->beside = pthread_create(&j->thread, NULL, run_path, j) == 0;
    if (!j->beside) run_path(j);
    return 0;
}

/* Waits for the path and records it in s; when it went well, its normal
 * forces in r->n and its point as the first fixed LP's start (r->warm).
 * -1 with err set when it ran out of memory. */
static int path_answer(path_job *j, run *r, bl_solution *s, bl_error *err)
{
    if (!j->system) return 0;
    if (j->beside) pthread_join(j->thread, NULL);
    j->beside = 0;
    if (j->status < 0) return bl_error_set(err, "%s", j->err.msg);
    const bl_system *f = j->system;
    s->path_steps = j->res.iterations;
    s->path_alpha = j->res.alpha;
    s->path_products = j->res.complementarity;
    s->path_seconds = j->res.seconds;
    s->path_stopped = j->res.stopped;
    if (j->status != 0 || f->ncols != r->fixed->ncols || f->nrows != r->fixed->nrows) return 0;
    for (int p = 0; p < f->npoints; p++) r->n[p] = 0.0;
    for (int k = 0; k < f->nforce; k++)
        if (f->col_kind[k] == BL_COL_NORMAL) r->n[f->col_point[k]] = j->x[k];
    r->warm = j;
    s->path_taken = 1;
    return 0;
}

int bl_seqlp_solve(bl_model *m, const bl_seqlp_options *o, bl_solution **out, bl_error *err)
{
    double t0 = bl_clock();
    bl_solution *s;
    /* LPs with resultant joints run on the interior point unless told
     * otherwise: CLP's simplex cycles on them (W4 one block thick: 38,178
     * iterations for 16 LPs, then a false "infeasible"; the interior point
     * certifies in 92 iterations, doc/seqlp.md 7). */
    bl_seqlp_options own = *o;
    int ra, rb;
    if (bl_model_uses_resultant(m, &ra, &rb) && own.base.lp == BL_LP_AUTO) own.base.lp = BL_LP_IPM;
    /* Every LP of the sequence, its associative start included, ends at
     * the analytic centre of its optimal face: which solution of Eq. 12 a
     * start reaches depends on where it begins (doc/seqlp.md 5), and from
     * the weighted centres (lp.h) two of the six domes of
     * `ensemble.lua domes` did not certify in five starts, and the
     * 10,050-block wall took 106 or 150 LPs instead of 86. */
    int weighted = o->base.weighted; /* the caller's, for an associative answer alone */
    own.base.weighted = 0;
    own.base.progress = 0; /* only the associative LP shows the interior point's line (below) */
    o = &own;
    /* (3D: the associative start on the sequence's own pyramid) */
    bl_solve_options base = o->base;
    bl_cone pyramid = bl_seqlp_pyramid(&o->base.cone);
    if (m->dim == 3) base.cone = pyramid;
    double detection = bl_clock();
    if (!m->contacts_valid && bl_contact_detect(m, err)) return -1;
    detection = bl_clock() - detection;
    /* Only joints with friction dilate under the associative flow rule
     * (a rigid one, mu = inf, cannot slide even where it opens): where
     * every joint has mu = 0 the associative answer is the
     * non-associative one, and it is solved as an associative one, on the
     * weighted path */
    int sliding = 0, finite = bl_model_finite_friction(m); /* finite: where
                                    unlimited friction is another LP */
    for (int k = 0; k < m->ninterfaces; k++) sliding |= m->interfaces[k].mu > 0.0;
    /* solve's default, where no joint has finite friction: the associative
     * answer alone, its rigid joints unable to slide even where they open
     * (doc/theory.md 6) */
    if (o->when_sliding && !finite) sliding = 0;
    if (!finite) base.weighted = weighted;
    path_job pj = {0};
    if (sliding && path_start(m, o, &pj, err)) return -1;
    if (pj.beside) base.dead_load = BL_DEAD_AFTER; /* the path has the other core */
    base.progress = o->progress && !pj.beside;     /* beside, the path shows its own */
    if (bl_assoc_solve(m, &base, &s, err)) {
        path_free(&pj);
        return -1;
    }
    if (s->status == BL_NUMERICAL && !base.weighted && strcmp(s->lp, "ipm") == 0) {
        /* the unweighted path lost its round-off where the weighted one
         * does not (an arch of 2,000 voussoirs at mu = 0.6: the primal
         * residual grew from 1e-12 to 1e-3 as the gap closed): the start
         * from the weighted centre rather than none */
        bl_solution_free(s);
        base.weighted = 1;
        if (bl_assoc_solve(m, &base, &s, err)) {
            path_free(&pj);
            return -1;
        }
    }
    s->time.detection += detection;
    s->assoc_verified = s->verified; /* (a loose lp_tolerance: an upper bound no longer) */
    /* the wall clock the dead-load check added: its own time where it ran
     * after the LP, little where it ran beside it (assoc.c) */
    double stands_wall = fmax(0.0, s->time.total - s->time.detection + detection - s->time.assembly -
                                       s->time.solve - s->time.verification);
    base.progress = 0;
    /* An unbounded associative LP proves nothing without dilatancy (a block wedged
     * between supports cannot slide out if its joints must open, but can
     * if they need not): start 0 then begins from no normal forces, so
     * that its first LP is the frictionless one, unbounded only where no
     * mechanism at all can be driven by the live load (doc/theory.md 6,
     * step 1).  Without any other associative answer there is nothing to
     * start from: that result is returned as it is. */
    int locked = sliding && s->status == BL_UNBOUNDED;
    if (locked) path_free(&pj); /* it has no answer either: start 0 from no forces */
    if (locked && s->stands == 1 && live_scales_dead(m)) {
        /* A live load that is the self weight along gravity (a vertical
         * acceleration): at every alpha the problem is the dead load's
         * scaled by 1 + alpha, which the structure carries, so nothing
         * collapses, with dilatancy or without.  (The sequence certified
         * alpha = -1 on an arch, where no load is left and any mechanism
         * fits zero forces.) */
        s->method = "seqlp";
        s->flow = "nonassociative";
        s->alpha_assoc = INFINITY;
        s->alpha_rigid = NAN;
        s->live_scales_dead = 1;
        s->verified = 0;
        *out = s;
        return 0;
    }
    if (!sliding && !o->when_sliding) {
        /* The non-associative flow asked for where no joint has friction
         * (mu = 0 everywhere): the associative flow rule is the
         * non-associative one there (slip without opening), so the
         * associative answer, verified against it, is the answer */
        path_free(&pj);
        s->method = "seqlp";
        s->flow = "nonassociative";
        s->alpha_assoc = s->alpha;
        s->alpha_rigid = NAN;
        s->assoc_is_solution = 1;
        s->certified = s->has_mechanism && s->verified && (s->status == BL_OPTIMAL || s->status == BL_UNSTABLE);
        s->alpha_settled = s->alpha;
        s->slip = o->slip;
        s->lps = 1;
        s->none_dilates = 1;
        *out = s;
        return 0;
    }
    if ((!sliding && o->when_sliding) ||
        (!locked && ((s->status != BL_OPTIMAL && s->status != BL_UNSTABLE) || !s->has_mechanism))) {
        path_free(&pj);
        /* the sequence could not start (a limit, Ctrl-C, an LP that
         * failed, no equilibrium): its result, with the associative LP's
         * status, not an associative answer */
        if (sliding && s->status != BL_OPTIMAL && s->status != BL_UNSTABLE) {
            s->method = "seqlp";
            s->flow = "nonassociative";
            s->alpha_assoc = s->alpha_rigid = NAN;
            s->verified = 0;
        } else if (sliding && s->status == BL_UNSTABLE) {
            /* unstable, and with dilatancy held up from alpha_min on
             * whatever the live load: without it a mechanism may still
             * move at a finite alpha (a wedged block), unless normal
             * forces alone carry the live load; the sequence, with no
             * associative answer to start from, does not look for one */
            int none = live_on_normals(s->model, &pyramid, &base, err);
            if (none < 0) {
                bl_solution_free(s);
                return -1;
            }
            s->method = "seqlp";
            s->flow = "nonassociative";
            s->alpha_assoc = s->alpha;
            s->alpha_rigid = NAN;
            if (!none) s->alpha = NAN;
            s->verified = 0;
        }
        *out = s;
        return 0;
    }
    s->method = "seqlp";
    s->flow = "nonassociative";
    s->alpha_assoc = locked ? INFINITY : s->alpha;
    s->alpha_rigid = NAN; /* rigid_answer */
    s->slip = o->slip;
    s->lps = 1;
    s->certified = 0;
    s->verified = 0;

    run r = {0};
    rigid_lp rl = {.status = BL_LP_FAILED};
    r.t0 = t0;
    const bl_model *mc = s->model;
    r.cone = build(mc, &pyramid, BL_FRICTION_CONE, err);
    r.fixed = r.cone ? search_system(mc, &pyramid, BL_FRICTION_FIXED, BL_SEQLP_MU_RIGID, INFINITY, err)
                     : NULL;
    r.states = r.cone;
    r.model = mc;
    r.pyramid = pyramid;
    r.mu_rigid = NAN; /* search_friction sets them */
    if (!r.fixed || search_friction(&r, 0, err)) goto fail;
    if (locked) {
        /* Blocks confined so that dilatancy locks them carry any
         * compression: from the first fixed LP on, the least normal force
         * among the optimal force fields (LEAST_N), else the capacities
         * grow from LP to LP (1 to 1e9 on a wall between abutments). */
        r.least_n = 1;
        bl_system_cost_normal(r.fixed, BL_LEAST_N, r.fixed->obj);
    }
    int np = r.fixed->npoints, nc = r.fixed->ncols;
    int ncc = r.cone->ncols > r.states->ncols ? r.cone->ncols : r.states->ncols;
    r.n = calloc((size_t)np + 1, sizeof *r.n);
    r.dn = calloc((size_t)np + 1, sizeof *r.dn);
    r.dt = calloc((size_t)np + 1, sizeof *r.dt);
    r.dt3 = calloc((size_t)np + 1, sizeof *r.dt3);
    r.resist = calloc((size_t)np + 1, sizeof *r.resist);
    r.speed = calloc((size_t)np + 1, sizeof *r.speed);
    r.slide = calloc((size_t)np + 1, sizeof *r.slide);
    r.open = calloc((size_t)np + 1, sizeof *r.open);
    r.n_first = malloc(((size_t)np + 1) * sizeof *r.n_first);
    r.lo = malloc((size_t)nc * sizeof *r.lo);
    r.hi = malloc((size_t)nc * sizeof *r.hi);
    r.clo = malloc((size_t)ncc * sizeof *r.clo);
    r.chi = malloc((size_t)ncc * sizeof *r.chi);
    r.obj = malloc((size_t)ncc * sizeof *r.obj);
    r.w = malloc((size_t)(nc > ncc ? nc : ncc) * sizeof *r.w);
    r.best_x = malloc((size_t)ncc * sizeof *r.best_x);
    r.best_y = malloc((size_t)r.fixed->nrows * sizeof *r.best_y);
    r.yc = malloc((size_t)r.fixed->nrows * sizeof *r.yc);
    r.xc = malloc((size_t)ncc * sizeof *r.xc);
    if (!r.n || !r.n_first || !r.dn || !r.dt || !r.dt3 || !r.resist ||
        !r.speed || !r.slide || !r.open || !r.lo || !r.hi || !r.clo || !r.chi || !r.obj || !r.w ||
        !r.best_x || !r.best_y || !r.yc || !r.xc) {
        bl_error_set(err, "solve: out of memory");
        goto fail;
    }

    /* One LP with unlimited friction: when its alpha equals the associative
     * one, no joint's friction limits the collapse, and the associative
     * answer is itself a non-associative solution (a lower one may exist,
     * so the search goes on).  Only the restarts depend on it: where the
     * sequence's LPs leave a core idle, it runs there beside start 0
     * (not with verbose, whose lines it would interleave).  Where every
     * joint with friction is rigid it is the associative LP. */
    if (finite) {
        rl.system = rigid_system(mc, &pyramid, err);
        if (!rl.system) goto fail;
        rl.lp = bl_solve_lp(rl.system, rl.system->lo, rl.system->hi, NULL, &o->base, err);
        if (rl.lp && !o->base.verbose && strcmp(bl_lp_engine(rl.lp), "ipm") == 0 &&
            bl_lp_leaves_core(fixed_options(r.fixed, &o->base).lp, o->base.threads, r.fixed->nrows,
                              r.fixed->ncols))
            r.rigid_beside = pthread_create(&r.rigid_thread, NULL, solve_rigid, &rl) == 0;
        if (rl.lp && !r.rigid_beside) solve_rigid(&rl);
    }

    /* Start 0 from the associative normal forces; then starts from random
     * admissible stress states below the best alpha so far, and above the
     * least alpha with an equilibrium where the dead load alone has none
     * (below it the state's LP is infeasible and the restart lost: a block
     * on a slope ran 8 of 11 starts). */
    double least = s->stands == 0 && s->alpha_min > 0.0 ? s->alpha_min : 0.0;
    /* Where the dead load alone stands, the answer is the multiplier of a
     * live load applied from zero: a certificate's alpha at least 0.
     * Below it forces may fit a mechanism too (a block over an opening,
     * held at one end by a corner and clamped by the course above, can
     * turn down as that course slides over it: a wall at mu = 2 certified
     * -0.63 and was called unstable, though it stands), but they do not
     * bear on the load as applied. */
    r.floor = s->stands == 1 ? 0.0 : -INFINITY;
    unsigned long long rng = o->seed;
    bl_lp_status stop = BL_LP_OPTIMAL;
    /* Without sliding joints the first LP settles and certifies at once.
     * How many restarts follow is decided after start 0, or after the
     * first retry to certify where start 0 did not (below). */
    int retry = 0, starts = 0;
    double probe = NAN; /* the answer two restarts probe, or NaN (below) */
    start_state first = {0}; /* where start 0 stopped */
    int low_from = 0; /* the first of the restarts at a lower friction, or 0 */
    int small = 0;    /* a small model, with BL_SEQLP_SEARCH_SMALL restarts (below) */
    int varied = 0;   /* ... and BL_SEQLP_SEARCH_VARIED more have been planned */
    for (int k = 0; k == 0 || stop == BL_LP_OPTIMAL; k++) {
        if (k > starts) {
            /* The restarts planned have run (or been skipped).  After a
             * probe, the rest of the search where one of its two
             * certified more than BL_SEQLP_PROBE_DROP below the answer it
             * probed; after the search of a small model, whose starts
             * certified BL_SEQLP_VARIED or more different answers,
             * BL_SEQLP_SEARCH_VARIED more; after a search of
             * BL_SEQLP_SEARCH restarts on a model above the small sizes,
             * BL_SEQLP_LOW_STARTS more at a lower friction
             * (search_friction). */
            if (probe == probe && r.best_alpha < probe - BL_SEQLP_PROBE_DROP * fabs(probe)) {
                starts = k - 1 - BL_SEQLP_PROBE + BL_SEQLP_SEARCH;
                s->restarts_why = "probe found";
            }
            probe = NAN;
            if (k > starts && small && !varied && o->starts < 0 &&
                different_answers(s) >= BL_SEQLP_VARIED) {
                varied = 1;
                starts = k - 1 + BL_SEQLP_SEARCH_VARIED;
                s->restarts_why = "varied";
            }
            if (k > starts && !low_from && sliding && o->starts < 0 && starts >= BL_SEQLP_SEARCH && !small &&
                bl_model_finite_friction(mc)) {
                low_from = k;
                starts = k + BL_SEQLP_LOW_STARTS - 1;
            }
            r.planned = starts + 1;
            if (k > starts) break;
        }
        /* (after an unbounded associative LP, below the first fixed LP's
         * answer, at 0 where none had one) */
        double from = r.found ? r.best_alpha
                      : locked ? (r.bounded ? r.first_alpha : 0.0)
                               : s->alpha_assoc;
        int lps0 = s->lps, its0 = s->iterations + r.iterations;
        double tk = bl_clock();
        /* restarts from stress states two at each friction, the most and
         * the least loaded (random_state); retries of a model with rigid
         * joints, which start as start 0 does, one at each from the
         * second, 3 (from 1 the 4 x 12 dome at mu = inf did not certify
         * in its 3 retries; from 3 its first certified, doc/seqlp.md 17) */
        int rigid_retry = retry && has_rigid(mc);
        if (search_friction(&r, low_from && k >= low_from ? -1 : rigid_retry ? k + 1 : (k + 1) / 2, err))
            goto fail;
        if (k == 0) {
            for (int p = 0; p < np; p++) r.n[p] = locked ? 0.0 : s->force[mc->dim * p] / r.fixed->W0;
            bl_lp_status st; /* (an LP that fails leaves the associative forces) */
            if (!locked && r.states != r.cone && search_start(&r, o, s, &st, err)) goto fail;
            if (path_answer(&pj, &r, s, err)) goto fail;
        } else if (rigid_retry) {
            /* a retry with rigid joints: from the associative forces at
             * its own friction, as start 0 (4 x 12 dome at mu = inf
             * certified only so, doc/seqlp.md 16) */
            bl_lp_status st;
            if (search_start(&r, o, s, &st, err)) goto fail;
            if (st != BL_LP_OPTIMAL) { /* as a random state that cannot be drawn */
                if (st == BL_LP_INTERRUPTED || st == BL_LP_TIME_LIMIT) stop = st;
                else s->skipped++;
                continue;
            }
        } else {
            if (!isfinite(from)) break; /* no alpha to draw below */
            bl_lp_status st;
            double low = least <= from ? least : 0.0;
            if (random_state(&r, low + uniform(&rng) * (from - low), k % 2 == 0, &rng, o, &st, err))
                goto fail;
            s->lps++;
            if (st != BL_LP_OPTIMAL) {
                /* Ctrl-C and the time limit end the run; a state that
                 * cannot be drawn (no equilibrium at that alpha, or an LP
                 * the interior point does not finish: the 10,050-block
                 * wall's, doc/seqlp.md 14) only skips this restart */
                if (st == BL_LP_INTERRUPTED || st == BL_LP_TIME_LIMIT) {
                    stop = st;
                } else {
                    s->skipped++;
                    if (st != BL_LP_INFEASIBLE && !r.found)
                        snprintf(s->note, sizeof s->note,
                                 "restart %d: the LP of its random stress state ended with %s", k,
                                 bl_status_name(bl_status_of_lp(st)));
                }
                continue;
            }
        }
        /* from a path that went deep, start 0 begins at the path's alpha */
        start_state ss = fresh_start(o, k == 0 && s->path_taken && pj.res.deep ? s->path_alpha : from);
        if (timed_start(&r, o, s, &ss, 0, lps0, its0, tk, &stop, err) < 0) goto fail;
        /* (the search's friction, where it is not every joint's own) */
        if (r.states != r.cone) s->start[s->nstarts - 1].search_mu = r.mu_cap;
        /* An LP that failed in a restart (its limit, numerical trouble)
         * ends that restart alone, its note kept, as a state that could
         * not be drawn does: the restarts' lower friction met more such
         * LPs, and W1 at mu = 20 ran 3 of its 10.  So in start 0, unless
         * the cap is the user's (solve{ iterations }): the restarts and
         * retries that follow an uncertified start 0 still run (a two-bay
         * arcade at mu = inf: numerical trouble at LP 20 of start 0 ended
         * the solve); where none follow, the run ends with that LP's
         * status (below). */
        bl_lp_status failed = stop;
        if (k > 0 ? stop != BL_LP_INTERRUPTED && stop != BL_LP_TIME_LIMIT
                  : stop == BL_LP_FAILED || (stop == BL_LP_ITERATION_LIMIT && o->base.iterations == 0))
            stop = BL_LP_OPTIMAL;
        if (k == 0) {
            first = ss;
            if (first.done == first.cap) memcpy(r.n_first, r.n, (size_t)np * sizeof *r.n);
            if (finite) rigid_answer(&r, &rl, s);
            /* By default (starts < 0) 20 restarts on small 2D models
             * (BL_SEQLP_SEARCH_ROWS), where start 0 certified up to 21 %
             * above the lowest of 10 restarts (W4 and W5 loaded the other
             * way) and 20 restarts take 0.3-10 s, and on 3D
             * models as small (BL_SEQLP_SEARCH_COLUMNS3), where one start
             * certified two unbonded leaves 11 % above their own
             * overturning; on larger ones 10 when unlimited friction gives
             * the associative alpha: start 0 then certifies the
             * associative answer, and restarts found lower ones in every
             * case measured (doc/seqlp.md: W1, the stack-bond wall); else
             * restarts only while none has certified
             * (BL_SEQLP_RETRIES).  Start 0 settling at the associative
             * alpha searches too, whatever unlimited friction gives: a
             * 104-block wall at mu = 1.2 certified its associative 1.0276
             * (unlimited friction: 3.69), where 3 restarts found 0.3809.
             * Settling, not certifying: the certificate's lowest alpha can
             * lie below (a 105-block wall at mu = 5 settled at its
             * associative 2.2200, certified 2.1963 and ran no restarts,
             * which find 0.6079; doc/seqlp.md 17).  Up to a size
             * (BL_SEQLP_MARGIN_ROWS, BL_SEQLP_MARGIN_COLUMNS3), also where
             * start 0 certified more than BL_SEQLP_MARGIN below a finite
             * associative alpha (sliding then decides the mechanism), or
             * the associative alpha is within it of unlimited friction's
             * (friction hardly bounds it, and dilatancy hides sliding):
             * one start was up to 2.9 times the lowest answer found
             * (doc/seqlp.md 18).  Where start 0 did not certify, the
             * first retry to certify decides so (search_after). */
            small = within(&r, mc, BL_SEQLP_SEARCH_ROWS, BL_SEQLP_SEARCH_COLUMNS3);
            const char *why = small ? "small" : s->assoc_is_solution ? "solution" : search_after(&r, s, mc, o);
            retry = sliding && o->starts < 0 && !why && !r.found && r.fixed->nrows <= BL_SEQLP_RETRY_ROWS;
            /* where none of these holds on a model of that size, two
             * restarts probe start 0's answer (BL_SEQLP_PROBE) */
            probe = sliding && o->starts < 0 && !why && r.found && medium(&r, mc) ? r.best_alpha : NAN;
            starts = !sliding          ? 0
                     : o->starts >= 0  ? o->starts
                     : small           ? BL_SEQLP_SEARCH_SMALL
                     : why             ? BL_SEQLP_SEARCH
                     : retry           ? (medium(&r, mc) ? BL_SEQLP_RETRIES_MEDIUM : BL_SEQLP_RETRIES)
                     : probe == probe  ? BL_SEQLP_PROBE
                                       : 0;
            r.planned = starts + 1;
            /* why the default restarts, for the user (r.restarts_why) */
            if (sliding && o->starts < 0 && starts > 0)
                s->restarts_why = why ? why : probe == probe ? "probe" : "not certified";
            if (starts == 0) stop = failed;
        } else if (retry && r.found) {
            /* the first retry to certify: the restarts start 0 would have
             * decided on its answer follow it (the running bond of 16 x 16
             * at mu = 2 towards -x: start 0 did not certify, the second
             * retry certified 0.65710, 0.386 of the associative alpha, and
             * 10 restarts after it 0.63097; doc/seqlp.md 18) */
            const char *why = search_after(&r, s, mc, o);
            retry = 0;
            probe = !why && medium(&r, mc) ? r.best_alpha : NAN;
            starts = why ? k + BL_SEQLP_SEARCH : probe == probe ? k + BL_SEQLP_PROBE : k;
            r.planned = starts + 1;
            if (why) s->restarts_why = why;
            if (probe == probe) s->restarts_why = "probe";
        }
    }

    /* By default, when no start has certified and start 0 was cut at its
     * cap, start 0 goes on where it stopped, once, for as many LPs again:
     * a sequence that settles slowly can need more than the cap (a
     * 2,048-block wall at mu = 1 certified at LP 140 of one start, where
     * four starts of 100 certified nothing; doc/seqlp.md, "Where the
     * method fails or is slow"). */
    if (!r.found && stop == BL_LP_OPTIMAL && sliding && o->starts < 0 && first.cap > 0 &&
        first.done == first.cap) {
        memcpy(r.n, r.n_first, (size_t)np * sizeof *r.n);
        first.cap += o->max_lps;
        if (search_friction(&r, 0, err)) goto fail;
        if (timed_start(&r, o, s, &first, 1, s->lps, s->iterations + r.iterations, bl_clock(),
                        &stop, err) < 0)
            goto fail;
    }

    int given = 0; /* the mechanism given that a stop came in, 1-based */
    if (stop != BL_LP_INTERRUPTED && stop != BL_LP_TIME_LIMIT &&
        try_given(&r, o, s, &stop, &given, err))
        goto fail;

    if (stop == BL_LP_INTERRUPTED) {
        s->interrupted = 1;
        const char *what = r.found ? "the lowest certified answer so far; lower ones may exist"
                                   : "nothing certified yet";
        const char *lps = s->lps == 1 ? "" : "s";
        if (given)
            snprintf(s->note, sizeof s->note,
                     "stopped by Ctrl-C after %d LP%s, at mechanism %d of the %d given: %s", s->lps, lps,
                     given, o->nmechanisms, what);
        else if (s->start[s->nstarts - 1].continues)
            snprintf(s->note, sizeof s->note,
                     "stopped by Ctrl-C after %d LP%s, in start 1 going on after the restarts: %s",
                     s->lps, lps, what);
        else
            snprintf(s->note, sizeof s->note, "stopped by Ctrl-C after %d LP%s, in start %d of %d: %s",
                     s->lps, lps, s->nstarts, starts + 1, what);
    }
    if (stop == BL_LP_TIME_LIMIT && r.found) {
        s->time_up = 1;
        if (given)
            snprintf(s->note, sizeof s->note, "the time limit ended the search at mechanism %d of the %d "
                     "given (%d LPs): lower answers may exist", given, o->nmechanisms, s->lps);
        else if (s->start[s->nstarts - 1].continues)
            snprintf(s->note, sizeof s->note, "the time limit ended the search in start 1 going on after "
                     "the restarts (%d LPs): lower answers may exist", s->lps);
        else
            snprintf(s->note, sizeof s->note,
                     "the time limit ended the search in start %d of %d (%d LPs): lower answers may exist",
                     s->nstarts, starts + 1, s->lps);
    }
    if (r.found) {
        s->alpha = r.best_alpha;
        s->alpha_settled = r.best_settled;
        s->early = r.best_early;
        s->given = r.best_given;
        bl_solution_answer_status(s);
        s->certified = 1;
        s->has_mechanism = 1; /* none from an unbounded associative LP */
        if (mc->dim == 3) {
            bl_system_forces3(r.cone, r.best_x, s->force);
            bl_system_mechanism3(r.fixed, mc, r.best_y, s->u);
        } else {
            bl_system_forces(r.cone, mc, r.best_x, s->force);
            bl_system_mechanism(r.fixed, mc, r.best_y, s->u);
        }
        bl_system_reactions(r.cone, mc, r.best_x, s->reaction);
        bl_solution_classify(s);
        double tv = bl_clock();
        s->verified = bl_verify_nonassoc(r.cone, r.fixed, s->alpha, r.best_x, r.best_y,
                                         o->base.tolerance, o->slip, &s->res);
        s->time.verification += bl_clock() - tv;
        if (bl_solution_keep(s, r.best_x, r.cone->ncols, r.best_y, r.fixed->nrows)) {
            bl_error_set(err, "solve: out of memory");
            goto fail;
        }
    } else {
        /* no equilibrium at alpha = 0 (the associative LP's check): unstable
         * whatever the sequence found */
        s->status = stop != BL_LP_OPTIMAL ? bl_status_of_lp(stop)
                    : s->stands == 0      ? BL_UNSTABLE
                                          : BL_UNCERTIFIED;
        s->has_mechanism = 0;
        if (s->status == BL_UNCERTIFIED && !s->note[0])
            snprintf(s->note, sizeof s->note,
                     "no certificate passed within each start's %d fixed LPs (lps)", o->max_lps);
        /* no answer; unbounded (its first, frictionless LP: no live load
         * makes it collapse), infinite as from the associative LP */
        s->alpha = s->status == BL_UNBOUNDED ? INFINITY : NAN;
        free(s->x);
        free(s->y);
        s->x = s->y = NULL; /* the associative start's, no longer the answer */
    }
    s->iterations += r.iterations;
    if (r.lp_fixed) s->lp = bl_lp_engine(r.lp_fixed);
    s->lp_switched = r.switched;
    if (r.shown) fprintf(stderr, "\r%79s\r", "");
    path_free(&pj);
    run_free(&r);
    s->time.total = bl_clock() - t0;
    s->time.solve = s->time.total - s->time.detection - s->time.assembly - s->time.verification - stands_wall;
    *out = s;
    return 0;
fail:
    if (r.shown) fprintf(stderr, "\r%79s\r", ""); /* the error's message on a line of its own */
    path_free(&pj);
    if (r.rigid_beside) pthread_join(r.rigid_thread, NULL);
    bl_lp_free(rl.lp);
    bl_system_free(rl.system);
    run_free(&r);
    bl_solution_free(s);
    return -1;
}
