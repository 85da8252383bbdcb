/* A model key given as a dotted path (keypath.c), found in the model
 * file's text, so that a sweep can set it to a number and load the model
 * again: the loader then validates the value and derives what follows
 * from it (a gravity takeup's force from its mass) as for a file. */
#ifndef BD_STUDY_KEYPATH_H
#define BD_STUDY_KEYPATH_H

#include <stddef.h>

/* where a key's number goes in the text */
typedef struct bd_key_site {
    size_t at;              /* byte offset in the text */
    size_t len;             /* bytes of the number there (0: the key is
                               added, wrapped in before and after) */
    char before[320];       /* an added key: the text before its number */
    char after[64];         /*   and after it */
    char adds[64];          /* an added key: the first key it adds */
    double value;           /* the number the file has, NaN when added */
} bd_key_site;

/* find key (e.g. "pulleys.takeup.takeup.mass", "idlers[0].spacing", a
 * list entry by its `name` or its index) in the model text. A key the
 * file does not have is added to the deepest mapping on its path that it
 * has, and the loader then says whether the model takes it. 0, or -1
 * with a message naming the key and what is wrong */
int bd_key_find(const char *text, size_t len, const char *key, bd_key_site *site, char *err,
                size_t errlen);

/* the text with n sites set to values (each written as %.17g: the same
 * double when read back). Sites must not overlap; two added at one place
 * must add different keys. malloc'ed (*outlen bytes, NUL-terminated), NULL
 * out of memory or when two sites are one number (or overlap) */
char *bd_key_apply(const char *text, size_t len, const bd_key_site *sites, const double *values,
                   int n, size_t *outlen);

#endif
