#include "model.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

bl_model *bl_model_new(void)
{
    bl_model *m = calloc(1, sizeof *m);
    if (!m) return NULL;
    m->mu = 0.65;
    m->cohesion = 0.0;
    m->density = 1.0;
    m->thickness = 1.0;
    m->gravity = bl_v2(0.0, -1.0);
    m->self_weight = 1;
    m->live_weight = 1;
    m->live_dir = bl_v2(1.0, 0.0);
    m->dim = 2;
    m->gravity3 = bl_v3(0.0, 0.0, -1.0);
    m->live_dir3 = bl_v3(1.0, 0.0, 0.0);
    m->tilt_axis = bl_v2(0.0, -1.0);
    return m;
}

void bl_model_free(bl_model *m)
{
    if (!m) return;
    for (int i = 0; i < m->nblocks; i++) {
        free(m->blocks[i].v);
        bl_polyhedron_free(&m->blocks[i].solid);
    }
    free(m->blocks);
    bl_model_clear_interfaces(m);
    free(m->interfaces);
    free(m->joints);
    free(m->loads);
    free(m);
}

static void *dup_array(const void *p, size_t n, size_t size)
{
    if (n == 0) return NULL;
    void *q = malloc(n * size);
    if (q) memcpy(q, p, n * size);
    return q;
}

bl_model *bl_model_copy(const bl_model *m)
{
    bl_model *c = malloc(sizeof *c);
    if (!c) return NULL;
    *c = *m;
    c->blocks = dup_array(m->blocks, (size_t)m->nblocks, sizeof *m->blocks);
    c->interfaces = dup_array(m->interfaces, (size_t)m->ninterfaces, sizeof *m->interfaces);
    c->joints = dup_array(m->joints, (size_t)m->njoints, sizeof *m->joints);
    c->loads = dup_array(m->loads, (size_t)m->nloads, sizeof *m->loads);
    c->cap_blocks = c->nblocks;
    c->cap_interfaces = c->ninterfaces;
    c->cap_joints = c->njoints;
    c->cap_loads = c->nloads;
    int ok = (!m->nblocks || c->blocks) && (!m->ninterfaces || c->interfaces) &&
             (!m->njoints || c->joints) && (!m->nloads || c->loads);
    for (int i = 0; ok && i < m->nblocks; i++) {
        const bl_block *b = &m->blocks[i];
        c->blocks[i].v = dup_array(b->v, (size_t)b->nv, sizeof(bl_vec2));
        if ((b->nv && !c->blocks[i].v) || bl_polyhedron_copy(&c->blocks[i].solid, &b->solid)) {
            for (int j = i; j < m->nblocks; j++) {
                if (j > i || !c->blocks[i].v) c->blocks[j].v = NULL;
                memset(&c->blocks[j].solid, 0, sizeof c->blocks[j].solid);
            }
            ok = 0;
        }
    }
    /* the interfaces' 3D polygons: shared with m until copied */
    for (int k = 0; c->interfaces && k < m->ninterfaces; k++) {
        bl_interface *ck = &c->interfaces[k];
        ck->poly = ok && ck->np ? dup_array(ck->poly, (size_t)ck->np, sizeof *ck->poly) : NULL;
        if (ck->np && !ck->poly) ok = 0;
    }
    if (!ok) {
        if (!c->blocks) c->nblocks = 0;
        bl_model_free(c);
        return NULL;
    }
    return c;
}

/* Grows *p (of *cap elements of size bytes) to hold n elements. */
static int reserve(void **p, int *cap, int n, size_t size)
{
    if (n <= *cap) return 0;
    int c = *cap ? *cap : 16;
    while (c < n) c *= 2;
    void *q = realloc(*p, (size_t)c * size);
    if (!q) return -1;
    *p = q;
    *cap = c;
    return 0;
}

#define RESERVE(arr, cap, n) reserve((void **)&(arr), &(cap), (n), sizeof *(arr))

/* A free block's weight must be a positive number: one that overflowed
 * (density 1e300 times thickness 1e300) or underflowed to zero read as
 * no collapse at all. */
static int usable_weight(double w, int id, bl_error *err)
{
    if (isfinite(w) && w > 0.0) return 0;
    return bl_error_set(err, "block %d: its weight, density times size, %s the range of numbers (%g); "
                             "give the model units nearer 1",
                        id, w > 0.0 ? "overflows" : "underflows", w);
}

