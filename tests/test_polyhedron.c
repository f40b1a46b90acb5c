/* Unit tests of polyhedron.c against hand-computed volumes and centroids,
 * and the checks' messages on bad solids. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "polyhedron.h"

/* A box [0,a] x [0,b] x [0,c]: vertices 0-3 at z = 0, 4-7 at z = c. */
static const int box_fs[7] = {0, 4, 8, 12, 16, 20, 24};
static const int box_fi[24] = {0, 3, 2, 1, /* bottom, outward -z */ 4, 5, 6, 7, /* top */
                               0, 1, 5, 4, /* y = 0 */ 1, 2, 6, 5, /* x = a */
                               2, 3, 7, 6, /* y = b */ 3, 0, 4, 7 /* x = 0 */};

static void box(bl_vec3 v[8], double a, double b, double c, double x0)
{
    double x[4] = {0, a, a, 0}, y[4] = {0, 0, b, b};
    for (int i = 0; i < 4; i++) {
        v[i] = bl_v3(x0 + x[i], y[i], 0);
        v[i + 4] = bl_v3(x0 + x[i], y[i], c);
    }
}

static void box_volume(void **state)
{
    (void)state;
    bl_vec3 v[8];
    box(v, 2, 3, 4, 1e6); /* far from the origin: the fan from a vertex keeps accuracy */
    bl_polyhedron p;
    assert_int_equal(bl_polyhedron_make(&p, v, 8, box_fs, box_fi, 6), 0);
    bl_error err;
    assert_int_equal(bl_polyhedron_check(&p, 1e-9, 1, &err), 0);
    bl_vec3 c;
    double vol = bl_polyhedron_volume(&p, &c);
    assert_true(fabs(vol - 24.0) < 1e-8);
    assert_true(fabs(c.x - (1e6 + 1)) < 1e-8 && fabs(c.y - 1.5) < 1e-12 && fabs(c.z - 2) < 1e-12);
    double area;
    bl_vec3 n = bl_polyhedron_face_normal(&p, 1, &area);
    assert_true(fabs(n.z - 1) < 1e-15 && fabs(area - 6) < 1e-9);
    bl_polyhedron_free(&p);
}

