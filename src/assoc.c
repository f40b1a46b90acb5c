#include "assoc.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "assemble.h"
#include "contact.h"
#include "lp.h"
#include "verify.h"

void bl_solve_options_default(bl_solve_options *o)
{
    o->tolerance = 1e-7;
    o->verbose = 0;
    o->deadline = 0;
    o->iterations = 0;
    o->threads = 0;
    o->lp = BL_LP_AUTO;
    o->mps = NULL;
    o->cone = (bl_cone){.facets = 8};
    o->early_infeasible = 0;
    o->lp_tolerance = 0;
    o->weighted = 1;
    o->progress = 0;
    o->dead_load = BL_DEAD_BESIDE;
}

bl_lp *bl_solve_lp(const bl_system *s, const double *lo, const double *hi, const double *obj,
                   const bl_solve_options *o, bl_error *err)
{
    bl_lp_settings ls;
    bl_lp_settings_default(&ls);
    ls.engine = o->lp;
    ls.verbose = o->verbose;
    ls.deadline = o->deadline;
    ls.max_iterations = o->iterations;
    ls.threads = o->threads;
    ls.early_infeasible = o->early_infeasible;
    ls.tolerance = o->lp_tolerance;
    ls.weighted = o->weighted;
    ls.progress = o->progress;
    bl_lp_problem p = {s->nrows, s->ncols, s->colptr, s->rowind, s->val,
                       lo,       hi,       s->rhs,    obj ? obj : s->obj};
    return bl_lp_create(&p, &ls, err);
}

/* The dead-load check (doc/theory.md 8): the LP of a system with alpha
 * fixed at 0.  Its objective is gone with alpha's column, so it asks only
 * whether the dead load alone has an equilibrium within the yield
 * conditions; fixed, alpha's dense column also stays out of the interior
 * point's normal matrix, which made a bounded alpha several times slower
 * per iteration.  Cold, since a warm start from the answer at the top of
 * the interval took the interior point more iterations, not fewer.  Its
 * LP is made on the calling thread, only solved beside: two interior
 * points analysed at once (CHOLMOD, METIS, the thread settings) changed
 * the round-off of the answer from run to run. */
typedef struct dead_check {
    bl_lp *lp;
    int owned; /* lp is the check's own, not the answer's re-solved */
    bl_lp_status status;
    double seconds;
    pthread_t thread;
    int beside, started;
} dead_check;

static void *dead_run(void *arg)
{
    dead_check *c = arg;
    double t0 = bl_clock();
    c->status = c->lp ? bl_lp_solve(c->lp) : BL_LP_FAILED;
    c->seconds += bl_clock() - t0;
    return NULL;
}

/* Starts the check of sys, on a thread of its own when beside, else on
 * the answer's LP when reuse is given; without a dead load it holds at
 * once (no forces at all are an equilibrium). */
static void dead_start(dead_check *c, const bl_system *sys, const bl_solve_options *o,
                       bl_lp *reuse, int beside)
{
    double t0 = bl_clock();
    c->started = 1;
    c->status = BL_LP_OPTIMAL;
    int loaded = 0;
    for (int i = 0; i < sys->nrows; i++) loaded |= sys->rhs[i] != 0.0;
    if (!loaded) return;
    size_t n = (size_t)sys->ncols;
    double *lo = malloc(n * sizeof *lo), *hi = malloc(n * sizeof *hi);
    bl_error err;
    if (lo && hi) {
        memcpy(lo, sys->lo, n * sizeof *lo);
        memcpy(hi, sys->hi, n * sizeof *hi);
        lo[sys->nforce] = hi[sys->nforce] = 0.0;
        if (reuse) bl_lp_set_bounds(reuse, lo, hi);
        bl_solve_options quiet = *o; /* beside, its line would mix with the LP's */
        quiet.progress = 0;
        c->lp = reuse ? reuse : bl_solve_lp(sys, lo, hi, NULL, &quiet, &err);
        c->owned = !reuse;
    }
    free(lo);
    free(hi);
    c->seconds = bl_clock() - t0; /* the LP's making; dead_run adds its solve */
    if (beside) c->beside = pthread_create(&c->thread, NULL, dead_run, c) == 0;
    if (!c->beside) dead_run(c);
}

