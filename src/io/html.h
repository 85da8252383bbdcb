/* small pieces for writing self-contained HTML pages (the report of a run
 * and of a start study): a growing text buffer, HTML escaping, PNG files
 * embedded as base64 data URIs, the pages' style sheet, and writing the
 * page through a temporary name. */
#ifndef BD_IO_HTML_H
#define BD_IO_HTML_H

#include <stddef.h>

/* text that grows as needed; oom is set (and further output dropped) when
 * memory runs out. Start from {0}; free(p) when done. */
typedef struct bd_strbuf {
    char *p;
    size_t n, cap;
    int oom;
} bd_strbuf;

void bd_sb_grow(bd_strbuf *b, size_t more);
void bd_sb_put(bd_strbuf *b, const char *s, size_t len);
void bd_sb_puts(bd_strbuf *b, const char *s);
void bd_sb_printf(bd_strbuf *b, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* text with &, <, >, " escaped */
void bd_sb_html(bd_strbuf *b, const char *s);
/* a table cell of a JSON value: a number right-aligned to 4 digits, a
 * bool as yes/no, text escaped, anything else as — */
struct cJSON;
void bd_sb_json_cell(bd_strbuf *b, const struct cJSON *v);
void bd_sb_base64(bd_strbuf *b, const unsigned char *d, size_t n);
/* "data:image/png;base64,..." of the PNG file at path; 0, or -1 */
int bd_sb_embed_png(bd_strbuf *b, const char *path);

/* a page's start, up to its <h1>: "TITLE — beltdyn WHAT" in the tab */
void bd_sb_page_start(bd_strbuf *b, const char *title, const char *what);

/* <figure> of plots_dir/NAME.png embedded, with the caption and a word of
 * plots/NAME.svg; 0, or -1 with a message in err */
int bd_sb_figure(bd_strbuf *b, const char *plots_dir, const char *name, const char *caption,
                 char *err, size_t errlen);

/* the style sheet of the pages */
extern const char *const bd_html_css;

/* write b (a page, or any text file: the study's tables, a case's
 * case.json) to path through path.tmp and a rename, and free b's text;
 * 0, or -1 with a message in err */
int bd_html_write(bd_strbuf *b, const char *path, char *err, size_t errlen);

/* close a page and write it as DIR/report.html (bd_html_write); 0, or -1
 * with a message in err */
int bd_html_page_finish(bd_strbuf *b, const char *dir, char *err, size_t errlen);

/* 1: a case's name from a study's table can name its directory under the
 * study's (not empty, no '/', no "..": a table edited by hand cannot point
 * a link or a report outside, or at the study's own page) */
int bd_case_name_ok(const char *name);

#endif
