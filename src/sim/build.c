/* Building a simulation from a validated model: the pulley bodies, the belt
 * (its formulation's build), the drive monitors, the time step, the parts
 * (drives, transmissions, takeups) and the drives' speed loops, and the
 * start from rest.
 * Everything is allocated here; the step loop allocates nothing. */
#include "sim/engine.h"
#include "sim/timestep.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "parts/parts.h"
#include "sensors/sensors.h"

/* the inertia the speed controllers are tuned for: everything the belt
 * moves, reflected to each drive pulley, shared among the speed drives */
static void prepare_drives(bd_sim *sim)
{
    double belt_mass = bd_sim_belt_mass(sim);
    int speed_drives = 0;
    for (int i = 0; i < sim->model->pulley_count; i++)
        if (sim->pulleys[i].m->def->has_drive
            && sim->pulleys[i].m->def->drive.control == BD_CONTROL_SPEED)
            speed_drives++;
    for (int i = 0; i < sim->model->pulley_count; i++) {
        bd_pulley_body *p = &sim->pulleys[i];
        if (!p->m->def->has_drive)
            continue;
        double R = p->m->radius;
        double J = belt_mass * R * R;
        for (int k = 0; k < sim->model->pulley_count; k++) {
            double r = sim->pulleys[k].m->radius;
            J += sim->pulleys[k].m->inertia * (R / r) * (R / r);
        }
        J = sim->model->belt->support_inertia(sim, R, J);
        bd_drive_prepare(sim, bd_part_drive(bd_pulley_drive_part(sim, p)), p,
                         J / (speed_drives > 0 ? speed_drives : 1));
    }
    /* a transmission's speed loop also moves its motor side */
    for (int k = 0; k < sim->part_count; k++)
        if (sim->parts[k].type == BD_PART_TRANSMISSION)
            bd_transmission_tune(sim, &sim->parts[k]);
}

static int create(const bd_model_def *def, bd_sim *volatile *out, bd_diag *diag);

int bd_sim_create(const bd_model_def *def, bd_sim **out, bd_diag *diag)
{
    *out = NULL;
    bd_sim *volatile built = NULL;
    bd_alloc_guard guard;
    bd_alloc_guard_push(&guard);
    if (setjmp(guard.env)) {
        bd_alloc_guard_pop(&guard);
        double L = built && built->model ? built->model->path.length : 0.0;
        double el = def->belt.element_length;
        if (L > 0.0 && el > 0.0)
            bd_diag_error(diag, def->source, def->belt.mark,
                          "out of memory while building the simulation: a %.1f m belt in "
                          "elements of %g m (belt.element_length) is %.3g nodes",
                          L, el, L / el);
        else
            bd_diag_error(diag, def->source, def->belt.mark,
                          "out of memory while building the simulation");
        bd_sim_free(built);
        return 1;
    }
    int bad = create(def, &built, diag);
    bd_alloc_guard_pop(&guard);
    if (bad) {
        bd_sim_free(built);
        return 1;
    }
    *out = built;
    return 0;
}

/* bd_sim_create's work; *sim is set first, so that a jump out of memory
 * finds what to free */
static int create(const bd_model_def *def, bd_sim *volatile *out, bd_diag *diag)
{
    bd_sim *sim = bd_xcalloc(1, sizeof *sim);
    *out = sim;
    sim->own = bd_xcalloc(1, sizeof *sim->own);
    sim->model = sim->own;
    sim->own->def = def;
    sim->own->belt = bd_belt_ops_for(def->belt.formulation);
    if (!sim->own->belt) {
        bd_diag_error(diag, def->source, def->belt.mark, "belt.formulation: unknown (%d)",
                      (int)def->belt.formulation);
        return 1;
    }
    /* what it will cost, before anything large is allocated */
    if (bd_cost_estimate(sim, diag))
        return 1;
    sim->own->gravity = def->gravity;
    sim->own->EA = def->belt.axial_stiffness;
    sim->own->EI = def->belt.bending_stiffness;
    sim->own->belt_mpl = def->belt.mass_per_length;
    sim->own->pulley_count = def->pulley_count;
    sim->own->pulleys = bd_xcalloc((size_t)def->pulley_count, sizeof *sim->own->pulleys);
    sim->pulleys = bd_xcalloc((size_t)def->pulley_count, sizeof *sim->pulleys);
    for (int i = 0; i < def->pulley_count; i++) {
        bd_pulley_model_init(sim->own, &sim->own->pulleys[i], &def->pulleys[i]);
        /* a drive on a bare shaft: when the belt slips, only the floored
         * inertia (and the implicit speed loop) holds the pulley's speed */
        if (def->pulleys[i].has_drive
            && def->pulleys[i].inertia + def->pulleys[i].drive.inertia <= 0.0)
            bd_sim_warn(sim, "drive pulley '%s' has no inertia (mass, inertia and drive "
                        "inertia all 0): it is given %.3g kg·m², 1%% of the belt wrapped on it; "
                        "give the motor's and gearbox's inertia (drive.inertia) for a "
                        "physical slip", def->pulleys[i].name, sim->own->pulleys[i].inertia);
        sim->pulleys[i].m = &sim->own->pulleys[i];
        sim->pulleys[i].cx = sim->own->pulleys[i].x0;
        sim->pulleys[i].cy = sim->own->pulleys[i].y0;
    }
    if (sim->model->belt->build(sim, diag))
        return 1;
    for (int i = 0; i < sim->model->pulley_count; i++)
        if (sim->pulleys[i].m->def->has_drive)
            bd_monitor_init(sim, &sim->pulleys[i]);
    if (bd_time_step_choose(sim, diag))
        return 1;
    bd_pulley_resistance_init(sim);
    bd_bounds_prepare(sim->own);
    bd_cost_update(sim);
    bd_parts_create(sim);
    prepare_drives(sim);
    for (int i = 0; i < sim->model->n; i++)
        bd_node_mass_changed(sim, i);
    /* a failure of its forces shows again, with its message, in the first step */
    (void)bd_sim_start_at_rest(sim);
    bd_idler_turn_warn(sim);
    bd_sag_compliance_warn(sim);
    /* a belt not in its own equilibrium where the layout lays it settles
     * there (a stabilization, when asked for, does more) */
    if (sim->model->belt->settle_time && !def->simulation.stabilize && bd_sim_settle(sim)) {
        bd_diag_error(diag, def->source, def->belt.mark,
                      "the %s belt did not settle where the layout lays it (before "
                      "t = 0): %s",
                      sim->model->belt->name, sim->fail_msg);
        return 1;
    }
    bd_sim_records_restart(sim);
    return 0;
}

