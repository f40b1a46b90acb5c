/* seqlp.h - non-associative friction by a sequence of LPs, with a
 * certificate (the seed's section 4; doc/theory.md, "The sequence of LPs").
 *
 * From the associative answer, each LP fixes the shear capacity of every
 * contact point from normal forces relaxed over the previous LPs (no
 * dilatancy); once alpha settles, a certificate LP looks for forces at that
 * alpha that fit the LP's mechanism under Coulomb's law.  Feasible: the
 * answer solves the seed's Eq. 12. */
#ifndef BL_SEQLP_H
#define BL_SEQLP_H

#include "assoc.h"

typedef struct bl_seqlp_options {
    bl_solve_options base; /* LP engine, tolerance, limits */
    double beta;           /* relaxation of the normal forces (0.7) */
    double settle;         /* |d alpha| <= settle alpha starts a certificate (1e-4) */
    double slip;           /* motions below slip x the largest count as zero (1e-4) */
    int max_lps;           /* cap on the LPs of one start (100) */
    int starts;            /* further starts from random stress states (Eq. 22);
                              < 0: BL_SEQLP_SEARCH on 2D models of at most
                              BL_SEQLP_SEARCH_ROWS rows, 3D ones of at most
                              BL_SEQLP_SEARCH_COLUMNS3 columns, and where unlimited
                              friction gives the associative alpha or the
                              rules of BL_SEQLP_MARGIN hold, else, on models
                              within those sizes, BL_SEQLP_PROBE (the rest
                              of the BL_SEQLP_SEARCH where they find a lower
                              answer), or up to BL_SEQLP_RETRIES
                              (BL_SEQLP_RETRIES_MEDIUM within those sizes)
                              until one certifies (then the same rules for
                              it), on models of at most BL_SEQLP_RETRY_ROWS
                              rows; after BL_SEQLP_SEARCH restarts (not the
                              small models' 20), BL_SEQLP_LOW_STARTS more at
                              a lower friction */
    unsigned long long seed; /* of those random states */
    int nearest;           /* after this many failed certificates of a start,
                              each further one is followed by the nearest
                              forces; 0: never; < 0: BL_SEQLP_NEAREST */
    int path;              /* start 0 from the point of the path of the
                              non-associative problem (napath.h) where it
                              applies, instead of the associative forces: 1
                              yes, 0 no, < 0 where the fixed LPs run on the
                              interior point */
    int progress;          /* after 0.5 s, one line on stderr kept up to date:
                              the associative LP's iteration (lp.h), the
                              path's step, then start, LP and alpha */
    int when_sliding;      /* solve's default: without a joint of finite, non-zero
                              friction, return the associative answer alone */
    int nmechanisms;       /* mechanisms given to try after the starts: */
    const double *mechanisms; /* nmechanisms after one another, each the
                              velocities of the blocks as bl_solution's u (of a
                              model with the same blocks), tried as a
                              certificate; the lowest certified alpha over the
                              starts and these is the answer */
} bl_seqlp_options;

void bl_seqlp_options_default(bl_seqlp_options *o);

/* By default a first start that ends without a certificate is followed by
 * further starts until one certifies, up to BL_SEQLP_RETRIES (and the
 * restarts of BL_SEQLP_MARGIN after it where its rules hold): whether a
 * start certifies within its LPs is close to chance on domes (one start
 * certified 4 of 6 and, with other round-off, 3 of 6; with the retries 6
 * and 5, doc/seqlp.md 14).  Only up to BL_SEQLP_RETRY_ROWS rows, where a
 * start takes seconds (a start of the 10,050-block wall takes minutes, and
 * none has certified it). */
#define BL_SEQLP_RETRIES 3
/* On models of the medium sizes (BL_SEQLP_MARGIN_ROWS,
 * BL_SEQLP_MARGIN_COLUMNS3), where a start takes seconds at most, up to
 * 10: an arcade of three bays, 124 blocks, at mu = 5 certified nothing
 * in start 0 and 3 retries, and 0.24020 in the 9th (6.5 s;
 * doc/seqlp.md 18). */
