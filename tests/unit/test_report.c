/* beltdyn report: fake run directories in, plots and report.html out.
 *
 * With no arguments: the unit tests. The same executable is a helper for
 * tests/cli/report_*.sh and scripts/bench_report.sh:
 *   test_report fake DIR [NELEM NTIMES] [--minimal]   write a plausible run DIR
 *   test_report report DIR                            bd_report_write(DIR)
 *   test_report pngcheck FILE MIN_COLOURS             a PNG with enough colours */
#include "testlib.h"

#include "beltdyn/report.h"
#include "io/csv_read.h"

#include <cairo.h>
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define PI 3.14159265358979323846

/* ---- a fake run: a starting conveyor with a tension wave running round ---- */

typedef struct fake_opts {
    int nelem, ntimes;
    int minimal;  /* no takeup, no tension.csv, no design values, no static table */
} fake_opts;

static const double belt_L = 2000.0;    /* m, loop length */
static const double wave_c = 700.0;     /* m/s */
static const double duration = 12.0;    /* s */

static double ramp(double t) { return t <= 0.0 ? 0.0 : t >= 6.0 ? 1.0 : 0.5 - 0.5 * cos(PI * t / 6.0); }

/* belt tension at position s (m from the drive), time t */
static double fake_tension(double s, double t)
{
    /* static distribution: tight side at the drive, slack after it,
     * rising along the carrying side */
    double u = s / belt_L;
    double stat = u < 0.5 ? 150e3 - 130e3 * u / 0.5 * 0.9 : 33e3 + 117e3 * (u - 0.5) / 0.5;
    double start = 0.6 + 0.4 * ramp(t);
    /* a start wave leaving the drive at t = 1 s, damped, running round */
    double T = stat * start;
    if (t > 1.0) {
        double front = fmod(wave_c * (t - 1.0), belt_L);
        double d = s - front;
        if (d > 0.5 * belt_L) d -= belt_L;
        if (d < -0.5 * belt_L) d += belt_L;
        T += 45e3 * exp(-0.25 * (t - 1.0)) * exp(-(d / 80.0) * (d / 80.0));
        /* a trough behind it */
        T -= 25e3 * exp(-0.3 * (t - 1.0)) * exp(-((d + 150.0) / 60.0) * ((d + 150.0) / 60.0));
    }
    return T;
}

static double fake_speed(double t) { return 4.5 * ramp(t - 0.5); }

