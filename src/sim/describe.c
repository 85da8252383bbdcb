/* `beltdyn check`: what was derived from the model */
#include "sim/engine.h"
#include "sim/timestep.h"
#include "belt/rfe/rfe.h"
#include "parts/parts.h"
#include "base/constants.h"

#include <math.h>
#include <stdio.h>

/* each speed loop: its bandwidth, the inertia it is tuned for and its
 * proportional gain against the belt's wave impedance at the drum
 * (docs/physics.md §6): above it the drum reflects the belt's waves, at it
 * the drum absorbs them, and the bandwidth that does is said */
static void describe_speed_loops(FILE *f, const bd_sim *sim)
{
    for (int i = 0; i < sim->model->pulley_count; i++) {
        const bd_pulley_body *p = &sim->pulleys[i];
        bd_part *part = bd_pulley_drive_part(sim, p);
        const bd_drive *dr = part ? bd_part_drive(part) : NULL;
        if (!dr || dr->def->control != BD_CONTROL_SPEED)
            continue;
        double R = p->m->radius, J = dr->ctrl_inertia;
        double Kp = 2.0 * dr->ctrl_bandwidth * J;
        /* the bare belt's impedance on both strands, R²·2·√(EA·m′) (the
         * characteristic impedance of m′·ü = EA·u″, Graff, Wave Motion in
         * Elastic Solids, ch. 2; a load only raises it), and the bandwidth
         * at which K_p = 2ω_c·J equals it (drive.c) */
        double Zb = R * R * 2.0 * sqrt(sim->model->EA * sim->model->belt_mpl);
        fprintf(f, "speed loop %s: %.3g Hz on %.4g kg m2, K_p %.4g N m s, %.3g x the belt's "
                   "wave impedance at the drum (%.4g N m s; at drive.bandwidth: %.4g Hz it "
                   "would absorb the belt's waves, not reflect them)\n",
                p->m->def->name, dr->ctrl_bandwidth / (2.0 * BD_PI), J, Kp, Kp / Zb, Zb,
                Zb / (4.0 * BD_PI * J));
    }
}

/* the steady running force the model's own resistance law gives at the
 * drives' speed (running_law.c): the figure a run's steady drive force
 * should come to, and the torture test holds it to */
static void describe_running_law(FILE *f, const bd_sim *sim)
{
    double v = bd_drives_reference_speed(sim->model->def);
    if (!(v > 0.0))
        return;
    const bd_model_def *def = sim->model->def;
    bd_running_law law;
    bd_running_law_build(sim, &law);
    double F = bd_running_law_force(&law, v, NULL);
    fprintf(f, "steady running force at %.4g m/s by the model's own law: %.4g N (idler rolling "
               "resistance %.4g N, lift of the load %.4g N, its acceleration at the feed %.4g N, "
               "pulley bearing_damping %.4g N%s)\n",
            v, F, law.idlers, law.lift, law.feed_mass * v * v, law.bearings * v,
            def->design.present && def->design.secondary == BD_SECONDARY_INDIVIDUAL
                ? "; design.secondary's resistances come on top"
                : "");
}

/* how each span runs (the pulleys' centres are on their own lines): a
 * layout made from a `profile` is checked here before it is run
 * (model-format.md) */
static void describe_spans(FILE *f, const bd_sim *sim)
{
    const bd_path *path = &sim->model->path;
    fprintf(f, "spans (x, y in m; s along the belt from where it leaves '%s'):\n",
            sim->model->def->pulleys[0].name);
    for (int i = 0; i < sim->model->pulley_count; i++) {
        const bd_path_segment *sp = bd_path_span(path, i);
        fprintf(f, "  span %-12s s %.3f to %.3f m, from (%.3f, %.3f) to (%.3f, %.3f), "
                   "slope %.2f to %.2f deg\n", sim->pulleys[i].m->def->name, sp->s0,
                sp->s0 + sp->length, sp->p0[0], sp->p0[1], sp->p1[0], sp->p1[1],
                atan2(sp->dir[1], fabs(sp->dir[0])) / BD_DEG,
                atan2(sp->dir1[1], fabs(sp->dir1[0])) / BD_DEG);
        for (int q = 0; q < sp->piece_count; q++) {
            const bd_path_piece *g = &path->pieces[sp->piece_first + q];
            if (!g->is_arc)
                continue;
            double a[2], b[2], t[2];
            bd_path_point(path, g->s0, a, t);
            bd_path_point(path, g->s0 + g->length, b, t);
            /* concave: its centre on the side away from the idlers (up),
             * the travel direction's left for a ccw turn */
            double up[2], left = g->sweep > 0.0 ? 1.0 : -1.0;
            bd_path_up_normal(t, up);
            int concave = left * (-t[1] * up[0] + t[0] * up[1]) > 0.0;
            fprintf(f, "    %s vertical curve, radius %.1f m: s %.3f to %.3f m, from (%.3f, "
                       "%.3f) to (%.3f, %.3f)\n", concave ? "concave" : "convex", g->radius,
                    g->s0, g->s0 + g->length, a[0], a[1], b[0], b[1]);
        }
    }
}

