
/* normal.c - the normal matrix F F^T + delta I of the interior-point engine
 * (normal.h), on CHOLMOD.
 *
 * Small matrices: one supernodal factorization in CHOLMOD's METIS order.
 * Large ones: a vertex separator S of the graph of F F^T (METIS, through
 * cholmod_bisect) splits the rows into two domains P0 and P1 that share no
 * column of F.  Each domain k is factored with the separator's rows last,
 *
 *     [M_kk  M_kS ]          [L_kk   0 ] [L_kk   0 ]^T
 *     [M_Sk  M^k_SS] + dI  =  [L_Sk  T_k] [L_Sk  T_k]  ,
 *
 * where M^k_SS sums only the columns of domain k, so that the whole matrix
 * has the factor [L_00 0 0; 0 L_11 0; L_S0 L_S1 L_SS] with
 *
 *     L_SS L_SS^T = T_0 T_0^T + T_1 T_1^T - dI     (dense, ns x ns).
 *
 * The two domains are factored, and their triangular solves run, on two
 * threads at once; only the small dense separator is serial.  A solve is
 * a forward solve of each domain with zero on its separator rows (which
 * leaves w_k with T_k w_k = -L_Sk y_k), the separator's dense solve, and a
 * backward solve of each domain with T_k^T x_S on its separator rows.
 */
#include <math.h>
#include <omp.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <suitesparse/cholmod.h>

#include "lp_engine.h"
#include "normal.h"

/* BLAS and LAPACK */
void dlauum_(const char *uplo, const int *n, double *a, const int *lda, int *info);
void dtrmv_(const char *uplo, const char *trans, const char *diag, const int *n, const double *a,
            const int *lda, double *x, const int *incx);
void dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info);
void dpotrs_(const char *uplo, const int *n, const int *nrhs, const double *a, const int *lda,
             double *b, const int *ldb, int *info);

/* One CHOLMOD factorization: of the whole matrix, or of one domain with
 * the separator's ns rows last. */
typedef struct part {
    cholmod_common cm;
    int nrow, ns;
    cholmod_sparse *F, *Ft; /* rows in the factor's order */
    int *col;               /* column of F here -> column of the whole F */
    int *ft_src;            /* entry of Ft -> entry of F */
    int *row;               /* factor position -> row of the whole matrix */
    cholmod_factor *L;
    double *b;              /* nrow: a right-hand side in the factor's order */
    double *T, *W, *z;      /* the separator's block of L (ns x ns), T T^T reversed, T w */
    double *u;              /* the rows of L's largest supernode */
    int status;             /* of the last factorization: 0, 1 (not positive definite), -1 */
    double fmax;
} part;

struct bl_normal {
    bl_normal_pattern A;
    int nparts, ns;
    part p[2];
    int *srow;              /* the separator's rows, in the order of both domains */
    double *S;              /* ns x ns: L_SS L_SS^T, then L_SS */
    double *r;              /* ns */
};

static void part_free(part *P)
{
    if (!P->nrow) return;
    cholmod_free_sparse(&P->F, &P->cm);
    cholmod_free_sparse(&P->Ft, &P->cm);
    cholmod_free_factor(&P->L, &P->cm);
    cholmod_finish(&P->cm);
    free(P->col);
    free(P->ft_src);
    free(P->row);
    free(P->b);
    free(P->T);
    free(P->W);
    free(P->z);
    free(P->u);
    memset(P, 0, sizeof *P);
}

void bl_normal_free(bl_normal *N)
{
    if (!N) return;
    part_free(&N->p[0]);
    part_free(&N->p[1]);
    free(N->srow);
    free(N->S);
    free(N->r);
    free(N);
}

/* Builds part P from nrow rows of the whole matrix (loc: whole row ->
 * local index or -1; glob: local index -> whole row) and ncols columns of
 * the whole F.  perm: the factor order of the local rows, or NULL for
 * CHOLMOD's METIS order.  Returns 0 or -1. */
