/* The YAML field machinery of the model loaders (fields.h): values by
 * kind, mappings against their field tables, lists, whole documents. */
#include "model/fields.h"

#include <assert.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/constants.h"
#include "base/file.h"

/* ---- messages and paths ---- */

void bd_fields_err(bd_fields_ctx *c, bd_mark at, const char *path, const char *fmt, ...)
{
    char msg[768];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (path[0])
        bd_diag_error(c->diag, c->file, at, "%s: %s", path, msg);
    else
        bd_diag_error(c->diag, c->file, at, "%s", msg);
    c->errors++;
}

void bd_fields_join(char *out, const char *path, const char *key)
{
    if (snprintf(out, PATH_LEN, "%s%s%s", path, path[0] ? "." : "", key) >= PATH_LEN)
        out[PATH_LEN - 1] = '\0';
}

void bd_fields_join_index(char *out, const char *path, int i)
{
    if (snprintf(out, PATH_LEN, "%s[%d]", path, i) >= PATH_LEN)
        out[PATH_LEN - 1] = '\0';
}

/* a plain scalar that reads entirely as a finite decimal number */
static int scalar_number(const yaml_node_t *n, double *x)
{
    const char *s;
    char *end;
    size_t len;
    if (!bd_fields_is_scalar(n) || n->data.scalar.style != YAML_PLAIN_SCALAR_STYLE)
        return 0;
    s = bd_fields_text_of(n);
    len = n->data.scalar.length;
    if (len == 0 || strspn(s, "0123456789+-.eE") != len || strpbrk(s, "0123456789") == NULL)
        return 0;
    errno = 0;
    *x = strtod(s, &end);
    return end == s + len && isfinite(*x);
}

/* what a node is, for "got ..." */
static const char *describe(const yaml_node_t *n, char *buf, size_t size)
{
    double x;
    if (!n)
        return "nothing";
    if (n->type == YAML_MAPPING_NODE)
        return "a mapping";
    if (n->type == YAML_SEQUENCE_NODE)
        return "a list";
    if (n->data.scalar.length == 0 && n->data.scalar.style == YAML_PLAIN_SCALAR_STYLE)
        return "nothing";
    snprintf(buf, size, scalar_number(n, &x) ? "%.60s" : "'%.60s'", bd_fields_text_of(n));
    return buf;
}

void bd_fields_type_error(bd_fields_ctx *c, const yaml_node_t *v, const char *path,
                          const char *want)
{
    char buf[80];
    bd_fields_err(c, bd_fields_mark_of(v), path, "expected %s, got %s", want,
                  describe(v, buf, sizeof buf));
}

/* ---- values ---- */

/* "WHAT in [lo, hi]" ("(lo" with GT, "hi)" with LT), or "WHAT >= lo" */
static void range_words(char *want, size_t size, const char *what, double lo, double hi,
                        unsigned flags)
{
    int k = snprintf(want, size, "%s%s", (flags & AUTO) ? "auto or " : "", what);
    if (k < 0 || (size_t)k >= size)
        return;
    if (isfinite(lo) && isfinite(hi))
        snprintf(want + k, size - (size_t)k, " in %s%g, %g%s", (flags & GT) ? "(" : "[", lo, hi,
                 (flags & LT) ? ")" : "]");
    else if (isfinite(lo))
        snprintf(want + k, size - (size_t)k, " %s %g", (flags & GT) ? ">" : ">=", lo);
}

static int in_range(double x, double lo, double hi, unsigned flags)
{
    return x >= lo && x <= hi && !((flags & GT) && x == lo) && !((flags & LT) && x == hi);
}

int bd_fields_get_num(bd_fields_ctx *c, yaml_node_t *v, const char *path, double lo, double hi,
                      unsigned flags, double *out)
{
    char want[96];
    double x;
    if ((flags & AUTO) && bd_fields_scalar_is(v, "auto")) {
        *out = 0.0;
        return 0;
    }
    range_words(want, sizeof want, "a number", lo, hi, flags);
    if (!scalar_number(v, &x) || !in_range(x, lo, hi, flags)) {
        bd_fields_type_error(c, v, path, want);
        return 1;
    }
    *out = (flags & DEG) ? x * BD_DEG : x;
    return 0;
}