/* idler set k's turn of the discrete belt without bending stiffness
 * (idler_turn.c), on its line */
static void describe_idler_turn(FILE *f, const bd_sim *sim, int k)
{
    double phi, voc;
    if (bd_idler_turn(sim, k, &phi, &voc))
        fprintf(f, ", the belt turns %.3f rad at each at rest, v %.2f of its wave speed", phi,
                voc);
    if ((sim->model->def->belt.formulation == BD_FORMULATION_DISCRETE
         || sim->model->def->belt.formulation == BD_FORMULATION_RFE)
        && sim->model->idlers_per_set[k] > 0) {
        int count = sim->model->idlers_per_set[k], quintic = bd_idler_set_quintic(sim, k);
        if (quintic == 0 || quintic == count)
            fprintf(f, ", running line %s", quintic ? "quintic" : "quadratic");
        else
            fprintf(f, ", running line quintic at %d of them, quadratic at the others",
                    quintic);
    }
    fprintf(f, "\n");
}

void bd_sim_describe(const bd_sim *sim, FILE *f)
{
    const bd_model_def *def = sim->model->def;
    double belt_mass = 0.0, material = 0.0;
    for (int i = 0; i < sim->model->n; i++) {
        belt_mass += sim->mass[i] - sim->material[i];
        material += sim->material[i];
    }
    int dof = sim->model->belt->node_dof * sim->model->n + sim->model->pulley_count + sim->model->idler_count;
    for (int i = 0; i < sim->model->pulley_count; i++)
        dof += sim->pulleys[i].m->movable;
    fprintf(f, "model: %s\n", def->name);
    fprintf(f, "formulation: %s\n", sim->model->belt->description);
    fprintf(f, "belt loop length: %.3f m\n", sim->model->path.length);
    fprintf(f, "belt elements: %d (unstretched length %.4f m%s)\n", sim->model->n,
            sim->model->l0,
            sim->model->element_refined == 1
                ? "; the default halved: idlers turn the belt by 0.05 rad or more, "
                  "docs/model-format.md"
            : sim->model->element_refined == 2
                ? "; the rfe belt's default, 15° of the smallest pulley, shortened so that its "
                  "polygon on the pulleys costs at most 1 % of the running resistance, "
                  "docs/model-format.md"
            : def->belt.formulation == BD_FORMULATION_RFE && !(def->belt.element_length > 0.0)
                ? "; the rfe belt's default, 15° of the smallest pulley, docs/model-format.md"
                : "");
    if (def->belt.formulation == BD_FORMULATION_RFE) {
        double share = bd_lumped_polygon_share(def, &sim->model->path, sim->model->l0);
        if (isfinite(share))
            fprintf(f, "rfe polygon on the pulleys: about %.2g %% of the running resistance "
                    "lost to it at %.3g m/s (an estimate, docs/physics.md §15)\n",
                    100.0 * share, bd_drives_reference_speed(def));
    }
    fprintf(f, "belt nodes: %d\n", sim->model->n);
    if (def->belt.formulation == BD_FORMULATION_DISCRETE) {
        /* docs/physics.md §10: without bending stiffness the nodes' passage
         * over idlers and onto pulleys excites the string's transverse
         * modes at every element length */
        fprintf(f, "belt bending stiffness: %.4g N m2", sim->model->EI);
        if (sim->model->EI > 0.0)
            fprintf(f, "\n");
        else
            fprintf(f, " (none: where its idlers press on the quadratic running line, the "
                       "running force may carry a few %% of node vibration, docs/physics.md "
                       "§5, §10; give belt.bending_stiffness, or modulus, width and "
                       "thickness)\n");
    }
    if (def->belt.formulation == BD_FORMULATION_RFE) {
        double ga = bd_rfe_shear_stiffness(def);
        fprintf(f, "spring-damping elements: EA %.4g N, GA %.4g N%s, EI %.4g N m2\n",
                def->belt.axial_stiffness, ga,
                def->belt.shear_stiffness > 0.0 ? "" : " (10 EA)", sim->model->EI);
    }
    fprintf(f, "degrees of freedom: %d (%s)\n", dof, sim->model->belt->dof_text);
    if (sim->model->belt->topology) {
        /* the belt's long sections (belt.h): where they stand, what the
         * belt's degrees of freedom fall to with every window full (an
         * element 3, a section 2) */
        bd_belt_topology top;
        sim->model->belt->topology(sim, &top);
        if (!def->belt.group_sections)
            fprintf(f, "variable topology: off (belt.variable_topology.enabled: false)\n");
        else if (top.windows == 0 && top.kink_free_spans == 0)
            fprintf(f, "variable topology: no window for a long section (none on a straight "
                       "span on its idlers, one row of idlers, bays of 4 elements or more, two "
                       "bays and five elements clear of its pulleys and curves)\n");
        else if (top.windows == 0)
            fprintf(f, "variable topology: no window for a long section (every span with "
                       "room for one left free for the kink at its sections' ends)\n");
        else {
            double tied = top.window_length / sim->model->l0;
            fprintf(f, "variable topology: %d windows, %.1f m of the %.1f m belt in long "
                       "sections of up to %.4g m; belt degrees of freedom about %.0f with "
                       "them full\n",
                    top.windows, top.window_length, sim->model->path.length,
                    def->belt.group_length, 3.0 * (sim->model->n - tied) + 2.0 * top.windows);
        }
        if (def->belt.group_sections && (top.windows > 0 || top.kink_free_spans > 0))
            fprintf(f, "variable topology: the kink at the sections' ends about %.2f %% of the "
                       "running resistance; %d span(s) left free, whose ends' kink would pass "
                       "1 %% (docs/physics.md §15)\n",
                    100.0 * top.kink_share, top.kink_free_spans);
    }
    fprintf(f, "stable time step: %.4g s, limited by the %s\n", sim->model->dt_limit,
            bd_time_step_limit_name(sim->model->limit_kind));
    fprintf(f, "time step used: %.4g s (%s)\n", sim->model->dt,
            def->simulation.time_step > 0.0 ? "given" : "auto, 0.8 x limit");
    fprintf(f, "steps for %.4g s: %.0f\n", def->simulation.duration,
            ceil(def->simulation.duration / sim->model->dt));
    if (sim->settle_steps > 0)
        fprintf(f, "settled where the layout lays it (before t = 0): %ld steps, %d "
                   "kinetic-energy resets, %.4g J let go (the %s belt at the tangent points; "
                   "docs/physics.md §15)\n",
                sim->settle_steps, sim->settle_resets, sim->settle_released,
                sim->model->belt->name);
    fprintf(f, "pulleys:\n");
    for (int i = 0; i < sim->model->pulley_count; i++) {
        const bd_pulley_body *p = &sim->pulleys[i];
        const bd_path_segment *sp = bd_path_span(&sim->model->path, i);
        fprintf(f, "  %-12s wrap %6.1f deg, span after it %.3f m, inertia %.4g kg m2, centre "
                   "(%.3f, %.3f) m, radius %.3f m%s%s\n",
                p->m->def->name, bd_path_wrap_angle(&sim->model->path, i) * 180.0 / BD_PI,
                sp->length, p->m->inertia, p->m->def->x, p->m->def->y, p->m->def->radius,
                p->m->def->has_drive ? ", drive" : "", p->m->def->has_takeup ? ", takeup" : "");
    }
    describe_speed_loops(f, sim);
    describe_running_law(f, sim);
    describe_spans(f, sim);
    if (def->idler_set_count > 0)
        fprintf(f, "idlers:\n");
    for (int k = 0; k < def->idler_set_count; k++) {
        fprintf(f, "  span %-12s %d idlers, spacing %.4f m",
                def->pulleys[def->idler_sets[k].span].name, sim->model->idlers_per_set[k],
                sim->model->idler_spacing[k]);
        describe_idler_turn(f, sim, k);
    }
    double pulley_mass = 0.0, takeup_mass = 0.0;
    for (int i = 0; i < sim->model->pulley_count; i++) {
        pulley_mass += def->pulleys[i].mass;
        if (def->pulleys[i].has_takeup)
            takeup_mass += def->pulleys[i].takeup.mass;
    }
    fprintf(f, "masses: belt %.1f kg, material %.1f kg, pulleys %.1f kg, takeup carriages "
               "%.1f kg\n", belt_mass, material, pulley_mass, takeup_mass);
    const bd_cost *c = &sim->model->cost;
    char mem[32], phys[32], time[32];
    bd_cost_bytes_text(c->bytes, mem, sizeof mem);
    bd_cost_bytes_text(c->physical, phys, sizeof phys);
    bd_cost_time_text(c->seconds, time, sizeof time);
    char stepped[96] = "";
    if (c->stepped < 0.999 * (c->nodes + c->idlers))
        snprintf(stepped, sizeof stepped, ", each step about %.0f of them with the long sections",
                 c->stepped);
    fprintf(f, "estimate: %.0f nodes and %.0f idlers, memory about %s (physical memory %s), "
               "run time about %s for %g s (%.0f steps at %.2g node-steps/s%s; stabilization "
               "not counted)\n", c->nodes, c->idlers, mem, phys, time,
            def->simulation.duration, c->steps, c->rate, stepped);
    for (int i = 0; i < sim->warning_count; i++)
        fprintf(f, "warning: %s\n", sim->warnings[i]);
}
