#include "base/json_util.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>

#include "base/file.h"

void bd_json_add_number(cJSON *obj, const char *key, double v)
{
    if (isfinite(v))
        cJSON_AddNumberToObject(obj, key, v);
    else
        cJSON_AddNullToObject(obj, key);
}

double bd_json_num(const cJSON *obj, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    return cJSON_IsNumber(v) ? v->valuedouble : NAN;
}

const char *bd_json_str(const cJSON *obj, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
    return cJSON_IsString(v) ? v->valuestring : "";
}

cJSON *bd_json_load(const char *path)
{
    char *text;
    size_t len;
    if (bd_read_file(path, &text, &len) != BD_READ_OK)
        return NULL;
    cJSON *root = cJSON_ParseWithLength(text, len);
    free(text);
    if (!root)
        errno = 0;
    return root;
}