static int write_fake(const char *dir, fake_opts o)
{
    char path[4096];
    mkdir(dir, 0777);
    double *emax = malloc((size_t)o.nelem * sizeof *emax);
    double *emin = malloc((size_t)o.nelem * sizeof *emin);
    if (!emax || !emin) return -1;
    for (int i = 0; i < o.nelem; i++) {
        emax[i] = -INFINITY;
        emin[i] = INFINITY;
    }
    double gmax = -INFINITY, gmin = INFINITY, gmax_t = 0, gmax_s = 0, gmin_t = 0, gmin_s = 0;

    /* tension.csv: long format, grouped by time */
    FILE *ft = NULL;
    if (!o.minimal) {
        snprintf(path, sizeof path, "%s/tension.csv", dir);
        ft = fopen(path, "w");
        if (!ft) return -1;
        setvbuf(ft, NULL, _IOFBF, 1 << 20);
        fputs("t_s,s_m,x_m,y_m,tension_N,speed_mps\n", ft);
    }
    for (int k = 0; k < o.ntimes; k++) {
        double t = duration * (double)k / (double)(o.ntimes - 1);
        double v = fake_speed(t);
        for (int i = 0; i < o.nelem; i++) {
            double s = belt_L * ((double)i + 0.5) / (double)o.nelem;
            double T = fake_tension(s, t);
            if (T > emax[i]) emax[i] = T;
            if (T < emin[i]) emin[i] = T;
            if (T > gmax) gmax = T, gmax_t = t, gmax_s = s;
            if (T < gmin) gmin = T, gmin_t = t, gmin_s = s;
            if (ft) {
                double x = s < 0.5 * belt_L ? s : belt_L - s;
                double y = s < 0.5 * belt_L ? 0.0 : -1.5;
                fprintf(ft, "%.4f,%.3f,%.3f,%.3f,%.1f,%.4f\n", t, s, x, y, T, v);
            }
        }
    }
    if (ft && fclose(ft)) return -1;

    /* envelope.csv */
    snprintf(path, sizeof path, "%s/envelope.csv", dir);
    FILE *fe = fopen(path, "w");
    if (!fe) return -1;
    fputs("s_m,tension_max_N,tension_min_N\n", fe);
    for (int i = 0; i < o.nelem; i++)
        fprintf(fe, "%.3f,%.1f,%.1f\n", belt_L * ((double)i + 0.5) / (double)o.nelem, emax[i], emin[i]);
    fclose(fe);

    /* history.csv */
    snprintf(path, sizeof path, "%s/history.csv", dir);
    FILE *fh = fopen(path, "w");
    if (!fh) return -1;
    fputs("t_s,HEAD.tension_N,HEAD.speed_mps,TAIL.tension_N,TAIL.speed_mps,"
          "DRIVE.omega_rad_s,DRIVE.torque_Nm", fh);
    if (!o.minimal) fputs(",TAKEUP.travel_m", fh);
    fputs(",kinetic_J,potential_J,dissipated_J,input_J\n", fh);
    int nh = 4 * o.ntimes;
    double K0 = 0.0, P0 = 2.5e6, tu_min = INFINITY, tu_max = -INFINITY, tq_max = 0.0;
    double in = 0.0;
    for (int k = 0; k < nh; k++) {
        double t = duration * (double)k / (double)(nh - 1);
        double v = fake_speed(t);
        double Th = fake_tension(0.05 * belt_L, t), Tt = fake_tension(0.55 * belt_L, t);
        double torque = 0.5 * (fake_tension(belt_L - 1.0, t) - fake_tension(1.0, t) + 140e3 * ramp(t));
        double travel = 0.8 * (1.0 - exp(-t / 2.0)) + 0.05 * sin(2.0 * PI * 0.6 * t) * exp(-0.2 * t);
        double K = 0.5 * 90e3 * v * v, P = P0 + 3e4 * sin(0.8 * t), D = 6e4 * t * ramp(t);
        in = (K - K0) + (P - P0) + D + 800.0 * sin(3.0 * t);  /* a small balance error */
        if (travel < tu_min) tu_min = travel;
        if (travel > tu_max) tu_max = travel;
        if (fabs(torque) > tq_max) tq_max = fabs(torque);
        fprintf(fh, "%.5f,%.2f,%.5f,%.2f,%.5f,%.5f,%.2f", t, Th, v, Tt, v * 1.001, v / 0.5, torque);
        if (!o.minimal) fprintf(fh, ",%.6f", travel);
        fprintf(fh, ",%.2f,%.2f,%.2f,%.2f\n", K, P, D, in);
    }
    fclose(fh);

    /* summary.json */
    snprintf(path, sizeof path, "%s/summary.json", dir);
    FILE *fs = fopen(path, "w");
    if (!fs) return -1;
    fprintf(fs,
            "{\n  \"model\": \"%s\",\n  \"duration_s\": %g, \"time_step_s\": 1.2e-4, \"steps\": 100000,\n"
            "  \"nodes\": %d, \"belt_length_m\": %g, \"wall_time_s\": 3.1,\n"
            "  \"tension\": {\"max_N\": %.1f, \"max_time_s\": %.4f, \"max_s_m\": %.3f,\n"
            "              \"min_N\": %.1f, \"min_time_s\": %.4f, \"min_s_m\": %.3f},\n"
            "  \"probes\": {\"HEAD\": {\"tension_max_N\": 1.5e5, \"tension_min_N\": 9e4, "
            "\"tension_final_N\": 1.4e5, \"speed_final_mps\": 4.5},\n"
            "             \"TAIL\": {\"tension_max_N\": 6e4, \"tension_min_N\": 2e4, "
            "\"tension_final_N\": 4e4, \"speed_final_mps\": 4.5}},\n",
            o.minimal ? "minimal & <test>" : "CV-01 overland (fake run)", duration, o.nelem + 1,
            belt_L, gmax, gmax_t, gmax_s, gmin, gmin_t, gmin_s);
    /* the full run gives the drive's radius (its plot then shows ω·R),
     * the minimal one does not (ω, as an older summary.json) */
    fprintf(fs, "  \"pulleys\": {\"DRIVE\": {\"omega_final_rad_s\": 9.0, \"torque_max_Nm\": %.1f%s, "
            "\"belt_accel_max_mps2\": 0.31}", tq_max, o.minimal ? "" : ", \"radius_m\": 0.5");
    if (!o.minimal)
        fprintf(fs, ",\n              \"TAKEUP\": {\"travel_min_m\": %.4f, \"travel_max_m\": %.4f}",
                tu_min, tu_max);
    fprintf(fs, "},\n  \"energy\": {\"kinetic_final_J\": 911250, \"balance_error_rel\": 0.0009},\n");
    if (!o.minimal) {
        fprintf(fs,
                "  \"rated_tension_N\": 1.6e6,\n"
                "  \"static\": {\"standard\": \"din22101\",\n"
                "    \"resistances_N\": {\"main\": 61000, \"secondary\": 9000, \"slope\": 0, \"total\": 70000},\n"
                "    \"effective_tension_N\": 70000, \"power_kW\": 315, \"T1_N\": 120000, \"T2_N\": 50000,\n"
                "    \"T2_min_slip_N\": 42000, \"T_min_sag_N\": 22000, \"takeup_force_N\": 100000,\n"
                "    \"spans\": [{\"from\": \"DRIVE\", \"length_m\": 990, \"T_start_N\": 50000, \"T_end_N\": 35000},\n"
                "              {\"from\": \"TAIL\", \"length_m\": 990, \"T_start_N\": 35000, \"T_end_N\": 120000}],\n"
                "    \"warnings\": [\"drive slips: pulley 'DRIVE' (static check)\"]},\n"
                "  \"warnings\": [\"belt lifts off idler 12 at t = 2.31 s\", \"tension below T_min_sag at s = 1000 m\"]\n");
    } else {
        fprintf(fs, "  \"warnings\": []\n");
    }
    fprintf(fs, "}\n");
    fclose(fs);
    free(emax);
    free(emin);
    return 0;
}

