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

/* 3D: where the model is seen from, in degrees: azimuth from -y (0: the
 * front, looking along +y; 90: from +x) and elevation above the horizon.
 * A 3D picture shows the faces of the blocks moved by the mechanism that
 * face the viewer, painted far to near and shaded. */
typedef struct bl_view {
    double azimuth, elevation;
} bl_view;
#define BL_VIEW_AZIMUTH (-35.0)
#define BL_VIEW_ELEVATION 25.0

/* Draws the mechanism of s into file: SVG (bl_draw_svg) or PNG (bl_draw_png).
 * width is the picture width in pixels/points (0: 1000); view is for 3D
 * models (NULL: the default); returns 0 or -1 with err. */
int bl_draw_svg(const bl_solution *s, const char *file, int width, const bl_view *view,
                bl_error *err);
int bl_draw_png(const bl_solution *s, const char *file, int width, const bl_view *view,
                bl_error *err);

#endif
