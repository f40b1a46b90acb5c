/* Re-solves of the W4 wall's LP (DESIGN.md 5, assembled through the model).
 * Warm starts: after a small change of the bounds, re-solving from the last
 * solve (its basis; for the interior point, an iterate kept from its path)
 * takes fewer iterations than solving the changed LP from scratch,
 * with either engine, and reaches the same optimum (counted, not timed).
 * The interior point's early dual ray (settings.early_infeasible): with the
 * load multiplier held above W4's associative 0.331948, where no
 * equilibrium exists, it ends sooner, and its ray, checked on the matrix,
 * proves that an equilibrium would need more than ten times the forces of
 * one at 0.3; at 0.3 itself it solves as without it.
 * A warm start far off (far_warm) falls back to a cold start.
 * Rewinding (bl_lp_mark, bl_lp_rewind): a solve taken back leaves no trace
 * on the next one, whose iterations and answer are those of the same two
 * solves made without it, to the last bit.
 * The weighted path (settings.weighted) ends at another point of the
 * optimal face, with the simplex's alpha. */
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
#include "w4.h"

static bl_lp *make(const bl_system *s, const double *lo, bl_lp_engine_kind engine)
{
    bl_lp_problem p = {s->nrows, s->ncols, s->colptr, s->rowind, s->val,
                       lo,       s->hi,    s->rhs,    s->obj};
    bl_lp_settings set;
    bl_lp_settings_default(&set);
    set.engine = engine;
    bl_lp *lp = bl_lp_create(&p, &set, NULL);
    assert_non_null(lp);
    return lp;
}

static void warm_vs_cold(bl_lp_engine_kind engine)
{
    bl_system *s = w4(BL_FRICTION_CONE);
    /* the changed LP: every force column carries at least 1e-3 W0 */
    double *lo2 = malloc((size_t)s->ncols * sizeof *lo2);
    memcpy(lo2, s->lo, (size_t)s->ncols * sizeof *lo2);
    for (int j = 0; j < s->nforce; j++)
        if (lo2[j] == 0.0) lo2[j] = 1e-3;

    bl_lp *warm = make(s, s->lo, engine);
    assert_int_equal(bl_lp_solve(warm), BL_LP_OPTIMAL);
    double a1 = bl_lp_primal(warm)[s->nforce];
    bl_lp_set_bounds(warm, lo2, s->hi);
    assert_int_equal(bl_lp_solve(warm), BL_LP_OPTIMAL);
    bl_lp *cold = make(s, lo2, engine);
    assert_int_equal(bl_lp_solve(cold), BL_LP_OPTIMAL);

    double aw = bl_lp_primal(warm)[s->nforce], ac = bl_lp_primal(cold)[s->nforce];
    print_message("# %s: alpha %.10f -> %.10f; iterations warm %d, cold %d\n",
                  bl_lp_engine(warm), a1, ac, bl_lp_iterations(warm), bl_lp_iterations(cold));
    assert_true(ac < a1);                          /* the change matters */
    assert_true(fabs(aw - ac) <= 1e-7 * fabs(ac)); /* same optimum */
    assert_true(bl_lp_iterations(warm) < bl_lp_iterations(cold));
    bl_lp_free(warm);
    bl_lp_free(cold);
    free(lo2);
    bl_system_free(s);
}

static void simplex(void **state)
{
    (void)state;
    warm_vs_cold(BL_LP_SIMPLEX);
}

static void interior_point(void **state)
{
    (void)state;
    warm_vs_cold(BL_LP_IPM);
}

/* The W4 LP with alpha held at a, on the interior point, with or without
 * the early ray: its status, and the forces' sum when optimal. */
static bl_lp *held(const bl_system *s, double a, int early, bl_lp_status *st)
{
    double *lo = malloc((size_t)s->ncols * sizeof *lo), *hi = malloc((size_t)s->ncols * sizeof *hi);
    memcpy(lo, s->lo, (size_t)s->ncols * sizeof *lo);
    memcpy(hi, s->hi, (size_t)s->ncols * sizeof *hi);
    lo[s->nforce] = hi[s->nforce] = a;
    double *zero = calloc((size_t)s->ncols, sizeof *zero);
    bl_lp_problem p = {s->nrows, s->ncols, s->colptr, s->rowind, s->val, lo, hi, s->rhs, zero};
    bl_lp_settings set;
    bl_lp_settings_default(&set);
    set.engine = BL_LP_IPM;
    set.early_infeasible = early;
    bl_lp *lp = bl_lp_create(&p, &set, NULL);
    assert_non_null(lp);
    *st = bl_lp_solve(lp);
    free(lo);
    free(hi);
    free(zero);
    return lp;
}