static void tetrahedron(void **state)
{
    (void)state;
    /* corners at the origin and the unit points: volume 1/6, centroid 1/4 */
    bl_vec3 v[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    int fs[5] = {0, 3, 6, 9, 12}, fi[12] = {0, 1, 2, 0, 1, 3, 1, 2, 3, 0, 2, 3};
    bl_polyhedron p;
    bl_error err;
    assert_int_equal(bl_polyhedron_make(&p, v, 4, fs, fi, 4), 0);
    /* every face given in an arbitrary order: the check orients them */
    assert_int_equal(bl_polyhedron_check(&p, 1e-9, 1, &err), 0);
    bl_vec3 c;
    assert_true(fabs(bl_polyhedron_volume(&p, &c) - 1.0 / 6) < 1e-15);
    assert_true(fabs(c.x - 0.25) < 1e-15 && fabs(c.y - 0.25) < 1e-15 && fabs(c.z - 0.25) < 1e-15);
    for (int k = 0; k < 4; k++) { /* outward: away from the centroid */
        bl_vec3 n = bl_polyhedron_face_normal(&p, k, NULL);
        assert_true(bl_v3_dot(n, bl_v3_sub(p.v[p.fi[p.fs[k]]], c)) > 0);
    }
    bl_polyhedron_free(&p);
}

/* Runs the check on a box changed by `edit` and expects a message
 * containing every given string. */
static void expect_error(void (*edit)(bl_vec3 *, int *), const char *a, const char *b)
{
    bl_vec3 v[8];
    int fi[24];
    box(v, 1, 1, 1, 0);
    memcpy(fi, box_fi, sizeof fi);
    edit(v, fi);
    bl_polyhedron p;
    bl_error err;
    assert_int_equal(bl_polyhedron_make(&p, v, 8, box_fs, fi, 6), 0);
    assert_int_equal(bl_polyhedron_check(&p, 1e-9, 7, &err), -1);
    assert_non_null(strstr(err.msg, "block 7"));
    assert_non_null(strstr(err.msg, a));
    assert_non_null(strstr(err.msg, b));
    bl_polyhedron_free(&p);
}

static void bent_top(bl_vec3 *v, int *fi) { (void)fi; v[6].z = 1.01; }
static void open_side(bl_vec3 *v, int *fi) { (void)v; fi[20] = 3, fi[21] = 0, fi[22] = 4, fi[23] = 0; }
static void flat_box(bl_vec3 *v, int *fi)
{
    (void)fi;
    for (int i = 4; i < 8; i++) v[i].z = 0;
}

static void bad_solids(void **state)
{
    (void)state;
    expect_error(bent_top, "face 2", "not planar");
    expect_error(open_side, "face 6", "twice");
    expect_error(flat_box, "face", "zero area");
    /* a face left out: the surface is open at its edges */
    bl_vec3 v[8];
    box(v, 1, 1, 1, 0);
    bl_polyhedron p;
    bl_error err;
    int fs[6] = {0, 4, 8, 12, 16, 20};
    assert_int_equal(bl_polyhedron_make(&p, v, 8, fs, box_fi, 5), 0);
    assert_int_equal(bl_polyhedron_check(&p, 1e-9, 2, &err), -1);
    assert_non_null(strstr(err.msg, "open"));
    bl_polyhedron_free(&p);
}

static void inverted_faces(void **state)
{
    (void)state;
    bl_vec3 v[8];
    box(v, 1, 2, 3, 0);
    int fi[24];
    for (int t = 0; t < 24; t++) fi[t] = box_fi[23 - t]; /* every face reversed, and reordered */
    int fs[7] = {0, 4, 8, 12, 16, 20, 24};
    bl_polyhedron p;
    bl_error err;
    assert_int_equal(bl_polyhedron_make(&p, v, 8, fs, fi, 6), 0);
    assert_int_equal(bl_polyhedron_check(&p, 1e-9, 1, &err), 0);
    assert_true(fabs(bl_polyhedron_volume(&p, NULL) - 6.0) < 1e-12);
    bl_polyhedron_free(&p);
}

static void hull(void **state)
{
    (void)state;
    /* the corners of a 2 x 1 x 1 box and points inside and on its faces */
    bl_vec3 pts[12];
    box(pts, 2, 1, 1, 0);
    pts[8] = bl_v3(1, 0.5, 0.5);
    pts[9] = bl_v3(1, 0, 0.5);   /* on a face */
    pts[10] = bl_v3(0.5, 0.5, 1); /* on a face */
    pts[11] = bl_v3(0.3, 0.2, 0.1);
    bl_polyhedron p;
    bl_error err;
    assert_int_equal(bl_convex_hull(pts, 12, 3, &p, &err), 0);
    assert_int_equal(bl_polyhedron_check(&p, 1e-9, 3, &err), 0);
    assert_int_equal(p.nf, 6); /* coplanar facets merged into the box's faces */
    assert_int_equal(p.nv, 8);
    bl_vec3 c;
    assert_true(fabs(bl_polyhedron_volume(&p, &c) - 2.0) < 1e-12);
    assert_true(fabs(c.x - 1) < 1e-12 && fabs(c.y - 0.5) < 1e-12 && fabs(c.z - 0.5) < 1e-12);
    bl_polyhedron_free(&p);
    /* points on one plane span no volume */
    bl_vec3 flat[5] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}};
    assert_int_equal(bl_convex_hull(flat, 5, 4, &p, &err), -1);
    assert_non_null(strstr(err.msg, "block 4"));
    assert_non_null(strstr(err.msg, "no volume"));
}

/* Signed distances to the surface, by hand: a box and an L-shaped prism
 * (not convex: a point in its notch is outside). */
