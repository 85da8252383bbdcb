/* The YAML field machinery the model loaders share: model/load.c (the
 * conveyor, model-format.md) and model/boom_load.c (the boom,
 * boom-format.md). Internal to the library.
 *
 * Every mapping is described by a table of fields (key, kind, where it is
 * stored, range); bd_fields_parse_map() walks a YAML mapping against such
 * a table, reporting unknown, duplicate and missing keys, and stores each
 * present key by its kind. What a table cannot say (derived values, keys
 * required only in some modes, relations between keys) is done by the
 * table's post function. Every problem is reported at its node as
 * "FILE:LINE:COL: error: PATH: MESSAGE" and counted in the context. */
#ifndef BD_MODEL_FIELDS_H
#define BD_MODEL_FIELDS_H

#include <yaml.h>

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "beltdyn/boom.h"
#include "beltdyn/model.h"

#define PATH_LEN 256    /* a key's dotted path, for messages */
#define MAX_FIELDS 16   /* keys of one mapping */

/* one load: the document, where messages go, what is being filled */
typedef struct bd_fields_ctx {
    yaml_document_t *doc;
    const char *file;
    bd_diag *diag;
    bd_model_def *m;     /* the conveyor being loaded (K_SPAN names its pulleys), or NULL */
    bd_boom_def *boom;   /* the boom being loaded (checks across its keys), or NULL */
    int errors;
    int index;           /* index of the list entry being parsed */
    int map_errors;      /* in a post: the errors its mapping's keys and values gave, so
                            that checks across them are made only on what read well */
} bd_fields_ctx;

struct bd_field;
struct bd_fieldset;
/* K_FN's handler: v the value, key where its key stands, base + off the
 * field's place */
typedef void (*bd_field_fn)(bd_fields_ctx *c, const struct bd_field *f, yaml_node_t *v,
                            bd_mark key, const char *path, void *base);
/* after a mapping's fields: found[i] the node of fs->fields[i] or NULL,
 * at where a missing key is reported */
typedef void (*bd_post_fn)(bd_fields_ctx *c, const struct bd_fieldset *fs,
                           yaml_node_t *const *found, bd_mark at, const char *path, void *base);

typedef struct bd_fieldset {
    const struct bd_field *fields;
    int n;
    bd_post_fn post;   /* after all fields, or NULL */
} bd_fieldset;

typedef struct bd_listspec {
    const bd_fieldset *elem;
    size_t size;             /* bytes of one element */
    size_t count_off;        /* offset of the int count beside the pointer */
    void (*init)(void *elem);
    int min;                 /* least number of entries */
} bd_listspec;

enum bd_field_kind {
    K_NUM,    /* double with range */
    K_INT,    /* int: a whole number in [lo, hi] */
    K_PAIR,   /* double[2] from a list of two numbers; `want` says what they are */
    K_BOOL,   /* int 0/1 */
    K_STR,    /* char[size] */
    K_ENUM,   /* int from names[] (value vals[i], or i) */
    K_MAP,    /* nested mapping, fields relative to base + off */
    K_LIST,   /* list of mappings: T *at off, int count at list->count_off */
    K_TABLE,  /* bd_table of [t, value] pairs */
    K_SPAN,   /* int index of a conveyor's pulley named by the value (needs ctx m) */
    K_FN      /* custom handler, given base + off */
};

enum {
    REQ = 1,       /* required */
    GT = 2,        /* lower bound is strict */
    AUTO = 4,      /* `auto` is accepted and stored as 0 */
    DEG = 8,       /* value in degrees, stored in rad */
    SCALAR = 16,   /* table: a single number is a one-point table */
    NONEMPTY = 32, /* string must not be empty */
    LT = 64        /* upper bound is strict */
};

typedef struct bd_field {
    const char *key;
    int kind;
    unsigned flags;
    size_t off;
    double lo, hi;              /* K_NUM / K_INT / K_TABLE values */
    const char *const *names;   /* K_ENUM, NULL-terminated */
    const int *vals;            /* K_ENUM values, NULL = index */
    const bd_fieldset *sub;     /* K_MAP */
    const bd_listspec *list;    /* K_LIST */
    bd_field_fn fn;             /* K_FN */
    size_t size;                /* K_STR buffer size */
    const char *want;           /* K_PAIR, e.g. "a point [x, y]" */
} bd_field;

