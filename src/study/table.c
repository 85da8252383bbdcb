/* The study's tables (study_case.h): DIR/study.csv, DIR/study.json and the
 * rows on the terminal. One list of columns serves all three and --best:
 *
 *   start study  case, curve, start_time_s, delay_s, creep_speed_mps,
 *   sweep        case, one column per varied key (named by the key),
 *   both         status, what the run compares by (bd_run_result), wall_time_s,
 *                message (why the case did not complete, or empty).
 *
 * Rows are the cases that have a result, in case order whatever order they
 * finished in, so that a parallel run writes a serial run's table. Each
 * file is written whole under a temporary name and renamed. */
#include "study/study_case.h"

#include <cjson/cJSON.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "base/json_util.h"
#include "io/html.h"

#define PATH_LEN 2048

/* what a run compares by, in the table's order, with its CSV format */
typedef struct out_col {
    const char *name;
    const char *fmt;
    size_t off;          /* in bd_run_result */
    int is_int;          /* slipped: an int, a bool in JSON */
} out_col;

static const out_col outs[] = {
    {"tight_tension_max_N", "%.6g", offsetof(bd_run_result, tight_max_N), 0},
    {"tight_tension_max_time_s", "%.4f", offsetof(bd_run_result, tight_max_t_s), 0},
    {"slack_tension_min_N", "%.6g", offsetof(bd_run_result, slack_min_N), 0},
    {"slack_tension_min_time_s", "%.4f", offsetof(bd_run_result, slack_min_t_s), 0},
    {"tight_tension_swing_N", "%.6g", offsetof(bd_run_result, tight_swing_N), 0},
    {"belt_accel_max_mps2", "%.5g", offsetof(bd_run_result, accel_max_mps2), 0},
    {"belt_accel_max_time_s", "%.4f", offsetof(bd_run_result, accel_max_t_s), 0},
    {"takeup_travel_range_m", "%.5g", offsetof(bd_run_result, travel_range_m), 0},
    {"drive_torque_max_Nm", "%.6g", offsetof(bd_run_result, torque_max_Nm), 0},
    {"slipped", "%d", offsetof(bd_run_result, slipped), 1},
    {"slip_longest_s", "%.4f", offsetof(bd_run_result, slip_longest_s), 0},
    {"slip_speed_max_mps", "%.4g", offsetof(bd_run_result, slip_speed_max_mps), 0},
    {"belt_tension_max_N", "%.6g", offsetof(bd_run_result, tension_max_N), 0},
    {"belt_tension_min_N", "%.6g", offsetof(bd_run_result, tension_min_N), 0},
};
#define NOUTS ((int)(sizeof outs / sizeof outs[0]))

const char *bd_study_status_word(int status)
{
    switch (status) {
    case BD_RUN_OK: return "completed";
    case BD_RUN_FAILED: return "failed";
    case BD_RUN_INTERRUPTED: return "interrupted";
    case -1: return "not run";
    default: return "bad input";
    }
}

const char *bd_study_table_name(const bd_study *s)
{
    return s->kind == BD_STUDY_CASES ? "cases" : "study";
}

/* the columns before `status` */
static int lead_count(const bd_study *s)
{
    return s->kind == BD_STUDY_START ? 5 : s->kind == BD_STUDY_CASES ? 3 : 1 + s->nkeys;
}

static int column_count(const bd_study *s)
{
    return lead_count(s) + 1 + NOUTS + 2;
}

static const char *const start_lead[] = {"case", "curve", "start_time_s", "delay_s",
                                          "creep_speed_mps"};
static const char *const cases_lead[] = {"case", "setup", "records_from_s"};

/* column i's name and CSV format */
static const char *column_at(const bd_study *s, int i, const char **fmt)
{
    int lead = lead_count(s);
    if (i < lead && s->kind == BD_STUDY_CASES) {
        *fmt = i < 2 ? "%s" : "%g";
        return cases_lead[i];
    }
    if (i < lead) {
        if (i == 0 || (s->kind == BD_STUDY_START && i == 1)) {
            *fmt = "%s";
            return start_lead[i];
        }
        if (s->kind == BD_STUDY_START) {
            *fmt = "%g";
            return start_lead[i];
        }
        *fmt = "%.12g";
        return s->keys[i - 1].key;
    }
    i -= lead;
    if (i == 0) {
        *fmt = "%s";
        return "status";
    }
    if (i <= NOUTS) {
        *fmt = outs[i - 1].fmt;
        return outs[i - 1].name;
    }
    if (i == NOUTS + 1) {
        *fmt = "%.2f";
        return "wall_time_s";
    }
    *fmt = "%s";
    return "message";
}

