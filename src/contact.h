/* contact.h - interface detection in a 2D block model.
 *
 * Two blocks share an interface where an edge of one and an edge of the
 * other are collinear, face opposite ways and overlap over a positive
 * length: T-junctions, partial overlaps and several interfaces between the
 * same two blocks come out of the same test.  A uniform grid over the
 * bounding boxes finds the candidate pairs in time linear in the number of
 * blocks.  Modelling mistakes are reported with the block numbers before any
 * solve: blocks that overlap, edges that almost touch (a near-miss: a gap
 * wider than tol but narrower than gap), and free blocks with no interface. */
#ifndef BL_CONTACT_H
#define BL_CONTACT_H

#include "model.h"

/* The tolerances in force: m->contact_tol and m->contact_gap, or when those
 * are 0 the defaults 1e-8 of the model size and 1e-2 of the typical block
 * size. */
void bl_contact_tolerances(const bl_model *m, double *tol, double *gap);

/* Checks a joint declared by hand (s->npoints > 0): each of its points,
 * and its middle, must lie within BL_JOINT_REACH of the smaller block's
 * size (its square or cube root of area or volume), or within the near-miss
 * gap if that is larger, of the boundary of both blocks, and no point may
 * lie past a block along the joint (outside by more than tol, and still
 * outside when moved that far across it).  Returns 0, or -1 with a message
 * naming the point, the block and the distance. */
#define BL_JOINT_REACH 0.1
int bl_joint_check(const bl_model *m, const bl_joint_spec *s, bl_error *err);

/* Replaces m->interfaces by the detected ones, then applies m->joints.
 * Returns 0, or -1 with a message listing the offending blocks (the model
 * then has no interfaces and contacts_valid stays 0). */
int bl_contact_detect(bl_model *m, bl_error *err);

#endif
