#define _POSIX_C_SOURCE 200809L
#include "error.h"

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
