/* HTML page helpers (html.h) */
#include "io/html.h"

#include "base/file.h"

#include <cjson/cJSON.h>

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


void bd_sb_grow(bd_strbuf *b, size_t more)
{
    if (b->oom || b->n + more + 1 <= b->cap) return;
    size_t cap = b->cap ? b->cap : 65536;
    while (cap < b->n + more + 1) cap *= 2;
    char *q = realloc(b->p, cap);
    if (!q) {
        b->oom = 1;
        return;
    }
    b->p = q;
    b->cap = cap;
}

void bd_sb_put(bd_strbuf *b, const char *s, size_t len)
{
    bd_sb_grow(b, len);
    if (b->oom) return;
    memcpy(b->p + b->n, s, len);
    b->n += len;
    b->p[b->n] = '\0';
}

void bd_sb_puts(bd_strbuf *b, const char *s) { bd_sb_put(b, s, strlen(s)); }

void bd_sb_printf(bd_strbuf *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int len = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (len < 0) return;
    bd_sb_grow(b, (size_t)len);
    if (b->oom) return;
    va_start(ap, fmt);
    vsnprintf(b->p + b->n, (size_t)len + 1, fmt, ap);
    va_end(ap);
    b->n += (size_t)len;
}

/* text with &, <, >, " escaped */
void bd_sb_html(bd_strbuf *b, const char *s)
{
    for (; s && *s; s++) {
        switch (*s) {
        case '&': bd_sb_puts(b, "&amp;"); break;
        case '<': bd_sb_puts(b, "&lt;"); break;
        case '>': bd_sb_puts(b, "&gt;"); break;
        case '"': bd_sb_puts(b, "&quot;"); break;
        default: bd_sb_put(b, s, 1);
        }
    }
}

void bd_sb_base64(bd_strbuf *b, const unsigned char *d, size_t n)
{
    static const char tab[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    bd_sb_grow(b, (n + 2) / 3 * 4);
    if (b->oom) return;
    char *o = b->p + b->n;
    size_t i = 0;
    for (; i + 2 < n; i += 3) {
        unsigned v = (unsigned)d[i] << 16 | (unsigned)d[i + 1] << 8 | d[i + 2];
        *o++ = tab[v >> 18 & 63];
        *o++ = tab[v >> 12 & 63];
        *o++ = tab[v >> 6 & 63];
        *o++ = tab[v & 63];
    }
    if (i < n) {
        unsigned v = (unsigned)d[i] << 16 | (i + 1 < n ? (unsigned)d[i + 1] << 8 : 0u);
        *o++ = tab[v >> 18 & 63];
        *o++ = tab[v >> 12 & 63];
        *o++ = i + 1 < n ? tab[v >> 6 & 63] : '=';
        *o++ = '=';
    }
    b->n = (size_t)(o - b->p);
    b->p[b->n] = '\0';
}

int bd_sb_embed_png(bd_strbuf *b, const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) return -1;
    fseek(fp, 0, SEEK_END);
    long len = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    unsigned char *d = len > 0 ? malloc((size_t)len) : NULL;
    int rc = -1;
    if (d && fread(d, 1, (size_t)len, fp) == (size_t)len) {
        bd_sb_puts(b, "data:image/png;base64,");
        bd_sb_base64(b, d, (size_t)len);
        rc = 0;
    }
    free(d);
    fclose(fp);
    return rc;
}

void bd_sb_page_start(bd_strbuf *b, const char *title, const char *what)
{
    bd_sb_puts(b, "<!DOCTYPE html>\n<html lang=en><head><meta charset=utf-8>\n<title>");
    bd_sb_html(b, title);
    bd_sb_printf(b, " — beltdyn %s</title>\n<style>", what);
    bd_sb_puts(b, bd_html_css);
    bd_sb_puts(b, "</style></head><body><main>\n<h1>");
    bd_sb_html(b, title);
    bd_sb_puts(b, "</h1>\n");
}

int bd_sb_figure(bd_strbuf *b, const char *plots_dir, const char *name, const char *caption,
                 char *err, size_t errlen)
{
    char png[4096];
    if (snprintf(png, sizeof png, "%s/%s.png", plots_dir, name) >= (int)sizeof png) {
        snprintf(err, errlen, "%s: path too long", plots_dir);
        return -1;
    }
    bd_sb_printf(b, "<figure id=\"%s\"><img alt=\"%s\" src=\"", name, name);
    if (bd_sb_embed_png(b, png)) {
        snprintf(err, errlen, "%s: cannot read back", png);
        return -1;
    }
    bd_sb_puts(b, "\"><figcaption>");
    bd_sb_html(b, caption);
    bd_sb_printf(b, " (also plots/%s.svg)</figcaption></figure>\n", name);
    return 0;
}