/* a whole number in [lo, hi] into an int */
static int get_int(bd_fields_ctx *c, yaml_node_t *v, const char *path, double lo, double hi,
                   unsigned flags, int *out)
{
    char want[96];
    double x;
    range_words(want, sizeof want, "a whole number", lo, hi, flags);
    if (!scalar_number(v, &x) || !in_range(x, lo, hi, flags) || x != floor(x)
        || fabs(x) > 1e9) {
        bd_fields_type_error(c, v, path, want);
        return 1;
    }
    *out = (int)x;
    return 0;
}

int bd_fields_get_numbers(bd_fields_ctx *c, yaml_node_t *v, const char *path, int k,
                          const char *want, double *out)
{
    char sub[PATH_LEN];
    int bad = 0;
    if (!v || v->type != YAML_SEQUENCE_NODE || bd_fields_seq_len(v) != k) {
        bd_fields_type_error(c, v, path, want);
        return 1;
    }
    for (int i = 0; i < k; i++) {
        bd_fields_join_index(sub, path, i);
        bad |= bd_fields_get_num(c, bd_fields_item(c, v, i), sub, -INFINITY, INFINITY, 0,
                                 &out[i]);
    }
    return bad;
}

int bd_fields_get_bool(bd_fields_ctx *c, yaml_node_t *v, const char *path, int *out)
{
    static const char *const yes[] = {"true", "True", "TRUE", "yes", "Yes", "YES"};
    static const char *const no[] = {"false", "False", "FALSE", "no", "No", "NO"};
    for (int i = 0; bd_fields_is_scalar(v) && v->data.scalar.style == YAML_PLAIN_SCALAR_STYLE
                    && i < 6; i++) {
        if (bd_fields_scalar_is(v, yes[i]) || bd_fields_scalar_is(v, no[i])) {
            *out = bd_fields_scalar_is(v, yes[i]);
            return 0;
        }
    }
    bd_fields_type_error(c, v, path, "true or false");
    return 1;
}

int bd_fields_get_string(bd_fields_ctx *c, yaml_node_t *v, const char *path, unsigned flags,
                         char *out, size_t size)
{
    char want[64];
    size_t len;
    snprintf(want, sizeof want, "a %sname of at most %d characters",
             (flags & NONEMPTY) ? "non-empty " : "", (int)size - 1);
    if (!bd_fields_is_scalar(v) || (len = v->data.scalar.length) >= size
        || strlen(bd_fields_text_of(v)) != len || ((flags & NONEMPTY) && len == 0)) {
        bd_fields_type_error(c, v, path, want);
        return 1;
    }
    memcpy(out, bd_fields_text_of(v), len + 1);
    return 0;
}

int bd_fields_get_enum(bd_fields_ctx *c, yaml_node_t *v, const char *path,
                       const char *const *names, const int *vals, int *out)
{
    char want[160] = "";
    int n = 0;
    for (; names[n]; n++) {
        if (bd_fields_scalar_is(v, names[n])) {
            *out = vals ? vals[n] : n;
            return 0;
        }
    }
    for (int i = 0; i < n; i++) {
        size_t used = strlen(want);
        snprintf(want + used, sizeof want - used, "%s%s",
                 i == 0 ? "" : (i == n - 1 ? " or " : ", "), names[i]);
    }
    bd_fields_type_error(c, v, path, want);
    return 1;
}

int bd_fields_table_alloc(bd_table *tab, int n)
{
    tab->t = calloc((size_t)n, sizeof *tab->t);
    tab->v = calloc((size_t)n, sizeof *tab->v);
    if (!tab->t || !tab->v) {
        free(tab->t);
        free(tab->v);
        tab->t = tab->v = NULL;
        return 1;
    }
    tab->n = n;
    return 0;
}