int bd_study_column(const bd_study *s, const bd_study_case *c, const char *col, double *num,
                    const char **text)
{
    static const bd_study_case none;
    if (!c)
        c = &none;
    if (strcmp(col, "case") == 0) {
        *text = c->name;
        return 2;
    }
    if (strcmp(col, "status") == 0) {
        *text = bd_study_status_word(c->status);
        return 2;
    }
    if (strcmp(col, "message") == 0) {
        *text = c->message;
        return 2;
    }
    if (strcmp(col, "wall_time_s") == 0) {
        *num = c->wall_s;
        return 1;
    }
    if (s->kind == BD_STUDY_CASES) {
        if (strcmp(col, "setup") == 0) {
            *text = c->setup;
            return 2;
        }
        if (strcmp(col, "records_from_s") == 0) {
            *num = c->records_from;
            return 1;
        }
    } else if (s->kind == BD_STUDY_START) {
        if (strcmp(col, "curve") == 0) {
            *text = bd_start_curve_name(c->curve);
            return 2;
        }
        const double v[3] = {c->time, c->delay, c->creep};
        for (int k = 0; k < 3; k++)
            if (strcmp(col, start_lead[2 + k]) == 0) {
                *num = v[k];
                return 1;
            }
    } else {
        for (int k = 0; k < s->nkeys; k++)
            if (strcmp(col, s->keys[k].key) == 0) {
                *num = c->values ? c->values[k] : 0.0;
                return 1;
            }
    }
    for (int k = 0; k < NOUTS; k++)
        if (strcmp(col, outs[k].name) == 0) {
            const char *p = (const char *)&c->res + outs[k].off;
            if (outs[k].is_int) {
                int v;
                memcpy(&v, p, sizeof v);
                *num = v;
            } else {
                memcpy(num, p, sizeof *num);
            }
            return 1;
        }
    return 0;
}

void bd_study_column_names(const bd_study *s, char *buf, size_t len)
{
    size_t o = 0;
    buf[0] = '\0';
    for (int i = 0; i < column_count(s) && o + 1 < len; i++) {
        const char *fmt;
        o += (size_t)snprintf(buf + o, len - o, "%s%s", i ? ", " : "", column_at(s, i, &fmt));
    }
}

static int is_int_column(const char *name)
{
    return strcmp(name, "slipped") == 0;
}

/* a text field, quoted (RFC 4180) when it holds a comma, a quote or a
 * line break: a failed case's message may */
static void csv_field(bd_strbuf *b, const char *text)
{
    if (!strpbrk(text, ",\"\r\n")) {
        bd_sb_puts(b, text);
        return;
    }
    bd_sb_puts(b, "\"");
    for (const char *p = text; *p; p++)
        bd_sb_printf(b, *p == '"' ? "\"\"" : "%c", *p);
    bd_sb_puts(b, "\"");
}

static void csv_text(const bd_study *s, bd_strbuf *out)
{
    bd_strbuf b = {0};
    int nc = column_count(s);
    for (int i = 0; i < nc; i++) {
        const char *fmt;
        bd_sb_printf(&b, "%s%s", i ? "," : "", column_at(s, i, &fmt));
    }
    bd_sb_puts(&b, "\n");
    for (int j = 0; j < s->n; j++) {
        const bd_study_case *c = &s->cases[j];
        if (c->status < 0)
            continue;
        for (int i = 0; i < nc; i++) {
            const char *fmt, *name = column_at(s, i, &fmt), *text = "";
            double v = 0.0;
            if (i)
                bd_sb_puts(&b, ",");
            int kind = bd_study_column(s, c, name, &v, &text);
            if (kind == 2)
                csv_field(&b, text);
            else if (is_int_column(name))
                bd_sb_printf(&b, fmt, (int)v);
            else
                bd_sb_printf(&b, fmt, v);
        }
        bd_sb_puts(&b, "\n");
    }
    *out = b;
}

