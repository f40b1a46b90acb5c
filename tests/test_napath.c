/* The path of the non-associative problem (src/napath.h).
 *
 * Closed forms: followed to the end (products 1e-10), the path of a single
 * block on the ground and of a column of three ends at the only solution of
 * the seed's Eq. 12 there, alpha = min(mu, b / h) with h the height of
 * what overturns (the whole column); to 1e-6.
 *
 * Its last point as a warm start (bl_lp_warm): the fixed LP of W4 whose
 * capacities are mu times the path's normal forces, solved from the path's
 * point, reaches the same optimum as from scratch (to 1e-7) in fewer
 * interior-point iterations (counted, not timed).
 *
 * A path cut short (W4, 12 steps towards 1e-12) is taken exactly when its
 * products are at most the given "near": its point then is the one whose
 * products were measured (recomputed here from the returned forces and
 * multipliers, to 1e-9) and in equilibrium (residual below 1e-6 of the
 * loads).
 *
 * Past its target towards a deeper level (deep_or_the_targets_point): the
 * deeper point when it gets there, else the target's, unchanged.
 *
 * Cancelled (stopped_when_cancelled): a path whose cancel flag is set takes
 * no step and reports that it was stopped; with the flag clear the same
 * call reaches the closed form. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "assemble.h"
#include "contact.h"
#include "lp.h"
#include "napath.h"
#include "w4.h"

static void box(bl_model *m, double x0, double y0, double b, double h, int support)
{
    bl_vec2 v[4] = {{x0, y0}, {x0 + b, y0}, {x0 + b, y0 + h}, {x0, y0 + h}};
    assert_int_equal(bl_model_add_block(m, v, 4, support, 0, 0, NULL), 0);
}

/* A column of n blocks b x h on a wide support, friction mu. */
static bl_system *column(int n, double b, double h, double mu)
{
    bl_model *m = bl_model_new();
    m->mu = mu;
    for (int k = 0; k < n; k++) box(m, 0.0, k * h, b, h, 0);
    box(m, -1.0, -0.2, b + 2.0, 0.2, 1);
    assert_int_equal(bl_contact_detect(m, NULL), 0);
    bl_system *s = bl_system_build(m, BL_FRICTION_FIXED, NULL);
    bl_model_free(m);
    assert_non_null(s);
    assert_true(bl_napath_applies(s));
    return s;
}

/* The path to its end on s: its alpha, with x the forces if given. */
static double path_alpha(const bl_system *s, double *x_out)
{
    double *x = calloc((size_t)s->ncols, sizeof *x), *zl = calloc((size_t)s->ncols, sizeof *zl);
    double *zu = calloc((size_t)s->ncols, sizeof *zu), *y = calloc((size_t)s->nrows, sizeof *y);
    bl_napath_result res;
    assert_int_equal(bl_napath_run(s, 1e-10, 1e-10, 1e-10, 100, 0, NULL, 0, x, zl, zu, y, &res, NULL), 0);
    assert_true(res.complementarity <= 1e-10);
    if (x_out) memcpy(x_out, x, (size_t)s->ncols * sizeof *x);
    free(x);
    free(zl);
    free(zu);
    free(y);
    return res.alpha;
}

static void single_block_slides(void **state)
{
    (void)state;
    bl_system *s = column(1, 0.4, 0.175, 0.5); /* b / h = 2.29 > mu */
    assert_true(fabs(path_alpha(s, NULL) - 0.5) <= 1e-6);
    bl_system_free(s);
}

static void single_block_overturns(void **state)
{
    (void)state;
    bl_system *s = column(1, 0.2, 1.0, 0.65); /* b / h = 0.2 < mu */
    assert_true(fabs(path_alpha(s, NULL) - 0.2) <= 1e-6);
    bl_system_free(s);
}

static void column_overturns_whole(void **state)
{
    (void)state;
    bl_system *s = column(3, 0.2, 0.5, 0.65); /* b / H = 0.2 / 1.5 */
    assert_true(fabs(path_alpha(s, NULL) - 0.2 / 1.5) <= 1e-6);
    bl_system_free(s);
}

