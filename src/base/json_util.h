/* Small cJSON helpers shared by the writers of summary.json and of the
 * static calculation's JSON */
#ifndef BD_JSON_UTIL_H
#define BD_JSON_UTIL_H

#include <cjson/cJSON.h>

/* add key: v, or key: null when v is not finite (JSON has no inf/nan) */
void bd_json_add_number(cJSON *obj, const char *key, double v);

#endif
