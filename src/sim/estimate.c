/* What a run will cost, estimated before anything is built (issue 10 item
 * 8): a model asking for 1 µm elements would otherwise build 10⁸ nodes for
 * minutes and gigabytes, or run for centuries.
 *
 * From the definition and its path only (the formulation's `estimate`,
 * belt/belt.h): nodes ≈ loop length / element length, idler bodies per
 * set, bytes per node and per idler at the build's peak (from the arrays
 * the build allocates), the stable time step of elements that long (the
 * build's own law), and a measured rate of (node + idler)-steps per second.
 * Then
 *   memory  = nodes·node_bytes + idlers·idler_bytes,
 *   steps   = duration / Δt,   Δt = 0.8 × the stable step, or the model's,
 *   seconds = (nodes + idlers)·steps / rate   (stabilization not counted).
 * Refused (an error at `belt`, naming element_length) when the memory is
 * more than this process may use — the machine's physical memory
 * (sysconf _SC_PHYS_PAGES·_SC_PAGESIZE), or less under an address-space or
 * data limit (ulimit -v, -d), less what the process already maps — or when
 * the run would take more than 30 days: no engineering question waits a
 * month for one transient, and such a model is a slip in element_length or
 * duration. A run estimated at more than 10 minutes gets a warning. After
 * the build the estimate is updated with the nodes and step actually made
 * (what `beltdyn check` prints). */
#include "sim/engine.h"
#include "sim/timestep.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

/* a run longer than this is said in a warning, s */
#define LONG_RUN_S 600.0
/* and one longer than this is refused, s */
#define REFUSED_RUN_S (30.0 * 86400.0)
/* tension.csv sizes above this get a warning (a policy choice: a file a
 * spreadsheet or a plot still opens quickly) */
#define TENSION_CSV_WARN_BYTES 100e6

/* bytes this process may use: physical memory, or a lower limit on its
 * address space or data less what it maps already (Linux /proc) */
