/* A model key found in the model file's text (keypath.h), with libyaml's
 * document API: its nodes carry the byte offsets of their text.
 *
 * Setting a key edits the text rather than bd_model_def: the loader then
 * checks the value (range, type) and derives what depends on it, and its
 * messages keep the file's line and column (a number replaced in place
 * moves nothing; an added key is one new line, or an item in a flow
 * mapping's braces). */
#include "study/keypath.h"

#include <yaml.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SEGS 16

static const char *scalar_text(const yaml_node_t *n)
{
    return (const char *)n->data.scalar.value;
}

static int scalar_is(const yaml_node_t *n, const char *s)
{
    return n && n->type == YAML_SCALAR_NODE && n->data.scalar.length == strlen(s)
           && strcmp(scalar_text(n), s) == 0;
}

/* a plain scalar that reads whole as a finite number, as the loader's */
static int scalar_number(const yaml_node_t *n, double *x)
{
    if (!n || n->type != YAML_SCALAR_NODE || n->data.scalar.style != YAML_PLAIN_SCALAR_STYLE)
        return 0;
    const char *s = scalar_text(n);
    size_t len = n->data.scalar.length;
    if (len == 0 || strspn(s, "0123456789+-.eE") != len || !strpbrk(s, "0123456789"))
        return 0;
    char *end;
    *x = strtod(s, &end);
    return end == s + len && isfinite(*x);
}

/* "pulleys[2].takeup.mass" → pulleys, 2, takeup, mass; the count, or -1
 * when a part is empty, too long, or there are too many */
static int split(const char *key, char seg[][128])
{
    int n = 0;
    const char *p = key;
    while (*p) {
        if (n == MAX_SEGS)
            return -1;
        int bracket = *p == '[';
        if (bracket)
            p++;
        size_t k = bracket ? strcspn(p, "]") : strcspn(p, ".[");
        if (k == 0 || k >= 128 || (bracket && p[k] != ']'))
            return -1;
        memcpy(seg[n], p, k);
        seg[n++][k] = '\0';
        p += k + (size_t)bracket;
        if (*p == '.' && *++p == '\0')
            return -1;   /* a trailing dot */
        else if (bracket && *p && *p != '[' && p[-1] != '.')
            return -1;
    }
    return n;
}

static yaml_node_t *node(yaml_document_t *d, int id)
{
    return yaml_document_get_node(d, id);
}

/* the byte after a node's text; for a block collection, after its last
 * item's text (a block's end mark lies at the next line's start) */
static size_t text_end(yaml_document_t *d, yaml_node_t *n)
{
    if (n->type == YAML_MAPPING_NODE && n->data.mapping.style == YAML_BLOCK_MAPPING_STYLE
        && n->data.mapping.pairs.top > n->data.mapping.pairs.start)
        return text_end(d, node(d, (n->data.mapping.pairs.top - 1)->value));
    if (n->type == YAML_SEQUENCE_NODE && n->data.sequence.style == YAML_BLOCK_SEQUENCE_STYLE
        && n->data.sequence.items.top > n->data.sequence.items.start)
        return text_end(d, node(d, *(n->data.sequence.items.top - 1)));
    return n->end_mark.index;
}

/* entries' names for a message: "head, tail, takeup" */
static void entry_names(yaml_document_t *d, yaml_node_t *seq, char *out, size_t len)
{
    size_t o = 0;
    out[0] = '\0';
    for (yaml_node_item_t *it = seq->data.sequence.items.start;
         it < seq->data.sequence.items.top && o + 80 < len; it++) {
        yaml_node_t *e = node(d, *it);
        if (!e || e->type != YAML_MAPPING_NODE)
            continue;
        for (yaml_node_pair_t *pr = e->data.mapping.pairs.start; pr < e->data.mapping.pairs.top;
             pr++)
            if (scalar_is(node(d, pr->key), "name") && node(d, pr->value)->type
                == YAML_SCALAR_NODE) {
                o += (size_t)snprintf(out + o, len - o, "%s%.60s", o ? ", " : "",
                                      scalar_text(node(d, pr->value)));
                break;
            }
    }
}

