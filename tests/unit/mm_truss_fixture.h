/* mm_truss_fixture.h — trusses built in memory for the truss tests and the
 * statics bench (tests/unit/test_truss.c, tests/bench/bench_statics.c):
 * the storage an mm_truss points into, and the Pratt truss of N panels.
 * static inline: each file uses its own subset. */
#ifndef MM_TRUSS_FIXTURE_H
#define MM_TRUSS_FIXTURE_H

#include <string.h>

#include "mm_truss.h"

typedef struct built {
    double xy[2 * MM_TRUSS_MAX_NODES];
    int ends[2 * MM_TRUSS_MAX_MEMBERS];
    int sup[3 * MM_TRUSS_MAX_SUPPORTS];
    int lnode[MM_TRUSS_MAX_LOADS];
    double lf[2 * MM_TRUSS_MAX_LOADS];
    mm_truss t;
    double force[MM_TRUSS_MAX_MEMBERS], reaction[2 * MM_TRUSS_MAX_NODES];
    mm_truss_result r;
} built;

static inline void bind(built *b, int n, int m, int ns, int nl)
{
    b->t = (mm_truss){n, b->xy, m, b->ends, ns, b->sup, nl, b->lnode, b->lf};
    b->r.force = b->force;
    b->r.reaction = b->reaction;
}

/* A Pratt truss of N panels of width a and height h: bottom joints B_i =
 * (i a, 0) are nodes i = 0..N, top joints T_i = (i a, h) nodes N + i,
 * i = 1..N-1; diagonals fall toward the middle; pin at B_0, roller at B_N;
 * P down at every inner bottom joint.  2N joints, 4N - 3 members. */
static inline void pratt(built *b, int N, double a, double h, double P)
{
    int n = 0, m = 0;
    for (int i = 0; i <= N; i++)
        b->xy[2 * n] = i * a, b->xy[2 * n + 1] = 0, n++;
    for (int i = 1; i < N; i++)
        b->xy[2 * n] = i * a, b->xy[2 * n + 1] = h, n++;
#define T(i) (N + (i))
#define E(p, q) (b->ends[2 * m] = (p), b->ends[2 * m + 1] = (q), m++)
    for (int i = 0; i < N; i++)
        E(i, i + 1);
    for (int i = 1; i + 1 < N; i++)
        E(T(i), T(i + 1));
    for (int i = 1; i < N; i++)
        E(i, T(i));
    E(0, T(1));
    E(N, T(N - 1));
    for (int i = 1; i + 1 < N; i++) {
        if (2 * i < N)
            E(T(i), i + 1);
        else
            E(i, T(i + 1));
    }
#undef T
#undef E
    int sup[] = {0, 1, 1, N, 0, 1};
    memcpy(b->sup, sup, sizeof sup);
    for (int i = 1; i < N; i++) {
        b->lnode[i - 1] = i;
        b->lf[2 * (i - 1)] = 0, b->lf[2 * (i - 1) + 1] = -P;
    }
    bind(b, n, m, 2, N - 1);
}

#endif