void bd_fields_get_table(bd_fields_ctx *c, yaml_node_t *v, const char *path, unsigned flags,
                         double lo, bd_table *tab)
{
    char sub[PATH_LEN];
    double one;
    int n;
    if ((flags & SCALAR) && bd_fields_is_scalar(v)) {
        if (bd_fields_get_num(c, v, path, lo, INFINITY, 0, &one) == 0
            && bd_fields_table_alloc(tab, 1) == 0)
            tab->v[0] = one;
        return;
    }
    if (!v || v->type != YAML_SEQUENCE_NODE || (n = bd_fields_seq_len(v)) == 0) {
        bd_fields_type_error(c, v, path, (flags & SCALAR)
                                             ? "a number or a list of [time, value] pairs"
                                             : "a list of [time, value] pairs");
        return;
    }
    if (bd_fields_table_alloc(tab, n)) {
        bd_fields_err(c, bd_fields_mark_of(v), path, "out of memory");
        return;
    }
    for (int i = 0; i < n; i++) {
        yaml_node_t *item = bd_fields_item(c, v, i);
        double pt[2];
        bd_fields_join_index(sub, path, i);
        if (bd_fields_get_numbers(c, item, sub, 2, "a [time, value] pair", pt))
            continue;
        if (i > 0 && !(pt[0] > tab->t[i - 1]))
            bd_fields_err(c, bd_fields_mark_of(bd_fields_item(c, item, 0)), sub,
                          "expected a time > %g (times must increase), got %g", tab->t[i - 1],
                          pt[0]);
        if (pt[1] < lo)
            bd_fields_err(c, bd_fields_mark_of(bd_fields_item(c, item, 1)), sub,
                          "expected a value >= %g, got %g", lo, pt[1]);
        tab->t[i] = pt[0];
        tab->v[i] = pt[1];
    }
}

void bd_fields_span_index(bd_fields_ctx *c, yaml_node_t *v, const char *path, int *out)
{
    char name[BD_NAME_MAX];
    int i;
    assert(c->m);
    if (bd_fields_get_string(c, v, path, NONEMPTY, name, sizeof name))
        return;
    i = bd_model_find_pulley(c->m, name);
    if (i >= 0)
        *out = i;
    else if (c->m->pulley_count > 0)   /* no pulleys at all was reported already */
        bd_fields_err(c, bd_fields_mark_of(v), path, "unknown pulley '%s'", name);
}

/* ---- mappings and lists ---- */

void bd_fields_parse_list(bd_fields_ctx *c, const bd_listspec *ls, yaml_node_t *v,
                          const char *path, void *base, size_t off)
{
    char sub[PATH_LEN];
    char buf[80];
    char *arr;
    int n, saved = c->index;
    if (!v || v->type != YAML_SEQUENCE_NODE) {
        bd_fields_type_error(c, v, path, "a list");
        return;
    }
    n = bd_fields_seq_len(v);
    if (n < ls->min) {
        snprintf(buf, sizeof buf, "%d", n);
        bd_fields_err(c, bd_fields_mark_of(v), path,
                      "expected a list of at least %d entries, got %s", ls->min, buf);
    }
    if (n == 0)
        return;
    arr = calloc((size_t)n, ls->size);
    if (!arr) {
        bd_fields_err(c, bd_fields_mark_of(v), path, "out of memory");
        return;
    }
    *(void **)((char *)base + off) = arr;
    *(int *)((char *)base + ls->count_off) = n;
    for (int i = 0; i < n; i++)
        ls->init(arr + (size_t)i * ls->size);
    for (int i = 0; i < n; i++) {
        yaml_node_t *item = bd_fields_item(c, v, i);
        bd_fields_join_index(sub, path, i);
        c->index = i;
        bd_fields_parse_map(c, item, bd_fields_mark_of(item), sub, ls->elem,
                            arr + (size_t)i * ls->size);
    }
    c->index = saved;
}