/* ---- checks on the output ---- */

static int png_magic(const char *path)
{
    unsigned char m[8] = {0};
    FILE *fp = fopen(path, "rb");
    if (!fp) return 0;
    size_t n = fread(m, 1, 8, fp);
    fclose(fp);
    static const unsigned char want[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    return n == 8 && memcmp(m, want, 8) == 0;
}

typedef struct png_stats {
    int w, h;
    int colours;         /* distinct colours (capped at 4096) */
    long ink;            /* non-white pixels in the middle 80 % */
} png_stats;

static int png_look(const char *path, png_stats *st)
{
    memset(st, 0, sizeof *st);
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(s);
        return -1;
    }
    st->w = cairo_image_surface_get_width(s);
    st->h = cairo_image_surface_get_height(s);
    int stride = cairo_image_surface_get_stride(s);
    const unsigned char *d = cairo_image_surface_get_data(s);
    static uint32_t seen[4096];
    int ns = 0;
    for (int y = 0; y < st->h; y++) {
        const uint32_t *row = (const uint32_t *)(const void *)(d + (size_t)y * (size_t)stride);
        for (int x = 0; x < st->w; x++) {
            uint32_t c = row[x] & 0xFFFFFFu;
            if (c != 0xFFFFFFu && x > st->w / 10 && x < st->w * 9 / 10 && y > st->h / 10 &&
                y < st->h * 9 / 10)
                st->ink++;
            if (ns < 4096) {
                int i;
                for (i = 0; i < ns; i++)
                    if (seen[i] == c) break;
                if (i == ns) seen[ns++] = c;
            }
        }
    }
    st->colours = ns;
    cairo_surface_destroy(s);
    return 0;
}

