/* The values of a sweep's cases (sweep.h): a grid over the keys of
 * --vary, or a Latin hypercube sample over the keys of --range.
 *
 * Latin hypercube (McKay, Beckman & Conover 1979): each key's range is cut
 * into N equal strata; key k takes stratum π_k(i) in case i, π_k a random
 * permutation, at a uniform random point inside it:
 *   x_ik = lo_k + (hi_k − lo_k)·(π_k(i) + u_ik)/N.
 * Every key then covers its whole range once per stratum with N cases
 * however many keys there are. The random numbers are splitmix64 (Steele,
 * Lea & Flood 2014) from the seed, drawn key by key (the permutation by
 * Fisher–Yates, then the N offsets), so a seed gives the same cases on
 * every machine and every rank. */
#include "study/sweep.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* a number that is the whole of s; 0 ok */
static int number(const char *s, double *x)
{
    char *end;
    if (!*s)
        return -1;
    *x = strtod(s, &end);
    return *end == '\0' && isfinite(*x) ? 0 : -1;
}

int bd_study_parse_range(const char *text, int with_n, bd_study_range *out, char *err,
                         size_t errlen)
{
    const char *form = with_n ? "KEY=LO:HI:N" : "KEY=LO:HI";
    const char *eq = strrchr(text, '=');
    memset(out, 0, sizeof *out);
    if (!eq || eq == text || (size_t)(eq - text) >= sizeof out->key) {
        snprintf(err, errlen, "'%s': expected %s, e.g. %s", text, form,
                 with_n ? "pulleys.takeup.takeup.mass=1000:3000:5"
                        : "belt.axial_stiffness=2e7:4e7");
        return -1;
    }
    memcpy(out->key, text, (size_t)(eq - text));
    out->key[eq - text] = '\0';
    char buf[256], *part[4];
    snprintf(buf, sizeof buf, "%s", eq + 1);
    int n = 0;
    for (char *p = buf; n < 4; n++) {
        part[n] = p;
        char *c = strchr(p, ':');
        if (!c) {
            n++;
            break;
        }
        *c = '\0';
        p = c + 1;
    }
    double nv = 0.0;
    if (n != (with_n ? 3 : 2) || number(part[0], &out->lo) || number(part[1], &out->hi)
        || (with_n && (number(part[2], &nv) || nv != floor(nv) || nv < 1 || nv > 100000))) {
        snprintf(err, errlen, "'%s': expected %s with numbers LO and HI%s", text, form,
                 with_n ? " and a whole number of points N >= 1" : "");
        return -1;
    }
    out->n = with_n ? (int)nv : 0;
    if (with_n && out->n == 1 && out->hi != out->lo) {
        snprintf(err, errlen, "'%s': one point (N = 1) needs LO = HI", text);
        return -1;
    }
    if (!with_n && !(out->hi > out->lo)) {
        snprintf(err, errlen, "'%s': a range needs HI > LO", text);
        return -1;
    }
    return 0;
}

/* the grid's number of cases (the product of the keys' n), -1 above
 * BD_SWEEP_MAX_CASES */
static long grid_count(const bd_study_range *keys, int nkeys)
{
    long n = 1;
    for (int k = 0; k < nkeys; k++) {
        n *= keys[k].n;
        if (n > BD_SWEEP_MAX_CASES)
            return -1;
    }
    return n;
}

/* point i of n from lo to hi, both ends exact */
static double grid_point(const bd_study_range *r, int i)
{
    if (r->n <= 1)
        return r->lo;
    if (i == r->n - 1)
        return r->hi;
    return r->lo + (r->hi - r->lo) * (double)i / (double)(r->n - 1);
}

double *bd_sweep_grid(const bd_study_range *keys, int nkeys, int *ncases)
{
    long n = grid_count(keys, nkeys);
    if (n < 1 || nkeys < 1)
        return NULL;
    double *v = malloc((size_t)n * (size_t)nkeys * sizeof *v);
    if (!v)
        return NULL;
    /* case c in mixed radix, the last key fastest */
    for (long c = 0; c < n; c++) {
        long rest = c;
        for (int k = nkeys - 1; k >= 0; k--) {
            v[c * nkeys + k] = grid_point(&keys[k], (int)(rest % keys[k].n));
            rest /= keys[k].n;
        }
    }
    *ncases = (int)n;
    return v;
}

static uint64_t splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* uniform in [0, 1), 53 bits */
static double uniform(uint64_t *state)
{
    return (double)(splitmix64(state) >> 11) * 0x1.0p-53;
}

double *bd_sweep_lhs(const bd_study_range *keys, int nkeys, int n, unsigned long long seed)
{
    if (n < 1 || nkeys < 1 || n > BD_SWEEP_MAX_CASES)
        return NULL;
    double *v = malloc((size_t)n * (size_t)nkeys * sizeof *v);
    int *perm = malloc((size_t)n * sizeof *perm);
    if (!v || !perm) {
        free(v);
        free(perm);
        return NULL;
    }
    uint64_t state = seed;
    for (int k = 0; k < nkeys; k++) {
        for (int i = 0; i < n; i++)
            perm[i] = i;
        for (int i = n - 1; i > 0; i--) {
            int j = (int)(splitmix64(&state) % (uint64_t)(i + 1));
            int t = perm[i];
            perm[i] = perm[j];
            perm[j] = t;
        }
        for (int i = 0; i < n; i++) {
            double u = uniform(&state);
            v[(size_t)i * (size_t)nkeys + (size_t)k] =
                keys[k].lo + (keys[k].hi - keys[k].lo) * ((double)perm[i] + u) / (double)n;
        }
    }
    free(perm);
    return v;
}