static void dead_finish(dead_check *c)
{
    if (c->beside) pthread_join(c->thread, NULL);
    c->beside = 0;
    if (c->owned) bl_lp_free(c->lp);
    c->lp = NULL;
}

/* Where the interior point fails an LP or leaves the check undecided,
 * models of up to this many LP rows have it solved again by the simplex
 * (at 1,040 blocks, 3,120 rows, the simplex took seconds for an LP of the
 * associative solve). */
#define BL_SIMPLEX_ROWS 3000

/* Chains of blocks (an arch: about one joint per block) give the simplex a
 * banded LP it solves in seconds far beyond that: 4.4 s at 2,000
 * voussoirs, 12 s at 3,000 (9,000 rows), where the interior point lost
 * its round-off on both paths at mu = inf and a wall of 6,000 rows took
 * the simplex 70 s. */
#define BL_SIMPLEX_CHAIN_ROWS 12000

/* Whether the model is a chain: at most one and a half joints per free
 * block. */
static int chain(const bl_model *m)
{
    int free_blocks = 0;
    for (int i = 0; i < m->nblocks; i++) free_blocks += !m->blocks[i].support;
    return 2 * m->ninterfaces <= 3 * free_blocks;
}

int bl_simplex_rescues(const bl_model *m, int nrows)
{
    return nrows <= BL_SIMPLEX_ROWS || (chain(m) && nrows <= BL_SIMPLEX_CHAIN_ROWS);
}

/* Where alpha = 0 has no equilibrium: the least alpha that has one (the
 * bottom of the interval whose top the solve found), or NAN.  On the
 * answer's LP of sys when given (its bounds as sys's again, its objective
 * turned round: the simplex goes on from its basis, which took a fifth of
 * the time of an LP of its own), else on an LP of its own. */
static double alpha_min(const bl_system *sys, bl_lp *answer, const bl_solve_options *o)
{
    double *obj = calloc((size_t)sys->ncols, sizeof *obj), a = NAN;
    bl_error err;
    if (!obj) return NAN;
    obj[sys->nforce] = -1.0;
    bl_lp *lp = answer;
    if (lp) {
        bl_lp_set_bounds(lp, sys->lo, sys->hi);
        bl_lp_set_objective(lp, obj);
    } else {
        lp = bl_solve_lp(sys, sys->lo, sys->hi, obj, o, &err);
    }
    if (lp && bl_lp_solve(lp) == BL_LP_OPTIMAL) a = bl_lp_primal(lp)[sys->nforce];
    if (lp != answer) bl_lp_free(lp);
    free(obj);
    return a;
}

