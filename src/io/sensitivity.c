/* Spearman's rank correlation (sensitivity.h): the Pearson correlation of
 * the ranks of x and of y. It measures how consistently an output rises
 * (or falls) with a key, whatever the shape of the relation, and is
 * unaffected by the keys' units and ranges, so the keys of a sweep can be
 * ranked by it. For a grid (every combination) and a Latin hypercube (the
 * keys' columns nearly uncorrelated) each key's coefficient is its own
 * influence, not another key's carried along. It does not see a relation
 * that rises and falls again, nor the keys' interactions. */
#include "io/sensitivity.h"

#include <math.h>
#include <stdlib.h>

typedef struct pair {
    double v;
    size_t i;
} pair;

static int by_value(const void *a, const void *b)
{
    const pair *p = a, *q = b;
    if (p->v != q->v)
        return p->v < q->v ? -1 : 1;
    return (p->i > q->i) - (p->i < q->i);
}

/* rank[i] of v[i] among n, 1-based, ties at their mean rank */
static void ranks(const double *v, size_t n, pair *scratch, double *rank)
{
    for (size_t i = 0; i < n; i++)
        scratch[i] = (pair){v[i], i};
    qsort(scratch, n, sizeof *scratch, by_value);
    for (size_t a = 0; a < n;) {
        size_t b = a + 1;
        while (b < n && scratch[b].v == scratch[a].v)
            b++;
        double mean = 0.5 * (double)(a + 1 + b);   /* mean of a+1 .. b */
        for (size_t k = a; k < b; k++)
            rank[scratch[k].i] = mean;
        a = b;
    }
}

double bd_spearman(const double *x, const double *y, size_t n)
{
    double *buf = malloc(4 * (n > 0 ? n : 1) * sizeof *buf);
    pair *scratch = malloc((n > 0 ? n : 1) * sizeof *scratch);
    if (!buf || !scratch) {
        free(buf);
        free(scratch);
        return NAN;
    }
    double *xs = buf, *ys = buf + n, *rx = buf + 2 * n, *ry = buf + 3 * n;
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(x[i]) && isfinite(y[i])) {
            xs[m] = x[i];
            ys[m++] = y[i];
        }
    double rho = NAN;
    if (m >= 3) {
        ranks(xs, m, scratch, rx);
        ranks(ys, m, scratch, ry);
        double mean = 0.5 * (double)(m + 1), sxy = 0.0, sxx = 0.0, syy = 0.0;
        for (size_t i = 0; i < m; i++) {
            double a = rx[i] - mean, b = ry[i] - mean;
            sxy += a * b;
            sxx += a * a;
            syy += b * b;
        }
        if (sxx > 0.0 && syy > 0.0)
            rho = sxy / sqrt(sxx * syy);
    }
    free(buf);
    free(scratch);
    return rho;
}
