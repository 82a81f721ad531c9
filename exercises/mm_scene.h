/* mm_scene.h — drawing the physical system of an answer's animation
 * (mm_exercise.h "animation"): springs as zigzags that stretch, dampers,
 * blocks, walls, and how many frames a motion needs.
 *
 * Every function writes frame f of a shape the exercise made with
 * mm_anim_shape, with the number of points named here (MM_SCENE_*_POINTS);
 * coordinates in metres, x right, y up.  None can fail.
 *
 *   mm_shape *spring = mm_anim_shape(res, "spring", MM_SHAPE_LINE, nf, MM_SCENE_SPRING_POINTS);
 *   for (int f = 0; f < nf; f++)
 *       mm_scene_spring(spring, f, 0, 0, L + x[f], 0, 0.1 * L);
 */
#ifndef MM_SCENE_H
#define MM_SCENE_H

#include "mm_exercise.h"

#define MM_SCENE_SPRING_POINTS 16   /* 2 leads, 6 coils of 2 corners */
#define MM_SCENE_CUP_POINTS 7       /* a damper's cylinder with its rod */
#define MM_SCENE_PISTON_POINTS 4    /* a damper's piston with its rod */
#define MM_SCENE_BOX_POINTS 4       /* a rectangle, as a polygon */

/* A zigzag spring from (x0, y0) to (x1, y1), width across its axis: straight
 * leads of 1/8 of the length at each end, the coils between them stretch. */
void mm_scene_spring(mm_shape *s, int f, double x0, double y0, double x1, double y1, double width);

/* A damper from (x0, y0) (the cylinder's end) to (x1, y1) (the piston's
 * end), width across: cup gets MM_SCENE_CUP_POINTS, piston
 * MM_SCENE_PISTON_POINTS.  The cylinder is 0.45 of the rest length rest,
 * so the piston stays inside while |length - rest| < 0.35 rest.  A cup
 * with fewer frames than f is left as it is: a cylinder whose end and
 * direction do not move needs one frame. */
void mm_scene_damper(mm_shape *cup, mm_shape *piston, int f, double x0, double y0, double x1,
                     double y1, double width, double rest);

/* A rectangle centred at (cx, cy), w wide and h high, turned by angle
 * [rad] counter-clockwise. */
void mm_scene_box(mm_shape *s, int f, double cx, double cy, double w, double h, double angle);

/* How many frames show a motion of the given shortest period over t_end:
 * 24 frames a period, at most MM_ANIM_MAX_FRAMES; when that cannot cover
 * t_end, the animation covers *t_show < t_end (whole frames of 24 a
 * period), else t_show = t_end.  At least 2 frames.  period <= 0 or
 * infinite: a slow motion, MM_ANIM_MAX_FRAMES / 2 frames over t_end. */
int mm_scene_frames(double t_end, double period, double *t_show);

#endif