static void warm_from_the_path(void **state)
{
    (void)state;
    bl_system *s = w4(BL_FRICTION_FIXED);
    assert_true(bl_napath_applies(s));
    size_t nc = (size_t)s->ncols;
    double *x = calloc(nc, sizeof *x), *zl = calloc(nc, sizeof *zl), *zu = calloc(nc, sizeof *zu);
    double *y = calloc((size_t)s->nrows, sizeof *y), *n = calloc((size_t)s->npoints, sizeof *n);
    double *lo = calloc(nc, sizeof *lo), *hi = calloc(nc, sizeof *hi);
    bl_napath_result res;
    assert_int_equal(bl_napath_run(s, 1e-3, 1e-3, 1e-3, 100, 0, NULL, 0, x, zl, zu, y, &res, NULL), 0);
    for (size_t k = 0; k < (size_t)s->nforce; k++)
        if (s->col_kind[k] == BL_COL_NORMAL) n[s->col_point[k]] = x[k];
    bl_system_fixed_bounds(s, n, lo, hi);
    bl_lp_settings set;
    bl_lp_settings_default(&set);
    set.engine = BL_LP_IPM;
    bl_lp_problem p = {s->nrows, s->ncols, s->colptr, s->rowind, s->val, lo, hi, s->rhs, s->obj};
    bl_lp *cold = bl_lp_create(&p, &set, NULL), *warm = bl_lp_create(&p, &set, NULL);
    assert_non_null(cold);
    assert_non_null(warm);
    assert_int_equal(bl_lp_warm(warm, x, zl, zu, y, res.mu), 0);
    assert_int_equal(bl_lp_solve(cold), BL_LP_OPTIMAL);
    assert_int_equal(bl_lp_solve(warm), BL_LP_OPTIMAL);
    double ac = bl_lp_primal(cold)[s->nforce], aw = bl_lp_primal(warm)[s->nforce];
    print_message("# W4's fixed LP from the path (products %.1e, %d steps): %d iterations against "
                  "%d cold; alpha %.10f against %.10f\n",
                  res.complementarity, res.iterations, bl_lp_iterations(warm), bl_lp_iterations(cold),
                  aw, ac);
    assert_true(fabs(aw - ac) <= 1e-7 * fabs(ac));
    assert_true(bl_lp_iterations(warm) < bl_lp_iterations(cold));
    bl_lp_free(cold);
    bl_lp_free(warm);
    free(x);
    free(zl);
    free(zu);
    free(y);
    free(n);
    free(lo);
    free(hi);
    bl_system_free(s);
}

/* sum over the points of n z + s1 w1 + s2 w2, over 1 + |alpha|, from the
 * returned columns (x = n with z in zl; x = t = mu u with w2 / mu in zl and
 * w1 / mu in zu) */
static double products_of(const bl_system *s, const double *x, const double *zl, const double *zu)
{
    double *n = calloc((size_t)s->npoints, sizeof *n), sum = 0.0;
    for (int k = 0; k < s->nforce; k++)
        if (s->col_kind[k] == BL_COL_NORMAL) n[s->col_point[k]] = x[k];
    for (int k = 0; k < s->nforce; k++) {
        int p = s->col_point[k];
        if (s->col_kind[k] == BL_COL_NORMAL) sum += x[k] * zl[k];
        else sum += (s->mu[p] * n[p] + x[k]) * zl[k] + (s->mu[p] * n[p] - x[k]) * zu[k];
    }
    free(n);
    return sum / (1.0 + fabs(x[s->nforce]));
}

static void cut_short_taken_when_near(void **state)
{
    (void)state;
    bl_system *s = w4(BL_FRICTION_FIXED);
    size_t nc = (size_t)s->ncols;
    double *x = calloc(nc, sizeof *x), *zl = calloc(nc, sizeof *zl), *zu = calloc(nc, sizeof *zu);
    double *y = calloc((size_t)s->nrows, sizeof *y), *r = calloc((size_t)s->nrows, sizeof *r);
    bl_napath_result res;
    assert_int_equal(bl_napath_run(s, 1e-12, 1e-12, 1e-12, 12, 0, NULL, 0, x, zl, zu, y, &res, NULL), 1);
    double reached = res.complementarity;
    assert_true(reached > 1e-12);
    assert_int_equal(bl_napath_run(s, 1e-12, 0.5 * reached, 1e-12, 12, 0, NULL, 0, x, zl, zu, y, &res, NULL), 1);
    assert_int_equal(bl_napath_run(s, 1e-12, 2.0 * reached, 1e-12, 12, 0, NULL, 0, x, zl, zu, y, &res, NULL), 0);
    double own = products_of(s, x, zl, zu), bmax = 0.0, rmax = 0.0;
    for (int i = 0; i < s->nrows; i++) {
        r[i] = s->rhs[i];
        bmax = fmax(bmax, fabs(s->rhs[i]));
    }
    for (int k = 0; k < s->ncols; k++)
        for (int q = s->colptr[k]; q < s->colptr[k + 1]; q++) r[s->rowind[q]] -= s->val[q] * x[k];
    for (int i = 0; i < s->nrows; i++) rmax = fmax(rmax, fabs(r[i]));
    print_message("# W4's path cut at 12 steps: products %.3e (recomputed %.3e), equilibrium "
                  "residual %.1e of %.1e\n",
                  res.complementarity, own, rmax, bmax);
    assert_true(fabs(own - res.complementarity) <= 1e-9 * res.complementarity);
    assert_true(own <= 2.0 * reached);
    assert_true(rmax <= 1e-6 * bmax);
    free(x);
    free(zl);
    free(zu);
    free(y);
    free(r);
    bl_system_free(s);
}

