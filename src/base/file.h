/* Files for the readers and writers above (model/, io/, study/): a file
 * read into memory in one piece, a directory and a name joined. */
#ifndef BD_FILE_H
#define BD_FILE_H

#include <stddef.h>

/* what bd_read_file returns */
enum {
    BD_READ_OK = 0,
    BD_READ_OPEN = -1,    /* the file cannot be opened (errno: fopen's) */
    BD_READ_ERROR = -2,   /* reading it failed (errno: the read's, or EIO) */
    BD_READ_NOMEM = -3    /* out of memory (errno: ENOMEM) */
};

/* the whole file at path into *text (malloc'ed, a NUL after its *len
 * bytes; free it), or one of the codes above with *text NULL, *len 0 and
 * nothing left open or allocated */
int bd_read_file(const char *path, char **text, size_t *len);

/* "dir/name" into out (cap bytes); 0, or -1 when it does not fit (out is
 * then ""): a path too long is an error, never a file name cut short */
int bd_path_join(char *out, size_t cap, const char *dir, const char *name);

/* what directory `path` holds (an output directory before it is written):
 * BD_DIR_EMPTY (nothing, or it does not exist), BD_DIR_MARKED (one of the
 * `count` names in `marks`: an earlier output of that kind), BD_DIR_OTHER
 * (something else), BD_DIR_BAD (not a directory that can be read) */
enum { BD_DIR_EMPTY = 1, BD_DIR_MARKED = 2, BD_DIR_OTHER = 0, BD_DIR_BAD = -1 };
int bd_dir_state(const char *path, const char *const *marks, int count);

#endif
