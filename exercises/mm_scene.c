/* mm_scene.c — the drawing kit of mm_scene.h. */
#include "mm_scene.h"

#include <math.h>

static void put(mm_shape *s, int f, int k, double x, double y)
{
    s->x[(size_t)f * (size_t)s->npts + (size_t)k] = x;
    s->y[(size_t)f * (size_t)s->npts + (size_t)k] = y;
}

void mm_scene_spring(mm_shape *s, int f, double x0, double y0, double x1, double y1, double width)
{
    double dx = x1 - x0, dy = y1 - y0, len = hypot(dx, dy);
    double ux = len > 0 ? dx / len : 1, uy = len > 0 ? dy / len : 0;   /* along, across = (-uy, ux) */
    const int coils = (MM_SCENE_SPRING_POINTS - 4) / 2;
    double lead = len / 8, pitch = (len - 2 * lead) / (2 * coils);
    put(s, f, 0, x0, y0);
    put(s, f, 1, x0 + lead * ux, y0 + lead * uy);
    for (int k = 0; k < 2 * coils; k++) {
        double a = lead + (k + 0.5) * pitch, side = (k % 2 ? -0.5 : 0.5) * width;
        put(s, f, 2 + k, x0 + a * ux - side * uy, y0 + a * uy + side * ux);
    }
    put(s, f, MM_SCENE_SPRING_POINTS - 2, x1 - lead * ux, y1 - lead * uy);
    put(s, f, MM_SCENE_SPRING_POINTS - 1, x1, y1);
}

void mm_scene_damper(mm_shape *cup, mm_shape *piston, int f, double x0, double y0, double x1,
                     double y1, double width, double rest)
{
    double dx = x1 - x0, dy = y1 - y0, len = hypot(dx, dy);
    double ux = len > 0 ? dx / len : 1, uy = len > 0 ? dy / len : 0, nx = -uy, ny = ux;
    double h = 0.5 * width, c0 = 0.15 * rest, cl = 0.45 * rest;   /* cup bottom, cup length */
    double bx = x0 + c0 * ux, by = y0 + c0 * uy;
    /* the cup: rod to its bottom, one wall, back, the other wall (a cup of
     * fewer frames than f stands still: drawn at its frames only) */
    if (f < cup->frames) {
        put(cup, f, 0, x0, y0);
        put(cup, f, 1, bx, by);
        put(cup, f, 2, bx + h * nx, by + h * ny);
        put(cup, f, 3, bx + h * nx + cl * ux, by + h * ny + cl * uy);
        put(cup, f, 4, bx + h * nx, by + h * ny);
        put(cup, f, 5, bx - h * nx, by - h * ny);
        put(cup, f, 6, bx - h * nx + cl * ux, by - h * ny + cl * uy);
    }
    /* the piston: its plate inside the cup, 0.4 of the rest length from the far end */
    double p = len - 0.4 * rest, px = x0 + p * ux, py = y0 + p * uy, ph = 0.8 * h;
    put(piston, f, 0, x1, y1);
    put(piston, f, 1, px, py);
    put(piston, f, 2, px + ph * nx, py + ph * ny);
    put(piston, f, 3, px - ph * nx, py - ph * ny);
}

void mm_scene_box(mm_shape *s, int f, double cx, double cy, double w, double h, double angle)
{
    static const double corner[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
    double c = cos(angle), sn = sin(angle);
    for (int k = 0; k < 4; k++) {
        double u = corner[k][0] * w, v = corner[k][1] * h;
        put(s, f, k, cx + c * u - sn * v, cy + sn * u + c * v);
    }
}

int mm_scene_frames(double t_end, double period, double *t_show)
{
    *t_show = t_end;
    if (!(period > 0) || !isfinite(period))
        return MM_ANIM_MAX_FRAMES / 2;
    double want = ceil(24 * t_end / period) + 1;
    if (want <= MM_ANIM_MAX_FRAMES)
        return want < 2 ? 2 : (int)want;
    *t_show = (MM_ANIM_MAX_FRAMES - 1) * period / 24;
    return MM_ANIM_MAX_FRAMES;
}