#define BL_SEQLP_RETRIES_MEDIUM 10

/* By default small models get BL_SEQLP_SEARCH_SMALL restarts, whatever
 * start 0 did: one start's answer is a solution, not always the lowest,
 * and on the walls W4 and W5 loaded towards -x start 0 certified 0.318207
 * and 0.227542 where 10 restarts reached 0.263736 and 0.209302, the +x
 * answers of the mirrored walls (doc/seqlp.md 2).  20 rather than 10
 * since half of them start from the least loaded states: over six seeds
 * 20 found W4's pier rocking at mu = 2, 5 and 100 in 16 of 18 runs (17
 * with the search friction of 1), 10 in 11, and W4 towards -x in 6 of 6
 * against 4 (doc/seqlp.md 17).  Larger
 * models get BL_SEQLP_SEARCH where start 0 certified the associative
 * answer or unlimited friction gives it (seqlp.c).  Up to
 * BL_SEQLP_SEARCH_ROWS rows (W4 165, W5 183) 10 restarts took 0.4-0.7 s
 * (20 of both kinds: 0.3-0.4 s at mu = 0.65, up to 2.8 s at mu = 100);
 * a 95-block wall of 315 rows took 3.2 s against 0.2 s.  3D models, whose
 * pyramids make LPs of many more columns per row, search up to
 * BL_SEQLP_SEARCH_COLUMNS3 columns (a few blocks: two unbonded leaves of
 * two blocks each, 193 columns, where start 0 certified 0.2222 and the
 * restarts their overturning at 0.2, in 0.03 s; a pier of 8 blocks, 577
 * columns, 0.13 s against 0.02 s); larger ones keep the rules below (W1
 * one block thick, 2,657 columns: 6.4 s against 0.3 s; a dome of 4 x 8,
 * 2,049: 140 s against 12 s). */
#define BL_SEQLP_SEARCH 10
#define BL_SEQLP_SEARCH_SMALL 20
#define BL_SEQLP_SEARCH_ROWS 300
#define BL_SEQLP_SEARCH_COLUMNS3 1000
#define BL_SEQLP_RETRY_ROWS 10000

/* Where start 0 and the BL_SEQLP_SEARCH_SMALL restarts of a small model
 * certified BL_SEQLP_VARIED or more different answers,
 * BL_SEQLP_SEARCH_VARIED more restarts follow.  So many solutions mark a search that has not seen them all: on
 * 108 runs (W1, W4, W5, a wall with lintels, a running bond of 8 x 8 and
 * a stack bond, mu = 0.65 to 1000, seeds 1-3) the 20 restarts missed the
 * lowest answer of 100 in 28, by up to 14.6 % (W4 at mu = 5, seed 2:
 * 0.30225 for 0.26374), and every miss had certified 4 or more answers;
 * 60 restarts missed 7, by at most 6.3 %.  At mu = 0.65 that held on W5
 * alone of the six, from mu = 1.2 on on nearly every run (doc/seqlp.md 18). */
#define BL_SEQLP_VARIED 4
#define BL_SEQLP_SEARCH_VARIED 40

