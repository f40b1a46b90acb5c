#include "draw.h"

#include <cairo.h>
#include <cairo-svg.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DEFAULT_WIDTH 1000
#define SHOW_FRACTION 0.08  /* largest drawn displacement / model size */
#define SHOW_TURN 0.15      /* radians: the largest drawn rotation of a block */
#define THIN_BLOCK 2.0      /* px: blocks thinner than this on average get no outlines */
#define MAX_ASPECT 2.0      /* a tall model is shrunk rather than drawn taller */
#define ARROW 0.06          /* a load's arrow, of the canvas's width */
#define PNG_MAX_SIDE 32767  /* cairo's limit for image surfaces */

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

typedef struct rgb {
    double r, g, b;
} rgb;

static const rgb INK = {0.13, 0.13, 0.13};
static const rgb GHOST = {0.60, 0.60, 0.60};
static const rgb SUPPORT_FILL = {0.82, 0.82, 0.82};
static const rgb SUPPORT_HATCH = {0.38, 0.38, 0.38};
static const rgb SUPPORT_EDGE = {0.25, 0.25, 0.25};
static const rgb MOVING = {0.89, 0.58, 0.44};  /* light terracotta */
static const rgb STILL = {0.96, 0.90, 0.85};
static const rgb BLOCK_EDGE = {0.33, 0.17, 0.10};
static const rgb HINGE = {0.84, 0.09, 0.09};
static const rgb HINGE_EDGE = {0.45, 0.02, 0.02};
static const rgb SLIDING = {0.11, 0.38, 0.82};
static const rgb SEPARATING = {0.96, 0.52, 0.03};
static const rgb DEAD_LOAD = {0.30, 0.30, 0.30};
static const rgb LIVE_LOAD = {0.50, 0.12, 0.50};

/* Everything the drawing needs, worked out before the surface exists because
 * the canvas height depends on it. */
typedef struct pic {
    const bl_solution *s;
    const bl_model *m;    /* NULL when there is nothing to draw */
    double k;             /* mechanism scale; 0 draws the undeformed model */
    double maxd;          /* largest vertex speed of the mechanism */
    double w, h;
    double unit;          /* line widths and text follow the picture width */
    double mark;          /* the joints' markers and the blocks' outlines: unit, less where
                             blocks are drawn small */
    int outlines;         /* 2D: the blocks' outlines are drawn (not where they would
                             cover blocks thinner than THIN_BLOCK) */
    double sc, x0, y0;    /* model (x, y) -> canvas (x0 + sc x, y0 - sc y) */
    double top, dh;       /* drawing area, canvas units */
    double font;
    double margin;        /* around the drawing and left of the caption */
    char caption[160];
    /* 3D: the view (eye: towards the viewer; right and up: the canvas axes) */
    int dim;
    bl_vec3 eye, right, up;
    double caption_y, legend_x, legend_y;
    int has_legend;
} pic;

static void color(cairo_t *cr, rgb c) { cairo_set_source_rgb(cr, c.r, c.g, c.b); }

static int moves(const pic *P, int b)
{
    return P->k > 0.0 && b >= 0 && b < P->m->nblocks && !P->m->blocks[b].support;
}

/* Speed of block b at p in the (linear) velocity field u describes. */
static double speed(const bl_solution *s, int b, bl_vec2 p)
{
    return bl_v3_norm(bl_solution_velocity(s, b, bl_v3(p.x, p.y, 0.0)));
}

/* Whether free block b is drawn still (BL_STILL_FRACTION): always where
 * no mechanism is drawn. */
static int still(const pic *P, int b)
{
    return !(P->k > 0.0) || !(bl_solution_block_speed(P->s, b) >= BL_STILL_FRACTION * P->maxd);
}

/* Rigid motion of block b over "time" k under its constant velocity field:
 * rotation by a = k omega about the centroid plus the translation
 * k (sin a / a, (1 - cos a) / a) applied to v.  This is the exact integral of
 * the velocity field, a pure rotation about the instantaneous centre, so the
 * blocks do not distort and a block rocking on a still one keeps its hinge
 * corner in place; rotating about the centroid and then adding k v would let
 * that corner drift by a second-order amount. */
static bl_vec2 moved(const pic *P, int b, bl_vec2 p)
{
    if (!moves(P, b)) return p;
    const double *u = P->s->u + 3 * b;
    bl_vec2 c = P->m->blocks[b].centroid, r = bl_v2_sub(p, c);
    double a = P->k * u[2], cs = cos(a), sn = sin(a);
    double s1 = fabs(a) < 1e-8 ? 1.0 : sn / a;
    double s2 = fabs(a) < 1e-8 ? 0.5 * a : 2.0 * sin(0.5 * a) * sin(0.5 * a) / a;
    bl_vec2 t = bl_v2(P->k * (s1 * u[0] - s2 * u[1]), P->k * (s1 * u[1] + s2 * u[0]));
    return bl_v2(c.x + cs * r.x - sn * r.y + t.x, c.y + sn * r.x + cs * r.y + t.y);
}

/* 3D: the rigid motion of block b over "time" k under its constant
 * velocity field (v, w), a screw: rotation by k w about the centroid, and
 * the translation (k I + (1 - cos t)/|w|^2 W + (k - sin t/|w|)/|w|^2 W^2) v,
 * t = k |w|, W the cross product by w: the exact integral, as in 2D. */
static bl_vec3 moved3(const pic *P, int b, bl_vec3 p)
{
    if (!moves(P, b)) return p;
    const double *u = P->s->u + 6 * b;
    bl_vec3 v = bl_v3(u[0], u[1], u[2]), w = bl_v3(u[3], u[4], u[5]);
    bl_vec3 c = P->m->blocks[b].centroid3, r = bl_v3_sub(p, c);
    double wn = bl_v3_norm(w), t = P->k * wn;
    if (t < 1e-9) return bl_v3_add(p, bl_v3_scale(bl_v3_add(v, bl_v3_cross(w, r)), P->k));
    bl_vec3 a = bl_v3_scale(w, 1.0 / wn);
    double cs = cos(t), sn = sin(t);
    /* Rodrigues: r turned by t about a */
    bl_vec3 rr = bl_v3_add(bl_v3_add(bl_v3_scale(r, cs), bl_v3_scale(bl_v3_cross(a, r), sn)),
                           bl_v3_scale(a, bl_v3_dot(a, r) * (1.0 - cs)));
    bl_vec3 wv = bl_v3_cross(w, v), wwv = bl_v3_cross(w, wv);
    bl_vec3 tr = bl_v3_add(bl_v3_scale(v, P->k),
                           bl_v3_add(bl_v3_scale(wv, (1.0 - cs) / (wn * wn)),
                                     bl_v3_scale(wwv, (P->k - sn / wn) / (wn * wn))));
    return bl_v3_add(c, bl_v3_add(rr, tr));
}