/* the entry of a list named `name` (its `name` key), or at index `name` */
static yaml_node_t *list_entry(yaml_document_t *d, yaml_node_t *seq, const char *name)
{
    int count = (int)(seq->data.sequence.items.top - seq->data.sequence.items.start);
    for (int i = 0; i < count; i++) {
        yaml_node_t *e = node(d, seq->data.sequence.items.start[i]);
        if (!e || e->type != YAML_MAPPING_NODE)
            continue;
        for (yaml_node_pair_t *pr = e->data.mapping.pairs.start; pr < e->data.mapping.pairs.top;
             pr++)
            if (scalar_is(node(d, pr->key), "name") && scalar_is(node(d, pr->value), name))
                return e;
    }
    char *end;
    long i = strtol(name, &end, 10);
    if (*name && *end == '\0' && name[0] != '-' && name[0] != '+' && i < count)
        return node(d, seq->data.sequence.items.start[i]);
    return NULL;
}

/* "a: {b: {c: " ... "}}" around the number, for keys seg[0..n-1] added */
static int added_text(char seg[][128], int n, char *before, size_t blen, char *after,
                      size_t alen)
{
    size_t o = 0;
    before[0] = '\0';
    for (int i = 0; i < n; i++) {
        size_t k = strlen(seg[i]);
        if (o + k + 4 >= blen)
            return -1;
        memcpy(before + o, seg[i], k);
        o += k;
        memcpy(before + o, i + 1 < n ? ": {" : ": ", i + 1 < n ? 3 : 2);
        o += i + 1 < n ? 3 : 2;
        before[o] = '\0';
    }
    if ((size_t)n >= alen)
        return -1;
    for (int i = 0; i + 1 < n; i++)
        after[i] = '}';
    after[n > 0 ? n - 1 : 0] = '\0';
    return 0;
}

/* the place in mapping m for keys seg[0..n-1] that the file lacks */
static int add_to(const char *text, yaml_document_t *d, yaml_node_t *m, char seg[][128], int n,
                  bd_key_site *site)
{
    char kv[300], after[64];
    if (added_text(seg, n, kv, sizeof kv, after, sizeof after))
        return -1;
    /* a key name too long to add is refused, not cut */
    if (snprintf(site->adds, sizeof site->adds, "%s", seg[0]) >= (int)sizeof site->adds)
        return -1;
    snprintf(site->after, sizeof site->after, "%s", after);
    site->len = 0;
    site->value = NAN;
    int pairs = (int)(m->data.mapping.pairs.top - m->data.mapping.pairs.start);
    if (m->data.mapping.style == YAML_FLOW_MAPPING_STYLE) {
        /* {a: 1} → {a: 1, key: V}; {} → {key: V} */
        if (pairs > 0) {
            site->at = text_end(d, node(d, (m->data.mapping.pairs.top - 1)->value));
            snprintf(site->before, sizeof site->before, ", %s", kv);
        } else {
            const char *brace = strchr(text + m->start_mark.index, '{');
            if (!brace)
                return -1;
            site->at = (size_t)(brace - text) + 1;
            snprintf(site->before, sizeof site->before, "%s", kv);
        }
        return 0;
    }
    if (pairs == 0)
        return -1;
    /* a new line after the mapping's last text, at its keys' column */
    yaml_node_t *first = node(d, m->data.mapping.pairs.start->key);
    int col = (int)first->start_mark.column;
    site->at = text_end(d, node(d, (m->data.mapping.pairs.top - 1)->value));
    if (col > 200)
        return -1;
    snprintf(site->before, sizeof site->before, "\n%*s%s", col, "", kv);
    return 0;
}

static const char *what(const yaml_node_t *n)
{
    return n->type == YAML_MAPPING_NODE ? "a mapping" : n->type == YAML_SEQUENCE_NODE ? "a list"
                                                                                    : "text";
}