int bl_model_add_block(bl_model *m, const bl_vec2 *v, int nv, int support,
                       double density, double thickness, bl_error *err)
{
    int id = m->nblocks + 1;
    if (nv < 3)
        return bl_error_set(err, "block %d: needs at least 3 vertices, got %d", id, nv);
    for (int i = 0; i < nv; i++)
        if (!isfinite(v[i].x) || !isfinite(v[i].y))
            return bl_error_set(err, "block %d: vertex %d is not a finite point", id, i + 1);
    double box[4];
    bl_polygon_bbox(v, nv, box);
    double size = hypot(box[2] - box[0], box[3] - box[1]);
    double area = bl_polygon_area(v, nv);
    if (!isfinite(area) || !isfinite(size))
        return bl_error_set(err, "block %d: polygon's size overflows the range of numbers; give the "
                                 "model units nearer 1", id);
    /* All points on one line: zero area, whatever the self-intersection
     * test would say about the edges folding back. */
    int flat = 1;
    for (int i = 1; i < nv && flat; i++)
        for (int j = i + 1; j < nv && flat; j++)
            flat = fabs(bl_v2_cross(bl_v2_sub(v[i], v[0]), bl_v2_sub(v[j], v[0]))) <=
                   1e-12 * size * size;
    if (flat) return bl_error_set(err, "block %d: polygon has zero area", id);
    for (int i = 0; i < nv; i++) {
        int j = (i + 1) % nv;
        if (bl_v2_norm(bl_v2_sub(v[i], v[j])) <= 1e-12 * size)
            return bl_error_set(err, "block %d: vertex %d repeats vertex %d; list each corner "
                                     "once (the polygon closes itself)",
                                id, i > j ? i + 1 : j + 1, i > j ? j + 1 : i + 1);
    }
    int ei, ej;
    if (bl_polygon_self_intersection(v, nv, 1e-12 * size, &ei, &ej))
        return bl_error_set(err, "block %d: polygon is self-intersecting (edges %d and %d)",
                            id, ei + 1, ej + 1);
    if (!(fabs(area) > 1e-12 * size * size))
        return bl_error_set(err, "block %d: polygon has zero area", id);
    if (RESERVE(m->blocks, m->cap_blocks, m->nblocks + 1))
        return bl_error_set(err, "block %d: out of memory", id);
    bl_vec2 *copy = malloc((size_t)nv * sizeof *copy);
    if (!copy) return bl_error_set(err, "block %d: out of memory", id);
    memcpy(copy, v, (size_t)nv * sizeof *copy);
    if (area < 0.0) {
        bl_polygon_reverse(copy, nv);
        area = -area;
    }
    density = density > 0.0 ? density : m->density;
    thickness = thickness > 0.0 ? thickness : m->thickness;
    if (!support && usable_weight(density * area * thickness, id, err)) {
        free(copy);
        return -1;
    }
    bl_block *b = &m->blocks[m->nblocks++];
    memset(b, 0, sizeof *b);
    b->nv = nv;
    b->v = copy;
    b->support = support;
    b->density = density;
    b->thickness = thickness;
    b->area = area;
    b->centroid = bl_polygon_centroid(copy, nv);
    b->weight = b->density * b->area * b->thickness;
    memcpy(b->box, box, sizeof box);
    m->contacts_valid = 0;
    return 0;
}

int bl_model_add_solid(bl_model *m, bl_polyhedron *solid, int support, double density,
                       bl_error *err)
{
    int id = m->nblocks + 1;
    double box[6];
    bl_polyhedron_bbox(solid, box);
    double size = sqrt((box[3] - box[0]) * (box[3] - box[0]) + (box[4] - box[1]) * (box[4] - box[1]) +
                       (box[5] - box[2]) * (box[5] - box[2]));
    /* 1e-9 of the block's size, or, far from the origin (survey
     * coordinates: 5e6 m), some hundred round-offs of its coordinates
     * (a vertex that is not finite is reported before the tolerance is used) */
    double reach = 0.0;
    for (int d = 0; d < 6; d++) reach = fmax(reach, fabs(box[d]));
    if (bl_polyhedron_check(solid, fmax(1e-9 * size, 1e-13 * reach), id, err)) {
        bl_polyhedron_free(solid);
        return -1;
    }
    density = density > 0.0 ? density : m->density;
    bl_vec3 centroid;
    double volume = bl_polyhedron_volume(solid, &centroid);
    if (!support && usable_weight(density * volume, id, err)) {
        bl_polyhedron_free(solid);
        return -1;
    }
    if (RESERVE(m->blocks, m->cap_blocks, m->nblocks + 1)) {
        bl_polyhedron_free(solid);
        return bl_error_set(err, "block %d: out of memory", id);
    }
    bl_block *b = &m->blocks[m->nblocks++];
    memset(b, 0, sizeof *b);
    b->solid = *solid;
    memset(solid, 0, sizeof *solid);
    b->support = support;
    b->density = density;
    b->volume = volume;
    b->centroid3 = centroid;
    b->weight = b->density * b->volume;
    memcpy(b->box3, box, sizeof box);
    m->contacts_valid = 0;
    return 0;
}

