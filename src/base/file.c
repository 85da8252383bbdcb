#include "base/file.h"

#include <dirent.h>
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int bd_read_file(const char *path, char **text, size_t *len)
{
    *text = NULL;
    *len = 0;
    FILE *f = fopen(path, "rb");
    if (!f)
        return BD_READ_OPEN;
    char *buf = NULL;
    size_t n = 0, cap = 0;
    for (;;) {
        /* room for the next chunk (doubling from 64 kB) and the NUL */
        if (n == cap) {
            size_t grown = cap ? 2 * cap : 65536;
            char *more = grown > cap && grown < SIZE_MAX ? realloc(buf, grown + 1) : NULL;
            if (!more) {
                free(buf);
                fclose(f);
                errno = ENOMEM;
                return BD_READ_NOMEM;
            }
            buf = more;
            cap = grown;
        }
        errno = 0;
        size_t got = fread(buf + n, 1, cap - n, f);
        n += got;
        if (got == 0)
            break;
    }
    if (ferror(f)) {
        int e = errno ? errno : EIO;
        free(buf);
        fclose(f);
        errno = e;
        return BD_READ_ERROR;
    }
    fclose(f);
    buf[n] = '\0';
    *text = buf;
    *len = n;
    return BD_READ_OK;
}

int bd_path_join(char *out, size_t cap, const char *dir, const char *name)
{
    int n = snprintf(out, cap, "%s/%s", dir, name);
    if (n < 0 || (size_t)n >= cap) {
        if (cap > 0)
            out[0] = '\0';
        return -1;
    }
    return 0;
}

int bd_dir_state(const char *path, const char *const *marks, int count)
{
    struct stat st;
    if (stat(path, &st) != 0)
        return errno == ENOENT ? BD_DIR_EMPTY : BD_DIR_BAD;
    if (!S_ISDIR(st.st_mode))
        return BD_DIR_BAD;
    DIR *d = opendir(path);
    if (!d)
        return BD_DIR_BAD;
    int empty = 1, marked = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        empty = 0;
        for (int k = 0; k < count; k++)
            marked = marked || strcmp(e->d_name, marks[k]) == 0;
    }
    closedir(d);
    return empty ? BD_DIR_EMPTY : (marked ? BD_DIR_MARKED : BD_DIR_OTHER);
}
