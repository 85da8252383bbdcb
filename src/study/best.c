/* --best and --where (study_case.h): the case with the lowest value of a
 * table column (with "max:", the highest) among the completed cases that
 * meet every constraint. A constraint compares a column with a number
 * (=, !=, <, <=, >, >=; true/false/yes/no are 1/0, for `slipped`) or, for
 * the text columns (case, curve, status), with a text (= and != only).
 * Ties go to the first case in table order. */
#include "study/study_case.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const op_text[] = {"=", "!=", "<", "<=", ">", ">="};

int bd_study_parse_where(const char *text, bd_study_where *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    size_t k = strcspn(text, "=!<>");
    const char *p = text + k;
    int op = -1;
    if (strncmp(p, "!=", 2) == 0)
        op = BD_OP_NE;
    else if (strncmp(p, "<=", 2) == 0)
        op = BD_OP_LE;
    else if (strncmp(p, ">=", 2) == 0)
        op = BD_OP_GE;
    else if (*p == '=')
        op = BD_OP_EQ;
    else if (*p == '<')
        op = BD_OP_LT;
    else if (*p == '>')
        op = BD_OP_GT;
    const char *value = op < 0 ? p : p + strlen(op_text[op]);
    if (op < 0 || k == 0 || k >= sizeof out->column || !*value
        || strlen(value) >= sizeof out->value) {
        snprintf(err, errlen, "'%s': expected COLUMN=VALUE (or !=, <, <=, >, >=), e.g. "
                 "slipped=false", text);
        return -1;
    }
    memcpy(out->column, text, k);
    out->column[k] = '\0';
    out->op = (bd_study_op)op;
    snprintf(out->value, sizeof out->value, "%s", value);
    return 0;
}

/* a constraint's value as a number: 0 ok */
static int where_number(const char *s, double *x)
{
    if (strcmp(s, "true") == 0 || strcmp(s, "yes") == 0) {
        *x = 1.0;
        return 0;
    }
    if (strcmp(s, "false") == 0 || strcmp(s, "no") == 0) {
        *x = 0.0;
        return 0;
    }
    char *end;
    *x = strtod(s, &end);
    return *s && *end == '\0' ? 0 : -1;
}

const char *bd_study_best_column(const bd_study *s)
{
    const char *col = s->opt->best;
    return strncmp(col, "max:", 4) == 0 ? col + 4 : col;
}

int bd_study_best_check(const bd_study *s, char *err, size_t errlen)
{
    const bd_study_options *o = s->opt;
    char names[4096];
    double x;
    const char *t;
    if (o->nwhere > 0 && !o->best) {
        snprintf(err, errlen, "--where constrains --best: give --best COLUMN too");
        return -1;
    }
    if (!o->best)
        return 0;
    bd_study_column_names(s, names, sizeof names);
    int kind = bd_study_column(s, NULL, bd_study_best_column(s), &x, &t);
    if (kind != 1) {
        snprintf(err, errlen, "--best %s: %s; the numeric columns are among: %s", o->best,
                 kind == 2 ? "a text column has no lowest value" : "no such column", names);
        return -1;
    }
    for (int i = 0; i < o->nwhere; i++) {
        const bd_study_where *w = &o->where[i];
        kind = bd_study_column(s, NULL, w->column, &x, &t);
        if (kind == 0) {
            snprintf(err, errlen, "--where %s: no such column; the columns: %s", w->column,
                     names);
            return -1;
        }
        if (kind == 1 && where_number(w->value, &x) != 0) {
            snprintf(err, errlen, "--where %s: '%s' is not a number (or true/false)", w->column,
                     w->value);
            return -1;
        }
        if (kind == 2 && w->op != BD_OP_EQ && w->op != BD_OP_NE) {
            snprintf(err, errlen, "--where %s: a text column takes = or != only", w->column);
            return -1;
        }
    }
    return 0;
}

static int meets(const bd_study *s, const bd_study_case *c, const bd_study_where *w)
{
    double v = 0.0, x = 0.0;
    const char *t = "";
    int kind = bd_study_column(s, c, w->column, &v, &t);
    if (kind == 2) {
        int same = strcmp(t, w->value) == 0;
        return w->op == BD_OP_EQ ? same : !same;
    }
    if (kind != 1 || where_number(w->value, &x) != 0 || isnan(v))
        return 0;
    switch (w->op) {
    case BD_OP_EQ: return v == x;
    case BD_OP_NE: return v != x;
    case BD_OP_LT: return v < x;
    case BD_OP_LE: return v <= x;
    case BD_OP_GT: return v > x;
    case BD_OP_GE: return v >= x;
    }
    return 0;
}

int bd_study_best_find(const bd_study *s)
{
    const char *col = bd_study_best_column(s);
    int highest = strncmp(s->opt->best, "max:", 4) == 0, best = -1;
    double best_v = 0.0;
    for (int j = 0; j < s->n; j++) {
        const bd_study_case *c = &s->cases[j];
        if (c->status != BD_RUN_OK)
            continue;
        int ok = 1;
        for (int i = 0; ok && i < s->opt->nwhere; i++)
            ok = meets(s, c, &s->opt->where[i]);
        double v;
        const char *t;
        if (!ok || bd_study_column(s, c, col, &v, &t) != 1 || isnan(v))
            continue;
        if (best < 0 || (highest ? v > best_v : v < best_v)) {
            best = j;
            best_v = v;
        }
    }
    return best;
}

void bd_study_best_describe(const bd_study *s, char *buf, size_t len)
{
    const bd_study_options *o = s->opt;
    size_t n = (size_t)snprintf(buf, len, "%s %s",
                                strncmp(o->best, "max:", 4) == 0 ? "highest" : "lowest",
                                bd_study_best_column(s));
    for (int i = 0; i < o->nwhere && n < len; i++)
        n += (size_t)snprintf(buf + n, len - n, "%s%s%s%s", i ? " and " : " where ",
                              o->where[i].column, op_text[o->where[i].op], o->where[i].value);
}