/* 3D: a point on the canvas plane, before scaling. */
static bl_vec2 project(const pic *P, bl_vec3 x)
{
    return bl_v2(bl_v3_dot(x, P->right), bl_v3_dot(x, P->up));
}

static bl_vec2 dev(const pic *P, bl_vec2 p)
{
    return bl_v2(P->x0 + P->sc * p.x, P->y0 - P->sc * p.y);
}

/* A joint marker rides with the side that moves less there, usually the one
 * that stays: a sliding or separating line then marks the face the other
 * block left, and a hinge sits where both blocks still touch. */
static int anchor(const pic *P, const bl_interface *f)
{
    double da = 0.0, db = 0.0;
    for (int j = 0; j < 2; j++) {
        if (moves(P, f->a)) da += speed(P->s, f->a, f->p[j]);
        if (moves(P, f->b)) db += speed(P->s, f->b, f->p[j]);
    }
    return db < da ? f->b : f->a;
}

static void block_path(cairo_t *cr, const pic *P, int b, int displaced)
{
    const bl_block *B = &P->m->blocks[b];
    cairo_new_path(cr);
    for (int i = 0; i < B->nv; i++) {
        bl_vec2 q = dev(P, displaced ? moved(P, b, B->v[i]) : B->v[i]);
        cairo_line_to(cr, q.x, q.y);
    }
    cairo_close_path(cr);
}

static void hatched(cairo_t *cr, const pic *P, int b)
{
    double step = fmax(3.0, 7.0 * P->unit), x1, y1, x2, y2;
    block_path(cr, P, b, 0);
    color(cr, SUPPORT_FILL);
    cairo_fill_preserve(cr);
    cairo_save(cr);
    cairo_clip_preserve(cr);
    cairo_path_extents(cr, &x1, &y1, &x2, &y2);
    cairo_new_path(cr);
    /* 45 degree lines anchored on the canvas, so that neighbouring supports
     * continue each other's hatch */
    double first = floor((x1 + y1) / step) * step;
    for (double c = first; c <= x2 + y2 + step; c += step) {
        cairo_move_to(cr, c - y1 + step, y1 - step);
        cairo_line_to(cr, c - y2 - step, y2 + step);
    }
    color(cr, SUPPORT_HATCH);
    cairo_set_line_width(cr, 0.8 * P->unit);
    cairo_stroke(cr);
    cairo_restore(cr);
    block_path(cr, P, b, 0);
    color(cr, SUPPORT_EDGE);
    cairo_set_line_width(cr, 1.3 * P->unit);
    cairo_stroke(cr);
}

/* The markers' sizes are in units of `size` (P->unit in the legend,
 * P->mark on the drawing). */
static void hinge_dot(cairo_t *cr, double size, bl_vec2 q)
{
    cairo_new_path(cr);
    cairo_arc(cr, q.x, q.y, 5.0 * size, 0.0, 2.0 * M_PI);
    color(cr, HINGE);
    cairo_fill_preserve(cr);
    color(cr, HINGE_EDGE);
    cairo_set_line_width(cr, size);
    cairo_stroke(cr);
}

static void hinge_line(cairo_t *cr, double size, bl_vec2 a, bl_vec2 b)
{
    cairo_new_path(cr);
    cairo_move_to(cr, a.x, a.y);
    cairo_line_to(cr, b.x, b.y);
    color(cr, HINGE);
    cairo_set_line_width(cr, 5.0 * size);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_stroke(cr);
}

static void sliding_line(cairo_t *cr, double size, bl_vec2 a, bl_vec2 b)
{
    cairo_new_path(cr);
    cairo_move_to(cr, a.x, a.y);
    cairo_line_to(cr, b.x, b.y);
    color(cr, SLIDING);
    cairo_set_line_width(cr, 4.5 * size);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    cairo_stroke(cr);
}

static void separating_line(cairo_t *cr, double size, bl_vec2 a, bl_vec2 b)
{
    double dash[2] = {7.0 * size, 4.0 * size};
    cairo_new_path(cr);
    cairo_move_to(cr, a.x, a.y);
    cairo_line_to(cr, b.x, b.y);
    color(cr, SEPARATING);
    cairo_set_line_width(cr, 2.4 * size);
    cairo_set_dash(cr, dash, 2, 0.0);
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0.0);
}

static void set_font(cairo_t *cr, const pic *P)
{
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, P->font);
}

static const char *const LEGEND[3] = {"hinge", "sliding", "separating"};

/* Draws the legend with its left end at (x, baseline y), or with draw 0 only
 * measures it.  Returns its width. */
static double legend(cairo_t *cr, const pic *P, double x, double y, int draw)
{
    double sample = 1.8 * P->font, pad = 0.45 * P->font, gap = 1.3 * P->font;
    double mid = y - 0.33 * P->font, x_start = x;
    for (int i = 0; i < 3; i++) {
        if (draw) {
            bl_vec2 a = bl_v2(x, mid), b = bl_v2(x + sample, mid);
            /* 3D hinges are mostly edges, drawn as lines */
            if (i == 0 && P->m && P->m->dim == 3) hinge_line(cr, P->unit, a, b);
            else if (i == 0) hinge_dot(cr, P->unit, bl_v2(x + 0.5 * sample, mid));
            if (i == 1) sliding_line(cr, P->unit, a, b);
            if (i == 2) separating_line(cr, P->unit, a, b);
        }
        x += sample + pad;
        cairo_text_extents_t te;
        cairo_text_extents(cr, LEGEND[i], &te);
        if (draw) {
            color(cr, INK);
            cairo_move_to(cr, x, y);
            cairo_show_text(cr, LEGEND[i]);
        }
        x += te.x_advance + (i < 2 ? gap : 0.0);
    }
    return x - x_start;
}

/* Largest vertex speed of the free blocks, 0 when u holds a NaN or an
 * infinity: such a mechanism cannot be drawn, the model still can. */
static double max_speed(const bl_solution *s)
{
    const bl_model *m = s->model;
    double maxd = 0.0;
    for (int b = 0; b < m->nblocks; b++) {
        if (m->blocks[b].support) continue;
        double d = bl_solution_block_speed(s, b);
        if (!isfinite(d)) return 0.0;
        maxd = fmax(maxd, d);
    }
    return maxd;
}