static int part_build(part *P, const bl_normal_pattern *A, const int *loc, const int *glob,
                      int nrow, int ns, const int *cols, int ncols, int *perm)
{
    cholmod_start(&P->cm);
    P->nrow = nrow;
    P->ns = ns;
    P->cm.print = 0;
    P->cm.error_handler = NULL;
    P->cm.supernodal = CHOLMOD_SUPERNODAL;
    P->cm.nmethods = 1;
    P->cm.method[0].ordering = perm ? CHOLMOD_GIVEN : CHOLMOD_METIS;
    P->cm.postorder = perm == NULL;
    P->cm.quick_return_if_not_posdef = 1;
    size_t nnz = 0;
    for (int c = 0; c < ncols; c++) {
        int j = A->map[cols[c]];
        nnz += (size_t)(A->colptr[j + 1] - A->colptr[j]);
    }
    /* the entries of a column keep A's order: CHOLMOD's analysis and
     * cholmod_super_numeric take unsorted columns */
    P->F = cholmod_allocate_sparse((size_t)nrow, (size_t)ncols, nnz, 0, 1, 0, CHOLMOD_REAL, &P->cm);
    P->col = malloc((size_t)(ncols ? ncols : 1) * sizeof *P->col);
    P->row = malloc((size_t)nrow * sizeof *P->row);
    P->b = malloc(2 * (size_t)nrow * sizeof *P->b);
    if (!P->F || !P->col || !P->row || !P->b) return -1;
    int *Fp = P->F->p, *Fi = P->F->i, q = 0;
    for (int c = 0; c < ncols; c++) {
        int j = A->map[cols[c]];
        P->col[c] = cols[c];
        Fp[c] = q;
        for (int t = A->colptr[j]; t < A->colptr[j + 1]; t++) Fi[q++] = loc[A->rowind[t]];
    }
    Fp[ncols] = q;
    P->L = cholmod_analyze_p(P->F, perm, NULL, 0, &P->cm);
    if (!P->L) return -1;

    /* F's rows in the factor's order, and the pattern of its transpose */
    const int *Perm = P->L->Perm;
    int *inv = malloc((size_t)nrow * sizeof *inv);
    P->Ft = cholmod_allocate_sparse((size_t)ncols, (size_t)nrow, nnz, 0, 1, 0, CHOLMOD_REAL,
                                    &P->cm);
    P->ft_src = malloc((nnz ? nnz : 1) * sizeof *P->ft_src);
    if (!inv || !P->Ft || !P->ft_src) {
        free(inv);
        return -1;
    }
    for (int i = 0; i < nrow; i++) {
        inv[Perm[i]] = i;
        P->row[i] = glob[Perm[i]];
    }
    int *Tp = P->Ft->p, *Ti = P->Ft->i;
    memset(Tp, 0, (size_t)(nrow + 1) * sizeof *Tp);
    for (int t = 0; t < q; t++) {
        Fi[t] = inv[Fi[t]];
        Tp[Fi[t] + 1]++;
    }
    for (int i = 0; i < nrow; i++) Tp[i + 1] += Tp[i];
    memcpy(inv, Tp, (size_t)nrow * sizeof *inv); /* next free slot per row */
    for (int c = 0; c < ncols; c++)
        for (int t = Fp[c]; t < Fp[c + 1]; t++) {
            int u = inv[Fi[t]]++;
            Ti[u] = c;
            P->ft_src[u] = t;
        }
    free(inv);
    const int *pi = P->L->pi;
    int umax = 1;
    for (size_t s = 0; s < P->L->nsuper; s++)
        if (pi[s + 1] - pi[s] > umax) umax = pi[s + 1] - pi[s];
    P->u = malloc(2 * (size_t)umax * sizeof *P->u);
    if (!P->u) return -1;
    if (ns > 0) {
        size_t ss = (size_t)ns * (size_t)ns;
        P->T = malloc(ss * sizeof *P->T);
        P->W = malloc(ss * sizeof *P->W);
        P->z = malloc(2 * (size_t)ns * sizeof *P->z);
        if (!P->T || !P->W || !P->z) return -1;
    }
    return 0;
}

/* The split: a vertex separator and a domain per side, each ordered by
 * METIS with the separator last.  Returns 0, or -1 when the matrix does
 * not split well (the caller then factors it whole). */
