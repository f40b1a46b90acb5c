#include "vtk.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

/* Legacy ASCII VTK, POLYDATA: the points of every block's faces, then of
 * every contact polygon; one polygon cell per face and per interface, with
 * the cell data of the file's header comment. */
int bl_write_vtk(const bl_solution *s, const char *file, bl_error *err)
{
    const bl_model *m = s->model;
    if (m->dim != 3) return bl_error_set(err, "vtk: VTK files are written for 3D models");
    FILE *f = fopen(file, "w");
    if (!f) return bl_error_set(err, "vtk: cannot write '%s': %s", file, strerror(errno));
    int npts = 0, ncells = 0, nidx = 0;
    for (int b = 0; b < m->nblocks; b++) {
        npts += m->blocks[b].solid.nv;
        ncells += m->blocks[b].solid.nf;
        nidx += m->blocks[b].solid.nf + m->blocks[b].solid.fs[m->blocks[b].solid.nf];
    }
    for (int k = 0; k < m->ninterfaces; k++) {
        npts += m->interfaces[k].np;
        ncells++;
        nidx += 1 + m->interfaces[k].np;
    }
    /* the title: one line of at most 255 characters, the format's limit */
    char title[256];
    snprintf(title, sizeof title, "blocklim %s: alpha %.10g (%s); cells: block faces, then interfaces",
             m->name[0] ? m->name : "model", s->alpha, bl_status_name(s->status));
    for (char *c = title; *c; c++)
        if ((unsigned char)*c < 32) *c = ' ';
    fprintf(f, "# vtk DataFile Version 3.0\n%s\n", title);
    fprintf(f, "ASCII\nDATASET POLYDATA\nPOINTS %d double\n", npts);
    for (int b = 0; b < m->nblocks; b++)
        for (int i = 0; i < m->blocks[b].solid.nv; i++) {
            bl_vec3 p = m->blocks[b].solid.v[i];
            fprintf(f, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
        }
    for (int k = 0; k < m->ninterfaces; k++)
        for (int i = 0; i < m->interfaces[k].np; i++) {
            bl_vec3 p = m->interfaces[k].poly[i];
            fprintf(f, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
        }
    fprintf(f, "POLYGONS %d %d\n", ncells, nidx);
    int base = 0;
    for (int b = 0; b < m->nblocks; b++) {
        const bl_polyhedron *S = &m->blocks[b].solid;
        for (int k = 0; k < S->nf; k++) {
            fprintf(f, "%d", S->fs[k + 1] - S->fs[k]);
            for (int t = S->fs[k]; t < S->fs[k + 1]; t++) fprintf(f, " %d", base + S->fi[t]);
            fputc('\n', f);
        }
        base += S->nv;
    }
    for (int k = 0; k < m->ninterfaces; k++) {
        fprintf(f, "%d", m->interfaces[k].np);
        for (int i = 0; i < m->interfaces[k].np; i++) fprintf(f, " %d", base + i);
        fputc('\n', f);
        base += m->interfaces[k].np;
    }

    /* per cell: what it is, its block (faces) or blocks (interfaces), the
     * block's velocity and rotation, the interface's state and forces */
    int mech = bl_solution_moves(s);
    fprintf(f, "CELL_DATA %d\nSCALARS kind int 1\nLOOKUP_TABLE default\n", ncells);
    for (int b = 0; b < m->nblocks; b++)
        for (int k = 0; k < m->blocks[b].solid.nf; k++) fprintf(f, "%d\n", m->blocks[b].support);
    for (int k = 0; k < m->ninterfaces; k++) fprintf(f, "2\n");
    fprintf(f, "SCALARS block int 1\nLOOKUP_TABLE default\n");
    for (int b = 0; b < m->nblocks; b++)
        for (int k = 0; k < m->blocks[b].solid.nf; k++) fprintf(f, "%d\n", b + 1);
    for (int k = 0; k < m->ninterfaces; k++) fprintf(f, "%d\n", m->interfaces[k].b + 1);
    fprintf(f, "SCALARS state int 1\nLOOKUP_TABLE default\n");
    for (int b = 0; b < m->nblocks; b++)
        for (int k = 0; k < m->blocks[b].solid.nf; k++) fprintf(f, "-1\n");
    for (int k = 0; k < m->ninterfaces; k++) fprintf(f, "%d\n", mech ? (int)s->state[k] : -1);
    const char *vec[2] = {"velocity", "rotation"};
    for (int v = 0; v < 2; v++) {
        fprintf(f, "VECTORS %s double\n", vec[v]);
        for (int b = 0; b < m->nblocks; b++)
            for (int k = 0; k < m->blocks[b].solid.nf; k++) {
                const double *u = s->u + 6 * b + 3 * v;
                /* (+ 0.0: a -0 written as 0) */
                fprintf(f, "%.10g %.10g %.10g\n", mech ? u[0] + 0.0 : 0.0, mech ? u[1] + 0.0 : 0.0,
                        mech ? u[2] + 0.0 : 0.0);
            }
        for (int k = 0; k < m->ninterfaces; k++) fprintf(f, "0 0 0\n");
    }
    /* the interface's resultant force on b, in x, y, z */
    fprintf(f, "VECTORS force double\n");
    for (int b = 0; b < m->nblocks; b++)
        for (int k = 0; k < m->blocks[b].solid.nf; k++) fprintf(f, "0 0 0\n");
    const double *fp = s->force;
    for (int k = 0; k < m->ninterfaces; k++) {
        const bl_interface *in = &m->interfaces[k];
        bl_vec3 F = {0, 0, 0};
        for (int i = 0; i < in->np; i++, fp += 3)
            if (mech)
                F = bl_v3_add(F, bl_v3_add(bl_v3_scale(in->n3, fp[0]),
                                           bl_v3_add(bl_v3_scale(in->t2, fp[1]),
                                                     bl_v3_scale(in->t3, fp[2]))));
        fprintf(f, "%.10g %.10g %.10g\n", F.x, F.y, F.z);
    }
    if (fclose(f) != 0) return bl_error_set(err, "vtk: cannot write '%s': %s", file, strerror(errno));
    return 0;
}
