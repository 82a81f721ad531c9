/* bench_statics.c — the statics solvers in-process: a 50-joint Pratt truss
 * by the method of joints (assembly, rank test, solve: mm_truss_solve)
 * against Octave's 1.4 ms for the same work (PERFORMANCE.md: method of
 * joints + A\b), its diagnosis when a diagonal is missing, the sta-truss
 * request end to end, a beam with many loads and a polygon of 200 vertices.
 * Prints the ratio; the goal is at least 10x. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mm_api.h"
#include "mm_beam.h"
#include "mm_section.h"
#include "../unit/mm_truss_fixture.h"

#define OCTAVE_TRUSS_US 1400.0   /* PERFORMANCE.md, Octave 7.3 in-process */

static double now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return 1e6 * (double)ts.tv_sec + 1e-3 * (double)ts.tv_nsec;
}

/* Median of 7 timings of reps calls. */
static double time_truss(const mm_truss *t, int reps, int expect)
{
    double force[MM_TRUSS_MAX_MEMBERS], reaction[2 * MM_TRUSS_MAX_NODES], runs[7];
    mm_truss_result r = {.force = force, .reaction = reaction};
    mm_error err;
    for (int k = 0; k < 7; k++) {
        double t0 = now_us();
        for (int i = 0; i < reps; i++)
            if (mm_truss_solve(t, &r, &err) != expect) {
                fprintf(stderr, "unexpected status: %s\n", err.msg);
                exit(1);
            }
        runs[k] = (now_us() - t0) / reps;
    }
    for (int i = 0; i < 7; i++)
        for (int j = i + 1; j < 7; j++)
            if (runs[j] < runs[i]) {
                double s = runs[i];
                runs[i] = runs[j], runs[j] = s;
            }
    return runs[3];
}

int main(void)
{
    static built p;                      /* the Pratt truss of mm_truss_fixture.h */
    pratt(&p, 25, 2, 3, 1000);
    double us = time_truss(&p.t, 200, MM_OK);
    printf("50-joint Pratt truss (97 members), mm_truss_solve: %8.1f us   Octave 1.4 ms / this = %.1fx "
           "(goal >= 10x)\n", us, OCTAVE_TRUSS_US / us);

    pratt(&p, 50, 2, 3, 1000);
    us = time_truss(&p.t, 100, MM_OK);
    printf("100-joint Pratt truss (197 members, the limit):   %8.1f us\n", us);

    pratt(&p, 25, 2, 3, 1000);
    p.t.n_members--;                     /* a diagonal missing: the diagnosis path */
    us = time_truss(&p.t, 20, MM_ESINGULAR);
    printf("50-joint truss with a diagonal missing (rank test, mechanism named): %8.1f us\n", us);
    pratt(&p, 50, 2, 3, 1000);
    p.t.n_members--;
    us = time_truss(&p.t, 5, MM_ESINGULAR);
    printf("100-joint truss with a diagonal missing:                             %8.1f us\n", us);

    /* a beam with every kind of load at its limits: 50 forces, 20 distributed, 20 couples, EI */
    {
        double pt[2 * 50], dl[4 * 20], mo[2 * 20];
        for (int i = 0; i < 50; i++)
            pt[2 * i] = 0.2 * i + 0.05, pt[2 * i + 1] = -100 - i;
        for (int i = 0; i < 20; i++) {
            dl[4 * i] = 0.5 * i, dl[4 * i + 1] = 0.5 * i + 0.4, dl[4 * i + 2] = -50, dl[4 * i + 3] = -80;
            mo[2 * i] = 0.5 * i + 0.2, mo[2 * i + 1] = 30;
        }
        mm_beam_problem bp = {.L = 10, .kind = MM_BEAM_TWO_SUPPORTS, .a = 1, .b = 9, .n_point = 50, .point = pt,
                              .n_dist = 20, .dist = dl, .n_moment = 20, .moment = mo, .EI = 1e6};
        double best = 1e30;
        for (int k = 0; k < 50; k++) {
            double t0 = now_us(), v, x;
            mm_beam *b;
            if (mm_beam_solve(&bp, &b, NULL) != MM_OK)
                return 1;
            mm_beam_extreme_V(b, &v, &x);
            mm_beam_extreme_M(b, &v, &x);
            mm_beam_extreme_y(b, &v, &x);
            mm_beam_unit_load(b, x, &v, NULL, NULL);
            mm_beam_free(b);
            best = fmin(best, now_us() - t0);
        }
        printf("beam, 90 loads: solve, extremes of V, M, y and the unit-load deflection: %8.1f us\n", best);
    }
    /* a star polygon of 200 vertices: Green's theorem, simplicity test, ear clipping */
    {
        double xy[400];
        int tri[3 * 198];
        for (int k = 0; k < 200; k++) {
            double t = 2 * M_PI * k / 200, r = k % 2 ? 1 : 0.6;
            xy[2 * k] = r * cos(t), xy[2 * k + 1] = r * sin(t);
        }
        double best = 1e30, best_t = 1e30;
        for (int k = 0; k < 20; k++) {
            mm_section_props sp;
            double t0 = now_us();
            if (mm_section_polygon(200, xy, &sp, NULL, NULL) != MM_OK)
                return 1;
            double t1 = now_us();
            if (mm_section_triangulate(200, xy, tri) != 198)
                return 1;
            best = fmin(best, t1 - t0);
            best_t = fmin(best_t, now_us() - t1);
        }
        printf("200-vertex star: properties with the simplicity test %8.1f us, ear clipping %8.1f us\n", best, best_t);
    }

    /* sta-truss end to end: parse, validate, solve, checks, JSON */
    const mm_exercise *ex = mm_exercise_find("sta-truss");
    if (ex) {
        static char nodes[8192], members[8192], loads[8192];
        size_t a = 0, b = 0, c = 0;
        pratt(&p, 25, 2, 3, 1000);
        for (int i = 0; i < p.t.n_nodes; i++)
            a += (size_t)snprintf(nodes + a, sizeof nodes - a, "%s%g,%g", i ? ";" : "", p.xy[2 * i],
                                  p.xy[2 * i + 1]);
        for (int e = 0; e < p.t.n_members; e++)
            b += (size_t)snprintf(members + b, sizeof members - b, "%s%d,%d", e ? ";" : "",
                                  p.ends[2 * e] + 1, p.ends[2 * e + 1] + 1);
        for (int l = 0; l < p.t.n_loads; l++)
            c += (size_t)snprintf(loads + c, sizeof loads - c, "%s%d,0,-1000", l ? ";" : "",
                                  p.lnode[l] + 1);
        mm_input in[4] = {{"nodes", nodes, 5, a}, {"members", members, 7, b},
                          {"supports", "1,1,1;26,0,1", 8, 12}, {"loads", loads, 5, c}};
        double best = 1e30;
        size_t len = 0;
        for (int k = 0; k < 20; k++) {
            mm_buf out;
            mm_buf_init(&out, MM_ANSWER_MAX);
            double t0 = now_us();
            int st = mm_api_solve(ex, in, 4, &out);
            double dt = now_us() - t0;
            if (st != 200) {
                fprintf(stderr, "sta-truss: %d %.300s\n", st, out.p);
                return 1;
            }
            len = out.len;
            mm_buf_free(&out);
            best = fmin(best, dt);
        }
        printf("sta-truss request, 50 joints (parse, solve, sections, checks, drawing, JSON): %8.1f us, %zu bytes\n",
               best, len);
    }
    return 0;
}