static int split(bl_normal *N)
{
    const bl_normal_pattern *A = &N->A;
    int m = A->m, n = A->n, ret = -1;
    int *side = malloc((size_t)m * sizeof *side), *dom = malloc((size_t)n * sizeof *dom);
    int *loc = malloc((size_t)m * sizeof *loc), *glob = malloc((size_t)m * sizeof *glob);
    int *cols = malloc((size_t)n * sizeof *cols), *perm = malloc((size_t)m * sizeof *perm);
    cholmod_common cm;
    cholmod_start(&cm);
    cm.error_handler = NULL;
    cholmod_sparse *G = NULL;
    if (!side || !dom || !loc || !glob || !cols || !perm) goto done;

    /* the pattern of the whole F, for the separator */
    size_t nnz = 0;
    for (int k = 0; k < n; k++) nnz += (size_t)(A->colptr[A->map[k] + 1] - A->colptr[A->map[k]]);
    G = cholmod_allocate_sparse((size_t)m, (size_t)n, nnz, 0, 1, 0, CHOLMOD_PATTERN, &cm);
    if (!G) goto done;
    int *Gp = G->p, *Gi = G->i, q = 0;
    for (int k = 0; k < n; k++) {
        Gp[k] = q;
        for (int t = A->colptr[A->map[k]]; t < A->colptr[A->map[k] + 1]; t++) Gi[q++] = A->rowind[t];
    }
    Gp[n] = q;
    long ns = cholmod_bisect(G, NULL, 0, 1, side, &cm);
    if (ns <= 0 || ns > m / 10) goto done;

    /* every column lies in one domain (and the separator); columns on the
     * separator alone go to domain 0 */
    int count[2] = {0, 0};
    for (int k = 0; k < n; k++) {
        dom[k] = -1;
        for (int t = Gp[k]; t < Gp[k + 1]; t++) {
            int s = side[Gi[t]];
            if (s == 2) continue;
            if (dom[k] >= 0 && dom[k] != s) goto done; /* not a separator */
            dom[k] = s;
        }
        if (dom[k] < 0) dom[k] = 0;
        count[dom[k]]++;
    }
    N->ns = (int)ns;
    N->srow = malloc((size_t)ns * sizeof *N->srow);
    N->S = malloc((size_t)ns * (size_t)ns * sizeof *N->S);
    N->r = malloc(2 * (size_t)ns * sizeof *N->r);
    if (!N->srow || !N->S || !N->r) goto done;
    for (int i = 0, s = 0; i < m; i++)
        if (side[i] == 2) N->srow[s++] = i;

    for (int d = 0; d < 2; d++) {
        /* local rows: the domain's in order, then the separator's */
        int nd = 0;
        for (int i = 0; i < m; i++) {
            loc[i] = side[i] == d ? nd : -1;
            if (side[i] == d) glob[nd++] = i;
        }
        if (nd == 0 || count[d] == 0) goto done;
        for (int s = 0; s < ns; s++) {
            loc[N->srow[s]] = nd + s;
            glob[nd + s] = N->srow[s];
        }
        int nc = 0;
        for (int k = 0; k < n; k++)
            if (dom[k] == d) cols[nc++] = k;
        /* METIS on the domain's own rows (the separator's dropped) */
        cholmod_sparse *D = cholmod_allocate_sparse((size_t)nd, (size_t)nc, nnz, 0, 1, 0,
                                                    CHOLMOD_PATTERN, &cm);
        if (!D) goto done;
        int *Dp = D->p, *Di = D->i, e = 0;
        for (int c = 0; c < nc; c++) {
            Dp[c] = e;
            for (int t = Gp[cols[c]]; t < Gp[cols[c] + 1]; t++)
                if (side[Gi[t]] == d) Di[e++] = loc[Gi[t]];
        }
        Dp[nc] = e;
        int ok = cholmod_metis(D, NULL, 0, 1, perm, &cm);
        cholmod_free_sparse(&D, &cm);
        if (!ok) goto done;
        for (int s = 0; s < ns; s++) perm[nd + s] = nd + s;
        if (part_build(&N->p[d], A, loc, glob, nd + (int)ns, (int)ns, cols, nc, perm)) goto done;
        /* the analysis kept the given order: the separator's rows are last */
        for (int s = 0; s < ns; s++)
            if (N->p[d].row[nd + s] != N->srow[s]) goto done;
    }
    N->nparts = 2;
    ret = 0;
done:
    cholmod_free_sparse(&G, &cm);
    cholmod_finish(&cm);
    free(side);
    free(dom);
    free(loc);
    free(glob);
    free(cols);
    free(perm);
    return ret;
}