static void available_memory(bd_cost *c)
{
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    c->physical = pages > 0 && page > 0 ? (double)pages * (double)page : INFINITY;
    c->available = c->physical;
    c->available_is = "physical memory";
    double mapped = 0.0;
    FILE *f = fopen("/proc/self/statm", "r");
    if (f) {
        unsigned long size;
        if (fscanf(f, "%lu", &size) == 1 && page > 0)
            mapped = (double)size * (double)page;
        fclose(f);
    }
    const struct {
        int resource;
        const char *what;
    } limits[] = {{RLIMIT_AS, "address-space limit, ulimit -v"},
                  {RLIMIT_DATA, "data limit, ulimit -d"}};
    for (int i = 0; i < 2; i++) {
        struct rlimit r;
        if (getrlimit(limits[i].resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY)
            continue;
        double left = (double)r.rlim_cur - mapped;
        if (left < c->available) {
            c->available = left > 0.0 ? left : 0.0;
            c->available_is = limits[i].what;
        }
    }
}

/* bytes and seconds from the counts and the step */
static void complete(bd_cost *c, double duration)
{
    c->bytes = c->nodes * c->node_bytes + c->idlers * c->idler_bytes;
    c->steps = ceil(duration / c->dt);
    c->seconds = c->stepped * c->steps / c->rate;
}

void bd_cost_bytes_text(double bytes, char *buf, size_t len)
{
    const char *unit[] = {"B", "kB", "MB", "GB", "TB", "PB"};
    int u = 0;
    while (bytes >= 1000.0 && u < 5) {
        bytes /= 1000.0;
        u++;
    }
    snprintf(buf, len, "%.3g %s", bytes, unit[u]);
}

void bd_cost_time_text(double s, char *buf, size_t len)
{
    if (s < 120.0)
        snprintf(buf, len, "%.2g s", s);
    else if (s < 7200.0)
        snprintf(buf, len, "%.2g min", s / 60.0);
    else if (s < 2.0 * 86400.0)
        snprintf(buf, len, "%.2g h", s / 3600.0);
    else if (s < 730.0 * 86400.0)
        snprintf(buf, len, "%.3g days", s / 86400.0);
    else
        snprintf(buf, len, "%.3g years", s / (365.25 * 86400.0));
}

/* "belt.element_length: 1e-05 m on a 111.5 m belt loop makes about 1.1e+07
 * nodes (and 89 idlers)" */
static void what_it_makes(const bd_model_def *def, const bd_cost *c, double loop, char *buf,
                          size_t len)
{
    char idlers[64] = "";
    if (c->idlers > 0.0)
        snprintf(idlers, sizeof idlers, " and %.3g idlers", c->idlers);
    if (c->element_what[0])
        snprintf(buf, len, "%s on a %.1f m belt loop makes about %.3g nodes%s", c->element_what,
                 loop, c->nodes, idlers);
    else
        snprintf(buf, len, "belt.element_length: %g m%s on a %.1f m belt loop makes about %.3g "
                 "nodes%s", c->element_length,
                 def->belt.element_length > 0.0 ? "" : " (the default)", loop, c->nodes, idlers);
}

int bd_cost_from_def(const bd_model_def *def, double duration, bd_cost *c, double *loop)
{
    const bd_belt_ops *ops = bd_belt_ops_for(def->belt.formulation);
    bd_path path;
    bd_diag quiet;
    bd_diag_init(&quiet);
    int bad = !ops || bd_path_build(def, &path, &quiet);
    bd_diag_free(&quiet);
    if (bad)
        return -1;
    bd_belt_estimate be;
    memset(&be, 0, sizeof be);
    ops->estimate(def, &path, &be);
    snprintf(c->element_what, sizeof c->element_what, "%s", be.element_what);
    snprintf(c->element_advice, sizeof c->element_advice, "%s", be.element_advice);
    if (loop)
        *loop = path.length;
    bd_path_free(&path);
    c->element_length = be.element_length;
    c->nodes = be.nodes;
    c->idlers = be.idlers;
    c->node_bytes = be.node_bytes;
    c->idler_bytes = be.idler_bytes;
    c->stepped = be.stepped > 0.0 ? be.stepped : c->nodes + c->idlers;
    c->rate = be.rate;
    c->dt = def->simulation.time_step > 0.0 ? def->simulation.time_step
                                            : BD_TIME_STEP_SAFETY * be.stable_step;
    complete(c, duration);
    return 0;
}

int bd_cost_estimate(bd_sim *sim, bd_diag *diag)
{
    const bd_model_def *def = sim->model->def;
    bd_cost *c = &sim->own->cost;
    double loop = 0.0;
    if (bd_cost_from_def(def, def->simulation.duration, c, &loop) != 0)
        return 0;   /* the build says what is wrong with the path */
    available_memory(c);
    char makes[256], mem[32], avail[32], phys[32], time[32];
    what_it_makes(def, c, loop, makes, sizeof makes);
    bd_cost_bytes_text(c->bytes, mem, sizeof mem);
    bd_cost_bytes_text(c->available, avail, sizeof avail);
    bd_cost_bytes_text(c->physical, phys, sizeof phys);
    bd_cost_time_text(c->seconds, time, sizeof time);
    if (c->bytes > c->available || c->nodes + c->idlers > (double)INT_MAX) {
        char limit[96] = "";
        if (c->available < c->physical)
            snprintf(limit, sizeof limit, " (its %s; physical memory %s)", c->available_is, phys);
        else
            snprintf(limit, sizeof limit, " (this machine's physical memory)");
        bd_diag_error(diag, def->source, def->belt.mark,
                      "%s, needing about %s of memory: more than the %s this process may "
                      "use%s; use %s", makes, mem, avail, limit,
                      c->element_advice[0] ? c->element_advice : "a longer element_length");
        return 1;
    }
    char steps[320];
    snprintf(steps, sizeof steps, "%g s simulated in steps of %.3g s is %.3g steps, about %s "
             "on this machine (at %.2g node-steps per second); memory about %s, physical "
             "memory %s", def->simulation.duration, c->dt, c->steps, time, c->rate, mem, phys);
    if (c->seconds > REFUSED_RUN_S) {
        bd_diag_error(diag, def->source, def->belt.mark,
                      "%s: %s; refused, a run of more than %g days is not practical: use %s "
                      "or a shorter simulation.duration", makes, steps, REFUSED_RUN_S / 86400.0,
                      c->element_advice[0] ? c->element_advice : "a longer element_length");
        return 1;
    }
    if (c->seconds > LONG_RUN_S)
        bd_diag_warning(diag, def->source, def->belt.mark, "a long run: %s: %s", makes, steps);
    /* tension.csv: one row of about 50 bytes per written element and time
     * (io/outputs.c); big files are worth a word before the run */
    const bd_simulation_def *sd = &def->simulation;
    double every = bd_tension_interval(sd);
    double stride = bd_tension_stride(sd, loop, c->nodes);
    double field = (floor(sd->duration / every) + 2.0) * ceil(c->nodes / stride) * 50.0;
    if (field > TENSION_CSV_WARN_BYTES) {
        char size[32];
        bd_cost_bytes_text(field, size, sizeof size);
        bd_diag_warning(diag, def->source, sd->mark,
                        "tension.csv will be about %s (%.0f elements every %g s for %g s); "
                        "set simulation.tension_interval and/or tension_spacing to thin it",
                        size, ceil(c->nodes / stride), every, sd->duration);
    }
    return 0;
}

void bd_cost_update(bd_sim *sim)
{
    bd_cost *c = &sim->own->cost;
    const bd_belt_ops *belt = sim->model->belt;
    c->nodes = sim->model->n;
    c->idlers = sim->model->idler_count;
    c->stepped = c->nodes + c->idlers;
    if (belt->topology && sim->model->def->belt.group_sections) {
        bd_belt_topology top;
        belt->topology(sim, &top);
        double tied = fmin(top.window_length / sim->model->l0, c->nodes);
        if (top.windows > 0)
            c->stepped = (c->nodes - tied) + BD_SECTION_STEP_ELEMENTS * top.windows
                       + c->idlers * (1.0 - tied / c->nodes);
    }
    c->dt = sim->model->dt;
    complete(c, sim->model->def->simulation.duration);
}