static void depth(void **state)
{
    (void)state;
    bl_vec3 v[12];
    box(v, 2, 3, 4, 0);
    bl_polyhedron p;
    bl_error err;
    assert_int_equal(bl_polyhedron_make(&p, v, 8, box_fs, box_fi, 6), 0);
    assert_int_equal(bl_polyhedron_check(&p, 1e-9, 1, &err), 0);
    assert_true(fabs(bl_polyhedron_depth(&p, bl_v3(1, 1.5, 2)) - 1.0) < 1e-12);
    assert_true(fabs(bl_polyhedron_depth(&p, bl_v3(0.2, 1.5, 2)) - 0.2) < 1e-12);
    assert_true(fabs(bl_polyhedron_depth(&p, bl_v3(3, 1.5, 2)) + 1.0) < 1e-12);
    assert_true(fabs(bl_polyhedron_depth(&p, bl_v3(3, 4, 2)) + sqrt(2.0)) < 1e-12);
    assert_true(fabs(bl_polyhedron_depth(&p, bl_v3(3, 4, 5)) + sqrt(3.0)) < 1e-12);
    bl_polyhedron_free(&p);
    /* the L (0,0) (2,0) (2,1) (1,1) (1,2) (0,2), from z = 0 to 1 */
    double x[6] = {0, 2, 2, 1, 1, 0}, y[6] = {0, 0, 1, 1, 2, 2};
    for (int i = 0; i < 6; i++) {
        v[i] = bl_v3(x[i], y[i], 0);
        v[i + 6] = bl_v3(x[i], y[i], 1);
    }
    int fs[9] = {0, 6, 12, 16, 20, 24, 28, 32, 36}, fi[36] = {5, 4, 3, 2, 1, 0, 6, 7, 8, 9, 10, 11};
    for (int i = 0; i < 6; i++) {
        int j = (i + 1) % 6, *f = fi + 12 + 4 * i;
        f[0] = i, f[1] = j, f[2] = j + 6, f[3] = i + 6;
    }
    assert_int_equal(bl_polyhedron_make(&p, v, 12, fs, fi, 8), 0);
    assert_int_equal(bl_polyhedron_check(&p, 1e-9, 1, &err), 0);
    assert_true(fabs(bl_polyhedron_depth(&p, bl_v3(1.5, 1.5, 0.5)) + 0.5) < 1e-12);
    assert_true(fabs(bl_polyhedron_depth(&p, bl_v3(1.8, 1.9, 0.5)) + 0.8) < 1e-12);
    assert_true(fabs(bl_polyhedron_depth(&p, bl_v3(0.5, 1.5, 0.5)) - 0.5) < 1e-12);
    assert_true(fabs(bl_polyhedron_depth(&p, bl_v3(1.5, 0.8, 0.5)) - 0.2) < 1e-12);
    assert_true(fabs(bl_polyhedron_depth(&p, bl_v3(1.5, 0.5, -0.25)) + 0.25) < 1e-12);
    /* in the notch, in the plane of an end face (which they lie outside):
     * outside, as far from the notch's walls as from the nearer one (the
     * fan of the end face, seen edge on, read some as inside) */
    for (int z = 0; z <= 1; z++)
        for (int i = 1; i < 10; i++)
            for (int j = 1; j < 10; j++) {
                double a = 1 + 0.1 * i, b = 1 + 0.1 * j;
                assert_true(fabs(bl_polyhedron_depth(&p, bl_v3(a, b, z)) + fmin(a, b) - 1) < 1e-12);
            }
    bl_polyhedron_free(&p);
}

/* Segments through a face of a box 2 x 3 x 4, by hand: through the face
 * x = 0 into the box, either way; along it (not through); through it only
 * within tol of its edge; ending within tol of it; and through it far from
 * its edges but out again at once, never deeper than tol. */
static void pierced(void **state)
{
    (void)state;
    bl_vec3 v[8];
    box(v, 2, 3, 4, 0);
    bl_polyhedron p;
    bl_error err;
    double tol = 1e-6;
    assert_int_equal(bl_polyhedron_make(&p, v, 8, box_fs, box_fi, 6), 0);
    assert_int_equal(bl_polyhedron_check(&p, 1e-9, 1, &err), 0);
    assert_true(bl_polyhedron_pierced(&p, bl_v3(-1, 1.5, 2), bl_v3(1, 1.5, 2), tol));
    assert_true(bl_polyhedron_pierced(&p, bl_v3(1, 1.5, 2), bl_v3(-1, 1.5, 2), tol));
    assert_false(bl_polyhedron_pierced(&p, bl_v3(0, -1, 2), bl_v3(0, 4, 2), tol));
    assert_false(bl_polyhedron_pierced(&p, bl_v3(-1, 0.5 * tol, 2), bl_v3(1, 0.5 * tol, 2), tol));
    assert_false(bl_polyhedron_pierced(&p, bl_v3(-1, 1.5, 2), bl_v3(0.5 * tol, 1.5, 2), tol));
    /* through x = 0 at y = 0.5, then out through y = 0 at x = 0.3 tol:
     * never deeper than 0.3 tol */
    assert_false(bl_polyhedron_pierced(&p, bl_v3(-3 * tol, 5.5, 2), bl_v3(3.3 * tol, -5, 2), tol));
    /* the same, out through y = 0 at x = 3 tol: deeper */
    assert_true(bl_polyhedron_pierced(&p, bl_v3(-30 * tol, 5.5, 2), bl_v3(33 * tol, -5, 2), tol));
    bl_polyhedron_free(&p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(box_volume), cmocka_unit_test(tetrahedron), cmocka_unit_test(bad_solids),
        cmocka_unit_test(inverted_faces), cmocka_unit_test(hull), cmocka_unit_test(depth),
        cmocka_unit_test(pierced),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