bl_normal *bl_normal_analyse(const bl_normal_pattern *A, int threads, int verbose, bl_error *err)
{
    bl_normal *N = calloc(1, sizeof *N);
    if (!N) {
        bl_error_set(err, "lp: out of memory");
        return NULL;
    }
    N->A = *A;
    if (threads >= 2 && A->m >= BL_IPM_SPLIT_ROWS && split(N) != 0) {
        part_free(&N->p[0]);
        part_free(&N->p[1]);
        free(N->srow);
        free(N->S);
        free(N->r);
        N->srow = NULL;
        N->S = N->r = NULL;
        N->ns = 0;
    }
    if (N->nparts == 0) {
        int m = A->m, n = A->n;
        int *id = malloc((size_t)(m > n ? m : n) * sizeof *id);
        int fail = !id;
        if (!fail) {
            for (int i = 0; i < (m > n ? m : n); i++) id[i] = i;
            fail = part_build(&N->p[0], A, id, id, m, 0, id, n, NULL) != 0;
        }
        free(id);
        if (fail) {
            bl_normal_free(N);
            bl_error_set(err, "lp: CHOLMOD could not analyse the normal matrix (out of memory?)");
            return NULL;
        }
        N->nparts = 1;
    }
    if (verbose) {
        if (N->nparts == 2)
            fprintf(stderr, "ipm: normal matrix split into domains of %d and %d rows, separator %d\n",
                    N->p[0].nrow - N->ns, N->p[1].nrow - N->ns, N->ns);
        fprintf(stderr, "ipm: %d rows, %d columns; factor %.0f non-zeros, %.3g flops\n", A->m, A->n,
                bl_normal_nnz(N), bl_normal_flops(N));
    }
    return N;
}

int bl_normal_domains(const bl_normal *N) { return N->nparts; }

double bl_normal_nnz(const bl_normal *N)
{
    double s = (double)N->ns;
    double nnz = N->p[0].cm.lnz + (N->nparts == 2 ? N->p[1].cm.lnz - s * (s + 1) / 2 : 0.0);
    return nnz;
}

double bl_normal_flops(const bl_normal *N)
{
    /* two domains: theirs, two T T^T (dlauum) and L_SS (dpotrf), s^3 / 3 each */
    double s = (double)N->ns;
    return N->p[0].cm.fl + (N->nparts == 2 ? N->p[1].cm.fl + s * s * s : 0.0);
}

static void part_fill(part *P, const bl_normal_pattern *A, const double *scale)
{
    const int *Fp = P->F->p;
    double *Fx = P->F->x, *Tx = P->Ft->x, fmax = 0.0;
    for (int c = 0; c < (int)P->F->ncol; c++) {
        double s = scale[P->col[c]];
        const double *a = A->val + A->colptr[A->map[P->col[c]]] - Fp[c];
        for (int q = Fp[c]; q < Fp[c + 1]; q++) {
            Fx[q] = a[q] * s;
            fmax = fmax > Fx[q] * Fx[q] ? fmax : Fx[q] * Fx[q];
        }
    }
    for (int t = 0, nnz = Fp[P->F->ncol]; t < nnz; t++) Tx[t] = Fx[P->ft_src[t]];
    P->fmax = fmax;
}

double bl_normal_fill(bl_normal *N, const double *scale)
{
#pragma omp parallel for num_threads(N->nparts) schedule(static, 1)
    for (int k = 0; k < N->nparts; k++) part_fill(&N->p[k], &N->A, scale);
    return N->nparts == 2 ? fmax(N->p[0].fmax, N->p[1].fmax) : N->p[0].fmax;
}

/* Copies the separator's block of L (its last ns rows and columns) into
 * T (column-major, lower triangle; the upper one zero). */
static void separator_block(part *P)
{
    const cholmod_factor *L = P->L;
    const int *super = L->super, *pi = L->pi, *px = L->px, *Ls = L->s;
    const double *Lx = L->x;
    int ns = P->ns, off = P->nrow - ns;
    memset(P->T, 0, (size_t)ns * (size_t)ns * sizeof *P->T);
    for (size_t s = 0; s < L->nsuper; s++) {
        int k1 = super[s], k2 = super[s + 1], nr = pi[s + 1] - pi[s];
        if (k2 <= off) continue;
        for (int j = k1 > off ? k1 : off; j < k2; j++)
            for (int i = j - k1; i < nr; i++) {
                int r = Ls[pi[s] + i];
                P->T[(size_t)(r - off) + (size_t)(j - off) * (size_t)ns] =
                    Lx[(size_t)px[s] + (size_t)i + (size_t)(j - k1) * (size_t)nr];
            }
    }
}