static void early_ray(void **state)
{
    (void)state;
    bl_system *s = w4(BL_FRICTION_CONE);
    bl_lp_status st;
    /* an equilibrium at 0.3, below the associative alpha */
    bl_lp *ok = held(s, 0.3, 1, &st);
    assert_int_equal(st, BL_LP_OPTIMAL);
    double sum = 0.0;
    for (int j = 0; j < s->nforce; j++) sum += bl_lp_primal(ok)[j];
    bl_lp *plain = held(s, 0.3, 0, &st);
    assert_int_equal(st, BL_LP_OPTIMAL);
    assert_int_equal(bl_lp_iterations(ok), bl_lp_iterations(plain));

    /* none at 0.4 */
    bl_lp *late = held(s, 0.4, 0, &st);
    assert_int_equal(st, BL_LP_INFEASIBLE);
    bl_lp *early = held(s, 0.4, 1, &st);
    assert_int_equal(st, BL_LP_INFEASIBLE);
    print_message("# infeasible at 0.4: %d iterations, %d with the early ray\n",
                  bl_lp_iterations(late), bl_lp_iterations(early));
    assert_true(bl_lp_iterations(early) < bl_lp_iterations(late));

    /* the ray r on the matrix: for x >= 0 with A x = rhs - 0.4 fL,
     * r.(rhs - 0.4 fL) = (A^T r).x <= e sum x, e the largest (A^T r)_j */
    const double *r = bl_lp_ray(early);
    assert_non_null(r);
    double L = 0.0, e = 0.0;
    for (int i = 0; i < s->nrows; i++) L += s->rhs[i] * r[i];
    for (int q = s->colptr[s->nforce]; q < s->colptr[s->nforce + 1]; q++)
        L -= 0.4 * s->val[q] * r[s->rowind[q]];
    double sg = L < 0.0 ? -1.0 : 1.0; /* the ray's sign is the engine's */
    for (int j = 0; j < s->nforce; j++) {
        assert_true(s->lo[j] == 0.0 && isinf(s->hi[j])); /* the cone's columns */
        double w = 0.0;
        for (int q = s->colptr[j]; q < s->colptr[j + 1]; q++) w += s->val[q] * r[s->rowind[q]];
        e = fmax(e, sg * w);
    }
    print_message("# ray: any equilibrium at 0.4 needs sum x >= %.3g (%.3g at 0.3)\n",
                  sg * L / e, sum);
    assert_true(sg * L > 0.0 && sg * L >= 10.0 * e * sum);
    bl_lp_free(ok);
    bl_lp_free(plain);
    bl_lp_free(late);
    bl_lp_free(early);
    bl_system_free(s);
}

/* The W4 LP with every force column at least lo: the bounds of a re-solve. */
static void floor_bounds(const bl_system *s, double lo, double *out)
{
    memcpy(out, s->lo, (size_t)s->ncols * sizeof *out);
    for (int j = 0; j < s->nforce; j++)
        if (out[j] == 0.0) out[j] = lo;
}

static void rewind_solve(void **state)
{
    (void)state;
    bl_system *s = w4(BL_FRICTION_CONE);
    double *b = malloc((size_t)s->ncols * sizeof *b), *c = malloc((size_t)s->ncols * sizeof *c);
    floor_bounds(s, 5e-3, b); /* the solve taken back */
    floor_bounds(s, 1e-3, c); /* the one after it */

    bl_lp *straight = make(s, s->lo, BL_LP_IPM);
    assert_int_equal(bl_lp_solve(straight), BL_LP_OPTIMAL);
    bl_lp_set_bounds(straight, c, s->hi);
    assert_int_equal(bl_lp_solve(straight), BL_LP_OPTIMAL);

    bl_lp *back = make(s, s->lo, BL_LP_IPM);
    assert_int_equal(bl_lp_solve(back), BL_LP_OPTIMAL);
    assert_int_equal(bl_lp_mark(back), 0);
    bl_lp_set_bounds(back, b, s->hi);
    assert_int_equal(bl_lp_solve(back), BL_LP_OPTIMAL);
    double ab = bl_lp_primal(back)[s->nforce];
    int ib = bl_lp_iterations(back);
    bl_lp_rewind(back);
    bl_lp_set_bounds(back, c, s->hi);
    assert_int_equal(bl_lp_solve(back), BL_LP_OPTIMAL);

    /* without the rewind the third solve starts elsewhere */
    bl_lp *on = make(s, s->lo, BL_LP_IPM);
    assert_int_equal(bl_lp_solve(on), BL_LP_OPTIMAL);
    bl_lp_set_bounds(on, b, s->hi);
    assert_int_equal(bl_lp_solve(on), BL_LP_OPTIMAL);
    bl_lp_set_bounds(on, c, s->hi);
    assert_int_equal(bl_lp_solve(on), BL_LP_OPTIMAL);

    double as = bl_lp_primal(straight)[s->nforce], ar = bl_lp_primal(back)[s->nforce];
    print_message("# taken back: alpha %.10f in %d iterations; then alpha %.17g in %d "
                  "iterations, %.17g in %d without it, %.17g in %d not taken back\n",
                  ab, ib, ar, bl_lp_iterations(back), as, bl_lp_iterations(straight),
                  bl_lp_primal(on)[s->nforce], bl_lp_iterations(on));
    assert_true(ab != as); /* the solve taken back had another answer */
    assert_int_equal(bl_lp_iterations(back), bl_lp_iterations(straight));
    assert_memory_equal(bl_lp_primal(back), bl_lp_primal(straight), (size_t)s->ncols * sizeof(double));
    assert_memory_equal(bl_lp_dual(back), bl_lp_dual(straight), (size_t)s->nrows * sizeof(double));
    assert_true(bl_lp_iterations(on) != bl_lp_iterations(back) ||
                memcmp(bl_lp_primal(on), bl_lp_primal(back), (size_t)s->ncols * sizeof(double)) != 0);

    /* the simplex has no such state to keep */
    bl_lp *simplex = make(s, s->lo, BL_LP_SIMPLEX);
    assert_int_equal(bl_lp_mark(simplex), -1);
    bl_lp_free(simplex);
    bl_lp_free(straight);
    bl_lp_free(back);
    bl_lp_free(on);
    free(b);
    free(c);
    bl_system_free(s);
}

