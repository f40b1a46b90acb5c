/* Unit tests of normal.c: the solve of (F F^T + delta I) x = b checked by
 * its residual, computed here from F itself, for one factorization and for
 * the split into two domains; both answers agree; a negative delta is
 * reported as not positive definite. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "normal.h"

/* A g x g grid of nodes with 3 rows each, like the blocks of a wall: a
 * column of 6 entries per pair of neighbouring nodes (right and up, two
 * each), and one of 3 entries per node. */
typedef struct grid {
    int m, n;
    int *colptr, *rowind, *map;
    double *val, *scale;
} grid;

static unsigned long long state = 12345;
static double uniform(void)
{
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(state >> 11) / 9007199254740992.0;
}

static void grid_make(grid *G, int g)
{
    int nodes = g * g, maxcols = nodes * 5;
    G->m = 3 * nodes;
    G->colptr = malloc((size_t)(maxcols + 1) * sizeof(int));
    G->rowind = malloc((size_t)maxcols * 6 * sizeof(int));
    G->val = malloc((size_t)maxcols * 6 * sizeof(double));
    int c = 0, q = 0;
    for (int i = 0; i < g; i++)
        for (int j = 0; j < g; j++) {
            int a = i * g + j, nb[2] = {j + 1 < g ? a + 1 : -1, i + 1 < g ? a + g : -1};
            for (int e = 0; e < 2; e++)
                for (int twice = 0; twice < 2 && nb[e] >= 0; twice++) {
                    G->colptr[c++] = q;
                    for (int r = 0; r < 3; r++, q++) G->rowind[q] = 3 * a + r, G->val[q] = uniform() - 0.5;
                    for (int r = 0; r < 3; r++, q++) G->rowind[q] = 3 * nb[e] + r, G->val[q] = uniform() - 0.5;
                }
            G->colptr[c++] = q;
            for (int r = 0; r < 3; r++, q++) G->rowind[q] = 3 * a + r, G->val[q] = uniform();
        }
    G->colptr[c] = q;
    G->n = c;
    G->map = malloc((size_t)c * sizeof(int));
    G->scale = malloc((size_t)c * sizeof(double));
    for (int k = 0; k < c; k++) G->map[k] = k, G->scale[k] = 0.1 + 2.0 * uniform();
}

static void grid_free(grid *G)
{
    free(G->colptr), free(G->rowind), free(G->val), free(G->map), free(G->scale);
}

/* The backward error max |(F F^T + delta I) x - b| / (|M| max |x| + max |b|),
 * with |M| bounded by the largest row sum of |F| |F|^T + |delta|. */
static double residual(const grid *G, double delta, const double *x, const double *b)
{
    double *r = malloc((size_t)G->m * sizeof *r), *rows = calloc((size_t)G->m, sizeof *rows);
    double xn = 0, bn = 0, rn = 0, mn = 0;
    for (int i = 0; i < G->m; i++) r[i] = delta * x[i] - b[i];
    for (int k = 0; k < G->n; k++) {
        double t = 0, s2 = G->scale[k] * G->scale[k], cn = 0;
        for (int q = G->colptr[k]; q < G->colptr[k + 1]; q++)
            t += G->val[q] * x[G->rowind[q]], cn += fabs(G->val[q]);
        for (int q = G->colptr[k]; q < G->colptr[k + 1]; q++) {
            r[G->rowind[q]] += s2 * G->val[q] * t;
            rows[G->rowind[q]] += s2 * fabs(G->val[q]) * cn;
        }
    }
    for (int i = 0; i < G->m; i++) {
        rn = fmax(rn, fabs(r[i]));
        xn = fmax(xn, fabs(x[i]));
        bn = fmax(bn, fabs(b[i]));
        mn = fmax(mn, rows[i] + fabs(delta));
    }
    free(r);
    free(rows);
    return rn / (mn * xn + bn);
}

static double *solve_with(const grid *G, int threads, int expect_domains, double delta, const double *b)
{
    bl_normal_pattern p = {G->m, G->n, G->colptr, G->rowind, G->map, G->val};
    bl_error err;
    bl_normal *N = bl_normal_analyse(&p, threads, 0, &err);
    assert_non_null(N);
    assert_int_equal(bl_normal_domains(N), expect_domains);
    assert_true(bl_normal_fill(N, G->scale) > 0);
    assert_int_equal(bl_normal_factor(N, delta), 0);
    double *x = malloc((size_t)G->m * sizeof *x);
    memcpy(x, b, (size_t)G->m * sizeof *x);
    assert_int_equal(bl_normal_solve(N, &x, 1), 0);
    /* two right-hand sides at once: the first gives the same answer, the
     * second (b reversed) solves its own system */
    double *y = malloc((size_t)G->m * sizeof *y), *y2 = malloc((size_t)G->m * sizeof *y2);
    for (int i = 0; i < G->m; i++) y[i] = b[i], y2[i] = b[G->m - 1 - i];
    double *two[2] = {y, y2};
    assert_int_equal(bl_normal_solve(N, two, 2), 0);
    double dn = 0, xn = 0;
    for (int i = 0; i < G->m; i++) dn = fmax(dn, fabs(x[i] - y[i])), xn = fmax(xn, fabs(x[i]));
    assert_true(dn <= 1e-12 * xn);
    for (int i = 0; i < G->m; i++) y[i] = b[G->m - 1 - i];
    assert_true(residual(G, delta, y2, y) < 1e-14);
    free(y), free(y2);
    /* a negative shift larger than the smallest eigenvalue: not positive definite */
    assert_int_equal(bl_normal_factor(N, -1e3), 1);
    bl_normal_free(N);
    return x;
}

static void split_and_whole(void **st)
{
    (void)st;
    grid G;
    grid_make(&G, 60); /* 10,800 rows: above the split's threshold */
    double *b = malloc((size_t)G.m * sizeof *b), delta = 1e-8;
    for (int i = 0; i < G.m; i++) b[i] = uniform() - 0.5;
    double *x1 = solve_with(&G, 1, 1, delta, b);
    double *x2 = solve_with(&G, 2, 2, delta, b);
    double r1 = residual(&G, delta, x1, b), r2 = residual(&G, delta, x2, b);
    print_message("# relative residual: one factor %.1e, two domains %.1e\n", r1, r2);
    assert_true(r1 < 1e-14);
    assert_true(r2 < 1e-14);
    double dn = 0, xn = 0;
    for (int i = 0; i < G.m; i++) dn = fmax(dn, fabs(x1[i] - x2[i])), xn = fmax(xn, fabs(x1[i]));
    print_message("# the two answers differ by %.1e relative\n", dn / xn);
    assert_true(dn <= 1e-9 * xn);
    free(x1), free(x2), free(b);
    grid_free(&G);
}

static void small_stays_whole(void **st)
{
    (void)st;
    grid G;
    grid_make(&G, 20); /* 1,200 rows: one factorization even with two threads */
    double *b = malloc((size_t)G.m * sizeof *b);
    for (int i = 0; i < G.m; i++) b[i] = uniform() - 0.5;
    double *x = solve_with(&G, 2, 1, 1e-8, b);
    assert_true(residual(&G, 1e-8, x, b) < 1e-14);
    free(x), free(b);
    grid_free(&G);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(split_and_whole),
        cmocka_unit_test(small_stays_whole),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