static void part_factor(part *P, double delta)
{
    double beta[2] = {delta, 0.0};
    P->cm.status = CHOLMOD_OK;
    cholmod_super_numeric(P->F, P->Ft, beta, P->L, &P->cm);
    P->status = P->cm.status < 0 ? -1
                : P->cm.status == CHOLMOD_OK && P->L->minor == P->L->n ? 0
                                                                        : 1;
    if (P->status == 0 && P->ns > 0) {
        /* T T^T in a third of dsyrk's flops: with J the reversal, U = J T J
         * is upper triangular and LAPACK's dlauum forms U U^T = J T T^T J */
        int ns = P->ns, info;
        separator_block(P);
        for (int j = 0; j < ns; j++)
            for (int i = j; i < ns; i++)
                P->W[(size_t)(ns - 1 - i) + (size_t)(ns - 1 - j) * (size_t)ns] =
                    P->T[(size_t)i + (size_t)j * (size_t)ns];
        dlauum_("U", &ns, P->W, &ns, &info);
    }
}

/* The second domain's factorization, on a thread of its own. */
typedef struct factor_job {
    part *P;
    double delta;
} factor_job;

static void *factor_thread(void *arg)
{
    factor_job *j = arg;
    omp_set_max_active_levels(0); /* this thread's own setting */
    part_factor(j->P, j->delta);
    return NULL;
}

int bl_normal_factor(bl_normal *N, double delta)
{
    int np = N->nparts, ns = N->ns;
    /* CHOLMOD's own OpenMP regions stay serial (doc/performance.md,
     * "Threads") and outside any parallel region, where gomp_serial.c
     * runs them as plain calls: the second domain is factored on a POSIX
     * thread, not in an OpenMP team (nested in one, each of CHOLMOD's
     * regions cost a futex call: 27,000 per iteration at 10,050 blocks) */
    omp_set_max_active_levels(0);
    factor_job second = {&N->p[1], delta};
    pthread_t other;
    int started = np == 2 && pthread_create(&other, NULL, factor_thread, &second) == 0;
    part_factor(&N->p[0], delta);
    if (started) pthread_join(other, NULL);
    else if (np == 2) part_factor(&N->p[1], delta); /* no thread to be had */
    omp_set_max_active_levels(1);
    for (int k = 0; k < np; k++)
        if (N->p[k].status < 0) return -1;
    for (int k = 0; k < np; k++)
        if (N->p[k].status > 0) return 1;
    if (np == 1) return 0;
    const double *W0 = N->p[0].W, *W1 = N->p[1].W;
    for (int j = 0; j < ns; j++) {
        size_t c = (size_t)j * (size_t)ns;
        for (int i = j; i < ns; i++) {
            /* (T T^T)(i, j) = W(ns-1-i, ns-1-j), in W's upper triangle */
            size_t w = (size_t)(ns - 1 - i) + (size_t)(ns - 1 - j) * (size_t)ns;
            N->S[c + (size_t)i] = W0[w] + W1[w];
        }
        N->S[c + (size_t)j] -= delta;
    }
    int info = 0;
    dpotrf_("L", &ns, N->S, &ns, &info);
    return info == 0 ? 0 : info > 0 ? 1 : -1;
}

/* x = L^-1 x over the supernodes of L, in the factor's order, for nrhs
 * (1 or 2) vectors of length ld one after the other: each supernode's rows
 * gathered into u (nrhs times L's largest supernode) and its block of L
 * read once for both.  By hand rather than through cholmod_solve2: its
 * many small BLAS calls serialize on OpenBLAS's buffer lock when the two
 * domains solve at once (each domain took 1.8 ms instead of 1.0 ms at
 * 10,050 blocks). */