/* The largest angular speed of a free block. */
static double max_turn(const bl_solution *s)
{
    const bl_model *m = s->model;
    double w = 0.0;
    for (int b = 0; b < m->nblocks; b++) {
        if (m->blocks[b].support) continue;
        const double *u = s->u + (m->dim == 3 ? 6 * b : 3 * b);
        w = fmax(w, m->dim == 3 ? sqrt(u[3] * u[3] + u[4] * u[4] + u[5] * u[5]) : fabs(u[2]));
    }
    return w;
}

static void grow(double box[4], bl_vec2 q)
{
    box[0] = fmin(box[0], q.x);
    box[1] = fmin(box[1], q.y);
    box[2] = fmax(box[2], q.x);
    box[3] = fmax(box[3], q.y);
}

/* Point load pl in the picture's plane: where it acts, on its block as
 * moved (move) or not, and the unit direction of its arrow, along its
 * force (a carried weight's along gravity); zero for a couple alone or a
 * force along the line of sight. */
static void load_point(const pic *P, const bl_point_load *pl, int move, bl_vec2 *at, bl_vec2 *dir)
{
    int w = pl->weight > 0.0;
    if (P->dim == 3) {
        bl_vec3 p = move ? moved3(P, pl->block, pl->at3) : pl->at3;
        *at = project(P, p);
        *dir = bl_v2_sub(project(P, bl_v3_add(p, bl_v3_unit(w ? bl_model_gravity3(P->m) : pl->force3))), *at);
    } else {
        *at = move ? moved(P, pl->block, pl->at) : pl->at;
        *dir = bl_v2_unit(w ? bl_model_gravity(P->m) : pl->force);
    }
    double n = bl_v2_norm(*dir);
    *dir = n > 1e-9 ? bl_v2_scale(*dir, 1.0 / n) : bl_v2(0.0, 0.0);
}

/* Scale of the mechanism and bounding box of what will be drawn. */
static void extent(pic *P, double box[4])
{
    const bl_model *m = P->m;
    P->maxd = bl_solution_moves(P->s) ? max_speed(P->s) : 0.0;
    double size = bl_model_size(m);
    P->k = P->maxd > 0.0 && size > 0.0 ? SHOW_FRACTION * size / P->maxd : 0.0;
    /* and no block turned by more than SHOW_TURN: each moves rigidly over
     * "time" k, so blocks hinged together part at the hinge by about
     * (k w)^2 / 2 of their size (a flying buttress's short links drawn
     * turned by 0.8 rad came apart at their hinges) */
    double turn = P->k > 0.0 ? max_turn(P->s) : 0.0;
    if (turn * P->k > SHOW_TURN) P->k = SHOW_TURN / turn;
    box[0] = box[1] = INFINITY;
    box[2] = box[3] = -INFINITY;
    for (int b = 0; m->dim == 3 && b < m->nblocks; b++) {
        const bl_polyhedron *S = &m->blocks[b].solid;
        for (int i = 0; i < S->nv; i++)
            for (int pass = 0; pass < 2; pass++) grow(box, project(P, pass ? moved3(P, b, S->v[i]) : S->v[i]));
    }
    for (int b = 0; m->dim == 2 && b < m->nblocks; b++) {
        const bl_block *B = &m->blocks[b];
        for (int i = 0; i < B->nv; i++)
            for (int pass = 0; pass < 2; pass++) grow(box, pass ? moved(P, b, B->v[i]) : B->v[i]);
    }
    /* the loads' points (a carried weight's may lie off its block: a
     * fill's centroid, or the dead-load check's forces that were weights)
     * and their arrows' tails, ARROW of the canvas's width, in model
     * units at the scale the blocks will take (the drawing is 0.92 of the
     * canvas's width, between its margins) */
    double room = ARROW / 0.92 * fmax(box[2] - box[0], (box[3] - box[1]) / MAX_ASPECT);
    for (int l = 0; l < m->nloads; l++)
        for (int pass = 0; pass < 2; pass++) {
            bl_vec2 at, dir;
            load_point(P, &m->loads[l], pass, &at, &dir);
            grow(box, at);
            grow(box, bl_v2_sub(at, bl_v2_scale(dir, room)));
            const bl_point_load *pl = &m->loads[l];
            if (pl->moment != 0.0 || bl_v3_norm(pl->moment3) > 0.0) /* its couple, around it */
                for (int c = 0; c < 4; c++)
                    grow(box, bl_v2_add(at, bl_v2((c & 1 ? 1.0 : -1.0) * room, (c & 2 ? 1.0 : -1.0) * room)));
        }
}

/* For the caption: where the weight-proportional live load points, "" where
 * there is none (its point loads have arrows; this one acts on every
 * block): "; live load along -x", or along its unit vector. */
static void live_words(const bl_model *m, char *out, size_t n)
{
    out[0] = '\0';
    if (!m || !m->live_weight) return;
    double d[3] = {m->live_dir.x, m->live_dir.y, 0.0};
    if (m->dim == 3) d[0] = m->live_dir3.x, d[1] = m->live_dir3.y, d[2] = m->live_dir3.z;
    int dims = m->dim == 3 ? 3 : 2;
    for (int k = 0; k < dims; k++)
        if (fabs(fabs(d[k]) - 1.0) < 1e-12) {
            snprintf(out, n, "; live load along %c%c", d[k] > 0 ? '+' : '-', "xyz"[k]);
            return;
        }
    if (dims == 2) snprintf(out, n, "; live load along (%.3g, %.3g)", d[0], d[1]);
    else snprintf(out, n, "; live load along (%.3g, %.3g, %.3g)", d[0], d[1], d[2]);
}