const char *const bd_html_css =
    "body{font-family:'DejaVu Sans',Arial,sans-serif;margin:0;background:#f4f5f7;color:#1a1a1a}"
    "main{max-width:1240px;margin:0 auto;padding:16px 24px 48px}"
    "h1{font-size:26px;margin:18px 0 2px}h2{font-size:20px;margin:28px 0 8px;"
    "border-bottom:2px solid #d0d4da;padding-bottom:4px}"
    ".sub{color:#555;margin:0 0 14px}"
    ".cards{display:flex;flex-wrap:wrap;gap:12px}"
    ".card{background:#fff;border:1px solid #d0d4da;border-left:6px solid #0072b2;"
    "border-radius:6px;padding:10px 14px;flex:1 1 220px;max-width:calc(25% - 9px);"
    "box-sizing:border-box}"
    ".card.bad{border-left-color:#c00000}.card.ok{border-left-color:#009e73}"
    "td.bad{color:#c00000;font-weight:600}td.ok{color:#007a5a;font-weight:600}"
    ".card .k{font-size:13px;color:#555;text-transform:uppercase;letter-spacing:.04em}"
    ".card .v{font-size:28px;font-weight:bold;margin:2px 0}"
    ".card .d{font-size:14px;color:#333}"
    "table{border-collapse:collapse;background:#fff;margin:6px 0 12px;font-size:14px}"
    "th,td{border:1px solid #d0d4da;padding:4px 10px;text-align:left}"
    "td.n{text-align:right;font-variant-numeric:tabular-nums}"
    "th{background:#e9ecf0}"
    ".warn{background:#fff4e5;border:1px solid #e69f00;border-radius:6px;padding:8px 16px 8px 34px}"
    ".warn li{margin:4px 0}.none{color:#555}"
    "figure{background:#fff;border:1px solid #d0d4da;border-radius:6px;margin:14px 0;padding:8px}"
    "figure img{width:100%;height:auto;display:block}"
    "figcaption{font-size:14px;color:#333;padding:6px 4px 0}"
    "nav a{margin-right:14px}";

int bd_html_write(bd_strbuf *b, const char *path, char *err, size_t errlen)
{
    char tmp[4200];
    if (b->oom) {
        free(b->p);
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    if (snprintf(tmp, sizeof tmp, "%s.tmp", path) >= (int)sizeof tmp) {
        free(b->p);
        snprintf(err, errlen, "%s: path too long", path);
        return -1;
    }
    FILE *fp = fopen(tmp, "wb");
    int ok = fp && fwrite(b->p, 1, b->n, fp) == b->n;
    if (fp && fclose(fp) != 0) ok = 0;
    free(b->p);
    b->p = NULL;
    if (!ok || rename(tmp, path) != 0) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        remove(tmp);
        return -1;
    }
    return 0;
}

int bd_html_page_finish(bd_strbuf *b, const char *dir, char *err, size_t errlen)
{
    char path[4096];
    bd_sb_puts(b, "</main></body></html>\n");
    if (bd_path_join(path, sizeof path, dir, "report.html")) {
        free(b->p);
        b->p = NULL;
        snprintf(err, errlen, "%s: path too long", dir);
        return -1;
    }
    return bd_html_write(b, path, err, errlen);
}

void bd_sb_json_cell(bd_strbuf *b, const cJSON *v)
{
    if (cJSON_IsNumber(v)) {
        bd_sb_printf(b, "<td class=n>%.4g</td>", v->valuedouble);
    } else if (cJSON_IsBool(v)) {
        bd_sb_puts(b, cJSON_IsTrue(v) ? "<td>yes</td>" : "<td>no</td>");
    } else {
        bd_sb_puts(b, "<td>");
        bd_sb_html(b, cJSON_IsString(v) ? v->valuestring : "—");
        bd_sb_puts(b, "</td>");
    }
}

int bd_case_name_ok(const char *name)
{
    return name[0] && !strchr(name, '/') && !strstr(name, "..");
}