#define NUM(k, T, m, fl, l, h) {.key = k, .kind = K_NUM, .flags = fl, \
    .off = offsetof(T, m), .lo = l, .hi = h}
#define ANY(k, T, m, fl) NUM(k, T, m, fl, -INFINITY, INFINITY)
#define POS(k, T, m, fl) NUM(k, T, m, (fl) | GT, 0.0, INFINITY)
#define NONNEG(k, T, m, fl) NUM(k, T, m, fl, 0.0, INFINITY)
#define INT(k, T, m, fl, l, h) {.key = k, .kind = K_INT, .flags = fl, \
    .off = offsetof(T, m), .lo = l, .hi = h}
#define PAIR(k, T, m, fl, w) {.key = k, .kind = K_PAIR, .flags = fl, .off = offsetof(T, m), \
    .want = w}
#define BOOL(k, T, m) {.key = k, .kind = K_BOOL, .off = offsetof(T, m)}
#define STR(k, T, m, fl) {.key = k, .kind = K_STR, .flags = fl, .off = offsetof(T, m), \
    .size = sizeof(((T *)0)->m)}
#define ENUM(k, T, m, fl, nm, v) {.key = k, .kind = K_ENUM, .flags = fl, \
    .off = offsetof(T, m), .names = nm, .vals = v}
#define MAP(k, T, m, fl, s) {.key = k, .kind = K_MAP, .flags = fl, .off = offsetof(T, m), .sub = s}
#define SUBMAP(k, fl, s) {.key = k, .kind = K_MAP, .flags = fl, .off = 0, .sub = s}
#define LIST(k, T, m, fl, l) {.key = k, .kind = K_LIST, .flags = fl, .off = offsetof(T, m), \
    .list = l}
#define TABLE(k, T, m, fl, l) {.key = k, .kind = K_TABLE, .flags = fl, .off = offsetof(T, m), \
    .lo = l, .hi = INFINITY}
#define SPAN(k, T, m, fl) {.key = k, .kind = K_SPAN, .flags = fl, .off = offsetof(T, m)}
#define FN(k, f) {.key = k, .kind = K_FN, .off = 0, .fn = f}
#define FN_REQ(k, f) {.key = k, .kind = K_FN, .flags = REQ, .off = 0, .fn = f}
#define FIELDSET(name, arr, post) \
    static const bd_fieldset name = {arr, (int)(sizeof arr / sizeof arr[0]), post}

/* ---- nodes ---- */

static inline yaml_node_t *bd_fields_node_at(const bd_fields_ctx *c, int id)
{
    return yaml_document_get_node(c->doc, id);
}

/* where a node starts, 1-based ({1, 1} for none) */
static inline bd_mark bd_fields_mark_of(const yaml_node_t *n)
{
    bd_mark at = {1, 1};
    if (n) {
        at.line = (int)n->start_mark.line + 1;
        at.column = (int)n->start_mark.column + 1;
    }
    return at;
}

static inline int bd_fields_is_scalar(const yaml_node_t *n)
{
    return n && n->type == YAML_SCALAR_NODE;
}

static inline const char *bd_fields_text_of(const yaml_node_t *n)
{
    return (const char *)n->data.scalar.value;
}

static inline int bd_fields_scalar_is(const yaml_node_t *n, const char *s)
{
    return bd_fields_is_scalar(n) && n->data.scalar.length == strlen(s)
           && strcmp(bd_fields_text_of(n), s) == 0;
}

static inline int bd_fields_seq_len(const yaml_node_t *n)
{
    return (int)(n->data.sequence.items.top - n->data.sequence.items.start);
}

/* item i of a sequence node */
static inline yaml_node_t *bd_fields_item(const bd_fields_ctx *c, const yaml_node_t *seq, int i)
{
    return bd_fields_node_at(c, seq->data.sequence.items.start[i]);
}

/* ---- messages and paths ---- */

