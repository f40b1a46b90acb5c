/* error.h - the error struct every fallible core function fills.
 *
 * A fallible function returns 0 on success and -1 on failure; on failure it
 * writes one readable sentence naming the offending object into err->msg.
 * err may be NULL when the caller does not want the message. */
#ifndef BL_ERROR_H
#define BL_ERROR_H

typedef struct bl_error {
    char msg[1024];
} bl_error;

/* Formats the message into err (if not NULL) and returns -1. */
int bl_error_set(bl_error *err, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* Interruption (Ctrl-C).  The front end's signal handler calls
 * bl_interrupt_request(); long computations poll bl_interrupt_pending() and
 * stop with an "interrupted" status.  The front end clears the flag when
 * a new solve starts, and only then: a solve made of several parts (the
 * path and the associative LP before a sequence of LPs) stops in whichever
 * part comes next. */
void bl_interrupt_request(void);
void bl_interrupt_clear(void);
int bl_interrupt_pending(void);

/* Runs the numerical libraries on the calling thread only.  Debian's
 * CHOLMOD opens OpenMP regions of a fixed 4 threads in every supernodal
 * factorization, and OpenBLAS threads every BLAS call (also MUMPS's, under
 * Ipopt); on the 2-core machines this runs on, the threads cost more in
 * wake-ups than they give (10,050 blocks: 12.0 s with both, 5.6 s with
 * neither; doc/performance.md).  Looked up at run time, so that nothing
 * breaks where these libraries are built differently. */
void bl_one_thread(void);

/* Wall-clock seconds from an arbitrary origin, for the timings of a result. */
double bl_clock(void);

#endif
