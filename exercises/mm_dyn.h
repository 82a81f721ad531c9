/* mm_dyn.h — helpers of the chapter-4 (dynamics) exercises that are not
 * numerics: drawing coordinates rounded for the animation, and a floor
 * for values plotted on a log axis.
 */
#ifndef MM_DYN_H
#define MM_DYN_H

#include "mm_exercise.h"

/* The decimal quantum of an animation drawn to the size `size` [m]: the
 * power of ten at or below size * 1e-5 (a thousandth of a pixel on a
 * 1000-pixel canvas).  Cannot fail. */
double mm_dyn_quantum(double size);

/* x rounded to a multiple of the decimal quantum q (a power of ten), so
 * that it prints short ("0.12345" rather than 17 digits): a drawing needs
 * no more.  Cannot fail. */
double mm_dyn_round(double x, double q);

/* Round every coordinate of shape s to q.  Cannot fail. */
void mm_dyn_round_shape(mm_shape *s, double q);

/* The frame times of an animation: nf frames evenly over [0, t_show].
 * Cannot fail. */
void mm_dyn_frame_times(mm_anim *a, double t_show);

#endif
