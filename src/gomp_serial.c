/* gomp_serial.c - a parallel region that runs on one thread anyway, run as
 * a plain call, in the blocklim executable and the Lua module.
 *
 * GCC compiles "#pragma omp parallel" into a call of GOMP_parallel(fn,
 * data, num_threads, flags) (libgomp's documented ABI, "Implementing the
 * PARALLEL construct"), with num_threads 1 when an if clause is false.
 * libgomp then still sets up a team of one and ends it with a barrier
 * whose last thread wakes the others by a futex system call.  CHOLMOD's
 * supernodal factorization has such regions on every supernode, small
 * ones behind an if clause, and blocklim keeps them all on one thread
 * (doc/performance.md, "Threads" and "Regions of one thread"): 3,000
 * futex calls per interior-point iteration at 1,040 blocks, a fifth of the
 * solve's time in the kernel.
 *
 * This definition takes precedence over libgomp's: for the whole process
 * when the executable exports it (meson.build), and for the libraries the
 * Lua module loads, which look in the module before libgomp.  Outside any
 * parallel region, a region that would get one thread (an if clause that
 * is false, one thread asked or allowed, or no active level left) is
 * fn(data) itself: there omp_get_thread_num() is 0 and
 * omp_get_num_threads() 1 as in a team of one, and a nested region
 * behaves as it would inside that inactive team.  Inside a parallel region fn reads the enclosing team's
 * thread numbers, so there, and whenever more threads may run, libgomp's
 * own GOMP_parallel does the work. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <omp.h>
#include <stdlib.h>

typedef void (*gomp_parallel_fn)(void (*)(void *), void *, unsigned, unsigned);

static gomp_parallel_fn libgomp_parallel;

__attribute__((constructor)) static void find_libgomp(void)
{
    libgomp_parallel = (gomp_parallel_fn)dlsym(RTLD_NEXT, "GOMP_parallel");
}

void GOMP_parallel(void (*fn)(void *), void *data, unsigned num_threads, unsigned flags);

void GOMP_parallel(void (*fn)(void *), void *data, unsigned num_threads, unsigned flags)
{
    if (omp_get_level() == 0 &&
        (num_threads == 1 || omp_get_max_active_levels() == 0 || omp_get_thread_limit() == 1 ||
         (num_threads == 0 && omp_get_max_threads() == 1))) {
        fn(data);
        return;
    }
    if (!libgomp_parallel) abort(); /* libgomp is linked in: not reached */
    libgomp_parallel(fn, data, num_threads, flags);
}
