/* A case's result file, out_dir/<case>/case.json (study_case.h). The
 * worker that ran the case writes it after the run's outputs are closed,
 * whole under a temporary name and renamed, so it exists only complete:
 * that is what "complete" means to --resume. It names the case by its
 * definition (its start or its keys' values, its duration) and the model
 * file by a hash of its text, so a result is kept only for the same case
 * of the same model; numbers are written with 17 digits (read back as the
 * same double: a resumed table is the serial one bit for bit), non-finite
 * ones as "nan", "inf", "-inf". Only a completed or failed case counts as
 * done; an interrupted one has no file and runs again. */
#include "study/study_case.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "io/html.h"

#define PATH_LEN 2048

typedef struct field {
    const char *name;
    size_t off;
    int is_int;
} field;

static const field fields[] = {
    {"drives", offsetof(bd_run_result, drives), 1},
    {"tight_max_N", offsetof(bd_run_result, tight_max_N), 0},
    {"tight_max_t_s", offsetof(bd_run_result, tight_max_t_s), 0},
    {"slack_min_N", offsetof(bd_run_result, slack_min_N), 0},
    {"slack_min_t_s", offsetof(bd_run_result, slack_min_t_s), 0},
    {"tight_swing_N", offsetof(bd_run_result, tight_swing_N), 0},
    {"accel_max_mps2", offsetof(bd_run_result, accel_max_mps2), 0},
    {"accel_max_t_s", offsetof(bd_run_result, accel_max_t_s), 0},
    {"torque_max_Nm", offsetof(bd_run_result, torque_max_Nm), 0},
    {"slipped", offsetof(bd_run_result, slipped), 1},
    {"slip_t_s", offsetof(bd_run_result, slip_t_s), 0},
    {"slip_longest_s", offsetof(bd_run_result, slip_longest_s), 0},
    {"slip_speed_max_mps", offsetof(bd_run_result, slip_speed_max_mps), 0},
    {"travel_range_m", offsetof(bd_run_result, travel_range_m), 0},
    {"tension_max_N", offsetof(bd_run_result, tension_max_N), 0},
    {"tension_min_N", offsetof(bd_run_result, tension_min_N), 0},
};
#define NFIELDS ((int)(sizeof fields / sizeof fields[0]))

/* what makes the case this case: its start or its keys, its duration */
static void definition(const bd_study *s, const bd_study_case *c, char *buf, size_t len)
{
    size_t o = (size_t)snprintf(buf, len, "duration %.17g s", c->duration);
    if (s->kind == BD_STUDY_START)
        snprintf(buf + o, len - o, "; start %s, time %.17g s, delay %.17g s",
                 bd_start_curve_name(c->curve), c->time, c->delay);
    else if (s->kind == BD_STUDY_CASES)
        snprintf(buf + o, len - o, "; %s; records from %.17g s", c->setup, c->records_from);
    else
        for (int k = 0; k < s->nkeys && o < len; k++)
            o += (size_t)snprintf(buf + o, len - o, "; %s = %.17g", s->keys[k].key,
                                  c->values[k]);
}

/* out_dir/<case>/case.json; 0, or -1 when the path is too long */
static int path_of(const bd_study *s, const bd_study_case *c, char *buf, size_t len)
{
    char dir[PATH_LEN];
    return bd_path_join(dir, sizeof dir, s->opt->out_dir, c->name)
           || bd_path_join(buf, len, dir, "case.json") ? -1 : 0;
}

/* a double as JSON that reads back the same: 17 digits, or a word */
static cJSON *exact(double v)
{
    char buf[40];
    if (isnan(v))
        return cJSON_CreateString("nan");
    if (isinf(v))
        return cJSON_CreateString(v > 0 ? "inf" : "-inf");
    snprintf(buf, sizeof buf, "%.17g", v);
    return cJSON_CreateRaw(buf);
}

static int read_exact(const cJSON *o, const char *key, double *v)
{
    const cJSON *x = cJSON_GetObjectItemCaseSensitive(o, key);
    if (cJSON_IsNumber(x)) {
        *v = x->valuedouble;
        return 0;
    }
    if (cJSON_IsString(x)) {
        char *end;
        *v = strtod(x->valuestring, &end);
        return *end == '\0' && !isfinite(*v) ? 0 : -1;
    }
    return -1;
}

static char hex_hash[17];

static const char *hash_text(const bd_study *s)
{
    snprintf(hex_hash, sizeof hex_hash, "%016llx", (unsigned long long)s->model_hash);
    return hex_hash;
}

