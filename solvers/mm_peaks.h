/* mm_peaks.h — extrema of sampled signals (chapter 5, vibrations: the
 * peaks of a growing motion, the bottoms of a beating envelope).  Pure
 * functions, thread-safe.
 */
#ifndef MM_PEAKS_H
#define MM_PEAKS_H

/* The extrema of a motion sampled with its velocity: x[i], v[i] at the
 * ascending times t[i] (n samples).  Between samples i and i + 1 from
 * t_from on where v changes sign (v[i] v[i+1] < 0, or v[i+1] = 0 after
 * v[i] != 0) the extremum is placed at the zero of v's linear
 * interpolation, t[i] + u h, and valued by the cubic Hermite interpolant
 * of (x, v) there.  At most cap stored into tp (times) and xp (values);
 * returns the count. */
int mm_peaks_hermite(int n, const double *t, const double *x, const double *v, double t_from, int cap,
                     double *tp, double *xp);

/* The minima of samples y[0..n-1] at ascending times t: each inner i with
 * y[i] < y[i-1], y[i] <= y[i+1] and y[i] < level, placed at the vertex of
 * the parabola through (t, y) at i - 1, i, i + 1 (t[i] when the vertex
 * falls outside [t[i-1], t[i+1]]); a minimum within gap of the previous
 * one is the same (the lower sample keeps it).  At most cap stored into
 * tmin (times) and ymin (the samples y[i]); returns the count. */
int mm_peaks_minima(int n, const double *t, const double *y, double level, double gap, int cap, double *tmin,
                    double *ymin);

#endif