static char *slurp(const char *path, size_t *len)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) return NULL;
    fseek(fp, 0, SEEK_END);
    long n = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    char *b = malloc((size_t)n + 1);
    if (b && fread(b, 1, (size_t)n, fp) != (size_t)n) {
        free(b);
        b = NULL;
    }
    if (b) b[n] = '\0';
    if (len) *len = (size_t)n;
    fclose(fp);
    return b;
}

static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

static void rm_rf(const char *dir)
{
    static const char *files[] = {"summary.json", "history.csv", "tension.csv", "envelope.csv",
                                  "report.html"};
    static const char *plots[] = {"tension_surface", "envelope", "probes", "drives", "takeups",
                                  "energy"};
    char p[4096];
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        snprintf(p, sizeof p, "%s/%s", dir, files[i]);
        remove(p);
    }
    for (size_t i = 0; i < sizeof plots / sizeof plots[0]; i++) {
        snprintf(p, sizeof p, "%s/plots/%s.png", dir, plots[i]);
        remove(p);
        snprintf(p, sizeof p, "%s/plots/%s.svg", dir, plots[i]);
        remove(p);
    }
    snprintf(p, sizeof p, "%s/plots", dir);
    rmdir(p);
    rmdir(dir);
}

/* ---- tests ---- */

