/* Bulk material on the RFE belt: it lands on and leaves the elements as
 * on the lumped belt's nodes (belt/lumped/material.c, which shares the
 * momentum along the belt and books its kinetic and potential energy);
 * here what the rotation adds. Material rides on an element as part of
 * its body, J = mass·gyration2: landing without spin it keeps the
 * element's angular momentum, ω' = ω·m/(m + Δm), the loss of ½Jω² −
 * ½J'ω'² booked as dissipated, as the lumped belt books the translation's;
 * leaving, it takes its share of ½Jω² with it. */
#include "belt/rfe/rfe.h"

/* the elements whose mass the material phase may change: the four round
 * the feed point (its tracker moves at most one element in a step) and
 * those the discharge pulley touches */
#define FEED_SPAN 4

void bd_rfe_material(bd_sim *sim)
{
    bd_rfe *R = bd_rfe_of(sim);
    const int n = sim->model->n;
    const double g2 = bd_rfe_model_of(sim)->gyration2;
    const bd_wrap_contact *W = &R->lumped.wraps[sim->model->discharge_pulley];
    /* the mass before, of every element that may change (none shared:
     * a feed element the discharge also touches is taken once) */
    int node[FEED_SPAN];
    double before[FEED_SPAN];
    int count = 0;
    if (sim->has_feed) {
        int k = bd_node_prev(sim->feed.element, n);
        for (int q = 0; q < FEED_SPAN && q < n; q++, k = bd_node_next(k, n)) {
            node[count] = k;
            before[count++] = sim->mass[k];
        }
    }
    /* the discharge's elements lose all their material: their ω stays,
     * their spin's share leaves with it */
    for (int c = 0; c < W->contact_count; c++) {
        int i = W->c_node[c];
        double dm = sim->material[i];
        if (dm > 0.0)
            sim->energy.dissipated += 0.5 * dm * g2 * R->omega[i] * R->omega[i];
    }
    bd_lumped_material(sim);
    for (int q = 0; q < count; q++) {
        int i = node[q];
        double m0 = before[q], m1 = sim->mass[i];
        if (m1 <= m0)
            continue;   /* the feed added nothing here (or the discharge took it) */
        double w0 = R->omega[i], w1 = w0 * m0 / m1;
        sim->energy.dissipated += 0.5 * g2 * (m0 * w0 * w0 - m1 * w1 * w1);
        R->omega[i] = w1;
    }
}
