/* Unit tests of the LP interface on problems solved by hand: the optimum,
 * the sign convention of the row multipliers, warm re-solves after a bound
 * change, and the infeasible and unbounded outcomes. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "lp.h"

/* maximize a  s.t.  x1 + x2 = 2,  x1 - x2 + a = 0,  0 <= x1 <= hi, x2 >= 0.
 * a = x2 - x1 = 2 - 2 x1 is largest at x1 = 0: a = 2, x2 = 2.
 * Multipliers: obj - A^T y = 0 on a and x2 (basic): y2 = 1, y1 - y2 = 0 -> y1 = 1;
 * on x1 (at its lower bound): 0 - (y1 + y2) = -2 <= 0. */
static const int colptr[4] = {0, 2, 4, 5};
static const int rowind[5] = {0, 1, 0, 1, 1};
static const double val[5] = {1, 1, 1, -1, 1};
static const double rhs[2] = {2, 0};
static const double obj[3] = {0, 0, 1};

static void optimum_and_duals(void **state)
{
    (void)state;
    double lo[3] = {0, 0, -INFINITY}, hi[3] = {INFINITY, INFINITY, INFINITY};
    bl_lp_problem p = {2, 3, colptr, rowind, val, lo, hi, rhs, obj};
    bl_lp_settings s;
    bl_lp_settings_default(&s);
    bl_error err;
    bl_lp *lp = bl_lp_create(&p, &s, &err);
    assert_non_null(lp);
    assert_int_equal(bl_lp_solve(lp), BL_LP_OPTIMAL);
    const double *x = bl_lp_primal(lp), *y = bl_lp_dual(lp);
    assert_true(fabs(x[2] - 2) < 1e-12 && fabs(x[0]) < 1e-12 && fabs(x[1] - 2) < 1e-12);
    assert_true(fabs(y[0] - 1) < 1e-12 && fabs(y[1] - 1) < 1e-12);

    /* Force x1 >= 0.5: a = 2 - 2 * 0.5 = 1. */
    double lo2[3] = {0.5, 0, -INFINITY};
    bl_lp_set_bounds(lp, lo2, hi);
    assert_int_equal(bl_lp_solve(lp), BL_LP_OPTIMAL);
    assert_true(fabs(bl_lp_primal(lp)[2] - 1) < 1e-12);

    /* x1 >= 3 leaves x2 = 2 - x1 < 0: infeasible. */
    double lo3[3] = {3, 0, -INFINITY};
    bl_lp_set_bounds(lp, lo3, hi);
    assert_int_equal(bl_lp_solve(lp), BL_LP_INFEASIBLE);
    bl_lp_free(lp);
}

static void unbounded(void **state)
{
    (void)state;
    /* maximize a s.t. x1 - a = 0, x1 >= 0: a grows with x1. */
    const int cp[3] = {0, 1, 2}, ri[2] = {0, 0};
    const double v[2] = {1, -1}, b[1] = {0}, c[2] = {0, 1};
    double lo[2] = {0, -INFINITY}, hi[2] = {INFINITY, INFINITY};
    bl_lp_problem p = {1, 2, cp, ri, v, lo, hi, b, c};
    bl_lp_settings s;
    bl_lp_settings_default(&s);
    bl_lp *lp = bl_lp_create(&p, &s, NULL);
    assert_non_null(lp);
    assert_int_equal(bl_lp_solve(lp), BL_LP_UNBOUNDED);
    bl_lp_free(lp);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(optimum_and_duals),
        cmocka_unit_test(unbounded),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