static void lsolve(const cholmod_factor *L, double *x, double *u, int nrhs, size_t ld)
{
    const int *super = L->super, *pi = L->pi, *px = L->px, *Ls = L->s;
    for (size_t s = 0; s < L->nsuper; s++) {
        int k1 = super[s], nc = super[s + 1] - k1, nr = pi[s + 1] - pi[s];
        const int *rows = Ls + pi[s];
        const double *a = (const double *)L->x + px[s];
        double *u0 = u, *u1 = u + nr;
        for (int r = 0; r < nrhs; r++) {
            memcpy(u + r * nr, x + r * ld + k1, (size_t)nc * sizeof *u);
            memset(u + r * nr + nc, 0, (size_t)(nr - nc) * sizeof *u);
        }
        for (int j = 0; j < nc; j++, a += nr) {
            double v0 = u0[j] /= a[j];
            if (nrhs == 1) {
#pragma omp simd
                for (int i = j + 1; i < nr; i++) u0[i] -= a[i] * v0;
            } else {
                double v1 = u1[j] /= a[j];
#pragma omp simd
                for (int i = j + 1; i < nr; i++) {
                    u0[i] -= a[i] * v0;
                    u1[i] -= a[i] * v1;
                }
            }
        }
        for (int r = 0; r < nrhs; r++) {
            double *xr = x + r * ld, *ur = u + r * nr;
            memcpy(xr + k1, ur, (size_t)nc * sizeof *u);
            for (int i = nc; i < nr; i++) xr[rows[i]] += ur[i];
        }
    }
}

/* x = L^-T x, the same way backwards.  Each column's dot product with the
 * rows below it is a chain of dependent additions, so the columns go in
 * blocks of LT_BLOCK from the last: first the rows below the block, all
 * solved already, four columns at a time (one rhs) or two (two), which
 * makes four independent chains; then the block's own triangle.  One
 * column at a time took 2.4 times as long as the forward solve
 * (doc/performance.md). */
#define LT_BLOCK 16
static void ltsolve(const cholmod_factor *L, double *x, double *u, int nrhs, size_t ld)
{
    const int *super = L->super, *pi = L->pi, *px = L->px, *Ls = L->s;
    for (size_t s = L->nsuper; s-- > 0;) {
        int k1 = super[s], nc = super[s + 1] - k1, nr = pi[s + 1] - pi[s];
        const int *rows = Ls + pi[s];
        const double *A = (const double *)L->x + px[s];
        double *u0 = u, *u1 = u + nr;
        for (int r = 0; r < nrhs; r++)
            for (int i = 0; i < nr; i++) u[r * nr + i] = x[r * ld + (size_t)rows[i]];
        for (int je = nc, jb; je > 0; je = jb) {
            jb = je > LT_BLOCK ? je - LT_BLOCK : 0;
            int j = jb;
            if (nrhs == 1) {
                for (; j + 4 <= je; j += 4) {
                    const double *a0 = A + (size_t)j * (size_t)nr, *a1 = a0 + nr, *a2 = a1 + nr,
                                 *a3 = a2 + nr;
                    double v0 = 0.0, v1 = 0.0, v2 = 0.0, v3 = 0.0;
#pragma omp simd reduction(+ : v0, v1, v2, v3)
                    for (int i = je; i < nr; i++) {
                        v0 += a0[i] * u0[i];
                        v1 += a1[i] * u0[i];
                        v2 += a2[i] * u0[i];
                        v3 += a3[i] * u0[i];
                    }
                    u0[j] -= v0;
                    u0[j + 1] -= v1;
                    u0[j + 2] -= v2;
                    u0[j + 3] -= v3;
                }
            } else {
                for (; j + 2 <= je; j += 2) {
                    const double *a0 = A + (size_t)j * (size_t)nr, *a1 = a0 + nr;
                    double v00 = 0.0, v01 = 0.0, v10 = 0.0, v11 = 0.0;
#pragma omp simd reduction(+ : v00, v01, v10, v11)
                    for (int i = je; i < nr; i++) {
                        v00 += a0[i] * u0[i];
                        v01 += a0[i] * u1[i];
                        v10 += a1[i] * u0[i];
                        v11 += a1[i] * u1[i];
                    }
                    u0[j] -= v00;
                    u1[j] -= v01;
                    u0[j + 1] -= v10;
                    u1[j + 1] -= v11;
                }
            }
            for (; j < je; j++)
                for (int r = 0; r < nrhs; r++) {
                    const double *a = A + (size_t)j * (size_t)nr;
                    double *ur = u + r * nr, v = 0.0;
#pragma omp simd reduction(+ : v)
                    for (int i = je; i < nr; i++) v += a[i] * ur[i];
                    ur[j] -= v;
                }
            /* the block's triangle */
            for (j = je - 1; j >= jb; j--)
                for (int r = 0; r < nrhs; r++) {
                    const double *a = A + (size_t)j * (size_t)nr;
                    double *ur = u + r * nr, v = 0.0;
                    for (int i = j + 1; i < je; i++) v += a[i] * ur[i];
                    ur[j] = (ur[j] - v) / a[j];
                }
        }
        for (int r = 0; r < nrhs; r++) memcpy(x + r * ld + k1, u + r * nr, (size_t)nc * sizeof *u);
    }
}