int bd_study_record_write(const bd_study *s, const bd_study_case *c, const bd_job_result *r,
                          char *err, size_t errlen)
{
    if (r->status != BD_RUN_OK && r->status != BD_RUN_FAILED)
        return 0;   /* interrupted or not built: it runs again */
    char def[2048], path[PATH_LEN];
    definition(s, c, def, sizeof def);
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "case", c->name);
    cJSON_AddStringToObject(o, "definition", def);
    cJSON_AddStringToObject(o, "model_hash", hash_text(s));
    cJSON_AddStringToObject(o, "status", bd_study_status_word(r->status));
    cJSON_AddItemToObject(o, "wall_time_s", exact(r->wall_s));
    cJSON_AddStringToObject(o, "message", r->message);
    cJSON *res = cJSON_AddObjectToObject(o, "result");
    for (int k = 0; k < NFIELDS; k++) {
        const char *p = (const char *)&r->res + fields[k].off;
        if (fields[k].is_int) {
            int v;
            memcpy(&v, p, sizeof v);
            cJSON_AddNumberToObject(res, fields[k].name, v);
        } else {
            double v;
            memcpy(&v, p, sizeof v);
            cJSON_AddItemToObject(res, fields[k].name, exact(v));
        }
    }
    char *text = cJSON_Print(o);
    cJSON_Delete(o);
    if (!text) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    bd_strbuf b = {0};
    bd_sb_puts(&b, text);
    bd_sb_puts(&b, "\n");
    free(text);
    if (path_of(s, c, path, sizeof path)) {
        free(b.p);
        snprintf(err, errlen, "%s/%s: path too long", s->opt->out_dir, c->name);
        return -1;
    }
    return bd_html_write(&b, path, err, errlen) ? -1 : 0;
}

int bd_study_record_read(const bd_study *s, bd_study_case *c)
{
    char path[PATH_LEN], def[2048];
    if (path_of(s, c, path, sizeof path))
        return 0;
    char *text;
    size_t len;
    if (bd_read_file(path, &text, &len) != BD_READ_OK)
        return 0;   /* none, or unreadable: the case runs again */
    cJSON *o = cJSON_Parse(text);
    free(text);
    definition(s, c, def, sizeof def);
    const cJSON *name = cJSON_GetObjectItemCaseSensitive(o, "case");
    const cJSON *d = cJSON_GetObjectItemCaseSensitive(o, "definition");
    const cJSON *h = cJSON_GetObjectItemCaseSensitive(o, "model_hash");
    const cJSON *st = cJSON_GetObjectItemCaseSensitive(o, "status");
    const cJSON *res = cJSON_GetObjectItemCaseSensitive(o, "result");
    const cJSON *msg = cJSON_GetObjectItemCaseSensitive(o, "message");
    int ok = cJSON_IsString(name) && strcmp(name->valuestring, c->name) == 0
             && cJSON_IsString(d) && strcmp(d->valuestring, def) == 0 && cJSON_IsString(h)
             && strcmp(h->valuestring, hash_text(s)) == 0 && cJSON_IsString(st)
             && cJSON_IsObject(res);
    int status = -1;
    if (ok && strcmp(st->valuestring, "completed") == 0)
        status = BD_RUN_OK;
    else if (ok && strcmp(st->valuestring, "failed") == 0)
        status = BD_RUN_FAILED;
    ok = ok && status >= 0;
    snprintf(c->message, sizeof c->message, "%s",
             ok && cJSON_IsString(msg) ? msg->valuestring : "");
    bd_run_result r;
    memset(&r, 0, sizeof r);
    double wall = 0.0;
    ok = ok && read_exact(o, "wall_time_s", &wall) == 0;
    for (int k = 0; ok && k < NFIELDS; k++) {
        double v;
        ok = read_exact(res, fields[k].name, &v) == 0;
        char *p = (char *)&r + fields[k].off;
        if (ok && fields[k].is_int) {
            int iv = (int)v;
            memcpy(p, &iv, sizeof iv);
        } else if (ok) {
            memcpy(p, &v, sizeof v);
        }
    }
    cJSON_Delete(o);
    if (!ok)
        return 0;
    c->status = status;
    c->wall_s = wall;
    c->res = r;
    return 1;
}

void bd_study_record_remove(const bd_study *s, const bd_study_case *c)
{
    char path[PATH_LEN];
    if (path_of(s, c, path, sizeof path) == 0)
        remove(path);
}