/* one field's value */
static void parse_field(bd_fields_ctx *c, const bd_field *f, yaml_node_t *v, bd_mark key,
                        const char *path, void *base)
{
    void *dst = (char *)base + f->off;
    switch (f->kind) {
    case K_NUM: bd_fields_get_num(c, v, path, f->lo, f->hi, f->flags, dst); break;
    case K_INT: get_int(c, v, path, f->lo, f->hi, f->flags, dst); break;
    case K_PAIR: bd_fields_get_numbers(c, v, path, 2, f->want, dst); break;
    case K_BOOL: bd_fields_get_bool(c, v, path, dst); break;
    case K_STR: bd_fields_get_string(c, v, path, f->flags, dst, f->size); break;
    case K_ENUM: bd_fields_get_enum(c, v, path, f->names, f->vals, dst); break;
    case K_MAP: bd_fields_parse_map(c, v, key, path, f->sub, dst); break;
    case K_LIST: bd_fields_parse_list(c, f->list, v, path, base, f->off); break;
    case K_TABLE: bd_fields_get_table(c, v, path, f->flags, f->lo, dst); break;
    case K_SPAN: bd_fields_span_index(c, v, path, dst); break;
    case K_FN: f->fn(c, f, v, key, path, dst); break;
    default: assert(0);
    }
}

void bd_fields_parse_map(bd_fields_ctx *c, yaml_node_t *node, bd_mark at, const char *path,
                         const bd_fieldset *fs, void *base)
{
    yaml_node_t *found[MAX_FIELDS] = {0};
    bd_mark keys[MAX_FIELDS];
    char sub[PATH_LEN];
    int before = c->errors;
    assert(fs->n <= MAX_FIELDS);
    if (!node || node->type != YAML_MAPPING_NODE) {
        bd_fields_type_error(c, node, path, "a mapping");
        return;
    }
    for (yaml_node_pair_t *p = node->data.mapping.pairs.start; p < node->data.mapping.pairs.top;
         p++) {
        yaml_node_t *k = bd_fields_node_at(c, p->key);
        int i = 0;
        if (!bd_fields_is_scalar(k)) {
            bd_fields_type_error(c, k, path, "a key name");
            continue;
        }
        while (i < fs->n && !bd_fields_scalar_is(k, fs->fields[i].key))
            i++;
        if (i == fs->n)
            bd_fields_err(c, bd_fields_mark_of(k), path, "unknown key '%.60s'",
                          bd_fields_text_of(k));
        else if (found[i])
            bd_fields_err(c, bd_fields_mark_of(k), path, "duplicate key '%s'", fs->fields[i].key);
        else {
            found[i] = bd_fields_node_at(c, p->value);
            keys[i] = bd_fields_mark_of(k);
        }
    }
    for (int i = 0; i < fs->n; i++) {
        const bd_field *f = &fs->fields[i];
        if (!found[i]) {
            if (f->flags & REQ)
                bd_fields_err(c, at, path, "missing required key '%s'", f->key);
            continue;
        }
        bd_fields_join(sub, path, f->key);
        parse_field(c, f, found[i], keys[i], sub, base);
    }
    if (fs->post) {
        c->map_errors = c->errors - before;
        fs->post(c, fs, found, at, path, base);
    }
}

yaml_node_t *bd_fields_got(const bd_fieldset *fs, yaml_node_t *const *found, const char *key)
{
    for (int i = 0; i < fs->n; i++)
        if (strcmp(fs->fields[i].key, key) == 0)
            return found[i];
    return NULL;
}

void bd_fields_need(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                    bd_mark at, const char *path, const char *key, const char *why)
{
    if (!bd_fields_got(fs, found, key))
        bd_fields_err(c, at, path, "missing required key '%s' (%s)", key, why);
}

void bd_fields_check_friction(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                              const char *path, double mu_static, double mu_dynamic)
{
    yaml_node_t *dyn = bd_fields_got(fs, found, "dynamic");
    char sub[PATH_LEN];
    if (dyn && bd_fields_got(fs, found, "static") && mu_dynamic > mu_static) {
        bd_fields_join(sub, path, "dynamic");
        bd_fields_err(c, bd_fields_mark_of(dyn), sub, "expected a number <= static (%g), got %g",
                      mu_static, mu_dynamic);
    }
}

