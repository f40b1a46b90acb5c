/* Unit tests of geometry.c against hand-computed values. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "geometry.h"

static void area_and_centroid(void **state)
{
    (void)state;
    /* An L of three unit squares: area 3, centroid (5/6, 5/6). */
    bl_vec2 L[6] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    assert_true(fabs(bl_polygon_area(L, 6) - 3.0) < 1e-15);
    bl_vec2 c = bl_polygon_centroid(L, 6);
    assert_true(fabs(c.x - 5.0 / 6) < 1e-15 && fabs(c.y - 5.0 / 6) < 1e-15);
    bl_polygon_reverse(L, 6);
    assert_true(fabs(bl_polygon_area(L, 6) + 3.0) < 1e-15);
    /* Far from the origin the fan from p[0] keeps full accuracy. */
    bl_vec2 sq[4] = {{1e6, 1e6}, {1e6 + 1, 1e6}, {1e6 + 1, 1e6 + 1}, {1e6, 1e6 + 1}};
    c = bl_polygon_centroid(sq, 4);
    assert_true(fabs(c.x - (1e6 + 0.5)) < 1e-9 && fabs(c.y - (1e6 + 0.5)) < 1e-9);
}

static void self_intersection(void **state)
{
    (void)state;
    int i, j;
    bl_vec2 bow[4] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
    assert_int_equal(bl_polygon_self_intersection(bow, 4, 1e-12, &i, &j), 1);
    bl_vec2 sq[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    assert_int_equal(bl_polygon_self_intersection(sq, 4, 1e-12, &i, &j), 0);
    bl_vec2 spike[5] = {{0, 0}, {1, 0}, {1, 1}, {1, 0.5}, {0, 1}}; /* folds back on itself */
    assert_int_equal(bl_polygon_self_intersection(spike, 5, 1e-12, &i, &j), 1);
    bl_vec2 L[6] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    assert_int_equal(bl_polygon_self_intersection(L, 6, 1e-12, &i, &j), 0);
}

static void depth(void **state)
{
    (void)state;
    bl_vec2 sq[4] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    assert_true(fabs(bl_polygon_depth(sq, 4, bl_v2(1, 0.5)) - 0.5) < 1e-15);
    assert_true(fabs(bl_polygon_depth(sq, 4, bl_v2(3, 1)) + 1.0) < 1e-15);
    assert_true(bl_segments_cross(bl_v2(0, 0), bl_v2(1, 1), bl_v2(0, 1), bl_v2(1, 0), 1e-12));
    assert_false(bl_segments_cross(bl_v2(0, 0), bl_v2(1, 0), bl_v2(1, 0), bl_v2(2, 0), 1e-12));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(area_and_centroid),
        cmocka_unit_test(self_intersection),
        cmocka_unit_test(depth),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
