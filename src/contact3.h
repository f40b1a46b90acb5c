/* contact3.h - the pair tests of interface detection in 3D, for contact.c
 * (which reports what they find for both dimensions). */
#ifndef BL_CONTACT3_H
#define BL_CONTACT3_H

#include "contact.h"

/* What the pair tests found wrong with a model: the first few of each kind,
 * and how many. */
typedef struct bl_contact_problems {
    int noverlap, nnear;
    char overlap[5][128], near[5][128];
} bl_contact_problems;

/* Adds the interfaces of every pair of 3D blocks to m and records
 * overlapping blocks and near-misses in pr.  Returns 0, or -1 with err set
 * when out of memory. */
int bl_contact_pairs3(bl_model *m, double tol, double gap, bl_contact_problems *pr,
                      bl_error *err);

/* Whether a joint was declared by hand (interface{ points }) between
 * blocks a and b: their gap is then no near-miss. */
int bl_contact_declared(const bl_model *m, int a, int b);

#endif
