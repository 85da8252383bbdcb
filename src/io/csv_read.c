/* fast numeric CSV reader: block reads, in-place parsing, exact doubles */
#include "io/csv_read.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define BLOCK_BYTES ((size_t)8 << 20)

static const double pow10_exact[23] = {
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

static int is_digit(char c) { return c >= '0' && c <= '9'; }

double bd_csv_parse_double(const char *p, const char *end, const char **next)
{
    const char *s = p;
    int neg = 0, ndig = 0, any = 0, exp10 = 0, truncated = 0;
    uint64_t mant = 0;

    /* sign */
    if (s < end && (*s == '-' || *s == '+')) {
        neg = (*s == '-');
        s++;
    }
    /* integer digits: up to 19 significant digits fit in 64 bits */
    while (s < end && is_digit(*s)) {
        unsigned d = (unsigned)(*s - '0');
        any = 1;
        if (ndig < 19) {
            mant = mant * 10u + d;
            if (mant > 0) ndig++;
        } else {
            exp10++;
            if (d) truncated = 1;
        }
        s++;
    }
    /* fraction digits */
    if (s < end && *s == '.') {
        s++;
        while (s < end && is_digit(*s)) {
            unsigned d = (unsigned)(*s - '0');
            any = 1;
            if (ndig < 19) {
                mant = mant * 10u + d;
                if (mant > 0) ndig++;
                exp10--;
            } else if (d) {
                truncated = 1;
            }
            s++;
        }
    }
    if (!any) goto slow;  /* nan, inf, or not a number */
    /* exponent */
    if (s < end && (*s == 'e' || *s == 'E')) {
        const char *e = s + 1;
        int eneg = 0, ev = 0, edig = 0;
        if (e < end && (*e == '-' || *e == '+')) {
            eneg = (*e == '-');
            e++;
        }
        while (e < end && is_digit(*e)) {
            if (ev < 100000) ev = ev * 10 + (*e - '0');
            edig++;
            e++;
        }
        if (!edig) goto slow;
        exp10 += eneg ? -ev : ev;
        s = e;
    }
    /* Clinger's fast path: an exact mantissa times an exact power of ten
     * rounds once, so the result equals strtod's */
    if (!truncated && mant <= ((uint64_t)1 << 53) && exp10 >= -22 && exp10 <= 22) {
        double v = (double)mant;
        v = exp10 < 0 ? v / pow10_exact[-exp10] : v * pow10_exact[exp10];
        *next = s;
        return neg ? -v : v;
    }
slow: {
        /* the buffer is NUL-terminated and fields end at ',' or '\n', so
         * strtod stops inside the field */
        char *q = NULL;
        double v = strtod(p, &q);
        if (q == p || q > end) {
            *next = p;
            return NAN;
        }
        *next = q;
        return v;
    }
}

void bd_csv_free(bd_csv *csv)
{
    if (!csv) return;
    for (int i = 0; i < csv->ncols; i++) {
        if (csv->names) free(csv->names[i]);
        if (csv->col) free(csv->col[i]);
    }
    free(csv->names);
    free(csv->col);
    memset(csv, 0, sizeof *csv);
}

int bd_csv_find(const bd_csv *csv, const char *name)
{
    for (int i = 0; i < csv->ncols; i++)
        if (strcmp(csv->names[i], name) == 0) return i;
    return -1;
}

/* split a header line [p, end) into owned, trimmed names */
static int split_header(const char *p, const char *end, char ***names_out)
{
    int n = 1, k = 0;
    for (const char *c = p; c < end; c++)
        if (*c == ',') n++;
    char **names = calloc((size_t)n, sizeof *names);
    if (!names) return -1;
    const char *f = p;
    for (const char *c = p;; c++) {
        if (c == end || *c == ',') {
            const char *a = f, *b = c;
            while (a < b && (*a == ' ' || *a == '\t' || *a == '"')) a++;
            while (b > a && (b[-1] == ' ' || b[-1] == '\t' || b[-1] == '\r' || b[-1] == '"')) b--;
            names[k] = malloc((size_t)(b - a) + 1);
            if (!names[k]) {
                for (int i = 0; i < k; i++) free(names[i]);
                free(names);
                return -1;
            }
            memcpy(names[k], a, (size_t)(b - a));
            names[k][b - a] = '\0';
            k++;
            if (c == end) break;
            f = c + 1;
        }
    }
    *names_out = names;
    return n;
}

typedef struct reader {
    FILE *fp;
    char *buf;      /* [cap + 1], NUL after the filled part */
    size_t cap, len, pos;
    int eof;
} reader;

/* make sure a whole line starting at r->pos is in the buffer (or EOF);
 * returns the position of its '\n' or NULL at EOF without one */
static char *reader_line(reader *r)
{
    for (;;) {
        char *nl = memchr(r->buf + r->pos, '\n', r->len - r->pos);
        if (nl || r->eof) return nl;
        /* move the partial line to the front, grow if it fills the buffer */
        memmove(r->buf, r->buf + r->pos, r->len - r->pos);
        r->len -= r->pos;
        r->pos = 0;
        if (r->len == r->cap) {
            char *nb = realloc(r->buf, 2 * r->cap + 1);
            if (!nb) return NULL;
            r->buf = nb;
            r->cap *= 2;
        }
        size_t got = fread(r->buf + r->len, 1, r->cap - r->len, r->fp);
        r->len += got;
        r->buf[r->len] = '\0';
        if (got == 0) r->eof = 1;
    }
}

static int open_reader(reader *r, const char *path, char *err, size_t errlen)
{
    memset(r, 0, sizeof *r);
    r->fp = fopen(path, "rb");
    if (!r->fp) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    r->cap = BLOCK_BYTES;
    r->buf = malloc(r->cap + 1);
    if (!r->buf) {
        fclose(r->fp);
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    r->buf[0] = '\0';
    return 0;
}

static void close_reader(reader *r)
{
    if (r->fp) fclose(r->fp);
    free(r->buf);
}

/* reads the header into out->names / out->ncols (all columns) */
static int read_header(reader *r, const char *path, bd_csv *out, char *err, size_t errlen)
{
    char *nl = reader_line(r);
    const char *end = nl ? nl : r->buf + r->len;
    if (end == r->buf + r->pos) {
        snprintf(err, errlen, "%s:1: empty file (no header row)", path);
        return -1;
    }
    /* skip a UTF-8 byte order mark */
    const char *p = r->buf + r->pos;
    if (end - p >= 3 && (unsigned char)p[0] == 0xEF && (unsigned char)p[1] == 0xBB &&
        (unsigned char)p[2] == 0xBF)
        p += 3;
    int n = split_header(p, end, &out->names);
    if (n < 0) {
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    out->ncols = n;
    r->pos = nl ? (size_t)(nl - r->buf) + 1 : r->len;
    return 0;
}

int bd_csv_read_header(const char *path, bd_csv *out, char *err, size_t errlen)
{
    reader r;
    memset(out, 0, sizeof *out);
    if (open_reader(&r, path, err, errlen)) return -1;
    int rc = read_header(&r, path, out, err, errlen);
    close_reader(&r);
    return rc;
}

int bd_csv_read(const char *path, const char *const *want, int nwant,
                bd_csv *out, char *err, size_t errlen)
{
    reader r;
    bd_csv all;
    int rc = -1;
    int *map = NULL;    /* [file columns] kept index or -1 */
    size_t cap = 0;
    memset(out, 0, sizeof *out);
    memset(&all, 0, sizeof all);
    if (open_reader(&r, path, err, errlen)) return -1;
    if (read_header(&r, path, &all, err, errlen)) goto done;
    int nfile = all.ncols;

    /* which file columns are kept, and where */
    int nkeep = want ? nwant : nfile;
    map = malloc((size_t)nfile * sizeof *map);
    out->names = calloc((size_t)(nkeep > 0 ? nkeep : 1), sizeof *out->names);
    out->col = calloc((size_t)(nkeep > 0 ? nkeep : 1), sizeof *out->col);
    if (!map || !out->names || !out->col) {
        snprintf(err, errlen, "%s: out of memory", path);
        goto done;
    }
    out->ncols = nkeep;
    for (int j = 0; j < nfile; j++) map[j] = want ? -1 : j;
    for (int k = 0; k < nkeep; k++) {
        int j = want ? bd_csv_find(&all, want[k]) : k;
        if (j < 0) {
            snprintf(err, errlen, "%s:1: no column '%s'", path, want[k]);
            goto done;
        }
        map[j] = k;
        out->names[k] = strdup(all.names[j]);
        if (!out->names[k]) {
            snprintf(err, errlen, "%s: out of memory", path);
            goto done;
        }
    }

    /* first guess of the row count from the file size and the first row */
    {
        struct stat st;
        size_t guess = 1024;
        char *nl = reader_line(&r);
        if (nl && fstat(fileno(r.fp), &st) == 0 && nl > r.buf + r.pos) {
            size_t linelen = (size_t)(nl - (r.buf + r.pos)) + 1;
            guess = (size_t)st.st_size / linelen + 16;
        }
        cap = guess;
        for (int k = 0; k < nkeep; k++) {
            out->col[k] = malloc(cap * sizeof(double));
            if (!out->col[k]) {
                snprintf(err, errlen, "%s: out of memory", path);
                goto done;
            }
        }
    }

    /* rows */
    size_t line = 1, n = 0;
    for (;;) {
        char *nl = reader_line(&r);
        char *p = r.buf + r.pos;
        char *end = nl ? nl : r.buf + r.len;
        if (!nl && p == end) break;  /* clean end of file */
        line++;
        if (end > p && end[-1] == '\r') end--;
        if (p == end) {  /* blank line */
            r.pos = nl ? (size_t)(nl - r.buf) + 1 : r.len;
            if (!nl) break;
            continue;
        }
        if (n == cap) {
            cap *= 2;
            for (int k = 0; k < nkeep; k++) {
                double *c = realloc(out->col[k], cap * sizeof(double));
                if (!c) {
                    snprintf(err, errlen, "%s: out of memory", path);
                    goto done;
                }
                out->col[k] = c;
            }
        }
        int j = 0, bad = 0;
        const char *q = p;
        for (;;) {
            const char *fe;
            if (j >= nfile) {
                bad = 1;
                break;
            }
            if (map[j] >= 0) {
                while (q < end && *q == ' ') q++;
                double v;
                if (q == end || *q == ',') {
                    v = NAN;
                    fe = q;
                } else {
                    v = bd_csv_parse_double(q, end, &fe);
                    while (fe < end && *fe == ' ') fe++;
                    if (fe < end && *fe != ',') {
                        bad = 2;
                        break;
                    }
                }
                out->col[map[j]][n] = v;
            } else {
                fe = memchr(q, ',', (size_t)(end - q));
                if (!fe) fe = end;
            }
            j++;
            if (fe == end) break;
            q = fe + 1;
        }
        if (!bad && j != nfile) bad = 1;
        if (bad) {
            if (!nl) break;  /* an interrupted last line: ignore it */
            snprintf(err, errlen, "%s:%zu: %s (expected %d numeric fields)", path, line,
                     bad == 1 ? "wrong number of fields" : "not a number", nfile);
            goto done;
        }
        n++;
        if (!nl) break;
        r.pos = (size_t)(nl - r.buf) + 1;
    }
    out->nrows = n;
    rc = 0;
done:
    if (rc) bd_csv_free(out);
    bd_csv_free(&all);
    free(map);
    close_reader(&r);
    return rc;
}
