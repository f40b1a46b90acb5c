/* Unit tests of gomp_serial.c, linked in as in the blocklim executable:
 * every parallel loop still runs each of its iterations exactly once, with
 * the thread numbers the OpenMP specification gives; a region that gets
 * one thread outside any parallel region runs as a plain call (it sees
 * level 0, where libgomp's team of one would see 1); teams of two and
 * regions nested in them are libgomp's. */
#include <omp.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

enum { N = 1000 };

/* sum of 1..N by a parallel loop with an if clause; *level and *threads
 * as seen inside */
static long loop_sum(int parallel, int *level, int *threads)
{
    long sum = 0;
#pragma omp parallel for reduction(+ : sum) if (parallel) num_threads(2)
    for (int i = 1; i <= N; i++) {
        sum += i;
        if (i == 1) {
            *level = omp_get_level();
            *threads = omp_get_num_threads();
        }
    }
    return sum;
}

static void one_thread_is_a_plain_call(void **state)
{
    (void)state;
    int level = -1, threads = -1;
    assert_int_equal(loop_sum(0, &level, &threads), (long)N * (N + 1) / 2);
    assert_int_equal(threads, 1);
    assert_int_equal(level, 0); /* libgomp's team of one: 1 */

    omp_set_max_active_levels(0); /* no active level left: one thread too */
    assert_int_equal(loop_sum(1, &level, &threads), (long)N * (N + 1) / 2);
    assert_int_equal(threads, 1);
    assert_int_equal(level, 0);
    omp_set_max_active_levels(1);
}

static void two_threads_are_libgomps(void **state)
{
    (void)state;
    int level = -1, threads = -1;
    assert_int_equal(loop_sum(1, &level, &threads), (long)N * (N + 1) / 2);
    assert_int_equal(threads, 2);
    assert_int_equal(level, 1);
}

/* Nested in a team of two, a region of one thread must not be a plain
 * call: its loop would be shared out by the enclosing team's numbers, and
 * each thread would sum half of it. */
static void nested_region_runs_whole(void **state)
{
    (void)state;
    long sums[2] = {0, 0};
    int levels[2] = {-1, -1}, threads[2] = {-1, -1};
#pragma omp parallel num_threads(2)
    {
        int t = omp_get_thread_num();
        sums[t] = loop_sum(0, &levels[t], &threads[t]);
    }
    for (int t = 0; t < 2; t++) {
        assert_int_equal(sums[t], (long)N * (N + 1) / 2);
        assert_int_equal(threads[t], 1);
        assert_int_equal(levels[t], 2);
    }
}

/* A POSIX thread is outside any parallel region (normal.c factors its
 * second domain on one) */
static long thread_sum;
static int thread_level = -1, thread_threads = -1;
static void *posix_thread(void *arg)
{
    (void)arg;
    thread_sum = loop_sum(0, &thread_level, &thread_threads);
    return NULL;
}

static void posix_thread_is_outside(void **state)
{
    (void)state;
    pthread_t t;
    assert_int_equal(pthread_create(&t, NULL, posix_thread, NULL), 0);
    assert_int_equal(pthread_join(t, NULL), 0);
    assert_int_equal(thread_sum, (long)N * (N + 1) / 2);
    assert_int_equal(thread_threads, 1);
    assert_int_equal(thread_level, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(one_thread_is_a_plain_call),
        cmocka_unit_test(two_threads_are_libgomps),
        cmocka_unit_test(nested_region_runs_whole),
        cmocka_unit_test(posix_thread_is_outside),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
