/* fast reading of the numeric CSV files a run writes (history.csv,
 * tension.csv, envelope.csv): one header row of column names, then rows of
 * numbers. The file is read in large blocks and parsed in place (no
 * allocation per line); only the requested columns are converted. */
#ifndef BD_IO_CSV_READ_H
#define BD_IO_CSV_READ_H

#include <stddef.h>

typedef struct bd_csv {
    int ncols;        /* number of columns kept */
    char **names;     /* [ncols] column names (owned) */
    size_t nrows;     /* number of data rows */
    double **col;     /* [ncols][nrows] values, column by column (owned) */
} bd_csv;

/* read PATH. want: NULL to keep every column, else nwant column names to
 * keep, in that order (a missing name is an error). A last line without a
 * newline and with too few fields (a run that was interrupted) is ignored;
 * any other malformed row is an error naming FILE:LINE. Fields that are
 * empty read as NaN. Returns 0, or -1 with a message in err. */
int bd_csv_read(const char *path, const char *const *want, int nwant,
                bd_csv *out, char *err, size_t errlen);

/* read only the header row: the column names (owned by out; nrows = 0) */
int bd_csv_read_header(const char *path, bd_csv *out, char *err, size_t errlen);

/* index of the column called NAME, or -1 */
int bd_csv_find(const bd_csv *csv, const char *name);

void bd_csv_free(bd_csv *csv);

/* parse one decimal number from [p, end); sets *next past it. Exact (same
 * result as strtod) for every input; fast for the usual short decimals. */
double bd_csv_parse_double(const char *p, const char *end, const char **next);

#endif
