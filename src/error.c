#define _GNU_SOURCE /* RTLD_DEFAULT */
#include "error.h"

#include <dlfcn.h>

#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <time.h>

int bl_error_set(bl_error *err, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
    }
    return -1;
}

static volatile sig_atomic_t interrupted;

void bl_interrupt_request(void) { interrupted = 1; }
void bl_interrupt_clear(void) { interrupted = 0; }
int bl_interrupt_pending(void) { return interrupted != 0; }

double bl_clock(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void bl_one_thread(void)
{
    /* zero active OpenMP levels: every region runs on the calling thread */
    void (*max_levels)(int) = (void (*)(int))dlsym(RTLD_DEFAULT, "omp_set_max_active_levels");
    void (*blas_threads)(int) = (void (*)(int))dlsym(RTLD_DEFAULT, "openblas_set_num_threads");
    if (max_levels) max_levels(0);
    if (blas_threads) blas_threads(1);
}
