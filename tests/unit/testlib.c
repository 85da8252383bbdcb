#include "testlib.h"

int bd_test_failures = 0;
int bd_test_checks = 0;

int bd_test_finish(const char *name)
{
    printf("%s: %d checks, %d failed\n", name, bd_test_checks, bd_test_failures);
    return bd_test_failures == 0 ? 0 : 1;
}