int bl_assoc_solve(bl_model *m, const bl_solve_options *o, bl_solution **out, bl_error *err)
{
    double t0 = bl_clock();
    if (!m->contacts_valid && bl_contact_detect(m, err)) return -1;
    double t1 = bl_clock();

    bl_model *copy = bl_model_copy(m);
    bl_solution *s = copy ? bl_solution_new(copy) : NULL;
    if (!s) return bl_error_set(err, "solve: out of memory");
    /* 3D with the adaptive cone: the inscribed pyramid of every point gets
     * an edge along the slip the previous LP found there, until alpha
     * settles; edges are only added, so alpha rises towards the exact
     * cone's (doc/theory.md 3.3) */
    enum { ROUNDS = 40 };
    bl_cone cone = o->cone;
    double *extra = NULL, *slip = NULL;
    int *extra_n = NULL, np = 0;
    for (int k = 0; k < m->ninterfaces; k++) np += m->interfaces[k].np;
    if (m->dim == 3 && cone.adaptive) {
        extra = calloc((size_t)np * ROUNDS + 1, sizeof *extra);
        extra_n = calloc((size_t)np + 1, sizeof *extra_n);
        slip = calloc(2 * (size_t)np + 1, sizeof *slip);
        if (!extra || !extra_n || !slip) {
            free(extra), free(extra_n), free(slip);
            bl_solution_free(s);
            return bl_error_set(err, "solve: out of memory");
        }
        cone.circumscribed = 0;
        cone.nextra = ROUNDS;
        cone.extra = extra;
        cone.extra_n = extra_n;
    }
    bl_system *sys = NULL;
    bl_lp *lp = NULL;
    bl_lp_status st = BL_LP_FAILED;
    dead_check dead = {0};
    int reuse = 0; /* the check will re-solve lp */
    double t2 = bl_clock(), t3 = t2, prev = NAN, solve_time = 0.0, cap = INFINITY;
    int lost = 0; /* iterations of LPs solved again */
    for (int round = 1;; round++) {
        sys = m->dim == 3 ? bl_system_build3(m, &cone, BL_FRICTION_CONE, err) : bl_system_build(m, BL_FRICTION_CONE, err);
        if (!sys) break;
        /* one round: the check can run beside the LP from the start, or
         * else after it on the same LP (reuse) */
        if (!extra && o->dead_load == BL_DEAD_BESIDE && !o->verbose &&
            bl_lp_leaves_core(o->lp, o->threads, sys->nrows, sys->ncols))
            dead_start(&dead, sys, o, NULL, 1);
        reuse = !extra && !dead.started && o->dead_load != BL_DEAD_NONE;
        bl_lp_problem p = {sys->nrows, sys->ncols, sys->colptr, sys->rowind, sys->val,
                           sys->lo,    sys->hi,    sys->rhs,    sys->obj};
        lp = o->mps && bl_lp_write_mps(&p, o->mps, err) ? NULL
                                                       : bl_solve_lp(sys, sys->lo, sys->hi, NULL, o, err);
        if (!lp) break;
        t2 = bl_clock();
        st = bl_lp_solve(lp);
        /* an LP stopped at the user's own iteration cap is not tried again */
        int retry = st == BL_LP_FAILED || (st == BL_LP_ITERATION_LIMIT && o->iterations == 0);
        if (retry && strcmp(bl_lp_engine(lp), "ipm") == 0) {
            /* Blocks confined between supports can carry any compression,
             * and the interior point does not converge on the unbounded
             * optimal face (doc/seqlp.md 13).  Every force column capped
             * far above any force equilibrium needs (BL_LP_CONFINED)
             * bounds it without a cost that would tilt the mechanism;
             * the verification checks the answer against the bounds
             * without the caps (a force at its cap would fail it). */
            cap = BL_LP_CONFINED * sys->nrows;
            for (int j = 0; j < sys->nforce; j++) {
                if (isinf(sys->hi[j])) sys->hi[j] = cap;
                if (isinf(sys->lo[j])) sys->lo[j] = -cap;
            }
            lost += bl_lp_iterations(lp);
            bl_lp_free(lp);
            lp = bl_solve_lp(sys, sys->lo, sys->hi, NULL, o, err);
            if (!lp) break;
            st = bl_lp_solve(lp);
            retry = st == BL_LP_FAILED || (st == BL_LP_ITERATION_LIMIT && o->iterations == 0);
        }
        if (retry && o->lp == BL_LP_AUTO && strcmp(bl_lp_engine(lp), "ipm") == 0 &&
            bl_simplex_rescues(m, sys->nrows)) {
            /* Round-off can stop the interior point short of the answer
             * (an arch of 241 voussoirs at mu = 100 on the unweighted
             * path: the primal residual grew from 1e-12 to 1e-3 once the
             * barrier fell below 1e-9): on a model the simplex solves in
             * seconds, it does.  (Not after "infeasible", whose ray the
             * interior point checks: the simplex took 12 times as long to
             * agree on an arch too thin to stand, 2,403 rows.) */
            bl_solve_options simplex = *o;
            simplex.lp = BL_LP_SIMPLEX;
            lost += bl_lp_iterations(lp);
            bl_lp_free(lp);
            lp = bl_solve_lp(sys, sys->lo, sys->hi, NULL, &simplex, err);
            if (!lp) break;
            st = bl_lp_solve(lp);
        }
        t3 = bl_clock();
        solve_time += t3 - t2;
        s->cone_rounds = round;
        s->cone = o->cone;
        s->cone.extra = NULL;
        s->cone.extra_n = NULL;
        if (!extra || st != BL_LP_OPTIMAL || round == ROUNDS) break;
        /* the slip of every contact point (from the mechanism: the forces
         * sit on corners of the pyramid); the friction on b opposes it */
        double a = bl_lp_primal(lp)[sys->nforce], smax = 0.0;
        if (fabs(a - prev) <= o->tolerance * fmax(1.0, fabs(a))) break;
        prev = a;
        bl_system_slip3(sys, m, bl_lp_dual(lp), slip);
        for (int q = 0; q < np; q++) smax = fmax(smax, hypot(slip[2 * q], slip[2 * q + 1]));
        for (int q = 0; q < np; q++)
            if (hypot(slip[2 * q], slip[2 * q + 1]) > 1e-6 * smax)
                extra[q * ROUNDS + extra_n[q]++] = atan2(-slip[2 * q + 1], -slip[2 * q]);
        bl_lp_free(lp);
        bl_system_free(sys);
        lp = NULL;
        sys = NULL;
    }
    free(extra);
    free(extra_n);
    free(slip);
    if (!lp) {
        dead_finish(&dead);
        bl_system_free(sys);
        bl_solution_free(s);
        return -1;
    }
    if (st == BL_LP_OPTIMAL && o->lp_tolerance <= 0) {
        /* The simplex stops within its tolerances on the scaled problem,
         * which can leave a residual just above the verification's (a
         * façade of 457 blocks at mu = 3: admissibility 1.2e-7): once,
         * from its basis, 100 times tighter (1e-11 for CLP's 1e-9; the
         * dead-load check goes on with them), unscaled (lp_clp.cpp) */
        bl_residuals r0;
        const double *x = bl_lp_primal(lp), *y = bl_lp_dual(lp);
        if (!bl_verify(sys, x[sys->nforce], x, y, o->tolerance, &r0) && bl_lp_tighten(lp, 1e-2) == 0) {
            lost += bl_lp_iterations(lp);
            bl_lp_status again = bl_lp_solve(lp); /* (stopped short, it keeps its answer) */
            if (again == BL_LP_INTERRUPTED || again == BL_LP_TIME_LIMIT) st = again;
            double t = bl_clock();
            solve_time += t - t3;
            t3 = t;
        }
    }
    t2 = t3 - solve_time;

    s->status = bl_status_of_lp(st);
    if (s->status == BL_UNBOUNDED) s->alpha = INFINITY; /* no live load makes it collapse */
    s->lp = bl_lp_engine(lp);
    s->iterations = bl_lp_iterations(lp) + lost;
    s->factor_nnz = bl_lp_factor_nnz(lp);
    s->rows = sys->nrows;
    s->cols = sys->ncols;
    s->tolerance = o->tolerance;
    for (int j = 0; isfinite(cap) && j < sys->nforce; j++) {
        if (sys->hi[j] == cap) sys->hi[j] = INFINITY;
        if (sys->lo[j] == -cap) sys->lo[j] = -INFINITY;
    }
    if (st == BL_LP_OPTIMAL) {
        const double *x = bl_lp_primal(lp), *y = bl_lp_dual(lp);
        s->alpha = x[sys->nforce];
        bl_solution_answer_status(s);
        s->has_mechanism = 1;
        if (sys->dim == 3) {
            bl_system_forces3(sys, x, s->force);
            bl_system_mechanism3(sys, m, y, s->u);
        } else {
            bl_system_forces(sys, m, x, s->force);
            bl_system_mechanism(sys, m, y, s->u);
        }
        bl_system_reactions(sys, m, x, s->reaction);
        bl_solution_classify(s);
        s->verified = bl_verify(sys, s->alpha, x, y, o->tolerance, &s->res);
        if (bl_solution_keep(s, x, sys->ncols, y, sys->nrows)) {
            dead_finish(&dead);
            bl_lp_free(lp);
            bl_system_free(sys);
            bl_solution_free(s);
            return bl_error_set(err, "solve: out of memory");
        }
    }
    double t4 = bl_clock();
    /* The check, after an answer alpha >= 0, and where no live load makes
     * the structure collapse (unbounded): whether the dead load alone has
     * an equilibrium. */
    if ((s->status == BL_OPTIMAL || s->status == BL_UNBOUNDED) && o->dead_load != BL_DEAD_NONE) {
        /* 3D with the adaptive cone: its edges follow the slip at the top
         * of the interval; the circumscribed pyramid holds more friction
         * than the cone, so that no equilibrium on it is none on the cone */
        bl_system *check = sys;
        bl_cone around = {.facets = o->cone.facets, .circumscribed = 1};
        if (m->dim == 3 && o->cone.adaptive && !dead.started)
            check = bl_system_build3(m, &around, BL_FRICTION_CONE, err);
        if (!check) {
            bl_lp_free(lp);
            bl_system_free(sys);
            bl_solution_free(s);
            return -1;
        }
        /* After the solve, on its LP (its answer is kept in s): the
         * interior point starts cold but keeps its analysis and its arrays
         * (2,525 blocks: 24 % of the solve's time against 31 % for an LP of
         * its own); the simplex goes on from its basis. */
        if (!dead.started) {
            if (reuse) bl_lp_cold(lp);
            dead_start(&dead, check, o, reuse ? lp : NULL, 0);
        }
        dead_finish(&dead);
        /* The interior point can stall short of a small infeasibility (a
         * block on a slope 3e-4 steeper than its friction angle: 114
         * iterations, undecided) that the simplex decides: on models of up
         * to BL_SIMPLEX_ROWS rows it solves the check again. */
        bl_solve_options simplex = *o;
        simplex.lp = BL_LP_SIMPLEX;
        const bl_solve_options *how = o;
        if (dead.status != BL_LP_OPTIMAL && dead.status != BL_LP_INFEASIBLE &&
            dead.status != BL_LP_INTERRUPTED && dead.status != BL_LP_TIME_LIMIT &&
            strcmp(s->lp, "ipm") == 0 && check->nrows <= BL_SIMPLEX_ROWS) {
            double before = dead.seconds;
            how = &simplex;
            dead = (dead_check){0};
            dead_start(&dead, check, how, NULL, 0);
            dead_finish(&dead);
            dead.seconds += before;
        }
        s->stands = dead.status == BL_LP_OPTIMAL ? 1 : dead.status == BL_LP_INFEASIBLE ? 0 : -1;
        double ta = bl_clock();
        if (s->stands == 0) s->alpha_min = alpha_min(check, check == sys && how == o ? lp : NULL, how);
        /* The equilibria at alpha_min and at the answer's alpha bracket 0
         * where alpha_min <= 0, and their mean by weights is one at 0: a
         * check that said otherwise was wrong (a dual simplex on a model
         * whose joints cannot slide) */
        if (s->stands == 0 && s->alpha_min <= 0.0 && s->alpha >= 0.0) {
            s->stands = 1;
            s->alpha_min = NAN;
        }
        if (check != sys) bl_system_free(check);
        if (s->status == BL_OPTIMAL) {
            bl_solution_answer_status(s);
        } else if (s->stands == 0) { /* unbounded: held up from alpha_min on */
            s->alpha = INFINITY;
            s->status = BL_UNSTABLE;
        }
        s->time.stands = dead.seconds + (bl_clock() - ta);
    }
    dead_finish(&dead);
    bl_lp_free(lp);
    double t5 = bl_clock();
    s->time.detection = t1 - t0;
    s->time.assembly = t2 - t1;
    s->time.solve = t3 - t2;
    s->time.verification = t4 - t3;
    s->time.total = t5 - t0;
    bl_system_free(sys);
    *out = s;
    return 0;
}

int bl_assoc_dead_alone(const bl_model *m, const bl_solve_options *o, bl_solution **out, bl_error *err)
{
    bl_model *c = bl_model_copy(m);
    if (!c) return bl_error_set(err, "solve: out of memory");
    /* the dead load, turned by the tilt, becomes the live load (carried
     * weights as the forces they are); the live load goes */
    c->live_weight = c->self_weight;
    c->live_dir = bl_model_gravity(m);
    c->live_dir3 = bl_model_gravity3(m);
    c->self_weight = 0;
    c->tilt = 0.0;
    int n = 0;
    for (int l = 0; l < c->nloads; l++)
        if (!c->loads[l].live) {
            bl_point_load *pl = &c->loads[n++];
            bl_vec2 live2;
            bl_vec3 live3;
            *pl = c->loads[l];
            bl_point_load_forces(m, pl, &pl->force, &live2); /* a weight's dead force, as a force */
            bl_point_load_forces3(m, pl, &pl->force3, &live3);
            pl->weight = 0.0;
            pl->live = 1;
        }
    c->nloads = n;
    bl_solve_options d = *o;
    d.mps = NULL;
    int rc = bl_assoc_solve(c, &d, out, err);
    bl_model_free(c);
    return rc;
}