static void test_full_report(void)
{
    char dir[] = "/tmp/bd_report_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    CHECK(write_fake(dir, (fake_opts){240, 150, 0}) == 0);
    char err[512] = "";
    int rc = bd_report_write(dir, err, sizeof err);
    if (rc) fprintf(stderr, "bd_report_write: %s\n", err);
    CHECK(rc == BD_REPORT_OK);

    static const struct {
        const char *name;
        int w, h;
        int min_colours;
    } want[] = {{"tension_surface", 1200, 800, 100}, {"envelope", 1200, 700, 6},
                {"probes", 1200, 800, 4},             {"drives", 1200, 1000, 4},   /* 3 panels */
                {"takeups", 1200, 700, 3},            {"energy", 1200, 800, 6}};
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
        char png[4096], svg[4096];
        png_stats st;
        snprintf(png, sizeof png, "%s/plots/%s.png", dir, want[i].name);
        snprintf(svg, sizeof svg, "%s/plots/%s.svg", dir, want[i].name);
        CHECK(png_magic(png));
        CHECK(png_look(png, &st) == 0);
        CHECK(st.w == want[i].w && st.h == want[i].h);
        /* not blank: many colours in the map, lines in the plot area */
        CHECK(st.colours >= want[i].min_colours);
        CHECK(st.ink > 2000);
        if (st.colours < want[i].min_colours || st.ink <= 2000)
            fprintf(stderr, "%s: %d colours, %ld ink pixels\n", want[i].name, st.colours, st.ink);
        size_t n = 0;
        char *s = slurp(svg, &n);
        CHECK(s && strstr(s, "<svg"));
        if (i == 0) CHECK(s && strstr(s, "data:image/png;base64,"));  /* the raster map */
        CHECK(n < 4u << 20);
        free(s);
    }

    /* report.html: self-contained, names the model, shows the peak */
    char html[4096];
    snprintf(html, sizeof html, "%s/report.html", dir);
    char *h = slurp(html, NULL);
    CHECK(h != NULL);
    if (h) {
        CHECK(strstr(h, "CV-01 overland (fake run)") != NULL);
        CHECK(strstr(h, "data:image/png;base64,") != NULL);
        /* the peak as the summary gives it, in kN with one decimal */
        char sum[4096];
        snprintf(sum, sizeof sum, "%s/summary.json", dir);
        char *js = slurp(sum, NULL);
        const char *mx = js ? strstr(js, "\"max_N\": ") : NULL;
        double peak = mx ? strtod(mx + 9, NULL) : 0.0;
        CHECK(peak > 100e3 && peak < 1000e3);
        char want_peak[64];
        snprintf(want_peak, sizeof want_peak, "%.1f kN", peak / 1000.0);
        CHECK(strstr(h, want_peak) != NULL);
        if (!strstr(h, want_peak)) fprintf(stderr, "report.html lacks '%s'\n", want_peak);
        CHECK(strstr(h, "Static design calculation") != NULL);
        CHECK(strstr(h, "belt lifts off idler 12") != NULL);
        /* units read as units (a level span's slope term is exactly 0 at
         * its source: tests/cli/static_json.sh) */
        CHECK(strstr(h, "belt accel max [m/s²]") != NULL);
        CHECK(strstr(h, "mps2") == NULL);
        /* the drives: belt speed ω·R and power M·ω besides the torque */
        CHECK(strstr(h, "Belt speed at the drive pulleys (ω·R), their torque and the power") != NULL);
        /* the static design's warnings are listed and counted with the
         * run's (issue 15: a red card beside "warnings 0") */
        CHECK(strstr(h, "static design: drive slips: pulley ") != NULL);
        CHECK(strstr(h, "warnings</div><div class=v>3</div>") != NULL);
        CHECK(strstr(h, "takeup travel") != NULL);
        CHECK(strstr(h, "drive peak torque") != NULL);
        /* nothing from outside */
        CHECK(strstr(h, "http://") == NULL && strstr(h, "https://") == NULL);
        CHECK(strstr(h, "<script") == NULL);
        for (const char *p = h; (p = strstr(p, "src=\"")) != NULL; p += 5)
            CHECK(strncmp(p + 5, "data:", 5) == 0);
        free(js);
    }
    free(h);
    CHECK(!exists(html) || 1);
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s/report.html.tmp", dir);
    CHECK(!exists(tmp));

    /* again over an existing report: replaces it */
    CHECK(bd_report_write(dir, err, sizeof err) == BD_REPORT_OK);
    rm_rf(dir);
}

static void test_minimal_report(void)
{
    char dir[] = "/tmp/bd_report_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    CHECK(write_fake(dir, (fake_opts){50, 20, 1}) == 0);
    char err[512] = "", p[4096];
    int rc = bd_report_write(dir, err, sizeof err);
    if (rc) fprintf(stderr, "bd_report_write: %s\n", err);
    CHECK(rc == BD_REPORT_OK);
    /* absent data: no plot, no error */
    snprintf(p, sizeof p, "%s/plots/takeups.png", dir);
    CHECK(!exists(p));
    snprintf(p, sizeof p, "%s/plots/tension_surface.png", dir);
    CHECK(!exists(p));
    snprintf(p, sizeof p, "%s/plots/envelope.png", dir);
    CHECK(png_magic(p));
    snprintf(p, sizeof p, "%s/report.html", dir);
    char *h = slurp(p, NULL);
    CHECK(h && strstr(h, "minimal &amp; &lt;test&gt;"));  /* escaped */
    CHECK(h && strstr(h, "No warnings"));
    /* no radius in its summary.json: the drive's speed stays ω */
    CHECK(h && strstr(h, "Angular speed of the drive pulleys, their torque"));
    free(h);
    rm_rf(dir);
}