int bl_model_add_interface(bl_model *m, const bl_interface *k, bl_error *err)
{
    if (RESERVE(m->interfaces, m->cap_interfaces, m->ninterfaces + 1))
        return bl_error_set(err, "interface: out of memory");
    m->interfaces[m->ninterfaces++] = *k;
    return 0;
}

void bl_model_clear_interfaces(bl_model *m)
{
    for (int k = 0; k < m->ninterfaces; k++) free(m->interfaces[k].poly);
    m->ninterfaces = 0;
}

void bl_model_truncate(bl_model *m, int nblocks)
{
    if (nblocks < 0 || nblocks >= m->nblocks) return;
    for (int i = nblocks; i < m->nblocks; i++) {
        free(m->blocks[i].v);
        bl_polyhedron_free(&m->blocks[i].solid);
    }
    m->nblocks = nblocks;
    int k = 0;
    for (int j = 0; j < m->njoints; j++)
        if (m->joints[j].a < nblocks && m->joints[j].b < nblocks) m->joints[k++] = m->joints[j];
    m->njoints = k;
    k = 0;
    for (int l = 0; l < m->nloads; l++)
        if (m->loads[l].block < nblocks) m->loads[k++] = m->loads[l];
    m->nloads = k;
    bl_model_clear_interfaces(m);
    m->contacts_valid = 0;
}

int bl_model_add_joint(bl_model *m, const bl_joint_spec *s, bl_error *err)
{
    if (RESERVE(m->joints, m->cap_joints, m->njoints + 1))
        return bl_error_set(err, "interface: out of memory");
    m->joints[m->njoints++] = *s;
    m->contacts_valid = 0;
    return 0;
}

int bl_model_check_point_load(const bl_model *m, const bl_point_load *l, bl_error *err)
{
    const bl_block *b = &m->blocks[l->block];
    const char *kind = l->live ? "live" : "dead";
    double f = l->weight > 0.0 ? l->weight : m->dim == 3 ? bl_v3_norm(l->force3) : bl_v2_norm(l->force);
    if (!(f <= BL_LOAD_RATIO * b->weight))
        return bl_error_set(err, "load %s: field '%s' on block %d is %g, more than %g times the block's "
                            "weight (%g): the solve would not hold it", kind,
                            l->weight > 0.0 ? "weight" : "force", l->block + 1, f, BL_LOAD_RATIO, b->weight);
    const double *x = m->dim == 3 ? b->box3 : b->box;
    double size = m->dim == 3 ? sqrt((x[3] - x[0]) * (x[3] - x[0]) + (x[4] - x[1]) * (x[4] - x[1]) +
                                     (x[5] - x[2]) * (x[5] - x[2]))
                              : hypot(x[2] - x[0], x[3] - x[1]);
    double c = m->dim == 3 ? bl_v3_norm(l->moment3) : fabs(l->moment);
    if (l->weight > 0.0) /* its moment about the centroid, whichever way it acts */
        c = l->weight * (m->dim == 3 ? bl_v3_norm(bl_v3_sub(l->at3, b->centroid3))
                                     : bl_v2_norm(bl_v2_sub(l->at, b->centroid)));
    if (!(c <= BL_LOAD_RATIO * b->weight * size))
        return bl_error_set(err, "load %s: field '%s' on block %d %s %g, more than %g times the "
                            "block's weight times its size (%g): the solve would not hold it", kind,
                            l->weight > 0.0 ? "at" : "moment", l->block + 1,
                            l->weight > 0.0 ? "gives the weight a moment about its centroid of" : "is", c,
                            BL_LOAD_RATIO, b->weight * size);
    return 0;
}

