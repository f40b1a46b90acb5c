/* draw.h - pictures of a solution's collapse mechanism (cairo).
 *
 * The picture shows the undeformed blocks as faint outlines, supports
 * hatched, every free block moved rigidly by the mechanism (scaled so the
 * largest displacement is about 8% of the model size), the hinges of rocking
 * joints as red dots, sliding joints in blue, separating joints dashed
 * orange, and a caption with alpha and the status.  Without a mechanism only
 * the undeformed model is drawn. */
#ifndef BL_DRAW_H
#define BL_DRAW_H

#include "error.h"
#include "solution.h"

/* Draws the mechanism of s into file: SVG (bl_draw_svg) or PNG (bl_draw_png).
 * width is the picture width in pixels/points (0: 1000); returns 0 or -1 with err. */
int bl_draw_svg(const bl_solution *s, const char *file, int width, bl_error *err);
int bl_draw_png(const bl_solution *s, const char *file, int width, bl_error *err);

#endif
