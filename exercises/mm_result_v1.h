/* mm_result_v1.h — the builders by name that came before declared outputs.
 * Only exercises not yet converted to an output table use them; they go
 * when the last one is converted.  Names and labels are copied. */
#ifndef MM_RESULT_V1_H
#define MM_RESULT_V1_H

#include "mm_exercise.h"

int mm_res_scalar_v1(mm_result *r, const char *name, const char *label, const char *unit,
                     double value);
int mm_res_scalar_text_v1(mm_result *r, const char *name, const char *label, const char *unit,
                          double value, const char *text);
mm_series *mm_res_series_v1(mm_result *r, const char *name, const char *label, const char *unit,
                            const char *x_label, const char *x_unit, int n);
mm_table *mm_res_table_v1(mm_result *r, const char *name, int nrows, int ncols,
                          const char *const *columns, const char *const *units);

#endif