/* the state's own allocations */
static void free_state(bd_sim *sim)
{
    if (sim->model && sim->model->belt)
        sim->model->belt->free(sim);
    bd_parts_free(sim);
    bd_node_arrays_free(sim);
    free(sim->pulleys);
    free(sim->idlers);
    free(sim->probes);
    for (int i = 0; i < sim->warning_count; i++)
        free(sim->warnings[i]);
    free(sim->warnings);
    free(sim);
}

void bd_model_free(bd_model *m)
{
    if (!m)
        return;
    if (m->initial)
        free_state(m->initial);
    if (m->belt)
        m->belt->free_model(m);
    free(m->s_node0);
    free(m->idlers_per_set);
    free(m->idler_spacing);
    free(m->idler_turn);
    free(m->idler_turn_speed);
    free(m->pulleys);
    free(m->idlers);
    bd_path_free(&m->path);
    free(m);
}

void bd_sim_free(bd_sim *sim)
{
    if (!sim)
        return;
    bd_model *own = sim->own;
    free_state(sim);
    bd_model_free(own);
}

int bd_model_compile(const bd_model_def *def, bd_model **out, bd_diag *diag)
{
    *out = NULL;
    bd_sim *sim;
    if (bd_sim_create(def, &sim, diag))
        return 1;
    /* the model keeps the state at t = 0 that every run starts from */
    bd_model *m = sim->own;
    sim->own = NULL;
    m->initial = sim;
    *out = m;
    return 0;
}


/* *out as a deep copy of the state src, reading the same model. The copy
 * starts with nothing of its own and takes each allocation as it is made,
 * so that a jump out of memory half way leaves it freeable. */
static void clone_state(bd_sim *volatile *out, const bd_sim *src)
{
    const bd_model *m = src->model;
    bd_sim *sim = bd_xcalloc(1, sizeof *sim);
    *sim = *src;
    sim->own = NULL;
    sim->pulleys = NULL;
    sim->idlers = NULL;
    sim->probes = NULL;
    sim->parts = NULL;
    sim->part_count = 0;
    sim->belt_data = NULL;
    sim->warnings = NULL;
    sim->warning_count = 0;
    *out = sim;
    bd_node_arrays_dup(sim, src);   /* its first step: no longer the source's */
    sim->pulleys = bd_xdup(src->pulleys, (size_t)m->pulley_count, sizeof *sim->pulleys);
    sim->idlers = bd_xdup(src->idlers, (size_t)m->idler_count, sizeof *sim->idlers);
    sim->probes = bd_xdup(src->probes, (size_t)m->probe_count, sizeof *sim->probes);
    bd_parts_clone(sim, src);
    m->belt->clone(sim, src);
    sim->warnings = bd_xcalloc((size_t)src->warning_count, sizeof *sim->warnings);
    for (int i = 0; i < src->warning_count; i++) {
        sim->warnings[i] = bd_xdup(src->warnings[i], strlen(src->warnings[i]) + 1, 1);
        sim->warning_count = i + 1;
    }
}

int bd_sim_create_from(const bd_model *model, bd_sim **out)
{
    *out = NULL;
    if (!model->initial)
        return 1;
    bd_sim *volatile copy = NULL;
    bd_alloc_guard guard;
    bd_alloc_guard_push(&guard);
    if (setjmp(guard.env)) {
        bd_alloc_guard_pop(&guard);
        if (copy)
            free_state(copy);
        return 1;
    }
    clone_state(&copy, model->initial);
    bd_alloc_guard_pop(&guard);
    *out = copy;
    return 0;
}