/* A warm start that does not take: the W4 LP started from its own answer
 * with every force at a hundredth of its value (the rows off by nearly the
 * whole load) and products of 1e-7.  Pinned to the boundary, such a start
 * ran to the iteration limit of 200 (so did a certificate of the
 * 10,050-block wall's sequence); the engine now starts again from
 * Mehrotra's point after WARM_PATIENCE (10) iterations that do not halve
 * its residuals, and must end at the cold solve's optimum (1e-7 relative)
 * in at most the cold iterations plus 11. */
static void far_warm(void **state)
{
    (void)state;
    bl_system *s = w4(BL_FRICTION_CONE);
    size_t nc = (size_t)s->ncols;
    bl_lp *cold = make(s, s->lo, BL_LP_IPM);
    assert_int_equal(bl_lp_solve(cold), BL_LP_OPTIMAL);
    double *x = malloc(nc * sizeof *x), *zl = calloc(nc, sizeof *zl), *zu = calloc(nc, sizeof *zu);
    memcpy(x, bl_lp_primal(cold), nc * sizeof *x);
    for (int j = 0; j < s->nforce; j++) {
        x[j] = 0.01 * x[j] + 1e-9;
        zl[j] = 1e-7 / x[j];
    }
    bl_lp *far = make(s, s->lo, BL_LP_IPM);
    assert_int_equal(bl_lp_warm(far, x, zl, zu, bl_lp_dual(cold), 1e-7), 0);
    bl_lp_status st = bl_lp_solve(far);
    double ac = bl_lp_primal(cold)[s->nforce];
    print_message("# far warm start: status %d, alpha %.10f in %d iterations; cold %.10f in %d\n", st,
                  st == BL_LP_OPTIMAL ? bl_lp_primal(far)[s->nforce] : NAN, bl_lp_iterations(far), ac,
                  bl_lp_iterations(cold));
    assert_int_equal(st, BL_LP_OPTIMAL);
    assert_true(fabs(bl_lp_primal(far)[s->nforce] - ac) <= 1e-7 * ac);
    assert_true(bl_lp_iterations(far) <= bl_lp_iterations(cold) + 11);
    bl_lp_free(cold);
    bl_lp_free(far);
    free(x);
    free(zl);
    free(zu);
    bl_system_free(s);
}

static void weighted_path(void **state)
{
    (void)state;
    bl_system *s = w4(BL_FRICTION_CONE);
    bl_lp *sx = make(s, s->lo, BL_LP_SIMPLEX);
    assert_int_equal(bl_lp_solve(sx), BL_LP_OPTIMAL);
    double as = bl_lp_primal(sx)[s->nforce];
    const double *x[2];
    bl_lp *lp[2];
    for (int weighted = 0; weighted <= 1; weighted++) {
        bl_lp_problem p = {s->nrows, s->ncols, s->colptr, s->rowind, s->val,
                           s->lo,    s->hi,    s->rhs,    s->obj};
        bl_lp_settings set;
        bl_lp_settings_default(&set);
        set.engine = BL_LP_IPM;
        set.weighted = weighted;
        lp[weighted] = bl_lp_create(&p, &set, NULL);
        assert_non_null(lp[weighted]);
        assert_int_equal(bl_lp_solve(lp[weighted]), BL_LP_OPTIMAL);
        x[weighted] = bl_lp_primal(lp[weighted]);
    }
    double dmax = 0.0;
    for (int j = 0; j < s->nforce; j++) dmax = fmax(dmax, fabs(x[1][j] - x[0][j]));
    print_message("# alpha simplex %.10f, analytic centre %.10f (%d iterations), weighted %.10f "
                  "(%d); forces apart by up to %.3g W0\n",
                  as, x[0][s->nforce], bl_lp_iterations(lp[0]), x[1][s->nforce],
                  bl_lp_iterations(lp[1]), dmax);
    for (int k = 0; k < 2; k++) assert_true(fabs(x[k][s->nforce] - as) <= 1e-8 * as);
    assert_true(dmax > 1e-4); /* the two paths end apart */
    for (int k = 0; k < 2; k++) bl_lp_free(lp[k]);
    bl_lp_free(sx);
    bl_system_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(simplex),
        cmocka_unit_test(interior_point),
        cmocka_unit_test(early_ray),
        cmocka_unit_test(rewind_solve),
        cmocka_unit_test(far_warm),
        cmocka_unit_test(weighted_path),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