/* W4's path past its target: to deep = 1e-8 it gets there (res.deep), its
 * point's products as recomputed from the returned columns (to 1e-9) and
 * in equilibrium; towards 1e-30, which it cannot reach, the point at the
 * target is returned, the same bit for bit as from a path without the
 * deeper phase, with all the steps taken counted. */
static void deep_or_the_targets_point(void **state)
{
    (void)state;
    bl_system *s = w4(BL_FRICTION_FIXED);
    size_t nc = (size_t)s->ncols, nr = (size_t)s->nrows;
    double *x = calloc(nc, sizeof *x), *zl = calloc(nc, sizeof *zl), *zu = calloc(nc, sizeof *zu);
    double *y = calloc(nr, sizeof *y), *x0 = calloc(nc, sizeof *x0), *y0 = calloc(nr, sizeof *y0);
    double *r = calloc(nr, sizeof *r);
    bl_napath_result at, res;
    assert_int_equal(bl_napath_run(s, 1e-3, 1e-3, 1e-3, 100, 0, NULL, 0, x0, zl, zu, y0, &at, NULL), 0);
    assert_int_equal(at.deep, 0);

    assert_int_equal(bl_napath_run(s, 1e-3, 1e-3, 1e-8, 100, 0, NULL, 0, x, zl, zu, y, &res, NULL), 0);
    double own = products_of(s, x, zl, zu), bmax = 0.0, rmax = 0.0;
    for (size_t i = 0; i < nr; i++) {
        r[i] = s->rhs[i];
        bmax = fmax(bmax, fabs(s->rhs[i]));
    }
    for (int k = 0; k < s->ncols; k++)
        for (int q = s->colptr[k]; q < s->colptr[k + 1]; q++) r[s->rowind[q]] -= s->val[q] * x[k];
    for (size_t i = 0; i < nr; i++) rmax = fmax(rmax, fabs(r[i]));
    print_message("# W4's path: products %.1e at %d steps, %.1e at %d going deeper (recomputed "
                  "%.1e), equilibrium residual %.1e of %.1e\n",
                  at.complementarity, at.iterations, res.complementarity, res.iterations, own,
                  rmax, bmax);
    assert_int_equal(res.deep, 1);
    assert_true(res.complementarity <= 1e-8 && res.iterations > at.iterations);
    assert_true(fabs(own - res.complementarity) <= 1e-9 * res.complementarity);
    assert_true(rmax <= 1e-6 * bmax);

    assert_int_equal(bl_napath_run(s, 1e-3, 1e-3, 1e-30, 100, 0, NULL, 0, x, zl, zu, y, &res, NULL), 0);
    print_message("# towards 1e-30: %d steps, the point at %d returned\n", res.iterations,
                  at.iterations);
    assert_int_equal(res.deep, 0);
    assert_true(res.iterations > at.iterations);
    assert_true(res.complementarity == at.complementarity && res.alpha == at.alpha);
    assert_memory_equal(x, x0, nc * sizeof *x);
    assert_memory_equal(y, y0, nr * sizeof *y);
    free(x);
    free(zl);
    free(zu);
    free(y);
    free(x0);
    free(y0);
    free(r);
    bl_system_free(s);
}

static void stopped_when_cancelled(void **state)
{
    (void)state;
    bl_system *s = column(1, 0.4, 0.175, 0.5);
    double *x = calloc((size_t)s->ncols, sizeof *x), *zl = calloc((size_t)s->ncols, sizeof *zl);
    double *zu = calloc((size_t)s->ncols, sizeof *zu), *y = calloc((size_t)s->nrows, sizeof *y);
    bl_napath_result res;
    atomic_int cancel = 1;
    assert_int_equal(bl_napath_run(s, 1e-10, 1e-10, 1e-10, 100, 0, &cancel, 0, x, zl, zu, y, &res, NULL), 1);
    assert_true(res.stopped);
    assert_int_equal(res.iterations, 0);
    atomic_store(&cancel, 0);
    assert_int_equal(bl_napath_run(s, 1e-10, 1e-10, 1e-10, 100, 0, &cancel, 0, x, zl, zu, y, &res, NULL), 0);
    assert_false(res.stopped);
    assert_true(fabs(x[s->nforce] - 0.5) <= 1e-6);
    free(x);
    free(zl);
    free(zu);
    free(y);
    bl_system_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(single_block_slides),
        cmocka_unit_test(single_block_overturns),
        cmocka_unit_test(column_overturns_whole),
        cmocka_unit_test(warm_from_the_path),
        cmocka_unit_test(cut_short_taken_when_near),
        cmocka_unit_test(deep_or_the_targets_point),
        cmocka_unit_test(stopped_when_cancelled),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
