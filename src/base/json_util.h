/* Small cJSON helpers shared by the writers of summary.json and of the
 * static calculation's JSON */
#ifndef BD_JSON_UTIL_H
#define BD_JSON_UTIL_H

#include <cjson/cJSON.h>

/* add key: v, or key: null when v is not finite (JSON has no inf/nan) */
void bd_json_add_number(cJSON *obj, const char *key, double v);
/* obj's number at key, NAN when absent or not a number */
double bd_json_num(const cJSON *obj, const char *key);
/* obj's string at key, "" when absent or not a string */
const char *bd_json_str(const cJSON *obj, const char *key);
/* the JSON file at path, parsed; NULL when it cannot be read (errno says
 * why) or is not JSON (errno 0). Free with cJSON_Delete. */
cJSON *bd_json_load(const char *path);

#endif
