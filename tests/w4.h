/* w4.h - the W4 wall of DESIGN.md 5 for the C tests (test_warm.c,
 * test_napath.c): eleven courses of 0.4 x 0.175 blocks with two windows on
 * a 2 x 0.175 support, friction 0.65, its interfaces detected.  Include
 * after <cmocka.h>, "assemble.h" and "contact.h". */
#ifndef BL_TEST_W4_H
#define BL_TEST_W4_H

#include <math.h>

static void w4_course(bl_model *m, const double *c, int n, int row)
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

/* W4's system in the given friction form. */
static bl_system *w4(bl_friction_form form)
{
    bl_model *m = bl_model_new();
    const double E[] = {.5, 1, 1, 1, 1, .5}, U[] = {1, 1, 1, 1, 1}, Wu[] = {1, -1, 1, -1, 1},
                 We[] = {.5, .5, -1, .5, .5, -1, .5, .5};
    const double *cs[] = {E, U, E, Wu, We, Wu, We, Wu, E, U, E};
    const int ns[] = {6, 5, 6, 5, 8, 5, 8, 5, 6, 5, 6};
    for (int r = 0; r < 11; r++) w4_course(m, cs[r], ns[r], r);
    bl_vec2 b[4] = {{0, -0.175}, {2, -0.175}, {2, 0}, {0, 0}};
    assert_int_equal(bl_model_add_block(m, b, 4, 1, 0, 0, NULL), 0);
    assert_int_equal(bl_contact_detect(m, NULL), 0);
    bl_system *s = bl_system_build(m, form, NULL);
    bl_model_free(m);
    assert_non_null(s);
    return s;
}

#endif