/* Forward: [y; w] = L^-1 [rhs on the domain's rows; 0], z = T w, for each
 * of the nrhs right-hand sides. */
static void forward(part *P, double *const *rhs, int nrhs)
{
    int ns = P->ns, off = P->nrow - ns, one = 1;
    size_t ld = (size_t)P->nrow;
    for (int r = 0; r < nrhs; r++) {
        double *b = P->b + r * ld;
        for (int i = 0; i < off; i++) b[i] = rhs[r][P->row[i]];
        memset(b + off, 0, (size_t)ns * sizeof *b);
    }
    lsolve(P->L, P->b, P->u, nrhs, ld);
    for (int r = 0; r < nrhs; r++) {
        double *z = P->z + r * ns;
        memcpy(z, P->b + r * ld + off, (size_t)ns * sizeof *z);
        dtrmv_("L", "N", "N", &ns, P->T, &ns, z, &one);
    }
}

/* Backward: x = L^-T [y; T^T x_S], onto the domain's rows of rhs. */
static void backward(part *P, const double *xs, double *const *rhs, int nrhs)
{
    int ns = P->ns, off = P->nrow - ns, one = 1;
    size_t ld = (size_t)P->nrow;
    for (int r = 0; r < nrhs; r++) {
        double *b = P->b + r * ld + off;
        memcpy(b, xs + r * ns, (size_t)ns * sizeof *b);
        dtrmv_("L", "T", "N", &ns, P->T, &ns, b, &one);
    }
    ltsolve(P->L, P->b, P->u, nrhs, ld);
    for (int r = 0; r < nrhs; r++)
        for (int i = 0; i < off; i++) rhs[r][P->row[i]] = P->b[r * ld + i];
}

int bl_normal_solve(bl_normal *N, double *const *rhs, int nrhs)
{
    if (N->nparts == 1) {
        part *P = &N->p[0];
        const int *perm = P->L->Perm;
        size_t ld = (size_t)P->nrow;
        for (int r = 0; r < nrhs; r++)
            for (int i = 0; i < P->nrow; i++) P->b[r * ld + i] = rhs[r][perm[i]];
        lsolve(P->L, P->b, P->u, nrhs, ld);
        ltsolve(P->L, P->b, P->u, nrhs, ld);
        for (int r = 0; r < nrhs; r++)
            for (int i = 0; i < P->nrow; i++) rhs[r][perm[i]] = P->b[r * ld + i];
        return 0;
    }
    int ns = N->ns, info = 0;
#pragma omp parallel for num_threads(2) schedule(static, 1)
    for (int k = 0; k < 2; k++) forward(&N->p[k], rhs, nrhs);
    for (int r = 0; r < nrhs; r++)
        for (int s = 0; s < ns; s++)
            N->r[r * ns + s] = rhs[r][N->srow[s]] + N->p[0].z[r * ns + s] + N->p[1].z[r * ns + s];
    dpotrs_("L", &ns, &nrhs, N->S, &ns, N->r, &ns, &info);
    if (info) return -1;
#pragma omp parallel for num_threads(2) schedule(static, 1)
    for (int k = 0; k < 2; k++) backward(&N->p[k], N->r, rhs, nrhs);
    for (int r = 0; r < nrhs; r++)
        for (int s = 0; s < ns; s++) rhs[r][N->srow[s]] = N->r[r * ns + s];
    return 0;
}