/* "FILE:LINE:COL: error: PATH: MSG" (no "PATH: " for an empty path), counted */
void bd_fields_err(bd_fields_ctx *c, bd_mark at, const char *path, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
/* "expected WANT, got WHAT v IS" at v */
void bd_fields_type_error(bd_fields_ctx *c, const yaml_node_t *v, const char *path,
                          const char *want);
/* out (PATH_LEN bytes) = "path.key", or "key" at the top */
void bd_fields_join(char *out, const char *path, const char *key);
/* out (PATH_LEN bytes) = "path[i]" */
void bd_fields_join_index(char *out, const char *path, int i);

/* ---- values; each returns 0 when stored, else 1 after its message ---- */

/* a number in [lo, hi] ((lo with GT, hi) with LT), `auto` -> 0 with AUTO,
 * degrees stored in rad with DEG */
int bd_fields_get_num(bd_fields_ctx *c, yaml_node_t *v, const char *path, double lo, double hi,
                      unsigned flags, double *out);
/* a list of exactly k numbers; want says what it is for the message */
int bd_fields_get_numbers(bd_fields_ctx *c, yaml_node_t *v, const char *path, int k,
                          const char *want, double *out);
int bd_fields_get_bool(bd_fields_ctx *c, yaml_node_t *v, const char *path, int *out);
int bd_fields_get_string(bd_fields_ctx *c, yaml_node_t *v, const char *path, unsigned flags,
                         char *out, size_t size);
int bd_fields_get_enum(bd_fields_ctx *c, yaml_node_t *v, const char *path,
                       const char *const *names, const int *vals, int *out);
/* tab->t and tab->v of n points, zeroed; 0, or 1 out of memory (tab left empty) */
int bd_fields_table_alloc(bd_table *tab, int n);
/* [[t, v], ...] with strictly increasing t and v >= lo, or (SCALAR) one
 * number v meaning [[0, v]]; what was read is stored even after an error
 * (the caller frees the table) */
void bd_fields_get_table(bd_fields_ctx *c, yaml_node_t *v, const char *path, unsigned flags,
                         double lo, bd_table *tab);
/* the index of the conveyor's pulley named by v into *out */
void bd_fields_span_index(bd_fields_ctx *c, yaml_node_t *v, const char *path, int *out);

/* ---- mappings and lists ---- */

/* walk a mapping against fs: unknown, duplicate and missing keys, then
 * every present field in table order (so what is named comes before what
 * names it), then fs->post. at = where a missing key is reported. */
void bd_fields_parse_map(bd_fields_ctx *c, yaml_node_t *node, bd_mark at, const char *path,
                         const bd_fieldset *fs, void *base);
/* a list of mappings: ls->size bytes each, allocated at base + off, their
 * count at base + ls->count_off, each ls->init'ed then parsed */
void bd_fields_parse_list(bd_fields_ctx *c, const bd_listspec *ls, yaml_node_t *v,
                          const char *path, void *base, size_t off);
/* the node given for key in a finished parse_map (in a post), or NULL */
yaml_node_t *bd_fields_got(const bd_fieldset *fs, yaml_node_t *const *found, const char *key);
/* "missing required key" for a key needed only in some modes */
void bd_fields_need(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                    bd_mark at, const char *path, const char *key, const char *why);
/* a friction pair's rule, in a post: `dynamic` (when both were given) not
 * above `static` */
void bd_fields_check_friction(bd_fields_ctx *c, const bd_fieldset *fs, yaml_node_t *const *found,
                              const char *path, double mu_static, double mu_dynamic);

/* ---- whole files ---- */

/* what a loader fills: its top-level table and its description's set-up */
typedef struct bd_fields_loader {
    const bd_fieldset *root;     /* the top-level mapping */
    const char *empty_msg;       /* said of an empty document */
    void (*init)(void *out);     /* every field at its default */
    void (*free)(void *out);     /* what out holds freed, out at its defaults */
    size_t source_off;           /* char source[source_size] in out: the file, for messages */
    size_t source_size;
} bd_fields_loader;

/* text as exactly one YAML document into out (initialized first): YAML
 * errors, an empty document and a second one reported too. 0, or 1 with
 * every problem in c->diag and out freed but for its source. The caller
 * sets c->diag and c->m or c->boom; path NULL reads as "<string>". */
int bd_fields_load_text(bd_fields_ctx *c, const bd_fields_loader *l, const char *text,
                        size_t len, const char *path, void *out);
/* the model file at path, as bd_fields_load_text (a file that cannot be
 * read is said in c->diag) */
int bd_fields_load_file(bd_fields_ctx *c, const bd_fields_loader *l, const char *path,
                        void *out);
/* the model's default name: source's base name without its extension */
void bd_fields_default_name(const char *source, char *name, size_t size);

#endif