/* Fixes the canvas size and where everything goes. */
static void layout(pic *P, const bl_solution *s, int width, double azimuth, double elevation)
{
    memset(P, 0, sizeof *P);
    P->s = s;
    P->dim = s->model ? s->model->dim : 2;
    double az = azimuth * M_PI / 180.0, el = elevation * M_PI / 180.0;
    P->eye = bl_v3(sin(az) * cos(el), -cos(az) * cos(el), sin(el));
    P->right = bl_v3(cos(az), sin(az), 0.0);
    P->up = bl_v3_cross(P->eye, P->right);
    P->m = s->model && s->model->nblocks > 0 ? s->model : NULL;
    P->w = width;
    P->unit = fmax(0.6, width / 1000.0);
    P->font = fmax(11.0, 15.0 * width / 1000.0);
    double margin = P->margin = fmax(8.0, 0.04 * width);
    double dw = fmax(1.0, P->w - 2.0 * margin);
    P->top = margin;
    P->dh = 0.3 * dw;
    if (P->m) {
        double box[4];
        extent(P, box);
        double bw = fmax(box[2] - box[0], 1e-300), bh = fmax(box[3] - box[1], 1e-300);
        P->sc = dw / bw;
        P->dh = bh * P->sc;
        if (P->dh > MAX_ASPECT * dw) {
            P->dh = MAX_ASPECT * dw;
            P->sc = P->dh / bh;
        }
        P->x0 = 0.5 * (P->w - bw * P->sc) - box[0] * P->sc;
        P->y0 = P->top + box[3] * P->sc;
    }
    /* markers of at most about a third of the canvas's share per block, so
     * that on walls of thousands of blocks they do not cover the blocks
     * (a hinge's dot is 10 marks across), and the blocks' outlines with
     * them; never below a fifth of unit */
    P->mark = P->unit;
    if (P->m)
        P->mark = fmin(P->unit, fmax(0.2 * P->unit, sqrt(dw * P->dh / P->m->nblocks) / 30.0));
    /* 2D: no outlines on blocks thinner than THIN_BLOCK on average (their
     * area over their longest edge), which outlines would cover: an arch
     * of 3,000 voussoirs half a pixel thick was a dark band */
    P->outlines = 1;
    if (P->m && P->dim == 2) {
        double thin = 0.0;
        int n = 0;
        for (int b = 0; b < P->m->nblocks; b++) {
            const bl_block *B = &P->m->blocks[b];
            if (B->support) continue;
            double longest = 0.0;
            for (int i = 0; i < B->nv; i++)
                longest = fmax(longest, bl_v2_norm(bl_v2_sub(B->v[(i + 1) % B->nv], B->v[i])));
            thin += longest > 0.0 ? B->area / longest : 0.0;
            n++;
        }
        P->outlines = n == 0 || thin / n * P->sc >= THIN_BLOCK;
    }
    const char *name = bl_status_name(s->status);
    /* as print(r) says: no alpha where a sequence found none or no live
     * load makes the structure collapse; an interval where only the live
     * load holds it up (doc/theory.md 8) */
    char value[64] = "no alpha";
    if (isfinite(s->alpha) && !isnan(s->alpha_min))
        snprintf(value, sizeof value, "alpha = %.5g, held up from alpha_min = %.5g", s->alpha, s->alpha_min);
    else if (isfinite(s->alpha))
        snprintf(value, sizeof value, "alpha = %.5g", s->alpha);
    else if (!isnan(s->alpha_min))
        snprintf(value, sizeof value, "no alpha, held up from alpha_min = %.5g", s->alpha_min);
    /* as print(r): an answer is verified or says it is not */
    const char *check = s->verified ? ", verified"
                        : (s->status == BL_OPTIMAL || s->status == BL_UNSTABLE) && isfinite(s->alpha)
                            ? ", NOT verified"
                            : "";
    char live[64];
    live_words(P->m, live, sizeof live);
    snprintf(P->caption, sizeof P->caption, "%s  (%s, %s flow, %s%s%s)", value, name ? name : "?",
             s->flow, s->method, check, live);
    P->has_legend = P->m && P->k > 0.0;

    /* text widths need a cairo context; a 1x1 image gives the same metrics
     * as the real surfaces for the toy font API */
    cairo_surface_t *scratch = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
    cairo_t *cr = cairo_create(scratch);
    set_font(cr, P);
    cairo_text_extents_t te;
    cairo_text_extents(cr, P->caption, &te);
    double cw = te.x_advance, lw = P->has_legend ? legend(cr, P, 0.0, 0.0, 0) : 0.0;
    cairo_destroy(cr);
    cairo_surface_destroy(scratch);
    /* a narrow picture: the text smaller, so that the caption and the
     * legend fit between the margins (both scale with the font) */
    double fit = dw / fmax(1e-9, fmax(cw, lw));
    if (fit < 1.0) {
        P->font *= fit;
        cw *= fit;
        lw *= fit;
    }

    double line = 1.7 * P->font;
    P->caption_y = P->top + P->dh + 0.6 * margin + P->font;
    P->legend_x = P->w - margin - lw;
    P->legend_y = P->caption_y;
    int two_lines = P->has_legend && margin + cw + 2.0 * P->font > P->legend_x;
    if (two_lines) {
        P->legend_x = margin;
        P->legend_y += line;
    }
    P->h = ceil(P->legend_y + 0.6 * P->font + 0.5 * margin);
}

/* A visible face of a 3D block, for the painter's algorithm. */
typedef struct face3 {
    int block, face;
    double depth, light;
} face3;

static int farther(const void *x, const void *y)
{
    double a = ((const face3 *)x)->depth, b = ((const face3 *)y)->depth;
    return (a > b) - (a < b);
}

/* 3D: the side of a joint that moves less over its contact polygon. */
static int anchor3(const pic *P, const bl_interface *f)
{
    double da = 0.0, db = 0.0;
    for (int e = 0; e < f->np; e++) {
        if (moves(P, f->a)) da += bl_v3_norm(bl_solution_velocity(P->s, f->a, f->poly[e]));
        if (moves(P, f->b)) db += bl_v3_norm(bl_solution_velocity(P->s, f->b, f->poly[e]));
    }
    return db < da ? f->b : f->a;
}

/* Whether joint i moves enough to be marked: its relative motion at least
 * the share of the largest at which blocks stop looking still (a 250-block
 * facade marked 160 joints moving less than a thousandth of it as hinges
 * and slides, over blocks drawn still). */
static int visible_motion(const pic *P, int i)
{
    return P->s->speed[i] >= BL_STILL_FRACTION * P->s->speed_max;
}

/* Whether joint i gets a 3D marker: sliding, separating or rocking. */
static int marked3(const pic *P, int i)
{
    bl_state st = P->s->state[i];
    return P->m->interfaces[i].np >= 2 && visible_motion(P, i) &&
           (st == BL_SLIDING || st == BL_SEPARATING || st == BL_ROCKING);
}

/* Whether the hinge from a to b, riding with block side, is seen end on:
 * shorter on the canvas than a dot (joint3 draws it as one). */
static int end_on_hinge(const pic *P, int side, bl_vec3 a, bl_vec3 b)
{
    bl_vec2 pa = dev(P, project(P, moved3(P, side, a))), pb = dev(P, project(P, moved3(P, side, b)));
    return bl_v2_norm(bl_v2_sub(pb, pa)) < 5.0 * P->mark;
}

/* One piece of a 3D joint marker: edge e of the contact polygon (vertex 0)
 * or, on a rocking joint, its corner e alone (vertex 1).  A sliding joint
 * outlines its polygon blue, a separating one dashed orange; a rocking
 * joint draws its hinge, the edges whose both ends stay closed, red, and a
 * closed corner between open ones as a red dot.  It rides with the side
 * that moves less. */
