/* vtk.h - a 3D result as a legacy VTK file for ParaView.
 *
 * One POLYDATA data set: every face of every block at its place, then every
 * contact polygon.  Cell data: kind (0 a free block's face, 1 a support's,
 * 2 an interface), block (the block's number; an interface's block b),
 * state (an interface's state: 0 closed, 1 rocking, 2 sliding,
 * 3 separating; -1 on faces), velocity and rotation (the block's, per unit
 * live-load work), force (the resultant of an interface's contact forces on
 * block b). */
#ifndef BL_VTK_H
#define BL_VTK_H

#include "error.h"
#include "solution.h"

int bl_write_vtk(const bl_solution *s, const char *file, bl_error *err);

#endif
