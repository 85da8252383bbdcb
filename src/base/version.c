/* the version the build was made from (CMakeLists.txt's project()) */
#include "beltdyn/model.h"

#ifndef BD_VERSION
#error "BD_VERSION must be defined by the build"
#endif

const char *bd_version(void)
{
    return BD_VERSION;
}
