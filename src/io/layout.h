/* The conveyor's layout as built, for summary.json's "layout" (layout.c):
 * the belt path sampled along s, the pulleys with their place on s and
 * their drives' ratings, the loaded region. The report draws the layout
 * from it and marks the pulleys and the feed on its s axes. */
#ifndef BD_IO_LAYOUT_H
#define BD_IO_LAYOUT_H

#include <cjson/cJSON.h>

#include "sim/engine.h"

void bd_layout_to_json(cJSON *root, const bd_sim *sim);

#endif
