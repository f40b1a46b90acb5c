/* Warm starts: after a small change of the bounds, re-solving from the last
 * solve (its basis; for the interior point, an iterate kept from its path)
 * takes fewer iterations than solving the changed LP from scratch,
 * with either engine, and reaches the same optimum (counted, not timed).
 * The LP is the W4 wall of DESIGN.md 5 (assembled through the model). */
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

static void course(bl_model *m, const double *c, int n, int row)
{
    double x = 0, L = 0.4, H = 0.175;
    for (int i = 0; i < n; i++) {
        double len = fabs(c[i]);
        if (c[i] > 0) {
            bl_vec2 v[4] = {{x * L, row * H}, {(x + len) * L, row * H},
                            {(x + len) * L, (row + 1) * H}, {x * L, (row + 1) * H}};
            assert_int_equal(bl_model_add_block(m, v, 4, 0, 0, 0, NULL), 0);
        }
        x += len;
    }
}

static bl_system *w4(void)
{
    bl_model *m = bl_model_new();
    const double E[] = {.5, 1, 1, 1, 1, .5}, U[] = {1, 1, 1, 1, 1}, Wu[] = {1, -1, 1, -1, 1},
                 We[] = {.5, .5, -1, .5, .5, -1, .5, .5};
    const double *cs[] = {E, U, E, Wu, We, Wu, We, Wu, E, U, E};
    const int ns[] = {6, 5, 6, 5, 8, 5, 8, 5, 6, 5, 6};
    for (int r = 0; r < 11; r++) course(m, cs[r], ns[r], r);
    bl_vec2 b[4] = {{0, -0.175}, {2, -0.175}, {2, 0}, {0, 0}};
    assert_int_equal(bl_model_add_block(m, b, 4, 1, 0, 0, NULL), 0);
    assert_int_equal(bl_contact_detect(m, NULL), 0);
    bl_system *s = bl_system_build(m, BL_FRICTION_CONE, NULL);
    bl_model_free(m);
    assert_non_null(s);
    return s;
}

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
    bl_system *s = w4();
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(simplex),
        cmocka_unit_test(interior_point),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