static int find(const char *text, yaml_document_t *d, const char *key, char seg[][128], int nseg,
                bd_key_site *site, char *err, size_t errlen)
{
    yaml_node_t *n = yaml_document_get_root_node(d);
    if (!n || n->type != YAML_MAPPING_NODE) {
        snprintf(err, errlen, "%s: the model file is not a mapping of keys", key);
        return -1;
    }
    char where[512];
    where[0] = '\0';
    for (int i = 0; i < nseg; i++) {
        if (n->type == YAML_MAPPING_NODE) {
            yaml_node_t *v = NULL;
            for (yaml_node_pair_t *pr = n->data.mapping.pairs.start;
                 pr < n->data.mapping.pairs.top; pr++)
                if (scalar_is(node(d, pr->key), seg[i])) {
                    v = node(d, pr->value);
                    break;
                }
            if (!v) {
                if (add_to(text, d, n, seg + i, nseg - i, site)) {
                    snprintf(err, errlen, "%s: cannot add '%s' to %s in the model file", key,
                             seg[i], where[0] ? where : "the top level");
                    return -1;
                }
                return 0;
            }
            n = v;
        } else if (n->type == YAML_SEQUENCE_NODE) {
            yaml_node_t *e = list_entry(d, n, seg[i]);
            if (!e) {
                char names[400];
                entry_names(d, n, names, sizeof names);
                int count = (int)(n->data.sequence.items.top - n->data.sequence.items.start);
                snprintf(err, errlen, "%s: '%s' has no entry named '%s' (%s%s%sor an index 0 to %d)",
                         key, where, seg[i], names[0] ? "names: " : "", names,
                         names[0] ? "; " : "", count - 1);
                return -1;
            }
            n = e;
        } else {
            snprintf(err, errlen, "%s: '%s' is a value in the model file, with no keys below it",
                     key, where);
            return -1;
        }
        /* the path so far, for the messages; a long one is cut there */
        size_t o = strlen(where);
        if (snprintf(where + o, sizeof where - o, "%s%s", o ? "." : "", seg[i])
            >= (int)(sizeof where - o))
            where[sizeof where - 1] = '\0';
    }
    double x = 0.0;
    if (scalar_number(n, &x) || (scalar_is(n, "auto")
                                 && n->data.scalar.style == YAML_PLAIN_SCALAR_STYLE)) {
        site->at = n->start_mark.index;
        site->len = n->end_mark.index - n->start_mark.index;
        site->before[0] = site->after[0] = site->adds[0] = '\0';
        site->value = scalar_is(n, "auto") ? NAN : x;
        return 0;
    }
    if (n->type == YAML_SCALAR_NODE)
        snprintf(err, errlen, "%s: the model file has '%.60s' there (line %d), not a number",
                 key, scalar_text(n), (int)n->start_mark.line + 1);
    else
        snprintf(err, errlen, "%s: the model file has %s there (line %d), not a number", key,
                 what(n), (int)n->start_mark.line + 1);
    return -1;
}

int bd_key_find(const char *text, size_t len, const char *key, bd_key_site *site, char *err,
                size_t errlen)
{
    char seg[MAX_SEGS][128];
    int nseg = split(key, seg);
    if (nseg <= 0) {
        snprintf(err, errlen, "'%s' is not a key path: expected names joined by dots, e.g. "
                 "pulleys.takeup.takeup.mass or idlers[0].spacing", key);
        return -1;
    }
    yaml_parser_t parser;
    yaml_document_t doc;
    if (!yaml_parser_initialize(&parser)) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    yaml_parser_set_input_string(&parser, (const unsigned char *)text, len);
    int rc;
    if (!yaml_parser_load(&parser, &doc)) {
        snprintf(err, errlen, "%s: the model file is not valid YAML", key);
        rc = -1;
    } else {
        rc = find(text, &doc, key, seg, nseg, site, err, errlen);
        yaml_document_delete(&doc);
    }
    yaml_parser_delete(&parser);
    return rc;
}

static const bd_key_site *order_sites;

static int by_place(const void *a, const void *b)
{
    const bd_key_site *x = &order_sites[*(const int *)a], *y = &order_sites[*(const int *)b];
    if (x->at != y->at)
        return x->at < y->at ? -1 : 1;
    return *(const int *)a - *(const int *)b;
}

char *bd_key_apply(const char *text, size_t len, const bd_key_site *sites, const double *values,
                   int n, size_t *outlen)
{
    int idx[64];
    if (n > 64)
        return NULL;
    size_t cap = len + 1;
    for (int i = 0; i < n; i++) {
        idx[i] = i;
        cap += strlen(sites[i].before) + strlen(sites[i].after) + 32;
    }
    order_sites = sites;
    qsort(idx, (size_t)n, sizeof idx[0], by_place);
    char *out = malloc(cap);
    if (!out)
        return NULL;
    size_t o = 0, from = 0;
    for (int k = 0; k < n; k++) {
        const bd_key_site *s = &sites[idx[k]];
        /* two sites on one number (or past the text) would copy from
         * behind where the last one ended: refused, not wrapped around */
        if (s->at < from || s->at > len || s->len > len - s->at) {
            free(out);
            return NULL;
        }
        memcpy(out + o, text + from, s->at - from);
        o += s->at - from;
        o += (size_t)snprintf(out + o, cap - o, "%s%.17g%s", s->before, values[idx[k]], s->after);
        from = s->at + s->len;
    }
    memcpy(out + o, text + from, len - from);
    o += len - from;
    out[o] = '\0';
    *outlen = o;
    return out;
}