static void joint3(cairo_t *cr, const pic *P, int i, int e, int vertex)
{
    const bl_interface *f = &P->m->interfaces[i];
    const bl_solution *s = P->s;
    int side = anchor3(P, f), e1 = (e + 1) % f->np;
    bl_vec2 a = dev(P, project(P, moved3(P, side, f->poly[e])));
    bl_vec2 b = dev(P, project(P, moved3(P, side, f->poly[e1])));
    /* a hinge seen end on is a dot */
    if (vertex || (s->state[i] == BL_ROCKING && end_on_hinge(P, side, f->poly[e], f->poly[e1])))
        hinge_dot(cr, P->mark, vertex ? a : bl_v2_scale(bl_v2_add(a, b), 0.5));
    else if (s->state[i] == BL_SLIDING) sliding_line(cr, P->mark, a, b);
    else if (s->state[i] == BL_SEPARATING) separating_line(cr, P->mark, a, b);
    else hinge_line(cr, P->mark, a, b);
}

/* The depth of face k of block b where it is seen edge on (its normal
 * across the line of sight, to round-off), else NAN: a marker on such a
 * face lies on the block's outline, in sight. */
static void face_plane(const pic *P, int b, int k, int unmoved, bl_vec3 *c, bl_vec3 *nrm);

static double edge_on(const pic *P, int b, int k)
{
    bl_vec3 c, nrm;
    face_plane(P, b, k, 0, &c, &nrm);
    double nn = bl_v3_norm(nrm);
    return nn > 0.0 && fabs(bl_v3_dot(nrm, P->eye)) <= 1e-9 * nn ? bl_v3_dot(c, P->eye) : NAN;
}

/* The pieces of joint i's marker (see joint3) whose point (an edge's
 * midpoint, or the corner) lies on a visible face of the block the marker
 * rides with, into F with the depth of the nearest visible face of either
 * block that holds it, so that they paint just over both and under
 * whatever is nearer; pieces on no visible face of that block are inside
 * the structure or behind it and left out (judged by either block, a joint
 * on a slab's top was drawn over the slab seen from below).  depth: per face of every block (face_off[b] +
 * k), NAN where turned away.  Returns the number added. */
static int joint_pieces(const pic *P, int i, const int *face_off, const double *depth, face3 *F)
{
    const bl_model *m = P->m;
    const bl_interface *f = &m->interfaces[i];
    bl_state st = P->s->state[i];
    int side = anchor3(P, f);
    double size = 0.0;
    for (int e = 0; e < f->np; e++)
        size += bl_v3_norm(bl_v3_sub(f->poly[(e + 1) % f->np], f->poly[e]));
    int n = 0;
    for (int e = 0; e < f->np; e++)
        for (int vertex = 0; vertex < 2; vertex++) {
            int e1 = (e + 1) % f->np;
            if (st == BL_ROCKING) {
                int c0 = bl_solution_closed3(P->s, i, e), c1 = bl_solution_closed3(P->s, i, e1);
                int cp = bl_solution_closed3(P->s, i, (e + f->np - 1) % f->np);
                if (vertex ? !c0 || c1 || cp : !c0 || !c1) continue;
            } else if (vertex) {
                continue;
            }
            /* a piece by its point; a hinge seen end on (drawn as a dot,
             * joint3) also by either end and on faces seen edgewise, where
             * its midpoint lies */
            bl_vec3 q[3] = {vertex ? f->poly[e] : bl_v3_scale(bl_v3_add(f->poly[e], f->poly[e1]), 0.5),
                            f->poly[e], f->poly[e1]};
            int end_on = !vertex && st == BL_ROCKING && end_on_hinge(P, side, q[1], q[2]);
            double d = -INFINITY;
            int seen = 0, rim = 0, blk[2] = {side, side == f->a ? f->b : f->a};
            for (int c = 0; c < (end_on ? 3 : 1); c++)
                for (int j = 0; j < 2; j++) {
                    const bl_polyhedron *S = &m->blocks[blk[j]].solid;
                    for (int k = 0; k < S->nf; k++) {
                        double dk = depth[face_off[blk[j]] + k];
                        int edgewise = isnan(dk) && end_on;
                        if (edgewise) dk = edge_on(P, blk[j], k);
                        if (isnan(dk) || !bl_polyhedron_on_face(S, k, q[c], 1e-6 * size)) continue;
                        seen |= j == 0;
                        rim |= j == 0 && edgewise;
                        d = fmax(d, dk);
                    }
                }
            /* a dot on the outline of the block it rides with: in front of
             * that block's faces (a base slab's front face hid a toe's
             * hinge) */
            for (int k = 0; rim && k < m->blocks[side].solid.nf; k++)
                if (!isnan(depth[face_off[side] + k])) d = fmax(d, depth[face_off[side] + k]);
            if (!seen) continue;
            if (d > -INFINITY) F[n++] = (face3){i, -1 - (2 * e + vertex), d + 1e-9 * (1.0 + fabs(d)), 0.0};
        }
    return n;
}

/* Face k of block b as moved (or where it was, unmoved): the mean of its
 * corners in *c and twice its area along its normal in *nrm (outward). */
static void face_plane(const pic *P, int b, int k, int unmoved, bl_vec3 *c, bl_vec3 *nrm)
{
    const bl_polyhedron *S = &P->m->blocks[b].solid;
    int a0 = S->fs[k], len = S->fs[k + 1] - a0;
    *c = *nrm = (bl_vec3){0, 0, 0};
    for (int i = 0; i < len; i++) {
        bl_vec3 p = S->v[S->fi[a0 + i]], q = S->v[S->fi[a0 + (i + 1) % len]];
        if (!unmoved) p = moved3(P, b, p), q = moved3(P, b, q);
        *c = bl_v3_add(*c, bl_v3_scale(p, 1.0 / len));
        *nrm = bl_v3_add(*nrm, bl_v3_cross(p, q));
    }
}

/* Where the face of F[u] lies against the plane nrm . x = d0: 1 wholly in
 * front of it (towards the viewer, or on it), -1 wholly behind, 0 across. */
static int face_side(const pic *P, const face3 *u, bl_vec3 nrm, double d0, double tol)
{
    const bl_polyhedron *S = &P->m->blocks[u->block].solid;
    double lo = INFINITY, hi = -INFINITY;
    for (int i = S->fs[u->face]; i < S->fs[u->face + 1]; i++) {
        double h = bl_v3_dot(nrm, moved3(P, u->block, S->v[S->fi[i]])) - d0;
        lo = fmin(lo, h);
        hi = fmax(hi, h);
    }
    return lo >= -tol ? 1 : hi <= tol ? -1 : 0;
}