int bl_model_add_point_load(bl_model *m, const bl_point_load *l, bl_error *err)
{
    if (RESERVE(m->loads, m->cap_loads, m->nloads + 1))
        return bl_error_set(err, "load: out of memory");
    m->loads[m->nloads++] = *l;
    return 0;
}

double bl_model_size(const bl_model *m)
{
    if (m->nblocks == 0) return 0.0;
    if (m->dim == 3) {
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (int i = 0; i < m->nblocks; i++)
            for (int d = 0; d < 3; d++) {
                lo[d] = fmin(lo[d], m->blocks[i].box3[d]);
                hi[d] = fmax(hi[d], m->blocks[i].box3[d + 3]);
            }
        return sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                    (hi[2] - lo[2]) * (hi[2] - lo[2]));
    }
    double box[4];
    memcpy(box, m->blocks[0].box, sizeof box);
    for (int i = 1; i < m->nblocks; i++) {
        const double *b = m->blocks[i].box;
        box[0] = fmin(box[0], b[0]);
        box[1] = fmin(box[1], b[1]);
        box[2] = fmax(box[2], b[2]);
        box[3] = fmax(box[3], b[3]);
    }
    return hypot(box[2] - box[0], box[3] - box[1]);
}

int bl_model_finite_friction(const bl_model *m)
{
    for (int k = 0; k < m->ninterfaces; k++)
        if (isfinite(m->interfaces[k].mu) && m->interfaces[k].mu > 0.0) return 1;
    return 0;
}

bl_vec2 bl_model_gravity(const bl_model *m)
{
    double c = cos(m->tilt), s = sin(m->tilt);
    return bl_v2(c * m->gravity.x - s * m->gravity.y, s * m->gravity.x + c * m->gravity.y);
}

bl_vec3 bl_model_gravity3(const bl_model *m)
{
    /* Rodrigues: gravity turned by tilt about the unit horizontal axis k */
    double n = bl_v2_norm(m->tilt_axis);
    bl_vec3 k = bl_v3(m->tilt_axis.x / n, m->tilt_axis.y / n, 0.0), g = m->gravity3;
    double c = cos(m->tilt), s = sin(m->tilt);
    return bl_v3_add(bl_v3_add(bl_v3_scale(g, c), bl_v3_scale(bl_v3_cross(k, g), s)),
                     bl_v3_scale(k, bl_v3_dot(k, g) * (1.0 - c)));
}

void bl_point_load_forces(const bl_model *m, const bl_point_load *l, bl_vec2 *dead, bl_vec2 *live)
{
    if (l->weight > 0.0) {
        *dead = bl_v2_scale(bl_model_gravity(m), l->weight);
        *live = m->live_weight ? bl_v2_scale(m->live_dir, l->weight) : bl_v2(0.0, 0.0);
    } else {
        *dead = l->live ? bl_v2(0.0, 0.0) : l->force;
        *live = l->live ? l->force : bl_v2(0.0, 0.0);
    }
}

void bl_point_load_forces3(const bl_model *m, const bl_point_load *l, bl_vec3 *dead, bl_vec3 *live)
{
    if (l->weight > 0.0) {
        *dead = bl_v3_scale(bl_model_gravity3(m), l->weight);
        *live = m->live_weight ? bl_v3_scale(m->live_dir3, l->weight) : bl_v3(0.0, 0.0, 0.0);
    } else {
        *dead = l->live ? bl_v3(0.0, 0.0, 0.0) : l->force3;
        *live = l->live ? l->force3 : bl_v3(0.0, 0.0, 0.0);
    }
}

int bl_model_uses_resultant(const bl_model *m, int *a, int *b)
{
    *a = *b = -1;
    if (m->dim != 3) return 0;
    if (m->interface_model == BL_RESULTANT) return 1;
    for (int k = 0; k < m->njoints; k++) {
        const bl_joint_spec *s = &m->joints[k];
        if (!s->has_imodel || s->imodel != BL_RESULTANT) continue;
        int later = 0; /* a later setting of the same pair's model wins */
        for (int l = k + 1; l < m->njoints && !later; l++)
            later = m->joints[l].has_imodel && ((m->joints[l].a == s->a && m->joints[l].b == s->b) ||
                                                (m->joints[l].a == s->b && m->joints[l].b == s->a));
        if (later) continue;
        *a = s->a;
        *b = s->b;
        return 1;
    }
    return 0;
}

int bl_model_free_blocks(const bl_model *m)
{
    int n = 0;
    for (int i = 0; i < m->nblocks; i++) n += !m->blocks[i].support;
    return n;
}