static void test_bad_dirs(void)
{
    char err[512] = "";
    CHECK(bd_report_write("/nonexistent/beltdyn/run", err, sizeof err) == BD_REPORT_EINPUT);
    CHECK(strstr(err, "/nonexistent/beltdyn/run") != NULL);
    CHECK(bd_report_write(NULL, err, sizeof err) != 0);
    CHECK(bd_report_write("/etc/hostname", err, sizeof err) == BD_REPORT_EINPUT);

    /* a directory that is not a run */
    char dir[] = "/tmp/bd_report_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    err[0] = '\0';
    CHECK(bd_report_write(dir, err, sizeof err) == BD_REPORT_EINPUT);
    CHECK(strstr(err, "summary.json") != NULL);

    /* broken summary.json: a message with the line */
    char p[4096];
    snprintf(p, sizeof p, "%s/summary.json", dir);
    FILE *fp = fopen(p, "w");
    fputs("{\n \"model\": \"x\",\n oops\n}\n", fp);
    fclose(fp);
    CHECK(bd_report_write(dir, err, sizeof err) == BD_REPORT_EINPUT);
    CHECK(strstr(err, "summary.json:3") != NULL);

    /* a malformed CSV row in the middle */
    fp = fopen(p, "w");
    fputs("{\"model\": \"x\", \"warnings\": []}\n", fp);
    fclose(fp);
    snprintf(p, sizeof p, "%s/envelope.csv", dir);
    fp = fopen(p, "w");
    fputs("s_m,tension_max_N,tension_min_N\n0,1,2\n1,2,x\n2,3,4\n", fp);
    fclose(fp);
    CHECK(bd_report_write(dir, err, sizeof err) == BD_REPORT_EINPUT);
    CHECK(strstr(err, "envelope.csv:3") != NULL);
    rm_rf(dir);
}

static void test_csv(void)
{
    /* the fast number parser agrees with strtod exactly */
    static const char *nums[] = {"0",        "1",         "-1",        "0.1",        "123.456",
                                 "-0.000123", "1e5",       "2.5E-3",    "1234567.891", "4.9e-324",
                                 "1.7976931348623157e308", "123456789012345678901234", "0.30000000000000004",
                                 "9007199254740993", "nan", "inf", "-inf", "+3.25", ".5", "5."};
    for (size_t i = 0; i < sizeof nums / sizeof nums[0]; i++) {
        const char *s = nums[i], *next = NULL;
        double got = bd_csv_parse_double(s, s + strlen(s), &next);
        double want = strtod(s, NULL);
        CHECK((isnan(got) && isnan(want)) || memcmp(&got, &want, sizeof got) == 0);
        CHECK(next == s + strlen(s));
    }
    /* random decimals as printf writes them */
    srand(7);
    for (int i = 0; i < 20000; i++) {
        char buf[64];
        double v = ((double)rand() / RAND_MAX - 0.5) * pow(10.0, (double)(rand() % 16 - 6));
        snprintf(buf, sizeof buf, i % 2 ? "%.*f" : "%.*g", rand() % 12 + 1, v);
        const char *next;
        double got = bd_csv_parse_double(buf, buf + strlen(buf), &next);
        double want = strtod(buf, NULL);
        if (memcmp(&got, &want, sizeof got) != 0) {
            CHECK(0);
            fprintf(stderr, "parse '%s': %.17g != %.17g\n", buf, got, want);
            break;
        }
    }

    char dir[] = "/tmp/bd_csv_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char p[4096], err[512];
    snprintf(p, sizeof p, "%s/a.csv", dir);
    /* CRLF, an empty field, an interrupted last line */
    FILE *fp = fopen(p, "w");
    fputs("t_s, a ,b\r\n0,1,2\r\n1,,3\r\n2,5,6\r\n3,7", fp);
    fclose(fp);
    bd_csv c;
    const char *want[2] = {"b", "t_s"};
    CHECK(bd_csv_read(p, want, 2, &c, err, sizeof err) == 0);
    CHECK(c.nrows == 3 && c.ncols == 2);
    CHECK(c.col[0][2] == 6.0 && c.col[1][2] == 2.0);
    bd_csv_free(&c);
    CHECK(bd_csv_read(p, NULL, 0, &c, err, sizeof err) == 0);
    CHECK(c.ncols == 3 && strcmp(c.names[1], "a") == 0 && isnan(c.col[1][1]));
    bd_csv_free(&c);
    const char *missing[1] = {"zz"};
    CHECK(bd_csv_read(p, missing, 1, &c, err, sizeof err) != 0);
    CHECK(strstr(err, "zz") != NULL);
    /* a complete last line without newline is kept */
    fp = fopen(p, "w");
    fputs("x,y\n1,2\n3,4", fp);
    fclose(fp);
    CHECK(bd_csv_read(p, NULL, 0, &c, err, sizeof err) == 0);
    CHECK(c.nrows == 2 && c.col[1][1] == 4.0);
    bd_csv_free(&c);
    /* a line longer than the read block */
    fp = fopen(p, "w");
    fputs("x", fp);
    for (int i = 0; i < 1200000; i++) fputs(",y", fp);
    fputs("\n", fp);
    fputs("1", fp);
    for (int i = 0; i < 1200000; i++) fputs(",2", fp);
    fputs("\n", fp);
    fclose(fp);
    CHECK(bd_csv_read(p, NULL, 0, &c, err, sizeof err) == 0);
    CHECK(c.nrows == 1 && c.ncols == 1200001);
    bd_csv_free(&c);
    remove(p);
    rmdir(dir);
}