/* The painting keys of the supports' faces (F[0..n), keys in depth too).
 * A support's face can be far larger than a block's (a base slab under a
 * whole building), and its centre's depth says little: blocks standing on
 * the slab behind its centre were painted over by its top.  A flat face
 * hides only what lies behind its plane and is hidden only by what lies in
 * front, so its key is put after every block face wholly behind its plane
 * and before every one wholly in front, where one key does both. */
static void support_keys(const pic *P, face3 *F, int n, const int *face_off, double *depth)
{
    const bl_model *m = P->m;
    for (int t = 0; t < n; t++) {
        if (!m->blocks[F[t].block].support) continue;
        bl_vec3 c, nrm;
        face_plane(P, F[t].block, F[t].face, 0, &c, &nrm);
        nrm = bl_v3_scale(nrm, 1.0 / bl_v3_norm(nrm)); /* towards the viewer: the face is shown */
        double d0 = bl_v3_dot(nrm, c), tol = 1e-9 * (1.0 + fabs(d0));
        double behind = -INFINITY, front = INFINITY;
        for (int u = 0; u < n; u++) {
            if (m->blocks[F[u].block].support) continue;
            int side = face_side(P, &F[u], nrm, d0, tol);
            if (side > 0) front = fmin(front, F[u].depth);
            if (side < 0) behind = fmax(behind, F[u].depth);
        }
        if (!(behind < front)) continue;
        double gap = fmin(1e-9 * (1.0 + fabs(F[t].depth)), 0.25 * (front - behind));
        double key = fmin(fmax(F[t].depth, behind + gap), front - gap);
        F[t].depth = depth[face_off[F[t].block] + F[t].face] = key;
    }
}

/* Faces that lie wholly against neighbours they move with: the contact
 * polygons on them, of joints that do not visibly move, cover their area.
 * They cannot be seen, and painted in the order of their depths the top
 * of a course showed through the front of the next, seen from 45 degrees
 * (a wall overturning as one body).  hidden: per face (face_off[b] + k). */
static void hidden_faces(const pic *P, const int *face_off, char *hidden)
{
    const bl_model *m = P->m;
    int nf = face_off[m->nblocks - 1] + m->blocks[m->nblocks - 1].solid.nf;
    double *covered = calloc((size_t)nf + 1, sizeof *covered);
    if (!covered) return;
    for (int i = 0; i < m->ninterfaces; i++) {
        const bl_interface *f = &m->interfaces[i];
        if (P->k > 0.0 && P->s->state && visible_motion(P, i)) continue;
        bl_vec3 cen = {0, 0, 0};
        for (int e = 0; e < f->np; e++) cen = bl_v3_add(cen, bl_v3_scale(f->poly[e], 1.0 / f->np));
        for (int side = 0; side < 2; side++) {
            int b = side ? f->b : f->a;
            const bl_polyhedron *S = &m->blocks[b].solid;
            bl_vec3 out = bl_v3_scale(f->n3, side ? -1.0 : 1.0); /* the face's outward normal */
            for (int k = 0; k < S->nf; k++) {
                bl_vec3 c, nrm;
                face_plane(P, b, k, 1, &c, &nrm);
                double area2 = bl_v3_norm(nrm);
                if (!(area2 > 0.0) || bl_v3_dot(nrm, out) < 0.999 * area2) continue;
                double size = sqrt(area2);
                if (fabs(bl_v3_dot(bl_v3_sub(cen, c), nrm)) / area2 > 1e-9 * size) continue;
                covered[face_off[b] + k] += f->area3;
                break;
            }
        }
    }
    for (int b = 0; b < m->nblocks; b++)
        for (int k = 0; k < m->blocks[b].solid.nf; k++) {
            bl_vec3 c, nrm;
            face_plane(P, b, k, 1, &c, &nrm);
            hidden[face_off[b] + k] = covered[face_off[b] + k] >= (1.0 - 1e-9) * 0.5 * bl_v3_norm(nrm);
        }
    free(covered);
}

/* 3D: the blocks as moved by the mechanism, seen along the view: faces
 * turned away are dropped, the others painted far to near, shaded by how
 * squarely they face the light (from the viewer's upper left); supports
 * grey, moving blocks terracotta, still ones pale. */
static void draw3(cairo_t *cr, const pic *P)
{
    const bl_model *m = P->m;
    int nf = 0, npieces = 0, joints = P->k > 0.0 && P->s->state;
    int *face_off = malloc(((size_t)m->nblocks + 1) * sizeof *face_off);
    for (int b = 0; face_off && b < m->nblocks; b++) {
        face_off[b] = nf;
        nf += m->blocks[b].solid.nf;
    }
    for (int i = 0; joints && i < m->ninterfaces; i++)
        if (marked3(P, i)) npieces += 2 * m->interfaces[i].np;
    face3 *F = malloc(((size_t)nf + (size_t)npieces + 1) * sizeof *F);
    double *depth = malloc(((size_t)nf + 1) * sizeof *depth);
    char *hidden = calloc((size_t)nf + 1, 1);
    if (!F || !depth || !face_off || !hidden) {
        free(F), free(depth), free(face_off), free(hidden);
        return;
    }
    hidden_faces(P, face_off, hidden);
    bl_vec3 light = bl_v3_add(bl_v3_add(bl_v3_scale(P->eye, 0.8), bl_v3_scale(P->up, 0.5)),
                              bl_v3_scale(P->right, -0.35));
    light = bl_v3_scale(light, 1.0 / bl_v3_norm(light));
    int n = 0;
    for (int b = 0; b < m->nblocks; b++) {
        const bl_polyhedron *S = &m->blocks[b].solid;
        for (int k = 0; k < S->nf; k++) {
            bl_vec3 c, nrm;
            face_plane(P, b, k, 0, &c, &nrm);
            double nn = bl_v3_norm(nrm);
            depth[face_off[b] + k] = NAN;
            if (!(nn > 0.0) || bl_v3_dot(nrm, P->eye) <= 0.0 || hidden[face_off[b] + k]) continue;
            nrm = bl_v3_scale(nrm, 1.0 / nn);
            depth[face_off[b] + k] = bl_v3_dot(c, P->eye);
            F[n++] = (face3){b, k, depth[face_off[b] + k], fabs(bl_v3_dot(nrm, light))};
        }
    }
    support_keys(P, F, n, face_off, depth);
    for (int i = 0; joints && i < m->ninterfaces; i++)
        if (marked3(P, i)) n += joint_pieces(P, i, face_off, depth, F + n);
    qsort(F, (size_t)n, sizeof *F, farther);
    for (int t = 0; t < n; t++) {
        int b = F[t].block, k = F[t].face;
        if (k < 0) { /* a piece of joint b's marker */
            joint3(cr, P, b, (-1 - k) / 2, (-1 - k) % 2);
            continue;
        }
        const bl_block *B = &m->blocks[b];
        const bl_polyhedron *S = &B->solid;
        rgb base = B->support ? SUPPORT_FILL : still(P, b) ? STILL : MOVING;
        double shade = 0.55 + 0.45 * F[t].light;
        cairo_new_path(cr);
        for (int i = S->fs[k]; i < S->fs[k + 1]; i++) {
            bl_vec2 q = dev(P, project(P, moved3(P, b, S->v[S->fi[i]])));
            cairo_line_to(cr, q.x, q.y);
        }
        cairo_close_path(cr);
        cairo_set_source_rgb(cr, base.r * shade, base.g * shade, base.b * shade);
        cairo_fill_preserve(cr);
        color(cr, B->support ? SUPPORT_EDGE : BLOCK_EDGE);
        cairo_set_line_width(cr, 0.9 * P->mark);
        cairo_stroke(cr);
    }
    free(F);
    free(depth);
    free(face_off);
    free(hidden);
}

