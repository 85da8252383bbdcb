/* `beltdyn report` on a start-study directory (study_report.c) */
#ifndef BD_IO_STUDY_REPORT_H
#define BD_IO_STUDY_REPORT_H

#include <stddef.h>

/* DIR holds study.csv and study.json from `beltdyn study`: write
 * DIR/plots/study_{tension,peaks}.{png,svg} and DIR/report.html. Returns
 * BD_REPORT_OK or a BD_REPORT_E* code with a message in err. */
int bd_study_report_write(const char *dir, char *err, size_t errlen);

#endif