static char *json_text(const bd_study *s)
{
    const bd_model_def *def = &s->def;
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "model", def->name);
    cJSON_AddStringToObject(root, "model_file", def->source);
    cJSON_AddStringToObject(root, "slip_definition",
                            "drive pulley surface speed and belt speed at the pulley differ by "
                            "more than 0.05 m/s + 2% of the surface speed for at least 0.2 s");
    if (s->kind == BD_STUDY_CASES)
        cJSON_AddStringToObject(root, "kind", "load_cases");
    if (s->kind == BD_STUDY_GRID || s->kind == BD_STUDY_SAMPLE) {
        cJSON *sw = cJSON_AddObjectToObject(root, "sweep");
        cJSON_AddStringToObject(sw, "method", s->kind == BD_STUDY_GRID ? "grid"
                                                                       : "latin_hypercube");
        if (s->kind == BD_STUDY_SAMPLE) {
            cJSON_AddNumberToObject(sw, "samples", s->opt->samples);
            char seed[32];
            snprintf(seed, sizeof seed, "%llu", s->opt->seed);
            cJSON_AddRawToObject(sw, "seed", seed);
        }
        cJSON *keys = cJSON_AddArrayToObject(sw, "keys");
        for (int k = 0; k < s->nkeys; k++) {
            cJSON *o = cJSON_CreateObject();
            cJSON_AddStringToObject(o, "key", s->keys[k].key);
            bd_json_add_number(o, "lo", s->keys[k].lo);
            bd_json_add_number(o, "hi", s->keys[k].hi);
            if (s->kind == BD_STUDY_GRID)
                cJSON_AddNumberToObject(o, "n", s->keys[k].n);
            bd_json_add_number(o, "model_value", s->sites[k].value);
            cJSON_AddItemToArray(keys, o);
        }
    }
    cJSON *cases = cJSON_AddArrayToObject(root, "cases");
    int nc = column_count(s);
    for (int j = 0; j < s->n; j++) {
        const bd_study_case *c = &s->cases[j];
        if (c->status < 0)
            continue;
        cJSON *o = cJSON_CreateObject();
        for (int i = 0; i < nc; i++) {
            const char *fmt, *name = column_at(s, i, &fmt), *text = "";
            double v = 0.0;
            int kind = bd_study_column(s, c, name, &v, &text);
            if (kind == 2)
                cJSON_AddStringToObject(o, name, text);
            else if (is_int_column(name))
                cJSON_AddBoolToObject(o, name, v != 0.0);
            else
                bd_json_add_number(o, name, v);
        }
        cJSON_AddItemToArray(cases, o);
    }
    if (s->best != -2) {
        cJSON *b = cJSON_AddObjectToObject(root, "best");
        char what[600];
        bd_study_best_describe(s, what, sizeof what);
        cJSON_AddStringToObject(b, "asked", what);
        if (s->best >= 0) {
            double v = 0.0;
            const char *text, *col = bd_study_best_column(s);
            cJSON_AddStringToObject(b, "case", s->cases[s->best].name);
            if (bd_study_column(s, &s->cases[s->best], col, &v, &text) == 1)
                bd_json_add_number(b, "value", v);
        } else {
            cJSON_AddNullToObject(b, "case");
        }
    }
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    return text;
}

int bd_study_write_tables(const bd_study *s, char *err, size_t errlen)
{
    char path[PATH_LEN];
    bd_strbuf csv = {0}, json = {0};
    csv_text(s, &csv);
    char *text = json_text(s);
    if (text) {
        bd_sb_puts(&json, text);
        bd_sb_puts(&json, "\n");
    } else {
        json.oom = 1;
    }
    free(text);
    /* each whole through a temporary name and a rename */
    char csv_name[16], json_name[16];
    snprintf(csv_name, sizeof csv_name, "%s.csv", bd_study_table_name(s));
    snprintf(json_name, sizeof json_name, "%s.json", bd_study_table_name(s));
    if (bd_path_join(path, sizeof path, s->opt->out_dir, json_name)) {
        free(csv.p);
        free(json.p);
        snprintf(err, errlen, "%s: path too long", s->opt->out_dir);
        return 1;
    }
    bd_path_join(path, sizeof path, s->opt->out_dir, csv_name);   /* as long: fits */
    if (bd_html_write(&csv, path, err, errlen)) {
        free(json.p);
        return 1;
    }
    bd_path_join(path, sizeof path, s->opt->out_dir, json_name);
    return bd_html_write(&json, path, err, errlen) ? 1 : 0;
}

/* ---- the rows on the terminal ---- */

void bd_study_table_header(const bd_study *s, FILE *f)
{
    for (int k = 0; k < s->nkeys; k++)
        fprintf(f, "  k%d = %s\n", k + 1, s->keys[k].key);
    fprintf(f, "%-22s", "case");
    for (int k = 0; k < s->nkeys; k++) {
        char h[16];
        snprintf(h, sizeof h, "k%d", k + 1);
        fprintf(f, " %11s", h);
    }
    fprintf(f, " %9s %7s %9s %9s %9s %7s %8s %9s %5s %7s\n", "T_tight", "at", "T_slack",
            "T_tight", "a_max", "travel", "M_max", "T_belt", "slip", "wall");
    fprintf(f, "%-22s", "");
    for (int k = 0; k < s->nkeys; k++)
        fprintf(f, " %11s", "");
    fprintf(f, " %9s %7s %9s %9s %9s %7s %8s %9s %5s %7s\n", "max [kN]", "[s]", "min [kN]",
            "swing[kN]", "[m/s2]", "[m]", "[kN m]", "max [kN]", "", "[s]");
}

void bd_study_table_row(const bd_study *s, FILE *f, const bd_study_case *c)
{
    const bd_run_result *r = &c->res;
    fprintf(f, "%-22s", c->name);
    for (int k = 0; k < s->nkeys; k++)
        fprintf(f, " %11.5g", c->values ? c->values[k] : 0.0);
    fprintf(f, " %9.2f %7.2f %9.2f %9.2f %9.3f %7.3f %8.2f %9.2f %5s %7.1f%s%s\n",
            r->tight_max_N / 1e3, r->tight_max_t_s, r->slack_min_N / 1e3,
            r->tight_swing_N / 1e3, r->accel_max_mps2, r->travel_range_m,
            r->torque_max_Nm / 1e3, r->tension_max_N / 1e3, r->slipped ? "yes" : "no", c->wall_s,
            c->status == BD_RUN_OK ? "" : "  ",
            c->status == BD_RUN_OK ? "" : bd_study_status_word(c->status));
    fflush(f);
}
