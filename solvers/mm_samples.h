/* mm_samples.h — reading numbers off the samples of a function, as a plot
 * shows them (num-plot): how far the drawn polyline strays from f, the
 * best local extremes among the samples refined between them, and the
 * area the polyline encloses.
 *
 * Pure numerics: no globals, safe from many threads; the caller owns every
 * array.  Nothing here can fail.
 */
#ifndef MM_SAMPLES_H
#define MM_SAMPLES_H

#include "mm_opt.h"

/* How far f strays from the chords of its samples (x[i], y[i]), i < n:
 * the largest |f(x_m) - chord| at the golden-section fraction g = (3 -
 * sqrt 5) / 2 of each step between finite samples (an irrational fraction
 * rather than the midpoint, so that a wave whose period fits the step
 * twice cannot hide there too), where f is finite; *x_at receives where.
 * f is called once a step.  Cannot fail. */
double mm_samples_chord_deviation(mm_opt_fn f, void *ctx, int n, const double *x, const double *y,
                                  double *x_at);

/* The candidates for the largest (s = +1) or the smallest (s = -1) value
 * of f: the MM_SAMPLES_NCAND best local extremes offered, best first, each
 * with the spacing h of the scan that found it (h = 0: an empty place;
 * start from an array of zeros) and whether the plot's samples found it. */
#define MM_SAMPLES_NCAND 4
typedef struct mm_samples_cand {
    double x, v, h;
    int from_plot;
} mm_samples_cand;

/* Offer the value v at x with its neighbours vl, vr (NaN at an end of the
 * scan): kept if no neighbour beats it and it beats the worst kept.
 * Cannot fail. */
void mm_samples_offer(mm_samples_cand *cd, double s, double x, double v, double vl, double vr, double h,
                      int from_plot);

/* Every finite sample of a scan (x[i], y[i]), i < n, with spacing h,
 * offered to both lists: cd[0] for the largest value, cd[1] for the
 * smallest.  Cannot fail. */
void mm_samples_offer_scan(mm_samples_cand cd[2][MM_SAMPLES_NCAND], int n, const double *x, const double *y,
                           double h, int from_plot);

/* Each candidate refined between its neighbours (mm_opt_refine_extreme
 * within [a, b]); the best refined one, with its errors, replaces *x, *v
 * (xe, ve 0 and from_plot 1 left when there is no candidate).  Cannot
 * fail. */
void mm_samples_best(mm_opt_fn_err f, void *ctx, double s, const mm_samples_cand *cd, double a, double b,
                     double *x, double *v, double *xe, double *ve, int *from_plot);

/* The trapezoid rule on n equally spaced samples y over [a, b] (the area
 * the polyline encloses), summed with compensation; *err receives its
 * rounding: 2 u |term| for each term, and twice ef (the largest rounding
 * error of a sample) over b - a.  Cannot fail. */
double mm_samples_trapezoid(int n, double a, double b, const double *y, double ef, double *err);

#endif