/* Models up to BL_SEQLP_MARGIN_ROWS rows in 2D and
 * BL_SEQLP_MARGIN_COLUMNS3 columns in 3D get BL_SEQLP_SEARCH restarts too
 * where start 0 certified more than BL_SEQLP_MARGIN below a finite
 * associative alpha, or the associative alpha is within BL_SEQLP_MARGIN
 * of unlimited friction's (no rigid joints).  Where dilatancy carries that
 * much of the associative answer, or friction hardly bounds it, sliding
 * that dilatancy hides decides the mechanism, and one start's answer was
 * far from the lowest (W4 doubled each way at mu = 5, 660 rows: 0.4289
 * where 10 restarts certify 0.2307; a running bond of 16 x 16 at mu = 5,
 * 1.8951 where they certify 0.6462-0.6655; a running bond of 20 x 20 at
 * mu = 20, 2.2131 where they certify 0.7190, 0.6717 since a certificate is tried
 * before a sequence settles), while where neither held
 * restarts moved the answer by 0.5 % at most (doc/seqlp.md 18).  10
 * restarts took up to 45 s on a running bond of 12 x 12 (450 rows) and
 * 92-106 s on one of 32 x 32 (3,120 rows) for 0.3-3.3 %, hence the
 * bounds.  Not where the associative alpha is infinite (a wall locked
 * between abutments certifies its exact answer with one start).  Where
 * start 0 does not certify, the first retry that does (BL_SEQLP_RETRIES)
 * is held to the same rules, and to settling at the associative alpha: a
 * running bond of 16 x 16 at mu = 2 towards -x certified 0.6571 in its
 * second retry, and 10 restarts after it 0.6310. */
#define BL_SEQLP_MARGIN 0.1
#define BL_SEQLP_MARGIN_ROWS 2000
#define BL_SEQLP_MARGIN_COLUMNS3 10000

/* Where none of those rules holds on a model of that size, the default
 * runs BL_SEQLP_PROBE restarts, the first of those BL_SEQLP_SEARCH, and
 * the rest of them only where the probe certified more than
 * BL_SEQLP_PROBE_DROP below the answer it probed: a dome of 6 x 16 at
 * mu = 0.7 certified 0.4640 with one start, 0.961 of its associative
 * alpha and far from unlimited friction's, where its second restart
 * certifies 0.3723 (doc/seqlp.md 18). */
#define BL_SEQLP_PROBE 2
#define BL_SEQLP_PROBE_DROP 0.01

/* After a default search of BL_SEQLP_SEARCH restarts (not the small
 * models' BL_SEQLP_SEARCH_SMALL, where they found nothing more on W1, W4,
 * W5 and a running bond of 8 x 8), BL_SEQLP_LOW_STARTS more whose search
 * (stress state, fixed LPs) caps every finite friction at BL_SEQLP_LOW
 * times the highest (rigid joints as in start 0); the certificates hold
 * each joint to its own.  Lower friction lets the
 * search reach mechanisms that slide more, which can be solutions at the
 * model's own friction too: a façade 8 x 3 x 10 at mu = 0.7 certified
 * 0.23049 after 10 restarts and 0.15680 after these two; a façade
 * 4 x 2 x 4 at mu = 0.6, 0.30612 and 0.25164 (doc/seqlp.md 18). */
#define BL_SEQLP_LOW 0.5
#define BL_SEQLP_LOW_STARTS 2

/* The friction at which a rigid joint (mu = inf) slides in start 0's
 * search, its fixed LPs and stress states (not in the certificates, which
 * hold it rigid unless it carries nothing): an infinite one would never
 * let a joint that the previous LP left without normal force slide open,
 * and the sequence could not leave the associative answer, whose flow
 * rule forbids any slip even where a rigid joint opens (a pier beside a
 * wall it is not bonded to: associative alpha infinite, 1/3 without
 * dilatancy; doc/seqlp.md 16). */
#define BL_SEQLP_MU_RIGID 100.0

/* The restarts' friction in turn, two restarts at each (seqlp.c,
 * search_friction): rigid joints at it, the others at most at it
 * (doc/seqlp.md 16).  From 1: a search below the joints' friction finds
 * mechanisms whose sliding joints carry nothing, solutions at any higher
 * friction (W4 doubled each way at mu = 5: 0.2307 with 1, 0.2910 without;
 * doc/seqlp.md 17). */
#define BL_SEQLP_MU_TRIED {1.0, 3.0, 10.0, 30.0, 100.0}

