/* `beltdyn report` on a load-cases directory (cases_report.c) */
#ifndef BD_IO_CASES_REPORT_H
#define BD_IO_CASES_REPORT_H

#include <stddef.h>

/* DIR holds cases.csv and cases.json from `beltdyn cases`: write
 * DIR/plots/cases_peaks.{png,svg} and DIR/report.html. Returns
 * BD_REPORT_OK or a BD_REPORT_E* code with a message in err. */
int bd_cases_report_write(const char *dir, char *err, size_t errlen);

#endif