/* ---- whole files ---- */

static void yaml_error(bd_fields_ctx *c, const yaml_parser_t *parser)
{
    bd_mark at;
    at.line = (int)parser->problem_mark.line + 1;
    at.column = (int)parser->problem_mark.column + 1;
    if (parser->context)
        bd_fields_err(c, at, "", "invalid YAML: %s (%s)",
                      parser->problem ? parser->problem : "error", parser->context);
    else
        bd_fields_err(c, at, "", "invalid YAML: %s",
                      parser->problem ? parser->problem : "out of memory");
}

/* parse text as one document whose root mapping is walked against root */
static void load_document(bd_fields_ctx *c, const char *text, size_t len,
                          const bd_fields_loader *l, void *out)
{
    yaml_parser_t parser;
    yaml_document_t doc;
    c->doc = &doc;
    if (!yaml_parser_initialize(&parser)) {
        bd_fields_err(c, (bd_mark){0, 0}, "", "out of memory");
        return;
    }
    yaml_parser_set_input_string(&parser, (const unsigned char *)text, len);
    if (!yaml_parser_load(&parser, &doc)) {
        yaml_error(c, &parser);
    } else {
        yaml_node_t *root = yaml_document_get_root_node(&doc);
        if (!root)
            bd_fields_err(c, (bd_mark){1, 1}, "", "%s", l->empty_msg);
        else
            bd_fields_parse_map(c, root, bd_fields_mark_of(root), "", l->root, out);
        yaml_document_delete(&doc);
        /* a model is one document: look for a second one or trailing junk */
        if (root && !yaml_parser_load(&parser, &doc)) {
            yaml_error(c, &parser);
        } else if (root) {
            yaml_node_t *extra = yaml_document_get_root_node(&doc);
            if (extra)
                bd_fields_err(c, bd_fields_mark_of(extra), "",
                              "expected one YAML document, found another");
            yaml_document_delete(&doc);
        }
    }
    yaml_parser_delete(&parser);
    c->doc = NULL;
}

/* out at its defaults, its source the file */
static void start(const bd_fields_loader *l, const char *file, void *out)
{
    l->init(out);
    snprintf((char *)out + l->source_off, l->source_size, "%s", file);
}

int bd_fields_load_text(bd_fields_ctx *c, const bd_fields_loader *l, const char *text,
                        size_t len, const char *path, void *out)
{
    c->file = path ? path : "<string>";
    start(l, c->file, out);
    load_document(c, text, len, l, out);
    if (c->errors) {
        l->free(out);
        start(l, c->file, out);
        return 1;
    }
    return 0;
}

int bd_fields_load_file(bd_fields_ctx *c, const bd_fields_loader *l, const char *path,
                        void *out)
{
    char *text;
    size_t len;
    start(l, path, out);
    int rc = bd_read_file(path, &text, &len);
    if (rc != BD_READ_OK) {
        const char *why = strerror(errno);
        if (rc == BD_READ_OPEN)
            bd_diag_error(c->diag, path, (bd_mark){0, 0}, "cannot open model file: %s", why);
        else if (rc == BD_READ_NOMEM)
            bd_diag_error(c->diag, path, (bd_mark){0, 0}, "out of memory reading the model file");
        else
            bd_diag_error(c->diag, path, (bd_mark){0, 0}, "cannot read model file: %s", why);
        return 1;
    }
    rc = bd_fields_load_text(c, l, text, len, path, out);
    free(text);
    return rc;
}

void bd_fields_default_name(const char *source, char *name, size_t size)
{
    const char *slash = strrchr(source, '/');
    const char *dot;
    size_t len;
    slash = slash ? slash + 1 : source;
    dot = strrchr(slash, '.');
    len = dot && dot != slash ? (size_t)(dot - slash) : strlen(slash);
    if (len >= size)
        len = size - 1;
    memcpy(name, slash, len);
    name[len] = '\0';
}