/* An arrow's head: a triangle with its tip at tip, along the unit d (canvas). */
static void arrow_head(cairo_t *cr, bl_vec2 tip, bl_vec2 d, double head)
{
    bl_vec2 base = bl_v2_sub(tip, bl_v2_scale(d, 2.0 * head)), side = bl_v2(-d.y * head, d.x * head);
    cairo_new_path(cr);
    cairo_move_to(cr, tip.x, tip.y);
    cairo_line_to(cr, base.x + side.x, base.y + side.y);
    cairo_line_to(cr, base.x - side.x, base.y - side.y);
    cairo_close_path(cr);
    cairo_fill(cr);
}

/* An arrow from tail to tip, along the unit d (canvas): its shaft to its
 * head's base, and the head. */
static void arrow(cairo_t *cr, bl_vec2 tail, bl_vec2 tip, bl_vec2 d, double head)
{
    bl_vec2 base = bl_v2_sub(tip, bl_v2_scale(d, 2.0 * head));
    cairo_new_path(cr);
    cairo_move_to(cr, tail.x, tail.y);
    cairo_line_to(cr, base.x, base.y);
    cairo_set_line_width(cr, 0.5 * head);
    cairo_stroke(cr);
    arrow_head(cr, tip, d, head);
}

/* A couple at the canvas point at, as its sense is seen: three quarters of
 * a circle of radius r around it, ending in a head (anticlockwise as seen
 * where ccw; on the canvas y runs down, so that is decreasing angle). */
static void couple_arc(cairo_t *cr, bl_vec2 at, double r, double head, int ccw)
{
    double a0 = 0.25 * M_PI, a1 = a0 + (ccw ? -1.5 : 1.5) * M_PI;
    cairo_new_path(cr);
    if (ccw)
        cairo_arc_negative(cr, at.x, at.y, r, a0, a1);
    else
        cairo_arc(cr, at.x, at.y, r, a0, a1);
    cairo_set_line_width(cr, 0.5 * head);
    cairo_stroke(cr);
    bl_vec2 end = bl_v2(at.x + r * cos(a1), at.y + r * sin(a1));
    bl_vec2 along = ccw ? bl_v2(sin(a1), -cos(a1)) : bl_v2(-sin(a1), cos(a1));
    arrow_head(cr, bl_v2_add(end, bl_v2_scale(along, head)), along, head);
}

/* A couple of point load pl, drawn at where it acts (p, model units, on
 * its block as moved): in 2D, and in 3D where its moment points within
 * 30 degrees of the line of sight, as an arc with the sense seen
 * (couple_arc); else as its moment's vector, an arrow with two heads. */
static void couple(cairo_t *cr, const pic *P, const bl_point_load *pl, bl_vec2 p, double len, double head)
{
    bl_vec2 at = dev(P, p);
    double towards = pl->moment; /* 2D: anticlockwise, towards the viewer */
    bl_vec2 in = bl_v2(0.0, 0.0);
    if (P->dim == 3) {
        towards = bl_v3_dot(pl->moment3, P->eye);
        in = bl_v2(bl_v3_dot(pl->moment3, P->right), -bl_v3_dot(pl->moment3, P->up));
    }
    double size = hypot(towards, bl_v2_norm(in));
    if (size == 0.0) return;
    if (bl_v2_norm(in) < 0.5 * size) { /* (a live one around a dead one at the same point) */
        couple_arc(cr, at, (pl->live ? 0.45 : 0.3) * len, head, towards > 0.0);
        return;
    }
    bl_vec2 d = bl_v2_scale(in, 1.0 / bl_v2_norm(in));
    arrow(cr, bl_v2_sub(at, bl_v2_scale(d, len)), at, d, head);
    arrow_head(cr, bl_v2_sub(at, bl_v2_scale(d, 2.0 * head)), d, head);
}

/* Every point load as an arrow ending where it acts (on its block as
 * moved), along its force (a carried weight along gravity), of one length
 * (ARROW of the canvas's width, not to scale), and its couple (couple):
 * dead grey, live purple.  A force along the line of sight has none. */
static void load_arrows(cairo_t *cr, const pic *P)
{
    const bl_model *m = P->m;
    double len = ARROW * P->w, head = fmax(3.0, 5.0 * P->mark);
    for (int l = 0; l < m->nloads; l++) {
        const bl_point_load *pl = &m->loads[l];
        bl_vec2 p, d;
        load_point(P, pl, 1, &p, &d);
        color(cr, pl->live ? LIVE_LOAD : DEAD_LOAD);
        couple(cr, P, pl, p, len, head);
        if (d.x == 0.0 && d.y == 0.0) continue;
        bl_vec2 at = dev(P, p);
        d = bl_v2(d.x, -d.y); /* the canvas's y runs down */
        /* shorter where the canvas ends (a load on a wall's top) */
        double fit = len;
        if (d.x > 0.0) fit = fmin(fit, at.x / d.x);
        if (d.x < 0.0) fit = fmin(fit, (at.x - P->w) / d.x);
        if (d.y > 0.0) fit = fmin(fit, at.y / d.y);
        if (d.y < 0.0) fit = fmin(fit, (at.y - P->h) / d.y);
        fit = fmax(fit, 3.0 * head);
        arrow(cr, bl_v2_sub(at, bl_v2_scale(d, fit)), at, d, head);
    }
}