/* A start whose certificates keep failing while alpha has settled is
 * caught in a slow mode of the relaxation (the 10,050-block wall: the
 * normal forces at the sliding points moved by 2-3 % per LP and none of
 * 100 LPs certified).  From its BL_SEQLP_NEAREST-th failed certificate on,
 * each failed certificate is followed by the nearest forces: the forces
 * at the LP's alpha that fit its mechanism but for the least total force
 * on the columns the certificate forbids, whose normal forces the next LP
 * takes whole.  Not after the first or second: the 2,525-block wall, whose
 * one failed certificate is followed by a passing one, took 34 LPs with it
 * against 19.  In 3D it certified in their first start the domes of 8 to
 * 12 rings that no start had certified, and took more starts on two of
 * six smaller ones (doc/seqlp.md 12, 14). */
#define BL_SEQLP_NEAREST 3

/* How far the path goes: until its products (over 1 + |alpha|) are at most
 * BL_SEQLP_PATH_PRODUCTS with its residuals below 1e-6, or
 * BL_SEQLP_PATH_STEPS Newton steps.  Closer is not always better: from the
 * path at products 3.5e-2 the 2,525-block wall certified after 2 fixed LPs,
 * from 6e-3 after 7, from a converged path after 2 (doc/seqlp.md 15). */
#define BL_SEQLP_PATH_PRODUCTS 1e-3
#define BL_SEQLP_PATH_STEPS 100
/* A path that stalls (or reaches its last step) this near is taken all the
 * same: from 55 to 80 courses of running bond it stalled at 1.7e-3 to
 * 2.4e-3 on three walls of seven, whose sequences then took 7-13 LPs
 * instead of 36-48; taken at 9.4e-3 (68 courses), 59 instead of 55
 * (doc/seqlp.md 15). */
#define BL_SEQLP_PATH_NEAR 3e-3
/* A path that reaches its target goes on to products of BL_SEQLP_PATH_DEEP
 * while they fall fast; from there the path's point is nearly a solution,
 * and start 0 begins at the path's alpha, so that its first LP settles and
 * its certificate follows at once: 29 of 30 running-bond walls of 16 to 36
 * courses got there in 2 to 16 more steps and certified after one fixed
 * LP, 140 LPs in all against 198, the sum of the answers 0.05 % lower
 * (doc/seqlp.md 15). */
#define BL_SEQLP_PATH_DEEP 1e-6
/* By default the path starts the sequence up to this many rows: at 10,050
 * blocks (30,150 rows) it stayed at products 0.4 for 100 steps (35 s), and
 * the sequence from there did not certify in 112 LPs; with the stall rule
 * it ends at step 37, products 0.45. */
#define BL_SEQLP_PATH_ROWS 20000

/* With lp = "auto", a 3D fixed LP of more columns than this and 5 per
 * row runs on the interior point, where any other LP of its size would
 * take the simplex (lp.h): re-solved after its bounds change, the simplex
 * took about 1,000 pivots per LP on 200 rows (W1 in 3D at mu = 2: 348,559
 * for 327 LPs, 16 s, against 1.6 s; a vault of 36 voussoirs pushed along
 * its axis 26 s against 1.5 s); the pier of 72 rows and 561 columns keeps
 * the simplex, 0.5 s against 1.6 s (doc/seqlp.md 18). */
#define BL_SEQLP_IPM_COLUMNS3 1000

/* The pyramid the 3D sequence of LPs (and the direct solve) runs on: the
 * one asked for when it has an even number of facets (its section at n is
 * then the fixed form's polygon of shears), else the 8-facet inscribed one. */
bl_cone bl_seqlp_pyramid(const bl_cone *asked);

/* As bl_assoc_solve; the solution's alpha is the certified non-associative
 * multiplier, alpha_assoc the associative one, and status BL_UNCERTIFIED
 * when the cap came first.  With when_sliding, a model whose joints cannot
 * slide (no friction, or unlimited friction: both flow rules give the same
 * answer) gets the associative solution, method "assoc". */
int bl_seqlp_solve(bl_model *m, const bl_seqlp_options *o, bl_solution **out, bl_error *err);

#endif
