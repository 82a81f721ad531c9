/* mm_units.h — a learner's number with its unit, in SI.
 *
 * Answers to assignments arrive as text: "256.6 N", "0.2566 kN", "25 mm",
 * "90 deg", "1,5 kN" (a decimal comma), "3000 rpm", "4.2 kN*m", "9.81 m/s^2".
 * This module reads such a text into its value in SI units and the
 * dimension of the unit, so that a value in kN can be compared with an
 * answer in N, and a value in metres can be refused where a force is asked.
 *
 * Units: SI base and derived units (m, kg, g, t, s, min, h, N, Pa, J, W,
 * Hz), angles (rad, deg or °, rev), rpm (revolutions per minute), % and
 * the prefixes n, u or µ, m, c, d, k, M, G on the units that take them.
 * A unit expression is a product of units with powers (m^2, m², s^-2),
 * separated by spaces, '*' or '·', with at most one '/' whose right side
 * is the denominator ("N s/m", "kg m/s^2", "rad/s").
 *
 * Angles are kept as their own dimension (the radian, 1 in strict SI), so
 * that degrees convert to radians and rpm to rad/s, and a frequency in Hz
 * (cycles per second) is not silently taken for an angular velocity.
 * "%" is 0.01 and dimensionless.  No globals; cannot allocate.
 */
#ifndef MM_UNITS_H
#define MM_UNITS_H

#include "mm_status.h"

enum { MM_DIM_KG, MM_DIM_M, MM_DIM_S, MM_DIM_RAD, MM_DIM_COUNT };

typedef struct mm_quantity {
    double value;               /* in SI: kg, m, s, rad and their products */
    double number;              /* the number as typed (value = number * factor) */
    double factor;              /* the unit's factor to SI (1 for none) */
    signed char dim[MM_DIM_COUNT];  /* powers of kg, m, s, rad */
    int has_unit;               /* 0: a bare number */
} mm_quantity;

/* The factor to SI and the dimension of a unit expression ("kN/m", "" for
 * none) into q (value = the factor).  Returns MM_OK or MM_EVALUE naming
 * what could not be read. */
int mm_unit_parse(const char *unit, mm_quantity *q, mm_error *err);

/* A number with an optional unit: "256.6 N", "-1.5e3", "1,5 kN".  Returns
 * MM_OK or MM_EVALUE (no number, an unknown unit), err saying which. */
int mm_quantity_parse(const char *text, mm_quantity *q, mm_error *err);

/* Do a and b have the same dimension?  Cannot fail. */
int mm_dim_equal(const mm_quantity *a, const mm_quantity *b);

/* The dimension as text in SI base units, e.g. "kg m s^-2" ("1" for none),
 * into buf.  Cannot fail. */
void mm_dim_text(const mm_quantity *q, char *buf, size_t size);

#endif