static void draw(cairo_t *cr, const pic *P)
{
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_paint(cr);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    set_font(cr, P);

    const bl_model *m = P->m;
    if (!m) {
        const char *empty = "(no blocks)";
        cairo_text_extents_t te;
        cairo_text_extents(cr, empty, &te);
        color(cr, GHOST);
        cairo_move_to(cr, 0.5 * (P->w - te.x_advance), P->top + 0.5 * P->dh);
        cairo_show_text(cr, empty);
    } else if (P->dim == 3) {
        draw3(cr, P);
    } else {
        const bl_solution *s = P->s;
        if (P->k > 0.0 && P->outlines) {
            for (int b = 0; b < m->nblocks; b++) {
                if (m->blocks[b].support) continue;
                block_path(cr, P, b, 0);
                color(cr, GHOST);
                cairo_set_line_width(cr, 0.9 * P->mark);
                cairo_stroke(cr);
            }
        }
        for (int b = 0; b < m->nblocks; b++)
            if (m->blocks[b].support) hatched(cr, P, b);
        for (int b = 0; b < m->nblocks; b++) {
            const bl_block *B = &m->blocks[b];
            if (B->support) continue;
            rgb fill = still(P, b) ? STILL : MOVING;
            block_path(cr, P, b, 1);
            /* slightly see-through, so the outlines of the original
             * position stay visible under the moved blocks */
            cairo_set_source_rgba(cr, fill.r, fill.g, fill.b, P->k > 0.0 ? 0.88 : 1.0);
            if (!P->outlines) {
                cairo_fill(cr);
                continue;
            }
            cairo_fill_preserve(cr);
            color(cr, BLOCK_EDGE);
            cairo_set_line_width(cr, 1.2 * P->mark);
            cairo_stroke(cr);
        }
        if (P->k > 0.0 && s->state) {
            /* hinges last: a dot must not be hidden by a neighbouring line */
            for (int pass = 0; pass < 2; pass++)
                for (int i = 0; i < m->ninterfaces; i++) {
                    const bl_interface *f = &m->interfaces[i];
                    if (f->a < 0 || f->a >= m->nblocks || f->b < 0 || f->b >= m->nblocks ||
                        !visible_motion(P, i))
                        continue;
                    int side = anchor(P, f);
                    bl_vec2 a = dev(P, moved(P, side, f->p[0]));
                    bl_vec2 b = dev(P, moved(P, side, f->p[1]));
                    int h = s->hinge ? s->hinge[i] : -1;
                    if (pass == 0 && s->state[i] == BL_SLIDING) sliding_line(cr, P->mark, a, b);
                    if (pass == 0 && s->state[i] == BL_SEPARATING)
                        separating_line(cr, P->mark, a, b);
                    if (pass == 1 && s->state[i] == BL_ROCKING && (h == 0 || h == 1))
                        hinge_dot(cr, P->mark, h ? b : a);
                }
        }
    }
    if (m) load_arrows(cr, P);

    color(cr, INK);
    cairo_move_to(cr, P->margin, P->caption_y);
    cairo_show_text(cr, P->caption);
    if (P->has_legend) legend(cr, P, P->legend_x, P->legend_y, 1);
}

typedef struct sink {
    FILE *f;
    int errnum;
} sink;

static cairo_status_t put(void *closure, const unsigned char *data, unsigned int length)
{
    sink *o = closure;
    if (fwrite(data, 1, length, o->f) != length) {
        if (!o->errnum) o->errnum = errno ? errno : EIO;
        return CAIRO_STATUS_WRITE_ERROR;
    }
    return CAIRO_STATUS_SUCCESS;
}

static int check(const bl_solution *s, const char *kind, const char *file, int *width,
                 bl_error *err)
{
    if (!s) return bl_error_set(err, "%s: no solution to draw", kind);
    if (!file) return bl_error_set(err, "%s: no file name", kind);
    if (*width < 0) return bl_error_set(err, "%s: width must be positive, got %d", kind, *width);
    if (*width == 0) *width = DEFAULT_WIDTH;
    return 0;
}

static int start(sink *o, const char *kind, const char *file, bl_error *err)
{
    o->errnum = 0;
    o->f = fopen(file, "wb");
    if (!o->f) return bl_error_set(err, "%s: cannot write '%s': %s", kind, file, strerror(errno));
    return 0;
}

/* Closes the file and reports the first failure.  A partial file is left
 * alone: removing it could remove a device or a link the user named. */
static int finish(sink *o, cairo_status_t st, const char *kind, const char *file, bl_error *err)
{
    if (fclose(o->f) != 0 && !o->errnum) o->errnum = errno ? errno : EIO;
    if (st == CAIRO_STATUS_SUCCESS && !o->errnum) return 0;
    const char *why = o->errnum ? strerror(o->errnum) : cairo_status_to_string(st);
    return bl_error_set(err, "%s: cannot write '%s': %s", kind, file, why);
}

int bl_draw_svg(const bl_solution *s, const char *file, int width, const bl_view *view,
                bl_error *err)
{
    if (check(s, "svg", file, &width, err)) return -1;
    pic P;
    layout(&P, s, width, view ? view->azimuth : BL_VIEW_AZIMUTH,
           view ? view->elevation : BL_VIEW_ELEVATION);
    sink o;
    if (start(&o, "svg", file, err)) return -1;
    cairo_surface_t *sf = cairo_svg_surface_create_for_stream(put, &o, P.w, P.h);
#if CAIRO_VERSION >= CAIRO_VERSION_ENCODE(1, 16, 0)
    /* the same numbers as the PNG: a browser shows both at the same size */
    cairo_svg_surface_set_document_unit(sf, CAIRO_SVG_UNIT_PX);
#endif
    cairo_t *cr = cairo_create(sf);
    draw(cr, &P);
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_finish(sf);
    if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_status(sf);
    cairo_surface_destroy(sf);
    return finish(&o, st, "svg", file, err);
}

int bl_draw_png(const bl_solution *s, const char *file, int width, const bl_view *view,
                bl_error *err)
{
    if (check(s, "png", file, &width, err)) return -1;
    if (width > PNG_MAX_SIDE)
        return bl_error_set(err, "png: width %d is larger than %d pixels", width, PNG_MAX_SIDE);
    pic P;
    layout(&P, s, width, view ? view->azimuth : BL_VIEW_AZIMUTH,
           view ? view->elevation : BL_VIEW_ELEVATION);
    if (P.h > PNG_MAX_SIDE)
        return bl_error_set(err, "png: picture height %.0f is larger than %d pixels", P.h,
                            PNG_MAX_SIDE);
    sink o;
    if (start(&o, "png", file, err)) return -1;
    cairo_surface_t *sf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)P.w, (int)P.h);
    cairo_t *cr = cairo_create(sf);
    draw(cr, &P);
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_write_to_png_stream(sf, put, &o);
    cairo_surface_destroy(sf);
    return finish(&o, st, "png", file, err);
}