/* fontconfig (under cairo's toy text) keeps its caches to the end: not a
 * leak of ours. Read by LeakSanitizer in the sanitizer build only. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void) { return "leak:libfontconfig\n"; }

/* ---- helper modes ---- */

static int mode_pngcheck(const char *path, int min_colours)
{
    png_stats st;
    if (!png_magic(path) || png_look(path, &st)) {
        fprintf(stderr, "%s: not a PNG\n", path);
        return 1;
    }
    printf("%s: %dx%d, %d%s colours, %ld non-white pixels in the middle\n", path, st.w, st.h,
           st.colours, st.colours >= 4096 ? "+" : "", st.ink);
    if (st.colours < min_colours || st.ink < 1000) {
        fprintf(stderr, "%s: looks blank\n", path);
        return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc >= 3 && strcmp(argv[1], "fake") == 0) {
        fake_opts o = {300, 200, 0};
        int k = 0;
        for (int i = 3; i < argc; i++) {
            if (strcmp(argv[i], "--minimal") == 0) o.minimal = 1;
            else if (k == 0) o.nelem = atoi(argv[i]), k++;
            else o.ntimes = atoi(argv[i]);
        }
        if (o.nelem < 2 || o.ntimes < 2) {
            fprintf(stderr, "fake: NELEM and NTIMES must be >= 2\n");
            return 2;
        }
        return write_fake(argv[2], o) ? 1 : 0;
    }
    if (argc == 3 && strcmp(argv[1], "report") == 0) {
        char err[1024];
        struct timespec a, b;
        clock_gettime(CLOCK_MONOTONIC, &a);
        int rc = bd_report_write(argv[2], err, sizeof err);
        clock_gettime(CLOCK_MONOTONIC, &b);
        if (rc) fprintf(stderr, "beltdyn report: %s\n", err);
        else
            printf("report written in %.2f s\n",
                   (double)(b.tv_sec - a.tv_sec) + 1e-9 * (double)(b.tv_nsec - a.tv_nsec));
        return rc;
    }
    if (argc == 4 && strcmp(argv[1], "pngcheck") == 0) return mode_pngcheck(argv[2], atoi(argv[3]));
    if (argc > 1) {
        fprintf(stderr, "usage: %s [fake DIR [NELEM NTIMES] [--minimal] | report DIR | "
                        "pngcheck FILE MIN_COLOURS]\n", argv[0]);
        return 2;
    }

    test_csv();
    test_bad_dirs();
    test_minimal_report();
    test_full_report();
    cairo_debug_reset_static_data();  /* so LeakSanitizer sees only our leaks */
    return bd_test_finish("test_report");
}
